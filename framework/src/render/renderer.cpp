// The OpenGL renderer: shaders and buffer objects on OpenGL 3.3 core (OSMesa, EGL, a GLFW window) and,
// from the same source, on WebGL2 (./lab web, cmake/web.cmake). The one difference, the GLSL version
// line, is chosen in gl.h by the build switch CLOTHLAB_WEB.
#include "clothlab/render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include "gl.h"

namespace clothlab {

namespace {

constexpr double kPi = 3.14159265358979323846;
const float kBackground[3] = {0.88f, 0.91f, 0.95f};  // the views' background, RGB

// The vertex attributes' locations, as bound in the program and used by every vertex array.
enum Attribute { kPosition = 0, kNormal = 1, kColor = 2, kUv = 3 };
const char* const kAttributes[] = {"aPosition", "aNormal", "aColor", "aUv"};

// One shader source, compiled twice: with LIT (lit per pixel like the former fixed-function lighting:
// two directional lights that follow the camera, a warm key light with a specular highlight and a
// cool fill light, a global ambient term, two-sided with a material per side, the checker texture
// modulating the diffuse part and the specular term added after it) and without (unlit: the vertex's
// colour, or one colour for the whole draw, the attribute's constant value; points round with
// uRound). Two programs, not one with a branch: llvmpipe would run the lighting for every line too.
const char* const kVertexShader = R"(
in vec3 aPosition;
in vec3 aNormal;
in vec4 aColor;
in vec2 aUv;
uniform mat4 uProjection;
uniform mat4 uModelView;
uniform float uPointSize;
out vec3 vNormal;
out vec4 vColor;
out vec2 vUv;
void main() {
    gl_Position = uProjection * (uModelView * vec4(aPosition, 1.0));
    vNormal = mat3(uModelView) * aNormal;  // eye space; the model-view scales uniformly, if at all
    vColor = aColor;
    vUv = aUv;
    gl_PointSize = uPointSize;
}
)";
const char* const kFragmentShader = R"(
in vec3 vNormal;
in vec4 vColor;
in vec2 vUv;
out vec4 fragColor;
#ifdef LIT
uniform bool uTextured;
uniform vec3 uFront;      // diffuse colour of front faces (ambient: 0.35 of it)
uniform vec3 uBack;       // of back faces
uniform vec2 uSpecular;   // specular reflectance, front and back
uniform float uShininess;
uniform sampler2D uTexture;
const vec3 kKey = vec3(-0.28625, 0.61340, 0.73607);  // normalize(-0.35, 0.75, 0.9), eye space
const vec3 kFill = vec3(0.76200, -0.12700, 0.63500);  // normalize(0.6, -0.1, 0.5)
const vec3 kHalf = vec3(-0.15362, 0.32919, 0.93169);  // normalize(kKey + (0, 0, 1)): the viewer at infinity
void main() {
    vec3 n = normalize(vNormal), m = uFront;
    float s = uSpecular.x;
    if (!gl_FrontFacing) {
        n = -n;
        m = uBack;
        s = uSpecular.y;
    }
    float kd = max(dot(n, kKey), 0.0);
    vec3 c = m * (0.35 * vec3(0.25, 0.25, 0.27) + kd * vec3(0.80, 0.80, 0.78) + max(dot(n, kFill), 0.0) * vec3(0.30, 0.32, 0.36));
    c = min(c, vec3(1.0));
    if (uTextured) c *= texture(uTexture, vUv).rgb;
    float h = max(dot(n, kHalf), 0.0);
    fragColor = vec4(min(c + (kd > 0.0 ? 0.5 * s * pow(h, uShininess) : 0.0), vec3(1.0)), 1.0);
}
#else
uniform bool uRound;
void main() {
    if (uRound && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
    fragColor = vColor;
}
#endif
)";

// Triangles with optional per-vertex normals, indexed.
struct TriangleList {
    std::vector<float> xyz;     // positions, 3 floats per vertex, m
    std::vector<float> nrm;     // per-vertex normals, 3 floats per vertex
    std::vector<unsigned> idx;  // 3 vertex indices per triangle
};

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

// An orthonormal pair spanning the plane with normal n.
void planeAxes(const Vec3& n, Vec3& a, Vec3& b) {
    a = (std::abs(n.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)).cross(n).normalized();
    b = n.cross(a);
}


// A vertex array object and its buffers: one per attribute (kPosition .. kUv) and the indices.
struct Mesh {
    GLuint vao = 0;
    gl::Buffer attr[4];
    gl::Buffer idx;
    GLsizei indices = 0;  // how many indices were uploaded last

    void bind() {
        if (vao == 0) glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
    }
    // Uploads an attribute (`size` floats per vertex) and enables its array; an empty one disables it
    // (the shader then reads the attribute's constant value, glVertexAttrib*()).
    void set(Attribute a, const std::vector<float>& v, int size) {
        bind();
        if (v.empty()) {
            glDisableVertexAttribArray(a);
            return;
        }
        attr[a].upload(GL_ARRAY_BUFFER, v.data(), static_cast<long>(v.size() * sizeof(float)));
        glVertexAttribPointer(a, size, GL_FLOAT, GL_FALSE, 0, nullptr);
        glEnableVertexAttribArray(a);
    }
    void setIndices(const std::vector<unsigned>& i) {
        bind();
        idx.upload(GL_ELEMENT_ARRAY_BUFFER, i.data(), static_cast<long>(i.size() * sizeof(unsigned)));
        indices = static_cast<GLsizei>(i.size());
    }
    void drawElements() {
        bind();
        glDrawElements(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr);
    }
    void drawArrays(GLenum mode, GLint first, GLsizei count) {
        bind();
        if (count > 0) glDrawArrays(mode, first, count);
    }
};

Eigen::Matrix4f toFloat(const Eigen::Matrix4d& m) { return m.cast<float>(); }

// Blending "over" for the colour; the framebuffer's alpha stays 1 (an opaque picture: a PNG, and a
// browser's canvas, which the page would otherwise show through).
void blendOver() {
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
}

void push(std::vector<float>& v, const Vec3& p) {
    for (int k = 0; k < 3; ++k) v.push_back(static_cast<float>(p[k]));
}
void push(std::vector<float>& v, double x, double y, double z) { push(v, Vec3(x, y, z)); }

}  // namespace

// The renderer's GL objects (made in the context current at the first draw) and per-frame scratch.
struct Renderer::Gpu {
    // One of the two programs and its uniforms' locations (-1: not in this one).
    struct Program {
        GLuint id = 0;
        GLint uProjection = -1, uModelView = -1, uPointSize = -1, uRound = -1, uTextured = -1;
        GLint uFront = -1, uBack = -1, uSpecular = -1, uShininess = -1, uTexture = -1;
        void make(const char* defines) {
            id = gl::program(kVertexShader, kFragmentShader, kAttributes, 4, defines);
            const auto u = [this](const char* name) { return glGetUniformLocation(id, name); };
            uProjection = u("uProjection"), uModelView = u("uModelView"), uPointSize = u("uPointSize");
            uRound = u("uRound"), uTextured = u("uTextured"), uFront = u("uFront"), uBack = u("uBack");
            uSpecular = u("uSpecular"), uShininess = u("uShininess"), uTexture = u("uTexture");
        }
    };
    Program shaded, flat;              // lit (LIT) and unlit
    Program* current = nullptr;        // the one in use
    GLuint texture = 0;  // checker texture of the cloth (0: not created yet)
    std::map<std::pair<int, int>, Mesh> spheres;  // unit spheres by (slices, stacks), uploaded once
    Mesh cloth, ground, grid, shadow, colliders, edges, points, rings, planes;
    Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
    std::vector<float> xyz, nrm, rgba, uv;  // scratch, refilled for each upload
    std::vector<unsigned> idx;
    std::vector<unsigned> clothIdx;  // the cloth's indices as uploaded (uploaded again when they change)

    void make() {
        shaded.make("#define LIT\n");
        flat.make("");
    }
    void use(Program& p) {
        if (current != &p) glUseProgram(p.id), current = &p;
    }
    // Both programs: this frame's projection and view, no texture, unit-sized square points.
    void begin(const Eigen::Matrix4f& projection) {
        for (Program* p : {&shaded, &flat}) {
            glUseProgram(p->id);
            glUniformMatrix4fv(p->uProjection, 1, GL_FALSE, projection.data());
            glUniformMatrix4fv(p->uModelView, 1, GL_FALSE, view.data());
            glUniform1i(p->uTextured, 0);
            glUniform1i(p->uTexture, 0);
            glUniform1i(p->uRound, 0);
            glUniform1f(p->uPointSize, 1.0f);
        }
        current = &flat;
    }
    void modelView(const Eigen::Matrix4f& mv) { glUniformMatrix4fv(current->uModelView, 1, GL_FALSE, mv.data()); }
    // Unlit, in one colour (the colour attribute's constant value; a mesh with colours ignores it).
    void unlit(float r, float g, float b, float a = 1) {
        use(flat);
        glVertexAttrib4f(kColor, r, g, b, a);
    }
    // Lit, with a material per side: diffuse colour (ambient 0.35 of it), specular reflectance, shininess.
    void lit(const Eigen::Vector3f& front, const Eigen::Vector3f& back, float spec_front, float spec_back, float shininess) {
        use(shaded);
        glUniform3f(shaded.uFront, front[0], front[1], front[2]);
        glUniform3f(shaded.uBack, back[0], back[1], back[2]);
        glUniform2f(shaded.uSpecular, spec_front, spec_back);
        glUniform1f(shaded.uShininess, shininess);
    }
    void lit(const Eigen::Vector3f& c, float spec, float shininess) { lit(c, c, spec, spec, shininess); }
    // A lit sphere at centre c with radius r (the current material), a unit sphere scaled.
    void sphere(const Vec3& c, double r, int slices, int stacks) {
        Mesh& m = spheres[{slices, stacks}];
        if (m.vao == 0) {
            const TriangleList& t = unitSphere(slices, stacks);
            m.set(kPosition, t.xyz, 3);
            m.set(kNormal, t.nrm, 3);
            m.setIndices(t.idx);
        }
        Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
        model.topLeftCorner<3, 3>() *= static_cast<float>(r);
        model.topRightCorner<3, 1>() = c.cast<float>();
        modelView(view * model);
        m.drawElements();
        modelView(view);
    }
};

Renderer::Renderer() = default;
Renderer::~Renderer() = default;  // the GL objects stay: the context may be gone (one Renderer per context)
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

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
    if (!gpu_) gpu_ = std::make_unique<Gpu>(), gpu_->make();
    Gpu& g = *gpu_;
    const int width = vp.width, height = vp.height;
    glViewport(vp.x, fb_height - vp.y - vp.height, width, height);
    glScissor(vp.x, fb_height - vp.y - vp.height, width, height);
    glEnable(GL_SCISSOR_TEST);  // clear and draw only this part of the framebuffer
    glDisable(GL_DITHER);
    glDepthMask(GL_TRUE);
    glClearColor(kBackground[0], kBackground[1], kBackground[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    // Background: the clear colour, a light blue-grey (a gradient quad over the whole view cost a
    // full-screen pass of llvmpipe's fragment work per frame: docs/performance.md).
    lap("background");
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
#if CLOTHLAB_GL_DESKTOP
    glEnable(GL_PROGRAM_POINT_SIZE);  // the vertex shader sets the point size (always so in GLSL ES)
#endif
    const Eigen::Matrix4d P = cam.projection(double(width) / height), V = cam.view();
    g.view = toFloat(V);
    g.begin(toFloat(P));

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
            const double e = ncell * cell;
            g.xyz.clear();
            for (const auto& [dx, dz] : {std::pair(-e, -e), std::pair(-e, e), std::pair(e, e), std::pair(-e, -e), std::pair(e, e), std::pair(e, -e)})
                push(g.xyz, gx0 + dx, gy, gz0 + dz);
            g.ground.set(kPosition, g.xyz, 3);
            g.unlit(0.86f, 0.87f, 0.88f);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(1, 1);
            g.ground.drawArrays(GL_TRIANGLES, 0, 6);
            glDisable(GL_POLYGON_OFFSET_FILL);
        }
        blendOver();
        glLineWidth(1.0f);
        g.xyz.clear();
        g.rgba.clear();
        for (int k = -ncell; k <= ncell; ++k) {
            const float a = (k % 10 == 0) ? 0.45f : (k % 5 == 0 ? 0.30f : 0.16f);
            push(g.xyz, gx0 + k * cell, gy, gz0 - ncell * cell);
            push(g.xyz, gx0 + k * cell, gy, gz0 + ncell * cell);
            push(g.xyz, gx0 - ncell * cell, gy, gz0 + k * cell);
            push(g.xyz, gx0 + ncell * cell, gy, gz0 + k * cell);
            for (int v = 0; v < 4; ++v) g.rgba.insert(g.rgba.end(), {0.35f, 0.38f, 0.45f, a});
        }
        g.grid.set(kPosition, g.xyz, 3);
        g.grid.set(kColor, g.rgba, 4);
        g.unlit(0, 0, 0);
        g.grid.drawArrays(GL_LINES, 0, static_cast<GLsizei>(g.xyz.size() / 3));
        lap("ground and grid");
        // A soft shadow of the cloth and the particles straight down on the ground, one draw of triangles.
        glDepthMask(GL_FALSE);
        const double sy = gy + 1e-3 * scale;
        g.xyz.clear();
        // A fan around (cx, cz) with radius r in `segments` triangles.
        const auto disc = [&](double cx, double cz, double r, int segments) {
            for (int k = 0; k < segments; ++k) {
                push(g.xyz, cx, sy, cz);
                push(g.xyz, cx + r * std::cos(2 * kPi * k / segments), sy, cz + r * std::sin(2 * kPi * k / segments));
                push(g.xyz, cx + r * std::cos(2 * kPi * (k + 1) / segments), sy, cz + r * std::sin(2 * kPi * (k + 1) / segments));
            }
        };
        if (!d.triangles.empty()) {
            // The convex hull of the cloth projected straight down, one fan: a soft blob in place of
            // every triangle's projection (which cost llvmpipe a triangle setup each, twice per frame
            // with the cloth itself; docs/performance.md).
            const std::vector<int> hull = groundHull(d.x);
            for (size_t k = 1; k + 1 < hull.size(); ++k)
                for (const int i : {hull[0], hull[k], hull[k + 1]}) push(g.xyz, d.x(0, i), sy, d.x(2, i));
        }
        for (const Collider& c : d.colliders)
            if (c.type == Collider::Type::Sphere && opt.colliders) disc(c.point.x(), c.point.z(), 0.9 * c.radius, 48);
        if (d.triangles.empty())
            for (int i = 0; i < d.x.cols(); ++i) disc(d.x(0, i), d.x(2, i), 0.05 * scale, 24);
        g.shadow.set(kPosition, g.xyz, 3);
        g.unlit(0.1f, 0.12f, 0.18f, 0.12f);
        g.shadow.drawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(g.xyz.size() / 3));
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }

    lap("shadow");
    // The cloth before the colliders: the parts of a sphere or table it covers then fail the depth test
    // before their lighting is computed (llvmpipe tests depth first for a shader without discard).
    if (opt.surface && !d.triangles.empty()) drawSurface(d, scale);
    lap("cloth");
    // Colliders.
    if (opt.colliders) {
        for (const Collider& c : d.colliders) {
            if (c.type == Collider::Type::Sphere) {
                g.lit({0.55f, 0.60f, 0.66f}, 0.35f, 40);
                g.sphere(c.point, std::max(c.radius - 0.5e-3 * scale, 0.0), 48, 24);
            }
        }
        // Flat-shaded triangles (boxes, capsules, meshes): each corner with its triangle's normal.
        g.xyz.clear();
        g.nrm.clear();
        for (const Matrix3X& corners : d.collider_triangles)
            for (Eigen::Index k = 0; k + 2 < corners.cols(); k += 3) {
                const Vec3 n = (corners.col(k + 1) - corners.col(k)).cross(corners.col(k + 2) - corners.col(k)).normalized();
                for (int j = 0; j < 3; ++j) push(g.xyz, corners.col(k + j)), push(g.nrm, n);
            }
        if (!g.xyz.empty()) {
            g.colliders.set(kPosition, g.xyz, 3);
            g.colliders.set(kNormal, g.nrm, 3);
            g.lit({0.62f, 0.56f, 0.50f}, 0.2f, 30);
            g.colliders.drawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(g.xyz.size() / 3));
        }
    }

    lap("colliders");
    if (opt.edges || d.triangles.empty()) drawEdges(d, opt, scale);
    lap("edges");
    drawParticles(d, opt, scale);

    // Planes other than the ground: translucent panels with a border, drawn last so what lies behind shows.
    if (opt.colliders) {
        g.xyz.clear();
        int panels = 0;
        for (const Collider& c : d.colliders) {
            if (c.type != Collider::Type::Plane || (ground_is_plane && c.normal.y() > 0.99)) continue;
            Vec3 a, b;
            planeAxes(c.normal, a, b);
            const Vec3 o = c.point + (cam.target - c.point).dot(a) * a + (cam.target - c.point).dot(b) * b;
            const double e = 1.2 * scale;
            const Vec3 q[4] = {o - e * a - e * b, o + e * a - e * b, o + e * a + e * b, o - e * a + e * b};
            for (const int i : {0, 1, 2, 0, 2, 3}) push(g.xyz, q[i]);  // the panel, two triangles
            ++panels;
        }
        if (panels) {
            // The borders: corners 0, 1, 2, 3 of each panel are its vertices 0, 1, 2, 5.
            const size_t tri = g.xyz.size();
            for (int p = 0; p < panels; ++p)
                for (int i = 0; i < 4; ++i) {
                    static const int corner[4] = {0, 1, 2, 5};
                    for (const int c : {corner[i], corner[(i + 1) % 4]})
                        for (int k = 0; k < 3; ++k) g.xyz.push_back(g.xyz[18 * static_cast<size_t>(p) + 3 * c + k]);
                }
            g.planes.set(kPosition, g.xyz, 3);
            blendOver();
            glDepthMask(GL_FALSE);
            g.unlit(0.55f, 0.62f, 0.75f, 0.30f);
            g.planes.drawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tri / 3));
            g.unlit(0.30f, 0.36f, 0.50f, 0.8f);
            glLineWidth(1.5f);
            g.planes.drawArrays(GL_LINES, static_cast<GLint>(tri / 3), static_cast<GLsizei>((g.xyz.size() - tri) / 3));
            glLineWidth(1.0f);
            glDepthMask(GL_TRUE);
            glDisable(GL_BLEND);
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
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
    Gpu& g = *gpu_;
    const int n = static_cast<int>(d.x.cols());
    // Smooth shading: per-vertex normals, the area-weighted sum of the face normals around each particle.
    Matrix3X nrm = Matrix3X::Zero(3, n);
    for (const auto& t : d.triangles) {
        const Vec3 fn = (d.x.col(t[1]) - d.x.col(t[0])).cross(d.x.col(t[2]) - d.x.col(t[0]));
        for (int k = 0; k < 3; ++k) nrm.col(t[k]) += fn;
    }
    g.xyz.resize(3 * static_cast<size_t>(n));
    g.nrm.resize(3 * static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double len = nrm.col(i).norm();
        for (int k = 0; k < 3; ++k) {
            g.xyz[3 * i + k] = static_cast<float>(d.x(k, i));
            g.nrm[3 * i + k] = static_cast<float>(len > 0 ? nrm(k, i) / len : (k == 2));
        }
    }
    g.cloth.set(kPosition, g.xyz, 3);
    g.cloth.set(kNormal, g.nrm, 3);
    triangleIndices(d, g.idx);
    if (g.idx.size() != static_cast<size_t>(g.cloth.indices) || g.idx != g.clothIdx) {  // new topology only
        g.cloth.setIndices(g.idx);
        g.clothIdx = g.idx;
    }

    const bool textured = d.uv.cols() == n;
    g.uv.clear();
    if (textured) {
        if (g.texture == 0) {
            // A two-tone checker (8 x 8 squares) that makes stretching and folds visible.
            const int S = 64;
            std::vector<unsigned char> tex(S * S * 3);
            for (int y = 0; y < S; ++y)
                for (int x = 0; x < S; ++x) {
                    const bool dark = ((x / 8) + (y / 8)) % 2;
                    for (int k = 0; k < 3; ++k) tex[3 * (y * S + x) + k] = dark ? 214 : 255;
                }
            glGenTextures(1, &g.texture);
            glBindTexture(GL_TEXTURE_2D, g.texture);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, S, S, 0, GL_RGB, GL_UNSIGNED_BYTE, tex.data());
        }
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, g.texture);
        g.uv.resize(2 * static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) g.uv[2 * i] = static_cast<float>(d.uv(0, i)), g.uv[2 * i + 1] = static_cast<float>(d.uv(1, i));
    }
    g.cloth.set(kUv, g.uv, 2);  // none: the array is off
    // Two-sided lighting: warm front, cool back.
    g.lit({0.95f, 0.52f, 0.22f}, {0.30f, 0.52f, 0.85f}, 0.25f, 0.15f, 24);
    glUniform1i(g.shaded.uTextured, textured);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1, 1);
    g.cloth.drawElements();
    glUniform1i(g.shaded.uTextured, 0);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::drawEdges(const DrawData& d, const RenderOptions& opt, double scale) {
    Gpu& g = *gpu_;
    glLineWidth(opt.line_width);
    g.xyz.clear();
    g.rgba.clear();
    // A segment a-b in colour c, into the vertex arrays drawn at the end.
    const auto segment = [&g](const Vec3& a, const Vec3& b, const Eigen::Vector3f& c) {
        push(g.xyz, a), push(g.xyz, b);
        for (int v = 0; v < 2; ++v) g.rgba.insert(g.rgba.end(), {c[0], c[1], c[2], 1.0f});
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
    g.edges.set(kPosition, g.xyz, 3);
    g.edges.set(kColor, g.rgba, 4);
    g.unlit(0, 0, 0);
    g.edges.drawArrays(GL_LINES, 0, static_cast<GLsizei>(g.xyz.size() / 3));
    glLineWidth(1.0f);
}

void Renderer::drawParticles(const DrawData& d, const RenderOptions& opt, double scale) {
    Gpu& g = *gpu_;
    const int n = static_cast<int>(d.x.cols());
    const bool few = n <= 400 && d.triangles.empty();
    if (few) {
        // Few particles (spring, chain): lit spheres, pinned ones as red anchors.
        for (int i = 0; i < n; ++i) {
            const bool pinned = d.w.size() == n && d.w[i] == 0;
            if (pinned && !opt.pinned) continue;
            g.lit(pinned ? Eigen::Vector3f(0.85f, 0.12f, 0.10f) : Eigen::Vector3f(0.95f, 0.55f, 0.15f), 0.5f, 50);
            g.sphere(d.x.col(i), (pinned ? 0.035 : (n > 3 ? 0.045 : 0.08)) * scale, 24, 12);
        }
        // The analytic solution as a green ring facing the camera, drawn on top.
        if (d.ghosts.empty()) return;
        g.xyz.clear();
        const double gr = (n > 3 ? 0.06 : 0.11) * scale;
        for (const Vec3& c : d.ghosts)
            for (int k = 0; k < 48; ++k)
                for (const int j : {k, k + 1}) {
                    const double a = 2 * kPi * j / 48;
                    push(g.xyz, c + gr * (std::cos(a) * right_ + std::sin(a) * up_));
                }
        g.rings.set(kPosition, g.xyz, 3);
        glDisable(GL_DEPTH_TEST);
        blendOver();
        glLineWidth(3.0f);
        g.unlit(0.10f, 0.70f, 0.25f, 0.9f);
        g.rings.drawArrays(GL_LINES, 0, static_cast<GLsizei>(g.xyz.size() / 3));
        glLineWidth(1.0f);
        glDisable(GL_BLEND);
        glEnable(GL_DEPTH_TEST);
        return;
    }
    if (opt.particles && n <= 20000) {
        // Round points (the fragment shader cuts the square to a disc).
        blendOver();
        g.xyz.resize(3 * static_cast<size_t>(n));
        for (int i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) g.xyz[3 * i + k] = static_cast<float>(d.x(k, i));
        g.points.set(kPosition, g.xyz, 3);
        g.unlit(0.20f, 0.20f, 0.25f);
        glUniform1f(g.flat.uPointSize, n > 2000 ? 2.0f : 3.5f);
        glUniform1i(g.flat.uRound, 1);
        g.points.drawArrays(GL_POINTS, 0, n);
        glUniform1i(g.flat.uRound, 0);
        glUniform1f(g.flat.uPointSize, 1.0f);
        glDisable(GL_BLEND);
    }
    if (opt.pinned && d.w.size() == n) {
        // Pinned particles of a cloth: small red spheres.
        g.lit({0.85f, 0.12f, 0.10f}, 0.5f, 50);
        int drawn = 0;
        for (int i = 0; i < n && drawn < 2000; ++i)
            if (d.w[i] == 0) g.sphere(d.x.col(i), 0.02 * scale, 16, 8), ++drawn;
    }
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
