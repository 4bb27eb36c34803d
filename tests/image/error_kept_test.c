/* SPDX-License-Identifier: MIT */
/* stin never clears a GL error it did not raise (issue 38): the caller's
 * pending GL_INVALID_ENUM is still there for the caller's glGetError after
 * stin_create, the scene's meshes and textures, a frame with the visibility
 * export where the tier has one, and stin_destroy - on four-lights, every
 * tier the profile runs. On main stin_create drained glGetError in a loop
 * (capability detection) and the checked build after every pass. */
#include "caller_gl.h"
#include "image_test.h"
#include "test_context.h"

#include <stdio.h>
#include <string.h>

void error_kept_tests(run *r, stin_tier tier, const char *path)
{
    char name[160], err[256];
    scene s;
    caller_gl gl;
    test_context t;
    stin_frame_desc fd;
    stin_result frame = STIN_ERROR_INVALID_STATE;
    GLenum kept;
    if (strcmp(scene_base_name(path), "four-lights"))
        return;
    snprintf(name, sizeof name, "%s/four-lights/caller-error-kept", stin_tier_name(tier));
    if (!scene_load(path, &s, err, sizeof err)) {
        report(r, "FAIL", name, "%s", err);
        return;
    }
    caller_gl_load(&gl, r->plat);
    while (gl.GetError() != GL_NO_ERROR) { /* the test's own state: nothing pending */
    }
    gl.Enable(0); /* the caller's error: GL_INVALID_ENUM, left pending */
    if (test_context_create(&t, r, &s, tier, STIN_TECH_NONE, 0)) {
        /* the export's needs (stin.h): otherwise the frame is refused */
        uint64_t need = STIN_CAP_BIT(STIN_CAP_FBO) | STIN_CAP_BIT(STIN_CAP_PACKED_DEPTH_STENCIL);
        test_frame_desc(r, &s, &fd);
        if ((stin_query_caps(t.ctx)->present & need) == need)
            fd.export_visibility = STIN_EXPORT_VISIBILITY;
        frame = test_context_frame(&t, &s, &fd, -1);
        test_context_destroy(&t);
    }
    kept = gl.GetError();
    report(r, frame == STIN_OK && kept == GL_INVALID_ENUM ? "PASS" : "FAIL", name,
           "the caller's GL_INVALID_ENUM across stin_create, a frame (%s) and stin_destroy: "
           "glGetError then gives 0x%x (need 0x%x)",
           stin_result_name(frame), (unsigned)kept, (unsigned)GL_INVALID_ENUM);
    scene_free(&s);
}
