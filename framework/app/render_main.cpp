// clothlab-render (OSMesa) and clothlab-render-egl (EGL surfaceless): offscreen pictures, no display
// needed. One source, two programs: each links one backend of render/offscreen.h; ./lab picks one.
//   render SCENE [--seconds T] [--fps F] --out DIR [--video FILE.mp4]   frames of a simulated scene
//   gui [SCENE] --screenshot FILE.png [--frames N] [--compare a,b] [--status F.json] [--timings]
//                                                                        the whole app, panels included
//   bench [--n 32] [--frames 60]                                         app frames per second on an n x n cloth
//   probe                                                                can this backend make a context here?
// Each run prints one line "renderer: OSMesa (llvmpipe)" or "renderer: EGL surfaceless (llvmpipe)";
// when no context can be made: one line "error: renderer: ..." and exit code 4.
#include <imgui.h>

#include <GL/gl.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "clothlab/core/input_error.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/scene_checks.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/core/stub_advice.h"
#include "clothlab/gui/app.h"
#include "clothlab/io/report.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/render/offscreen.h"
#include "clothlab/render/overlay.h"
#include "clothlab/render/imgui_gl.h"
#include "clothlab/render/renderer.h"
#include "clothlab/render/video.h"
#include "clothlab/sim/run.h"

#ifndef CLOTHLAB_SCENES_DIR
#define CLOTHLAB_SCENES_DIR "scenes"
#endif

using namespace clothlab;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// CPU time of this process, every thread (the simulation's and llvmpipe's), s: on a busy machine a
// frame's wall time grows with the others' load, its CPU time much less; on an idle machine with two
// cores the wall time is at most the CPU time (docs/performance.md).
double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// An ImGui context drawing into the current (offscreen) GL context.
struct OffscreenImGui {
    OffscreenImGui(int w, int h) {
        ImGui::CreateContext();
        setupImGuiStyle();
        ImGui::GetIO().DisplaySize = ImVec2(float(w), float(h));
        imguiGlInit();
    }
    ~OffscreenImGui() {
        imguiGlShutdown();
        ImGui::DestroyContext();
    }
    void begin(double dt) {
        ImGui::GetIO().DeltaTime = static_cast<float>(dt);
        imguiGlNewFrame();
        ImGui::NewFrame();
    }
    void end() {
        ImGui::Render();
        imguiGlRender(ImGui::GetDrawData());
    }
};

// The offscreen context, with the one "renderer:" line of the run.
std::unique_ptr<OffscreenContext> makeContext(int w, int h) {
    auto ctx = std::make_unique<OffscreenContext>(w, h);
    std::cout << "renderer: " << ctx->description() << std::endl;
    return ctx;
}

void parseSize(const std::string& s, int& w, int& h) {
    if (std::sscanf(s.c_str(), "%dx%d", &w, &h) != 2 || w < 16 || h < 16 || w > 8192 || h > 8192)
        throw InputError("command line", "--size", "expected WIDTHxHEIGHT, e.g. 960x540 (got \"" + s + "\")");
}

// ---- render ------------------------------------------------------------------------------------
struct RenderArgs {
    std::string scene, out, video, size = "960x540";
    std::vector<std::string> sets;
    double seconds = -1, fps = 30;
    bool edges = false, strain = false, quiet = false;
};

int runRender(const RenderArgs& a) {
    int W, H;
    parseSize(a.size, W, H);
    const Scene scene = loadScene(a.scene, a.sets);
    auto sim = makeSimulation(scene);
    auto ctx = makeContext(W, H);  // before simulating: no context, no point in simulating
    const double dt = scene.solver.dt;
    const double T = a.seconds >= 0 ? a.seconds : scene.solver.steps * dt;
    // Frame f shows the state after round(f / (fps dt)) steps, so the clip keeps time with the simulation.
    const long long per_frame = std::max<long long>(1, std::llround(1.0 / (a.fps * dt)));
    const long long frames = static_cast<long long>(std::floor(T * a.fps + 1e-9)) + 1;
    auto stepsUntil = [&](long long f) { return std::max<long long>(f, std::llround(f / (a.fps * dt))); };

    std::cout << "scene   " << scene.file << (scene.description.empty() ? "" : "  — " + scene.description) << "\n"
              << "method  " << methodName(scene.solver.method) << "   dt = " << dt << " s   " << frames << " frames at " << a.fps
              << " fps (about " << per_frame << " steps each)   particles = " << sim->state().size() << "\n";

    // 1) Simulate, keeping the state of every frame (and the report rows of error against wall time).
    std::vector<DrawData> shots;
    RunResult result;
    const long long every = std::max<long long>(1, stepsUntil(frames - 1) / 10);
    bool header = false;
    RunChecks checks(*sim);  // the same checks and messages as `clothlab run`
    const auto t0 = Clock::now();
    for (long long f = 0; f < frames; ++f) {
        if (f > 0) {
            const long long n = stepsUntil(f) - result.steps;
            for (long long k = 0; k < n; ++k) {
                result.message = checks.step(*sim, ++result.steps);
                if (!result.message.empty()) {
                    result.unstable = true;
                    break;
                }
                if (result.steps % every == 0 || (f == frames - 1 && k == n - 1)) {
                    ReportRow row{result.steps, sim->state().t, seconds(t0, Clock::now()), sim->metrics()};
                    if (!a.quiet) {
                        if (!header) printReportHeader(std::cout, row), header = true;
                        printReportRow(std::cout, row);
                    }
                    result.rows.push_back(row);
                }
            }
        }
        if (result.unstable) break;
        shots.push_back(makeDrawData(*sim));
        shots.back().note = lookChecksLine(lookChecks(*sim));  // what the picture shows, by numbers (sim/scene_checks.h)
    }
    result.wall = seconds(t0, Clock::now());
    if (!result.unstable) checks.finish(*sim);
    checks.collect(result);
    printSummary(std::cout, *sim, result);

    // 2) One camera for the whole clip, fitted to everything that moves (or the scene's own).
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const DrawData& d : shots) {
        Vec3 l, h;
        drawBounds(d, l, h);
        lo = lo.cwiseMin(l), hi = hi.cwiseMax(h);
    }
    const Camera cam = sceneCamera(scene, lo, hi, double(W) / H);
    RenderOptions opt;
    opt.edges = a.edges || a.strain;
    opt.color_by_strain = a.strain;
    opt.ground_y = lo.y() - 0.08 * std::max((hi - lo).maxCoeff(), 0.2);

    // 3) Render.
    std::filesystem::create_directories(a.out);
    OffscreenImGui gui(W, H);
    Renderer renderer;
    std::unique_ptr<VideoWriter> video;
    if (!a.video.empty()) {
        if (ffmpegAvailable()) video = std::make_unique<VideoWriter>(a.video, W, H, a.fps);
        else std::cout << "note: ffmpeg is not installed, so no video (apt-get install ffmpeg); the PNG frames are written\n";
    }
    const auto r0 = Clock::now();
    double draw_s = 0;
    for (size_t f = 0; f < shots.size(); ++f) {
        const auto d0 = Clock::now();
        renderer.draw(shots[f], cam, opt, W, H);
        gui.begin(1.0 / a.fps);
        drawOverlay(shots[f], opt);
        gui.end();
        const Image img = ctx->read();
        draw_s += seconds(d0, Clock::now());
        char name[32];
        std::snprintf(name, sizeof name, "/frame_%04zu.png", f);
        writePng(a.out + name, img);
        if (video) video->write(img);
    }
    const double total = seconds(r0, Clock::now());
    std::cout << "rendered " << shots.size() << " frames " << W << "x" << H << " to " << a.out << "/frame_*.png in "
              << total << " s: " << 1000 * draw_s / shots.size() << " ms per frame to draw, "
              << 1000 * total / shots.size() << " ms with the PNG\n";
    if (video) {
        if (video->close()) std::cout << "wrote " << a.video << "\n";
        else std::cout << "note: ffmpeg failed to write " << a.video << "\n";
    }
    if (result.unstable) {
        std::cerr << "error: " << scene.file << ": solver: " << result.message << "\n";
        return 3;
    }
    return 0;
}

// ---- gui --screenshot and bench ----------------------------------------------------------------
struct GuiArgs {
    std::string scene, screenshot, scenes = CLOTHLAB_SCENES_DIR, size = "1280x800", compare, status;
    int frames = 30, wave = 0, edges = -1;
    double display_fps = 60;  // each frame asks for 1/display_fps simulated seconds (a display at that rate)
    bool app_budget = false;  // step with the window app's budget (a 30 fps frame) instead of all a frame asks for
    bool strain = false, timings = false;
    std::vector<std::string> sets;
};

int runGui(const GuiArgs& a) {
    int W, H;
    parseSize(a.size, W, H);
    auto ctx = makeContext(W, H);
    OffscreenImGui gui(W, H);
    AppOptions o;
    o.scene = a.scene;
    o.scenes_dir = a.scenes;
    o.wave_grid = a.wave;
    o.edges = a.edges;
    o.strain = a.strain;
    o.sets = a.sets;
    o.compare = a.compare;
    o.timing = a.timings;
    o.step_beside_drawing = true;  // as the window app (with --timings each part in turn)
    o.cpu_clock = cpuSeconds;
    // Offscreen every frame steps all it asks for: a screenshot after N frames shows t = N / display fps,
    // whatever the machine's load; --app-budget steps as the window does (docs/performance.md).
    if (!a.app_budget) o.step_budget = 1e9;
    const double frame_dt = 1.0 / a.display_fps;
    App app(o);
    // The first frames build the font texture and lay out the panel; time the rest.
    const int warm = 3, frames = std::max(a.frames, warm + 1);
    auto t0 = Clock::now();
    double imgui_ms = 0, imgui_cpu = 0, cpu0 = 0;
    for (int f = 0; f < frames; ++f) {
        if (f == warm) t0 = Clock::now(), app.resetTimings(), imgui_ms = imgui_cpu = 0, cpu0 = cpuSeconds();
        gui.begin(frame_dt);
        app.frame(W, H);
        const auto r0 = Clock::now();
        const double c = cpuSeconds();
        gui.end();
        app.endFrame();
        glFinish();
        imgui_ms += 1e3 * seconds(r0, Clock::now());
        imgui_cpu += 1e3 * (cpuSeconds() - c);
    }
    const double s = seconds(t0, Clock::now()), n = frames - warm, cpu = cpuSeconds() - cpu0;
    const Image img = ctx->read();
    std::cout << "app frame " << W << "x" << H << (a.wave > 1 ? ", " + std::to_string(a.wave) + "x" + std::to_string(a.wave) + " cloth" : "")
                  << ": " << 1000 * s / n << " ms per frame (" << n / s << " fps, " << ctx->description() << "); CPU time "
                  << 1000 * cpu / n << " ms per frame, all threads\n";
    if (a.timings) {  // where the frame's time goes, wall and CPU (docs/performance.md)
        const AppTimings& t = app.timings();
        std::printf("  per frame, wall (CPU of every thread): simulate %.2f (%.2f) ms, draw %.2f (%.2f) ms (data %.2f ms), panel %.2f (%.2f) ms, "
                    "imgui render %.2f (%.2f) ms\n",
                    t.simulate / n, t.cpu_simulate / n, t.draw / n, t.cpu_draw / n, t.draw_data / n, t.panel / n, t.cpu_panel / n, imgui_ms / n,
                    imgui_cpu / n);
        for (const RenderPassTime& p : app.renderer().passTimes())
            std::printf("    draw: %-22s %6.2f (%.2f) ms\n", p.name, p.ms / n, p.cpu_ms / n);
    }
    if (!a.screenshot.empty()) {
        writePng(a.screenshot, img);
        std::cout << "wrote " << a.screenshot << " (" << W << "x" << H << ", " << a.frames << " frames)\n";
    }
    if (!a.status.empty()) {
        std::ofstream out(a.status);
        if (!(out << app.statusJson() << "\n")) throw InputError(a.status, "(file)", "cannot write the file");
        std::cout << "wrote " << a.status << "\n";
    }
    if (!app.message().empty()) std::cout << "panel message: " << app.message() << "\n";
    for (const std::string& w : app.warnings()) std::cout << "panel " << w << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"clothlab-render, clothlab-render-egl — offscreen rendering (OSMesa, EGL): frames, videos, app screenshots"};
    cli.require_subcommand(1);
    int code = 0;

    RenderArgs ra;
    auto* r = cli.add_subcommand("render", "Simulate a scene and write its frames as PNG (and a video)");
    r->add_option("scene", ra.scene, "Scene file (JSON)")->required();
    r->add_option("--set", ra.sets, "Override a scene field (repeatable)");
    r->add_option("--seconds", ra.seconds, "Simulated time (default: solver.steps * dt)")->check(CLI::NonNegativeNumber);
    r->add_option("--fps", ra.fps, "Frames per simulated second")->check(CLI::Range(1.0, 1000.0));
    r->add_option("--out", ra.out, "Folder for frame_NNNN.png")->required();
    r->add_option("--video", ra.video, "Also write a video (needs ffmpeg)");
    r->add_option("--size", ra.size, "Image size WIDTHxHEIGHT");
    r->add_flag("--edges", ra.edges, "Draw the springs/constraints, coloured by type");
    r->add_flag("--strain", ra.strain, "Draw the springs/constraints, coloured by strain");
    r->add_flag("--quiet", ra.quiet, "Print only the summary");
    r->callback([&] { code = runRender(ra); });

    GuiArgs ga;
    auto* g = cli.add_subcommand("gui", "Run the app offscreen for N frames and save the whole window as PNG");
    g->add_option("scene", ga.scene, "Scene file (default: the first in --scenes)");
    g->add_option("--screenshot", ga.screenshot, "PNG file")->required();
    g->add_option("--frames", ga.frames, "Frames to run before the screenshot")->check(CLI::Range(1, 100000));
    g->add_option("--set", ga.sets, "Override a scene field, e.g. --set cloth.nx=32 (repeatable)");
    g->add_option("--scenes", ga.scenes, "Folder the scene picker lists");
    g->add_option("--size", ga.size, "Window size WIDTHxHEIGHT");
    g->add_flag_callback("--edges", [&] { ga.edges = 1; }, "Start with the spring/constraint overlay shown");
    g->add_flag("--strain", ga.strain, "Start with the overlay coloured by strain");
    g->add_option("--compare", ga.compare, "Run 2 to 4 variants side by side, e.g. pbd,xpbd or pbd:iterations=5,pbd:iterations=50");
    g->add_option("--status", ga.status, "Also write what the last frame showed as JSON (runs, their views and labels, cut text)");
    g->add_flag("--timings", ga.timings, "Print where the frame's time goes (simulation, renderer passes, panel, ImGui)");
    g->add_option("--display-fps", ga.display_fps, "Each frame asks for 1/F simulated seconds, as on a display at F frames per second (default 60)")
        ->check(CLI::Range(1.0, 1000.0));
    g->add_flag("--app-budget", ga.app_budget,
                "Step as the window app does, what is left of a 30 fps frame (default: every frame steps all it asks for)");
    g->callback([&] { code = runGui(ga); });

    GuiArgs ba;
    ba.frames = 60;
    auto* b = cli.add_subcommand("bench", "Frames per second of the app drawing an n x n cloth (offscreen)");
    b->add_option("--n", ba.wave, "Cloth size n (particles per side)")->check(CLI::Range(2, 1024));
    b->add_option("--frames", ba.frames, "Frames to time")->check(CLI::Range(1, 100000));
    b->add_option("--size", ba.size, "Window size WIDTHxHEIGHT");
    b->add_option("--screenshot", ba.screenshot, "Also save the last frame");
    b->add_flag_callback("--edges", [&] { ba.edges = 1; }, "Draw the spring/constraint overlay too");
    b->add_flag("--strain", ba.strain, "Draw the overlay coloured by strain");
    b->add_flag("--timings", ba.timings, "Print where the frame's time goes");
    b->callback([&] {
        if (ba.wave == 0) ba.wave = 32;
        code = runGui(ba);
    });

    cli.add_subcommand("probe", "Make a small offscreen context, print the renderer line, exit 0 if it works")
        ->callback([] { makeContext(16, 16); });

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e);
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    } catch (const OffscreenError& e) {
        std::cerr << "error: renderer: " << e.what() << "\n";
        return 4;
    } catch (const NotImplemented& e) {
        std::cerr << e.what() << clothlab::stubAdvice(e.what()) << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: internal: " << e.what() << "\n";
        return 70;
    }
    return code;
}
