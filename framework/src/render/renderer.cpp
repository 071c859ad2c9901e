// The OpenGL renderer (fixed-function pipeline; works in OSMesa, EGL and a GLFW window alike, and in a
// browser through Emscripten's GL emulation: ./lab web, cmake/web.cmake).
#include "clothlab/render/renderer.h"

#include <GL/gl.h>

#ifdef CLOTHLAB_WEB
// The browser build's one difference: Emscripten's emulation of fixed-function GL on WebGL
// (-sLEGACY_GL_EMULATION, cmake/web.cmake). Between glBegin() and glEnd() it takes a vertex's
// attributes in the order they are called and needs every one for every vertex, where GL keeps a
// current colour and normal: the calls below keep them and give each vertex both. It has the float
// forms of these calls only, no separate specular colour (it adds the specular term before
// texturing, the same here: lit surfaces are not textured), one material for both sides
// (setMaterial()), and reads client-side indices as 16-bit only (drawTriangleList()).
namespace {
struct Immediate {
    bool inside = false;
    GLfloat color[4] = {1, 1, 1, 1};
    GLfloat normal[3] = {0, 0, 1};
} immediate;
void webBegin(GLenum mode) { immediate.inside = true, glBegin(mode); }
void webEnd() { immediate.inside = false, glEnd(); }
void webColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
    immediate.color[0] = r, immediate.color[1] = g, immediate.color[2] = b, immediate.color[3] = a;
    if (!immediate.inside) glColor4f(r, g, b, a);
}
void webColor3f(GLfloat r, GLfloat g, GLfloat b) { webColor4f(r, g, b, 1); }
void webNormal3d(GLdouble x, GLdouble y, GLdouble z) {
    immediate.normal[0] = GLfloat(x), immediate.normal[1] = GLfloat(y), immediate.normal[2] = GLfloat(z);
}
void webVertex3d(GLdouble x, GLdouble y, GLdouble z) {
    glColor4f(immediate.color[0], immediate.color[1], immediate.color[2], immediate.color[3]);
    glNormal3f(immediate.normal[0], immediate.normal[1], immediate.normal[2]);
    glVertex3f(GLfloat(x), GLfloat(y), GLfloat(z));
}
void webMaterialf(GLenum face, GLenum pname, GLfloat v) { glMaterialfv(face, pname, &v); }
void webLightModeli(GLenum pname, GLint v) {
    if (pname == GL_LIGHT_MODEL_TWO_SIDE) glLightModelf(pname, GLfloat(v));
}
}  // namespace
#define glBegin webBegin
#define glEnd webEnd
#define glColor4f webColor4f
#define glColor3f webColor3f
#define glNormal3d webNormal3d
#define glVertex3d webVertex3d
#define glMaterialf webMaterialf
#define glLightModeli webLightModeli
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

namespace clothlab {

namespace {

constexpr double kPi = 3.14159265358979323846;
const float kBackground[3] = {0.88f, 0.91f, 0.95f};  // the views' background, RGB

void setMaterial(GLenum face, const Eigen::Vector3f& c, float spec, float shininess) {
#ifdef CLOTHLAB_WEB
    if (face == GL_BACK) return;  // the emulation has one material for both sides: back faces look like the front
#endif
    const float amb[4] = {0.35f * c[0], 0.35f * c[1], 0.35f * c[2], 1};
    const float dif[4] = {c[0], c[1], c[2], 1};
    const float sp[4] = {spec, spec, spec, 1};
    glMaterialfv(face, GL_AMBIENT, amb);
    glMaterialfv(face, GL_DIFFUSE, dif);
    glMaterialfv(face, GL_SPECULAR, sp);
    glMaterialf(face, GL_SHININESS, shininess);
}

// A unit sphere (lat-long), as the triangles of `stacks` triangle strips in their winding order;
// made once per resolution.
const TriangleList& unitSphere(int slices, int stacks) {
    static std::map<std::pair<int, int>, TriangleList> made;
    TriangleList& t = made[{slices, stacks}];
    if (!t.idx.empty()) return t;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j <= slices; ++j) {
            const double th = kPi * i / stacks - kPi / 2, ph = 2 * kPi * j / slices;
            const Vec3 n(std::cos(th) * std::cos(ph), std::sin(th), std::cos(th) * std::sin(ph));
            for (int k = 0; k < 3; ++k) t.xyz.push_back(static_cast<float>(n[k])), t.nrm.push_back(static_cast<float>(n[k]));
        }
    const auto at = [slices](int i, int j) { return static_cast<unsigned>(i * (slices + 1) + j); };
    for (int i = 0; i < stacks; ++i) {
        std::vector<unsigned> strip;  // the strip's vertices: (i, j), (i + 1, j) for j = 0 .. slices
        for (int j = 0; j <= slices; ++j) strip.push_back(at(i, j)), strip.push_back(at(i + 1, j));
        for (size_t k = 0; k + 2 < strip.size(); ++k) {  // triangle k of a strip; odd ones swap their first two
            const bool odd = k % 2;
            t.idx.insert(t.idx.end(), {strip[odd ? k + 1 : k], strip[odd ? k : k + 1], strip[k + 2]});
        }
    }
    return t;
}

// A sphere at centre c with radius r (GL_NORMALIZE keeps the scaled normals unit).
void drawSphere(const Vec3& c, double r, int slices = 32, int stacks = 16) {
    glPushMatrix();
    glTranslated(c.x(), c.y(), c.z());
    glScaled(r, r, r);
    drawTriangleList(unitSphere(slices, stacks));
    glPopMatrix();
}

// An orthonormal pair spanning the plane with normal n.
// Flat-shaded triangles, 3 x 3K corners (a box, capsule or mesh collider from DrawData::collider_triangles).
void drawFlatTriangles(const Matrix3X& corners) {
    glBegin(GL_TRIANGLES);
    for (Eigen::Index k = 0; k + 2 < corners.cols(); k += 3) {
        const Vec3 n = (corners.col(k + 1) - corners.col(k)).cross(corners.col(k + 2) - corners.col(k)).normalized();
        glNormal3d(n.x(), n.y(), n.z());
        for (int j = 0; j < 3; ++j) glVertex3d(corners(0, k + j), corners(1, k + j), corners(2, k + j));
    }
    glEnd();
}

// The convex hull of the points' (x, z), counter-clockwise seen from above (Andrew's monotone chain).
std::vector<int> groundHull(const Matrix3X& x) {
    std::vector<int> order(static_cast<size_t>(x.cols()));
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return x(0, a) < x(0, b) || (x(0, a) == x(0, b) && x(2, a) < x(2, b)); });
    const auto turn = [&](int o, int a, int b) {  // > 0: o -> a -> b turns counter-clockwise seen from +y
        return (x(2, a) - x(2, o)) * (x(0, b) - x(0, o)) - (x(0, a) - x(0, o)) * (x(2, b) - x(2, o));
    };
    std::vector<int> h(2 * order.size());
    size_t k = 0;
    for (size_t i = 0; i < order.size(); ++i) {  // lower chain
        while (k >= 2 && turn(h[k - 2], h[k - 1], order[i]) <= 0) --k;
        h[k++] = order[i];
    }
    for (size_t i = order.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
        while (k >= t && turn(h[k - 2], h[k - 1], order[i]) <= 0) --k;
        h[k++] = order[i];
    }
    h.resize(k > 1 ? k - 1 : k);
    return h;
}

void planeAxes(const Vec3& n, Vec3& a, Vec3& b) {
    a = (std::abs(n.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)).cross(n).normalized();
    b = n.cross(a);
}

void lights() {
    // Light positions in eye space (the modelview is the identity here): the light follows the camera.
    const float key[4] = {-0.35f, 0.75f, 0.9f, 0}, keyc[4] = {0.80f, 0.80f, 0.78f, 1};
    const float fill[4] = {0.6f, -0.1f, 0.5f, 0}, fillc[4] = {0.30f, 0.32f, 0.36f, 1};
    const float spec[4] = {0.5f, 0.5f, 0.5f, 1}, none[4] = {0, 0, 0, 1};
    const float ambient[4] = {0.25f, 0.25f, 0.27f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, key);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, keyc);
    glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
    glLightfv(GL_LIGHT0, GL_AMBIENT, none);
    glLightfv(GL_LIGHT1, GL_POSITION, fill);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, fillc);
    glLightfv(GL_LIGHT1, GL_SPECULAR, none);
    glLightfv(GL_LIGHT1, GL_AMBIENT, none);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
}

}  // namespace

void drawTriangleList(const TriangleList& t) {
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, t.xyz.data());
    if (!t.nrm.empty()) {
        glEnableClientState(GL_NORMAL_ARRAY);
        glNormalPointer(GL_FLOAT, 0, t.nrm.data());
    }
#ifdef CLOTHLAB_WEB
    // The emulation reads indices from client memory as 16-bit only (up to 65536 vertices: a 256 x 256 cloth).
    static std::vector<unsigned short> idx16;
    idx16.assign(t.idx.begin(), t.idx.end());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(idx16.size()), GL_UNSIGNED_SHORT, idx16.data());
#else
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(t.idx.size()), GL_UNSIGNED_INT, t.idx.data());
#endif
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

Eigen::Vector3f edgeKindColor(EdgeKind kind) {
    switch (kind) {
        case EdgeKind::Single: return {0.15f, 0.17f, 0.22f};
        case EdgeKind::Structural: return {0.10f, 0.35f, 0.85f};
        case EdgeKind::Shear: return {0.05f, 0.60f, 0.25f};
        case EdgeKind::Bending: return {0.75f, 0.15f, 0.65f};
    }
    return {0, 0, 0};
}

Eigen::Vector3f strainColor(double strain, double range) {
    const float s = static_cast<float>(std::clamp(strain / range, -1.0, 1.0));
    const Eigen::Vector3f mid(0.85f, 0.85f, 0.85f), red(0.85f, 0.10f, 0.10f), blue(0.10f, 0.30f, 0.90f);
    return s >= 0 ? Eigen::Vector3f(mid + s * (red - mid)) : Eigen::Vector3f(mid - s * (blue - mid));
}

void Renderer::lap(const char* pass) {
    if (!timing_) return;
    glFinish();
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    const double cpu = cpu_ ? cpu_() : 0.0;
    if (pass) {
        auto it = std::find_if(times_.begin(), times_.end(), [&](const RenderPassTime& t) { return std::strcmp(t.name, pass) == 0; });
        if (it == times_.end()) times_.push_back({pass, 0.0, 0.0}), it = times_.end() - 1;
        it->ms += 1e3 * (now - lap_);
        it->cpu_ms += 1e3 * (cpu - lapCpu_);
    }
    lap_ = now, lapCpu_ = cpu;
}

void Renderer::clear(int width, int height) {
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, width, height);
    glClearColor(kBackground[0], kBackground[1], kBackground[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

void Renderer::fill(const Viewport& vp, int fb_height, const Eigen::Vector3f& rgb) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(vp.x, fb_height - vp.y - vp.height, vp.width, vp.height);
    glClearColor(rgb[0], rgb[1], rgb[2], 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw(const DrawData& d, const Camera& cam, const RenderOptions& opt, int width, int height) {
    draw(d, cam, opt, Viewport{0, 0, width, height}, height);
}

void Renderer::draw(const DrawData& d, const Camera& cam, const RenderOptions& opt, const Viewport& vp, int fb_height) {
    lap(nullptr);
    const int width = vp.width, height = vp.height;
    glViewport(vp.x, fb_height - vp.y - vp.height, width, height);
    glScissor(vp.x, fb_height - vp.y - vp.height, width, height);
    glEnable(GL_SCISSOR_TEST);  // clear and draw only this part of the framebuffer
    glDisable(GL_DITHER);
    glClearColor(kBackground[0], kBackground[1], kBackground[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    // Background: the clear colour, a light blue-grey (a gradient quad over the whole view cost a
    // full-screen pass of llvmpipe's fragment work per frame: docs/performance.md).
    lap("background");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    lights();  // in eye space, before the view matrix
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    const Eigen::Matrix4d P = cam.projection(double(width) / height), V = cam.view();
    glLoadMatrixd(P.data());
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(V.data());

    right_ = V.block<1, 3>(0, 0).transpose();
    up_ = V.block<1, 3>(1, 0).transpose();
    // Size of what is seen, for grid spacing, marker and sphere sizes.
    const double scale = (cam.eye - cam.target).norm() * std::sin(cam.fovy * kPi / 360);

    // Ground: a plane collider with an upward normal, else a grid below the lowest point.
    bool ground_is_plane = false;
    double gy = opt.ground_y;
    for (const Collider& c : d.colliders)
        if (c.type == Collider::Type::Plane && c.normal.y() > 0.99) ground_is_plane = true, gy = c.point.y();
    if (std::isnan(gy)) {
        gy = d.x.cols() ? d.x.row(1).minCoeff() : 0.0;
        for (const Collider& c : d.colliders)
            if (c.type == Collider::Type::Sphere) gy = std::min(gy, c.point.y() - c.radius);
        gy -= 0.15 * scale;
    }
    const double cell = std::pow(10.0, std::floor(std::log10(scale * 0.5)));
    const double gx0 = std::round(cam.target.x() / cell) * cell, gz0 = std::round(cam.target.z() / cell) * cell;
    // Out to 3 scale, at most 16 cells each way (the far lines crowd towards the horizon, and each line
    // costs llvmpipe a blended pass across the view).
    const int ncell = std::min(16, static_cast<int>(std::ceil(3.0 * scale / cell)));
    if (opt.ground) {
        if (ground_is_plane && opt.colliders) {
            glColor3f(0.86f, 0.87f, 0.88f);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(1, 1);
            glBegin(GL_QUADS);
            const double e = ncell * cell;
            glVertex3d(gx0 - e, gy, gz0 - e);
            glVertex3d(gx0 - e, gy, gz0 + e);
            glVertex3d(gx0 + e, gy, gz0 + e);
            glVertex3d(gx0 + e, gy, gz0 - e);
            glEnd();
            glDisable(GL_POLYGON_OFFSET_FILL);
        }
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glLineWidth(1.0f);
        glBegin(GL_LINES);
        for (int k = -ncell; k <= ncell; ++k) {
            const float a = (k % 10 == 0) ? 0.45f : (k % 5 == 0 ? 0.30f : 0.16f);
            glColor4f(0.35f, 0.38f, 0.45f, a);
            glVertex3d(gx0 + k * cell, gy, gz0 - ncell * cell);
            glVertex3d(gx0 + k * cell, gy, gz0 + ncell * cell);
            glVertex3d(gx0 - ncell * cell, gy, gz0 + k * cell);
            glVertex3d(gx0 + ncell * cell, gy, gz0 + k * cell);
        }
        glEnd();
        lap("ground and grid");
        // A soft shadow of the cloth and the particles straight down on the ground.
        glDepthMask(GL_FALSE);
        glColor4f(0.1f, 0.12f, 0.18f, 0.12f);
        const double sy = gy + 1e-3 * scale;
        if (!d.triangles.empty()) {
            // The convex hull of the cloth projected straight down, one fan: a soft blob in place of
            // every triangle's projection (which cost llvmpipe a triangle setup each, twice per frame
            // with the cloth itself; docs/performance.md).
            TriangleList& shadow = scratch_;
            const std::vector<int> hull = groundHull(d.x);
            shadow.xyz.clear();
            shadow.nrm.clear();
            shadow.idx.clear();
            for (int i : hull)
                for (const double v : {d.x(0, i), sy, d.x(2, i)}) shadow.xyz.push_back(static_cast<float>(v));
            for (size_t k = 1; k + 1 < hull.size(); ++k)
                shadow.idx.insert(shadow.idx.end(), {0u, static_cast<unsigned>(k), static_cast<unsigned>(k + 1)});
            drawTriangleList(shadow);
        }
        for (const Collider& c : d.colliders) {
            if (c.type != Collider::Type::Sphere || !opt.colliders) continue;
            glBegin(GL_TRIANGLE_FAN);
            glVertex3d(c.point.x(), sy, c.point.z());
            for (int k = 0; k <= 48; ++k)
                glVertex3d(c.point.x() + 0.9 * c.radius * std::cos(2 * kPi * k / 48), sy,
                           c.point.z() + 0.9 * c.radius * std::sin(2 * kPi * k / 48));
            glEnd();
        }
        if (d.triangles.empty()) {
            for (int i = 0; i < d.x.cols(); ++i) {
                glBegin(GL_TRIANGLE_FAN);
                glVertex3d(d.x(0, i), sy, d.x(2, i));
                for (int k = 0; k <= 24; ++k)
                    glVertex3d(d.x(0, i) + 0.05 * scale * std::cos(2 * kPi * k / 24), sy,
                               d.x(2, i) + 0.05 * scale * std::sin(2 * kPi * k / 24));
                glEnd();
            }
        }
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    lap("shadow");
    // Colliders.
    if (opt.colliders) {
        glEnable(GL_LIGHTING);
        for (const Collider& c : d.colliders) {
            if (c.type == Collider::Type::Sphere) {
                setMaterial(GL_FRONT_AND_BACK, {0.55f, 0.60f, 0.66f}, 0.35f, 40);
                drawSphere(c.point, std::max(c.radius - 0.5e-3 * scale, 0.0), 48, 24);
            }
        }
        setMaterial(GL_FRONT_AND_BACK, {0.62f, 0.56f, 0.50f}, 0.2f, 30);
        for (const Matrix3X& corners : d.collider_triangles) drawFlatTriangles(corners);
        glDisable(GL_LIGHTING);
    }

    lap("colliders");
    if (opt.surface && !d.triangles.empty()) drawSurface(d, scale);
    lap("cloth");
    if (opt.edges || d.triangles.empty()) drawEdges(d, opt, scale);
    lap("edges");
    drawParticles(d, opt, scale);

    // Planes other than the ground: translucent panels with a border, drawn last so what lies behind shows.
    if (opt.colliders) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (const Collider& c : d.colliders) {
            if (c.type != Collider::Type::Plane || (ground_is_plane && c.normal.y() > 0.99)) continue;
            Vec3 a, b;
            planeAxes(c.normal, a, b);
            const Vec3 o = c.point + (cam.target - c.point).dot(a) * a + (cam.target - c.point).dot(b) * b;
            const double e = 1.2 * scale;
            const Vec3 quad[4] = {o - e * a - e * b, o + e * a - e * b, o + e * a + e * b, o - e * a + e * b};
            glColor4f(0.55f, 0.62f, 0.75f, 0.30f);
            glBegin(GL_QUADS);
            for (const Vec3& v : quad) glVertex3d(v.x(), v.y(), v.z());
            glEnd();
            glColor4f(0.30f, 0.36f, 0.50f, 0.8f);
            glLineWidth(1.5f);
            glBegin(GL_LINE_LOOP);
            for (const Vec3& v : quad) glVertex3d(v.x(), v.y(), v.z());
            glEnd();
            glLineWidth(1.0f);
        }
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_SCISSOR_TEST);
    glFlush();  // llvmpipe rasterizes on its own threads from here; the caller may step the simulation meanwhile
    lap("particles and planes");
}

void Renderer::triangleIndices(const DrawData& d, std::vector<unsigned>& idx) {
    idx.clear();
    for (const auto& t : d.triangles)
        for (int k = 0; k < 3; ++k) idx.push_back(static_cast<unsigned>(t[k]));
}

void Renderer::drawSurface(const DrawData& d, double /*scale*/) {
    const int n = static_cast<int>(d.x.cols());
    // Smooth shading: per-vertex normals, the area-weighted sum of the face normals around each particle.
    Matrix3X nrm = Matrix3X::Zero(3, n);
    for (const auto& t : d.triangles) {
        const Vec3 fn = (d.x.col(t[1]) - d.x.col(t[0])).cross(d.x.col(t[2]) - d.x.col(t[0]));
        for (int k = 0; k < 3; ++k) nrm.col(t[k]) += fn;
    }
    TriangleList& cloth = scratch_;
    cloth.xyz.resize(3 * static_cast<size_t>(n));
    cloth.nrm.resize(3 * static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double len = nrm.col(i).norm();
        for (int k = 0; k < 3; ++k) {
            cloth.xyz[3 * i + k] = static_cast<float>(d.x(k, i));
            cloth.nrm[3 * i + k] = static_cast<float>(len > 0 ? nrm(k, i) / len : (k == 2));
        }
    }
    triangleIndices(d, cloth.idx);

    const bool textured = d.uv.cols() == n;
    std::vector<float> uv;  // texture coordinates, alive until the draw call
    if (textured) {
        if (texture_ == 0) {
            // A two-tone checker (8 x 8 squares) that makes stretching and folds visible.
            const int S = 64;
            std::vector<unsigned char> tex(S * S * 3);
            for (int y = 0; y < S; ++y)
                for (int x = 0; x < S; ++x) {
                    const bool dark = ((x / 8) + (y / 8)) % 2;
                    for (int k = 0; k < 3; ++k) tex[3 * (y * S + x) + k] = dark ? 214 : 255;
                }
            GLuint id = 0;
            glGenTextures(1, &id);
            texture_ = id;
            glBindTexture(GL_TEXTURE_2D, texture_);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, S, S, 0, GL_RGB, GL_UNSIGNED_BYTE, tex.data());
        }
        glBindTexture(GL_TEXTURE_2D, texture_);
        glEnable(GL_TEXTURE_2D);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        uv.resize(2 * static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) uv[2 * i] = static_cast<float>(d.uv(0, i)), uv[2 * i + 1] = static_cast<float>(d.uv(1, i));
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, uv.data());
    }
    // Two-sided lighting: warm front, cool back.
    glEnable(GL_LIGHTING);
    setMaterial(GL_FRONT, {0.95f, 0.52f, 0.22f}, 0.25f, 24);
    setMaterial(GL_BACK, {0.30f, 0.52f, 0.85f}, 0.15f, 24);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1, 1);
    drawTriangleList(cloth);
    if (textured) {
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glDisable(GL_TEXTURE_2D);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);
}

void Renderer::drawEdges(const DrawData& d, const RenderOptions& opt, double scale) {
    glDisable(GL_LIGHTING);
    glLineWidth(opt.line_width);
    lines_.clear();
    colours_.clear();
    // A segment a-b in colour c, into the vertex arrays drawn at the end.
    const auto segment = [this](const Vec3& a, const Vec3& b, const Eigen::Vector3f& c) {
        for (const Vec3* p : {&a, &b})
            for (int k = 0; k < 3; ++k) lines_.push_back(static_cast<float>((*p)[k])), colours_.push_back(c[k]);
    };
    for (size_t e = 0; e < d.edges.size(); ++e) {
        const EdgeKind kind = d.edge_kind.size() == d.edges.size() ? d.edge_kind[e] : EdgeKind::Single;
        if (!opt.show_kind[static_cast<int>(kind)]) continue;
        const Eigen::Vector3f c = opt.color_by_strain && d.rest_length.size() == d.edges.size()
                                      ? strainColor(d.strain(static_cast<int>(e)), opt.strain_range)
                                      : edgeKindColor(kind);
        const Vec3 a = d.x.col(d.edges[e][0]), b = d.x.col(d.edges[e][1]);
        if (kind == EdgeKind::Single && d.edges.size() <= 200) {
            // Draw a lone spring as a coil: a helix around the segment from a to b.
            const Vec3 axis = b - a;
            const double len = axis.norm();
            if (len <= 0) continue;
            Vec3 u, v;
            planeAxes(axis / len, u, v);
            const bool lone = d.edges.size() == 1;
            const double r = std::min(0.035 * scale, (lone ? 0.25 : 0.15) * d.rest_length[e]);
            const int turns = lone ? 12 : 5, seg = turns * 12;
            Vec3 prev = a;
            for (int k = 1; k <= seg; ++k) {
                const double s = double(k) / seg;
                const double env = (s < 0.08 || s > 0.92) ? 0.0 : 1.0;  // straight ends
                const double phi = 2 * kPi * turns * s;
                const Vec3 p = a + s * axis + env * r * (std::cos(phi) * u + std::sin(phi) * v);
                segment(prev, p, c);
                prev = p;
            }
        } else {
            segment(a, b, c);
        }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, lines_.data());
    glColorPointer(3, GL_FLOAT, 0, colours_.data());
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines_.size() / 3));
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glLineWidth(1.0f);
}

void Renderer::drawParticles(const DrawData& d, const RenderOptions& opt, double scale) {
    const int n = static_cast<int>(d.x.cols());
    const bool few = n <= 400 && d.triangles.empty();
    if (few) {
        // Few particles (spring, chain): lit spheres, pinned ones as red anchors.
        glEnable(GL_LIGHTING);
        for (int i = 0; i < n; ++i) {
            const bool pinned = d.w.size() == n && d.w[i] == 0;
            if (pinned && !opt.pinned) continue;
            setMaterial(GL_FRONT_AND_BACK, pinned ? Eigen::Vector3f(0.85f, 0.12f, 0.10f) : Eigen::Vector3f(0.95f, 0.55f, 0.15f), 0.5f, 50);
            drawSphere(d.x.col(i), (pinned ? 0.035 : (n > 3 ? 0.045 : 0.08)) * scale, 24, 12);
        }
        // The analytic solution as a green ring facing the camera, drawn on top.
        glDisable(GL_LIGHTING);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glEnable(GL_LINE_SMOOTH);
        glLineWidth(3.0f);
        glColor4f(0.10f, 0.70f, 0.25f, 0.9f);
        const double gr = (n > 3 ? 0.06 : 0.11) * scale;
        for (const Vec3& g : d.ghosts) {
            glBegin(GL_LINE_LOOP);
            for (int k = 0; k < 48; ++k) {
                const double a = 2 * kPi * k / 48;
                const Vec3 p = g + gr * (std::cos(a) * right_ + std::sin(a) * up_);
                glVertex3d(p.x(), p.y(), p.z());
            }
            glEnd();
        }
        glLineWidth(1.0f);
        glDisable(GL_LINE_SMOOTH);
        glDisable(GL_BLEND);
        glEnable(GL_DEPTH_TEST);
        glDisable(GL_LIGHTING);
        return;
    }
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (opt.particles && n <= 20000) {
        glPointSize(n > 2000 ? 2.0f : 3.5f);
        glColor3f(0.20f, 0.20f, 0.25f);
        lines_.resize(3 * static_cast<size_t>(n));
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) lines_[3 * i + k] = static_cast<float>(d.x(k, i));
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, lines_.data());
        glDrawArrays(GL_POINTS, 0, n);
        glDisableClientState(GL_VERTEX_ARRAY);
    }
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
    if (opt.pinned && d.w.size() == n) {
        // Pinned particles of a cloth: small red spheres.
        glEnable(GL_LIGHTING);
        setMaterial(GL_FRONT_AND_BACK, {0.85f, 0.12f, 0.10f}, 0.5f, 50);
        int drawn = 0;
        for (int i = 0; i < n && drawn < 2000; ++i)
            if (d.w[i] == 0) drawSphere(d.x.col(i), 0.02 * scale, 16, 8), ++drawn;
        glDisable(GL_LIGHTING);
    }
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
    glPointSize(1.0f);
}

Image readPixels(int width, int height) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(4 * static_cast<size_t>(width) * height);
    std::vector<unsigned char> raw(img.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
    const size_t row = 4 * static_cast<size_t>(width);
    for (int y = 0; y < height; ++y)
        std::copy_n(&raw[(height - 1 - y) * row], row, &img.rgba[y * row]);
    return img;
}

std::string glRendererName() {
    const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!s || !*s) return "unknown";
    const std::string name = s;
    return name.substr(0, name.find(" ("));
}

}  // namespace clothlab
