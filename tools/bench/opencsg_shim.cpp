// SPDX-License-Identifier: MIT
// OpenCSG for stin-bench's CSG section (section_csg.c), behind a C API
// (opencsg_shim.h). OpenCSG takes its GL entry points from GLEW, which the
// application initialises on its current context. Debian's GLEW is built
// for GLX: glewInit loads the GL entry points through the GL dispatch and
// then fails with GLEW_ERROR_NO_GLX_DISPLAY on an EGL context (no X
// display), which is harmless here; on an OSMesa context the dispatch has
// no current context, glGetString answers NULL and glewInit fails with
// "Missing GL version": OpenCSG cannot run there (reported, not faked).
#include <GL/glew.h>
#include <opencsg.h>

#include <cstdio>
#include <vector>

extern "C" {
#include "opencsg_shim.h"
}

namespace {

// One primitive: its mesh through client arrays under its transform.
class Mesh : public OpenCSG::Primitive {
public:
    explicit Mesh(const ocsg_primitive &p)
        : OpenCSG::Primitive(p.subtract ? OpenCSG::Subtraction : OpenCSG::Intersection, 1), m(p)
    {
    }
    void render() override
    {
        glPushMatrix();
        glMultMatrixf(m.transform);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, m.positions);
        if (m.normals) {
            glEnableClientState(GL_NORMAL_ARRAY);
            glNormalPointer(GL_FLOAT, 0, m.normals);
        }
        glDrawElements(GL_TRIANGLES, (GLsizei)m.index_count, GL_UNSIGNED_INT, m.indices);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
        glPopMatrix();
    }

private:
    ocsg_primitive m;
};

std::vector<OpenCSG::Primitive *> product;

} // namespace

extern "C" int ocsg_init(char *err, size_t err_size)
{
    glewExperimental = GL_TRUE;
    GLenum r = glewInit();
    if (r != GLEW_OK && !(r == GLEW_ERROR_NO_GLX_DISPLAY && GLEW_VERSION_2_0)) {
        std::snprintf(err, err_size, "glewInit: %s (error %u)",
                      (const char *)glewGetErrorString(r), (unsigned)r);
        return 0;
    }
    if (!GLEW_ARB_framebuffer_object || !GLEW_ARB_occlusion_query) {
        std::snprintf(err, err_size, "OpenCSG needs framebuffer objects and occlusion queries");
        return 0;
    }
    return 1;
}

extern "C" void ocsg_set_product(const ocsg_primitive *p, int n)
{
    for (OpenCSG::Primitive *q : product)
        delete q;
    product.clear();
    for (int i = 0; i < n; i++)
        product.push_back(new Mesh(p[i]));
}

extern "C" void ocsg_frame(unsigned framebuffer, int scs, const float view[16],
                           const float projection[16], const float light[4])
{
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(projection);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(view);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    OpenCSG::setOption(OpenCSG::AlgorithmSetting, scs ? OpenCSG::SCS : OpenCSG::Goldfeather);
    // each algorithm's strategy for many primitives: occlusion queries stop
    // SCS's sequence, depth complexity sampling bounds Goldfeather's layers
    OpenCSG::setOption(OpenCSG::DepthComplexitySetting,
                       scs ? OpenCSG::OcclusionQuery : OpenCSG::DepthComplexitySampling);
    OpenCSG::render(product);
    // the surface shaded as OpenSCAD does: the primitives again, depth EQUAL
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glDepthFunc(GL_EQUAL);
    for (OpenCSG::Primitive *q : product) {
        glCullFace(q->getOperation() == OpenCSG::Subtraction ? GL_FRONT : GL_BACK);
        glEnable(GL_CULL_FACE);
        q->render();
    }
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    glDisable(GL_LIGHT0);
    glDisable(GL_LIGHTING);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

extern "C" void ocsg_release(void)
{
    ocsg_set_product(nullptr, 0);
    OpenCSG::freeResources();
}
