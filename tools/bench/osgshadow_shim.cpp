// SPDX-License-Identifier: MIT
// osgShadow for stin-bench's peers section (section_peers.c), behind a C API
// (osgshadow_shim.h). Each peer is an osgViewer::Viewer embedded in the
// bench's current context (GraphicsWindowEmbedded: OSG draws with the GL
// entry points of libGL, which dispatch to the current EGL context), single
// threaded, its camera the scene's, with a ShadowedScene of the scene's
// objects and one light as OSG's own examples build it: osg::Material and
// an osg::Light, fixed-function lighting and the technique's shaders.
// stin draws in the same context between OSG's frames, so OSG's state
// tracking is reset before each frame and the GL state it leaves is put
// back to the defaults after it.
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LightModel>
#include <osg/LightSource>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/Notify>
#include <osgShadow/LightSpacePerspectiveShadowMap>
#include <osgShadow/ParallelSplitShadowMap>
#include <osgShadow/ShadowMap>
#include <osgShadow/ShadowSettings>
#include <osgShadow/ShadowedScene>
#include <osgShadow/SoftShadowMap>
#include <osgShadow/StandardShadowMap>
#include <osgShadow/ViewDependentShadowMap>
#include <osgUtil/CullVisitor>
#include <osgViewer/Viewer>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" {
#include "osgshadow_shim.h"
}

namespace {

const unsigned RECEIVES = 0x1, CASTS = 0x2;

// OSG reports a shader that does not compile, a program that does not link
// and GL errors through osg::notify: the peer's frame fails with the text.
class Catcher : public osg::NotifyHandler {
public:
    std::string text;
    void notify(osg::NotifySeverity severity, const char *message) override
    {
        std::string m(message);
        if (std::getenv("STIN_BENCH_OSG_NOTIFY"))
            std::fputs(message, stderr);
        if (severity <= osg::WARN &&
            (m.find("FAILED") != std::string::npos || m.find("rror") != std::string::npos) &&
            text.size() < 4096)
            text += m;
    }
};

Catcher *catcher()
{
    static osg::ref_ptr<Catcher> c;
    if (!c) {
        c = new Catcher;
        osg::setNotifyHandler(c.get());
        osg::setNotifyLevel(osg::WARN);
    }
    return c.get();
}

osg::ref_ptr<osg::Geometry> make_geometry(const osgs_mesh &m)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array(m.vertex_count);
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array(m.vertex_count);
    for (uint32_t i = 0; i < m.vertex_count; i++) {
        (*v)[i].set(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
        (*n)[i].set(m.normals[3 * i], m.normals[3 * i + 1], m.normals[3 * i + 2]);
    }
    g->setVertexArray(v.get());
    g->setNormalArray(n.get(), osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(new osg::DrawElementsUInt(GL_TRIANGLES, m.index_count, m.indices));
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    return g;
}

osg::ref_ptr<osg::Node> make_object(const osgs_object &o, osg::Geometry *g)
{
    osg::ref_ptr<osg::MatrixTransform> t = new osg::MatrixTransform(osg::Matrixd(o.transform));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    osg::ref_ptr<osg::Material> mat = new osg::Material;
    osg::Vec4 c(o.color[0], o.color[1], o.color[2], 1.0f);
    mat->setAmbient(osg::Material::FRONT_AND_BACK, c);
    mat->setDiffuse(osg::Material::FRONT_AND_BACK, c);
    mat->setSpecular(osg::Material::FRONT_AND_BACK,
                     osg::Vec4(o.specular[0], o.specular[1], o.specular[2], 1.0f));
    mat->setShininess(osg::Material::FRONT_AND_BACK, o.shininess);
    geode->addDrawable(g);
    geode->getOrCreateStateSet()->setAttributeAndModes(mat.get());
    t->addChild(geode.get());
    return t;
}

// The FULL frame's quad, both windings (a shadow camera may cull either).
osg::ref_ptr<osg::Node> make_eclipse(const osgs_scene &s)
{
    osg::Vec3 c(s.eclipse_center[0], s.eclipse_center[1], s.eclipse_center[2]);
    osg::Vec3 n(s.eclipse_normal[0], s.eclipse_normal[1], s.eclipse_normal[2]);
    osg::Vec3 a = std::fabs(n.x()) < 0.9f ? osg::Vec3(1, 0, 0) : osg::Vec3(0, 1, 0);
    osg::Vec3 u = n ^ a, w;
    u.normalize();
    w = n ^ u;
    u *= s.eclipse_half;
    w *= s.eclipse_half;
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::Vec3 q[4] = {c - u - w, c + u - w, c + u + w, c - u + w};
    const int order[12] = {0, 1, 2, 0, 2, 3, 0, 2, 1, 0, 3, 2};
    for (int i : order)
        v->push_back(q[i]);
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 12));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(g.get());
    return geode;
}

// The eclipse is for the shadow cameras only: the main camera skips it.
class ShadowCamerasOnly : public osg::NodeCallback {
public:
    explicit ShadowCamerasOnly(osg::Camera *main) : main(main) {}
    void operator()(osg::Node *node, osg::NodeVisitor *nv) override
    {
        osgUtil::CullVisitor *cv = nv->asCullVisitor();
        if (cv && cv->getCurrentCamera() == main)
            return;
        traverse(node, nv);
    }

private:
    osg::Camera *main;
};

osg::ref_ptr<osg::LightSource> make_light(const osgs_scene &s)
{
    const osgs_light &l = s.light;
    osg::ref_ptr<osg::LightSource> ls = new osg::LightSource;
    osg::Light *light = ls->getLight();
    light->setLightNum(0);
    if (l.type == 2)
        light->setPosition(osg::Vec4(-l.direction[0], -l.direction[1], -l.direction[2], 0.0f));
    else
        light->setPosition(osg::Vec4(l.position[0], l.position[1], l.position[2], 1.0f));
    if (l.type == 1) {
        light->setDirection(osg::Vec3(l.direction[0], l.direction[1], l.direction[2]));
        light->setSpotCutoff(l.spot_cutoff_deg);
        light->setSpotExponent(l.spot_exponent);
    }
    light->setAmbient(osg::Vec4(0, 0, 0, 1));
    light->setDiffuse(osg::Vec4(l.color[0], l.color[1], l.color[2], 1));
    light->setSpecular(osg::Vec4(l.color[0], l.color[1], l.color[2], 1));
    light->setConstantAttenuation(l.attenuation[0]);
    light->setLinearAttenuation(l.attenuation[1]);
    light->setQuadraticAttenuation(l.attenuation[2]);
    return ls;
}

osg::ref_ptr<osgShadow::ShadowTechnique> make_technique(int t, int size, osg::LightSource *ls,
                                                        osgShadow::ShadowSettings *settings)
{
    osg::Vec2s square((short)size, (short)size);
    switch (t) {
    case OSGS_SHADOW_MAP:
    case OSGS_SOFT_SHADOW_MAP: {
        osg::ref_ptr<osgShadow::ShadowMap> m =
            t == OSGS_SHADOW_MAP ? new osgShadow::ShadowMap : new osgShadow::SoftShadowMap;
        m->setTextureSize(square);
        m->setLight(ls);
        return m;
    }
    case OSGS_STANDARD_SHADOW_MAP:
    case OSGS_LISPSM: {
        osg::ref_ptr<osgShadow::StandardShadowMap> m =
            t == OSGS_LISPSM ? new osgShadow::LightSpacePerspectiveShadowMapDB
                             : new osgShadow::StandardShadowMap;
        m->setTextureSize(square);
        m->setLight(ls->getLight());
        return m;
    }
    case OSGS_PSSM: {
        osg::ref_ptr<osgShadow::ParallelSplitShadowMap> m =
            new osgShadow::ParallelSplitShadowMap(nullptr, 3);
        m->setTextureResolution((unsigned)size);
        m->setUserLight(ls->getLight());
        return m;
    }
    case OSGS_NONE:
        return nullptr;
    default:
        settings->setTextureSize(square);
        settings->setLightNum(0);
        return new osgShadow::ViewDependentShadowMap;
    }
}

} // namespace

struct osgs_peer {
    osg::ref_ptr<osgViewer::Viewer> viewer;
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> window;
    osg::ref_ptr<osg::Group> shadowed, objects;
    osg::ref_ptr<osg::MatrixTransform> eclipse;
    osg::Vec3 away;
    osg::Matrixd view;
    unsigned framebuffer;
    int mode;
};

static const char *const names[OSGS_TECHNIQUES] = {
    "ShadowMap", "SoftShadowMap", "StandardShadowMap", "LightSpacePerspectiveShadowMapDB",
    "ParallelSplitShadowMap", "ViewDependentShadowMap", "no shadows"};

extern "C" const char *osgs_name(int technique)
{
    return technique >= 0 && technique < OSGS_TECHNIQUES ? names[technique] : "?";
}

extern "C" osgs_peer *osgs_create(const osgs_scene *s, int technique, int map_size, char *err,
                                  size_t err_size)
{
    Catcher *c = catcher();
    osgs_peer *p = new osgs_peer;
    std::vector<osg::ref_ptr<osg::Geometry>> geometry;
    c->text.clear();
    for (int i = 0; i < s->mesh_count; i++)
        geometry.push_back(make_geometry(s->meshes[i]));
    osg::ref_ptr<osgShadow::ShadowedScene> shadowed = new osgShadow::ShadowedScene;
    osg::ref_ptr<osgShadow::ShadowSettings> settings = new osgShadow::ShadowSettings;
    settings->setReceivesShadowTraversalMask(RECEIVES);
    settings->setCastsShadowTraversalMask(CASTS);
    shadowed->setShadowSettings(settings.get());
    osg::ref_ptr<osg::LightSource> ls = make_light(*s);
    shadowed->setShadowTechnique(make_technique(technique, map_size, ls.get(), settings.get()));
    p->objects = new osg::Group;
    for (int i = 0; i < s->object_count; i++)
        p->objects->addChild(make_object(s->objects[i], geometry[s->objects[i].mesh].get()));
    p->eclipse = new osg::MatrixTransform;
    p->eclipse->addChild(make_eclipse(*s));
    p->away.set(s->eclipse_away[0], s->eclipse_away[1], s->eclipse_away[2]);
    shadowed->addChild(ls.get());
    shadowed->addChild(p->objects.get());
    p->eclipse->setNodeMask(CASTS);
    p->shadowed = shadowed;
    osg::StateSet *root = shadowed->getOrCreateStateSet();
    ls->setStateSetModes(*root, osg::StateAttribute::ON);
    root->setMode(GL_LIGHTING, osg::StateAttribute::ON);
    root->setMode(GL_NORMALIZE, osg::StateAttribute::ON);
    osg::ref_ptr<osg::LightModel> model = new osg::LightModel;
    model->setAmbientIntensity(osg::Vec4(s->ambient[0], s->ambient[1], s->ambient[2], 1));
    model->setLocalViewer(true);
    root->setAttributeAndModes(model.get());

    p->viewer = new osgViewer::Viewer;
    p->viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    p->viewer->setLightingMode(osg::View::NO_LIGHT);
    p->viewer->setKeyEventSetsDone(0);
    p->window = p->viewer->setUpViewerAsEmbeddedInWindow(0, 0, s->width, s->height);
    p->window->setDefaultFboId(s->framebuffer);
    p->framebuffer = s->framebuffer;
    p->mode = OSGS_SHADOWED;
    osg::Camera *cam = p->viewer->getCamera();
    cam->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    cam->setProjectionMatrix(osg::Matrixd(s->projection));
    p->view = osg::Matrixd(s->view);
    cam->setViewMatrix(p->view);
    cam->setClearColor(
        osg::Vec4(s->background[0], s->background[1], s->background[2], s->background[3]));
    if (s->framebuffer) {
        cam->setDrawBuffer(GL_COLOR_ATTACHMENT0);
        cam->setReadBuffer(GL_COLOR_ATTACHMENT0);
    }
    p->eclipse->setCullCallback(new ShadowCamerasOnly(cam));
    p->viewer->setSceneData(shadowed.get());
    p->viewer->realize();
    p->window->getState()->setCheckForGLErrors(osg::State::ONCE_PER_FRAME);
    if (!c->text.empty()) {
        std::snprintf(err, err_size, "%s", c->text.c_str());
        osgs_destroy(p);
        return nullptr;
    }
    return p;
}

extern "C" int osgs_frame(osgs_peer *p, int mode, char *err, size_t err_size)
{
    Catcher *c = catcher();
    osg::State *state = p->window->getState();
    c->text.clear();
    // UNSHADOWED keeps a caster where it shadows nothing: ShadowMap and
    // SoftShadowMap draw nothing at all without one
    // SHADOWED leaves it out of the graph: the techniques fit their maps to
    // the scene's bounds, which a node mask does not change
    p->objects->setNodeMask(mode == OSGS_UNSHADOWED ? RECEIVES : RECEIVES | CASTS);
    p->eclipse->setMatrix(osg::Matrixd::translate(mode == OSGS_FULL ? osg::Vec3() : p->away));
    if (mode == OSGS_SHADOWED)
        p->shadowed->removeChild(p->eclipse.get());
    else if (!p->shadowed->containsNode(p->eclipse.get()))
        p->shadowed->addChild(p->eclipse.get());
    // stin's frames changed what OSG believes is bound and enabled (a
    // State::reset() here loses the light's positional state: unlit frames)
    state->dirtyAllModes();
    state->dirtyAllAttributes();
    state->dirtyAllVertexArrays();
    p->viewer->getCamera()->setViewMatrix(p->view);
    // the first frame after a change of mode still shows the maps of the
    // mode before (seen with every technique but LiSPSM): drawn twice then
    if (mode != p->mode)
        p->viewer->frame();
    p->mode = mode;
    p->viewer->frame();
    // the GL defaults back for stin
    state->popAllStateSets();
    state->apply();
    state->unbindVertexBufferObject();
    state->unbindElementBufferObject();
    state->setActiveTextureUnit(0);
    state->setClientActiveTextureUnit(0);
    osg::GLExtensions *ext = state->get<osg::GLExtensions>();
    ext->glUseProgram(0);
    ext->glBindFramebuffer(GL_FRAMEBUFFER_EXT, p->framebuffer);
    if (!c->text.empty()) {
        std::string t = c->text;
        for (char &ch : t)
            if (ch == '\n' || ch == '|')
                ch = ' ';
        std::snprintf(err, err_size, "%s", t.c_str());
        return 0;
    }
    return 1;
}

extern "C" void osgs_destroy(osgs_peer *p)
{
    delete p;
}
