/* SPDX-License-Identifier: MIT */
/* Shared by the image-test files: the run of one profile on one platform and
 * its PASS/FAIL/SKIP lines. */
#ifndef STIN_TESTS_IMAGE_TEST_H
#define STIN_TESTS_IMAGE_TEST_H

#include "stin/stin.h"
#include "scene.h"
#include "stin_platform.h"

typedef struct run {
    const char *profile_name, *platform_name, *out_dir;
    stin_platform *plat;
    const stin_profile *profile;
    int width, height;
    int passed, failed, skipped;
} run;

void report(run *r, const char *verdict, const char *name, const char *fmt, ...);
const char *scene_base_name(const char *path);

struct scene;
struct image;
struct capture;
/* position, normal and beauty of an unshadowed frame's AOV image against the
 * reference (image_test.c; per_vertex as reference_render takes it). */
void render_rows(run *r, stin_tier tier, const char *scene_name, const struct scene *s,
                 const struct image *img, int per_vertex);
/* volume-vis of a frame drawn elsewhere (shadow_test.c). */
void shadow_vis_rows(run *r, stin_tier tier, const char *path, const struct capture *cap);
/* map-pcf-SIZE-kKERNEL of a frame drawn elsewhere (pcf_test.c). */
void pcf_rows(run *r, stin_tier tier, const char *path, uint32_t size, int kernel,
              const struct capture *cap);
/* Rows of frames drawn elsewhere (a browser's), as the native tests judge
 * their own: coloured-transmittance and -between (coloured_test.c); the
 * unshadowed peel-beauty of an RGBA8 beauty, rows bottom to top, drawn by
 * `chosen` (peel_test.c); normal- or pom-reference by `tech`
 * (surface_test.c; low: the renderer takes a quad's coarse derivatives at
 * its lower-left pixel, as ANGLE on SwiftShader does, not its upper-left as
 * llvmpipe); displace position and silhouette (displace_test.c). */
void coloured_frame_rows(run *r, stin_tier tier, const char *path, const struct capture *cap);
/* deep-transmittance and deep-own-layer of glass-panes' frame drawn
 * elsewhere with deep_tests' options (deep_test.c). */
void deep_frame_rows(run *r, stin_tier tier, const char *path, const struct capture *cap);
void peel_frame_rows(run *r, stin_tier tier, const char *path, const uint8_t *rgba,
                     stin_technique chosen);
void surface_frame_rows(run *r, stin_tier tier, const char *path, stin_technique tech,
                        int low, const struct capture *cap);
void displace_frame_rows(run *r, stin_tier tier, const char *path, const struct capture *cap);
/* parallax-down: a parallax frame against a normal-mapping one of the
 * parallax-down view; parallax-limit: a parallax frame of the parallax-limit
 * scene g (its material mi's uv shift) against the reference (surface_test.c;
 * the views in tools/common/scene_variant.h). */
void surface_down_rows(run *r, const char *name, const struct capture *parallax,
                       const struct capture *normal);
void surface_limit_rows(run *r, const char *name, const struct scene *g, int mi,
                        const struct capture *a);
/* P and N of csg.json's case `name` (carved, both, common) resolved by tech (csg_test.c). */
void csg_frame_rows(run *r, stin_tier tier, const char *path, const char *name,
                    stin_technique tech, const struct capture *cap);
/* The browser's read-backs of each case in dir against the reference, the
 * rows named as the native ones (browser_test.c; tests/web/run.sh). */
void browser_tests(run *r, const char *dir, const char *cases, const char *path);

/* A frame at a viewport origin inside the framebuffer against the same at
 * (0, 0) (viewport_test.c; csg.json, every tier). */
void viewport_tests(run *r, stin_tier tier, const char *path);

/* GLSL PCF shadow-map tests of one scene (pcf_test.c; GL2/GL4). */
void pcf_tests(run *r, stin_tier tier, const char *path);
/* 16-bit element indices: a mesh over 65,535 vertices drawn in chunks (index16_test.c). */
void index16_tests(run *r, stin_tier tier, const char *path);

/* Fixed-function shadow-map tests of one scene (map_test.c; GL1 only). */
void map_tests(run *r, stin_tier tier, const char *path);

/* Shadow maps on the scenes made for real-model defects (model_test.c):
 * every pixel's visibility, the sides turned from the light included, and
 * map-pcf's documented gap limit. */
void model_tests(run *r, stin_tier tier, const char *path);

/* Soft shadows of an area light under every shadow technique of the tier,
 * against the integrated reference over the true penumbra (soft_test.c). */
void soft_tests(run *r, stin_tier tier, const char *path);

/* Shadow-volume tests of one scene at one tier (shadow_test.c). */
void shadow_tests(run *r, stin_tier tier, const char *path);
/* VDSM exact shadows of one scene (vdsm_test.c; GL4 only). */
void vdsm_tests(run *r, stin_tier tier, const char *path);
/* The measured choice of the exact technique switching between vdsm and
 * volumes frame by frame: every frame exact, and the frames alike away from
 * shadow edges (choice_test.c; GL4, three scenes). */
void choice_tests(run *r, stin_tier tier, const char *path);
/* stin_update_mesh: a tube bent over three frames in one context, each
 * frame's shadows against its own reference, per shadow technique of the
 * tier; gl11, gl21 and gl45-core only (update_mesh_test.c). */
void update_mesh_tests(run *r, stin_tier tier);
/* The seed's VDSM behaviours on built-in scenes, once per run (GL4). */
void vdsm_seed_tests(run *r, stin_tier tier);
/* VDSM's conservative growth on random faces, from vdsm_seed_tests (vdsm_growth_test.c). */
void vdsm_growth_tests(run *r);
/* DOT3 bump mapping of one scene at one tier, plus a built-in analytic scene
 * on the first call per tier (dot3_test.c). */
void dot3_tests(run *r, stin_tier tier, const char *path);
/* s with every normal map flat (128,128,255) into flat, and without normal
 * maps into plain, which DOT3 and per-vertex lighting draw alike (the rest
 * shared with s): 1, or 0 out of memory; dot3_flat_free either way. */
int dot3_flat_scenes(const scene *s, scene *flat, scene *plain);
void dot3_flat_free(scene *flat, scene *plain, const scene *s);
/* GLSL surface detail (normal, parallax, pom) of one scene at one tier, and
 * the shaders/gl2 version check once (surface_test.c). */
void surface_tests(run *r, stin_tier tier, const char *path);
/* Frames under hostile caller state, on four-lights, glass-panes and
 * stone-wall only (hostile_test.c). */
void hostile_tests(run *r, stin_tier tier, const char *path);
/* The application's own geometry in stin's depth buffer, before and after
 * stin's draws, on four-lights only (composite_test.c). */
void composite_tests(run *r, stin_tier tier, const char *path);
/* The deferred outline against its filter on the reference, on
 * four-lights only (outline_test.c). */
void outline_tests(run *r, stin_tier tier, const char *path);
/* The visibility map for the application's own shaders, on four-lights
 * (six lights) and shadow-soft (visibility_test.c). */
void visibility_tests(run *r, stin_tier tier, const char *path);

/* A GL error the caller left pending is still pending after stin's calls,
 * on four-lights only (error_kept_test.c). */
void error_kept_tests(run *r, stin_tier tier, const char *path);

/* Lone convex objects never shadowed where their shading normal faces a
 * light, per shadow technique, on the terminator-* scenes (terminator_test.c). */
void terminator_tests(run *r, stin_tier tier, const char *path);

/* Lit programs specialised to a pass's lights and a draw's material against
 * the general one, on four-lights, stone-wall, deep-window and glass-panes
 * (lit_test.c). */
void lit_tests(run *r, stin_tier tier, const char *path);

/* Displacement ("displace", GL2/GL4) on scenes with displaced materials,
 * against the displaced Embree reference (displace_test.c). Such scenes get
 * no other test: the others' references are of the undisplaced meshes. */
int displace_scene(const char *path);
/* CSG products against the exact CSG reference, on csg.json and the scenes
 * of tests/scenes/csg/ beside it (csg_test.c). */
void csg_tests(run *r, stin_tier tier, const char *path);
/* STIN_DEBUG_CSG_NO_IN_PLACE against the default on the scene files' own
 * products, every pixel (csg_merge_test.c; from csg.json). */
void csg_merge_tests(run *r, stin_tier tier, const char *path);
/* Products of 1000 primitives, generated (csg_many_test.c; from csg_tests). */
void csg_many_tests(run *r, stin_tier tier);
/* N against the CSG reference: within `degrees` on min_match of the pixels
 * away from edges (csg_test.c; compare.h's result). */
struct compare_result;
void csg_report_normals(run *r, const char *name, const struct compare_result *cr,
                        double degrees, double min_match);
/* Products casting shadows (csg_cast_test.c; from csg_tests, dir: csg.json's folder).
 * volume_casts: whether volumes cast products in the context of a capture
 * (capture.h) through their map, for every kind of light. */
void csg_cast_tests(run *r, stin_tier tier, const char *dir);
struct capture;
int csg_volume_casts(const struct capture *one);
/* Deep shadow maps ("deep", GL4) against the reference's transmittance, on
 * deep-stack, deep-colour and glass-panes; below GL4 a SKIP and the refusal
 * of a forced deep (deep_test.c). */
void deep_tests(run *r, stin_tier tier, const char *path);
/* Coloured shadow maps ("coloured", GL2 and GL4) against the reference's
 * transmittance, the opacity threshold ("opaque") on every tier, and the
 * refusal of a forced coloured below GL2 (coloured_test.c). */
void coloured_tests(run *r, stin_tier tier, const char *path);
/* Camera transparency (depth-peel, sorted) against the reference's
 * composite, on glass-panes and the scenes of tests/scenes/peel/ beside it
 * (peel_test.c). */
void peel_tests(run *r, stin_tier tier, const char *path);
void displace_tests(run *r, stin_tier tier, const char *path);
/* Every shadow technique into a 4x multisampled target against the
 * reference at its sample positions, at silhouettes (msaa_test.c; from
 * shadow-overlap, on msaa/halo.json beside it). */
void msaa_tests(run *r, stin_tier tier, const char *path);
/* CSG products into a 4x target against the CSG reference at its sample
 * positions, away from edges and in the silhouette band (msaa_csg_test.c;
 * from csg.json, on msaa/csg.json beside it; GL1: the refusal). */
void msaa_csg_tests(run *r, stin_tier tier, const char *path);
/* Blended draws (depth-peel, dual-peel) and translucent shadows (deep,
 * coloured) into a 4x target against the reference composite at its sample
 * positions, at silhouettes (msaa_blend_test.c; from shadow-overlap, on
 * msaa/glass.json beside it). */
void msaa_blend_tests(run *r, stin_tier tier, const char *path);
/* Normal mapping and pom into a 4x target against the surface reference at
 * its sample positions, at silhouettes (msaa_surface_test.c; from
 * stone-wall, on msaa/wall.json beside it). */
void msaa_surface_tests(run *r, stin_tier tier, const char *path);
/* displace and displace-tess into a 4x target against the displaced
 * reference at its sample positions, at silhouettes (msaa_displace_test.c;
 * from displace-plate, on msaa/displace.json beside it). */
void msaa_displace_tests(run *r, stin_tier tier, const char *path);
/* The deferred outline into a 4x target: its pixels the single-sampled
 * target's, the frame under it the reference at the samples
 * (msaa_outline_test.c; from shadow-overlap, on msaa/halo.json). */
void msaa_outline_tests(run *r, stin_tier tier, const char *path);
/* Frames into an sRGB colour target against the encoded reference, per
 * shadow technique, on four-lights under gl21, gl33-core and gl45-core
 * (srgb_test.c). */
void srgb_tests(run *r, stin_tier tier, const char *path);
/* The seed's displacement behaviour 5 on a built-in plate, once per GLSL
 * tier (displace_seed_test.c); caps: the context's present capabilities. */
void displace_seed_tests(run *r, stin_tier tier, uint64_t caps);

#endif
