/// @file renderer.h
/// @brief The OpenGL renderer: cloth surface, spring/constraint overlay, particles, colliders, ground grid.
///
/// Draws into whatever OpenGL context is current (an offscreen one, offscreen.h, or a GLFW window):
/// OpenGL 3.3 core profile, with one shader program and vertex buffer objects; the browser build
/// compiles the same source for WebGL2 (OpenGL ES 3.0, GLSL ES 3.00; the switch is in
/// framework/src/render/gl.h). This code is compiled once and linked into every program; it links no
/// GL library itself.
#pragma once
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "clothlab/render/camera.h"
#include "clothlab/render/draw_data.h"
#include "clothlab/render/image.h"

namespace clothlab {

/// What to draw and how.
struct RenderOptions {
    bool surface = true;          ///< the cloth surface (lit, two-sided: front warm, back cool)
    bool edges = false;           ///< the spring/constraint overlay
    bool color_by_strain = false; ///< colour edges by strain (blue: compressed, red: stretched) instead of by type
    double strain_range = 0.1;    ///< strain mapped to full red/blue (0.1 = 10 %)
    bool show_kind[4] = {true, true, true, true};  ///< per EdgeKind (single, structural, shear, bending)
    bool particles = false;       ///< the particles of a cloth as points (a spring's or chain's particles are always drawn, as spheres)
    bool pinned = true;           ///< mark pinned particles (w = 0) in red
    bool colliders = true;        ///< planes and spheres
    bool ground = true;           ///< the ground grid
    bool legend = true;           ///< the colour legend and title in the overlay (see overlay.h)
    float line_width = 1.5f;      ///< overlay line width, pixels
    double ground_y = std::nan("");  ///< height of the ground grid, m (NaN: below the lowest point of this frame)
};

/// A rectangle of the framebuffer to draw into, in pixels, origin at the top-left corner (as the
/// mouse and Camera::project() count).
struct Viewport {
    int x = 0;       ///< left edge, pixels
    int y = 0;       ///< top edge, pixels
    int width = 0;   ///< width, pixels
    int height = 0;  ///< height, pixels
};

/// Wall time of one pass of Renderer::draw(), summed over the frames since Renderer::resetTimes().
struct RenderPassTime {
    const char* name;   ///< "background", "ground and grid", "shadow", "cloth", "colliders", "edges", "particles and planes" (in this order)
    double ms = 0.0;    ///< wall time, milliseconds, summed
    double cpu_ms = 0.0;  ///< CPU time of every thread (the GL's too) by the clock given to setTiming(), ms, summed
};

/// Draws DrawData with a camera. Holds the GL objects it creates at its first draw (the shader
/// program, vertex arrays and buffers, the cloth texture), so use one Renderer per GL context; they
/// are not deleted with it (the context may be gone by then).
class Renderer {
public:
    /// A renderer without GL objects yet (they are made in the context current at the first draw()).
    Renderer();
    ~Renderer();
    /// Moves the GL objects' handles to this one.
    Renderer(Renderer&&) noexcept;
    /// Moves the GL objects' handles to this one.
    Renderer& operator=(Renderer&&) noexcept;

    /// Renders one frame into the current context's viewport of size width x height:
    /// background, ground grid and the cloth's shadow, cloth surface, colliders, edges, particles. Ends
    /// with glFlush(), not glFinish(): the GL may still be drawing when it returns (reading the pixels
    /// waits for it), so the caller can step the simulation meanwhile (llvmpipe draws on its own threads).
    /// @param d              what to draw
    /// @param cam            camera
    /// @param opt            options
    /// @param width, height  viewport size in pixels
    void draw(const DrawData& d, const Camera& cam, const RenderOptions& opt, int width, int height);

    /// The same into a part of the framebuffer (a split view): only `vp` is cleared and drawn, with
    /// the projection of its own aspect ratio vp.width / vp.height.
    /// @param d          what to draw
    /// @param cam        camera
    /// @param opt        options
    /// @param vp         the rectangle, pixels from the top-left corner
    /// @param fb_height  the framebuffer's height, pixels
    void draw(const DrawData& d, const Camera& cam, const RenderOptions& opt, const Viewport& vp, int fb_height);

    /// Clears the whole framebuffer (colour and depth) to the background's light grey, e.g. before split views.
    /// @param width, height  framebuffer size in pixels
    void clear(int width, int height);
    /// Fills a rectangle with one colour by clearing it (cheap for any GL, llvmpipe included), e.g. the
    /// background of a panel that ImGui then draws without its own (a blended, textured fill per pixel).
    /// @param vp         the rectangle, pixels from the top-left corner
    /// @param fb_height  the framebuffer's height, pixels
    /// @param rgb        the colour, components in [0, 1]
    void fill(const Viewport& vp, int fb_height, const Eigen::Vector3f& rgb);

    /// Times each pass of draw() (glFinish() after each, which costs a little: for measuring only).
    /// @param on   time from now on, or stop
    /// @param cpu  the process's CPU time, s (e.g. from getrusage(); empty: no CPU times)
    void setTiming(bool on, std::function<double()> cpu = {}) { timing_ = on, cpu_ = std::move(cpu); }
    /// The passes' times since the last resetTimes() (empty unless setTiming(true)).
    const std::vector<RenderPassTime>& passTimes() const { return times_; }
    /// Sets the passes' times to zero.
    void resetTimes() { times_.clear(); }

private:
    void drawSurface(const DrawData& d, double scale);
    void drawEdges(const DrawData& d, const RenderOptions& opt, double scale);
    void drawParticles(const DrawData& d, const RenderOptions& opt, double scale);
    /// The cloth's triangles as indices into its particles (3 per triangle).
    static void triangleIndices(const DrawData& d, std::vector<unsigned>& idx);

    void lap(const char* pass);   ///< with timing: glFinish(), then books the time since the last lap on `pass`

    bool timing_ = false;         ///< setTiming()
    std::vector<RenderPassTime> times_;  ///< passTimes()
    double lap_ = 0.0;            ///< the time of the last lap, s (steady clock)
    double lapCpu_ = 0.0;         ///< the CPU time then, s
    std::function<double()> cpu_; ///< setTiming()
    struct Gpu;                   ///< the GL objects (program, vertex arrays, buffers, texture) and scratch arrays
    std::unique_ptr<Gpu> gpu_;    ///< made at the first draw()
    Vec3 right_{1, 0, 0};         ///< camera right axis (for markers facing the camera)
    Vec3 up_{0, 1, 0};            ///< camera up axis
};

/// RGB colour (components in [0, 1]) of an edge kind in the overlay.
/// @param kind  the kind
Eigen::Vector3f edgeKindColor(EdgeKind kind);

/// Diverging colour map for strain: blue (−range) – light grey (0) – red (+range), clamped.
/// @param strain  ε = l/l0 − 1
/// @param range   strain mapped to the end colours (> 0)
Eigen::Vector3f strainColor(double strain, double range);

/// Reads the current context's colour buffer (width x height) into an image, top row first.
/// @param width, height  size in pixels
Image readPixels(int width, int height);

/// GL_RENDERER of the current context up to its first " (", e.g. "llvmpipe" for
/// "llvmpipe (LLVM 15.0.6, 256 bits)"; "unknown" when there is none.
std::string glRendererName();

}  // namespace clothlab
