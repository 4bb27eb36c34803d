#version 150
// SPDX-License-Identifier: MIT
// CSG "interval" (src/csg/interval.c): one product's surface per pixel from
// its primitives' peeled crossings. Crossing j of primitive i is layer
// g = i k + j, slice g / 2 of the even or odd array u_crossing (r: the
// fragment's float depth, g: its side, 1 front, 0.5 back, 0 none). The
// crossings are walked nearest first keeping each primitive's in/out state;
// the product is the union of terms, term t inside every primitive of
// u_terms[t].x and outside every one of u_terms[t].y. The first crossing
// where it turns true is the surface: its layer g is written as
// (g + 1) / 255 (0: none), and the CPU takes that layer's depth as its
// depth attachment holds it. True before any crossing (the near plane
// inside the product) gives the cap's layer, n k.
#define MAX_PRIMITIVES 32
#define MAX_TERMS 64
#define NONE 2.0
// crossings this close count as one distance (the coplanar rule): 4 units
// of a 24-bit depth, goldfeather's polygon offset
#define TOGETHER (4.0 / 16777216.0)
uniform sampler2DArray u_crossing_even, u_crossing_odd;
uniform ivec4 u_counts; // primitives n, layers k, terms, cap layer present
uniform uvec2 u_terms[MAX_TERMS];
out vec4 o_layer;

float head_depth[MAX_PRIMITIVES];
float head_side[MAX_PRIMITIVES];
int next_layer[MAX_PRIMITIVES];

ivec3 texel(int g)
{
    return ivec3(ivec2(gl_FragCoord.xy), g / 2);
}

// layer g's crossing at this pixel: depth (NONE where there is none), side
vec2 crossing(int g)
{
    vec2 c = (g & 1) == 0 ? texelFetch(u_crossing_even, texel(g), 0).rg
                          : texelFetch(u_crossing_odd, texel(g), 0).rg;
    return c.y < 0.25 ? vec2(NONE, 0.0) : c;
}

vec4 layer(int g)
{
    return vec4(float(g + 1) / 255.0, 0.0, 0.0, 1.0);
}

// the next crossing of primitive i (peeled layers have no gaps; the
// one-interval debug mode's front and back layer may)
void advance(int i)
{
    head_depth[i] = NONE;
    while (head_depth[i] >= NONE && next_layer[i] < u_counts.y) {
        vec2 c = crossing(i * u_counts.y + next_layer[i]);
        head_depth[i] = c.x;
        head_side[i] = c.y;
        next_layer[i]++;
    }
}

bool holds(uint inside)
{
    for (int t = 0; t < u_counts.z; t++)
        if ((inside & u_terms[t].x) == u_terms[t].x && (inside & u_terms[t].y) == 0u)
            return true;
    return false;
}

void main()
{
    int n = u_counts.x, k = u_counts.y;
    uint inside = 0u;
    for (int i = 0; i < n; i++) {
        next_layer[i] = 0;
        advance(i);
        // the first crossing leaves: the ray starts inside (the near plane cuts it)
        if (head_depth[i] < NONE && head_side[i] < 0.75)
            inside |= 1u << uint(i);
    }
    bool was = holds(inside);
    if (was && u_counts.w != 0 && crossing(n * k).x < NONE) {
        o_layer = layer(n * k);
        return;
    }
    // every step takes one crossing at least: n k steps at most
    for (int step = 0; step < n * k; step++) {
        float d = NONE;
        int nearest = 0;
        for (int i = 0; i < n; i++)
            if (head_depth[i] < d) {
                d = head_depth[i];
                nearest = i * k + next_layer[i] - 1;
            }
        if (d >= NONE)
            break;
        for (int i = 0; i < n; i++)
            while (head_depth[i] <= d + TOGETHER) {
                if (head_side[i] > 0.75)
                    inside |= 1u << uint(i);
                else
                    inside &= ~(1u << uint(i));
                advance(i);
            }
        bool now = holds(inside);
        if (now && !was) {
            o_layer = layer(nearest);
            return;
        }
        was = now;
    }
    o_layer = vec4(0.0);
}
