/// @file app.h
/// @brief The interactive app: one simulation or two to four side by side (a comparison), their 3-D
/// views and the Dear ImGui panels.
///
/// Platform-free: a GLFW window (clothlab-gui) or an offscreen buffer (clothlab-render[-egl] gui --screenshot)
/// creates the GL context and the ImGui frame and calls App::frame() once per frame.
#pragma once
#include <chrono>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "clothlab/core/scene.h"
#include "clothlab/render/camera.h"
#include "clothlab/render/draw_data.h"
#include "clothlab/render/renderer.h"
#include "clothlab/sim/run.h"
#include "clothlab/sim/simulation.h"
#include "clothlab/study/compare.h"

struct ImVec2;  // Dear ImGui's 2-D point (imgui.h)

namespace clothlab {

/// How a stage's code was chosen at build time (stageCode(), core/stub_advice.h).
struct StageInfo {
    std::string dir;   ///< stage folder, e.g. "01_hooke"
    bool reference;    ///< true: solutions/ (reference), false: exercises/ (student code)
};

/// The stages of this build and which code each uses, parsed from "01_hooke=reference;02_mfn=student".
/// @param spec  the string (stageCode())
std::vector<StageInfo> parseStageCode(const std::string& spec);

/// The app's stepping against a frame's budget. A step is never cut, so a frame's stepping may
/// outlast what the frame allows; the excess is a debt the next frames pay back from their budgets:
/// \f$ a = b - d \f$ may step in a frame with budget b and debt d (none when \f$ a \le 0 \f$: that
/// frame pays back \f$ d \leftarrow d - b \f$), and after stepping s seconds \f$ d = \max(0, s - a) \f$.
/// On average a frame then steps for its budget (a frame whose debt is smaller than its budget still
/// steps for the rest of it).
struct SteppingDebt {
    double debt = 0.0;  ///< stepping time beyond the budgets not yet paid back, s

    /// The time this frame may step, s; 0 when the debt takes the whole budget (which it then pays back).
    /// @param budget  the frame's budget for stepping, s
    /// @return        the time the frame may step, s (a step may start until it has passed)
    double allow(double budget) {
        if (budget > debt) return budget - debt;
        debt -= budget;
        return 0.0;
    }
    /// Records what a frame stepped (nothing for a frame allowed none: allow() settled it).
    /// @param spent    the time its steps took, s
    /// @param allowed  what allow() gave it, s
    void settle(double spent, double allowed) {
        if (allowed > 0) debt = spent > allowed ? spent - allowed : 0.0;
    }
};

/// Start-up settings of the app.
struct AppOptions {
    std::string scene;        ///< scene file to open ("" = the first one in scenes_dir)
    std::string scenes_dir;   ///< folder the scene picker lists (*.json)
    std::vector<std::string> sets;  ///< "key=value" overrides applied to `scene` (as `--set` of `./lab run`)
    std::string compare;      ///< "a,b,...": run these variants of `scene` side by side (parseCompare(); "" = one run)
    bool play = true;         ///< start running
    int edges = -1;           ///< spring/constraint overlay: -1 by scene (on for springs and chains), 0 off, 1 on
    bool strain = false;      ///< colour the overlay by strain instead of by type
    /// Builds the simulation of a scene (default: makeSimulation); tests put a stand-in here.
    std::function<std::unique_ptr<Simulation>(const Scene&)> factory;
    int wave_grid = 0;        ///< > 0: benchmark mode, show an n x n cloth moved by a travelling wave instead of a simulation
    bool timing = false;      ///< time the frame's parts (App::timings(); the renderer's passes with glFinish() between them)
    std::function<double()> cpu_clock;  ///< with timing: the process's CPU time, s, for the CPU columns of AppTimings
    std::string out_dir = "."; ///< where "Export CSV + PNG" writes its folders clothlab_compare_N
    /// Called with the path of each file the app wrote ("Save PNG", "Export CSV + PNG"); the browser's
    /// page (framework/app/web_main.cpp) offers it as a download. Empty: nothing more is done.
    std::function<void(const std::string& path)> file_written;
    /// One line the panel shows under the step time about where the app runs (the browser's page: one
    /// thread); "" none. The status (App::statusJson()) has it as `platform_note`.
    std::string platform_note;
    /// Wall time a frame may spend stepping, s; 0: what a 30 fps frame leaves after the rest of the last
    /// frames (at least 5 ms, at most 40 ms). A measurement of the cost of real time sets it high.
    double step_budget = 0.0;
    /// Step the runs on a second thread while the frame draws the views and ImGui (the native apps: the
    /// simulation and llvmpipe's drawing then share the cores); the caller calls App::endFrame() after
    /// drawing ImGui's data. false (the browser's page, which has one thread; and with `timing`, whose
    /// parts are timed one after the other): frame() steps before it returns.
    bool step_beside_drawing = false;
};

/// Wall time of the parts of the app's frames, summed since App::resetTimings(), ms.
struct AppTimings {
    int frames = 0;            ///< frames summed
    double simulate = 0.0;     ///< stepping the runs (the comparison's advanceTo()) and their samples
    double draw_data = 0.0;    ///< copying the states into DrawData (makeDrawData())
    double draw = 0.0;         ///< the renderer (all views; Renderer::passTimes() splits it)
    double panel = 0.0;        ///< building the ImGui windows (panel, plots, labels)
    double cpu_simulate = 0.0; ///< CPU time of the stepping, every thread (AppOptions::cpu_clock)
    double cpu_draw = 0.0;     ///< CPU time of drawing the data and the views, every thread (the GL's that ran meanwhile too)
    double cpu_panel = 0.0;    ///< CPU time of building the ImGui windows
};

/// The app's look: Dear ImGui's light colours, rounded corners, readable on a projector.
/// Call once after ImGui::CreateContext().
void setupImGuiStyle();

/// A flag cloth of n x n particles (1 m wide, hanging from its top edge) moved by a travelling wave at time t,
/// for measuring drawing speed without a simulation.
/// @param n  particles per side (≥ 2)
/// @param t  time, s
DrawData waveCloth(int n, double t);

/// Text that Dear ImGui drew cut off by its window's edge, found in the draw data after ImGui::Render():
/// a glyph of a window named `window` (or of its child windows) that reaches beyond the clip rectangle
/// of its draw command by more than half a pixel. Needs ImGuiStyle::AntiAliasedLinesUseTex off (as
/// setupImGuiStyle() sets it), so that only glyphs use the font texture.
/// @param window  the window's name, e.g. "clothlab"
/// @return        one entry per cut draw command: "x y" of the first cut glyph's corner, pixels
std::vector<std::string> clippedText(const char* window);

/// The app: owns the scene being edited, the runs built from it (one, or two to four side by side) and the view.
class App {
public:
    /// Opens options.scene (or the first scene of options.scenes_dir), with options.compare's runs.
    /// @param options  start-up settings
    /// @throws InputError for a bad options.compare list
    explicit App(const AppOptions& options);

    /// One frame: handle mouse and keys, build the panels from the runs as they are, draw them into the
    /// current GL context and advance them when playing (on a second thread with
    /// AppOptions::step_beside_drawing, until endFrame()). Call between ImGui::NewFrame() and ImGui::Render().
    /// @param width, height  framebuffer size in pixels
    void frame(int width, int height);

    /// Waits until the stepping that frame() started beside the drawing is done (with
    /// AppOptions::step_beside_drawing; else nothing to wait for). Call after drawing ImGui's data,
    /// before anything else reads or changes the runs.
    void endFrame();
    ~App();

    /// Loads a scene file and rebuilds the runs; a bad file leaves a message in the panel.
    /// @param path  scene file
    /// @return      true when loaded
    bool load(const std::string& path);

    /// The message shown in red at the top of the panel ("" = none), e.g. "not implemented: exercise 3.1 ...".
    const std::string& message() const { return message_; }
    /// The run checks' warnings since the last reset or drag (warningText(): not converged, penetration,
    /// fell through, energy growth), of every run, shown under the message in the panel.
    std::vector<std::string> warnings() const;
    /// The first run's simulation (null when the scene's method is not available in this build).
    const Simulation* simulation() const;
    /// The runs (one, or two to four side by side).
    const Comparison* comparison() const { return cmp_.get(); }
    /// The camera of the 3-D views (fitted to the scene on the first frame; one for every view).
    const Camera& camera() const { return cam_; }
    /// Where run i is drawn in the last frame, pixels from the top-left corner.
    /// @param i  the run
    Viewport viewport(size_t i) const;
    /// Advances every run by one step (as the "Step" button does).
    void stepOnce();
    /// The parts of the frames' time since resetTimings() (with AppOptions::timing; else only `frames`).
    const AppTimings& timings() const { return timings_; }
    /// The renderer (its passes' times: Renderer::passTimes()).
    const Renderer& renderer() const { return renderer_; }
    /// Sets timings() and the renderer's pass times to zero.
    void resetTimings();
    /// What the last frame showed, as JSON: the window size, the scene and its "look" line, every run
    /// (label, colour, viewport, label box, time, steps, wall time, error measure, energy, max strain,
    /// message), the panel's cut text (clippedText()) and whether it scrolls, the timings.
    /// Call after ImGui::Render() (the cut text is read from the draw data).
    std::string statusJson() const;
    /// Writes the runs' samples as DIR/compare.csv and DIR/compare.png (writeCompareCsv(), plotCompare()),
    /// as the "Export CSV + PNG" button does, and says so in the panel.
    /// @param dir  the folder (made if missing)
    /// @return     the note shown in the panel ("wrote DIR/compare.csv and compare.png")
    std::string exportFigures(const std::string& dir);

private:
    void rebuild(bool keep_state);
    void advance(double frame_seconds);
    void guarded(const std::function<void()>& step);  ///< runs `step`; a stub or an error pauses and shows its message
    void handleMouse(int width, int height);
    void fitCamera(int width, int height);
    void layout(int width, int height);
    void panel(int width, int height);
    void panelScene();
    void panelRuns();
    void panelParameters();
    void panelView();
    void panelStages();
    void panelPlots();
    void comparePlots(int width, int height);
    void drawLabels();
    bool compareMode() const { return variants_.size() > 1; }
    int runAt(double px, double py) const;
    void rememberControl(const std::string& name);  // the last item's rectangle
    void rememberControl(const std::string& name, const ImVec2& min, const ImVec2& max);
    void wrote(const std::string& path);
    DrawData drawData(size_t i) const;
    std::string runLabel(const CompareVariant& v) const;

    AppOptions options_;                 ///< start-up settings
    std::vector<std::string> scenes_;    ///< files the picker lists
    std::string scene_path_;             ///< current scene file
    Scene original_;                     ///< as loaded
    Scene scene_;                        ///< as edited in the panel (every run's physics)
    std::vector<Collider> all_colliders_;///< every collider of the file
    std::vector<char> collider_on_;      ///< which of them are active
    std::vector<CompareVariant> variants_;  ///< the runs' labels and solvers (one: no comparison)
    std::unique_ptr<Comparison> cmp_;    ///< the runs
    std::future<void> stepping_;         ///< the frame's stepping beside the drawing (step_beside_drawing)
    std::vector<Viewport> views_;        ///< where each run is drawn
    Viewport plots_rect_;                ///< compare mode: the plots window below the views
    std::vector<std::pair<Viewport, std::string>> label_boxes_;  ///< each view's label as drawn (status)
    std::map<std::string, Viewport> controls_;  ///< where the panel drew its buttons this frame (status: tests click them)
    std::string message_;                ///< error or "not implemented" line
    std::string stub_hit_;               ///< the last NotImplemented message
    bool playing_ = true;                ///< running
    double speed_ = 1.0;                 ///< simulated seconds per wall second
    double target_t_ = 0.0;              ///< the simulated time the runs are advanced to, s
    Camera cam_;                         ///< view (shared by every run's view)
    bool camera_set_ = false;            ///< camera fitted for this scene
    RenderOptions view_;                 ///< what to draw
    Renderer renderer_;                  ///< GL drawing
    int grabbed_ = -1;                   ///< particle being dragged (-1: none)
    int grabbed_run_ = 0;                ///< the run whose particle it is
    double grab_depth_ = 0.0;            ///< its window depth when grabbed
    double grabbed_w_ = 0.0;             ///< its inverse mass before the grab
    bool orbiting_ = false;              ///< left drag on empty space turns the camera
    std::map<int, bool> user_pins_;      ///< pins toggled with the mouse (index -> pinned), every run
    std::vector<StageInfo> stages_;      ///< stages of this build
    double wave_t_ = 0.0;                ///< time of the benchmark wave, s
    bool save_view_ = false;             ///< "Save PNG" pressed: write the 3-D view on the next frame
    int saved_ = 0;                      ///< pictures saved so far
    int exported_ = 0;                   ///< comparisons exported so far
    std::string status_;                 ///< last non-error note (e.g. "saved clothlab_view_1.png")
    bool panel_scrolls_ = false;         ///< the panel's content is taller than the window
    int width_ = 0, height_ = 0;         ///< the last frame's size, pixels
    AppTimings timings_;                 ///< timings()
    long long frames_ = 0;               ///< frames so far
    std::chrono::steady_clock::time_point last_frame_;  ///< when the last frame began
    double simulate_ms_ = 0.0;           ///< the last frame's stepping, ms
    double other_ms_ = 0.0;              ///< the rest of a frame (drawing, panel, ImGui, the host), smoothed, ms
    double last_time_ = 0.0;             ///< the runs' simulated time when the last frame began, s
    SteppingDebt debt_;                  ///< stepping time beyond the frames' budgets, paid back by the next frames
    double asked_ = 0.0;                 ///< the simulated time the last frame asked the runs to advance, s
    double realtime_ = 1.0;              ///< speed x the fraction of it they advanced, smoothed (the panel says when well below speed)
};

}  // namespace clothlab
