// The interactive app: simulation + 3-D view + Dear ImGui panels (platform-free).
#include "clothlab/gui/app.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/render/overlay.h"
#include "clothlab/sim/run.h"
#include "clothlab/core/stub_advice.h"

namespace clothlab {

namespace {
constexpr size_t kHistory = 300;  // samples in each plot
const ImVec4 kRed(0.85f, 0.15f, 0.12f, 1.0f);

// Whether the key for character c (lower case) was typed this frame, in either case. The app reads
// typed characters, which Dear ImGui has queued the same way in every release Debian ships (1.86 in
// Debian 12, 1.90 in Debian 13), instead of key codes, whose API changed between those releases.
bool typedKey(char c) {
    for (const ImWchar ch : ImGui::GetIO().InputQueueCharacters)
        if (ch == static_cast<ImWchar>(c) || ch == static_cast<ImWchar>(std::toupper(static_cast<unsigned char>(c)))) return true;
    return false;
}

void push(std::deque<float>& q, double v) {
    q.push_back(static_cast<float>(v));
    if (q.size() > kHistory) q.pop_front();
}

// "2.5 us", "1.20 ms", "0.31 s": a duration in the unit that shows it.
std::string duration(double ms) {
    char b[32];
    if (ms < 0.1) std::snprintf(b, sizeof b, "%.3g us", ms * 1e3);
    else if (ms < 1000) std::snprintf(b, sizeof b, "%.3g ms", ms);
    else std::snprintf(b, sizeof b, "%.3g s", ms / 1e3);
    return b;
}

// "1 spring", "3 springs".
std::string count(size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

// A plot with its scale: the top and bottom of the y axis (the samples' maximum and minimum, with
// the unit), the last value, and the x axis (the last n samples, one per frame, over t0..t1 s).
void plot(const char* label, const std::deque<float>& q, const char* unit, double t0, double t1) {
    if (std::string(unit) == "1") unit = "";  // a fraction (strain): no unit to print
    std::vector<float> v(q.begin(), q.end());
    if (v.empty()) {
        ImGui::TextDisabled("%s: no samples yet", label);
        return;
    }
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "last %.4g", v.back());
    ImGui::Text("%s%s%s%s   top %.4g", label, *unit ? " [" : "", unit, *unit ? "]" : "", *hi);
    ImGui::PlotLines((std::string("##") + label).c_str(), v.data(), static_cast<int>(v.size()), 0, overlay, *lo, *hi,
                     ImVec2(ImGui::GetContentRegionAvail().x, 56));
    ImGui::TextDisabled("bottom %.4g  span %.3g  t %.3g-%.3g s", *lo, *hi - *lo, t0, t1);
}

// Stage number of "not implemented: exercise N.M name" (0 if none).
int stageOfMessage(const std::string& msg) {
    const auto p = msg.find("exercise ");
    if (p == std::string::npos) return 0;
    return std::atoi(msg.c_str() + p + 9);
}

// "dt = 0.00100 s###dt [s]": the value beside the slider, where its handle cannot cover it (the ID
// after ### stays the same while the value changes). `label` is "name [unit]".
std::string valueLabel(const char* label, const char* fmt, double v) {
    const std::string l = label;
    const auto open = l.find(" ["), close = l.rfind(']');
    const std::string name = open == std::string::npos ? l : l.substr(0, open);
    const std::string unit = open == std::string::npos || close == std::string::npos ? "" : " " + l.substr(open + 2, close - open - 2);
    char value[48];
    std::snprintf(value, sizeof value, fmt, v);
    return name + " = " + value + (unit == " 1" ? "" : unit) + "###" + l;
}

// A slider on a double, its value shown beside it; true when the user let go of it after a change.
bool sliderD(const char* label, double& v, double lo, double hi, const char* fmt, bool log = false) {
    float f = static_cast<float>(v);
    ImGui::SliderFloat(valueLabel(label, fmt, v).c_str(), &f, static_cast<float>(lo), static_cast<float>(hi), "",
                       log ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    if (ImGui::IsItemActive() || ImGui::IsItemDeactivatedAfterEdit()) v = f;
    return ImGui::IsItemDeactivatedAfterEdit();
}
}  // namespace

std::vector<StageInfo> parseStageCode(const std::string& spec) {
    std::vector<StageInfo> out;
    size_t start = 0;
    while (start < spec.size()) {
        size_t end = spec.find(';', start);
        if (end == std::string::npos) end = spec.size();
        const std::string item = spec.substr(start, end - start);
        const auto eq = item.find('=');
        if (eq != std::string::npos) out.push_back({item.substr(0, eq), item.substr(eq + 1) == "reference"});
        start = end + 1;
    }
    return out;
}

void setupImGuiStyle() {
    ImGui::StyleColorsLight();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 6;
    st.FrameRounding = 4;
    st.GrabRounding = 4;
    st.WindowBorderSize = 0;
    st.Colors[ImGuiCol_WindowBg].w = 0.92f;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini next to the user's files
    // A readable font when Debian's fonts-dejavu-core is installed; else ImGui's built-in one.
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if (io.Fonts->Fonts.empty() && std::filesystem::exists(font)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
}

DrawData waveCloth(int n, double t) {
    ClothSpec c;
    c.nx = c.ny = n;
    c.width = c.height = 1.0;
    c.origin = Vec3(-0.5, 0.5, 0);
    for (int i = 0; i < n; ++i) c.pins.push_back(i);
    const State rest = makeGridState(c);
    State s = rest;
    for (int i = 0; i < s.size(); ++i) {
        const double u = rest.x(0, i) + 0.5, v = 0.5 - rest.x(1, i);
        s.x(2, i) = 0.12 * v * std::sin(6.0 * u - 4.0 * t) + 0.05 * v * v * std::sin(9.0 * v - 3.0 * t);
    }
    s.t = t;
    DrawData d = makeClothDrawData(c, s, rest);
    d.title = "benchmark: " + std::to_string(n) + "x" + std::to_string(n) + " cloth, travelling wave";
    return d;
}

App::App(const AppOptions& options) : options_(options) {
    stages_ = parseStageCode(stageCode());
    std::error_code ec;
    if (!options_.scenes_dir.empty())
        for (const auto& e : std::filesystem::directory_iterator(options_.scenes_dir, ec))
            if (e.path().extension() == ".json") scenes_.push_back(e.path().string());
    std::sort(scenes_.begin(), scenes_.end());
    playing_ = options_.play;
    view_.edges = false;
    const std::string first = !options_.scene.empty() ? options_.scene : (scenes_.empty() ? "" : scenes_.front());
    if (first.empty()) message_ = "no scene: pass a scene file or a folder with scenes";
    else load(first);
}

bool App::load(const std::string& path) {
    try {
        original_ = loadScene(path, path == options_.scene ? options_.sets : std::vector<std::string>{});
    } catch (const InputError& e) {
        message_ = std::string("error: ") + e.what();
        return false;
    }
    scene_path_ = path;
    scene_ = original_;
    all_colliders_ = original_.colliders;
    collider_on_.assign(all_colliders_.size(), 1);
    user_pins_.clear();
    energy_.clear(), error_.clear(), step_ms_.clear(), sample_t_.clear();
    camera_set_ = false;
    view_.color_by_strain = options_.strain;
    view_.edges = options_.strain ? true : options_.edges < 0 ? (scene_.model != Model::Cloth && options_.wave_grid < 2) : options_.edges == 1;
    rebuild(false);
    return true;
}

void App::rebuild(bool keep_state) {
    State old;
    if (sim_) old = sim_->state();
    scene_.colliders.clear();
    for (size_t i = 0; i < all_colliders_.size(); ++i)
        if (collider_on_[i]) scene_.colliders.push_back(all_colliders_[i]);
    sim_.reset();
    checks_.reset();  // made at the next step (safeStep), where a stub's NotImplemented is caught
    message_.clear();
    grabbed_ = -1;
    try {
        sim_ = options_.factory ? options_.factory(scene_) : makeSimulation(scene_);
    } catch (const InputError& e) {
        message_ = std::string("not available: ") + e.what();
    } catch (const NotImplemented& e) {
        message_ = e.what();
        stub_hit_ = e.what();
    } catch (const std::exception& e) {
        message_ = std::string("error: ") + e.what();
    }
    if (!sim_) return;
    State& st = sim_->state();
    if (keep_state && old.size() == st.size()) {
        st.x = old.x;
        st.v = old.v;
        st.t = old.t;
    }
    for (const auto& [i, pinned] : user_pins_)
        if (i < st.size()) {
            if (pinned) st.w[i] = 0.0;
            else if (st.w[i] == 0.0) st.w[i] = 1.0;
        }
    if (!keep_state) energy_.clear(), error_.clear(), step_ms_.clear(), sample_t_.clear(), steps_ = 0;
}

std::vector<std::string> App::warnings() const {
    std::vector<std::string> out;
    RunResult r;
    if (sim_ && checks_) checks_->collect(r);
    for (const RunWarning& w : r.warnings) out.push_back("warning: " + warningText(w, scene_));
    return out;
}

DrawData App::currentDrawData() const {
    if (options_.wave_grid > 1) return waveCloth(options_.wave_grid, wave_t_);
    return sim_ ? makeDrawData(*sim_) : makeDrawData(scene_);
}

void App::safeStep() {
    if (!sim_) return;
    const auto t0 = std::chrono::steady_clock::now();
    std::string unstable;
    try {
        // The user moving a particle puts energy in and particles anywhere: the checks start again.
        if (!checks_ || grabbed_ >= 0) checks_ = std::make_unique<RunChecks>(*sim_);
        unstable = checks_->step(*sim_, ++steps_);
    } catch (const NotImplemented& e) {
        message_ = e.what();
        stub_hit_ = e.what();
        playing_ = false;
        return;
    } catch (const std::exception& e) {
        message_ = std::string("error: ") + e.what();
        playing_ = false;
        return;
    }
    last_step_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!unstable.empty()) {
        message_ = unstable + ": reduce dt or stiffness, then Reset";
        playing_ = false;
    }
}

void App::stepOnce() {
    safeStep();
    pushSample();
}

void App::advance(double frame_seconds) {
    if (!playing_ || !sim_) return;
    const double dt = scene_.solver.dt;
    long long steps = std::max<long long>(1, std::llround(speed_ * frame_seconds / dt));
    const auto t0 = std::chrono::steady_clock::now();
    for (long long k = 0; k < steps && playing_; ++k) {
        if (grabbed_ >= 0) sim_->state().v.col(grabbed_).setZero();
        safeStep();
        // Keep the frame interactive: at most 40 ms of stepping per frame (the simulation then runs slower than real time).
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > 0.04) break;
    }
    pushSample();
}

void App::pushSample() {
    if (!sim_) return;
    std::vector<Metric> m;
    try {
        m = sim_->metrics();
    } catch (const std::exception&) {
        return;
    }
    double energy = NAN, err = NAN;
    for (const Metric& x : m) {
        if (x.name == "energy") energy = x.value;
        const bool is_error = x.name == "error" || x.name.find("constraint") != std::string::npos ||
                              x.name.find("strain") != std::string::npos;
        if (is_error && std::isnan(err)) err = x.value, error_name_ = x.name, error_unit_ = x.unit;
    }
    if (std::isnan(err))
        for (const Metric& x : m)
            if (x.name == "energy_drift") err = x.value, error_name_ = "energy drift", error_unit_ = "J";
    if (!std::isnan(energy)) push(energy_, energy);
    if (!std::isnan(err)) push(error_, err);
    push(step_ms_, last_step_ms_);
    // The time the plots span: from the oldest sample kept to now.
    sample_t_.push_back(sim_->state().t);
    if (sample_t_.size() > kHistory) sample_t_.pop_front();
    plot_span_ = sample_t_.back() - sample_t_.front();
}

void App::handleMouse(int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    const double sx = io.DisplaySize.x > 0 ? width / io.DisplaySize.x : 1.0;
    const double sy = io.DisplaySize.y > 0 ? height / io.DisplaySize.y : 1.0;
    const double px = io.MousePos.x * sx, py = io.MousePos.y * sy;
    const bool over_ui = io.WantCaptureMouse && grabbed_ < 0 && !orbiting_;
    if (!over_ui) {
        if (io.MouseWheel != 0) cam_.zoom(std::pow(0.9, io.MouseWheel));
        const bool pin_key = !io.WantCaptureKeyboard && typedKey('p');
        if ((ImGui::IsMouseClicked(1) || pin_key) && sim_) {
            const int i = pickParticle(makeDrawData(*sim_), cam_, px, py, width, height, 14);
            if (i >= 0) {
                State& st = sim_->state();
                const bool pin = st.w[i] != 0.0;
                user_pins_[i] = pin;
                if (pin) st.w[i] = 0.0, st.v.col(i).setZero();
                else {
                    // Unpin with the mean inverse mass of the free particles (1/kg).
                    double sum = 0;
                    int n = 0;
                    for (int k = 0; k < st.size(); ++k)
                        if (st.w[k] > 0) sum += st.w[k], ++n;
                    st.w[i] = n ? sum / n : 1.0;
                }
                checks_.reset();  // the pins changed: the run checks start again (run.h)
            }
        }
        if (ImGui::IsMouseClicked(0)) {
            const int i = sim_ ? pickParticle(makeDrawData(*sim_), cam_, px, py, width, height, 14) : -1;
            if (i >= 0) {
                grabbed_ = i;
                grabbed_w_ = sim_->state().w[i];
                grab_depth_ = cam_.project(sim_->state().x.col(i), width, height).z();
            } else {
                orbiting_ = true;
            }
        }
    }
    if (grabbed_ >= 0 && sim_) {
        State& st = sim_->state();
        if (ImGui::IsMouseDown(0)) {
            st.x.col(grabbed_) = cam_.unproject(px, py, grab_depth_, width, height);
            st.v.col(grabbed_).setZero();
            st.w[grabbed_] = 0.0;  // held by the mouse: infinite mass while dragged
        } else {
            auto it = user_pins_.find(grabbed_);
            if (!(it != user_pins_.end() && it->second)) st.w[grabbed_] = grabbed_w_;
            grabbed_ = -1;
        }
    }
    if (orbiting_) {
        if (ImGui::IsMouseDown(0)) cam_.orbit(-io.MouseDelta.x * 0.008, io.MouseDelta.y * 0.008);
        else orbiting_ = false;
    }
    if (!io.WantCaptureKeyboard) {
        if (typedKey(' ')) playing_ = !playing_;
        if (typedKey('s')) stepOnce();
        if (typedKey('r')) rebuild(false);
    }
}

void App::frame(int width, int height) {
    const double frame_seconds = std::min(1.0 / 20, static_cast<double>(ImGui::GetIO().DeltaTime));
    advance(frame_seconds);
    if (playing_) wave_t_ += frame_seconds;
    DrawData d = currentDrawData();
    if (!camera_set_) {
        Vec3 lo, hi;
        drawBounds(d, lo, hi);
        // Leave room for the motion: a hanging cloth or chain swings below its pins.
        const double reach = (hi - lo).maxCoeff();
        bool pinned = false;
        for (int i = 0; i < d.w.size(); ++i) pinned = pinned || d.w[i] == 0;
        if (scene_.model != Model::Spring && pinned) lo.y() -= 0.5 * reach;
        const double panel = 360.0;
        cam_ = sceneCamera(scene_, lo, hi, double(width - panel) / height);
        // Shift the view so the scene sits in the part of the window right of the panel.
        const double shift = (panel / 2) / width * 2;  // in NDC
        const Vec3 right = (cam_.eye - cam_.target).cross(cam_.up).normalized() * -1;
        const double dist = (cam_.eye - cam_.target).norm();
        const double half_w = dist * std::tan(cam_.fovy * 3.14159265358979 / 360) * double(width) / height;
        cam_.target -= right * shift * half_w;
        cam_.eye -= right * shift * half_w;
        view_.ground_y = lo.y() - 0.05 * std::max(reach, 0.2);
        camera_set_ = true;
    }
    handleMouse(width, height);
    d = currentDrawData();
    renderer_.draw(d, cam_, view_, width, height);
    if (save_view_) {
        // The 3-D view without the panel, as drawn just now.
        save_view_ = false;
        const std::string name = "clothlab_view_" + std::to_string(++saved_) + ".png";
        try {
            writePng(name, readPixels(width, height));
            status_ = "saved " + (std::filesystem::current_path() / name).string();
        } catch (const std::exception& e) {
            message_ = std::string("error: ") + e.what();
        }
    }
    panel(width, height);
    drawOverlay(d, view_, 360.0f);
}

void App::panel(int /*width*/, int height) {
    const float scale = ImGui::GetIO().DisplaySize.y > 0 ? ImGui::GetIO().DisplaySize.y / height : 1.0f;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(340, height * scale - 16), ImGuiCond_Always);
    ImGui::Begin("clothlab", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(190);
    if (!message_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kRed);
        ImGui::TextWrapped("%s", message_.c_str());
        ImGui::PopStyleColor();
    }
    if (sim_ && checks_) {  // when the result is not a result (run.h): one line each, the whole sentence on hover
        RunResult r;
        checks_->collect(r);
        for (const RunWarning& w : r.warnings) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.42f, 0.0f, 1.0f));
            ImGui::TextWrapped("warning: %s", warningHeadline(w, scene_).c_str());
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", warningText(w, scene_).c_str());
        }
    }
    if (options_.wave_grid > 1)
        ImGui::TextWrapped("Benchmark: the view shows a %dx%d cloth moved by a travelling wave (no simulation).",
                           options_.wave_grid, options_.wave_grid);
    panelScene();
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) panelParameters();
    if (ImGui::CollapsingHeader("View")) panelView();
    if (ImGui::CollapsingHeader("Stages", ImGuiTreeNodeFlags_DefaultOpen)) panelStages();
    if (ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) panelPlots();
    ImGui::Separator();
    ImGui::TextDisabled("left drag: particle / orbit   wheel: zoom");
    ImGui::TextDisabled("right click or P: pin/unpin   space: play");
    ImGui::PopItemWidth();
    ImGui::End();
}

void App::panelScene() {
    namespace fs = std::filesystem;
    const std::string current = fs::path(scene_path_).filename().string();
    if (ImGui::BeginCombo("scene", current.c_str())) {
        for (const std::string& s : scenes_)
            if (ImGui::Selectable(fs::path(s).filename().string().c_str(), s == scene_path_)) load(s);
        ImGui::EndCombo();
    }
    if (!scene_.description.empty()) ImGui::TextWrapped("%s", scene_.description.c_str());
    if (ImGui::BeginCombo("method", methodName(scene_.solver.method))) {
        for (Method m : allMethods())
            if (ImGui::Selectable(methodName(m), m == scene_.solver.method)) {
                scene_.solver.method = m;
                rebuild(true);
            }
        ImGui::EndCombo();
    }
    if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
    ImGui::SameLine();
    if (ImGui::Button("Step")) stepOnce();
    ImGui::SameLine();
    if (ImGui::Button("Reset")) rebuild(false);
    ImGui::SameLine();
    if (ImGui::Button("Save PNG")) save_view_ = true;
    ImGui::SameLine();
    ImGui::Text("t = %.3f s", sim_ ? sim_->state().t : 0.0);
    if (!status_.empty()) ImGui::TextDisabled("%s", status_.c_str());
    float sp = static_cast<float>(speed_);
    if (ImGui::SliderFloat("speed", &sp, 0.01f, 2.0f, "%.2fx", ImGuiSliderFlags_Logarithmic)) speed_ = sp;
    if (sim_) {
        const bool constraints = isPositionBased(scene_.solver.method);
        ImGui::Text("%s, %s, step %s", count(static_cast<size_t>(sim_->state().size()), "particle", "particles").c_str(),
                    count(sim_->edges().size(), constraints ? "constraint edge" : "spring", constraints ? "constraint edges" : "springs").c_str(),
                    duration(last_step_ms_).c_str());
    }
}

void App::panelParameters() {
    bool changed = false;
    SolverSpec& sv = scene_.solver;
    ImGui::PushItemWidth(140);  // room beside each slider for its value and unit
    changed |= sliderD("dt [s]", sv.dt, 1e-5, 0.05, "%.5f", true);
    const bool position_based = isPositionBased(sv.method);
    if (position_based) {
        ImGui::SliderInt("iterations", &sv.iterations, 1, 100);
        changed |= ImGui::IsItemDeactivatedAfterEdit();
        ImGui::SliderInt("substeps", &sv.substeps, 1, 50);
        changed |= ImGui::IsItemDeactivatedAfterEdit();
    }
    if (scene_.model == Model::Spring) {
        changed |= sliderD("k [N/m]", scene_.spring.k, 1, 1e4, "%.1f", true);
        changed |= sliderD("kd [Ns/m]", scene_.spring.kd, 0, 10, "%.3f");
    } else if (scene_.model == Model::Chain) {
        changed |= sliderD("k [N/m]", scene_.chain.k, 1, 1e5, "%.1f", true);
        changed |= sliderD("kd [Ns/m]", scene_.chain.kd, 0, 10, "%.3f");
    } else {
        struct G { const char* name; SpringGroup* g; } groups[] = {{"structural", &scene_.springs.structural},
                                                              {"shear", &scene_.springs.shear},
                                                              {"bending", &scene_.springs.bending}};
        if (!position_based)
            for (auto& [name, g] : groups) {
                ImGui::PushID(name);
                changed |= ImGui::Checkbox("##on", &g->enabled);
                ImGui::SameLine();
                ImGui::SetNextItemWidth(155);
                changed |= sliderD((std::string(name) + " k").c_str(), g->k, 1, 1e5, "%.0f", true);
                ImGui::PopID();
            }
        if (!position_based) {
            changed |= ImGui::Checkbox("Provot", &scene_.provot.enabled);
            ImGui::SameLine();
            ImGui::SetNextItemWidth(110);
            double pct = scene_.provot.max_strain * 100;
            changed |= sliderD("tau [%]", pct, 0.1, 50, "%.1f", true);
            scene_.provot.max_strain = pct / 100;
        }
        struct C { const char* name; ConstraintGroup* g; } cons[] = {{"distance", &scene_.constraints.distance},
                                                                 {"bending", &scene_.constraints.bending}};
        if (position_based)
            for (auto& [name, g] : cons) {
                ImGui::PushID(name);
                changed |= ImGui::Checkbox("##on", &g->enabled);
                ImGui::SameLine();
                ImGui::SetNextItemWidth(155);
                if (sv.method == Method::Xpbd) changed |= sliderD((std::string(name) + " alpha").c_str(), g->compliance, 0, 1e-2, "%.2e");
                else changed |= sliderD((std::string(name) + " k").c_str(), g->stiffness, 0, 1, "%.3f");
                ImGui::PopID();
            }
        if (position_based) {  // stage 07: the cloth against itself
            changed |= ImGui::Checkbox("##self", &scene_.self_collision.enabled);
            ImGui::SameLine();
            ImGui::SetNextItemWidth(155);
            changed |= sliderD("self-collision h [m]", scene_.self_collision.thickness, 0.002, 0.1, "%.3f", true);
        }
    }
    // Two quantities, two sliders: the air damping force (every method) and dampVelocities' k_damping (pbd, xpbd).
    changed |= sliderD("air damping [Ns/m]", scene_.forces.air_damping, 0, 5.0, "%.3f");
    if (position_based) changed |= sliderD("k_damping [1]", scene_.pbd.damping, 0, 1.0, "%.3f");
    float wind[3] = {float(scene_.forces.wind.x()), float(scene_.forces.wind.y()), float(scene_.forces.wind.z())};
    ImGui::SliderFloat3("wind [m/s]", wind, -20, 20, "%.1f");
    if (ImGui::IsItemActive() || ImGui::IsItemDeactivatedAfterEdit()) scene_.forces.wind = Vec3(wind[0], wind[1], wind[2]);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    for (size_t i = 0; i < all_colliders_.size(); ++i) {
        const Collider& c = all_colliders_[i];
        const std::string label = std::string(colliderTypeName(c.type)) + " " + std::to_string(i);
        bool on = collider_on_[i];
        if (ImGui::Checkbox(label.c_str(), &on)) collider_on_[i] = on, changed = true;
        if (i + 1 < all_colliders_.size()) ImGui::SameLine();
    }
    ImGui::PopItemWidth();
    if (changed) rebuild(true);
}

void App::panelView() {
    ImGui::Checkbox("surface", &view_.surface);
    ImGui::SameLine();
    ImGui::Checkbox("edges", &view_.edges);
    ImGui::SameLine();
    ImGui::Checkbox("by strain", &view_.color_by_strain);
    for (int k = 0; k < 4; ++k) {
        ImGui::Checkbox(edgeKindName(static_cast<EdgeKind>(k)), &view_.show_kind[k]);
        if (k < 3) ImGui::SameLine();
    }
    ImGui::Checkbox("particles", &view_.particles);
    ImGui::SameLine();
    ImGui::Checkbox("colliders", &view_.colliders);
    ImGui::SameLine();
    ImGui::Checkbox("ground", &view_.ground);
    ImGui::SameLine();
    ImGui::Checkbox("legend", &view_.legend);
    float range = static_cast<float>(view_.strain_range * 100);
    if (ImGui::SliderFloat("strain range", &range, 0.1f, 50.0f, "%.1f %%", ImGuiSliderFlags_Logarithmic))
        view_.strain_range = range / 100;
    if (ImGui::Button("Fit camera")) camera_set_ = false;
}

void App::panelStages() {
    if (stages_.empty()) ImGui::TextDisabled("(no stage information in this build)");
    const int hit = stageOfMessage(stub_hit_);
    for (const StageInfo& s : stages_) {
        ImGui::Text("%-14s", s.dir.c_str());
        ImGui::SameLine(150);
        if (s.reference) ImGui::TextColored(ImVec4(0.2f, 0.55f, 0.25f, 1), "reference");
        else ImGui::TextColored(ImVec4(0.2f, 0.4f, 0.85f, 1), "student");
        if (hit > 0 && std::atoi(s.dir.c_str()) == hit) {
            ImGui::PushStyleColor(ImGuiCol_Text, kRed);
            ImGui::TextWrapped("  %s", stub_hit_.c_str());
            ImGui::PopStyleColor();
            ImGui::TextWrapped("%s", stubAdvice(stub_hit_).c_str());  // what to do, in this copy
        }
    }
}

void App::panelPlots() {
    const double t1 = sim_ ? sim_->state().t : 0.0, t0 = std::max(0.0, t1 - plot_span_);
    plot("energy", energy_, "J", t0, t1);
    plot(error_name_.empty() ? "error" : error_name_.c_str(), error_, error_unit_.c_str(), t0, t1);
    plot("step time", step_ms_, "ms", t0, t1);
}

}  // namespace clothlab
