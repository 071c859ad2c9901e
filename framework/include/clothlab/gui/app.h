/// @file app.h
/// @brief The interactive app: a simulation, its 3-D view and the Dear ImGui panels.
///
/// Platform-free: a GLFW window (clothlab-gui) or an offscreen buffer (clothlab-render[-egl] gui --screenshot)
/// creates the GL context and the ImGui frame and calls App::frame() once per frame.
#pragma once
#include <deque>
#include <functional>
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

namespace clothlab {

/// How a stage's code was chosen at build time (stageCode(), core/stub_advice.h).
struct StageInfo {
    std::string dir;   ///< stage folder, e.g. "01_hooke"
    bool reference;    ///< true: solutions/ (reference), false: exercises/ (student code)
};

/// The stages of this build and which code each uses, parsed from "01_hooke=reference;02_mfn=student".
/// @param spec  the string (stageCode())
std::vector<StageInfo> parseStageCode(const std::string& spec);

/// Start-up settings of the app.
struct AppOptions {
    std::string scene;        ///< scene file to open ("" = the first one in scenes_dir)
    std::string scenes_dir;   ///< folder the scene picker lists (*.json)
    std::vector<std::string> sets;  ///< "key=value" overrides applied to `scene` (as `--set` of `./lab run`)
    bool play = true;         ///< start running
    int edges = -1;           ///< spring/constraint overlay: -1 by scene (on for springs and chains), 0 off, 1 on
    bool strain = false;      ///< colour the overlay by strain instead of by type
    /// Builds the simulation of a scene (default: makeSimulation); tests put a stand-in here.
    std::function<std::unique_ptr<Simulation>(const Scene&)> factory;
    int wave_grid = 0;        ///< > 0: benchmark mode, show an n x n cloth moved by a travelling wave instead of a simulation
};

/// The app's look: Dear ImGui's light colours, rounded corners, readable on a projector.
/// Call once after ImGui::CreateContext().
void setupImGuiStyle();

/// A flag cloth of n x n particles (1 m wide, hanging from its top edge) moved by a travelling wave at time t,
/// for measuring drawing speed without a simulation.
/// @param n  particles per side (≥ 2)
/// @param t  time, s
DrawData waveCloth(int n, double t);

/// The app: owns the scene being edited, the simulation built from it and the view.
class App {
public:
    /// Opens options.scene (or the first scene of options.scenes_dir).
    /// @param options  start-up settings
    explicit App(const AppOptions& options);

    /// One frame: advance the simulation when playing, handle mouse and keys, draw the 3-D view into
    /// the current GL context and build the panels. Call between ImGui::NewFrame() and ImGui::Render().
    /// @param width, height  framebuffer size in pixels
    void frame(int width, int height);

    /// Loads a scene file and rebuilds the simulation; a bad file leaves a message in the panel.
    /// @param path  scene file
    /// @return      true when loaded
    bool load(const std::string& path);

    /// The message shown in red at the top of the panel ("" = none), e.g. "not implemented: exercise 3.1 ...".
    const std::string& message() const { return message_; }
    /// The run checks' warnings since the last reset or drag (warningText(): not converged, penetration,
    /// fell through, energy growth), shown under the message in the panel.
    std::vector<std::string> warnings() const;
    /// The running simulation (null when the scene's method is not available in this build).
    const Simulation* simulation() const { return sim_.get(); }
    /// The camera of the 3-D view (fitted to the scene on the first frame).
    const Camera& camera() const { return cam_; }
    /// Advances the simulation by one step (as the "Step" button does).
    void stepOnce();

private:
    void rebuild(bool keep_state);
    void advance(double frame_seconds);
    void safeStep();
    void handleMouse(int width, int height);
    void panel(int width, int height);
    void panelScene();
    void panelParameters();
    void panelView();
    void panelStages();
    void panelPlots();
    DrawData currentDrawData() const;
    void pushSample();

    AppOptions options_;                 ///< start-up settings
    std::vector<std::string> scenes_;    ///< files the picker lists
    std::string scene_path_;             ///< current scene file
    Scene original_;                     ///< as loaded
    Scene scene_;                        ///< as edited in the panel
    std::vector<Collider> all_colliders_;///< every collider of the file
    std::vector<char> collider_on_;      ///< which of them are active
    std::unique_ptr<Simulation> sim_;    ///< the simulation (null: not available)
    std::string message_;                ///< error or "not implemented" line
    std::string stub_hit_;               ///< the last NotImplemented message
    bool playing_ = true;                ///< running
    double speed_ = 1.0;                 ///< simulated seconds per wall second
    Camera cam_;                         ///< view
    bool camera_set_ = false;            ///< camera fitted for this scene
    RenderOptions view_;                 ///< what to draw
    Renderer renderer_;                  ///< GL drawing
    int grabbed_ = -1;                   ///< particle being dragged (-1: none)
    double grab_depth_ = 0.0;            ///< its window depth when grabbed
    double grabbed_w_ = 0.0;             ///< its inverse mass before the grab
    bool orbiting_ = false;              ///< left drag on empty space turns the camera
    std::map<int, bool> user_pins_;      ///< pins toggled with the mouse (index -> pinned)
    std::deque<float> energy_, error_, step_ms_;  ///< plot histories
    std::string error_name_;             ///< which metric the error plot shows
    std::string error_unit_;             ///< its unit
    std::deque<double> sample_t_;        ///< simulated time of each plot sample, s
    double plot_span_ = 0.0;             ///< simulated time the plots span, s
    double last_step_ms_ = 0.0;          ///< wall time of the last step, ms
    long long steps_ = 0;                ///< steps since the last reset
    std::unique_ptr<RunChecks> checks_;  ///< the run checks since the last reset or drag (run.h)
    std::vector<StageInfo> stages_;      ///< stages of this build
    double wave_t_ = 0.0;                ///< time of the benchmark wave, s
    bool save_view_ = false;             ///< "Save PNG" pressed: write the 3-D view on the next frame
    int saved_ = 0;                      ///< pictures saved so far
    std::string status_;                 ///< last non-error note (e.g. "saved clothlab_view_1.png")
};

}  // namespace clothlab
