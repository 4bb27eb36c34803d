/* Handles of the fixed slot pools (meshes, textures): {generation << 16 |
 * slot + 1}, so a stale handle of a reused slot never resolves and 0 is
 * never a handle. */
#include "internal.h"

#define SLOT_AT(first, stride, i) ((stin__handle *)(void *)((unsigned char *)(first) + (stride) * (i)))

uint32_t stin__handle_free_slot(const stin__handle *first, size_t stride, uint32_t count)
{
    uint32_t i;
    for (i = 0; i < count; i++)
        if (!SLOT_AT(first, stride, i)->alive)
            return i;
    return STIN__NO_SLOT;
}

uint32_t stin__handle_issue(stin__handle *h, uint32_t slot)
{
    h->alive = 1;
    h->generation = (h->generation + 1u) & 0xffffu;
    if (h->generation == 0)
        h->generation = 1;
    return (h->generation << 16) | (slot + 1u);
}

uint32_t stin__handle_resolve(const stin__handle *first, size_t stride, uint32_t count,
                              uint32_t id)
{
    uint32_t s = id & 0xffffu;
    const stin__handle *h;
    if (!first || s == 0 || s > count)
        return STIN__NO_SLOT;
    h = SLOT_AT(first, stride, s - 1u);
    return h->alive && h->generation == (id >> 16) ? s - 1u : STIN__NO_SLOT;
}
