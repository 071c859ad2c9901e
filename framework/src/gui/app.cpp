// The interactive app: runs + 3-D views + Dear ImGui panels (platform-free).
#include "clothlab/gui/app.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "clothlab/core/grid.h"
#include "clothlab/core/input_error.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/core/stub_advice.h"
#include "clothlab/gui/plots.h"
#include "clothlab/io/scene_json.h"
#include "clothlab/render/overlay.h"
#include "clothlab/sim/run.h"

namespace clothlab {

namespace {
constexpr size_t kHistory = 600;  // samples each plot shows (the last ones)
constexpr float kPanelWidth = 340.0f;  // the panel; the views start right of it
constexpr double kFrameRate = 30.0;    // frames per second the stepping leaves room for
const ImVec4 kRed(0.85f, 0.15f, 0.12f, 1.0f);
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Whether the key for character c (lower case) was typed this frame, in either case. The app reads
// typed characters, which Dear ImGui has queued the same way in every release Debian ships (1.86 in
// Debian 12, 1.90 in Debian 13), instead of key codes, whose API changed between those releases.
bool typedKey(char c) {
    for (const ImWchar ch : ImGui::GetIO().InputQueueCharacters)
        if (ch == static_cast<ImWchar>(c) || ch == static_cast<ImWchar>(std::toupper(static_cast<unsigned char>(c)))) return true;
    return false;
}

// "2.5 us", "1.20 ms", "0.31 s": a duration in the unit that shows it.
std::string duration(double ms) {
    char b[32];
    if (!std::isfinite(ms)) return "-";
    if (ms < 0.1) std::snprintf(b, sizeof b, "%.3g us", ms * 1e3);
    else if (ms < 1000) std::snprintf(b, sizeof b, "%.3g ms", ms);
    else std::snprintf(b, sizeof b, "%.3g s", ms / 1e3);
    return b;
}

// A measure's value with its unit ("0.0123", "1.2e-05 m", "-0.31 J"); a fraction (unit 1) has none.
std::string withUnit(double v, const std::string& unit) {
    char b[48];
    std::snprintf(b, sizeof b, "%.3g", v);
    return std::string(b) + (unit == "1" || unit.empty() ? "" : " " + unit);
}

// "1 spring", "3 springs".
std::string count(size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

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

// The colour of run i (compareColor()) for ImGui.
ImU32 runColor(size_t i, int alpha = 255) {
    unsigned r = 0, g = 0, b = 0;
    std::sscanf(compareColor(i), "#%02x%02x%02x", &r, &g, &b);
    return IM_COL32(r, g, b, alpha);
}

// A filled square in run i's colour at the cursor, then the text on the same line.
void swatch(size_t i) {
    const float s = ImGui::GetTextLineHeight();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + s - 4, p.y + s - 2), runColor(i), 2);
    ImGui::Dummy(ImVec2(s - 2, s));
    ImGui::SameLine();
}

const char* kRunWindow = "clothlab";
const char* kPlotWindow = "comparison plots";
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
    st.AntiAliasedLinesUseTex = false;  // only glyphs use the font texture: clippedText() finds cut text by it
    st.AntiAliasedFill = false;  // rounded corners without a blended fringe: less for llvmpipe to draw (docs/performance.md)
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini next to the user's files
    // A readable font when Debian's fonts-dejavu-core is installed; else ImGui's built-in one.
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if (io.Fonts->Fonts.empty() && std::filesystem::exists(font)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
}

std::vector<std::string> clippedText(const char* window) {
    std::vector<std::string> cut;
    const ImDrawData* dd = ImGui::GetDrawData();
    if (!dd) return cut;
    const ImVec2 white = ImGui::GetIO().Fonts->TexUvWhitePixel;
    const size_t n = std::strlen(window);
    for (int l = 0; l < dd->CmdListsCount; ++l) {
        const ImDrawList* dl = dd->CmdLists[l];
        const char* owner = dl->_OwnerName ? dl->_OwnerName : "";
        if (std::strncmp(owner, window, n) != 0 || (owner[n] != '\0' && owner[n] != '/')) continue;
        for (const ImDrawCmd& cmd : dl->CmdBuffer) {
            if (cmd.UserCallback) continue;
            for (unsigned e = 0; e < cmd.ElemCount; ++e) {
                const ImDrawVert& v = dl->VtxBuffer[static_cast<int>(cmd.VtxOffset + dl->IdxBuffer[static_cast<int>(cmd.IdxOffset + e)])];
                if (v.uv.x == white.x && v.uv.y == white.y) continue;  // a shape, not a glyph
                if (v.pos.x > cmd.ClipRect.z + 0.5f || v.pos.x < cmd.ClipRect.x - 0.5f) {
                    cut.push_back(std::to_string(static_cast<int>(v.pos.x)) + " " + std::to_string(static_cast<int>(v.pos.y)));
                    break;
                }
            }
        }
    }
    return cut;
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
    renderer_.setTiming(options_.timing, options_.cpu_clock);
    if (!options_.compare.empty() && options_.scene.empty())
        throw InputError("command line", "--compare", "needs a scene file, e.g. ./lab gui scenes/pbd_sphere.json --compare pbd,xpbd");
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
    const bool first = scene_path_.empty();
    scene_path_ = path;
    scene_ = original_;
    all_colliders_ = original_.colliders;
    collider_on_.assign(all_colliders_.size(), 1);
    user_pins_.clear();
    if (first && !options_.compare.empty()) {
        variants_ = parseCompare(options_.compare, path, options_.sets);  // a bad list: InputError out of the constructor
    } else if (variants_.size() > 1) {
        // Another scene in the picker: the same methods side by side, each with this scene's solver.
        for (CompareVariant& v : variants_) {
            const Method m = v.solver.method;
            v.solver = original_.solver;
            v.solver.method = m;
            v.label = compareLabel(v.solver, original_.solver);
        }
    } else {
        variants_ = {{methodName(original_.solver.method), original_.solver}};
    }
    camera_set_ = false;
    view_.color_by_strain = options_.strain;
    view_.edges = options_.strain ? true : options_.edges < 0 ? (scene_.model != Model::Cloth && options_.wave_grid < 2) : options_.edges == 1;
    rebuild(false);
    return true;
}

void App::rebuild(bool keep_state) {
    std::vector<CompareRun> old;
    if (cmp_) old = std::move(cmp_->runs());
    scene_.colliders.clear();
    for (size_t i = 0; i < all_colliders_.size(); ++i)
        if (collider_on_[i]) scene_.colliders.push_back(all_colliders_[i]);
    message_.clear();
    grabbed_ = -1;
    scene_.solver = variants_.front().solver;  // the single run's solver is the scene's
    cmp_ = std::make_unique<Comparison>(scene_, variants_, options_.factory);
    for (size_t i = 0; i < cmp_->runs().size(); ++i) {
        CompareRun& r = cmp_->runs()[i];
        if (!r.sim) {
            if (r.message.rfind("not implemented:", 0) == 0) stub_hit_ = r.message;
            else r.message = "not available: " + r.message;
            if (!compareMode()) message_ = r.message;
            continue;
        }
        State& st = r.sim->state();
        if (keep_state && i < old.size() && old[i].sim && old[i].sim->state().size() == st.size()) {
            st.x = old[i].sim->state().x;
            st.v = old[i].sim->state().v;
            st.t = old[i].sim->state().t;
            r.samples = std::move(old[i].samples);
            r.steps = old[i].steps;
        }
        for (const auto& [k, pinned] : user_pins_)
            if (k < st.size()) {
                if (pinned) st.w[k] = 0.0;
                else if (st.w[k] == 0.0) st.w[k] = 1.0;
            }
    }
    target_t_ = keep_state ? cmp_->time() : 0.0;
    if (!keep_state) cmp_->sample();  // the plots start at t = 0
}

const Simulation* App::simulation() const { return cmp_ && !cmp_->runs().empty() ? cmp_->runs().front().sim.get() : nullptr; }

Viewport App::viewport(size_t i) const { return i < views_.size() ? views_[i] : Viewport{}; }

std::vector<std::string> App::warnings() const {
    std::vector<std::string> out;
    if (!cmp_) return out;
    for (const CompareRun& r : cmp_->runs()) {
        if (!r.sim || !r.checks) continue;
        RunResult res;
        r.checks->collect(res);
        for (const RunWarning& w : res.warnings)
            out.push_back("warning: " + warningText(w, r.scene) + (compareMode() ? " (run " + r.variant.label + ")" : ""));
    }
    return out;
}

DrawData App::drawData(size_t i) const {
    if (options_.wave_grid > 1) return waveCloth(options_.wave_grid, wave_t_);
    const CompareRun* r = cmp_ && i < cmp_->runs().size() ? &cmp_->runs()[i] : nullptr;
    DrawData d = r && r->sim ? makeDrawData(*r->sim) : makeDrawData(scene_);
    if (compareMode() && r) d.title = r->variant.label;
    return d;
}

void App::guarded(const std::function<void()>& step) {
    try {
        step();
    } catch (const NotImplemented& e) {  // a stub: pause and name the task (and its stage, panelStages())
        message_ = e.what();
        stub_hit_ = e.what();
        playing_ = false;
    } catch (const std::exception& e) {
        message_ = std::string("error: ") + e.what();
        playing_ = false;
    }
}

void App::stepOnce() {
    endFrame();
    if (!cmp_) return;
    guarded([this] {
        for (size_t i = 0; i < cmp_->runs().size(); ++i) cmp_->stepRun(i);
    });
    cmp_->sample();
}

void App::advance(double frame_seconds) {
    if (!playing_ || !cmp_) return;
    bool running = false;
    for (const CompareRun& r : cmp_->runs()) running = running || !r.stopped();
    if (!running) return;
    // The runs go to a common simulated time; a frame that cannot step that far leaves them behind
    // real time, together.
    target_t_ = std::min(target_t_, cmp_->time()) + speed_ * frame_seconds;
    // The stepping gets what is left of a frame at 30 fps after the rest of the last frames took theirs
    // (at least 5 ms, at most 40 ms): a scene too costly to step in real time runs slower, at 30 fps.
    const double budget = options_.step_budget > 0 ? options_.step_budget : std::clamp((1000.0 / kFrameRate - other_ms_) / 1e3, 0.005, 0.04);
    // One step may outlast what the frame allows (a step is never cut): the next frames pay the excess
    // back from their budgets (SteppingDebt), so a scene with long steps still draws at 30 fps, its runs
    // slower.
    const double allowed = options_.step_budget > 0 ? budget : debt_.allow(budget);
    if (allowed <= 0) return;
    const auto start = Clock::now();
    guarded([&] {
        cmp_->advanceTo(target_t_, allowed, [this](CompareRun& r) {
            if (grabbed_ < 0 || &r != &cmp_->runs()[static_cast<size_t>(grabbed_run_)]) return;
            r.sim->state().v.col(grabbed_).setZero();
            r.checks.reset();  // the user moving a particle puts energy in and particles anywhere: the checks start again
        });
    });
    if (options_.step_budget <= 0) debt_.settle(std::chrono::duration<double>(Clock::now() - start).count(), allowed);
    if (!compareMode() && !cmp_->runs().empty() && cmp_->runs().front().message.rfind("unstable", 0) == 0 && message_.empty()) {
        message_ = cmp_->runs().front().message + ": reduce dt or stiffness, then Reset";
        playing_ = false;
    }
    cmp_->sample();
}

void App::layout(int width, int height) {
    views_.clear();
    const size_t n = cmp_ ? std::max<size_t>(1, cmp_->runs().size()) : 1;
    if (!compareMode()) {
        views_.push_back({0, 0, width, height});
        plots_rect_ = {};
        return;
    }
    // Right of the panel: the views on top (2 or 3 in a row, 4 as 2 x 2), the plots below.
    const int left = static_cast<int>(kPanelWidth) + 16, gap = 4;
    const int plots = std::clamp(static_cast<int>(0.36 * height), 200, 330);
    plots_rect_ = {left, height - plots, width - left, plots};
    const int cols = n == 4 ? 2 : static_cast<int>(n), rows = n == 4 ? 2 : 1;
    const int w = (width - left - gap * (cols - 1)) / cols, h = (height - plots - gap * rows) / rows;
    for (size_t i = 0; i < n; ++i)
        views_.push_back({left + static_cast<int>(i % cols) * (w + gap), static_cast<int>(i / cols) * (h + gap), w, h});
}

void App::fitCamera(int width, int height) {
    const DrawData d = drawData(0);
    Vec3 lo, hi;
    drawBounds(d, lo, hi);
    // The ground a cloth falls onto (a plane collider facing up, below it) is in view, and the ground is
    // drawn there: else a cloth dropped from high up (pbd_bounce) falls out of the view, through a
    // ground drawn just below its start.
    double plane_y = std::nan("");
    for (const Collider& c : d.colliders)
        if (c.type == Collider::Type::Plane && c.normal.y() > 0.99 && c.point.y() < lo.y() && !(c.point.y() < plane_y))
            plane_y = c.point.y();
    if (std::isfinite(plane_y)) lo.y() = plane_y;
    // Leave room for the motion: a hanging cloth or chain swings below its pins.
    const double reach = (hi - lo).maxCoeff();
    bool pinned = false;
    for (int i = 0; i < d.w.size(); ++i) pinned = pinned || d.w[i] == 0;
    if (scene_.model != Model::Spring && pinned) lo.y() -= 0.5 * reach;
    view_.ground_y = std::isfinite(plane_y) ? plane_y : lo.y() - 0.05 * std::max(reach, 0.2);
    camera_set_ = true;
    if (compareMode()) {
        cam_ = sceneCamera(scene_, lo, hi, double(views_[0].width) / std::max(1, views_[0].height));
        return;
    }
    const double panel = 360.0;
    cam_ = sceneCamera(scene_, lo, hi, double(width - panel) / height);
    // Shift the view so the scene sits in the part of the window right of the panel.
    const double shift = (panel / 2) / width * 2;  // in NDC
    const Vec3 right = (cam_.eye - cam_.target).cross(cam_.up).normalized() * -1;
    const double dist = (cam_.eye - cam_.target).norm();
    const double half_w = dist * std::tan(cam_.fovy * 3.14159265358979 / 360) * double(width) / height;
    cam_.target -= right * shift * half_w;
    cam_.eye -= right * shift * half_w;
}

int App::runAt(double px, double py) const {
    for (size_t i = 0; i < views_.size(); ++i) {
        const Viewport& v = views_[i];
        if (px >= v.x && px < v.x + v.width && py >= v.y && py < v.y + v.height) return static_cast<int>(i);
    }
    return -1;
}

void App::handleMouse(int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    const double sx = io.DisplaySize.x > 0 ? width / io.DisplaySize.x : 1.0;
    const double sy = io.DisplaySize.y > 0 ? height / io.DisplaySize.y : 1.0;
    const double px = io.MousePos.x * sx, py = io.MousePos.y * sy;
    const bool over_ui = io.WantCaptureMouse && grabbed_ < 0 && !orbiting_;
    const int at = runAt(px, py);
    const auto simOf = [&](int i) -> Simulation* {
        return cmp_ && i >= 0 && static_cast<size_t>(i) < cmp_->runs().size() ? cmp_->runs()[static_cast<size_t>(i)].sim.get() : nullptr;
    };
    // A particle of run i under the cursor (-1: none), picked in its own view.
    const auto pick = [&](int i) {
        if (!simOf(i)) return -1;
        const Viewport& v = views_[static_cast<size_t>(i)];
        return pickParticle(makeDrawData(*simOf(i)), cam_, px - v.x, py - v.y, v.width, v.height, 14);
    };
    if (!over_ui && at >= 0) {
        if (io.MouseWheel != 0) cam_.zoom(std::pow(0.9, io.MouseWheel));
        const bool pin_key = !io.WantCaptureKeyboard && typedKey('p');
        if (ImGui::IsMouseClicked(1) || pin_key) {
            const int k = pick(at);
            if (k >= 0) {
                const bool pin = simOf(at)->state().w[k] != 0.0;
                user_pins_[k] = pin;
                for (CompareRun& r : cmp_->runs()) {  // every copy of the scene: they stay identical
                    if (!r.sim || k >= r.sim->state().size()) continue;
                    State& st = r.sim->state();
                    if (pin) st.w[k] = 0.0, st.v.col(k).setZero();
                    else {
                        // Unpin with the mean inverse mass of the free particles (1/kg).
                        double sum = 0;
                        int n = 0;
                        for (int j = 0; j < st.size(); ++j)
                            if (st.w[j] > 0) sum += st.w[j], ++n;
                        st.w[k] = n ? sum / n : 1.0;
                    }
                    r.checks.reset();  // the pins changed: the run checks start again (run.h)
                }
            }
        }
        if (ImGui::IsMouseClicked(0)) {
            const int k = pick(at);
            if (k >= 0) {
                grabbed_ = k;
                grabbed_run_ = at;
                grabbed_w_ = simOf(at)->state().w[k];
                const Viewport& v = views_[static_cast<size_t>(at)];
                grab_depth_ = cam_.project(simOf(at)->state().x.col(k), v.width, v.height).z();
            } else {
                orbiting_ = true;
            }
        }
    }
    Simulation* held = grabbed_ >= 0 ? simOf(grabbed_run_) : nullptr;
    if (held) {
        State& st = held->state();
        const Viewport& v = views_[static_cast<size_t>(grabbed_run_)];
        if (ImGui::IsMouseDown(0)) {
            st.x.col(grabbed_) = cam_.unproject(px - v.x, py - v.y, grab_depth_, v.width, v.height);
            st.v.col(grabbed_).setZero();
            st.w[grabbed_] = 0.0;  // held by the mouse: infinite mass while dragged
        } else {
            auto it = user_pins_.find(grabbed_);
            if (!(it != user_pins_.end() && it->second)) st.w[grabbed_] = grabbed_w_;
            grabbed_ = -1;
        }
    } else {
        grabbed_ = -1;
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
    endFrame();  // the last frame's stepping, if the caller has not waited for it
    width_ = width, height_ = height;
    auto t0 = Clock::now();
    if (frames_ > 0) {  // the last frame: how long it took besides stepping, how fast the runs went
        const double interval = std::chrono::duration<double, std::milli>(t0 - last_frame_).count();
        other_ms_ = frames_ == 1 ? interval - simulate_ms_ : 0.9 * other_ms_ + 0.1 * std::max(0.0, interval - simulate_ms_);
        // Over the last frame: the simulated time the runs advanced against what the frame asked for
        // (speed x the frame's time step, ImGui's DeltaTime: the wall time between frames in a window).
        const double advanced = cmp_ ? cmp_->time() - last_time_ : 0.0;
        if (playing_ && asked_ > 0) realtime_ = 0.9 * realtime_ + 0.1 * speed_ * advanced / asked_;  // a step may pass the frame's time: no cap here
    }
    last_frame_ = t0;
    last_time_ = cmp_ ? cmp_->time() : 0.0;
    ++frames_;
    layout(width, height);
    if (!camera_set_) fitCamera(width, height);
    handleMouse(width, height);
    // The panel and the picture show the runs as they are; then the runs step, on a second thread
    // while the GL draws (AppOptions::step_beside_drawing, until endFrame()), else here.
    const auto cpu = [this] { return options_.timing && options_.cpu_clock ? 1e3 * options_.cpu_clock() : 0.0; };
    double c0 = cpu();
    t0 = Clock::now();
    std::vector<DrawData> shown;
    for (size_t i = 0; i < views_.size(); ++i) shown.push_back(drawData(i));
    timings_.draw_data += msSince(t0);
    t0 = Clock::now();
    c0 = cpu();
    panel(width, height);
    if (compareMode()) {
        comparePlots(width, height);
        drawLabels();
    } else {
        label_boxes_.clear();
        drawOverlay(shown.front(), view_, 360.0f);
    }
    timings_.panel += msSince(t0);
    timings_.cpu_panel += cpu() - c0;
    const double frame_seconds = std::min(1.0 / 20, static_cast<double>(ImGui::GetIO().DeltaTime));
    asked_ = speed_ * frame_seconds;
    if (playing_) wave_t_ += frame_seconds;
    const auto step = [this, frame_seconds, cpu] {
        const double c = cpu();
        const auto start = Clock::now();
        advance(frame_seconds);
        simulate_ms_ = msSince(start);
        timings_.simulate += simulate_ms_;
        timings_.cpu_simulate += cpu() - c;
    };
    // (Not beside a "Save PNG": its error goes to message_, which a failing step writes too.)
    if (options_.step_beside_drawing && !options_.timing && !save_view_) stepping_ = std::async(std::launch::async, step);
    else step();
    c0 = cpu();
    t0 = Clock::now();
    if (compareMode()) renderer_.clear(width, height);  // between and beside the views too
    for (size_t i = 0; i < views_.size(); ++i) renderer_.draw(shown[i], cam_, view_, views_[i], height);
    timings_.draw += msSince(t0);
    timings_.cpu_draw += cpu() - c0;
    if (save_view_) {
        // The 3-D views without the panel, as drawn just now.
        save_view_ = false;
        const std::string name = "clothlab_view_" + std::to_string(++saved_) + ".png";
        try {
            writePng(name, readPixels(width, height));
            status_ = "saved " + (std::filesystem::current_path() / name).string();
            wrote(name);
        } catch (const std::exception& e) {
            message_ = std::string("error: ") + e.what();
        }
    }
    // The panel's and the plots' backgrounds as cleared rectangles: ImGui draws them without its own
    // (a blended, textured fill of every pixel, the largest part of its cost on llvmpipe).
    const float scale = ImGui::GetIO().DisplaySize.y > 0 ? height / ImGui::GetIO().DisplaySize.y : 1.0f;
    const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const Eigen::Vector3f panel_rgb(bg.x, bg.y, bg.z);
    renderer_.fill({static_cast<int>(8 * scale), static_cast<int>(8 * scale), static_cast<int>(kPanelWidth * scale),
                    static_cast<int>(height - 16 * scale)},
                   height, panel_rgb);
    if (compareMode()) renderer_.fill(plots_rect_, height, panel_rgb);
    ++timings_.frames;
}

void App::endFrame() {
    if (stepping_.valid()) stepping_.get();
}

App::~App() { endFrame(); }

void App::resetTimings() {
    timings_ = AppTimings{};
    renderer_.resetTimes();
}

void App::panel(int /*width*/, int height) {
    const float scale = ImGui::GetIO().DisplaySize.y > 0 ? ImGui::GetIO().DisplaySize.y / height : 1.0f;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, height * scale - 16), ImGuiCond_Always);
    ImGui::Begin(kRunWindow, nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground);
    controls_.clear();
    ImGui::PushItemWidth(190);
    if (!message_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kRed);
        ImGui::TextWrapped("%s", message_.c_str());
        ImGui::PopStyleColor();
    }
    if (cmp_)  // when the result is not a result (run.h): one line each, the whole sentence on hover
        for (const CompareRun& r : cmp_->runs()) {
            if (!r.sim || !r.checks) continue;
            RunResult res;
            r.checks->collect(res);
            for (const RunWarning& w : res.warnings) {
                ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.42f, 0.0f, 1.0f));
                ImGui::TextWrapped("warning%s: %s", compareMode() ? (" (" + r.variant.label + ")").c_str() : "",
                                   warningHeadline(w, r.scene).c_str());
                ImGui::PopStyleColor();
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", warningText(w, r.scene).c_str());
            }
        }
    if (options_.wave_grid > 1)
        ImGui::TextWrapped("Benchmark: the view shows a %dx%d cloth moved by a travelling wave (no simulation).",
                           options_.wave_grid, options_.wave_grid);
    panelScene();
    if (compareMode() && ImGui::CollapsingHeader("Runs side by side", ImGuiTreeNodeFlags_DefaultOpen)) panelRuns();
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) panelParameters();
    if (ImGui::CollapsingHeader("View")) panelView();
    // Open when it has news: a stage runs the student's code, or a stub was hit.
    const bool student = std::any_of(stages_.begin(), stages_.end(), [](const StageInfo& s) { return !s.reference; });
    if (!stub_hit_.empty()) ImGui::SetNextItemOpen(true, ImGuiCond_Always);
    if (ImGui::CollapsingHeader("Stages", student && !compareMode() ? ImGuiTreeNodeFlags_DefaultOpen : 0)) panelStages();
    if (!compareMode() && ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) panelPlots();
    ImGui::Separator();
    ImGui::TextDisabled("left drag: particle / orbit   wheel: zoom");
    ImGui::TextDisabled("right click or P: pin/unpin   space: play");
    ImGui::PopItemWidth();
    panel_scrolls_ = ImGui::GetScrollMaxY() > 0;
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
    if (!scene_.view.look.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.10f, 0.35f, 0.65f, 1.0f));
        ImGui::TextWrapped("Look at: %s", scene_.view.look.c_str());
        ImGui::PopStyleColor();
    }
    if (!compareMode()) {
        const ImVec2 at = ImGui::GetCursorScreenPos();  // the combo's box (once open, the last item is its popup's)
        const ImVec2 end(at.x + ImGui::CalcItemWidth(), at.y + ImGui::GetFrameHeight());
        const bool open = ImGui::BeginCombo("method", methodName(variants_.front().solver.method));
        rememberControl("method", at, end);
        if (open) {
            for (Method m : allMethods()) {
                if (ImGui::Selectable(methodName(m), m == variants_.front().solver.method)) {
                    variants_.front().solver.method = m;
                    variants_.front().label = methodName(m);
                    rebuild(true);
                }
                rememberControl(std::string("method=") + methodName(m));
            }
            ImGui::EndCombo();
        }
    }
    if (ImGui::Button(playing_ ? "Pause" : "Play")) playing_ = !playing_;
    rememberControl("play");
    ImGui::SameLine();
    if (ImGui::Button("Step")) stepOnce();
    rememberControl("step");
    ImGui::SameLine();
    if (ImGui::Button("Reset")) rebuild(false);
    rememberControl("reset");
    ImGui::SameLine();
    ImGui::Text("t = %.3f s", cmp_ ? cmp_->time() : 0.0);
    if (ImGui::Button("Save PNG")) save_view_ = true;
    rememberControl("save_png");
    ImGui::SameLine();
    if (ImGui::Button("Export CSV + PNG")) exportFigures(options_.out_dir + "/clothlab_compare_" + std::to_string(++exported_));
    rememberControl("export");
    if (variants_.size() < static_cast<size_t>(kCompareMax)) {
        ImGui::SameLine();
        if (ImGui::Button(compareMode() ? "+ run" : "+ compare")) {
            variants_.push_back(variants_.back());
            camera_set_ = false;
            rebuild(false);
        }
        rememberControl("compare");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Run a copy of this scene side by side, started, paused and reset together");
    }
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
    float sp = static_cast<float>(speed_);
    if (ImGui::SliderFloat("speed", &sp, 0.01f, 2.0f, "%.2f x real time", ImGuiSliderFlags_Logarithmic)) speed_ = sp;
    if (playing_ && frames_ > 30 && realtime_ < 0.9 * speed_)  // the stepping does not keep up: say so
        ImGui::TextWrapped("runs at %.2f x real time (the steps take longer than the frame allows)", realtime_);
    const Simulation* sim = simulation();
    if (sim && !compareMode()) {
        const bool constraints = isPositionBased(variants_.front().solver.method);
        ImGui::TextWrapped("%s, %s", count(static_cast<size_t>(sim->state().size()), "particle", "particles").c_str(),
                           count(sim->edges().size(), constraints ? "constraint edge" : "spring", constraints ? "constraint edges" : "springs").c_str());
        const CompareRun& r = cmp_->runs().front();
        const std::string& kernel = r.scene.solver.kernel;  // a registered faster kernel (sim/kernel_registry.h): say so
        ImGui::Text("step %s%s", duration(r.samples.empty() ? NAN : r.samples.back().step_ms).c_str(),
                    constraints && kernel != "exercise" ? (", " + kernel + " kernel").c_str() : "");
    }
    if (!options_.platform_note.empty()) ImGui::TextWrapped("%s", options_.platform_note.c_str());
}

void App::panelRuns() {
    int remove = -1;
    bool changed = false;
    const float avail = ImGui::GetContentRegionAvail().x;
    for (size_t i = 0; i < cmp_->runs().size(); ++i) {
        CompareRun& r = cmp_->runs()[i];
        CompareVariant& v = variants_[i];
        ImGui::PushID(static_cast<int>(i));
        swatch(i);
        ImGui::TextWrapped("%s", v.label.c_str());
        ImGui::SameLine(avail - 14);
        if (ImGui::SmallButton("x")) remove = static_cast<int>(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this run");
        const float combo = 170;  // "symplectic_euler" and its arrow
        ImGui::SetNextItemWidth(combo);
        if (ImGui::BeginCombo("##method", methodName(v.solver.method))) {
            for (Method m : allMethods())
                if (ImGui::Selectable(methodName(m), m == v.solver.method)) v.solver.method = m, changed = true;
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(avail - combo - ImGui::GetStyle().ItemSpacing.x);
        float dt = static_cast<float>(v.solver.dt);
        ImGui::SliderFloat("##dt", &dt, 1e-5f, 0.05f, "dt = %.4f s", ImGuiSliderFlags_Logarithmic);
        if (ImGui::IsItemActive() || ImGui::IsItemDeactivatedAfterEdit()) v.solver.dt = dt;
        changed |= ImGui::IsItemDeactivatedAfterEdit();
        if (isPositionBased(v.solver.method)) {
            const float half = (avail - ImGui::GetStyle().ItemSpacing.x) / 2;
            ImGui::SetNextItemWidth(half);
            ImGui::SliderInt("##it", &v.solver.iterations, 1, 100, "%d iterations");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            ImGui::SameLine();
            ImGui::SetNextItemWidth(half);
            ImGui::SliderInt("##sub", &v.solver.substeps, 1, 50, "%d substeps");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
        }
        if (!r.samples.empty()) {
            const CompareSample& s = r.samples.back();
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
            ImGui::TextWrapped("%s per step, %s %s", duration(s.step_ms).c_str(), cmp_->measure().name.c_str(),
                               withUnit(s.error, cmp_->measure().unit).c_str());
            ImGui::PopStyleColor();
        }
        if (!r.message.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, kRed);
            ImGui::TextWrapped("%s", r.message.c_str());
            ImGui::PopStyleColor();
        }
        ImGui::PopID();
        if (i + 1 < cmp_->runs().size()) ImGui::Separator();
    }
    if (changed)
        for (CompareVariant& v : variants_) v.label = compareLabel(v.solver, original_.solver);
    if (remove >= 0) {
        variants_.erase(variants_.begin() + remove);
        camera_set_ = false;
        rebuild(false);
    } else if (changed) {
        rebuild(false);  // a run with other settings starts again, with the others: together
    }
}

void App::panelParameters() {
    bool changed = false;
    SolverSpec& sv = variants_.front().solver;
    ImGui::PushItemWidth(110);  // room beside each slider for its value and unit (and a scrollbar)
    const bool position_based = isPositionBased(sv.method);
    if (!compareMode()) {  // side by side each run has its own (Runs)
        changed |= sliderD("dt [s]", sv.dt, 1e-5, 0.05, "%.5f", true);
        if (position_based) {
            ImGui::SliderInt("iterations", &sv.iterations, 1, 100);
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            ImGui::SliderInt("substeps", &sv.substeps, 1, 50);
            changed |= ImGui::IsItemDeactivatedAfterEdit();
        }
    }
    bool any_pb = false, any_force = false, any_xpbd = false;
    for (const CompareVariant& v : variants_) {
        any_pb = any_pb || isPositionBased(v.solver.method);
        any_force = any_force || !isPositionBased(v.solver.method);
        any_xpbd = any_xpbd || v.solver.method == Method::Xpbd;
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
        if (any_force)
            for (auto& [name, g] : groups) {
                ImGui::PushID(name);
                changed |= ImGui::Checkbox("##on", &g->enabled);
                ImGui::SameLine();
                ImGui::SetNextItemWidth(90);
                changed |= sliderD((std::string(name) + " k [N/m]").c_str(), g->k, 1, 1e5, "%.0f", true);
                ImGui::PopID();
            }
        if (any_force) {
            changed |= ImGui::Checkbox("Provot", &scene_.provot.enabled);
            ImGui::SameLine();
            ImGui::SetNextItemWidth(90);
            double pct = scene_.provot.max_strain * 100;
            changed |= sliderD("tau [%]", pct, 0.1, 50, "%.1f", true);
            scene_.provot.max_strain = pct / 100;
        }
        struct C { const char* name; ConstraintGroup* g; const char* unit; } cons[] = {
            {"distance", &scene_.constraints.distance, "m/N"}, {"bending", &scene_.constraints.bending, "1/(N m)"}};
        const bool any_pbd = std::any_of(variants_.begin(), variants_.end(), [](const CompareVariant& v) { return v.solver.method == Method::Pbd; });
        if (any_pb)
            for (auto& [name, g, unit] : cons) {  // pbd: the stiffness k; xpbd: the compliance alpha; pbd beside xpbd: both
                ImGui::PushID(name);
                changed |= ImGui::Checkbox("##on", &g->enabled);
                ImGui::SameLine();
                ImGui::SetNextItemWidth(80);
                if (any_pbd) changed |= sliderD((std::string(name) + " k [1]").c_str(), g->stiffness, 0, 1, "%.3f");
                if (any_xpbd) {
                    if (any_pbd) {
                        ImGui::Dummy(ImVec2(ImGui::GetFrameHeight(), 1));
                        ImGui::SameLine();
                        ImGui::SetNextItemWidth(80);
                    }
                    changed |= sliderD((std::string(name) + " alpha [" + unit + "]").c_str(), g->compliance, 0, 1e-2, "%.3g");
                }
                ImGui::PopID();
            }
        if (any_pb) {  // stage 07: the cloth against itself
            changed |= ImGui::Checkbox("##self", &scene_.self_collision.enabled);
            ImGui::SameLine();
            ImGui::SetNextItemWidth(90);
            changed |= sliderD("self-collision h [m]", scene_.self_collision.thickness, 0.002, 0.1, "%.3f", true);
        }
    }
    // Two quantities, two sliders: the air damping force (every method) and dampVelocities' k_damping (pbd, xpbd).
    changed |= sliderD("air damping [Ns/m]", scene_.forces.air_damping, 0, 5.0, "%.3f");
    if (any_pb) changed |= sliderD("k_damping [1]", scene_.pbd.damping, 0, 1.0, "%.3f");
    float wind[3] = {float(scene_.forces.wind.x()), float(scene_.forces.wind.y()), float(scene_.forces.wind.z())};
    ImGui::SliderFloat3("wind [m/s]", wind, -20, 20, "%.1f");
    if (ImGui::IsItemActive() || ImGui::IsItemDeactivatedAfterEdit()) scene_.forces.wind = Vec3(wind[0], wind[1], wind[2]);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    float used = 0;
    for (size_t i = 0; i < all_colliders_.size(); ++i) {
        const Collider& c = all_colliders_[i];
        const std::string label = std::string(colliderTypeName(c.type)) + " " + std::to_string(i);
        const float w = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label.c_str()).x;
        if (i > 0 && used + ImGui::GetStyle().ItemSpacing.x + w < ImGui::GetContentRegionAvail().x) ImGui::SameLine(), used += ImGui::GetStyle().ItemSpacing.x;
        else used = 0;
        used += w;
        bool on = collider_on_[i];
        if (ImGui::Checkbox(label.c_str(), &on)) collider_on_[i] = on, changed = true;
    }
    ImGui::PopItemWidth();
    if (changed) {
        if (!compareMode()) variants_.front().label = methodName(sv.method);
        rebuild(true);
    }
}

void App::panelView() {
    ImGui::Checkbox("surface", &view_.surface);
    ImGui::SameLine();
    ImGui::Checkbox("edges", &view_.edges);
    ImGui::SameLine();
    ImGui::Checkbox("by strain", &view_.color_by_strain);
    for (int k = 0; k < 4; ++k) {
        ImGui::Checkbox(edgeKindName(static_cast<EdgeKind>(k)), &view_.show_kind[k]);
        if (k == 0 || k == 2) ImGui::SameLine();
    }
    ImGui::Checkbox("particles", &view_.particles);
    ImGui::SameLine();
    ImGui::Checkbox("colliders", &view_.colliders);
    ImGui::SameLine();
    ImGui::Checkbox("ground", &view_.ground);
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

// The samples of run r as plot lines: x and y of the last kHistory samples, at most kPlotPoints of
// them evenly spread (a plot is a few hundred pixels wide; each point is a stroke for llvmpipe), and the last.
namespace {
constexpr size_t kPlotPoints = 150;
PlotLine lineOf(const CompareRun& r, size_t i, double (*x)(const CompareSample&), double (*y)(const CompareSample&)) {
    PlotLine l;
    l.color = runColor(i);
    l.label = r.variant.label;
    const size_t n = r.samples.size(), first = n > kHistory ? n - kHistory : 0, stride = std::max<size_t>(1, (n - first + kPlotPoints - 1) / kPlotPoints);
    for (size_t k = first; k < n; k += stride) l.x.push_back(x(r.samples[k])), l.y.push_back(y(r.samples[k]));
    if (n > first && (n - 1 - first) % stride) l.x.push_back(x(r.samples.back())), l.y.push_back(y(r.samples.back()));
    return l;
}
double sampleT(const CompareSample& s) { return s.t; }
double sampleCost(const CompareSample& s) { return s.t > 0 ? s.wall / s.t : NAN; }
double sampleError(const CompareSample& s) { return s.error; }
double sampleAbsError(const CompareSample& s) { return std::abs(s.error); }
double sampleEnergy(const CompareSample& s) { return s.energy; }
double sampleStrain(const CompareSample& s) { return s.max_strain; }
double sampleStepMs(const CompareSample& s) { return s.step_ms; }
}  // namespace

void App::panelPlots() {
    if (!cmp_ || cmp_->runs().empty()) return;
    const CompareRun& r = cmp_->runs().front();
    const float w = ImGui::GetContentRegionAvail().x, h = 120;
    const CompareMeasure& m = cmp_->measure();
    PlotAxes a;
    a.xlabel = "t [s]";
    a.title = "energy [J]";
    plotLines(a, {lineOf(r, 0, sampleT, sampleEnergy)}, w, h);
    a.title = m.name + " [" + m.unit + "]";
    plotLines(a, {lineOf(r, 0, sampleT, sampleError)}, w, h);
    a.title = "ms per step [ms]";
    plotLines(a, {lineOf(r, 0, sampleT, sampleStepMs)}, w, h);
}

void App::comparePlots(int /*width*/, int height) {
    const float scale = ImGui::GetIO().DisplaySize.y > 0 ? ImGui::GetIO().DisplaySize.y / height : 1.0f;
    ImGui::SetNextWindowPos(ImVec2(plots_rect_.x * scale, plots_rect_.y * scale), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(plots_rect_.width * scale, plots_rect_.height * scale), ImGuiCond_Always);
    ImGui::Begin(kPlotWindow, nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground);
    const CompareMeasure& m = cmp_->measure();
    const auto lines = [&](double (*x)(const CompareSample&), double (*y)(const CompareSample&)) {
        std::vector<PlotLine> out;
        for (size_t i = 0; i < cmp_->runs().size(); ++i) out.push_back(lineOf(cmp_->runs()[i], i, x, y));
        return out;
    };
    const float sp = ImGui::GetStyle().ItemSpacing.x, w = ImGui::GetContentRegionAvail().x, h = ImGui::GetContentRegionAvail().y;
    const float big = 0.34f * (w - 3 * sp), small = (w - 3 * sp - big) / 3;
    PlotAxes a;
    a.title = m.name + " [" + m.unit + "]";
    a.xlabel = "wall s per simulated s";
    a.logx = a.logy = a.legend = a.mark_last = true;
    std::vector<PlotLine> err = lines(sampleCost, sampleAbsError);
    plotLines(a, err, big, h);
    a = PlotAxes{};
    a.xlabel = "t [s]";
    a.mark_last = true;
    ImGui::SameLine();
    a.title = "energy [J]";
    plotLines(a, lines(sampleT, sampleEnergy), small, h);
    ImGui::SameLine();
    a.title = "max strain [1]";
    if (scene_.model == Model::Spring) a.empty = "one spring: no strain";
    plotLines(a, lines(sampleT, sampleStrain), small, h);
    a.empty = PlotAxes{}.empty;
    ImGui::SameLine();
    a.title = "ms per step [ms]";
    plotLines(a, lines(sampleT, sampleStepMs), small, h);
    ImGui::End();
}

void App::drawLabels() {
    label_boxes_.clear();
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    const float lh = ImGui::GetTextLineHeightWithSpacing(), pad = 6;
    const ImU32 ink = IM_COL32(30, 34, 44, 255);
    for (size_t i = 0; i < views_.size() && i < cmp_->runs().size(); ++i) {
        const CompareRun& r = cmp_->runs()[i];
        const Viewport& v = views_[i];
        std::vector<std::pair<std::string, ImU32>> rows = {{r.variant.label, ink}};
        if (!r.samples.empty()) {
            const CompareSample& s = r.samples.back();
            char b[160];
            std::snprintf(b, sizeof b, "t = %.2f s   %s per step", s.t, duration(s.step_ms).c_str());
            rows.push_back({b, ink});
            rows.push_back({cmp_->measure().name + " = " + withUnit(s.error, cmp_->measure().unit), ink});
        }
        if (!r.message.empty()) rows.push_back({r.message, IM_COL32(200, 30, 25, 255)});
        float w = 0;
        for (auto& [text, col] : rows) {
            // A row wider than the view is cut at a word, with "..." (the whole message is in the panel).
            const float room = v.width - 2 * pad - 30;
            if (ImGui::CalcTextSize(text.c_str()).x > room) {
                while (!text.empty() && ImGui::CalcTextSize((text + "...").c_str()).x > room) text.pop_back();
                text += "...";
            }
            w = std::max(w, ImGui::CalcTextSize(text.c_str()).x);
        }
        const ImVec2 p(v.x + 8.0f, v.y + 8.0f), q(p.x + w + 2 * pad + 20, p.y + rows.size() * lh + 2 * pad);
        dl->AddRectFilled(p, q, IM_COL32(255, 255, 255, 225), 4);
        dl->AddRect(p, q, runColor(i), 4, 0, 2.0f);
        dl->AddRectFilled(ImVec2(p.x + pad, p.y + pad + 2), ImVec2(p.x + pad + 12, p.y + pad + 14), runColor(i), 2);
        for (size_t k = 0; k < rows.size(); ++k) dl->AddText(ImVec2(p.x + pad + 20, p.y + pad + k * lh), rows[k].second, rows[k].first.c_str());
        label_boxes_.push_back({Viewport{static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(q.x - p.x), static_cast<int>(q.y - p.y)},
                                rows.front().first});
    }
}

// The last item's rectangle (ImGui's screen coordinates: CSS pixels in a browser) under NAME, for the status.
void App::rememberControl(const std::string& name) { rememberControl(name, ImGui::GetItemRectMin(), ImGui::GetItemRectMax()); }

void App::rememberControl(const std::string& name, const ImVec2& p, const ImVec2& q) {
    controls_[name] = Viewport{static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(q.x - p.x), static_cast<int>(q.y - p.y)};
}

void App::wrote(const std::string& path) {
    if (options_.file_written) options_.file_written(path);
}

std::string App::exportFigures(const std::string& dir) {
    if (!cmp_) return "";
    try {
        std::filesystem::create_directories(dir);
        writeCompareCsv(dir + "/compare.csv", *cmp_);
        const std::string png = plotCompare(dir, *cmp_, std::filesystem::path(scene_path_).filename().string());
        status_ = "wrote " + dir + "/compare.csv" + (png.empty() ? " (no PNG: gnuplot missing)" : " and compare.png");
        wrote(dir + "/compare.csv");
        if (!png.empty()) wrote(png);
    } catch (const std::exception& e) {
        message_ = std::string("error: ") + e.what();
    }
    return status_;
}

std::string App::statusJson() const {
    using nlohmann::json;
    json j;
    j["size"] = {width_, height_};
    j["scene"] = scene_path_;
    j["look"] = scene_.view.look;
    j["playing"] = playing_;
    j["time"] = cmp_ ? cmp_->time() : 0.0;
    j["realtime"] = std::min(realtime_, speed_);
    j["message"] = message_;
    j["compare"] = compareMode();
    j["platform_note"] = options_.platform_note;
    if (cmp_) j["measure"] = {{"name", cmp_->measure().name}, {"unit", cmp_->measure().unit}};
    j["runs"] = json::array();
    for (size_t i = 0; cmp_ && i < cmp_->runs().size(); ++i) {
        const CompareRun& r = cmp_->runs()[i];
        json x = {{"label", r.variant.label}, {"method", methodName(r.variant.solver.method)}, {"kernel", r.scene.solver.kernel}, {"color", compareColor(i)},
                  {"steps", r.steps}, {"wall", r.wall}, {"samples", r.samples.size()}, {"message", r.message}};
        if (i < views_.size()) x["viewport"] = {views_[i].x, views_[i].y, views_[i].width, views_[i].height};
        if (i < label_boxes_.size()) {
            const Viewport& b = label_boxes_[i].first;
            x["label_box"] = {b.x, b.y, b.width, b.height};
            x["label_text"] = label_boxes_[i].second;
        }
        if (r.sim) {
            x["t"] = r.sim->state().t;
            x["passes"] = json::object();  // where its steps' time went: pass name → wall time, s
            for (const PassTimer::Pass& p : r.sim->timer().passes())
                if (p.calls > 0) x["passes"][p.name] = p.seconds;
        }
        if (!r.samples.empty()) {
            const CompareSample& s = r.samples.back();
            const auto num = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
            x["error"] = num(s.error), x["energy"] = num(s.energy), x["max_strain"] = num(s.max_strain), x["step_ms"] = num(s.step_ms);
        }
        j["runs"].push_back(x);
    }
    j["panel"] = {{"cut_text", clippedText(kRunWindow)}, {"scrolls", panel_scrolls_}};
    j["controls"] = json::object();
    for (const auto& [name, r] : controls_) j["controls"][name] = {r.x, r.y, r.width, r.height};
    if (compareMode())
        j["plots"] = {{"rect", {plots_rect_.x, plots_rect_.y, plots_rect_.width, plots_rect_.height}}, {"cut_text", clippedText(kPlotWindow)}};
    const double n = std::max(1, timings_.frames);
    j["timings_ms"] = {{"frames", timings_.frames}, {"simulate", timings_.simulate / n}, {"draw_data", timings_.draw_data / n},
                       {"draw", timings_.draw / n}, {"panel", timings_.panel / n}};
    for (const RenderPassTime& p : renderer_.passTimes()) j["timings_ms"]["draw: " + std::string(p.name)] = p.ms / n;
    return j.dump(2);
}

}  // namespace clothlab
