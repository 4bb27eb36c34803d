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
        // its window box, as OpenSCAD gives it: the scissor and SCS's batches
        setBoundingBox(p.ndc_box[0], p.ndc_box[1], p.ndc_box[2], p.ndc_box[3], p.ndc_box[4],
                       p.ndc_box[5]);
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

// The application's shading after OpenCSG::render, the same picture as
// stin's frame: stin's per-pixel equation (shaders/gl4/lit.frag) for one
// point light without attenuation, the material's defaults (albedo 0.8,
// no specular colour, shininess 32) and the frame's ambient 0.2, with a
// subtracted primitive's back faces lit from the inside. ftransform()
// keeps the fixed-function depth OpenCSG laid, so depth EQUAL meets it.
const char *const shade_vert = R"(#version 120
varying vec3 v_eye_pos;
varying vec3 v_normal;
void main()
{
    v_eye_pos = (gl_ModelViewMatrix * gl_Vertex).xyz;
    v_normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
)";

const char *const shade_frag = R"(#version 120
uniform vec3 u_light_eye;
uniform vec3 u_ambient;
uniform vec3 u_albedo;
uniform vec3 u_specular;
uniform float u_shininess;
varying vec3 v_eye_pos;
varying vec3 v_normal;
void main()
{
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    vec3 v = normalize(-v_eye_pos);
    vec3 l = normalize(u_light_eye - v_eye_pos);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
    float ndotl = dot(n, l);
    if (ndotl > 0.0) {
        diffuse = vec3(ndotl);
        specular = vec3(pow(max(dot(n, normalize(l + v)), 0.0), u_shininess));
    }
    gl_FragColor = vec4(clamp((u_ambient + diffuse) * u_albedo + specular * u_specular, 0.0, 1.0),
                        1.0);
}
)";

GLuint shade_program;
GLint shade_light;

GLuint compile(GLenum type, const char *text, char *err, size_t err_size)
{
    GLuint s = glCreateShader(type);
    GLint ok = 0;
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[256] = "";
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        std::snprintf(err, err_size, "the shading program failed to compile: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

bool build_shading(char *err, size_t err_size)
{
    GLuint v = compile(GL_VERTEX_SHADER, shade_vert, err, err_size);
    GLuint f = v ? compile(GL_FRAGMENT_SHADER, shade_frag, err, err_size) : 0;
    GLint ok = 0;
    if (!f) {
        glDeleteShader(v);
        return false;
    }
    shade_program = glCreateProgram();
    glAttachShader(shade_program, v);
    glAttachShader(shade_program, f);
    glLinkProgram(shade_program);
    glDeleteShader(v);
    glDeleteShader(f);
    glGetProgramiv(shade_program, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::snprintf(err, err_size, "the shading program failed to link");
        glDeleteProgram(shade_program);
        shade_program = 0;
        return false;
    }
    glUseProgram(shade_program);
    glUniform3f(glGetUniformLocation(shade_program, "u_ambient"), 0.2f, 0.2f, 0.2f);
    glUniform3f(glGetUniformLocation(shade_program, "u_albedo"), 0.8f, 0.8f, 0.8f);
    glUniform3f(glGetUniformLocation(shade_program, "u_specular"), 0.0f, 0.0f, 0.0f);
    glUniform1f(glGetUniformLocation(shade_program, "u_shininess"), 32.0f);
    shade_light = glGetUniformLocation(shade_program, "u_light_eye");
    glUseProgram(0);
    return true;
}

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
    return build_shading(err, err_size) ? 1 : 0;
}

extern "C" void ocsg_set_product(const ocsg_primitive *p, int n)
{
    for (OpenCSG::Primitive *q : product)
        delete q;
    product.clear();
    for (int i = 0; i < n; i++)
        product.push_back(new Mesh(p[i]));
}

extern "C" void ocsg_frame(unsigned framebuffer, int scs, int strategy, const float view[16],
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
    OpenCSG::setOption(OpenCSG::DepthComplexitySetting,
                       strategy == OCSG_OCCLUSION_QUERY     ? OpenCSG::OcclusionQuery
                       : strategy == OCSG_CONVEXITY_ONLY    ? OpenCSG::NoDepthComplexitySampling
                                                            : OpenCSG::DepthComplexitySampling);
    OpenCSG::render(product);
    // the surface shaded as OpenSCAD does, the primitives again depth EQUAL,
    // per pixel as stin shades (the light into eye space by the view)
    float eye[3];
    for (int r = 0; r < 3; r++)
        eye[r] = view[r] * light[0] + view[4 + r] * light[1] + view[8 + r] * light[2] +
                 view[12 + r] * light[3];
    glUseProgram(shade_program);
    glUniform3fv(shade_light, 1, eye);
    glEnable(GL_DEPTH_TEST); // OpenCSG gives back the state it found: off here
    glDepthFunc(GL_EQUAL);
    for (OpenCSG::Primitive *q : product) {
        glCullFace(q->getOperation() == OpenCSG::Subtraction ? GL_FRONT : GL_BACK);
        glEnable(GL_CULL_FACE);
        q->render();
    }
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

extern "C" void ocsg_release(void)
{
    ocsg_set_product(nullptr, 0);
    OpenCSG::freeResources();
    glDeleteProgram(shade_program);
    shade_program = 0;
}
