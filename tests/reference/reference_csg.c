/* SPDX-License-Identifier: MIT */
/* CSG products by ray intervals: every crossing of the camera ray with the
 * primitives (an Embree context filter that records each hit and rejects
 * it, so traversal goes on to the next), in/out per primitive, and the
 * expression evaluated along the ray. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "reference_csg.h"
#include "reference_internal.h"

/* The SOA layout of Embree's RTCRayN / RTCHitN (its accessors are C++ only):
 * field k of ray i of N at k * N + i. */
#define RAY_F(ray, N, i, k) (((const float *)(const void *)(ray))[(k) * (N) + (i)])
#define HIT_F(hit, N, i, k) (((const float *)(const void *)(hit))[(k) * (N) + (i)])
#define HIT_U(hit, N, i, k) (((const unsigned *)(const void *)(hit))[(k) * (N) + (i)])
enum { RAY_DIR_X = 4, RAY_TFAR = 8, HIT_NG_X = 0, HIT_U_ = 3, HIT_V_ = 4, HIT_PRIM = 5,
       HIT_GEOM = 6 };

typedef struct crossing {
    float t, u, v;
    unsigned object, prim;
    int exit;            /* back face: the ray leaves the primitive */
} crossing;

typedef struct collector {
    struct RTCIntersectContext rtc; /* first: the filter gets this pointer */
    const reference *r;
    crossing *list;
    int count, capacity, overflow;
} collector;

/* Visibility rays: hits on CSG primitives are not occluders. */
static void skip_csg(const struct RTCFilterFunctionNArguments *args)
{
    const ref_csg_context *c = (const ref_csg_context *)(const void *)args->context;
    for (unsigned i = 0; i < args->N; i++)
        if (args->valid[i] && c->r->csg_primitive[HIT_U(args->hit, args->N, i, HIT_GEOM)])
            args->valid[i] = 0;
}

void ref_csg_context_init(const reference *r, ref_csg_context *ctx)
{
    rtcInitIntersectContext(&ctx->rtc);
    ctx->r = r;
    if (r->csg_primitive)
        ctx->rtc.filter = skip_csg;
}

/* Primary CSG rays: every hit on a CSG primitive is recorded and rejected. */
static void collect(const struct RTCFilterFunctionNArguments *args)
{
    collector *c = (collector *)(void *)args->context;
    for (unsigned i = 0; i < args->N; i++) {
        unsigned g;
        if (!args->valid[i])
            continue;
        g = HIT_U(args->hit, args->N, i, HIT_GEOM);
        args->valid[i] = 0;
        if (!c->r->csg_primitive[g])
            continue;
        if (c->count == c->capacity) {
            c->overflow = 1;
            continue;
        }
        crossing *x = &c->list[c->count++];
        float facing = 0.0f;
        for (int k = 0; k < 3; k++)
            facing += HIT_F(args->hit, args->N, i, HIT_NG_X + k) *
                      RAY_F(args->ray, args->N, i, RAY_DIR_X + k);
        x->t = RAY_F(args->ray, args->N, i, RAY_TFAR);
        x->u = HIT_F(args->hit, args->N, i, HIT_U_);
        x->v = HIT_F(args->hit, args->N, i, HIT_V_);
        x->object = g;
        x->prim = HIT_U(args->hit, args->N, i, HIT_PRIM);
        x->exit = facing > 0.0f;
    }
}

int reference_csg_mark(reference *r, const ref_csg_product *products, int count)
{
    if (!r || (count && !products))
        return 0;
    if (!r->csg_primitive) {
        r->csg_primitive = calloc((size_t)r->object_count + 1, 1);
        if (!r->csg_primitive)
            return 0;
    }
    for (int p = 0; p < count; p++)
        for (int i = 0; i < products[p].primitive_count; i++) {
            int o = products[p].objects[i];
            if (o < 0 || o >= r->object_count)
                return 0;
            r->csg_primitive[o] = 1;
        }
    return 1;
}

static int eval(const stin_csg_node *nodes, int i, const unsigned char *inside)
{
    const stin_csg_node *n = &nodes[i];
    switch (n->op) {
    case STIN_CSG_PRIMITIVE: return inside[n->primitive];
    case STIN_CSG_UNION: return eval(nodes, (int)n->a, inside) || eval(nodes, (int)n->b, inside);
    case STIN_CSG_INTERSECTION:
        return eval(nodes, (int)n->a, inside) && eval(nodes, (int)n->b, inside);
    case STIN_CSG_SUBTRACTION:
        return eval(nodes, (int)n->a, inside) && !eval(nodes, (int)n->b, inside);
    }
    return 0;
}

static int by_t(const void *a, const void *b)
{
    const crossing *x = a, *y = b;
    if (x->t != y->t)
        return x->t < y->t ? -1 : 1;
    if (x->object != y->object)
        return x->object < y->object ? -1 : 1;
    return x->prim < y->prim ? -1 : x->prim > y->prim;
}

/* Primitive of each scene object in one product (-1: none), so a crossing
 * finds its primitive at once whatever the primitive count. */
typedef struct product_index {
    const ref_csg_product *p;
    int *of_object;
} product_index;

static int primitive_of(const product_index *pi, unsigned object)
{
    return pi->of_object[object];
}

#define SAME_T(a, b) (fabsf((a) - (b)) <= 1e-6f * fmaxf(fabsf(a), 1.0f))

#define CAP (-2)

/* Each primitive's state at the ray's start into inside (primitive_count
 * bytes: in where its exits outnumber its entries along the whole ray),
 * and whether the product holds the start. */
static int starts_inside(const product_index *pi, const crossing *x, int n, unsigned char *inside,
                         int *balance)
{
    const ref_csg_product *p = pi->p;
    int i, k;
    memset(balance, 0, sizeof *balance * (size_t)p->primitive_count);
    for (i = 0; i < n; i++)
        balance[primitive_of(pi, x[i].object)] += x[i].exit ? 1 : -1;
    for (k = 0; k < p->primitive_count; k++)
        inside[k] = balance[k] > 0;
    return eval(p->nodes, p->node_count - 1, inside);
}

/* The first crossing (of the sorted list, one product's) where the
 * expression turns true; CAP where it holds at the near plane; -1 for
 * none. inside: primitive_count bytes. */
static int first_surface(const product_index *pi, const crossing *x, int n, unsigned char *inside,
                         int *balance)
{
    const ref_csg_product *p = pi->p;
    int i, k;
    if (starts_inside(pi, x, n, inside, balance))
        return CAP; /* holds the near plane */
    for (i = 0; i < n;) {
        int end = i, pick = -1;
        while (end < n && SAME_T(x[end].t, x[i].t))
            end++;
        for (k = i; k < end && pick < 0; k++) { /* a crossing alone that makes it true */
            int q = primitive_of(pi, x[k].object);
            unsigned char was = inside[q];
            inside[q] = (unsigned char)!x[k].exit;
            if (eval(p->nodes, p->node_count - 1, inside))
                pick = k;
            inside[q] = was;
        }
        for (k = i; k < end; k++)
            inside[primitive_of(pi, x[k].object)] = (unsigned char)!x[k].exit;
        if (eval(p->nodes, p->node_count - 1, inside))
            return pick >= 0 ? pick : i;
        i = end;
    }
    return -1;
}

/* Drops a crossing that repeats the one before on the same primitive and
 * side at the same distance (a ray through an edge hits both triangles). */
static int drop_edge_repeats(crossing *x, int n)
{
    int o = 0;
    for (int i = 0; i < n; i++) {
        int repeat = 0;
        for (int j = o - 1; j >= 0 && SAME_T(x[j].t, x[i].t); j--)
            if (x[j].object == x[i].object && x[j].exit == x[i].exit)
                repeat = 1;
        if (!repeat)
            x[o++] = x[i];
    }
    return o;
}

/* The cap's hit at view distance t along dir: facing the eye. */
static void fill_cap(const reference *r, const ref_csg_product *p, const ref_camera_frame *cf,
                     const float eye[3], const double dir[3], double t, ref_hit *h)
{
    double len = 0.0;
    memset(h, 0, sizeof *h);
    h->hit = 1;
    h->object = p->objects[0];
    for (int k = 0; k < 3; k++) {
        h->P[k] = (float)(eye[k] + t * dir[k]);
        h->N[k] = h->Ng[k] = (float)-cf->f[k];
        len += t * dir[k] * t * dir[k];
    }
    h->t = (float)sqrt(len);
    (void)r;
}

static int csg_primary_traced(const reference *r, const ref_csg_product *products, int count,
                              int width, int height, double dx, double dy, ref_hit *hits,
                              int *product_of)
{
    ref_camera_frame cf;
    collector c;
    crossing *mine;
    unsigned char *inside;
    int *balance, ok = 1, most = 1;
    product_index *index;
    if (!r || !hits || count < 0 || (count && !products) ||
        !r->csg_primitive)
        return 0;
    for (int p = 0; p < count; p++) {
        if (products[p].primitive_count < 1 || products[p].node_count < 1)
            return 0;
        most = products[p].primitive_count > most ? products[p].primitive_count : most;
        for (int i = 0; i < products[p].primitive_count; i++)
            if (products[p].objects[i] < 0 || products[p].objects[i] >= r->object_count ||
                !r->csg_primitive[products[p].objects[i]])
                return 0; /* reference_csg_mark first */
    }
    if (!ref_frame_of(&r->s->camera, width, height, &cf))
        return 0;
    memset(&c, 0, sizeof c);
    c.r = r;
    c.capacity = 4096 > 4 * most ? 4096 : 4 * most;
    c.list = malloc(sizeof *c.list * (size_t)c.capacity);
    mine = malloc(sizeof *mine * (size_t)c.capacity);
    inside = malloc((size_t)most);
    balance = malloc(sizeof *balance * (size_t)most);
    index = calloc((size_t)count + 1, sizeof *index);
    for (int p = 0; index && p < count; p++) {
        index[p].p = &products[p];
        index[p].of_object = malloc(sizeof(int) * (size_t)r->object_count);
        if (!index[p].of_object)
            continue;
        for (int o = 0; o < r->object_count; o++)
            index[p].of_object[o] = -1;
        for (int i = 0; i < products[p].primitive_count; i++)
            index[p].of_object[products[p].objects[i]] = i;
    }
    for (int p = 0; index && p < count; p++)
        ok &= index[p].of_object != NULL;
    if (!c.list || !mine || !inside || !balance || !index || !ok) {
        ok = 0;
        goto done;
    }
    const float *eye = r->s->camera.eye;
    /* the view distance of window depth REF_CSG_CAP_DEPTH */
    const double cn = r->s->camera.near_plane, cfar = r->s->camera.far_plane;
    const double cap_t = cfar * cn / (cfar - REF_CSG_CAP_DEPTH * (cfar - cn));
    for (int y = 0; y < height && ok; y++)
        for (int x = 0; x < width; x++) {
            size_t at = (size_t)y * (size_t)width + (size_t)x;
            ref_hit *h = &hits[at];
            double dir[3];
            struct RTCRayHit rh;
            if (product_of)
                product_of[at] = -1;
            /* the nearest ordinary object, through the primitives */
            ref_window_dir(&cf, width, height, x + dx, y + dy, dir);
            memset(&rh, 0, sizeof rh);
            rh.ray.org_x = eye[0];
            rh.ray.org_y = eye[1];
            rh.ray.org_z = eye[2];
            rh.ray.dir_x = (float)dir[0];
            rh.ray.dir_y = (float)dir[1];
            rh.ray.dir_z = (float)dir[2];
            rh.ray.tnear = r->s->camera.near_plane;
            rh.ray.tfar = r->s->camera.far_plane;
            rh.ray.mask = 0xffffffffu;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            {
                ref_csg_context plain;
                ref_csg_context_init(r, &plain);
                rtcIntersect1(r->rtc, &plain.rtc, &rh);
            }
            if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
                memset(h, 0, sizeof *h);
            else
                ref_fill_hit(r, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v, eye, h);
            float t_best = h->hit ? rh.ray.tfar : INFINITY;
            /* every crossing with a primitive, to infinity (the start's in/out) */
            rtcInitIntersectContext(&c.rtc);
            c.rtc.filter = collect;
            c.count = 0;
            rh.ray.tfar = INFINITY;
            rh.ray.tnear = r->s->camera.near_plane;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(r->rtc, &c.rtc, &rh);
            if (c.overflow) {
                ok = 0;
                break;
            }
            qsort(c.list, (size_t)c.count, sizeof *c.list, by_t);
            for (int p = 0; p < count; p++) {
                int n = 0, k;
                for (int i = 0; i < c.count; i++)
                    if (primitive_of(&index[p], c.list[i].object) >= 0)
                        mine[n++] = c.list[i];
                n = drop_edge_repeats(mine, n);
                k = first_surface(&index[p], mine, n, inside, balance);
                if (k == CAP && cap_t < t_best) {
                    t_best = cap_t;
                    fill_cap(r, &products[p], &cf, eye, dir, cap_t, h);
                    if (product_of)
                        product_of[at] = p;
                    continue;
                }
                if (k < 0 || !(mine[k].t < t_best) || mine[k].t > r->s->camera.far_plane)
                    continue;
                t_best = mine[k].t;
                ref_fill_hit(r, mine[k].object, mine[k].prim, mine[k].u, mine[k].v, eye, h);
                if (mine[k].exit)
                    for (int q = 0; q < 3; q++) {
                        h->N[q] = -h->N[q];
                        h->Ng[q] = -h->Ng[q];
                    }
                if (product_of)
                    product_of[at] = p;
            }
        }
done:
    for (int p = 0; index && p < count; p++)
        free(index[p].of_object);
    free(index);
    free(balance);
    free(inside);
    free(c.list);
    free(mine);
    return ok && rtcGetDeviceError(r->device) == RTC_ERROR_NONE;
}

void ref_csg_hash_products(ref_hasher *h, const ref_csg_product *products, int count)
{
    ref_hash_u64(h, (uint64_t)count);
    for (int p = 0; p < count; p++) {
        ref_hash_array(h, products[p].objects, sizeof(int) * (size_t)products[p].primitive_count);
        ref_hash_array(h, products[p].nodes, sizeof(stin_csg_node) * (size_t)products[p].node_count);
    }
}

int reference_csg_primary(const reference *r, const ref_csg_product *products, int count,
                          int width, int height, ref_hit *hits, int *product_of)
{
    return reference_csg_primary_at(r, products, count, width, height, 0.5, 0.5, hits,
                                    product_of);
}

/* Cached by everything above, the products and the point in the pixel
 * (reference_cache.h). */
int reference_csg_primary_at(const reference *r, const ref_csg_product *products, int count,
                             int width, int height, double dx, double dy, ref_hit *hits,
                             int *product_of)
{
    ref_hasher h;
    ref_cache_key key;
    ref_cache_part parts[2];
    size_t n = (size_t)width * (size_t)height;
    int cached = 0;
    if (r && hits && count >= 0 && (products || !count) && width > 0 && height > 0 &&
        ref_cache_key_begin(r, "csg_primary", &h)) {
        ref_csg_hash_products(&h, products, count);
        ref_hash_u64(&h, (uint64_t)width);
        ref_hash_u64(&h, (uint64_t)height);
        ref_hash_u64(&h, product_of != NULL);
        if (dx != 0.5 || dy != 0.5) { /* the centre's key as before */
            ref_hash_array(&h, &dx, sizeof dx);
            ref_hash_array(&h, &dy, sizeof dy);
        }
        ref_cache_key_end(&h, &key);
        parts[0].data = hits;
        parts[0].size = n * sizeof *hits;
        parts[1].data = product_of;
        parts[1].size = product_of ? n * sizeof *product_of : 0;
        cached = 1;
        if (ref_cache_load(&key, parts, 2))
            return 1;
    }
    int ok;
    if (cached)
        ref_cache_compute_begin();
    ok = csg_primary_traced(r, products, count, width, height, dx, dy, hits, product_of);
    if (cached)
        ref_cache_compute_end();
    if (!ok)
        return 0;
    if (cached)
        ref_cache_store(&key, parts, 2);
    return 1;
}

/* ---- products casting ------------------------------------------------------ */
struct ref_csg_cast {
    product_index *index;
    int count, most;
};

void ref_csg_cast_free(struct ref_csg_cast *c)
{
    if (!c)
        return;
    for (int p = 0; p < c->count; p++)
        free(c->index[p].of_object);
    free(c->index);
    free(c);
}

int reference_csg_cast(reference *r, const ref_csg_product *products, int count)
{
    struct ref_csg_cast *c;
    if (!r || count < 0 || (count && !products) || (count && !r->csg_primitive))
        return 0;
    ref_csg_cast_free(r->csg_cast);
    r->csg_cast = NULL;
    if (!count)
        return 1;
    for (int p = 0; p < count; p++) {
        if (products[p].primitive_count < 1 || products[p].node_count < 1)
            return 0;
        for (int i = 0; i < products[p].primitive_count; i++)
            if (products[p].objects[i] < 0 || products[p].objects[i] >= r->object_count ||
                !r->csg_primitive[products[p].objects[i]])
                return 0; /* reference_csg_mark first */
    }
    c = calloc(1, sizeof *c);
    if (!c || !(c->index = calloc((size_t)count, sizeof *c->index))) {
        free(c);
        return 0;
    }
    c->count = count;
    c->most = 1;
    for (int p = 0; p < count; p++) {
        c->index[p].p = &products[p];
        c->index[p].of_object = malloc(sizeof(int) * (size_t)r->object_count);
        if (!c->index[p].of_object) {
            ref_csg_cast_free(c);
            return 0;
        }
        for (int o = 0; o < r->object_count; o++)
            c->index[p].of_object[o] = -1;
        for (int i = 0; i < products[p].primitive_count; i++)
            c->index[p].of_object[products[p].objects[i]] = i;
        c->most = products[p].primitive_count > c->most ? products[p].primitive_count : c->most;
    }
    r->csg_cast = c;
    return 1;
}

/* Whether the product indexed by pi holds a point of the sorted crossings'
 * ray between its origin and `dist`: in at the origin (exits less entries
 * along the whole ray), or after a crossing nearer than dist. */
static int holds_before(const product_index *pi, const crossing *x, int n, double dist,
                        unsigned char *inside, int *balance)
{
    const ref_csg_product *p = pi->p;
    int i, k;
    if (starts_inside(pi, x, n, inside, balance))
        return 1;
    for (i = 0; i < n && x[i].t < dist;) {
        int end = i;
        while (end < n && SAME_T(x[end].t, x[i].t))
            end++;
        for (k = i; k < end; k++)
            inside[primitive_of(pi, x[k].object)] = (unsigned char)!x[k].exit;
        if (eval(p->nodes, p->node_count - 1, inside))
            return 1;
        i = end;
    }
    return 0;
}

void ref_csg_hash_state(const reference *r, ref_hasher *h)
{
    ref_hash_array(h, r->csg_primitive, (size_t)r->object_count);
    ref_hash_u64(h, r->csg_cast != NULL);
    if (r->csg_cast)
        ref_csg_hash_products(h, r->csg_cast->index[0].p, r->csg_cast->count);
}

int ref_csg_blocks(const reference *r, const float org[3], const float dir[3], double dist)
{
    const struct ref_csg_cast *cc = r->csg_cast;
    struct RTCRayHit rh;
    collector c;
    crossing *mine = NULL;
    unsigned char *inside = NULL;
    int *balance = NULL, blocked = 0;
    if (!cc)
        return 0;
    memset(&c, 0, sizeof c);
    c.r = r;
    c.capacity = 4096 > 4 * cc->most ? 4096 : 4 * cc->most;
    c.list = malloc(sizeof *c.list * (size_t)c.capacity);
    mine = malloc(sizeof *mine * (size_t)c.capacity);
    inside = malloc((size_t)cc->most);
    balance = malloc(sizeof *balance * (size_t)cc->most);
    if (!c.list || !mine || !inside || !balance) {
        blocked = -1;
        goto done;
    }
    memset(&rh, 0, sizeof rh);
    rh.ray.org_x = org[0];
    rh.ray.org_y = org[1];
    rh.ray.org_z = org[2];
    rh.ray.dir_x = dir[0];
    rh.ray.dir_y = dir[1];
    rh.ray.dir_z = dir[2];
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcInitIntersectContext(&c.rtc);
    c.rtc.filter = collect;
    rtcIntersect1(r->rtc, &c.rtc, &rh);
    if (c.overflow) {
        blocked = -1;
        goto done;
    }
    qsort(c.list, (size_t)c.count, sizeof *c.list, by_t);
    for (int p = 0; p < cc->count && !blocked; p++) {
        int n = 0;
        for (int i = 0; i < c.count; i++)
            if (primitive_of(&cc->index[p], c.list[i].object) >= 0)
                mine[n++] = c.list[i];
        n = drop_edge_repeats(mine, n);
        blocked = holds_before(&cc->index[p], mine, n, dist, inside, balance);
    }
done:
    free(c.list);
    free(mine);
    free(inside);
    free(balance);
    return blocked;
}

int ref_csg_primary_cast(const reference *r, int width, int height, ref_hit *hits)
{
    const struct ref_csg_cast *cc = r->csg_cast;
    return cc && reference_csg_primary(r, cc->index[0].p, cc->count, width, height, hits, NULL);
}
