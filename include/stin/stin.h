/* SPDX-License-Identifier: MIT */
/*
 * stin — shadows, surface detail and image-based CSG on whatever OpenGL is there.
 *
 * stin is a C99 static library. It links no GL and no platform library and never
 * touches the heap: the application owns the GL context, hands stin a function
 * that resolves GL entry points and a block of memory, and stin does the rest.
 *
 * QUICK START
 *
 *     stin_desc desc = {0};                    // zero means "default" everywhere
 *     desc.get_proc_address = my_get_proc;     // e.g. eglGetProcAddress wrapped
 *     size_t bytes = stin_memory_size(&desc);
 *     void *block = malloc(bytes);             // any memory, 16-byte aligned
 *     stin_context *ctx;
 *     if (stin_create(&desc, block, bytes, &ctx) != STIN_OK) fail();
 *     stin_mesh ball;
 *     stin_mesh_desc md = {0};
 *     md.positions = pos; md.normals = nrm; md.vertex_count = nv;
 *     md.indices = idx; md.index_count = ni;
 *     stin_create_mesh(ctx, &md, &ball);
 *     stin_frame_desc fd = {0};                // fill view, projection, viewport
 *     stin_begin_frame(ctx, &fd);
 *     stin_add_light(ctx, &light);
 *     stin_draw(ctx, ball, transform, &material);
 *     stin_end_frame(ctx);                     // runs the passes of the chosen tier
 *     stin_destroy(ctx);                       // GL objects go; the block is yours
 *
 * TIERS
 *   STIN_TIER_GL1  fixed function on any compatibility context from GL 1.1 up
 *                  (stencil shadow volumes need a stencil buffer); uses GL 1.3/1.4
 *                  extensions where present. Per-vertex (Gouraud) lighting.
 *   STIN_TIER_GL2  GLSL 1.10/1.20 on a GL 2.x (or compatibility) context.
 *                  Per-pixel lighting.
 *   STIN_TIER_GL4  GLSL 1.50+ on a GL 3.2+ context (core or compatibility),
 *                  or GLSL ES 3.00+ on OpenGL ES 3.0+ (STIN_CAP_GLSL_150).
 *                  Per-pixel lighting. vdsm, GPU-extruded volumes and
 *                  tessellated displacement need their stages as well
 *                  (geometry shaders, tessellation): without them the
 *                  tier's chains fall back (volumes, vertex textures).
 * OpenGL ES (caps.es): no fixed function, so never GL1. GL2 on ES 2.0 (the
 * GLSL 1.10 sources as GLSL ES 1.00 under a version and precision
 * preamble), GL4 on ES 3.0 and later (the GLSL 1.50 sources as the
 * context's GLSL ES 3.x0; GL2 below it when forced, its sources as GLSL ES
 * 3.x0). ES 3.0 and 3.1 (WebGL 2 too) run the GL4 tier without a geometry
 * stage: volumes built on the CPU instead of vdsm, deep shadow maps, dual
 * peeling where float targets blend (EXT_float_blend) and any-samples
 * queries answer within the frame (not WebGL), vertex-texture
 * displacement; ES 3.2 adds vdsm, GPU-extruded volumes and tessellated
 * displacement. Measured on Mesa 22.3 llvmpipe against the same reference
 * and bounds as desktop (docs/profiles.md). On bare ES 2.0 (no derivatives,
 * depth textures or 32-bit indices) the GL2 tier takes the shaders'
 * derivative-free paths (STIN_CAP_DERIVATIVES), map-pcf's depth packed
 * into RGBA8 and CSG's packed GPU resolve (GOLDFEATHER below). Not on ES:
 * deep's and vdsm's storage-buffer paths (COMPUTE stays off), vdsm's
 * transform-feedback culling pass (it culls in its geometry shader
 * instead): each falls back, logged. Soft vdsm (area lights) ORs its bits by
 * image atomics there (no logic op), on ES 3.2; below it, hard shadows.
 * desc.tier = STIN_TIER_AUTO picks the highest tier the context runs. Any other
 * value forces that tier; if the context (after desc.caps_mask) cannot run it,
 * stin_create fails with STIN_ERROR_UNSUPPORTED and logs the missing
 * capabilities by name. stin never changes a forced tier silently.
 * Inside a tier every feature walks an ordered fallback chain; each step down
 * is logged (STIN_LOG_FALLBACK) and can be read back with stin_query_choice().
 *
 * LIGHTING MODEL (all tiers, and the test reference)
 * The OpenGL fixed-function equation with a local viewer, evaluated per vertex
 * on GL1 and per pixel on GL2/GL4:
 *   c = ambient * albedo
 *     + sum_i att_i * spot_i * ( max(N.L,0) * light_i * albedo
 *                              + [N.L>0] * max(N.H,0)^shininess * light_i * specular )
 *   att  = 1 / (k0 + k1 d + k2 d^2) for point and spot lights, 1 for directional
 *   spot = max(-L.D, 0)^exponent inside the cone, 0 outside
 *   light_i = colour * intensity;  H = normalize(L + V)
 * Colour is linear; alpha is the material's opacity. Per-vertex results are
 * clamped to [0,1] before interpolation (as GL does); per-pixel at the end.
 * Per-pixel programs: a pass lights up to 8 lights (more take further
 * additive passes). Each draw is shaded by a program specialised to its
 * pass's lights (their count, and whether any is directional, positional,
 * a spot or attenuated), to its material (albedo texture or not) and to
 * whether the pass draws a peeled transparency layer: the same equation
 * without the parts that pass and material leave out, so the same picture
 * (bit for bit on Mesa's llvmpipe), faster where a driver runs uniform
 * branches on masked lanes, and outside peeled layers without a discard,
 * so the depth test can run before shading. Each such program is compiled
 * the first time a frame needs it (a compile in that frame), then kept:
 * up to 32 per context, the one that served the oldest frame replaced
 * when a new one is needed (a frame that needs more than 32 draws the rest
 * with the general programs, logged once). A program that does not build
 * logs a warning and the general program serves.
 * stin_frame_stats.lighting.specialised and lighting.programs_built count them;
 * STIN_DEBUG_LIGHTING_GENERAL turns them off.
 *
 * SHADOWS
 * The shadow feature's chain: "vdsm" (GL4 only), "volume" (stencil shadow
 * volumes, exact; needs a stencil buffer), "map-pcf" (GLSL lighting),
 * "map-depth" and "map-combine" (fixed-function lighting), then "shadows-off".
 * "vdsm" (view-dependent shadow maps: GL 3.2 geometry shaders, float and
 * packed depth-stencil textures, a texture unit beyond the surface's): exact
 * hard shadows at the frame's resolution without a stencil buffer, adjacency
 * or map resolution. A stage draws the visible surface into a position
 * buffer (RGBA32F world position + RGBA16F facet and shading normals, 32 bytes
 * a pixel of GL memory plus a 24-bit depth texture, the size of the
 * viewport's far corner, made at the first frame and kept); per light, into a
 * channel of the screen mask below, 1 where the side the eye sees faces the
 * light, then each triangle's shadow-volume faces the eye sees, grown by half
 * a pixel, write 0 wherever the segment from the pixel's surface point to the
 * light hits that triangle. The terminator rule (Hanika, "Hacking the Shadow
 * Terminator", 2021; the test reference shares it): on a triangle whose
 * vertex normals bend away from its facet the surface point is the one on
 * the curved surface those normals describe (the position projected onto each
 * corner's tangent plane, blended by the barycentrics) where that lies above
 * the facet, and the side faces the light where its facet or its shading
 * normal does, so a low-poly sphere's lit side has no terminator steps; a
 * triangle whose vertex normals equal its facet normal (planes, boxes) is
 * drawn as before, and displaced draws keep their facets. Volumes follow
 * the rule too, on closed and open meshes, on every tier (see Volumes), so a
 * switch of the measured choice (below) changes no pixel off a shadow edge. The
 * position stage carries a geometry shader for it. The segment leaves the
 * surface by 2^-13 of the point's largest coordinate along its facet
 * normal (no self-shadowing; contact
 * shadows closer than that are lost, as with the test reference's own
 * 1e-4 of the scene). Closed meshes drop the triangles facing the light
 * (EP; STIN_DEBUG_VDSM_NO_EP keeps them); open ones, and materials marked
 * two_sided, keep them. Per light a pyramid over the light's view (desc.
 * shadows.map_size texels a side, at most 2048: two RG32F textures, the
 * second with its mip levels, and a depth-stencil texture, about 23 bytes a
 * texel of GL memory, made at stin_create; each frame draws it at the
 * power of two nearest half the viewport's larger side, at least 256 and
 * at most that: a finer one costs more fill than it culls) drops triangles
 * that lie wholly behind drawn triangles nearer the light (SM) and
 * triangles with no visible surface
 * behind them (DC), and ends each shadow face at the deepest visible
 * surface behind its triangle instead of infinity (DC): the same mask at any
 * map size. Its view looks from the light (along a directional one) at the
 * centre of the draws, at most 166 degrees wide; triangles outside it cast
 * as without these steps, and draws reaching behind a point or spot light
 * do not count as occluders there. The occluders' outlines need the mesh's
 * adjacency: vdsm keeps a GL_TRIANGLES_ADJACENCY index buffer per mesh (24
 * bytes a triangle of GL memory). STIN_DEBUG_VDSM_NO_SM and _NO_DC turn the
 * steps off. Blended casters
 * also draw their own face (what is behind them is in the position buffer).
 * Under depth-peel each peeled layer gets the buffer drawn from its own
 * surface first (see Transparency), so the layers' masks, and their
 * pyramids' receivers, are the layer's.
 * An area light (radius > 0, point or spot) is soft: per pixel 64 segments
 * to points of the light's disc (facing the pixel's point; a Vogel spiral
 * turned per pixel, so the penumbra takes 65 levels, not stacked copies of
 * the hard shadow), one bit each, ORed over every casting triangle
 * (glLogicOp into an RG32UI texture the size of the position buffer, 8
 * bytes a pixel of GL memory, made with its two programs at the first area
 * light; OpenGL ES has no logic op, so on ES 3.2 imageAtomicOr into an
 * R32UI image twice as wide, the same bytes, the same bits: below ES 3.2
 * the light's shadow is hard, logged); the light's visibility is the share of bits left clear. Each
 * triangle covers a screen rectangle holding its whole penumbra, at its
 * nearest depth, tested against the visible surface's; EP keeps a closed
 * mesh's triangles that face away from any point of the light; SM and DC
 * (the centre's pyramid) and the culling pass are left out. Mean |error|
 * over the penumbra of tests/scenes/shadow-soft.json against the
 * integrated disc: 0.011 (0.23 hard). Cost there, llvmpipe at 256 x 192:
 * 144 ms a frame against 12.7 ms for the same light as a point. In frames
 * with tessellated draws, or where its programs do not build, an area
 * light is shadowed from its centre (logged once). The steps run
 * in a culling pass of their own: per light a small geometry shader decides
 * each triangle and transform feedback keeps the faces of its volume the
 * eye sees (48 bytes each, in a GL buffer grown to 4 a casting triangle of
 * the frame: 192 bytes, and a quarter more; given back to that after 60
 * light passes in a row that needed under a quarter of it, never under
 * 48 KB), and the shadow polygons' geometry shader draws
 * those alone, one face an invocation, in one draw - from
 * the feedback object where the context has them (GL 4.0, the "transform
 * feedback objects" capability), else by a query's count read back (one
 * wait per light). Frames with tessellated draws, and
 * STIN_DEBUG_VDSM_ONE_PASS, cull and draw in one geometry shader; the mask
 * is the same. Cost: every triangle of every draw once per light through
 * the culling shader (twice more through the pyramid's light pass), the
 * kept ones through the shadow polygons' shader, plus the screen area of
 * their grown shadow faces, less those behind the visible surface: each
 * face carries its own depth and is tested LESS against the position
 * buffer's (depth clamped,
 * pulled toward the eye by a pixel's slope and 4 steps; the eye ray enters a
 * volume through a face it sees before it reaches a point inside, so the
 * mask is the same; STIN_DEBUG_VDSM_NO_DEPTH_TEST shades them all, for
 * measurement; needs depth clamping, core since GL 3.2);
 * STIN_DEBUG_VDSM_COUNT counts the emitted primitives (and the culling
 * passes' kept faces, one more wait per light). Without
 * its shaders or the mask it falls back (logged) to "volume" where there is
 * a stencil buffer, else "map-pcf"; without the pyramid's shaders or
 * framebuffer it runs without SM and DC (logged).
 * Measured choice of the exact technique: vdsm and volumes are both exact,
 * and which is cheaper depends on the GPU and the scene (on llvmpipe
 * volumes take 0.4-0.7x vdsm's frame; on a GPU it may be the other way).
 * Where the shadows technique is left on auto (desc.techniques[SHADOWS]
 * NONE), the selection chose vdsm, volumes run here (stencil, and the
 * lighting they need) and the context has timer queries (the "timer
 * queries" and "occlusion queries" capabilities), stin_create sets up
 * volumes beside vdsm (their state is in the block either way) and each
 * frame runs the cheaper by measured GPU time: the candidates are vdsm,
 * volumes extruded by the geometry shader and volumes built on the CPU (two
 * where GPU extrusion is not there). A GL_TIME_ELAPSED query spans each
 * shadowed frame's plan, each of its ends between two glFlush calls (a
 * renderer that defers drawing to the flush, as llvmpipe does, would
 * otherwise time a frame as its submission); its result is read a frame or more later, only
 * once GL_QUERY_RESULT_AVAILABLE says so (4 in flight at most: a frame
 * finding none free goes untimed; no frame waits for the GPU). The first
 * 8 frames run vdsm (a context's first frames build programs and buffers;
 * an application that draws a handful of frames keeps vdsm); then after
 * every desc.shadows.choice_frames frames of the chosen technique (default
 * 30) one frame runs the next other candidate as a trial (round robin),
 * and until every candidate has been timed three times one frame in two is
 * a trial (the first switch can come at frame 17). Each candidate's first
 * timed frame is dropped (it makes its buffers), the rest smoothed (a
 * quarter of each new frame's ms). The choice moves to a
 * candidate when its smoothed ms is at least 15% below the chosen one's
 * (x 1.15 still below it) on two of its trials in a row, so a small or noisy
 * difference never switches it and it does not flip back; each switch logs
 * STIN_LOG_TECHNIQUE_SELECTED naming both techniques and their ms. The
 * shadows choice (stin_query_choice) stays "vdsm", its reason saying that
 * frames are chosen by measurement; stin_frame_stats.shadows.choice_* say
 * what each frame ran. The lit programs are the same for both (one shadow
 * chunk): a switch builds nothing. A frame volumes would not draw the same
 * stays on vdsm and is not a trial: CSG products and displaced draws
 * (vdsm casts them exactly, volumes through a map), blended draws (peeled
 * layers are vdsm's receivers; transparent casters), area lights (vdsm
 * shadows them by 64 segments a pixel, volumes by samples), or a target without
 * a stencil buffer; where such a frame follows a volume frame, the
 * projection already given out at begin (P_inf) stays, and vdsm draws with
 * it (exact either way), and the frames after begin on vdsm until one can
 * run volumes again. Forcing a shadows technique, a tier without vdsm, or
 * STIN_DEBUG_SHADOW_CHOICE_OFF keeps the selection's technique on every
 * frame: no trial, no switch.
 * "map-pcf": depth maps through an FBO, a receiver-plane bias and a 1/3/5-tap
 * kernel of hardware 2x2 compares (the light's pcf_kernel) in the lit shader;
 * without shadow compare (STIN_CAP_SHADOW: OpenGL ES 2.0, whose samplers
 * cannot compare) the maps are depth textures read as numbers (GL_NEAREST,
 * unsized GL_DEPTH_COMPONENT as OES_depth_texture takes them) and each tap
 * does the 2x2 compare in the shader: the four texels around it, each lit
 * where the reference (clamped to [0,1]) is at most its depth, weighted
 * bilinearly as GL_LINEAR weights them, so the kernel, the biases and the
 * bounds are the same. Without depth textures (STIN_CAP_DEPTH_TEXTURE:
 * bare ES 2.0) each map is an RGBA8 colour texture (unsized GL_RGBA) that
 * holds the casters' window depth in 24 bits (R high, B low, A 1), drawn
 * with a depth renderbuffer of its size beside it (GL_DEPTH_COMPONENT16 on
 * ES 2.0, 24 elsewhere: it only picks the nearest caster; the stored depth
 * is the fragment's own, in 24 bits), and each tap unpacks the four texels
 * and compares as above: the same kernel, biases and bounds. The packing
 * needs a highp fragment float (24-bit significand; ES 2.0 parts without
 * GL_FRAGMENT_PRECISION_HIGH round it). Displaced draws are drawn into
 * packed maps like any caster; CSG products are not yet (their resolve
 * writes depth only: they cast nothing there; bare ES 2.0's packed GPU
 * resolve has no depth texture to resolve them from a light anyway);
 * point lights get six 90-degree maps drawn before their pass into one
 * atlas (3 x 2 faces, one sampler; the face size halved while three faces
 * exceed GL_MAX_TEXTURE_SIZE), each face with only the casters whose bounds
 * meet its frustum, a face no visible draw's bounds reach not drawn at all,
 * and the kernel's taps kept inside the face's cell. A point whose
 * side the eye sees turns away from the light, by its facet and by its
 * shading normal, is in its own shadow, without a lookup (as the test
 * reference decides). On a triangle whose vertex normals bend away from its
 * facet the lookup starts from the point on the surface those normals
 * describe (vdsm's terminator rule, above; the lit vertex stage hands the
 * corners' tangent planes on as three more varyings, interpolated exactly),
 * so a low-poly sphere's lit side has no terminator steps; flat triangles
 * and displaced draws look up from their own point. The others compare, at each
 * tap, the depth of their own plane there (receiver-plane depth bias, from
 * the screen derivatives), so no tap of the kernel shadows a sloped
 * receiver with itself. Only where the light grazes the receiver (the
 * cosine under 0.3) is the point also moved along its geometric normal
 * toward the eye, by up to 1.5 texels' width of the map where the point is
 * (all of it under 0.1): 3 d / size for a point light (d the point's
 * distance from the light along the face's axis, its largest coordinate
 * difference), 3 d tan(cutoff + 1 degree) / size for a spot (d along its
 * direction), 3 h / size for a directional light (h the map's half-width:
 * the receivers in view, rounded up to a power of two). A receiver facing
 * the light is not moved, so a caster just above it across a thin gap
 * still shadows it (tests/image/model_test.c, "map-pcf-gap": shadowed at
 * 1.25 and 0.8 times the full push), and the side of a fin lit at an angle
 * keeps its shadow edge where the next fin puts it.
 * An area light (radius > 0, point or spot; a directional light has no
 * radius) gets percentage-closer soft shadows in place of the kernel: 16
 * taps search the region the light's disc spans in the map between the
 * receiver and half its distance from the light, each tap's blocker depth
 * found by 5 bisecting compares; 48 taps over the disc the mean blocker
 * gives (a Vogel spiral turned per pixel, so the penumbra takes many
 * levels; the disc stretched as it faces the receiver) average their
 * compares. Exact for one flat blocker; where blockers lie at several
 * depths (a sphere, a post under a table) the mean widens or narrows the
 * penumbra. Mean |error| over the penumbra of tests/scenes/shadow-soft.json
 * against the integrated disc: 0.027 (0.21 when the radius was ignored);
 * cost there, llvmpipe at 256 x 192 with a 1024 map: 55 ms a frame
 * against 14 ms for the same light as a point. Radius 0 keeps the kernel
 * above, unchanged.
 * Fixed-function shadow maps: spot lights get one map over the
 * cone, directional lights one orthographic map, point lights six 90-degree
 * maps with "map-depth" where there are FBOs (drawn mid-frame, one face at a
 * time, each kept to its square by a mask texture unit); otherwise a point
 * light falls back to volumes where there is a stencil buffer and says so.
 * "map-depth" uses ARB_depth_texture + ARB_shadow, compare LEQUAL with
 * LINEAR filtering (2x2 PCF), polygon offset per light (shadow_offset,
 * default factor 1.1, units 4). A depth map alone lights an open surface
 * (a shell seen through its opening, a one-sided quad from behind) where
 * the eye sees the side the light does not: the surface is its own nearest
 * caster. So map-depth draws a second pass per map, without polygon offset
 * (which would push a steep front face behind the back face under it near
 * the light's silhouette), writing by two-sided lighting which side of the
 * nearest surface the light sees into two LUMINANCE8 side maps (one lit
 * where the light sees front faces, one where it sees back faces, both lit
 * where it sees no surface, as the depth map is), and draws each lit pass
 * twice with face culling, once per side the eye sees, that side's map on
 * the texture unit after the depth compare's (NEAREST): a fragment is lit
 * only where the eye and the light see the same side, as volumes and the
 * test reference decide. Within about a texel of the light's silhouette (the
 * terminator) the side map may name the neighbouring facet's side. Without
 * a spare texture unit the side test is left out (logged at create).
 * The terminator test (where a texture unit is spare after the side
 * test's and the point-light faces' mask; else logged at create and the
 * facet decides as above) gives each receiver draw its own rule, with FBOs
 * or without. Closed solids (a closed mesh whose material is not
 * two_sided, at least 1.5 texels across along each axis of its bounds:
 * a texel's width, at the map's far plane for a spot light) cast
 * through second-depth maps: only their faces turned away from the light
 * are drawn (at half the offset's slope factor), so a solid's lit side
 * compares against its own far side and a pixel whose facet turns from the
 * light against itself. Open casters (floors, two_sided materials) and CSG
 * products keep both sides and the ordinary offset. The side map holds an
 * open caster's side as above and, for a solid, the light's diffuse term at
 * its far faces' vertex normals (saturated at N.L = 1/8). A solid seen from
 * outside is lit where the depth test passes and either the stored surface
 * lies 1.5 texels' depth behind it (a second lookup of the same map, pushed
 * back: its lit side) or its shading normal faces the light (N.L above
 * about 1/64; an alpha test on the sum): the band between a facet turned
 * from the light and a shading normal turned to it is lit (no terminator
 * steps, no acne on a solid's lit side: tests/image/terminator_test.c, 0 of
 * 7,938-13,478 pixels with N.L > 0.05 shadowed where up to 1,000 were) and
 * the side turned from the light keeps its shadow. On a very coarse smooth
 * mesh this lights more than the reference's rule (four-lights' octahedron,
 * whose vertex normals turn 55 degrees from its faces). Every other
 * receiver (open surfaces, CSG products, a solid seen from inside) keeps
 * the facet: an open surface's own back, which the light sees through an
 * opening at a slope, is stored with the full offset, deeper than the
 * 1.5-texel margin, and would pass for a far side. So does a solid thinner
 * than 1.5 texels: its lit side would compare with its own far side within
 * the margin (a 0.05-thick slab under a 128-texel map without FBOs, whose
 * texel is 0.125 wide: 5.3% of spheres-18k-sun's pixels shadowed on its
 * lit top before the solid's size was checked).
 * "map-combine" has no side test: it lights such surfaces. It keeps
 * first-depth maps and the facet (terminator steps, and stripes where a
 * receiver grazes the light; logged at create). A second-depth map alone
 * (every solid's far faces) clears its terminator (the checks' directional
 * light: box 542, cylinder 481 pixels shadowed on the lit side, then 0),
 * but its bias is one plane in the light's depth, as deep as a sphere
 * resting on a floor is tall at 128 texels: spheres-18k-sun's floor under
 * the spheres came out lit (45.6% of the shadowed pixels shadowed, where
 * 66.1% are and the bound is 50%), and every solid's side turned from the
 * light, compared with itself, would be lit. map-depth's rule needs two
 * more tests joined to the depth comparison (the side, and the far side by
 * a margin); the combiners clamp each stage and only the alpha test
 * thresholds, once, so map-combine cannot join a second comparison in one
 * pass.
 * "map-combine" needs only texture_env_combine:
 * the light's depth drawn as an 8-bit ramp over a near/far fitted to the draws,
 * compared in the combiner, kept by the alpha test. Its bias (1.5 ramp steps
 * plus two texels' depth per texel of slope, a plane in the light's depth)
 * cannot follow each receiver's slope as polygon offset does: surfaces lit at
 * more than about 75 degrees from their normal (N.L under 0.25) can shadow
 * themselves in stripes; use map-depth or map-pcf where they matter. Maps are desc.shadows.map_size
 * texels a side where the context has FBOs; without them they are drawn in the
 * frame's own framebuffer before its clear and so are at most the viewport's
 * largest power of two (stin_frame_stats.shadows.map_size says what was used).
 * Spot maps cover the cone; directional maps are orthographic, their square
 * fitted to the draws the camera sees and their depth to every caster. Area
 * lights are hard-shadowed by maps. Each of the
 * desc.max_lights light slots holds a map of shadows.map_size squared texels
 * (4 bytes each), made at stin_create: size max_lights to the scene.
 * map-depth's side test adds two bytes a texel to each slot (and to the six
 * point-light faces), and with FBOs one RGBA8 colour and one 24-bit depth
 * texture of the map's size that its side passes share.
 * Volumes: silhouettes from the adjacency built at
 * mesh creation, extracted on the CPU each frame into the block (GL1, GL2),
 * or on GL4 by a geometry shader from each mesh's GL_TRIANGLES_ADJACENCY
 * index buffer (24 bytes of GL memory a triangle, made at mesh creation;
 * no CPU work per caster triangle; STIN_DEBUG_VOLUME_CPU turns it off); z-pass per
 * caster where the near-clip region cannot reach its volume, else z-fail with
 * caps; two-sided stencil with wrap in one pass where present, else two culled
 * passes; casters that are not closed 2-manifolds get generalised volumes (each
 * triangle's own, so open and non-manifold meshes cast without leaks).
 * The terminator rule (see vdsm) on every tier: a visible pixel of a
 * closed mesh whose facet turns away from the light lies inside that mesh's
 * volume exactly once, so after each light's (or sample's) volumes are
 * counted, one more pass draws the closed, smooth, undisplaced opaque
 * casters with depth EQUAL, keeps only the fragments of the light's
 * terminator band (facet turned away from the light by its screen
 * derivatives, shading normal toward it, the curved surface above the
 * facet) and decrements the count there, clamped at zero: the band is lit
 * where nothing else lies between it and the light, and a low-poly
 * sphere's lit side has no steps. It tests from the surface point, the rule
 * from the curved surface above it (a fraction of a facet apart): on the
 * repository's scenes they differ on at most one pixel a scene, where a
 * shadow edge or the mesh's own neighbouring facets pass between the two
 * (tests/image/shadow_test.c bounds it at 0.01%). Its cost, per light
 * (sample) and such caster: a look at each triangle on the CPU (is a
 * corner's normal turned otherwise than the facet, seen from the light?)
 * and a draw of the thin ring of triangles that passes; on llvmpipe
 * (stin-bench --shadows, spheres-18k and terminator-sphere, 1 and 4 lights,
 * GL2 and GL4) the frame's time stays within its run-to-run noise (5%).
 * GL1's fixed function has no shading normal per pixel: there the CPU
 * keeps a ring triangle only where its facet turns away from the light
 * (constant over a facet), every corner normal lies on the side of the
 * facet the eye sees and the curved surface lies above the facet on the
 * whole triangle (else it keeps its facet: a concave corner, a saddle),
 * and draws it in immediate mode, lighting and texturing off, each corner
 * coloured with an alpha that the alpha test (GL_GREATER, a quarter of an
 * 8-bit step under one half) compares: the corners' values are set so
 * their blend turns where the rule does on the two edges it crosses
 * (false position on each edge), exact for a directional light and for a
 * cylinder, else off by the bend of the rule's curve inside the
 * triangle. On the repository's scenes GL1 then differs from the test
 * reference on no more pixels than the GLSL tiers (band pixels: at most 2
 * a scene where GLSL has 1, within shadow_test.c's 0.01%). The alpha test
 * goes back off, its function to GL_ALWAYS, after each band draw; the current
 * colour is left as the last corner's (the frame gives back the
 * caller's). Its cost at GL1 (spheres-18k, 102 casters, 1 point light):
 * 5,474 ring candidates, 1,084 drawn, 1.2 ms of CPU and immediate-mode
 * calls a frame; stin-bench --shadows (1 and 4 lights) stays within its
 * run-to-run noise, and a context's first frame pays the driver's build of
 * the alpha-tested pipeline once (llvmpipe: about 15 ms more shadow stage
 * in stin-render --stage-times). Open meshes (not closed 2-manifolds:
 * each triangle has its own volume, so a point's count is the number of
 * triangles between it and the light, its own averted facet included)
 * follow the rule too: a band pixel's count holds its own facet once and,
 * where its ray leaves the mesh through a light-facing neighbour, that
 * neighbour once more; near the mesh's open edge the ray may leave
 * through the hole instead. So the band takes back its own facet's count
 * and one more only where the pixel lies inside the volume of a
 * light-facing triangle of the ring around the band (those sharing a
 * corner with a band triangle or with one of its edge neighbours): the
 * ring's volumes are built on the CPU and drawn with z-fail and
 * GL_INVERT into stencil bit 0x40 (its parity; the counts must stay below
 * 64 at band pixels), the band decrements where that bit is set and a
 * count is left, and the ring's volumes drawn again clear it. A ray that
 * leaves beyond the ring keeps its count (the facet's step, shadowed), and
 * a pixel whose ray leaves through the hole is lit only where nothing else
 * lies between it and the light. (Limit: a ray that leaves through the hole
 * and then crosses a ring triangle farther along the same mesh, a bowl's
 * band facing its own far rim, would have that crossing taken back too.)
 * On tests/scenes/terminator/open-can.json
 * (an open 12-slice cylinder and a box shadowing its rim) volumes agree
 * with the reference's rule on every pixel off a shadow edge on GL1,
 * GL2 and GL4. Its cost per light (sample) and open smooth caster: three
 * looks at each triangle on the CPU (the band, the ring twice), two band
 * draws and the ring's volumes (8 triangles each) twice; with fewer than 8
 * stencil bits, or a band list larger than the frame scratch, only the own
 * count is taken back.
 * With a
 * perspective projection the frame is drawn with the far plane at infinity
 * (stin_query_frame_projection), so geometry past the caller's far plane shows;
 * orthographic projections use depth clamp. Each volume is cut at a plane
 * across its light's rays just past every visible draw's bounds and the eye,
 * and closed there (instead of running to the horizon: less fill, the same
 * count on every visible pixel); a volume whose cut hull misses the view is
 * not drawn (stats.shadows.volume_cut_casters, volume_culled_casters). A
 * keep_contents frame, whose depth may hold the caller's own surfaces, keeps
 * every volume to infinity, as STIN_DEBUG_VOLUME_UNBOUNDED does. Lights with
 * radius > 0 are area lights, a ball of that radius: desc.shadows.soft_samples
 * point samples inside it (stin_light_sample; default 32), each a stencil
 * count, their shares (whole 255ths summing to 1) adding up to the light's
 * visible fraction. On shadow-soft.json the penumbra's visibility is within
 * 0.025 of the integrated light on average, in 43 distinct values (8
 * samples on the sphere gave 0.078 in 9). Where the screen mask below is
 * drawn, the shares add up in the light's channel and one lit pass shades
 * the light at its centre; elsewhere (GL1, no masks) the shares add up in
 * the frame's destination alpha where its framebuffer has 8 alpha bits
 * (compatibility contexts, or a framebuffer object's first colour
 * attachment on core ones), one lit pass blended by it, and the alpha set
 * back to 1 on the opaque draws. Without alpha bits each sample is a lit
 * pass at its share of the intensity, each rounded to 8 bits, so a lit
 * surface may be a few 255ths off in sum, in bands (on shadow-soft 0.021
 * on average at 32 samples against 0.0017 through alpha).
 * Lights with range > 0 are scissored to their screen extent.
 * On GLSL tiers with FBOs and packed depth-stencil textures (GL 3.0,
 * ARB_framebuffer_object or EXT_packed_depth_stencil) and a texture unit to
 * spare, a frame of two or more lights, or of an area light, counts each
 * light's visibility in stin's own screen mask (an RGBA8 colour and a DEPTH24_STENCIL8 texture
 * the size of the viewport's far corner, 8 bytes a pixel of GL memory, made
 * at the first such frame and kept; its depth is a geometry pass of its own)
 * and one lit pass shades four lights reading their channels, so N lights
 * cost N stencil counts (an area light one a sample) and N/4 lit passes. A
 * frame of one point light, and any frame without masks, stencil-tests each
 * light's lit pass in the frame's framebuffer (one geometry pass fewer than
 * the mask).
 * An incomplete mask framebuffer is logged once and the context goes on
 * without masks.
 * Stencil and depth belong to a framebuffer, not to the context. stin_create
 * chooses "volume" where the framebuffer bound then or the default one has
 * a stencil buffer (so a stencil-less framebuffer left bound, e.g. by an
 * earlier frame, does not decide for every later frame). Each frame probes
 * its own framebuffer (desc.framebuffer; the bits are read again only when
 * a frame names another framebuffer than the one probed last): a frame into
 * one without a stencil buffer draws without shadows and without the point
 * lights' volume fallback of the fixed-function maps, logged (FALLBACK) when
 * the frames' target changes to it; stin_query_choice keeps the context's
 * choice.
 *
 * MULTISAMPLED TARGETS
 * A frame draws into a multisampled framebuffer (GL_SAMPLE_BUFFERS > 0:
 * a framebuffer object with multisampled renderbuffers, or a multisampled
 * default framebuffer) as GL draws there: every pass is rasterised per
 * sample, each fragment shaded once a pixel a surface at the pixel centre,
 * and depth, stencil and the blend per sample. What each technique's
 * visibility is per sample:
 * - "volume": the stencil counts in the frame's own stencil are per sample
 *   (one light, GL1, no masks); through the screen mask see below.
 * - "map-pcf", "map-depth", "map-combine", "deep", "coloured": looked up
 *   in the lit pass at the fragment's own surface point (the pixel centre
 *   on that surface), so a sample never takes another surface's. (Tested
 *   for map-pcf, map-depth, map-combine, deep and coloured; the
 *   fixed-function maps drawn in the frame's own buffer, without FBOs, are
 *   not tested into a multisampled default framebuffer.) Where that point
 *   lies beyond its surface's edge as the light sees it (the pixel centre
 *   past an outline), map-depth's depth map holds no surface there and its
 *   side test (shadow/map_facing.c) counts no surface as lit from either
 *   side, so the fragment is lit as the reference lights it (it was lit at
 *   half strength before: a dim rim, 101 of 711 silhouette-band pixels).
 * - "vdsm", and "volume" through the screen mask (two or more lights, or
 *   an area light, on GLSL tiers): the mask and vdsm's position buffer stay
 *   single-sampled, one surface a pixel, the one at its centre. Where the
 *   target is multisampled the lit pass also reads the depth the mask was
 *   decided against (the mask's own, or vdsm's position buffer's, where
 *   CSG products' faces write theirs as draws do) on one more texture
 *   unit (the one after displacement's), and where the
 *   fragment's depth is not within 16 steps of 24 bits of it, the fragment
 *   belongs to a surface that covers some samples but not the centre (a
 *   silhouette): it reads the neighbouring texel (of the 3 x 3) whose depth
 *   is nearest its own, its own surface one pixel on. So no sample takes the
 *   visibility of the surface in front of or behind it (no halo or dark
 *   rim); where a shadow edge of the fragment's own surface meets the
 *   silhouette, the visibility is that surface's one pixel away (a one-pixel
 *   bound, as any per-pixel shading). Without a unit to spare (the unit
 *   limit reached) the mask is read at the pixel as in a single-sampled
 *   target. Measured (tests/image/msaa_test.c, 4 samples): 0 of 698
 *   silhouette-band pixels beyond 0.03 of the reference shaded at the
 *   target's sample positions, against 125 (up to 0.21) reading the mask at
 *   the pixel.
 * - Depth peeling ("depth-peel", "dual-peel") peels and lights its layers
 *   single-sampled, one surface a pixel, the one at its centre. Into a
 *   multisampled target with a stencil the blended draws are drawn once
 *   more into the frame's target before the composite (depth LESS with
 *   writes, no colour: one more pass), marking in its stencil each sample
 *   a blended surface covers in front of the opaque ones; the composite
 *   then colours only those samples (the frame's depth there becomes the
 *   nearest blended surface's, per sample), with the layers of the
 *   pixel's centre, or where the centre has none, of the nearest
 *   neighbouring pixel (edges first, then corners) that has some. So the
 *   silhouette of a blended surface over an opaque one or the background
 *   is antialiased, and no sample of an opaque surface in front of or
 *   beside a blended one takes its colour. What stays once a pixel, a
 *   one-pixel bound: a covered sample takes the whole stack of layers at
 *   the centre (or that neighbour's), so the edge of a blended surface
 *   over or seen through another blended surface is not antialiased, and
 *   where three surfaces meet a sample may take a layer it does not see.
 *   Measured (tests/image/msaa_blend_test.c, 4 samples, two panes over a
 *   floor): 3 of 1,325 silhouette-band pixels beyond 0.03 of the
 *   reference composite at the target's sample positions, against 190 (up
 *   to 0.25) with the composite over every sample; at the panes' inner
 *   edges 33 of 114. The stencil is the frame's to overwrite (GL STATE);
 *   a multisampled target without one gets the composite over every
 *   sample, as before. "sorted" blends per sample; deep's light-space
 *   layers do not depend on the target.
 * - surface ("normal", "parallax", "pom", GL1's "dot3") and displacement
 *   ("displace", "displace-tess"): shaded once a pixel a surface at the
 *   pixel centre as any fragment (the uv moved there; displaced vertices
 *   give each sample its coverage and depth); their own passes read no
 *   single-sampled screen buffer, so their outlines are antialiased.
 *   Tested (tests/image/msaa_surface_test.c, msaa_displace_test.c: 2-3 of
 *   897-1,006 silhouette-band pixels beyond the bound; GL2's displace with
 *   shadows off), as are area lights under vdsm, volume and map-pcf, and
 *   GL1's volume (msaa_test.c: 0 of 642). GL2's pom
 *   takes its texture level from derivatives of the uv it moved, so it
 *   follows the rasteriser's 2x2 quads (llvmpipe's multisampled path
 *   differences at a quad's lower-left pixel, its single-sampled one at
 *   the upper-left).
 * - CSG products (the GPU resolve: GLSL tiers with FBOs and packed
 *   depth-stencil textures, every CSG technique): the resolve runs
 *   single-sampled (one depth a pixel, at its centre) in its work buffer,
 *   never in place or direct, and the products' faces are then snapped into
 *   the multisampled frame so that each sample gets its own face's depth
 *   (which the lit passes meet, depth EQUAL, per sample). A face's fragment
 *   at a pixel a triangle edge crosses carries its plane's depth at the
 *   centre, not the depth of the triangle the resolve rasterised there, so
 *   the snap keeps it where (1) an id pass (single-sampled, once a resolve:
 *   an RGBA8 texture of 4 bytes a window pixel, in
 *   stin_frame_stats.csg.gpu_bytes) says the centre's surface is the same
 *   face set's (primitive and side) and (2) its depth there lies within the
 *   resolve's band plus one pixel of its own depth slope (|dz/dx| +
 *   |dz/dy|); at a pixel whose centre shows no product (a silhouette), where
 *   its plane meets the same face set's surface at a neighbouring pixel's
 *   centre (of the 3 x 3). So there are no lines along triangle edges and
 *   the products' silhouettes are antialiased. The bound: where two
 *   primitives of a product meet (a cavity's rim) the pixel is decided at
 *   its centre, as in a single-sampled target (that edge is not
 *   antialiased, each sample still gets its own face's depth), and at a
 *   silhouette a face may cover the samples of one pixel more where the
 *   product is cut off there. Measured (tests/image/msaa_csg_test.c, 4
 *   samples, a cube minus a sphere): 17 of 17,448 pixels away from edges
 *   beyond 0.06 of the reference at the target's sample positions, against
 *   597 snapping at the centre (STIN_DEBUG_CSG_SNAP_AT_CENTRE). The
 *   products cast into the lights' maps as in a single-sampled frame (the
 *   maps' own resolves). The read-back resolve (GL1 tiers, or
 *   STIN_DEBUG_CSG_READBACK on a compatibility context) cannot read a
 *   multisampled framebuffer object: it blits the frame's depth and
 *   stencil (one sample a pixel) into the GPU resolve's single-sampled
 *   work framebuffer and resolves there, then draws the products' faces
 *   into the frame kept within a band about the result (8 steps of a
 *   24-bit depth plus twice the result's depth change to the next pixel;
 *   beside the outline, the neighbours' bands) with fixed-function depth
 *   and stencil tests: the farthest face at or behind the band's near
 *   bound, or where that is beyond its far bound the nearest before it;
 *   the band's bounds go in as a quad a pixel (glDrawPixels writes one
 *   sample a pixel on llvmpipe). So each sample takes its own face's
 *   depth, as the GPU resolve's snap gives it. It needs framebuffer
 *   objects, packed depth-stencil, depth textures, a framebuffer blit (GL
 *   3.0, ARB_framebuffer_object or EXT_framebuffer_blit), fixed function,
 *   and 13 bytes of texture staging a pixel (the CPU resolve's 9 and the
 *   frame's depth; short of it the products are not drawn, logged once).
 *   Measured (gl21's GL1 tier, volumes, the cavity left out): 8 of 14,986
 *   pixels away from edges beyond 0.06, 4 of 792 silhouette-band pixels;
 *   one depth a pixel (STIN_DEBUG_CSG_SNAP_AT_CENTRE) 1,099 and 311.
 *   Where the context lacks one of those (the GL 1.x profiles hide
 *   framebuffer objects) stin_draw_csg into a multisampled target is
 *   refused, STIN_ERROR_UNSUPPORTED, logged (TECHNIQUE_UNSUPPORTED, naming
 *   what it needs), the product dropped (stin_frame_stats.csg.dropped);
 *   render those into a single-sampled target.
 * The visibility export's map and the outline are drawn from the
 * single-sampled mask and buffers: one value a pixel. The outline's screen
 * pass blends over every sample, so it lies over the antialiased frame on
 * the pixels it marks in a single-sampled target (tested:
 * tests/image/msaa_outline_test.c, 0 of 698 band pixels beyond 0.03).
 * Tested (tests/image/msaa_test.c) at 4 samples for vdsm, volume and
 * map-pcf on GL4, volume and map-pcf on GL2, volume on GL1; at 2 and 8
 * samples, where GL_MAX_SAMPLES has them, for vdsm, GL2's map-pcf and
 * GL1's volume (llvmpipe has at most 4 and allocates 2 as 4); in a 4x sRGB
 * target (tests/image/srgb_test.c) for vdsm, GL2's and GL1's volume.
 *
 * GL STATE
 * stin_end_frame() binds desc->framebuffer (GL 3.0/FBO contexts), sets the
 * viewport, and on return leaves these at their GL defaults: depth test off,
 * depth mask on, depth func LESS, blending off with blend function ONE/ZERO,
 * stencil test off, stencil mask all ones, stencil func ALWAYS/0/all ones and
 * stencil ops KEEP on both faces, front face CCW, cull face BACK and off,
 * colour mask all on, scissor off, current program 0, texture unit 0 active
 * with no texture bound, array buffer 0, vertex array 0's element buffer 0,
 * all client arrays disabled with client unit 0 active (GL1), alpha function
 * ALWAYS/0 (GL1), and the state below that no pass of stin sets but every
 * pass relies on, which the frame also establishes before its first draw:
 * blend equation ADD (GL 1.4+), polygon mode FILL on both faces, depth range
 * 0..1, logic op, polygon smooth, user clip planes (clip distances) 0-7,
 * sample alpha-to-coverage, alpha-to-one and coverage (GL 1.3+), rasterizer
 * discard (3.0+), primitive restart (3.1+; fixed index 4.3+, ES 3.0+ but
 * not WebGL 2, where it is always on) and sample mask (3.2+) off, no sampler object on texture units 0-15 (3.3+), and on
 * compatibility contexts alpha test and polygon stipple off. So a caller may
 * leave any of it set: the frame's pixels do not change (tests/image
 * hostile_test.c renders under each such state and compares bit for bit).
 * Where there are vertex array objects the frame draws with
 * vertex array 0 or its own, never through the caller's, and binds the
 * caller's again at the end. Under vdsm (GL 3.2+) the frame leaves no
 * buffer on the generic transform feedback buffer binding, and none on
 * binding 0 of the bound feedback object, which is object 0 where the
 * context has feedback objects (GL 4.0).
 * Under vdsm with an area light on OpenGL ES 3.2 it leaves image unit 0
 * with no texture (the soft pass ORs its bits by image atomics there).
 * The viewport and the framebuffer binding stay as the frame set them; the
 * caller's matrices (GL1 matrix stacks) are restored. Clear colour, clear
 * depth and the polygon offset factor and units are overwritten, and so are
 * the scissor box and the stencil buffer's contents; depth clamp and polygon
 * offset fill (though the frame's passes set them) and the stencil clear
 * value are the caller's again.
 * State that would turn stin's own GL work into something else is set
 * aside for the frame (and for stin_create) and given back: a bound pixel
 * unpack or pack buffer (GL 2.1), a query buffer (GL 4.4,
 * ARB_query_buffer_object), a program pipeline object (GL 4.1,
 * ARB_separate_shader_objects), fragment and read colour clamping (GL 3.0,
 * ARB_color_buffer_float; FIXED_ONLY meanwhile) and the provoking vertex
 * (GL 3.2, ARB/EXT_provoking_vertex; LAST meanwhile).
 * A query of the caller's left active across a frame stays the caller's
 * and counts the frame's own work; stin begins none of its own on that
 * target. Under a samples-passed (or any-samples-passed) query peeling
 * runs to its layer limit (transparency.layers, translucent.deep_layers)
 * without the stop at the first empty layer and the CSG resolve reads its
 * stencil back instead of counting it (the same picture, slower), and
 * interval hands its products to scs or goldfeather for the frame (logged
 * once, as for a primitive with too many crossings).
 * Under a primitives-generated query stin_frame_stats' volume and vdsm
 * primitive counts stay 0; under a transform-feedback-primitives-written
 * query vdsm without feedback objects (GL 3.x) draws its casters without
 * the culling pass; under a time-elapsed query the measured shadow choice
 * times no frame.
 * On the GL1 tier the frame saves the caller's fixed-function state with one
 * level of the attribute stack (glPushAttrib of the current, lighting,
 * transform, enable, texture and pixel-mode groups) and one level of each
 * unit's texture-matrix stack, draws from GL's defaults (no program bound,
 * texturing, texture coordinate generation, fog, colour material and colour
 * sum off, identity texture matrices, no pixel-transfer scale or bias,
 * client arrays off) and restores it before the list above is applied:
 * lights, materials, light model, shade model, normalize, fog, matrix mode,
 * current colour, pixel transfer, and every texture unit's bindings,
 * environment, coordinate generation, matrix and enables are the caller's
 * again. Leave one level of the attribute stack and of each texture-matrix
 * stack free for it. ARB assembly programs (GL_VERTEX_PROGRAM_ARB,
 * GL_FRAGMENT_PROGRAM_ARB) must be off when a GL1 frame runs.
 * With a GLSL technique, the texture units a frame used (the surface
 * technique's units 1 and 2, the shadow maps' units) are left with no 2D,
 * 1D or cube-map texture bound; their 2D-array bindings (deep maps,
 * peeling, interval; GL 3.0) are the caller's again. On GL 4.3 a frame that used shader storage
 * buffers (deep's early-stop flag: binding point 0; vdsm's CSG product
 * shadows: points 0-2; vdsm's receivers, stin_frame_stats.
 * shadows.vdsm_atomic_receivers: point 0) leaves those binding points and the
 * generic GL_SHADER_STORAGE_BUFFER binding at 0.
 * Every other piece of GL state is left as the caller had it (multisampling
 * too: the frame honours it as the target's; MULTISAMPLED TARGETS above
 * says how each technique does).
 * sRGB targets: stin never enables GL_FRAMEBUFFER_SRGB. Into a target whose
 * colour is sRGB-encoded (GL_SRGB8_ALPHA8) with the caller's
 * GL_FRAMEBUFFER_SRGB on, a beauty frame lights in linear space and GL
 * encodes each write once; the ambient pass and every light's pass (volumes,
 * the GL1 passes, blended draws) blend in linear space, as GL decodes the
 * stored value before it blends. stin's own render targets (maps, screen
 * masks, position buffers, peeling layers, CSG results, the visibility map)
 * are linear formats, which GL never encodes whatever the enable; stin
 * copies no colour from an FBO target's frame and reads back only depth and
 * stencil. A frame with STIN_OUTPUT_NORMAL or STIN_OUTPUT_VISIBILITY writes
 * data, not colour: it turns GL_FRAMEBUFFER_SRGB off for the frame and gives
 * the caller's enable back (GL 3.0, ARB/EXT_framebuffer_sRGB). The GL1 tier
 * draws the same way: GL 1.x itself has no sRGB framebuffers, but on a
 * context that has them (GL 2.1 with the extensions, or 3.0+) the
 * fixed-function output is encoded by GL like any other, and tested so
 * (tests/image/srgb_test.c). Without framebuffer objects the fixed-function
 * maps are drawn in the frame's own colour buffer and copied; an
 * sRGB-encoding default framebuffer would encode them, which is untested.
 * A multisampled sRGB target: the beauty frame is written encoded per
 * sample, and a resolve (glBlitFramebuffer) with GL_FRAMEBUFFER_SRGB on
 * averages the samples in linear space, as it should for colour. A data
 * frame's samples are stored unencoded: resolve it with the enable off, or
 * a silhouette pixel's samples are decoded, averaged and encoded as if
 * colour (stin_platform_read_data does so).
 * stin_create_mesh leaves the array buffer and vertex array 0's element
 * buffer at 0, stin_update_mesh the array buffer; the caller's vertex array
 * object stays bound and untouched.
 * stin_create_texture leaves every binding as it found it (the active
 * unit's 2D texture included) and reads `pixels` as tightly packed client
 * memory whatever the caller's unpack state: alignment, row length, skip
 * rows and pixels and (GL 2.1+) a bound pixel unpack buffer are set for the
 * upload and restored after. stin_create and the destroy calls create or
 * delete GL objects and leave every binding as they found it (stin_create
 * sets aside the vertex array, array buffer, active unit, unit 0's 2D,
 * 2D-array and cube-map textures and the state above for its set-up).
 * Queries touch no GL.
 * On OpenGL ES (2.0, 3.0-3.2) the contract is the same for the state ES
 * has. stin_end_frame leaves depth test off, depth mask on, depth func LESS,
 * blending off with ONE/ZERO and equation ADD, stencil test off with mask
 * all ones, func ALWAYS/0/all ones and ops KEEP on both faces, front face
 * CCW, cull face BACK and off, colour mask all on, scissor off, program 0,
 * unit 0 active with no 2D texture bound, array buffer 0 and vertex array
 * 0's element buffer 0, and establishes before its first draw depth range
 * 0..1 (glDepthRangef), sample alpha-to-coverage and coverage off and, on
 * ES 3.0+, rasterizer discard and fixed-index primitive restart off and no
 * sampler object on units 0-15 (ES 3.1+: sample mask off). Polygon offset
 * fill and the stencil clear value are the caller's again; clear colour,
 * clear depth (glClearDepthf), the polygon offset factor and units, the
 * scissor box and the stencil contents are overwritten. Set aside and given
 * back on ES 3.0+: a bound pixel pack or unpack buffer and the 2D-array
 * textures of units 0-7. GL_FRAMEBUFFER_SRGB exists on ES only with
 * EXT_sRGB_write_control: with it a data frame turns it off and gives it
 * back as on desktop GL; without it an sRGB target always encodes (a data
 * frame into one is encoded too). The desktop states (logic op, polygon
 * mode and smooth, depth clamp, clip distances, alpha test, stipple,
 * primitive restart by index, colour clamping, the provoking vertex, query
 * buffers, samples-passed queries, fixed function) do not exist on ES and
 * stin neither reads nor sets them there; program pipelines (ES 3.1) and
 * storage-buffer bindings are not set aside on ES (stin's ES paths bind
 * neither). Tested on es30 and es32 (tests/image/hostile_test.c, the 18
 * states ES has, one at a time and all at once, bit for bit).
 *
 * GL ERRORS
 * stin raises no GL error: it asks the driver only for limits that the GL
 * version or a listed extension defines, and refuses (with a log line) what
 * GL would refuse, such as a program whose uniforms do not fit
 * stin_bind_visibility's chunk. It never calls glGetError, in either build,
 * so an error the caller left pending is still the caller's to read after
 * any stin call. To watch for GL errors, install a KHR_debug callback (the
 * image tests do, and fail on any error raised inside a stin call).
 *
 * MEMORY
 * stin_memory_size(&desc) returns the bytes a configuration needs; the block
 * passed to stin_create must be at least that big (else STIN_ERROR_OUT_OF_MEMORY
 * and a log line saying how many bytes are needed). All capacities live in the
 * block. A full pool is a logged error that drops the item. With every default
 * the block is about 41 MB, most of it the vertex and triangle stores
 * (52 bytes a vertex: 48 of data and its weld, 24 a triangle), the mesh-creation scratch for
 * max_mesh_triangles and the 8 MiB texture staging: size them to the
 * application's assets (stin_desc_fit with stin_texture_staging_bytes).
 *
 * THREADS: a context is used from the thread that owns its GL context.
 */
#ifndef STIN_H
#define STIN_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The header's version (CHANGELOG.md). stin_version() returns the linked
 * library's as STIN_VERSION does: an application can check they match. */
#define STIN_VERSION_MAJOR 0
#define STIN_VERSION_MINOR 3
#define STIN_VERSION_PATCH 0
#define STIN_VERSION (STIN_VERSION_MAJOR * 10000 + STIN_VERSION_MINOR * 100 + STIN_VERSION_PATCH)
int stin_version(void);

/* ---- results ------------------------------------------------------------ */
typedef enum stin_result {
    STIN_OK = 0,
    STIN_ERROR_INVALID_ARGUMENT, /* NULL pointer, bad enum, bad size */
    STIN_ERROR_OUT_OF_MEMORY,    /* memory block smaller than stin_memory_size() */
    STIN_ERROR_CAPACITY,         /* a pool from the desc is full; the item was dropped */
    STIN_ERROR_UNSUPPORTED,      /* the context cannot run the forced tier/technique */
    STIN_ERROR_GL,               /* missing entry point, GL error, shader failure */
    STIN_ERROR_INVALID_HANDLE,   /* stale or foreign handle */
    STIN_ERROR_INVALID_MESH,     /* index out of range, NaN/Inf, all triangles degenerate */
    STIN_ERROR_INVALID_STATE     /* call out of order, e.g. draw outside a frame */
} stin_result;

const char *stin_result_name(stin_result r);

/* ---- log items (one list: enum always, text too) ------------------------ */
#define STIN_LOG_ITEMS(X)                                                           \
    X(NONE, "no message")                                                           \
    X(ARENA_TOO_SMALL, "memory block too small")                                    \
    X(POOL_FULL, "pool full, item dropped")                                         \
    X(MISSING_ENTRY_POINT, "GL entry point did not load")                           \
    X(TIER_UNSUPPORTED, "forced tier needs capabilities the context lacks")         \
    X(TECHNIQUE_UNSUPPORTED, "forced technique needs capabilities the context lacks") \
    X(TIER_SELECTED, "tier selected")                                               \
    X(TECHNIQUE_SELECTED, "technique selected")                                     \
    X(FALLBACK, "feature fell back")                                                \
    X(SHADER_COMPILE, "shader failed to compile")                                   \
    X(SHADER_LINK, "shader program failed to link")                                 \
    X(GL_ERROR, "GL reported an error")                                             \
    X(BAD_ARGUMENT, "invalid argument")                                             \
    X(BAD_HANDLE, "invalid handle")                                                 \
    X(MESH_INDEX_RANGE, "mesh index out of range")                                  \
    X(MESH_NOT_FINITE, "mesh has NaN or Inf")                                       \
    X(MESH_DEGENERATE, "mesh has degenerate triangles")                             \
    X(MESH_NOT_MANIFOLD, "mesh is not a closed 2-manifold")                         \
    X(FRAME_STATE, "frame call out of order")                                       \
    X(CAPS, "capabilities")

typedef enum stin_log_item {
#define STIN_X_(id, text) STIN_LOG_##id,
    STIN_LOG_ITEMS(STIN_X_)
#undef STIN_X_
    STIN_LOG_ITEM_COUNT
} stin_log_item;

typedef enum stin_log_level {
    STIN_LOG_LEVEL_ERROR = 0,
    STIN_LOG_LEVEL_WARNING,
    STIN_LOG_LEVEL_INFO
} stin_log_level;

const char *stin_log_item_text(stin_log_item item);

/* message is a NUL-terminated line valid during the call only. */
typedef void (*stin_log_fn)(void *user, stin_log_level level, stin_log_item item,
                            const char *message);

/* ---- capabilities -------------------------------------------------------
 * One bit per capability stin can use. A capability is present when the GL
 * version or one of the listed extensions provides it AND every entry point it
 * needs loaded. desc.caps_mask hides capabilities to emulate weaker hardware.
 * X(id, name, min core version as major*10+minor (0 = never core), extensions)
 *
 * ELEMENT_INDEX_UINT (32-bit element indices; every desktop GL has them,
 * OpenGL ES 2.0 only with GL_OES_element_index_uint): without it, where
 * buffer objects exist, every mesh's element buffer holds 16-bit indices,
 * and a mesh of more than 65,535 vertices is split into chunks: runs of
 * consecutive triangles of at most 65,535 vertices each, a vertex shared
 * across a seam copied into each chunk that uses it, each chunk drawn with
 * its own index range and its attributes moved to its vertices, so every
 * technique draws the same triangles in the same order. The copies live in
 * the GL buffers only; the block's mesh (its vertices, triangles, queries
 * and stin_update_mesh) is unchanged, and the chunk table is part of the
 * block (stin_memory_size: 16 bytes a chunk, 3 max_mesh_triangles / 65,533
 * + 1 chunks per mesh slot). Refused with a logged fall-back for a split
 * mesh, where one draw must see the whole mesh: its adjacency buffer (vdsm
 * and GL4's extruded volumes, which need geometry shaders, i.e. ES 3.2,
 * which has 32-bit indices: CPU-built volumes instead, vdsm's fall-back),
 * DOT3's bumped passes (fixed function, not on ES: the mesh's bumped lit
 * passes are left out) and the GLSL terminator band of stencil volumes (a
 * pixel or two on the terminator of a smooth split mesh). Client arrays
 * (no buffer objects: desktop GL 1.x) keep the block's 32-bit indices.
 *
 * DERIVATIVES (dFdx/dFdy in fragment shaders: core in desktop GLSL and GLSL
 * ES 3.00, GL_OES_standard_derivatives on ES 2.0; never without GLSL;
 * STIN_DEBUG_NO_DERIVATIVES hides it like the mask): without it every
 * fragment stage is built with STIN_NO_DERIVATIVES defined and the GLSL 1.10
 * sources take their derivative-free paths:
 * - the geometric normal (map-pcf's and coloured's side of the surface, the
 *   terminator rule's facet) is the interpolated vertex normal: exact where
 *   a triangle's corners carry its facet's normal (a flat-shaded, unwelded
 *   mesh), the curved surface's elsewhere. The terminator rule then still
 *   lifts a lookup onto the curved surface, but cannot see a facet turned
 *   from a light its shading normal faces: such a point is looked up, not
 *   shadowed outright;
 * - map-pcf's receiver-plane bias spans the plane of that normal (two
 *   perpendiculars projected into the map: a slope-scaled bias from the
 *   normal in light space) instead of the screen derivatives; the volumes'
 *   CSG/displaced cast map (no normal there) compares each tap at the
 *   point's own depth, its polygon offset the only bias;
 * - the volumes' terminator band asks its facet facts (the facet's side of
 *   the light and of the eye, the corners' normals on the eye's side, the
 *   curved surface above the facet) of each triangle on the CPU, as the
 *   fixed-function band does, and draws only those that pass; the shader
 *   keeps the per-pixel "shading normal toward the light";
 * - normal, parallax and pom take the tangent frame from the mesh's tangent
 *   attribute (as before) and the uv scale from the mesh's mean edge over
 *   its mean uv edge, times the model's scale along the tangent: the same
 *   along both axes, exact for a mapping without stretch or skew; colour
 *   maps take the moved uv's own footprint;
 * - CSG's snap in multisampled targets has no slope band (ES 2.0 has no
 *   multisampled targets).
 * vdsm and deep shadows (GL4) need it: their facet normals cannot be
 * replaced by a vertex normal; forcing them fails naming it.
 */
#define STIN_CAP_LIST(X)                                                              \
    X(STENCIL, "stencil buffer", 11, "")                                              \
    X(MULTITEXTURE, "multitexture", 13, "GL_ARB_multitexture")                        \
    X(TEXTURE_ENV_COMBINE, "texture_env_combine", 13,                                 \
      "GL_ARB_texture_env_combine GL_EXT_texture_env_combine")                        \
    X(TEXTURE_ENV_DOT3, "texture_env_dot3", 13,                                       \
      "GL_ARB_texture_env_dot3 GL_EXT_texture_env_dot3")                              \
    X(TEXTURE_CUBE_MAP, "cube maps", 13, "GL_ARB_texture_cube_map")                   \
    X(SEPARATE_SPECULAR, "separate specular colour", 12, "GL_EXT_separate_specular_color") \
    X(DEPTH_TEXTURE, "depth textures", 14, "GL_ARB_depth_texture")                    \
    X(SHADOW, "shadow compare", 14, "GL_ARB_shadow")                                  \
    X(STENCIL_WRAP, "stencil wrap", 14, "GL_EXT_stencil_wrap")                        \
    X(STENCIL_TWO_SIDE, "two-sided stencil", 0, "GL_EXT_stencil_two_side")            \
    X(SEPARATE_STENCIL, "separate stencil", 20, "GL_ATI_separate_stencil")           \
    X(DEPTH_CLAMP, "depth clamp", 32, "GL_ARB_depth_clamp GL_NV_depth_clamp")         \
    X(VBO, "vertex buffer objects", 15, "GL_ARB_vertex_buffer_object")                \
    X(GLSL, "GLSL 1.10 shaders", 20, "")                                              \
    X(FBO, "framebuffer objects", 30, "GL_ARB_framebuffer_object GL_EXT_framebuffer_object") \
    X(FLOAT_TEXTURE, "float textures", 30, "GL_ARB_texture_float")                    \
    X(VAO, "vertex array objects", 30, "GL_ARB_vertex_array_object")                  \
    X(GEOMETRY_SHADER, "geometry shaders (GLSL 1.50)", 32, "")                        \
    X(TESSELLATION, "tessellation shaders", 40, "GL_ARB_tessellation_shader")         \
    X(VERTEX_TEXTURE_FETCH, "vertex texture fetch", 0, "")                            \
    X(OCCLUSION_QUERY, "occlusion queries", 15, "GL_ARB_occlusion_query")             \
    X(COMPUTE, "compute shaders", 43, "GL_ARB_compute_shader")                        \
    X(FIXED_FUNCTION, "compatibility profile (fixed function)", 11, "")                \
    X(PACKED_DEPTH_STENCIL, "packed depth-stencil textures", 30,                      \
      "GL_ARB_framebuffer_object GL_EXT_packed_depth_stencil")                        \
    X(TIMER_QUERY, "timer queries", 33, "GL_ARB_timer_query")                         \
    X(TRANSFORM_FEEDBACK, "transform feedback objects", 40, "GL_ARB_transform_feedback2") \
    X(ELEMENT_INDEX_UINT, "32-bit element indices", 11, "GL_OES_element_index_uint")     \
    X(FRAG_DEPTH, "fragment depth writes", 20, "")                                        \
    X(DERIVATIVES, "fragment derivatives (dFdx, dFdy)", 20, "")                           \
    X(ANY_SAMPLES_QUERY, "any-samples-passed queries", 15, "GL_ARB_occlusion_query")      \
    X(FLOAT_BLEND, "blending into float targets", 30, "GL_ARB_texture_float")          \
    X(GLSL_150, "GLSL 1.50 shaders (GLSL ES 3.00 on ES)", 32, "")

typedef enum stin_cap {
#define STIN_X_(id, name, ver, exts) STIN_CAP_##id,
    STIN_CAP_LIST(STIN_X_)
#undef STIN_X_
    STIN_CAP_COUNT
} stin_cap;

#define STIN_CAP_BIT(cap) ((uint64_t)1 << (cap))

typedef enum stin_gl_profile {
    STIN_GL_PROFILE_COMPATIBILITY = 0, /* includes every pre-3.2 context */
    STIN_GL_PROFILE_CORE
} stin_gl_profile;

typedef struct stin_caps {
    int gl_major, gl_minor;       /* parsed from GL_VERSION (the ES version on ES) */
    int glsl_major, glsl_minor;   /* 0.0 when there is no GLSL; GLSL ES 1.00 reads 1.0 */
    /* 1 on an OpenGL ES context ("OpenGL ES 3.2 Mesa ..."): the versions
     * above are ES and GLSL ES ones, profile reads CORE (ES has no fixed
     * function), and each capability comes from the ES version that has it
     * in core or from an ES extension:
     *   ES 2.0: GLSL (ES 1.00), FBO, VBO, separate stencil, stencil
     *           wrap, multitexture, cube maps; DERIVATIVES only with
     *           OES_standard_derivatives (without it the shaders take their
     *           derivative-free paths: see DERIVATIVES below), FRAG_DEPTH
     *           only with EXT_frag_depth;
     *   ES 3.0: + GLSL_150 (GLSL ES 3.00), DERIVATIVES, VAO, depth textures,
     *           shadow compare, packed depth-stencil,
     *           fragment depth writes, float textures (counted only with EXT_color_buffer_float:
     *           stin renders into them), ANY_SAMPLES_QUERY
     *           (GL_ANY_SAMPLES_PASSED), FLOAT_BLEND (by EXT_float_blend,
     *           beside EXT_color_buffer_float);
     *   ES 3.1: + compute (detected, but stin's storage-buffer reads and
     *           clears, glGetBufferSubData and glClearBufferData, are desktop
     *           GL: COMPUTE stays off on a live ES context for now);
     *   ES 3.2: + geometry shaders, tessellation;
     *   on ES 2.0 by extension: OES_depth_texture, OES_packed_depth_stencil,
     *           OES_vertex_array_object, EXT_shadow_samplers, EXT_frag_depth
     *           (FRAG_DEPTH), OES_element_index_uint. ES 2.0's textures take
     *           unsized formats (stin chooses them); without
     *           OES_texture_npot stin_create_texture resamples the
     *           application's textures to powers of two (mipmaps, repeat).
     * Never on ES: FIXED_FUNCTION (so never the GL1 tier), texture_env_*,
     * SEPARATE_SPECULAR, STENCIL_TWO_SIDE (EXT's), DEPTH_CLAMP, TIMER_QUERY,
     * TRANSFORM_FEEDBACK (drawing from the object is desktop GL 4.0),
     * OCCLUSION_QUERY (sample counts, GL_SAMPLES_PASSED; ES answers only
     * "any passed", which is all stin asks: ANY_SAMPLES_QUERY).
     * ANY_SAMPLES_QUERY on desktop GL is OCCLUSION_QUERY (a sample count
     * answers "any" too; a mask that hides OCCLUSION_QUERY hides it as
     * well); FLOAT_BLEND on desktop is FLOAT_TEXTURE's rule (GL 3.0 blends
     * float targets), and it is never present without FLOAT_TEXTURE.
     * Desktop-only entry points (glClearDepth, glDepthRange, glPolygonMode,
     * glDrawBuffer, glLogicOp, client arrays...) count as not loaded there,
     * whatever the driver's get_proc_address returns for them. */
    int es;
    /* 1 on WebGL (es is 1 too): GL_VERSION names it, "OpenGL ES 3.0 (WebGL
     * 2.0 ...)" as emscripten reports it. WebGL 2 is ES 3.0 less client
     * arrays (stin streams through buffers on every ES 3.0+ context) and
     * with primitive restart at the fixed index always on: it has no such
     * capability to disable, so a frame leaves it alone there. */
    int webgl;
    stin_gl_profile profile;
    uint64_t present;             /* STIN_CAP_BIT()s after desc.caps_mask */
    uint64_t hidden;              /* bits the driver has but caps_mask hid */
    int max_texture_size;
    int max_viewport_dims[2];     /* GL_MAX_VIEWPORT_DIMS: a frame's widest, tallest viewport */
    int max_texture_units;        /* fixed-function units (GL1), 1 without multitexture */
    int max_texture_image_units;  /* fragment shader samplers, 0 without GLSL */
    int max_vertex_texture_units;
    int max_lights;               /* fixed-function lights, 0 on core profiles and ES */
    int max_clip_planes;          /* user clip planes (clip distances on core profiles);
                                   * 0 on ES */
    int stencil_bits, depth_bits; /* at stin_create: the bound or the default framebuffer's,
                                   * whichever has the larger stencil; frames probe their own */
    int max_draw_buffers;
    /* uniform space in vec4s (GL_MAX_*_UNIFORM_VECTORS on ES, the
     * *_COMPONENTS / 4 on desktop GLSL); 0 without GLSL. ES 2.0 promises
     * only 128 vertex and 16 fragment vectors. */
    int max_vertex_uniform_vectors, max_fragment_uniform_vectors;
    int max_geometry_output_vertices;
    int max_tess_gen_level;       /* 0 without tessellation */
    char renderer[64];            /* GL_RENDERER, truncated */
} stin_caps;

const char *stin_cap_name(stin_cap cap);

/* ---- tiers, features, techniques ---------------------------------------- */
typedef enum stin_tier {
    STIN_TIER_AUTO = 0,
    STIN_TIER_GL1 = 1,
    STIN_TIER_GL2 = 2,
    STIN_TIER_GL4 = 4
} stin_tier;

const char *stin_tier_name(stin_tier tier);

typedef enum stin_feature {
    STIN_FEATURE_LIGHTING = 0,
    STIN_FEATURE_SHADOWS,
    STIN_FEATURE_SURFACE,
    /* Reserved axes: each has one technique today, the behaviour stin has
     * had so far; the GL4 work adds the others to their chains. */
    STIN_FEATURE_TRANSLUCENT_SHADOWS, /* how casters with alpha < 1 shadow */
    STIN_FEATURE_DISPLACEMENT,        /* geometry moved by height maps */
    STIN_FEATURE_CSG,                 /* image-based CSG products */
    STIN_FEATURE_TRANSPARENCY,        /* how the camera sees blended draws (alpha < 1) */
    STIN_FEATURE_COUNT
} stin_feature;

const char *stin_feature_name(stin_feature f);

/* X(id, name, feature, tier it belongs to), grouped by feature in the
 * order of stin_feature, each feature's chain best first (values changed in
 * 0.3.0 and may change again when a technique is added: store names, not
 * numbers). A feature's "none" is "<feature>-off" (shadows-off, csg-off,
 * displacement-off). Each feature's chain (best first) is the library's
 * own ranking, filtered by the tier ceiling, the caps and the texture units
 * the chosen techniques need together (GL_MAX_TEXTURE_IMAGE_UNITS with GLSL
 * lighting, GL_MAX_TEXTURE_UNITS with fixed-function lighting; features are
 * chosen lighting, shadows, surface, so shadows outrank surface detail for
 * units, and a forced technique's units are set aside first):
 *   lighting: glsl150-per-pixel, glsl110-per-pixel, fixed-function
 *   shadows:  vdsm, volume, map-pcf, map-depth, map-combine, shadows-off
 *   surface:  pom, parallax, normal, dot3, plain
 *   displacement: displace-tess, displace, displacement-off
 *   translucent shadows: deep, coloured, opaque (translucent-solid: forced only)
 *   csg:      scs, interval (GL4), goldfeather, csg-off (see "CSG products" below)
 *   transparency: dual-peel, depth-peel, sorted (see "Transparency" below)
 * Units: lighting 1 (albedo, unit 0); normal/parallax/pom 2; dot3 2 (units
 * 0-2, and unit 3 for materials with an albedo texture when it is spare);
 * map-pcf 1 (a light's map or a point light's atlas); map-depth 1 (plus 1
 * for its side test, 1 for point-light faces and 1 for its terminator test,
 * in that order, each when there is one to spare after dot3's); map-combine
 * 2; deep and coloured
 * 2. Surface units follow the albedo, shadow units follow the surface's,
 * translucent shadows' the shadows'.
 * Surface: "dot3" (GL1) is DOT3 bump mapping of the material's normal_map
 * with a normalisation cube map; it needs multitexture, texture_env_combine,
 * texture_env_dot3, cube maps and 3 texture units (4 for a material that
 * also has an albedo texture; with 3 such a material stays plain), and runs
 * only with the fixed-function lighting technique (the GLSL tiers never pick
 * it; forcing it there is UNSUPPORTED). Opaque draws with a normal map get
 * their diffuse term per pixel, one extra additive pass per light; ambient
 * and specular stay per vertex (unbumped), blended draws stay plain, and a
 * bumped normal tilted toward a light just below the surface's horizon still
 * catches some of it (no self-shadowing term). Exact tangent frames for any
 * affine transform.
 * Surface on the GLSL tiers (GL2 and GL4; they run with either GLSL lighting
 * technique, never with fixed-function lighting): the chain is
 * pom -> parallax -> normal -> (dot3, GL1 only) -> plain. One lit program per
 * technique from the chosen one down is built at stin_create; each draw uses
 * the best technique at or below both the context's choice and its
 * material's `surface` request that its textures allow (no normal map:
 * plain; no height map: normal at most), and each such per-material step
 * down is logged once (STIN_LOG_FALLBACK, info). All of them read the mesh
 * tangent frame (T, B = w * cross(N, T), N), the material's normal_map on
 * texture unit 1 and height_map on unit 2 (albedo on unit 0):
 *   "normal"   tangent-space normal mapping; the map decodes as
 *              n = (rgb * 255 - 128) / 127 (128 is zero, so (128,128,255) is
 *              exactly the vertex normal); Toksvig: the specular exponent s
 *              becomes s * |n| / (|n| + s (1 - |n|)) with |n| the mean-normal
 *              length that stin_create_texture stores in the alpha of the
 *              normal map's mip levels (1 at level 0).
 *   "parallax" offset limiting: uv' = uv + V.xy * (h * height_scale -
 *              height_bias) with V the unit vector to the eye in the tangent
 *              frame and lengths in scene units (the uv-per-unit scale is
 *              taken from the surface's screen-space derivatives); every map
 *              is sampled at uv'.
 *   "pom"      parallax occlusion mapping: the height field is recessed, its
 *              top (h = 1) in the polygon and h = 0 at height_scale below;
 *              the view ray is marched through it in n linear steps, n from
 *              pom_min_steps (straight on) to pom_max_steps (grazing), then
 *              refined by 5 bisections and a secant step; with self_shadow a
 *              second march from the hit toward each light (1 hard, 2 soft
 *              penumbra estimate). Limitations: the silhouette stays the
 *              polygon's (no clipping of the recessed edges), depth is the
 *              polygon's (no gl_FragDepth: shadows and depth-EQUAL passes
 *              see the flat surface), the N output shows the vertex normal.
 * Parallax and pom sample height maps at full resolution (level 0: the
 * march needs the true field).
 * Displacement: "displace" (GL2 and GL4, GLSL lighting, vertex texture
 * fetch: GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS > 0, capability "vertex texture
 * fetch", which desc.caps_mask can hide) moves the vertices of draws whose
 * material sets `displace` and has a height map along their world normal by
 *   d = h * height_scale - height_bias      (h the height map's R, 0..1)
 * in scene units, the same h' as parallax (a material looks alike under
 * both; the default bias, scale / 2, centres the relief on the polygon;
 * `height_bias` a tiny negative value gives d = h * scale, raised only).
 * It is a feature of its own, so a displaced draw's shading is still the
 * surface chain's, capped at "normal" (the relief is geometry now: no
 * parallax on top); without displace (another tier, no vertex textures, a
 * material without `displace` or a height map) the draw walks the surface
 * chain as before, so per draw the chain reads displace -> pom -> parallax
 * -> normal -> dot3 -> plain. Every pass that draws a displaced draw moves
 * the same vertices the same way (one vertex-shader chunk in every
 * program that draws meshes: lit, ambient, flat, normals, shadow-map depth,
 * vdsm's position buffer, shadow polygons and light-view pyramid), so
 * depth-EQUAL passes match and map-pcf and vdsm shadow the displaced
 * surface. Lighting normals come from the normal map (or are the vertex
 * normals without one): the vertex stage cannot see its neighbours.
 * Shadows: stencil volumes take silhouettes from the undisplaced mesh, so
 * under "volume" a displaced draw casts no volume: it casts through
 * volumes' own depth map (with the CSG products, see "CSG products": the
 * map-pcf test, its bound at those shadows' edges; logged once a light,
 * "volume: displaced casters cast through map-pcf (SIZE) for light N"),
 * and is lit and receives every shadow at its displaced depth. That map
 * needs framebuffer objects and depth textures (without shadow compare,
 * OpenGL ES 2.0, its test compares in the shader as map-pcf's does): where
 * the context lacks one, "displace" conflicts with "volume" (the technique
 * table's conflict, lifted by those capabilities): with volumes chosen
 * displacement is "displacement-off" (logged fallback) and materials get
 * their surface chain; forcing "displace" makes the shadow chain skip
 * "volume"; a shadow technique demoted to volume at set-up demotes
 * displacement too (logged), as does a map test that fails to build. No
 * technique shadows the flat mesh of a displaced draw.
 * The height map is read with GL's filtering (bilinear at texel centres,
 * repeat) at a mip level from the vertex's linear distance d to the eye:
 *   lambda = log2(d x texels per unit / pixels per unit at distance 1)
 * (texels per unit: the map's larger side x the mesh's mean uv edge over its
 * mean edge over the transform's mean axis scale; pixels per unit: the
 * projection's y scale x half the viewport's height; d = 1 for an
 * orthographic camera), the two levels around lambda blended, level 0 alone
 * up close (lambda <= 0). Where displacement is built, stin_create_texture
 * gives each height map (unless base_level_only) a second texture with its mip
 * chain, CPU box-filtered as albedo chains are (parallax keeps level 0);
 * STIN_DEBUG_DISPLACE_NO_MIP reads level 0 at every distance.
 * STIN_DEBUG_DISPLACE_MANUAL_BILINEAR fetches the four texels at their
 * centres and blends them in the shader instead (for drivers whose vertex
 * textures are nearest-only; the same surface within rounding).
 * "displace-tess" (GL4 with tessellation shaders: GL 4.0 or
 * ARB_tessellation_shader, capability "tessellation shaders") is the top of
 * the chain: every program that draws meshes gets a tessellation stage, and
 * each triangle of a displaced draw is split before the same vertex chunk
 * displaces the new points. An edge's level is its length in the camera's
 * pixels over desc.displacement.tess_pixels (default 4), from 1 up to
 * desc.displacement.tess_max (default 64), computed from that edge's two ends
 * only, so neighbouring triangles split a shared edge alike and no crack
 * opens; light passes use the camera's levels, so maps and vdsm shadow the
 * surface the camera sees. Undisplaced draws keep their triangles. Without
 * tessellation "displace" moves the mesh's own vertices (the choice's
 * reason says so). The frame sets GL_PATCH_VERTICES to 3 and gives the
 * caller's value back. Frames without a displaced draw use the programs
 * without tessellation stages (each has a tessellated twin, built at
 * stin_create). Limit: "deep" peels a displaced transparent caster at its
 * mesh's vertices (its peel program has no tessellated twin).
 * Vertices whose undisplaced clip position lies outside the view
 * volume grown by desc.displacement.guard_band (a fraction of the volume's
 * half-size each side, default 1) are not displaced in the camera's passes
 * (no fetch): a triangle with a vertex that far out and pixels on screen,
 * or one crossing the eye plane, is drawn with that vertex undisplaced
 * (STIN_DEBUG_DISPLACE_NO_GUARD turns the test off). Light passes (maps,
 * vdsm) never skip. VTF needs vertices: stin_mesh_desc.subdivide splits
 * each triangle at creation; a draw whose mesh's edges span more than 4
 * texels of its height map on average is logged once as coarse.
 * Translucent shadows: how a caster whose material opacity (color[3]) is
 * below 1 shadows. "translucent-solid" (every tier): like an opaque one,
 * fully. "deep" (GL4: GLSL 1.50 lighting, float textures; two texture units
 * after the shadows technique's) is deep shadow maps (seed 001): per light,
 * just before its lit pass, the transparent casters are depth-peeled from
 * the light into up to desc.translucent.deep_layers layers per face (one face for spot
 * and directional lights, fitted as the shadow maps are; six 90-degree faces
 * for point lights, the face picked by the major axis as map-pcf's, so no
 * seams), each texel holding its layer's depth and the visibility V behind
 * it, per RGB channel V = V' (1 - a) clamp(1 - a + c, 0, 1) (a the
 * opacity, c the colour: material colour times albedo texel at level 0; a
 * texel with a = 0 casts nothing and takes no layer; desc.translucent.deep_mono: V = V'
 * (1 - a), grey). The lit pass multiplies the shadows technique's
 * visibility by the V of the last layer nearer the light than the point
 * (pushed 1.5 texels along its normal toward the side the eye sees, so a
 * pane is not darkened by its own layer; nearest texel; on a triangle whose
 * vertex normals bend away from its facet from the terminator rule's point,
 * as map-pcf's, along its shading normal, so a translucent low-poly sphere
 * does not darken its own lit side). Opaque casters stay
 * the shadows technique's (exact under vdsm and volume); transparent ones
 * are left out of it (no volume, no shadow polygon, no map-pcf depth) and
 * shadow through the deep map only. A face's peeling stops at the first
 * layer that drew nothing: on GL 4.3 (capability "compute shaders") a flag
 * in a 4-byte shader storage buffer that the peel shader sets and stin
 * reads back (binding point 0 and the generic GL_SHADER_STORAGE_BUFFER
 * binding are left at 0), on GL 3.2-4.2 and OpenGL ES 3.2 an occlusion
 * query (GL_ANY_SAMPLES_PASSED on ES: "any-samples-passed queries")
 * (STIN_DEBUG_DEEP_QUERY_STOP: the query everywhere;
 * STIN_DEBUG_DEEP_NO_EARLY_STOP peels every layer of every face: the same
 * image); a face whose frustum no transparent caster's bounding box
 * reaches (a displaced one always counts) peels no layer at all, and the
 * lookup reads each face's layers up to its first empty one
 * (stin_frame_stats.translucent.deep_faces). Surfaces beyond desc.translucent.deep_layers
 * along a ray are not counted (their light passes). Lights are lit one per
 * pass while it is in use, and a frame without transparent draws draws no
 * layer. Blended draws receive the deep maps' coloured shadows where
 * "depth-peel" lights them (below), and the visibility map
 * (export_visibility) holds the shadows technique's visibility and each
 * light's transmittance in a tile of its own (VISIBILITY FOR THE
 * APPLICATION'S SHADERS).
 * Displaced transparent casters peel their displaced surface. With
 * "shadows-off" it falls back to "translucent-solid" (logged as INFO where deep was
 * the tier's default, as a WARNING where the caller forced it); forcing it on a
 * context without the GL4 tier is UNSUPPORTED, naming what is missing.
 * GPU memory: 2 x 6 x ceil(translucent.deep_layers / 2) x translucent.deep_map_size^2 x 16 bytes
 * (RGBA32F: depth and V; 6 faces, two ping-pong array textures) plus a
 * translucent.deep_map_size^2 x 4 depth buffer: 97 MiB at the defaults (4 layers, 512),
 * 1.52 GiB at 2048 with 4 layers (stin_deep_memory_bytes); only the faces
 * a frame peels are written.
 * "coloured" (GL2 and up: GLSL lighting, FBOs, depth textures; two texture
 * units after the shadows technique's) is the next in the chain and runs
 * under every GLSL shadows technique: per light, just before its lit pass,
 * the transparent casters are drawn from the light (faces fitted as deep's,
 * in a 3 x 2 atlas of translucent.deep_map_size a face) twice: their nearest depth into
 * a depth texture, then their eq 5.3 factors multiplied together by
 * blending into an RGBA8 map cleared to white. The lit pass multiplies the
 * shadows technique's visibility by the product where the point (pushed as
 * deep's) lies behind the nearest transparent depth, else by 1. Exact where
 * a point has no transparent caster between it and the light that also lies
 * behind it: a floor under non-overlapping or stacked panes is exact, but a
 * receiver between two panes (or a pane behind another) is darkened by
 * every pane on its light ray, those behind it and its own included (a box
 * pane: its back face by its own two faces). Needs no float texture; the
 * map's 8 bits round each factor by up to 1/510. As with deep, lights are
 * lit one per pass while it is in use, a frame without transparent draws
 * draws no map, blended draws are drawn unshadowed, the visibility map
 * (export_visibility) holds the transmittance as with deep, and
 * with "shadows-off" it falls back to "opaque" (logged, at deep's levels). The face size is
 * halved until three faces fit the context's largest texture. GPU memory:
 * 6 x translucent.deep_map_size^2 x (4 + 4) bytes (12 MiB at 512).
 * "opaque" (every tier) ends the chain: a caster whose opacity is at least
 * desc.translucent.opaque_threshold (default 0.5) casts a full shadow under
 * every shadows technique, one below it none at all; "translucent-solid"
 * (all cast fully) is chosen only when forced.
 * Transparency: how the camera sees blended draws (material opacity
 * color[3] below 1; opaque draws are drawn first either way). The chain is
 * dual-peel -> depth-peel -> sorted, each step logged with the capability
 * it lacked.
 *   "depth-peel" (GLSL lighting with framebuffer objects, depth textures,
 *   packed depth-stencil, VBOs; two texture units after the translucent
 *   shadows' units) peels the blended draws front to back (Everitt 2001):
 *   layer k is, per pixel, the nearest blended surface behind layer k - 1
 *   and in front of the opaque depth. Each layer is lit exactly as the
 *   opaque surfaces are: its ambient pass, then the frame's per-light
 *   stages against the layer's own depth and stencil, so it receives the
 *   shadows technique's shadows (volume, map-pcf: exact as on opaque
 *   surfaces; "deep": the coloured transmittance) and is lit unshadowed in
 *   an unshadowed frame. Under "vdsm" the position buffer is drawn again
 *   from each layer before its lights (the blended draws kept within 2^-21
 *   of the layer's own depth texture: the layer's points exactly), so
 *   its per-light masks and light-view pyramids are the layer's, exact as
 *   on opaque surfaces; the opaque surfaces go back into it afterwards when
 *   the frame exports its visibility. Cost per peeled layer and light: one
 *   position pass over the blended draws plus vdsm's mask passes (pyramid,
 *   facing, shadow polygons of every draw): about 3x what volumes cost for
 *   the same layers on llvmpipe (docs/benchmarks.md); STIN_DEBUG_PEEL_VDSM_UNSHADOWED
 *   lights the layers unshadowed instead (the behaviour before).
 *   The lit layers are composited front to back under one another
 *   (C += T a c, T *= 1 - a, from C = 0, T = 1; c clamped to 1 as the
 *   framebuffer clamps a surface's passes) and the result over the opaque
 *   image: frame = C + T frame. The image does not depend on the order of
 *   the draws (bit for bit), and intersecting or self-overlapping
 *   transparent objects (a box's front and back) are exact. Peeling stops
 *   at desc.transparency.layers (default 8; surfaces beyond it along a ray
 *   are not drawn) or at the first pass that peeled nothing (an occlusion
 *   query; without queries every layer up to the cap is peeled;
 *   STIN_DEBUG_PEEL_NO_EARLY_STOP peels them all: the same image), so a
 *   scene whose rays cross at most n blended surfaces takes n + 1 peel
 *   passes (stin_frame_stats.transparency.peel_passes, .peel_layers). Each peeled layer
 *   costs an ambient pass, the frame's light stages (per light: its
 *   volumes, its deep map again, its lit pass) and one full-viewport
 *   composite; one more composite ends the frame. The frame's depth buffer
 *   ends with the nearest surface, blended or opaque, as the sorted draws
 *   leave it; its alpha becomes 1 - T + T x the alpha that was there (the
 *   composite goes over the frame as premultiplied colour C with coverage
 *   1 - T). Displaced blended draws are peeled displaced (the same
 *   lit programs draw them). The visibility and normal outputs draw
 *   blended draws as before (nearest surface). GPU memory, at the
 *   viewport's size W x H (window coordinates from 0: (x + width) x
 *   (y + height)), made at the first frame with blended draws and grown
 *   when a frame needs more: 4 depth-stencil textures (three layers' and
 *   the opaque depth) and 4 RGBA8 colour textures (a layer's ambient and
 *   lights, the composite's two), W x H x 32 bytes: 2 MiB at 256 x 256,
 *   63 MiB at 1920 x 1080.
 *   "dual-peel" (GL4's default: GLSL 1.50 lighting, float textures
 *   (RG32F, RGBA16F targets) it blends into ("blending into float targets":
 *   EXT_float_blend on OpenGL ES), any-samples-passed queries (its early
 *   stop; GL_ANY_SAMPLES_PASSED on ES 3.2) and depth-peel's needs; the
 *   same two texture units) peels two layers per geometry pass (Bavoil &
 *   Myers 2008): pass k draws the blended draws once with MAX blending of
 *   (-z, z) into RG32F, keeping what lies in front of the opaque depth and
 *   strictly between pass k - 1's nearest and farthest, so it finds per
 *   pixel the nearest and the farthest surface no pass has taken: layer 2k
 *   (front) and layer 2k + 1 (back; where one surface is left it is the
 *   front layer's, drawn once). Each layer is lit exactly as depth-peel
 *   lights one (its depth written by the lit programs keeping the
 *   fragments at the recorded gl_FragCoord.z, compared float for float,
 *   then the frame's stages: the same shadows, the same vdsm exception).
 *   Front layers are composited under one another, back layers over one
 *   another (RGBA16F), and at the end the back under the front, the whole
 *   over the opaque image by depth-peel's rule (frame = C + T frame,
 *   alpha 1 - T + T alpha, depth of the nearest). desc.transparency.layers
 *   caps the layers (front and back counted alike: with a cap below the
 *   depth complexity the layers dropped are the middle ones, depth-peel's
 *   the farthest). Peeling stops at a pass that found nothing (occlusion
 *   query) or after a back layer that drew nothing (no pixel had a third
 *   surface left), so a scene of n layers takes n / 2 + 1 passes
 *   (stin_frame_stats.transparency.peel_passes, integer division; .peel_layers = n);
 *   STIN_DEBUG_DUAL_PEEL_NO_EARLY_STOP runs cap / 2 (rounded up) passes:
 *   the same image. Cost per pass: one geometry pass without depth test;
 *   per layer depth-peel's (ambient pass, light stages, one composite).
 *   The image does not depend on the order of the draws (bit for bit) and
 *   agrees with depth-peel's within 1/255. GPU memory at W x H (as
 *   depth-peel's): 3 depth-stencil textures (the first layer's, a layer's,
 *   the opaque depth), 2 RGBA8 (a layer's ambient and lights), 2 RG32F
 *   (min-max, ping-pong) and 4 RGBA16F (front and back composites,
 *   ping-pong): W x H x 68 bytes, 4.25 MiB at 256 x 256, 134 MiB at
 *   1920 x 1080. A displaced draw's min-max pass is tessellated as its lit
 *   passes are. STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY applies to it too. A min-max
 *   program that does not build moves it to depth-peel (logged; the lit
 *   programs are built again with depth-peel's chunk). On GL4
 *   depth-peel's composites are RGBA16F too (one rounding at the end;
 *   W x H x 40 bytes there).
 *   "sorted" (every tier; GL1's only choice) is the behaviour before
 *   depth-peel: each blended draw whole, after the opaque ones, far to near
 *   by the eye depth of its bounds' centre, with depth LESS, writes and
 *   SRC_ALPHA / ONE_MINUS_SRC_ALPHA blending. It is exact
 *   only for blended objects that neither intersect nor overlap in depth
 *   nor overlap themselves: crossing panes, interleaved objects and a
 *   closed mesh's far side come out in the wrong order or hidden (the first
 *   frame with blended draws logs this warning once). Shadows on its draws,
 *   per shadows technique:
 *     map-pcf (GL2/GL4), map-depth and map-combine (GL1): shadowed as the
 *     opaque surfaces are. Each blended draw is lit on its own, far to
 *     near: its ambient pass over the frame (dst (1 - a) + a ambient), then
 *     per light the technique's map test on a pass added at the draw's
 *     opacity (+ a light, depth EQUAL: a self-overlapping draw's lights
 *     reach its nearest surface only). GLSL adds SRC_ALPHA / ONE; GL1 adds
 *     ONE / ONE with the light's colour times a, because map-combine's
 *     alpha test replaces the fragment's alpha with its depth comparison
 *     (so on GL1 an albedo texture's alpha scales the ambient pass only).
 *     Each light's pass is clamped on its own, so a surface lit brighter
 *     than 1 in sum comes out brighter than one pass would give (a x the
 *     excess). A point light's six faces (map-pcf, map-depth) and deep or
 *     colour maps are drawn again for every blended draw; a GL1 point light
 *     without faces (no FBOs, or map-combine) has volumes and lights the
 *     blended draws unshadowed (logged once). Cost: 1 + lights passes per
 *     blended draw instead of one per light batch.
 *     volume, vdsm: lit unshadowed (logged once): a volume's stencil count
 *     and vdsm's mask are the visibility of the nearest opaque surface, and
 *     a draw drawn whole has no depth of its own to count or mask against.
 *     off: unshadowed, as everything.
 *   STIN_DEBUG_SORTED_UNSHADOWED lights them unshadowed under every
 *   technique (the behaviour before). */
#define STIN_TECHNIQUE_LIST(X)                                                        \
    X(NONE, "none", STIN_FEATURE_COUNT, STIN_TIER_AUTO)                               \
    X(LIGHTING_GLSL150, "glsl150-per-pixel", STIN_FEATURE_LIGHTING, STIN_TIER_GL4)    \
    X(LIGHTING_GLSL110, "glsl110-per-pixel", STIN_FEATURE_LIGHTING, STIN_TIER_GL2)    \
    X(LIGHTING_FIXED, "fixed-function", STIN_FEATURE_LIGHTING, STIN_TIER_GL1)         \
    X(SHADOWS_VDSM, "vdsm", STIN_FEATURE_SHADOWS, STIN_TIER_GL4)                      \
    X(SHADOWS_VOLUME, "volume", STIN_FEATURE_SHADOWS, STIN_TIER_GL1)                  \
    X(SHADOWS_MAP_PCF, "map-pcf", STIN_FEATURE_SHADOWS, STIN_TIER_GL2)                \
    X(SHADOWS_MAP_DEPTH, "map-depth", STIN_FEATURE_SHADOWS, STIN_TIER_GL1)            \
    X(SHADOWS_MAP_COMBINE, "map-combine", STIN_FEATURE_SHADOWS, STIN_TIER_GL1)        \
    X(SHADOWS_OFF, "shadows-off", STIN_FEATURE_SHADOWS, STIN_TIER_GL1)                \
    X(SURFACE_POM, "pom", STIN_FEATURE_SURFACE, STIN_TIER_GL2)                        \
    X(SURFACE_PARALLAX, "parallax", STIN_FEATURE_SURFACE, STIN_TIER_GL2)              \
    X(SURFACE_NORMAL, "normal", STIN_FEATURE_SURFACE, STIN_TIER_GL2)                  \
    X(SURFACE_DOT3, "dot3", STIN_FEATURE_SURFACE, STIN_TIER_GL1)                      \
    X(SURFACE_PLAIN, "plain", STIN_FEATURE_SURFACE, STIN_TIER_GL1)                    \
    X(TRANSLUCENT_DEEP, "deep", STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TIER_GL4)      \
    X(TRANSLUCENT_COLOURED, "coloured", STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TIER_GL2) \
    X(TRANSLUCENT_OPAQUE, "opaque", STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TIER_GL1)  \
    X(TRANSLUCENT_SOLID, "translucent-solid", STIN_FEATURE_TRANSLUCENT_SHADOWS, STIN_TIER_GL1) \
    X(DISPLACEMENT_TESS, "displace-tess", STIN_FEATURE_DISPLACEMENT, STIN_TIER_GL4)   \
    X(DISPLACEMENT_VTF, "displace", STIN_FEATURE_DISPLACEMENT, STIN_TIER_GL2)         \
    X(DISPLACEMENT_OFF, "displacement-off", STIN_FEATURE_DISPLACEMENT, STIN_TIER_GL1) \
    X(CSG_SCS, "scs", STIN_FEATURE_CSG, STIN_TIER_GL1)                                \
    X(CSG_INTERVAL, "interval", STIN_FEATURE_CSG, STIN_TIER_GL4)                      \
    X(CSG_GOLDFEATHER, "goldfeather", STIN_FEATURE_CSG, STIN_TIER_GL1)                \
    X(CSG_OFF, "csg-off", STIN_FEATURE_CSG, STIN_TIER_GL1)                            \
    X(TRANSPARENCY_DUAL_PEEL, "dual-peel", STIN_FEATURE_TRANSPARENCY, STIN_TIER_GL4)  \
    X(TRANSPARENCY_DEPTH_PEEL, "depth-peel", STIN_FEATURE_TRANSPARENCY, STIN_TIER_GL2) \
    X(TRANSPARENCY_SORTED, "sorted", STIN_FEATURE_TRANSPARENCY, STIN_TIER_GL1)

typedef enum stin_technique {
#define STIN_X_(id, name, feature, tier) STIN_TECH_##id,
    STIN_TECHNIQUE_LIST(STIN_X_)
#undef STIN_X_
    STIN_TECH_COUNT
} stin_technique;

const char *stin_technique_name(stin_technique t);
/* Looks a technique up by its name ("fixed-function", "shadows-off", ...); STIN_TECH_NONE if unknown. */
stin_technique stin_technique_from_name(const char *name);
/* The feature a technique belongs to (STIN_FEATURE_COUNT for NONE). */
stin_feature stin_technique_feature(stin_technique t);

typedef struct stin_choice {
    stin_technique technique;
    int fell_back;    /* 1 when a better technique of the chain could not run */
    char reason[160]; /* why this one; names the capability that made it fall back */
} stin_choice;

/* ---- context ------------------------------------------------------------ */
typedef void *(*stin_get_proc_fn)(void *user, const char *name);

/* Per-feature settings of stin_desc (0 = the default each field names). */
typedef struct stin_shadows_settings {
    uint32_t soft_samples;     /* point samples of an area light (radius > 0), default 32,
                                * at most 64; volumes: a stencil count each (and a lit
                                * pass each without the screen mask) */
    uint32_t map_size;         /* map-pcf, map-depth, map-combine: texels a side of a
                                * light's shadow map, default 1024; a power of two, at
                                * most 8192 */
    uint32_t choice_frames;    /* the measured choice of the exact technique (SHADOWS):
                                * frames of the chosen technique between two trial
                                * frames of another, default 30, at most 100000; 1
                                * makes every other frame a trial */
} stin_shadows_settings;

typedef struct stin_translucent_settings {
    uint32_t deep_layers;      /* "deep": layers peeled per face at most, default 4, at
                                * most 16 */
    uint32_t deep_map_size;    /* "deep" (and "coloured"'s faces): texels a side of a
                                * face, default 512; a power of two, at most 4096 (and
                                * the context's largest texture). "deep" halves it
                                * at stin_create until the driver takes its layer
                                * arrays (GL_PROXY_TEXTURE_2D_ARRAY; logged,
                                * STIN_LOG_FALLBACK), and falls back as when its
                                * targets fail where it takes none of 64 or more */
    int deep_mono;             /* "deep": 1 stores grey visibility V' (1 - a) instead of
                                * the coloured one; default 0 */
    float opaque_threshold;    /* "opaque": casters of opacity >= this cast a full
                                * shadow, the rest none; default (0) 0.5, finite, in
                                * (0, 1] */
} stin_translucent_settings;

typedef struct stin_displacement_settings {
    float guard_band;          /* "displace": the view volume grown by this fraction of
                                * its half-size each side before a vertex is left
                                * undisplaced; default (0) 1, finite and >= 0 */
    float tess_pixels;         /* "displace-tess": the edge length, in the camera's
                                * pixels, tessellation aims at; default (0) 4, finite
                                * and > 0; below 1 it is raised to 1 (logged
                                * at stin_create, STIN_LOG_BAD_ARGUMENT, a
                                * warning): no edge is split into pieces
                                * shorter than a pixel at their distance, so
                                * a frame's triangles grow with its pixels,
                                * not without bound (the work grows with the
                                * square of 1 / tess_pixels) */
    uint32_t tess_max;         /* "displace-tess": highest level an edge is split to,
                                * default 64, at most 64 (and the driver's
                                * GL_MAX_TESS_GEN_LEVEL) */
} stin_displacement_settings;

/* CSG products (stin_draw_csg), per frame, all products together. */
typedef struct stin_csg_settings {
    uint32_t max_primitives;   /* primitives, default 256, below 2^24 */
    uint32_t max_terms;        /* terms of the normal forms, default 256, below 2^24 */
    uint32_t max_literals;     /* primitives named by those terms, counted once per term;
                                * default 4096, below 2^24. Normalising takes a scratch
                                * of 2 (max_terms + max_literals) words, and the
                                * products a slot per term */
    uint32_t interval_layers;  /* "interval": crossings of one primitive peeled per
                                * pixel (k), default 4, at most 16; a product with more
                                * on a pixel goes to scs/goldfeather that frame */
} stin_csg_settings;

typedef struct stin_transparency_settings {
    uint32_t layers;           /* "depth-peel", "dual-peel": layers of blended surfaces
                                * peeled per pixel at most, default 8, at most 64;
                                * surfaces past it along a ray are not drawn */
} stin_transparency_settings;

typedef struct stin_desc {
    stin_get_proc_fn get_proc_address; /* required */
    void *get_proc_user;
    stin_log_fn log;                   /* optional; default prints nothing */
    void *log_user;
    stin_tier tier;                    /* default AUTO: best the context runs */
    uint64_t caps_mask;                /* STIN_CAP_BIT()s to hide; default 0 */
    int max_gl_version;                /* e.g. 14 to treat the context as GL 1.4 (on OpenGL ES:
                                        * 30 treats it as ES 3.0); 0 = as reported */
    stin_technique techniques[STIN_FEATURE_COUNT]; /* forced technique per feature; NONE = auto */
    uint64_t debug_flags;              /* STIN_DEBUG_*: diagnostics, default 0 */
    /* capacities (0 = default) */
    uint32_t max_meshes;               /* default 64 */
    uint32_t max_textures;             /* default 64 */
    uint32_t max_draws;                /* per frame, default 1024 */
    uint32_t max_lights;               /* per frame, default 8, at most 32 */
    uint32_t max_vertices;             /* all meshes together, default 262144 */
    uint32_t max_triangles;            /* all meshes together, default 262144 */
    uint32_t max_mesh_triangles;       /* one mesh, sizes creation scratch; default 65536 */
    uint32_t max_texture_bytes;        /* staging for texture creation, default 8 MiB
                                        * (a 2048x2048 albedo texture with mipmaps, a
                                        * 1024x1024 normal map; stin_texture_staging_bytes) */
    /* per feature */
    stin_shadows_settings shadows;
    stin_translucent_settings translucent;
    stin_displacement_settings displacement;
    stin_csg_settings csg;
    stin_transparency_settings transparency;
} stin_desc;

/* Diagnostics for tests and bug reports (desc.debug_flags, 64 bits: one
 * byte of bits a feature); none changes what a correct frame looks like
 * where the technique is exact. */
/* -- the frame and lighting (bits 0-7) */
/* GPU time per frame stage into stin_frame_stats.stage_ns, from timestamp
 * queries (GL 3.3 or ARB_timer_query: the "timer queries" capability) at
 * each change of stage, each between two glFlush calls (so a renderer that
 * defers drawing to the flush stamps it where it stands); stin_end_frame
 * waits for the last of them, so a timed frame ends with the GPU idle (a
 * measurement aid, as STIN_DEBUG_VDSM_COUNT is). Without the capability
 * stage_times stays 0. */
#define STIN_DEBUG_STAGE_TIMES 0x1ull
/* GLSL lighting: every lit pass through the general program (a loop over
 * up to 8 lights bounded by a uniform, every part of the equation behind a
 * uniform branch) instead of programs specialised to the pass's lights and
 * the draw's material: the same picture within rounding; a test and bench
 * baseline */
#define STIN_DEBUG_LIGHTING_GENERAL 0x2ull
/* the measured choice of the exact technique off: every frame runs the
 * selection's "vdsm" (no trials, no timer queries) */
#define STIN_DEBUG_SHADOW_CHOICE_OFF 0x4ull
/* -- shadows: volume (bits 8-15) */
#define STIN_DEBUG_VOLUME_ZFAIL 0x100ull /* z-fail for every caster (needs caps) */
#define STIN_DEBUG_VOLUME_ZPASS 0x200ull /* z-pass for every caster: wrong with the eye in
                                          * a volume */
/* GL4 extrudes volumes in a geometry shader (no CPU work per caster
 * triangle); these build them on the CPU as GL1/GL2 do, or count the
 * extruded triangles into stin_frame_stats.shadows.volume_triangles (a
 * GL_PRIMITIVES_GENERATED query per caster: waits for the GPU) */
#define STIN_DEBUG_VOLUME_CPU 0x400ull
#define STIN_DEBUG_VOLUME_COUNT 0x800ull
/* after the frame, every light's shadow volumes (its centre sample, capped)
 * are added over the colour in orange where they lie in front of the
 * surfaces: a picture of the volumes, not of the shadows */
#define STIN_DEBUG_VOLUME_SHOW 0x1000ull
/* every volume runs to infinity, none is skipped: neither cut past the
 * visible receivers nor culled against the view (a baseline for tests and
 * the bench) */
#define STIN_DEBUG_VOLUME_UNBOUNDED 0x2000ull
/* volumes keep the facets on every tier: no terminator band pass (a
 * baseline for the terminator tests and the bench) */
#define STIN_DEBUG_VOLUME_FACETS 0x4000ull
/* -- shadows: vdsm (bits 16-23). Its steps, each on by default, off for
 * measurement and tests; the mask is the same without them (NO_GROW: pixels
 * a shadow polygon covers only in part, not at their centre, may be lost -
 * the artifact the growth fixes). STIN_DEBUG_VDSM_COUNT's count is of what
 * the steps left. */
#define STIN_DEBUG_VDSM_NO_EP 0x10000ull   /* keep triangles facing the light */
#define STIN_DEBUG_VDSM_NO_GROW 0x20000ull /* no conservative growth of the shadow polygons */
#define STIN_DEBUG_VDSM_COUNT 0x40000ull   /* count the primitives the geometry shader
                                            * emits into stats.shadows.vdsm_primitives
                                            * (waits for the GPU after each light) */
#define STIN_DEBUG_VDSM_NO_SM 0x80000ull   /* no light-view pyramid culling of triangles
                                            * in shadow */
#define STIN_DEBUG_VDSM_NO_DC 0x100000ull  /* extrude to infinity; no culling of triangles
                                            * with no receiver behind them */
#define STIN_DEBUG_VDSM_NO_DEPTH_TEST 0x200000ull /* shade every fragment of the shadow
                                                   * polygons, those behind the visible
                                                   * surface too */
#define STIN_DEBUG_VDSM_ONE_PASS 0x400000ull /* cull and draw in one geometry shader, no
                                              * culling pass */
/* -- displacement (bits 24-31); see TIERS, displacement */
#define STIN_DEBUG_DISPLACE_NO_GUARD 0x1000000ull /* fetch the height of every vertex, on
                                                   * screen or not */
#define STIN_DEBUG_DISPLACE_MANUAL_BILINEAR 0x2000000ull /* four fetches at texel centres,
                                                          * blended in the shader */
/* level 0 of the height map at every distance (no mip chain) */
#define STIN_DEBUG_DISPLACE_NO_MIP 0x4000000ull
/* -- translucent shadows (bits 32-39) */
/* deep: peel every layer of every face, without stopping at the first layer
 * that drew nothing (the same image, more passes) */
#define STIN_DEBUG_DEEP_NO_EARLY_STOP 0x100000000ull
/* deep: the early stop by an occlusion query even where GL 4.3's storage
 * flag could run (the same image and layer count) */
#define STIN_DEBUG_DEEP_QUERY_STOP 0x200000000ull
/* coloured: no nearest-transparent-depth test: every point under a
 * transparent caster is tinted, those in front of it too (tests prove the
 * test is needed) */
#define STIN_DEBUG_COLOURED_NO_DEPTH 0x400000000ull
/* -- CSG (bits 40-47) */
/* resolve the frame's products on the CPU (read-backs into the staging, as
 * GL1 contexts do) where the GPU resolve would run (the same depth, bit for
 * bit; a test and bench baseline) */
#define STIN_DEBUG_CSG_READBACK 0x10000000000ull
/* resolve through the work buffer, merge and snap (below) where the frame's
 * one scs candidate would resolve in place or its candidates be snapped
 * straight into the frame (direct): a test and bench baseline, and the
 * path interval and multisampled targets always take. The same image but
 * on isolated pixels, at most 0.05% of the covered ones (measured on the
 * test scenes, llvmpipe: at 256 x 192 none on GL 4.5 and 3.3, 1 of about
 * 30,000-36,000 on four scenes on GL 2.1; 1-2 in 46,695-201,416 at 512 x
 * 384 and 640 x 480 on GL 4.5): where the product's surface meets another
 * of its faces within the snap's band (8 steps of 24-bit depth) the merge
 * may keep the nearer face, and a pixel an edge passes through exactly may
 * be covered in the frame and not in the work buffer (a texture), which
 * leaves it to what lies behind the product */
#define STIN_DEBUG_CSG_NO_IN_PLACE 0x20000000000ull
/* products cast no shadow into the lights' maps (as before they did): a
 * test that casting matters */
#define STIN_DEBUG_CSG_NO_CAST 0x40000000000ull
/* scs: run every run of each subtraction sequence (as many as its window
 * boxes' bound allows), without the stencil check that ends it where the
 * depth lies inside no subtracted primitive (the same image, more passes) */
#define STIN_DEBUG_CSG_SCS_NO_EARLY_STOP 0x80000000000ull
/* scs: count a term's plain primitives in one 8-bit stencil counter instead
 * of batches of 255: wrong (nothing drawn) where a term intersects more than
 * 255; a test that it shows the batching matters */
#define STIN_DEBUG_CSG_SCS_NO_BATCH 0x100000000000ull
/* interval: the seed's one-interval method (one layer per primitive: its
 * nearest front and nearest back face, no overflow check): wrong where an
 * operand is non-convex along a ray or bodies lie behind each other; a
 * test that the k layers matter */
#define STIN_DEBUG_CSG_INTERVAL_ONE_LAYER 0x200000000000ull
/* interval: peel 2 layers per primitive whatever desc.csg.interval_layers
 * says (a product deeper than that overflows and goes to goldfeather) */
#define STIN_DEBUG_CSG_INTERVAL_TWO_LAYERS 0x400000000000ull
/* a multisampled target's snap as a single-sampled target's: each product
 * face's fragment kept only where its depth at the pixel centre lies within
 * 8 steps of 24 bits of the resolve's, without the slope band or the
 * neighbours (MULTISAMPLED TARGETS): lines along its triangle edges and
 * aliased silhouettes (the test that the band matters); under the
 * read-back resolve, its result written one depth a pixel into every
 * sample instead of the faces' band passes */
#define STIN_DEBUG_CSG_SNAP_AT_CENTRE 0x800000000000ull
/* -- transparency (bits 48-55) */
/* no blended draw is drawn (depth-peel, dual-peel: no layer; sorted: no
 * draw): the frame shows its opaque draws alone (the blended ones still
 * cast shadows as the techniques say), the image the layers are composited
 * over */
#define STIN_DEBUG_TRANSPARENCY_OPAQUE_ONLY 0x1000000000000ull
/* depth-peel: peel all desc.transparency.layers layers, without stopping at
 * the first that drew nothing (the same image, more passes) */
#define STIN_DEBUG_PEEL_NO_EARLY_STOP 0x2000000000000ull
/* depth-peel under vdsm: the peeled layers lit unshadowed, as before vdsm
 * shadowed them (its position buffer made from each layer); a test that
 * the per-layer masks matter */
#define STIN_DEBUG_PEEL_VDSM_UNSHADOWED 0x4000000000000ull
/* dual-peel: run a geometry pass per two layers up to
 * desc.transparency.layers, without stopping at a pass that finds nothing
 * or after a back layer that drew nothing (the same image) */
#define STIN_DEBUG_DUAL_PEEL_NO_EARLY_STOP 0x8000000000000ull
/* sorted: the blended draws lit unshadowed in the light batches, as before
 * the map techniques shadowed them; a test that the shadows matter */
#define STIN_DEBUG_SORTED_UNSHADOWED 0x10000000000000ull
/* hide STIN_CAP_DERIVATIVES as caps_mask would: the shaders' derivative-free
 * paths (bare OpenGL ES 2.0's) on any context, for tests */
#define STIN_DEBUG_NO_DERIVATIVES 0x20000000000000ull

typedef struct stin_context stin_context;

/* GPU memory of "deep"'s maps for this desc (defaults applied): 2 x 6 x
 * ceil(translucent.deep_layers / 2) x translucent.deep_map_size^2 x 16 bytes of layers plus
 * translucent.deep_map_size^2 x 4 of depth buffer. 0 on a bad desc. */
uint64_t stin_deep_memory_bytes(const stin_desc *desc);

/* Bytes the configuration needs (the desc with defaults applied). 0 on a bad desc:
 * one stin_create refuses as STIN_ERROR_INVALID_ARGUMENT (a capacity out of range, an
 * unknown tier, a forced technique that is not one of its feature's). */
size_t stin_memory_size(const stin_desc *desc);

/* Creates a context in the caller's block. The GL context must be current.
 * Detects capabilities, selects the tier and the technique per feature. */
stin_result stin_create(const stin_desc *desc, void *memory, size_t memory_bytes,
                        stin_context **out);

/* Deletes GL objects. The memory block can be reused or freed afterwards. */
void stin_destroy(stin_context *ctx);

/* The desc with every default filled in. */
stin_desc stin_query_desc(const stin_context *ctx);
const stin_caps *stin_query_caps(const stin_context *ctx);
stin_tier stin_query_tier(const stin_context *ctx);
stin_choice stin_query_choice(const stin_context *ctx, stin_feature feature);

/* Detects capabilities of the current context without creating a stin context
 * (for tools that print them). caps_mask and max_gl_version as in stin_desc. */
stin_result stin_detect_caps(stin_get_proc_fn get_proc, void *user, uint64_t caps_mask,
                             int max_gl_version, stin_caps *out);
/* Best tier the caps run; writes the capabilities missing for `tier` into
 * `missing` (comma separated, may be NULL). Returns 1 if `tier` can run.
 * NULL caps: stin_tier_supported returns 0 (missing emptied) and
 * stin_best_tier STIN_TIER_AUTO. */
int stin_tier_supported(const stin_caps *caps, stin_tier tier, char *missing, size_t size);
stin_tier stin_best_tier(const stin_caps *caps);

/* Exact token match against the context's extension list (GL_EXTENSIONS or
 * glGetStringi). Reports what the driver says, before caps_mask. */
int stin_query_extension(const stin_context *ctx, const char *name);

/* ---- meshes ------------------------------------------------------------- */
/* Handles: 0 is never a handle. A handle resolves only in the context that
 * made it, while its mesh or texture lives; anything else is
 * STIN_ERROR_INVALID_HANDLE (or logged and ignored by the destroy calls):
 *   - a stale handle: each slot's generation grows with every re-creation
 *     and never wraps; a slot whose generation is spent (2^24 / the next
 *     power of two above max_meshes or max_textures, less one, issues: 255 with
 *     65535 slots, 131071 with 64) is retired for the context's life, so
 *     the pool loses that slot rather than reviving an old id;
 *   - another context's handle: each context's handles carry an 8-bit tag
 *     from a creation counter kept in the block and the block's address. A
 *     context made in the block of a destroyed one gets the next tag, so
 *     the old context's handles never resolve in it (for 255 re-creations
 *     in a row; keep the block's bytes between destroy and create, since
 *     the counter lives there). Two blocks' tags differ unless their
 *     addresses hash alike (1 in 256). */
typedef struct { uint32_t id; } stin_mesh;
typedef struct { uint32_t id; } stin_texture;

typedef struct stin_mesh_desc {
    const float *positions;   /* 3 floats per vertex, required */
    const float *normals;     /* 3 per vertex; default: area-weighted face normals */
    const float *uvs;         /* 2 per vertex; default 0 (no tangents without them) */
    uint32_t vertex_count;
    const uint32_t *indices;  /* 3 per triangle, counter-clockwise front faces */
    uint32_t index_count;
    /* Vertices whose positions differ by at most this much on every axis are
     * one vertex for adjacency (closed meshes get closed volumes) and are
     * snapped onto the first of them, so volumes and drawn surface stay
     * watertight. 0 (default): 2^-20 of the mesh's largest bounding-box
     * extent, which joins seams and poles that differ in their last bits;
     * negative: bit-equal positions only. */
    float weld_tolerance;
    /* Levels of subdivision at creation, for vertex displacement: each
     * level splits every triangle into four at its edges' midpoints
     * (shared between neighbours, so the mesh stays watertight; normals
     * normalised means, uvs means). Flat: the shape does not change.
     * 0 (default) none, at most 6. The stored mesh (vertex_count,
     * triangle_count, the capacities it takes) is the subdivided one: V + E
     * vertices and 4 T triangles a level (E the edges); it must fit
     * desc.max_mesh_triangles and the stores like any mesh. */
    uint32_t subdivide;
} stin_mesh_desc;

typedef struct stin_mesh_info {
    uint32_t vertex_count, triangle_count;
    uint32_t degenerate_dropped;   /* zero-area triangles removed at creation */
    uint32_t open_edges;           /* edges with one incident triangle */
    uint32_t nonmanifold_edges;    /* edges with more than two triangles, or two that
                                    * traverse it in the same direction */
    int closed_manifold;           /* 1 when every edge has exactly two opposite triangles */
    uint32_t welded_vertices;      /* vertices snapped onto another (weld_tolerance) */
    float bounds_min[3], bounds_max[3];
    /* 1 when the mesh bounds one convex solid: closed_manifold, every edge's
     * dihedral angle convex (the far vertex of either triangle lies on or
     * behind the other's plane, within 1e-5 of the longer edge: flat
     * quads split in two count) and one piece (V - E + F = 2 over welded
     * positions). CSG technique "scs" needs it of every primitive. */
    int convex;
} stin_mesh_info;

/* Validates (indices in range, finite values, degenerate triangles dropped and
 * counted), computes adjacency, manifold status and tangents, uploads.
 * Degenerate means twice the area under 1e-7 of the longest edge squared
 * (or repeated indices): a test of shape, the same at every scale from
 * float's smallest to its largest values. */
stin_result stin_create_mesh(stin_context *ctx, const stin_mesh_desc *desc, stin_mesh *out);
stin_result stin_query_mesh_info(const stin_context *ctx, stin_mesh mesh, stin_mesh_info *out);
/* Neighbour triangle across edge e (0..2: v0v1, v1v2, v2v0) of triangle t, or
 * UINT32_MAX for an open or non-manifold edge. */
stin_result stin_query_mesh_adjacency(const stin_context *ctx, stin_mesh mesh, uint32_t t,
                                      uint32_t out_neighbours[3]);
/* Tangent (xyz) and handedness (w = +1/-1) of a vertex. */
stin_result stin_query_mesh_tangent(const stin_context *ctx, stin_mesh mesh, uint32_t vertex,
                                    float out_tangent[4]);
/* Refused (logged, the mesh stays) while a frame is open: its draws may use it. */
void stin_destroy_mesh(stin_context *ctx, stin_mesh mesh);

/* New vertex data for a mesh whose shape changes (a character skinned or
 * morphed on the CPU): the same vertices in the same order, the triangles
 * and uvs as created. */
typedef struct stin_mesh_update_desc {
    const float *positions;   /* 3 floats per vertex, required */
    const float *normals;     /* 3 per vertex; default: area-weighted face normals of
                               * the new positions (as stin_create_mesh) */
    const float *tangents;    /* 4 per vertex: xyz and handedness (w < 0: -1, else +1);
                               * default: recomputed (below). Not with subdivide. */
    uint32_t vertex_count;    /* must equal the stin_mesh_desc.vertex_count the mesh
                               * was created with */
} stin_mesh_update_desc;

/* Replaces a mesh's positions and normals (and tangents) between frames,
 * keeping its topology: the triangles, the adjacency, the welds, the
 * adjacency index buffer and the GL names stay; what is derived from
 * positions is redone, so every technique (volumes, vdsm, the maps, deep
 * and coloured maps, CSG, displacement) casts and draws the new shape in
 * the next frame.
 * Cost: a few passes over the vertices and triangles (normals where none
 * are given, tangents, bounds, the mean edge length, and for a closed mesh
 * of one piece the convexity test), plus an upload of the vertex buffer
 * (48 bytes a vertex, glBufferData into the same buffer: its usage becomes
 * GL_DYNAMIC_DRAW) where the context has buffer objects; no index
 * validation, welding, adjacency or index upload: about 3-5x cheaper than
 * destroying and creating the mesh (docs/benchmarks.md, "Mesh updates").
 * Tangents: as given (xyz as they are, w made +1 or -1), else recomputed
 * from the uvs where the mesh was created with uvs (their gradients over
 * the new positions), else an arbitrary perpendicular to the new normal
 * (as stin_create_mesh gives a mesh without uvs).
 * Welds: vertices stin_create_mesh welded (stin_mesh_desc.weld_tolerance)
 * stay one vertex: each takes the new position of the first vertex of its
 * group (the lowest index, the one it was snapped onto at creation),
 * whatever position it is given, so volumes and the drawn surface stay
 * watertight. Give welded copies (uv seams, split normals) the same
 * position, as skinning equal rest positions with equal weights does, and
 * nothing is moved; their normals and tangents stay their own.
 * stin_mesh_info: bounds_min/max and convex (the same test as at
 * creation, over the kept adjacency) are recomputed; vertex and triangle
 * counts, degenerate_dropped, open_edges, nonmanifold_edges,
 * closed_manifold and welded_vertices are kept (topology). Whether the
 * normals bend away from the facets (the terminator rule, which also
 * decides the measured choice between vdsm and volumes) is tested again.
 * A triangle dropped as degenerate at creation stays dropped; one the new
 * positions flatten stays (it covers and casts nothing). A subdivided mesh
 * (stin_mesh_desc.subdivide) takes its source vertices; the midpoints are
 * made again as at creation. The result equals destroying the mesh and
 * creating it from the new data, bit for bit, where the new positions weld
 * and drop triangles as the creation's did.
 * Errors (logged where there is a context; the mesh unchanged):
 * STIN_ERROR_INVALID_ARGUMENT for a NULL context, desc or positions, a
 * vertex_count other than the creation's, or tangents for a subdivided
 * mesh; STIN_ERROR_INVALID_HANDLE for a stale or foreign handle;
 * STIN_ERROR_INVALID_MESH for a NaN or Inf position, normal or tangent
 * (the vertex named); STIN_ERROR_INVALID_STATE while a frame is open
 * (between stin_begin_frame and stin_end_frame: its draws were recorded
 * against the mesh's current shape). GL state: as stin_create_mesh (the
 * array buffer left at 0, the caller's vertex array untouched). */
stin_result stin_update_mesh(stin_context *ctx, stin_mesh mesh,
                             const stin_mesh_update_desc *desc);

/* ---- textures ----------------------------------------------------------- */
typedef enum stin_texture_kind {
    STIN_TEXTURE_ALBEDO = 0, /* RGBA8, sRGB-free linear colour */
    STIN_TEXTURE_NORMAL,     /* RGB8 tangent-space normal, 0.5 + 0.5 n */
    STIN_TEXTURE_HEIGHT      /* R8 height, 1 = top */
} stin_texture_kind;

typedef struct stin_texture_desc {
    stin_texture_kind kind;
    uint32_t width, height;  /* each at most caps.max_texture_size; any size (GL1
                              * and ES 2.0 without OES_texture_npot get a
                              * power-of-two resample); width *
                              * height above 2^30: STIN_ERROR_INVALID_ARGUMENT */
    const uint8_t *pixels;   /* RGBA8, 4 bytes per pixel, rows bottom to top */
    int base_level_only;     /* 1: no mip chain; default 0: mipmaps are built (for
                              * STIN_TEXTURE_HEIGHT only into displacement's
                              * copy, where displacement is built: parallax
                              * and pom march level 0) */
    /* STIN_TEXTURE_NORMAL only: > 0 derives the normal map from a height
     * field in the R channel of `pixels` (1 = top): central differences
     * with wrap-around, n = normalize(-s dh/dx, -s dh/dy, 1) with dh per
     * texel and s = normal_from_height, stored as 128 + 127 n. Done on the
     * CPU into the staging block (needs 4 bytes a texel more than the mip
     * chain). Normal maps' mip levels average the unit normals: RGB holds
     * the mean's direction, A its length (Toksvig). */
    float normal_from_height;
} stin_texture_desc;

/* Sizing a desc from the application's assets. stin_texture_staging_bytes
 * is the staging (desc.max_texture_bytes) stin_create_texture needs for a
 * texture on any context (pixels may be NULL): 5/16 of w * h * 4 for an
 * albedo or height map uploaded as given with mipmaps (levels 1 and 2; none
 * without mipmaps: a height map's chain is displacement's copy), 5/4 for normal maps and power-of-two resamples (GL1
 * contexts and ES 2.0 without OES_texture_npot resample non-power-of-two sizes up), plus w * h * 4 for a normal
 * map derived from a height field (kept while the size changes). 0 for a
 * bad desc. */
uint64_t stin_texture_staging_bytes(const stin_texture_desc *desc);

typedef struct stin_asset_summary {
    uint32_t meshes, textures;         /* alive at once */
    uint64_t vertices, triangles;      /* of all meshes together */
    uint32_t largest_mesh_triangles;
    uint64_t largest_texture_staging;  /* the largest stin_texture_staging_bytes */
    uint32_t draws, lights;            /* per frame */
} stin_asset_summary;

/* Raises each capacity of desc to what the summary needs (a larger value in
 * desc stays; 0 in the summary changes nothing). STIN_ERROR_CAPACITY, desc
 * unchanged and *field (if not NULL) naming the stin_desc field, when the
 * assets need more than stin accepts: 65535 meshes or textures, 2^30 - 1
 * vertices, 2^29 - 1 triangles, 2^24 - 1 draws, 32 lights, 2^32 - 1 staging
 * bytes. Then stin_memory_size says the block's size. */
stin_result stin_desc_fit(stin_desc *desc, const stin_asset_summary *assets, const char **field);

stin_result stin_create_texture(stin_context *ctx, const stin_texture_desc *desc,
                                stin_texture *out);
/* Refused (logged, the texture stays) while a frame is open: its draws may use it. */
void stin_destroy_texture(stin_context *ctx, stin_texture tex);

/* ---- frames ------------------------------------------------------------- */
typedef enum stin_light_type {
    STIN_LIGHT_POINT = 0,
    STIN_LIGHT_SPOT,
    STIN_LIGHT_DIRECTIONAL
} stin_light_type;

typedef struct stin_light_desc {
    stin_light_type type;
    float position[3];      /* world, point and spot */
    float direction[3];     /* world, the way light travels; spot and directional:
                             * any non-zero length (normalised scale-free) */
    float color[3];         /* default (1,1,1) when all zero */
    float intensity;        /* default 1 */
    float attenuation[3];   /* k0, k1, k2; default (1,0,0) when all zero */
    float spot_cutoff_deg;  /* half angle, (0,90]; default 45 */
    float spot_exponent;    /* default 0 */
    float radius;           /* > 0: area light (point and spot), soft shadows: volumes
                             * from desc.shadows.soft_samples point samples
                             * (stin_light_sample), vdsm and map-pcf per pixel
                             * (see Shadows); default 0 */
    float range;            /* > 0: the light reaches no farther (its attenuation makes it
                             * negligible); shadow passes are scissored to it. 0 = unbounded */
    float shadow_offset[2]; /* shadow-map polygon offset (factor, units), finite;
                             * default (1.1, 4.0) when both are 0, unless
                             * shadow_offset_exact; units are steps of 24-bit
                             * depth (2^-24) whatever the maps' own depth (ES
                             * 2.0's depth textures: 32 bits on Mesa) */
    int shadow_offset_exact; /* 1: shadow_offset as given, (0, 0) too: no offset
                              * (shows acne; for tests) */
    uint32_t pcf_kernel;    /* map-pcf: 1, 3 or 5 taps a side (each the hardware's 2x2
                             * compare); default 3 */
} stin_light_desc;

typedef struct stin_material {
    float color[4];         /* albedo and opacity; all zero means (0.8,0.8,0.8,1) */
    float specular[3];      /* default 0 */
    float shininess;        /* default 32, clamped to [0,128] */
    stin_texture albedo;    /* optional, multiplies color */
    stin_texture normal_map; /* optional: tangent-space normals (STIN_TEXTURE_NORMAL),
                              * used by the surface technique (GL1: dot3) */
    stin_texture height_map; /* optional: height field in R (STIN_TEXTURE_HEIGHT, 1 =
                              * top), used by parallax and pom */
    float height_scale;     /* scene units from h = 1 to h = 0; default (0) 0.04 */
    float height_bias;      /* parallax: uv' = uv + V.xy (h scale - bias); displace:
                             * d = h scale - bias along the normal; default (0)
                             * height_scale / 2 (a negative tiny value gives ~0) */
    int displace;           /* 1: displace the mesh by height_map where the displacement
                             * feature is "displace" (see TIERS, displacement); 0
                             * (default): the surface chain only. Opt-in: the mesh must
                             * be dense enough (stin_mesh_desc.subdivide) */
    uint32_t pom_min_steps; /* pom linear steps straight on, default 8 */
    uint32_t pom_max_steps; /* pom linear steps at grazing angles, default 32, at most 64 */
    int self_shadow;        /* pom: 0 off (default), 1 hard, 2 soft */
    stin_technique surface; /* requested surface technique; STIN_TECH_NONE = the
                             * context's choice. The draw uses the lower of the two
                             * (dot3 asks for normal mapping at most on GLSL tiers) */
    int two_sided;          /* 0 (default): a closed mesh is seen from outside only;
                             * nonzero: both sides of its surface may be seen (the eye
                             * inside it), so vdsm keeps the triangles facing the light
                             * (no EP). Open meshes are treated so anyway */
} stin_material;

typedef enum stin_output {
    STIN_OUTPUT_BEAUTY = 0, /* lit colour */
    STIN_OUTPUT_NORMAL,     /* world shading normal as 0.5 + 0.5 n, alpha 1 */
    STIN_OUTPUT_VISIBILITY  /* visibility of light 0 (1 lit, 0 shadowed) in RGB */
} stin_output;

/* What a frame hands the application besides its pixels (see VISIBILITY FOR
 * THE APPLICATION'S SHADERS below). */
typedef enum stin_export {
    STIN_EXPORT_NONE = 0,        /* default */
    STIN_EXPORT_VISIBILITY,      /* the frame's output, then every light's visibility */
    STIN_EXPORT_VISIBILITY_ONLY  /* the opaque draws' depth (into the target, whose colour
                                  * is cleared as usual and not drawn) and every light's
                                  * visibility: the application shades with its own
                                  * shaders */
} stin_export;

typedef struct stin_frame_desc {
    float view[16];          /* column-major world -> eye; required: finite and invertible */
    float projection[16];    /* column-major eye -> clip; required: finite and invertible
                              * (all zeros, e.g. a forgotten matrix, is an error) */
    int viewport[4];         /* x, y, width, height; required: width and height > 0
                              * and at most caps.max_viewport_dims, x and y >= 0,
                              * x + width and y + height at most
                              * caps.max_texture_size (stin's buffers of the
                              * viewport's window size are textures), width x
                              * height < 2^31; else a logged
                              * STIN_ERROR_INVALID_ARGUMENT before any GL call,
                              * the context unchanged */
    uint32_t framebuffer;    /* GL framebuffer name to draw into; 0 = default. Else a
                              * complete framebuffer object of the context:
                              * stin_begin_frame checks (binding it for the
                              * check, the caller's binding given back) and an
                              * unknown or incomplete one is a logged
                              * STIN_ERROR_INVALID_ARGUMENT; stin_end_frame
                              * checks again and, if it went bad in between,
                              * drops the frame with the same error. */
    float clear_color[4];    /* cleared before drawing */
    int keep_contents;       /* 1: draw over the target's colour, depth and stencil
                              * as they are (no clear) */
    float ambient[3];        /* scene ambient, multiplies albedo */
    stin_output output;
    stin_export export_visibility; /* default STIN_EXPORT_NONE */
    /* The deferred outline (see OUTLINE below; GLSL tiers with framebuffer
     * objects and packed depth-stencil, else the frame is refused with
     * STIN_ERROR_UNSUPPORTED): */
    float outline_step;        /* pixels between the filter's taps, 0..64; 0 (default): none */
    float outline_color[4];    /* RGBA blended over the frame by its alpha; all 0: opaque black */
    float outline_normal_edge; /* normals' Sobel magnitude that makes a crease; 0: 1.0 */
    float outline_depth_edge;  /* depth step, a share of the eye distance, that makes an
                                * edge; 0: 0.02 */
} stin_frame_desc;

stin_result stin_begin_frame(stin_context *ctx, const stin_frame_desc *desc);
/* At most desc.max_lights per frame; the light index order is kept (light 0 is
 * the one STIN_OUTPUT_VISIBILITY shows). A NaN or infinite field, an unknown
 * type or a zero direction (spot, directional) is STIN_ERROR_INVALID_ARGUMENT. */
stin_result stin_add_light(stin_context *ctx, const stin_light_desc *light);
/* transform: column-major object -> world; NULL means identity. */
stin_result stin_draw(stin_context *ctx, stin_mesh mesh, const float transform[16],
                      const stin_material *material);
stin_result stin_end_frame(stin_context *ctx);

/* ---- CSG products ----------------------------------------------------------
 * A CSG product is a solid made of primitives (closed stin meshes, each with
 * its transform and material) by an expression of union, intersection and
 * subtraction. stin_draw_csg adds one to the open frame (like stin_draw) and
 * normalises its expression into the context's block as Goldfeather's sum of
 * products: a union of terms, each the intersection of some primitives and
 * the complements of others (a - (b u c) = a !b !c; a - (b n c) = a !b u a !c;
 * a n (b u c) = a b u a c). Each term keeps at least one primitive that is
 * not complemented; literals are sorted by primitive, repeats within a term
 * are merged and a term that holds a primitive and its complement is empty
 * and dropped (a - a draws nothing). An operation whose two operands are
 * the same node is that node (a u a = a n a = a, a - a empty), so a tree
 * that unions a node with itself level after level stays one term, and a
 * term the list already holds is dropped (where the list has at most about
 * 2,900 terms: they are compared pairwise), so a chain that unions the same
 * primitive in again and again is one term of it. No other simplification
 * is made: a union of n terms with k primitives each costs what
 * Goldfeather's method costs for it.
 * The product's visible surface is where the camera ray first enters the
 * solid: a primitive's outside where it is not complemented, the inside of a
 * complemented one (a cavity's wall, shaded with the primitive's material and
 * its normal flipped to face the cavity). */
typedef enum stin_csg_op {
    STIN_CSG_PRIMITIVE = 0, /* a leaf: node.primitive */
    STIN_CSG_UNION,         /* a u b */
    STIN_CSG_INTERSECTION,  /* a n b */
    STIN_CSG_SUBTRACTION    /* a - b */
} stin_csg_op;

typedef struct stin_csg_node {
    stin_csg_op op;
    uint32_t primitive;     /* STIN_CSG_PRIMITIVE: index into stin_csg_desc.primitives */
    uint32_t a, b;          /* operations: operand nodes, each before this one in the array */
} stin_csg_node;

typedef struct stin_csg_primitive {
    stin_mesh mesh;         /* a closed 2-manifold (stin_mesh_info.closed_manifold) */
    float transform[16];    /* column-major object -> world, finite; all zero = identity */
    stin_material material; /* as stin_draw's; opaque (colour alpha 1 after defaults) and
                             * not displaced; normal_map and height_map are ignored */
} stin_csg_primitive;

typedef struct stin_csg_desc {
    const stin_csg_primitive *primitives;
    uint32_t primitive_count;  /* at least 1 */
    const stin_csg_node *nodes;
    uint32_t node_count;       /* at least 1, at most 65536; the LAST node is the root.
                                * Operands come before the node that uses them (a node
                                * may be used several times); nesting at most 1024 deep */
} stin_csg_desc;

/* Adds a CSG product to the open frame. Errors (logged, nothing of the
 * product kept): STIN_ERROR_INVALID_STATE outside a frame;
 * STIN_ERROR_INVALID_ARGUMENT for a NULL desc, an empty expression (no
 * nodes or no primitives), an unknown op, a primitive index out of range, an
 * operand that does not come before its node, nesting deeper than 1024, a
 * NaN/Inf or singular transform, a bad material (as stin_draw), a blended or
 * displaced material; STIN_ERROR_INVALID_HANDLE for a stale mesh;
 * STIN_ERROR_INVALID_MESH for a mesh that is not a closed 2-manifold (the
 * parity of its surfaces along a ray is what says inside);
 * STIN_ERROR_CAPACITY when the frame's csg.max_primitives, csg.max_terms or
 * csg.max_literals would be passed, when the partial normal forms outgrow
 * the scratch, or when normalising takes more than 2^24 steps (a step: a
 * node visited, a shared node at each use; and per pair of terms crossed,
 * one plus the literals of both: about 0.1 s; a union of 2^12 terms
 * crossed with 2^12 terms each empty against it is past it) (the log names
 * which; the product is dropped and counted in stin_frame_stats.csg.dropped);
 * STIN_ERROR_UNSUPPORTED when the frame's target is multisampled, the
 * resolve reads back (GL1 tiers, STIN_DEBUG_CSG_READBACK) and the context
 * lacks what its single-sampled copy needs (FBOs, packed depth-stencil,
 * depth textures, a blit, fixed function; logged, dropped and counted the
 * same; both resolves draw into multisampled targets otherwise:
 * MULTISAMPLED TARGETS).
 * Primitives no term names are not drawn. A product whose every term is
 * empty draws nothing and returns STIN_OK. stin_query_csg_terms reads the
 * normal form back. */
stin_result stin_draw_csg(stin_context *ctx, const stin_csg_desc *desc);

/* What stin_draw_csg would make of desc's expression, without a context or
 * GL (a scene loader's check before any frame): the checks on its nodes
 * (count, ops, primitive indices below desc->primitive_count, order, depth)
 * and its normal form, normalised in the caller's scratch of scratch_words
 * words (a context has 2 (csg.max_terms + csg.max_literals)). Primitives
 * are not looked at (desc->primitives need only be non-NULL). STIN_OK and
 * size->terms, size->literals (0 terms: every term empty); else the result
 * stin_draw_csg gives for it and *why (if not NULL) its log's words (a
 * STIN_ERROR_CAPACITY with size->scratch_words above scratch_words: the
 * scratch was short, try a larger one; else the expression's own).
 * size->scratch_words: the scratch it used at most, which a frame's
 * 2 (csg.max_terms + csg.max_literals) must reach. */
typedef struct stin_csg_size {
    uint32_t terms, literals, scratch_words;
} stin_csg_size;
stin_result stin_csg_measure(const stin_csg_desc *desc, uint32_t *scratch,
                             uint32_t scratch_words, stin_csg_size *size, const char **why);

/* CSG technique "goldfeather" (every tier with a stencil buffer: it reads
 * depth with glReadPixels and writes it back with glDrawPixels on
 * compatibility contexts, on core profiles through an R32F texture the
 * size of the viewport, made at the first frame and kept, and a GLSL 1.50
 * program writing gl_FragDepth (GLSL ES 3.00 on OpenGL ES 3.x, whatever
 * the lighting; ES reads depth and stencil back as GL_DEPTH_STENCIL 24_8
 * words with GL_NV_read_depth_stencil; an ES context without it (WebGL 2),
 * and OpenGL ES 2.0 (no program writes read-back depth again there),
 * resolves the camera's products on the GPU alone, and a light's map
 * resolves them so too (map-pcf's and volumes' maps: the direct GPU
 * resolve from the light, each candidate's faces drawn into the map with
 * its polygon offset; none under interval, nor where
 * the GPU resolve is packed), scs and goldfeather run to their limits
 * without counting layers, and STIN_DEBUG_CSG_READBACK makes it
 * "csg-off"; the GPU resolve's work
 * buffer needs depth textures, packed depth-stencil and fragment depth
 * writes, so bare ES 2.0 takes the packed resolve below, and a frame there
 * that keeps its contents or is multisampled draws no products, logged
 * once); a desktop core context without GL4 lighting, or a frame
 * into a framebuffer without stencil, draws no products: "csg-off" or a
 * FALLBACK warning, logged once; products are still accepted). The frame
 * plan resolves every product of the frame after the target's clear and
 * before the ambient pass, in the frame's own depth and stencil buffers:
 * per term, per literal, per layer of that primitive's front faces (back
 * faces where complemented), the layer is picked by a stencil counter (the
 * k-th fragment of a pixel, in any order; the first layer's count says
 * how many layers there are: at most 255, more is logged once; a convex
 * mesh's faces are one layer, not counted),
 * then the term's other primitives invert a stencil bit each where their
 * faces lie in front of it, eight (the stencil's bits) a batch, so no
 * counter overflows whatever the primitive count; a pixel survives where
 * every bit says inside a plain and outside a complemented primitive.
 * Where more than eight other primitives overlap the candidate and the
 * stencil wraps both ways in one pass (GL 2.0, or stencil wrap with
 * EXT_stencil_two_side), the convex ones count by winding numbers
 * instead, 255 a batch: +1 where a front face lies in front of the
 * candidate, -1 where a back face does (negated for a plain primitive), so
 * a pixel survives where the batch's sum is minus its plain count, and
 * the nearest survivor per pixel is kept (on the GPU or the CPU: see "The
 * GPU resolve" below). Faces that coincide
 * with the candidate (within 4 depth units) count as crossed before it: a
 * subtracted box sharing a face's plane takes it away, an intersected one
 * keeps it, two touching faces cancel (the exact reference's rule for
 * crossings at one distance; no speckle). The result is written into the
 * depth buffer (what it held before the resolve stays where nearer:
 * earlier products, a keep_contents frame's depth). Then the products' faces
 * are drawn like draws in every pass (ambient, lit, shadow tests, normal
 * and visibility outputs, the screen mask) with depth EQUAL on the
 * resolved surface, a complemented primitive's back faces with their
 * normals turned to the eye (GL1: two-sided lighting for them). Products
 * receive shadows from every technique (all five are tested against the
 * exact reference; vdsm's position buffer keeps a face's fragment where its
 * window depth lies within 2^-21 of the resolved depth rather than depth
 * EQUAL, as the resolve's float copy may round otherwise into that buffer's
 * depth format). Products cast shadows under the map techniques (map-pcf,
 * map-depth with its side test, map-combine; spot and directional maps and
 * point lights' faces): the same resolve runs from the light over the
 * rectangle of the map the products' bounding boxes cover (the projection
 * cropped to it), in the map's own framebuffer where that has a stencil
 * buffer (GL1 maps drawn in the frame's), else in a depth-stencil texture
 * framebuffer of stin's (made at the first such frame, as large as the
 * largest map, never shrunk; packed depth-stencil needed, else logged and
 * nothing cast), and goes into the map before the ordinary casters, its
 * depth pushed back by the light's shadow_offset as glPolygonOffset would
 * (slope from the resolved depth's one-sided differences). Its CPU copies
 * follow the camera's resolve in the staging (9 bytes a texel of the
 * rectangle); a rectangle that does not fit goes in bands of rows, each a
 * resolve (stin_frame_stats.csg.cast_maps, csg.cast_bands).
 * STIN_DEBUG_CSG_NO_CAST turns casting off. vdsm casts products exactly,
 * as it casts triangles, where the context has GL 4.3's shader storage
 * buffers (the "compute shaders" capability): per light and product, each
 * primitive's shadow polygons list in per-pixel linked lists every
 * crossing of the pixel's segment to the light with that primitive (which
 * primitive, where, and whether the segment enters it there), then a
 * screen pass walks each list from the light back to the surface - where
 * the light itself lies inside a primitive found by a ray's parity on the
 * CPU - and the pixel is shadowed where the product's normal form holds
 * anywhere on the way (crossings within 2^-16 of their distance count
 * together: an edge two triangles share once, a grazed silhouette not at
 * all, shared face planes as in the resolve). Two passes a light and
 * product; the lists take 4 bytes a pixel of the viewport plus a pool of
 * 16-byte nodes, one a pixel at first and grown (that product listed
 * again) when a product's crossings outrun it (stin_frame_stats.
 * shadows.vdsm_csg_casts, shadows.vdsm_csg_bytes). Without the storage
 * buffers (gl33-core), or where a product has more than 128 primitives or
 * 64 terms (logged once: "vdsm: a CSG product of P primitives and T terms
 * is past the walk's limits (128 and 64): the products cast through a
 * depth map"), vdsm casts the frame's products through the depth
 * map below instead (per light, after its mask is written: 0 into the
 * light's channel wherever the map shadows the position buffer's surface;
 * the map's bound at those shadows' edges; logged once a light, "vdsm: CSG
 * products cast through map-pcf (SIZE) for light N"; the map made at
 * stin_create where CSG is chosen). A product's volume
 * would need its resolved silhouette, so volumes on the GLSL tiers (with
 * framebuffer objects and depth textures) cast products
 * through a map of their own: per light, just before its volumes are
 * counted, the products are resolved from the light into one depth atlas
 * (3 x 2 cells of shadows.map_size texels a side, halved while three
 * exceed GL_MAX_TEXTURE_SIZE; a spot or directional light's map in one
 * cell, a point light's six faces in all six: 24 MiB of GL memory at 1024,
 * made at stin_create where volumes run on a GLSL tier with CSG or
 * displacement chosen, shared with vdsm's), and after the
 * count one more pass over the frame's opaque surfaces (depth EQUAL, the
 * map-pcf test with the light's pcf_kernel; displaced draws go into the map
 * too, see Displacement) sets the stencil wherever that
 * map shadows the pixel, so the light's lit pass (or its channel of the
 * screen mask) lights only what both the volumes and the map leave lit: exact
 * for the ordinary casters, the map's bound at the products' shadow edges.
 * Logged once a light (INFO, FALLBACK): "volume: CSG products cast through
 * map-pcf (SIZE) for light N". Frames without products draw none of it.
 * On the GL1 tier with multitexture volumes do the same with map-depth's
 * test: the map on texture unit 1 by eye-linear texgen, its compare's
 * result in alpha and the alpha test passing the shadowed fragments
 * (logged "... through map-depth (SIZE) ..."). With framebuffer objects,
 * depth textures and shadow compare (gl21's GL1 tier) it is the atlas
 * above. Without framebuffer objects (gl14-shadow) each light's map is
 * drawn as map-depth draws its own: in the light pre-pass, before the
 * frame's clear, in the frame's buffer at the viewport's corner
 * (scissored; the products resolved in its stencil, which such a frame
 * needs), and copied into a texture per light and face, SIZE the
 * smaller of shadows.map_size and the largest power of two the viewport
 * holds (logged "... (SIZE, drawn before the frame's clear) ..."; made
 * at the first frame that needs them, one a face, 4 bytes a texel, 1
 * with map-combine, remade when SIZE changes), its projection cropped to
 * the rectangle the products' bounds cover (2 texels clear round it). Without depth textures but with
 * texture_env_combine (gl13-combine) the copy is map-combine's: the
 * products' light-eye depth as an 8-bit ramp over the depths their
 * bounds span, and the test is the ramp's stored - own + 0.5 in alpha
 * (logged "... through map-combine ..."). A point light's six faces are
 * marked one after the other, each kept to its own pyramid by two more
 * texture units (its square, and the side of its plane the light faces):
 * units 1-3 (1-4 with map-combine) in all, else its products cast none,
 * logged once. The map's bound holds at the products' shadow edges on
 * all of them (1% of the pixels the products decide in tests/image/
 * csg_cast_test.c, measured 0-0.04% on gl13-combine and gl14-shadow).
 * On GL 1.1 (gl11: one texture unit, no framebuffer objects or depth
 * textures) the map is made and tested on the CPU (logged "volume: CSG
 * products cast through read-backs (SIZE, the light's depth images tested
 * on the CPU per pixel) for light N"): per light, before its count, the
 * products are resolved from the light into the frame's depth at the
 * viewport's corner and read back, one image for a spot or directional
 * light, one per face for a point light, SIZE the smaller of 128,
 * shadows.map_size and the largest power of two the viewport holds,
 * cropped to the products' bounds as above (the frame's depth there read
 * back first and drawn back after, glDrawPixels, depth ALWAYS). After the
 * count the frame's depth is read back in bands of 16384 pixels, each
 * pixel unprojected and projected into its light's image (a point light's
 * face by the major axis of its direction from the light): shadowed where
 * it lies farther from the light than the stored depth, which carries
 * the light's shadow_offset, plus 2^-14 of the light's window depth (the
 * frame's 24-bit depth unprojected). The decisions go into the stencil
 * as an alpha image (glDrawPixels, alpha test GREATER 0.5, stencil
 * REPLACE 0x80), so the lit pass's "count zero" leaves them dark. Memory:
 * the block holds 7 images of 128 x 128 floats (shadows.map_size below
 * 128: of its size) and the band (16384 x 5 bytes), 528 KiB at the
 * defaults, in stin_memory_size unless the desc rules the path out (tier
 * GL2 or GL4 forced, CSG or shadows forced off); a viewport wider than
 * 16384 pixels casts none (logged once). Cost per light: the frame's
 * depth read back (in bands) and its corner, each image's resolve and
 * read-back, glDrawPixels for the corner and each band, and an unprojection
 * per pixel on the CPU (measured in docs/testing.md). The stencil volumes map-depth (without framebuffer
 * objects) and
 * map-combine hand point lights to cast the products as volumes do: their
 * map (six faces, drawn in the light pre-pass without framebuffer objects),
 * marked into the stencil after each count.
 * Products are opaque; a primitive's normal and height maps are
 * ignored. Passes: about (1 + layers) x (1 + overlapping literals / 8)
 * per literal of each term; on the CPU each layer reads depth back (and
 * the stencil once per batch), so that resolve costs read-backs more than
 * fill. Only the
 * term's literals whose window rectangles (mesh bounds through transform,
 * view and projection; the whole viewport where a corner lies behind the
 * eye) meet the candidate's get a parity pass: one off it is outside (what
 * a complemented literal asks) or rules the candidate out (a plain one), so
 * a term of 1000 primitives costs passes by its overlaps, not 1000^2.
 * Complemented convex literals whose window rectangles lie apart (a pixel's
 * margin) are taken together, up to 32 from the next 64 of the term: no
 * pixel holds a layer of two of them, so they share the layer's clear, the
 * count of the other literals, the stencil-tested kill and the take, as
 * OpenCSG batches its primitives (stin_frame_stats.csg.grouped). A literal
 * counted over a member whose world box it does not meet follows the same
 * coincidence rule as any other (faces within 4 depth units of the
 * candidate count as crossed). Memory:
 * the CPU copies use the block's texture staging or mesh-creation scratch,
 * whichever is larger (both idle during a frame): 9 bytes a pixel of the
 * viewport (the GPU resolve: 1); a viewport that needs more is logged once
 * and its products are not drawn (raise desc.max_texture_bytes). GL state:
 * the CPU resolve clears the stencil buffer to 0 after it (its contents are
 * the frame's anyway, see GL STATE); the caller's pixel pack state
 * (alignment, row length, skips, a bound pixel pack buffer) is set aside
 * around the read-backs and given back, unpack state as for textures.
 * The GPU resolve: on the GLSL tiers where the context has FBOs and packed
 * depth-stencil textures, the frame's resolve reads nothing back (under
 * every CSG technique; GL1 tiers, the lights' map resolves and
 * STIN_DEBUG_CSG_READBACK read back as above). It runs in a work FBO of
 * stin's (a depth-stencil texture at the viewport's window size, x + w by
 * y + h, in the frame's depth precision) and leaves the frame's depth and
 * stencil alone until its end: a candidate's losing pixels go to the far
 * plane by a stencil-tested quad; the candidate is min-merged into a result
 * texture (a second FBO) by a quad writing its depth as gl_FragDepth; a
 * stencil's largest value (the layer count of a non-convex primitive, scs's
 * sample) comes from occlusion queries of quads at thresholds 1-16, 32, 64,
 * 128, 255 (one wait, exact up to 16, a bound above; where there are no
 * queries it is read back); the products' faces are then drawn into the
 * frame, depth LESS, each fragment kept where it lies within 2^-21 of the
 * result, so the frame's depth holds the faces' own depth (the result,
 * rasterised in another buffer and carried through a sampler, can be a
 * step off). Its image equals the CPU resolve's but on pixels an edge
 * passes exactly through (tests/image/csg_test.c: at most 2 a case).
 * In place: where the frame's only candidate is one scs term (one product
 * whose normal form has one term; the frame clears its buffers, no
 * desc.keep_contents; a framebuffer that is not multisampled: a
 * multisampled one takes the work buffer, merge and snap,
 * MULTISAMPLED TARGETS), it runs in the
 * frame's own depth and stencil, whose depth then holds the faces' own
 * rasterised depth: no work buffer, merge or snap (on llvmpipe 0.5-0.7x
 * the frame of a box minus one sphere). Its stencil is cleared after it. The result texture takes a copy of the
 * frame's depth (glCopyTexSubImage2D, no read-back) only when a later pass
 * draws the products elsewhere (screen masks, outlines, depth-peel, vdsm's
 * position buffer), once a frame (stin_frame_stats.csg.in_place;
 * STIN_DEBUG_CSG_NO_IN_PLACE keeps the work buffer).
 * Direct: every other frame's GPU resolve but interval's (its walk's layers
 * are no one face set) and a multisampled framebuffer's keeps the work
 * buffer but no result: each candidate (a goldfeather layer, an scs term)
 * is taken by drawing its own faces into the frame, depth LESS, each
 * fragment kept within 2^-21 of the candidate's depth in the work buffer.
 * The frame's depth is then the result, with the faces' own rasterised
 * depth: no result clear, merge quads or final snap, and the result
 * texture copied on demand as in place (stin_frame_stats.csg.direct;
 * STIN_DEBUG_CSG_NO_IN_PLACE merges instead).
 * Both resolves keep to a rectangle: a term's surface (scs) or a
 * candidate's (goldfeather) lies inside its own and every plain literal's
 * window rectangle, so the clears, draws and quads of that term or
 * candidate are scissored to it, and the CPU resolve reads back only that
 * rectangle (into its place in the viewport-sized staging).
 * Packed: without depth textures (bare OpenGL ES 2.0, no read-back either;
 * its FBOs cannot pair depth and stencil renderbuffers on Mesa, which
 * answers GL_FRAMEBUFFER_UNSUPPORTED) the resolve works in the frame's own
 * depth and stencil, just cleared, with the frame's colour as scratch: each
 * candidate is found there as in place, then taken by its own faces, depth
 * EQUAL on it, writing their window depth packed into 24 bits of RGBA8
 * (as map-pcf's packed maps) where nearer than the result so far, and the
 * colour of the candidate's rectangle is copied into the result texture
 * (RGBA8, 4 bytes a pixel; glCopyTexSubImage2D, no read-back). At the end
 * the frame's colour, depth and stencil are cleared again as the target's
 * clear left them and the faces snapped onto the unpacked result, as
 * above (stin_frame_stats.csg.packed; no in-place or direct variant). A
 * frame that keeps its contents, or a multisampled framebuffer, has no
 * cleared buffers to work in: its products are not drawn (logged once).
 * Measured on csg.json (es20): P and N as es20-ext's but one pixel of one
 * case (eye-cavity's coverage); P 100.000% on carved and both.
 * Programs: three (two packed), made at stin_create; GL memory: two
 * textures (one packed, 4 bytes a pixel), 8 bytes a
 * pixel for 24-bit depth (16 for 32-bit float), made at the first frame
 * with a product, grown, never shrunk, freed at stin_destroy
 * (stin_frame_stats.csg.gpu_resolves, csg.gpu_bytes), and into a
 * multisampled target a third, the snap's ids (RGBA8, 4 bytes a pixel,
 * made at the first such frame; MULTISAMPLED TARGETS).
 * The near and far planes: where the near plane cuts a primitive of a term
 * (its bounding box), that primitive has lost the faces in front of the
 * plane, so the term's parity is counted from behind instead (faces behind
 * the candidate; the same coincidence rule). That needs the far plane to
 * cut none of the term's primitives, or depth clamping (GL 3.2 or
 * ARB_depth_clamp); without either the term counts from the front and a
 * warning is logged once. Where the near plane lies inside a product (the
 * camera inside the solid), the product is cut open there: a cap at window
 * depth 2^-10 (just behind the near plane), facing the eye, in the
 * material of the product's first primitive, resolved as one more
 * candidate of each term whose plain primitives the near plane all cuts
 * and drawn like a face in every pass. The cap's quad is stin's own mesh
 * (one slot, 4 vertices and 2 triangles more than the desc's capacities,
 * counted by stin_memory_size). */

/* CSG technique "scs" (the default; every tier with a stencil buffer, the
 * same depth write-back, face passes, GL state and staging as goldfeather):
 * sequenced convex subtraction for a product whose every primitive is
 * convex (stin_mesh_info.convex) and whose every term has a plain
 * primitive. Per term: depth cleared to 0 and the plain primitives' front
 * faces drawn with depth GREATER (the farthest front face, where a convex
 * intersection begins); the complemented primitives in a subtraction
 * sequence, each pushing the depth to its back face where the depth lies
 * inside it (its front in front of the depth, its back not), front to back
 * (by the eye's power with respect to each bounding box's sphere: spheres,
 * intersecting ones too, then take one run; orthographic cameras: the
 * nearest corner's w), the list run at most as many times as complemented
 * primitives can cover one pixel (1 + the most others one's window box
 * meets, or their count past 1024 of them: every order of those is in
 * the sequence; once where every two whose window boxes meet have world
 * boxes apart by more than 8 depth units along every ray through both, as
 * a drilled plate's holes: no point lies in two), each run after the
 * first only where a check finds the depth still inside one of them
 * somewhere (one pass a primitive counting +1 at its front and -1 at its
 * back in the stencil, its largest value taken as stencil sample counts
 * are: one wait; STIN_DEBUG_CSG_SCS_NO_EARLY_STOP runs every run of the
 * bound; stin_frame_stats.csg.scs_runs counts the runs, csg.scs_checks the
 * checks); complemented
 * primitives whose boxes miss the term's rectangle are left out;
 * then a pixel survives where the depth lies in front of every plain
 * primitive's back face, counted in the stencil 255 primitives a batch
 * (no counter overflows; STIN_DEBUG_CSG_SCS_NO_BATCH shows why), and the
 * nearest survivor per pixel is kept as goldfeather keeps it (on the GPU
 * or the CPU).
 * Faces within 4 depth units of the depth count as in front of it (the
 * coplanar rule above). Passes a term: plain + 2 x complemented x runs (3
 * without two-sided stencil: the mark of the depth inside a primitive
 * takes a pass for its front and one for its back faces) +
 * complemented x (runs - 1) checks + plain; read-backs on the CPU: the
 * depth, one stencil a check and one each 255 plain primitives, against
 * goldfeather's per literal and layer (the GPU resolve: one wait a check),
 * so it is the faster from a few primitives up (stin-bench --csg on
 * llvmpipe, docs/benchmarks.md). More than 255 complemented primitives
 * over one pixel caps the runs at 255 (logged once).
 * Selection per product: under "scs", a product with a non-convex
 * primitive (or a term of complements only) is resolved by goldfeather,
 * logged once per context (INFO; WARNING where the caller forced scs with
 * desc.techniques[STIN_FEATURE_CSG]); force "goldfeather" for every
 * product. stin_frame_stats.csg.scs_products counts the products scs
 * resolved. */

/* CSG technique "interval" (GL4: GLSL 1.50 lighting, FBOs, float and array
 * textures, any-samples-passed queries; forced, not the default: on llvmpipe its
 * walk makes it 1.4-3x goldfeather's frame time on the bench's products,
 * docs/benchmarks.md):
 * the seed's G-buffer ray-interval method generalised to k layers per
 * primitive (desc.csg.interval_layers, default 4). Per product: each
 * primitive alone depth-peeled into k layers along the camera rays (depth
 * LESS into a layer of the frame's depth format, fragments at or in front
 * of the layer before discarded; an RG32F layer beside it keeps each
 * fragment's float depth and whether it is a front or a back face), then
 * one full-screen pass walks every primitive's crossings per pixel in depth
 * order: a front face enters, a back face leaves, a primitive starts inside
 * where its first crossing is a back face (the near plane cuts it),
 * crossings within 4 units of 2^-24 of each other count together (the
 * coplanar rule above), and the first crossing where the normal form turns
 * true is the surface (the near-plane cap, as goldfeather's, where it is
 * true from the start). The walk writes each pixel's surface layer; each
 * layer some pixel chose is peeled once more in the resolve's depth
 * buffer (the frame's own on the CPU, read back, so the depth kept is the
 * one the face draws' depth EQUAL meets; the GPU resolve's work buffer,
 * merged where the walk chose it, its faces snapped as goldfeather's) and
 * kept per pixel where nearer in goldfeather's result (the same
 * write-back, face passes, GL state and staging). The walk is read back
 * in both. Passes a product: n x (k + 1) peels (the last of each
 * primitive in an occlusion query: a fragment past layer k is an
 * overflow) + the cap + 1 walk + 1 peel (and on the CPU a read-back) per
 * layer chosen, against goldfeather's per literal and layer.
 * GL memory (made at the first frame with a product, grown with the
 * viewport's window size (x + w by y + h) and the largest n so far, freed
 * at stin_destroy): 2 x ceil((n k + 2) / 2) layers of 12 bytes a pixel
 * (depth 4, RG32F 8) and 1 byte a pixel of walk target, so about
 * (n k + 2) x 12 + 1 bytes a pixel: 409 bytes a pixel, 120 MiB at 640 x 480
 * for n = 8, k = 4 (31 MiB for n = 2); stin_frame_stats.csg.interval_bytes
 * reports it. Selection per product: under "interval", a product goes to
 * scs's rule (then goldfeather) when it has more than 32 primitives or 64
 * terms, n k + 1 > 255 layers (the walk's 8-bit answer) or more than
 * GL_MAX_ARRAY_TEXTURE_LAYERS, or a primitive shows more than k crossings
 * on a pixel (found that frame: the product is resolved again by the
 * others), logged once per context (INFO; WARNING where the caller forced
 * interval). stin_frame_stats.csg.interval_products counts the products
 * interval resolved. A light's map resolve (products casting) runs it too,
 * in the map's resolve framebuffer. */

/* The normal form of the frame's product `product` (0 = the first accepted
 * by stin_draw_csg since stin_begin_frame, until the next begin): the
 * number of terms; when `literals` is not NULL, the literals of term
 * `term` (at most `capacity` of them) as primitive index * 2 + 1 for a
 * complemented primitive, * 2 for a plain one, and *count their number.
 * Returns the term count, 0 for an unknown product. */
uint32_t stin_query_csg_terms(const stin_context *ctx, uint32_t product, uint32_t term,
                              uint32_t *literals, uint32_t capacity, uint32_t *count);

/* The frame plan's stages as STIN_DEBUG_STAGE_TIMES times them (GPU time
 * between the stage's timestamps, summed where a stage comes back, as the
 * per-light ones do light by light). */
typedef enum stin_stage {
    STIN_STAGE_PREPASS = 0, /* light pre-passes: the shadow maps (GL1 maps, map-pcf) */
    STIN_STAGE_CSG,         /* CSG products resolved into the depth (vdsm's copy too) */
    STIN_STAGE_BASE,        /* target clear, depth and ambient; unshadowed frames' lit
                             * batches; the normal output */
    STIN_STAGE_TRANSLUCENT, /* deep and colour maps, made per light */
    STIN_STAGE_SHADOW,      /* per light: the technique's visibility (stencil volumes,
                             * screen masks, vdsm's buffers and polygons, map tests) */
    STIN_STAGE_LIGHTING,    /* per light: the lit passes reading it */
    STIN_STAGE_BLENDED,     /* blended draws: peeling, sorting, compositing (their
                             * layers' lights count in shadow and lighting) */
    STIN_STAGE_EXPORT,      /* the visibility export and the outline */
    STIN_STAGE_COUNT
} stin_stage;

/* "prepass", "csg", "base", "translucent", "shadow", "lighting",
 * "blended", "export"; "unknown stage" else. */
const char *stin_stage_name(stin_stage s);

/* Per-feature counters of stin_frame_stats. */
typedef struct stin_lighting_stats {
    /* GLSL lighting: lit draws (per pass) shaded by a program specialised to
     * the pass's lights and the draw's material, and such programs built
     * this frame (each is built once, when a frame first needs it, and kept:
     * up to 32 a context) */
    uint32_t specialised, programs_built;
} stin_lighting_stats;

typedef struct stin_shadows_stats {
    uint32_t map_size;           /* texels a side the maps were rendered at (0: none) */
    /* map-pcf: point-light faces drawn into their atlas (per light and
     * pass; a face no visible draw's bounds reach is skipped: no visible
     * point reads it), and the casters drawn into them (a caster only into
     * the faces its bounds meet) */
    uint32_t map_faces, map_face_casters;
    /* volume: sides and caps drawn, and the casters (per light sample) by
     * z-fail and by z-pass; on GL4 the casters whose volumes the geometry
     * shader extruded from the mesh's own buffers (their triangles count in
     * volume_triangles only with STIN_DEBUG_VOLUME_COUNT) */
    uint32_t volume_triangles;
    uint32_t zfail_casters, zpass_casters;
    uint32_t volume_gpu_casters;
    /* volume, per light sample: casters whose volume was cut at a plane past
     * every visible receiver and the eye (instead of running to infinity),
     * and casters skipped because their cut volume misses the view frustum */
    uint32_t volume_cut_casters, volume_culled_casters;
    /* vdsm: primitives its geometry shader emitted, all lights
     * (GL_PRIMITIVES_GENERATED, the seed's P_c; STIN_DEBUG_VDSM_COUNT, 0
     * where the context has no queries) */
    uint32_t vdsm_primitives;
    /* vdsm: lights (per peeled layer too) whose shadow polygons came from a
     * culling pass, and with STIN_DEBUG_VDSM_COUNT the faces those passes
     * kept (the side faces and own faces of casting triangles the eye sees,
     * or the viewport where the eye is inside a triangle's volume) */
    uint32_t vdsm_cull_passes, vdsm_kept_faces;
    /* vdsm: lights (per peeled layer too) whose deepest receivers came by
     * storage-buffer atomics (GL 4.3; shader storage binding point 0) */
    uint32_t vdsm_atomic_receivers;
    /* vdsm: products whose shadow it drew (per light and peeled layer), and
     * the GL memory of its crossing lists (heads at the viewport's size and
     * the node pool, grown to the most crossings a product took so far) */
    uint32_t vdsm_csg_casts;
    uint64_t vdsm_csg_bytes;
    /* The measured choice of the exact technique (SHADOWS), as
     * stin_shadow_choice values: choice_frame what this frame's shadows ran,
     * choice_current the chosen one (they differ on a trial and on a frame
     * volumes cannot draw); both STIN_SHADOW_CHOICE_OFF where the choice is
     * off in the context. choice_trial: 1 on a trial frame. choice_ms: the
     * smoothed GPU time of a frame in ms per candidate, indexed by
     * stin_shadow_choice - 1 (vdsm, GPU-extruded volumes, CPU-built volumes),
     * 0 where not known yet (or not a candidate here) */
    uint32_t choice_frame, choice_current, choice_trial;
    float choice_ms[3];
} stin_shadows_stats;

/* What a frame's exact shadows ran under the measured choice (SHADOWS). */
typedef enum stin_shadow_choice {
    STIN_SHADOW_CHOICE_OFF = 0,    /* no measured choice in this context */
    STIN_SHADOW_CHOICE_VDSM,       /* "vdsm" */
    STIN_SHADOW_CHOICE_VOLUME_GPU, /* "volume", extruded by the geometry shader */
    STIN_SHADOW_CHOICE_VOLUME_CPU  /* "volume", built on the CPU */
} stin_shadow_choice;

typedef struct stin_translucent_stats {
    /* deep: layers peeled (passes into a deep map), all lights and faces;
     * the faces peeled (a spot or directional light's one, a point light's
     * six, less those no transparent caster's bounding box reaches, which
     * the early stop leaves unpeeled) */
    uint32_t deep_layers, deep_faces;
} stin_translucent_stats;

typedef struct stin_csg_stats {
    uint32_t products, terms;    /* accepted by stin_draw_csg (terms of their normal forms) */
    uint32_t dropped;            /* products stin_draw_csg refused */
    /* products resolved by "scs" (the others of a frame went to goldfeather),
     * the runs of its subtraction sequences (every term) and their checks
     * for a depth still inside a subtracted one */
    uint32_t scs_products, scs_runs, scs_checks;
    /* products resolved by "interval", and the GL memory its layers and
     * target hold (grown to the largest viewport and product so far) */
    uint32_t interval_products;
    uint64_t interval_bytes;
    /* goldfeather: candidates that shared their passes with others (a group
     * of complemented convex literals whose window rectangles lie apart) */
    uint32_t grouped;
    /* 1 when the frame's resolve kept its candidates and result on the GPU
     * (no read-backs), 0 when it read them back; and that resolve's GL
     * memory (two depth textures at the viewport's window size; the packed
     * resolve's one RGBA8 texture) */
    uint32_t gpu_resolves;
    uint64_t gpu_bytes;
    /* 1 when the frame's GPU resolve ran in place (one scs term in the
     * frame's own buffers: no work buffer, merge or snap), or took each
     * candidate by snapping its faces straight into the frame's depth (no
     * result buffer or merge) */
    uint32_t in_place, direct;
    /* 1 when the frame's GPU resolve was the packed one (no depth textures:
     * bare OpenGL ES 2.0; the frame's own buffers as its work, the result
     * packed into an RGBA8 texture) */
    uint32_t packed;
    /* maps (a spot or directional light's, a point light's face) that
     * products were resolved into from the light: they cast into it; and the
     * resolves those took: one a map, more where the products' rectangle of
     * it outgrew the staging beside the camera's resolve (bands of rows),
     * and map-depth's side test and map-combine's ramp resolving such a map
     * again band by band */
    uint32_t cast_maps, cast_bands;
} stin_csg_stats;

typedef struct stin_transparency_stats {
    /* depth-peel: geometry passes that peeled a camera layer (the last one,
     * which found nothing, counted: a scene of n layers under a cap above n
     * takes n + 1), and the layers that drew something; dual-peel: its
     * min-max passes (n layers: n / 2 + 1) and the layers lit */
    uint32_t peel_passes, peel_layers;
} stin_transparency_stats;

typedef struct stin_frame_stats {
    uint32_t draws, lights, passes, triangles;
    uint32_t dropped_draws, dropped_lights;
    stin_lighting_stats lighting;
    stin_shadows_stats shadows;
    stin_translucent_stats translucent;
    stin_csg_stats csg;
    stin_transparency_stats transparency;
    /* STIN_DEBUG_STAGE_TIMES: 1 when stage_ns holds this frame's GPU time
     * per stage in nanoseconds (0: not asked, or no timer queries) */
    uint32_t stage_times;
    uint64_t stage_ns[STIN_STAGE_COUNT];
} stin_frame_stats;

stin_frame_stats stin_query_frame_stats(const stin_context *ctx);

/* The projection the frame draws with, valid from stin_begin_frame until the
 * next one. Stencil shadow volumes (and map-depth / map-combine, whose point
 * lights may use them) move a perspective far plane to infinity (the nudged
 * P_inf of Everitt & Kilgard) in every frame, whatever its lights, so an
 * application that draws its own geometry into the same depth buffer (before
 * stin with desc.keep_contents, or after) must draw it with this projection, and
 * one that unprojects depth must use it rather than its own. */
void stin_query_frame_projection(const stin_context *ctx, float out[16]);

/* ---- outline ----------------------------------------------------------------
 * A frame with desc.outline_step > 0 (a beauty frame; normal and visibility
 * outputs and STIN_EXPORT_VISIBILITY_ONLY frames draw none) ends with a
 * deferred outline, seed 004's Sobel filter with its pixel step a
 * parameter: every draw's shading normal (CSG products' faces included,
 * blended draws too) goes into stin's screen mask over a depth of its own,
 * then one screen pass blends outline_color over the frame's viewport
 * where nine taps outline_step pixels apart around a pixel (clamped into
 * the viewport) show
 *   - a silhouette: some taps cover a surface and some do not (the line
 *     lies on both sides of it);
 *   - a crease: the Sobel magnitude of the normals, |Gx| + |Gy| summed
 *     over x, y and z, reaches outline_normal_edge (default 1: the seed's;
 *     a 90-degree edge measures about 4 at step 1);
 *   - a step in depth: in one of four directions across the pixel, the
 *     depth halfway between the two opposite taps (exact on any plane,
 *     so floors seen edge-on draw no lines) lies farther from the pixel's
 *     own than outline_depth_edge (default 0.02) of its eye distance.
 * The decision is on or off per pixel (no antialiasing; a partly
 * transparent outline_color fades it). Needs GLSL lighting, framebuffer
 * objects and packed depth-stencil textures: elsewhere (the GL1 tier)
 * stin_begin_frame refuses such a frame with STIN_ERROR_UNSUPPORTED
 * (logged); outline_step must lie in 0..64. Costs two passes (a geometry
 * pass of every draw and a screen pass) and no memory beyond the screen
 * mask's (8 bytes a pixel, see SHADOWS). stin-render --outline N draws it
 * in black. */

/* ---- visibility for the application's own shaders ------------------------
 * A frame with desc.export_visibility writes, after its drawing, every
 * light's visibility at every pixel of the viewport into one RGBA8 texture,
 * the visibility map: 1 where the surface of the nearest opaque draw sees
 * the light, 0 where it is shadowed, fractions for area lights (their
 * samples' share) and for map-pcf's filtered edges, and 0 where no opaque
 * draw covers the pixel. It is the test the frame's own lit passes use,
 * drawn again in stin's screen mask: each light's visibility equals the
 * STIN_OUTPUT_VISIBILITY of a frame with that light first but on a few
 * edge pixels that round the other way there (tests/image visibility_test.c
 * measures at most 0.05% of the covered pixels, 0.2% with the filtered
 * map-pcf and map-depth lookups). Blended draws are not in it (they
 * neither hide what is behind them nor have one depth per pixel).
 * Transmittance: where the frame's lights had deep or colour maps (the
 * translucent-shadows techniques "deep" and "coloured" with transparent
 * casters in the frame), each light's map is made again after the lights
 * and its transmittance alone - per colour channel, 1 where no transparent
 * caster lies toward the light, 0 behind an opaque one it carries - goes
 * into a tile of its own (RGB) after the visibility tiles, light i in tile
 * transmittance_tile + i: the product of a light's visibility and its
 * transmittance is the coloured shadow stin's lit passes use (within 2/255:
 * two 8-bit values multiplied; tests/image visibility_test.c). The maps are
 * made twice in such a frame (once for the lit pass, once here).
 * Layout: light i is channel i % 3 (R, G, B) of tile i / 3; tiles lie two to a row,
 * bottom row first, each tile_width x tile_height texels, and window pixel
 * (x, y) of the frame is texel (x, y) of its tile (a tile covers the
 * viewport's far corner, x + width by y + height, so gl_FragCoord addresses
 * it in a pass with the frame's viewport).
 * Needs framebuffer objects and packed depth-stencil textures (GL 3.0,
 * ARB_framebuffer_object or EXT_framebuffer_object with
 * EXT_packed_depth_stencil): without them stin_begin_frame refuses the
 * export with STIN_ERROR_UNSUPPORTED (logged). Lights whose tile would pass
 * GL_MAX_TEXTURE_SIZE are left out, logged (stin_visibility_map.lights).
 * The tiles are drawn in stin's screen mask (8 bytes a pixel of GL memory,
 * see SHADOWS) and copied into the map (4 bytes a texel), both made at the
 * first frame that needs them and grown, never shrunk. The map is stin's:
 * sample it until the next stin_end_frame or stin_destroy; do not change it.
 * A frame into a framebuffer without stencil (SHADOWS) exports 1 on every
 * covered pixel, as its lit passes draw. */
typedef struct stin_visibility_map {
    uint32_t texture;                 /* GL_TEXTURE_2D: RGBA8, NEAREST, CLAMP_TO_EDGE */
    uint32_t width, height;           /* texels of the texture */
    uint32_t tile_width, tile_height; /* texels of one tile */
    uint32_t lights;                  /* lights in it: 0 .. the frame's light count */
    uint32_t transmittance_tile;      /* light 0's transmittance tile (light i's: this + i);
                                       * 0: the map holds none */
} stin_visibility_map;

/* The visibility map of the last frame that exported one, ended with
 * stin_end_frame. STIN_ERROR_INVALID_STATE while a frame is open or when the
 * last frame exported nothing. */
stin_result stin_query_visibility_map(const stin_context *ctx, stin_visibility_map *out);

/* A GLSL chunk for the application's fragment shaders, for GLSL 1.10 to 4.60
 * on core and compatibility contexts and GLSL ES 1.00 to 3.20 on OpenGL ES
 * and WebGL: paste it after the #version line (on ES after the program's
 * default float precision; the chunk's own uniforms and texel address are
 * highp where the fragment stage has it), before any use. It declares
 *   uniform sampler2D stin_visibility_map;
 *   uniform vec4 stin_visibility_layout;   tile width, tile height, 1 / map
 *                                          width, 1 / map height
 *   uniform float stin_visibility_lights;  lights in the map
 * and defines
 *   float stin_visibility(int light);      at gl_FragCoord: 1 lit .. 0 shadowed
 *                                          (1 for lights not in the map)
 *   vec3 stin_shadow_transmittance(int light);  per colour channel: the
 *                                          visibility times the light's
 *                                          transmittance where the map has
 *                                          it, as stin's lit shaders use it
 *   uniform float stin_visibility_transmittance;  the first transmittance
 *                                          tile (0: none)
 * Its names all start with stin_ (STIN_ for macros). */
const char *stin_visibility_glsl(void);

/* Sets the chunk's uniforms on the program the caller has current
 * (glUseProgram) and binds the visibility map on texture unit `unit`; the
 * active texture unit is given back. STIN_ERROR_INVALID_STATE with no map
 * (see stin_query_visibility_map), on a context without GLSL or with no
 * current program (each logged),
 * STIN_ERROR_INVALID_ARGUMENT for a unit the context does not have.
 * A program without the chunk's uniforms is fine (nothing is set); one that
 * declares any of their names with another type (say an int
 * stin_visibility_lights), or whose last link failed, is
 * STIN_ERROR_INVALID_STATE, logged, with nothing bound or set. */
stin_result stin_bind_visibility(stin_context *ctx, int unit);

/* Sample i of n of an area light: the point light the soft-shadow pass uses.
 * The n points lie inside the ball of the light's radius with radial density
 * 1 / sqrt(r^2 - s^2), which projects to a uniform disc seen from any
 * direction (Abel transform): radii stratified by the base-2 radical inverse
 * of i, directions on a Fibonacci spiral; the same every frame. n = 1 or
 * radius 0 gives the light's position. For tests that must use the same
 * samples (the exact reference integrates the light's disc instead). */
void stin_light_sample(const stin_light_desc *light, uint32_t i, uint32_t n, float out_position[3]);

#ifdef __cplusplus
}
#endif
#endif /* STIN_H */
