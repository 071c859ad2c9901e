// clothlab in a browser: the same App as clothlab-gui (framework/src/gui), compiled with em++ (./lab web,
// cmake/web.cmake), in a GLFW canvas (Emscripten's GLFW on WebGL2). The renderer and its ImGui backend
// are the desktop's source, their shaders in GLSL ES 3.00 (the build switch CLOTHLAB_WEB, render/gl.h).
//   index.html?scene=NAME          opens scenes/NAME.json (default: pbd_sphere)
//   index.html?scene=NAME&steps=N  runs exactly N steps, then pauses (the browser test, tests/web/)
//   &set=KEY=VALUE (repeatable)    overrides a scene field, as ./lab gui --set
//   &timing=1                      times the frame's parts (the status' app.timings_ms; benchmarks/web_step.sh)
// "Save PNG" and "Export CSV + PNG" write into Emscripten's in-memory files; the page offers each file as a
// download (offerDownload). Where the panel drew its buttons is in the status (app.controls) for the tests.
// Each frame it publishes the status: window.clothlab (an object) and the same as JSON in the element
// with id clothlab-status (so chromium --headless --dump-dom reads it). Its `probe` is the hook for
// mouse tests (tests/web/page_run.py --mouse): the first run's middle particle (index particles / 2),
// its position, whether it is pinned (inverse mass 0: a pin, a right-click's pin or the left button's
// grab) and where it is drawn, in CSS pixels of the page (the left button there grabs it, the right
// button toggles its pin, as in ./lab gui); `pinned` counts the first run's particles of inverse mass 0.
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "clothlab/core/input_error.h"
#include "clothlab/gui/app.h"
#include "clothlab/render/imgui_gl.h"

namespace {

using namespace clothlab;

// The values of parameter NAME in the page's query string QUERY ("?scene=pbd_sphere&steps=200"; index.html
// passes it as the program's argument), percent-decoded, in their order.
std::vector<std::string> urlParameters(const std::string& query, const std::string& name) {
    std::vector<std::string> out;
    size_t at = query.empty() || query[0] != '?' ? 0 : 1;
    while (at < query.size()) {
        size_t end = query.find('&', at);
        if (end == std::string::npos) end = query.size();
        const std::string item = query.substr(at, end - at);
        const size_t eq = item.find('=');
        if (item.substr(0, eq) == name) {
            std::string v, raw = eq == std::string::npos ? "" : item.substr(eq + 1);
            for (size_t i = 0; i < raw.size(); ++i) {
                if (raw[i] == '%' && i + 2 < raw.size() && std::isxdigit(static_cast<unsigned char>(raw[i + 1])) &&
                    std::isxdigit(static_cast<unsigned char>(raw[i + 2])))
                    v += static_cast<char>(std::stoi(raw.substr(i + 1, 2), nullptr, 16)), i += 2;
                else v += raw[i] == '+' ? ' ' : raw[i];
            }
            out.push_back(v);
        }
        at = end + 1;
    }
    return out;
}

// The first value of parameter NAME ("" when missing).
std::string urlParameter(const std::string& query, const std::string& name) {
    const std::vector<std::string> v = urlParameters(query, name);
    return v.empty() ? "" : v.front();
}

struct Web {
    GLFWwindow* win = nullptr;
    std::unique_ptr<App> app;
    std::string scene;          // the scene's name (?scene=)
    std::string error;          // a bad page parameter: shown in the panel and in the status
    long long stop_at = -1;     // ?steps=N: pause after N steps
    long long frames = 0;
    double ms_per_frame = 0.0;  // smoothed wall time between frames
    std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
};
Web web;

// The status object: scene, step, simulated time, energy, max strain, ms per step, warnings, message,
// the first run's centroid and whether every position is finite, plus the app's own statusJson().
void publishStatus() {
    nlohmann::json j;
    j["scene"] = web.scene;
    j["frames"] = web.frames;
    j["ms_per_frame"] = web.ms_per_frame;
    j["threads"] = 1;
    j["message"] = !web.error.empty() ? web.error : web.app ? web.app->message() : "";
    j["warnings"] = web.app ? web.app->warnings() : std::vector<std::string>{};
    const Comparison* cmp = web.app ? web.app->comparison() : nullptr;
    const Simulation* sim = web.app ? web.app->simulation() : nullptr;
    j["step"] = cmp && !cmp->runs().empty() ? cmp->runs()[0].steps : 0;
    j["done"] = web.stop_at >= 0 && j["step"].get<long long>() >= web.stop_at;
    if (sim) {
        const Matrix3X& x = sim->state().x;
        const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
        j["t"] = sim->state().t;
        j["finite"] = x.allFinite() && sim->state().v.allFinite();
        const Vec3 c = x.cols() ? Vec3(x.rowwise().mean()) : Vec3::Zero();
        j["centroid"] = {num(c.x()), num(c.y()), num(c.z())};
        j["particles"] = x.cols();
        const VectorX& w = sim->state().w;
        j["pinned"] = (w.array() == 0.0).count();
        if (x.cols() > 0) {
            const int k = static_cast<int>(x.cols() / 2);
            const Viewport v = web.app->viewport(0);
            const Vec3 p = web.app->camera().project(x.col(k), v.width, v.height);
            const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;  // framebuffer pixels per CSS pixel
            const double sx = scale.x > 0 ? scale.x : 1.0, sy = scale.y > 0 ? scale.y : 1.0;
            j["probe"] = {{"index", k}, {"x", {num(x(0, k)), num(x(1, k)), num(x(2, k))}}, {"pinned", w[k] == 0.0},
                          {"px", {num((v.x + p.x()) / sx), num((v.y + p.y()) / sy)}}};
        }
    }
    if (cmp && !cmp->runs().empty() && !cmp->runs()[0].samples.empty()) {
        const CompareSample& s = cmp->runs()[0].samples.back();
        const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
        j["energy"] = num(s.energy), j["max_strain"] = num(s.max_strain), j["step_ms"] = num(s.step_ms);
    }
    if (web.app) j["app"] = nlohmann::json::parse(web.app->statusJson());
    const std::string text = j.dump();
    EM_ASM({
        const text = UTF8ToString($0);
        const errors = (window.clothlab && window.clothlab.console_errors) || [];
        window.clothlab = JSON.parse(text);
        window.clothlab.console_errors = errors;
        const el = document.getElementById('clothlab-status');
        if (el) el.textContent = JSON.stringify(window.clothlab);
        const msg = document.getElementById('clothlab-message');
        if (msg) msg.textContent = window.clothlab.message;
    }, text.c_str());
}

// A file the app wrote (in Emscripten's in-memory file system) offered as a download named after its
// path ("clothlab_compare_1/compare.csv" -> clothlab_compare_1_compare.csv); window.clothlab_downloads
// lists the names offered (tests/web/page_run.py --controls).
void offerDownload(const std::string& path) {
    EM_ASM({
        const path = UTF8ToString($0);
        const a = document.createElement('a');
        a.href = URL.createObjectURL(new Blob([FS.readFile(path)]));
        a.download = (path.startsWith('./') ? path.substring(2) : path).split('/').join('_');
        document.body.appendChild(a);
        a.click();
        a.remove();
        (window.clothlab_downloads = window.clothlab_downloads || []).push(a.download);
    }, path.c_str());
}

void frame() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = 1e3 * std::chrono::duration<double>(now - web.last).count();
    web.last = now;
    web.ms_per_frame = web.frames < 2 ? ms : 0.9 * web.ms_per_frame + 0.1 * ms;
    glfwPollEvents();
    imguiGlNewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    int w = 0, h = 0;
    glfwGetFramebufferSize(web.win, &w, &h);
    if (web.app) {
        if (web.stop_at >= 0) {  // the test's fixed step count: a few steps per frame, then stop
            const Comparison* cmp = web.app->comparison();
            for (int k = 0; k < 10 && cmp && !cmp->runs().empty() && cmp->runs()[0].steps < web.stop_at && !cmp->runs()[0].stopped(); ++k)
                web.app->stepOnce();
        }
        web.app->frame(w, h);
    }
    if (!web.error.empty()) {  // never a blank canvas: the page's own error in a window of its own
        ImGui::SetNextWindowPos(ImVec2(370, 60));  // over the 3-D view, beside the panel
        ImGui::Begin("clothlab: error", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::TextColored(ImVec4(0.8f, 0.1f, 0.1f, 1), "%s", web.error.c_str());
        ImGui::End();
    }
    ImGui::Render();
    imguiGlRender(ImGui::GetDrawData());
    ++web.frames;
    publishStatus();
}

}  // namespace

int main(int argc, char** argv) {
    const std::string query = argc > 1 ? argv[1] : "";
    if (!glfwInit()) return 1;
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);  // WebGL2 (OpenGL ES 3.0): what the renderer is written for
    const int W = EM_ASM_INT({ return window.innerWidth; }), H = EM_ASM_INT({ return window.innerHeight; });
    web.win = glfwCreateWindow(W > 64 ? W : 1280, H > 64 ? H : 800, "clothlab", nullptr, nullptr);
    if (!web.win) return 1;
    glfwMakeContextCurrent(web.win);
    ImGui::CreateContext();
    setupImGuiStyle();
    ImGui_ImplGlfw_InitForOpenGL(web.win, true);
    imguiGlInit();

    web.scene = urlParameter(query, "scene");
    if (web.scene.empty()) web.scene = "pbd_sphere";
    const std::string steps = urlParameter(query, "steps");
    if (!steps.empty()) {
        char* end = nullptr;
        const long long n = std::strtoll(steps.c_str(), &end, 10);
        if (*end || n < 0) web.error = "error: page: steps: expected a whole number >= 0 (got \"" + steps + "\")";
        else web.stop_at = n;
    }
    bool name_ok = web.scene.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") == std::string::npos;
    const std::string path = "scenes/" + web.scene + ".json";
    if (!name_ok || !std::ifstream(path))
        web.error = "error: page: scene: no scene \"" + web.scene + "\" (the scenes are the names in the panel's picker, e.g. ?scene=pbd_sphere)";
    try {
        AppOptions o;
        o.scene = web.error.empty() ? path : "";
        o.scenes_dir = "scenes";
        o.play = web.stop_at < 0;
        o.sets = urlParameters(query, "set");          // ?set=cloth.nx=64: as ./lab gui --set
        o.timing = urlParameter(query, "timing") == "1";  // ?timing=1: the frame's parts in the status (app.timings_ms)
        o.file_written = offerDownload;               // "Save PNG", "Export CSV + PNG": the browser downloads the file
        o.platform_note = "one thread: a browser page runs without threads here (./lab gui uses every core)";
        web.app = std::make_unique<App>(o);
    } catch (const InputError& e) {
        web.error = std::string("error: ") + e.what();
    }
    if (!web.error.empty()) EM_ASM({ console.warn(UTF8ToString($0)); }, web.error.c_str());
    emscripten_set_main_loop(frame, 0, true);
    return 0;
}
