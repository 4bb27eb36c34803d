/* SPDX-License-Identifier: MIT */
/* Handles of the fixed slot pools (meshes, textures). An id holds, from the
 * top: the context's tag (8 bits), the slot's generation, and slot + 1 in
 * the fewest bits that hold the pool's count (so 0 is never a handle):
 *   - the tag tells contexts apart (stin__handle_tag), so one context's
 *     handle does not resolve in another's pool;
 *   - a slot's generation grows with each issue and never wraps: a slot
 *     whose generation reached the top is retired when it is released (it
 *     stays unused for the context's life), so no stale id comes back. */
#include "internal.h"

#define SLOT_AT(first, stride, i) ((stin__handle *)(void *)((unsigned char *)(first) + (stride) * (i)))
#define TAG_SHIFT 24u

/* Bits of the slot field: slot + 1 <= count (at most 65535, 16 bits). */
static uint32_t slot_bits(uint32_t count)
{
    uint32_t b = 1;
    while (b < 16u && (count >> b) != 0)
        b++;
    return b;
}

static uint32_t generation_max(uint32_t count)
{
    return (1u << (TAG_SHIFT - slot_bits(count))) - 1u;
}

uint32_t stin__handle_tag(uint32_t serial, const void *block)
{
    uint64_t a = (uint64_t)(uintptr_t)block;
    uint32_t h = (uint32_t)((a ^ (a >> 32)) >> 4) * 2654435761u; /* Fibonacci hash */
    /* consecutive serials in one block differ by one: distinct tags for 255 re-creations */
    return ((h >> 24) + serial) & 0xffu;
}

uint32_t stin__handle_free_slot(const stin__handle *first, size_t stride, uint32_t count)
{
    uint32_t i;
    for (i = 0; i < count; i++) {
        const stin__handle *h = SLOT_AT(first, stride, i);
        if (!h->alive && !h->retired)
            return i;
    }
    return STIN__NO_SLOT;
}

uint32_t stin__handle_issue(stin__handle *h, uint32_t slot, uint32_t count, uint32_t tag)
{
    h->alive = 1;
    h->generation++; /* below generation_max: a slot that reached it was retired */
    return (tag << TAG_SHIFT) | (h->generation << slot_bits(count)) | (slot + 1u);
}

void stin__handle_release(stin__handle *h, uint32_t count)
{
    h->alive = 0;
    if (h->generation >= generation_max(count))
        h->retired = 1;
}

uint32_t stin__handle_resolve(const stin__handle *first, size_t stride, uint32_t count,
                              uint32_t tag, uint32_t id)
{
    uint32_t bits = slot_bits(count), s = id & ((1u << bits) - 1u);
    uint32_t generation = (id & ((1u << TAG_SHIFT) - 1u)) >> bits;
    const stin__handle *h;
    if (!first || s == 0 || s > count || id >> TAG_SHIFT != tag)
        return STIN__NO_SLOT;
    h = SLOT_AT(first, stride, s - 1u);
    return h->alive && h->generation == generation ? s - 1u : STIN__NO_SLOT;
}
