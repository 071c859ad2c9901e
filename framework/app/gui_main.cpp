// clothlab-gui: the interactive app in a GLFW window (OpenGL through libGL).
//   clothlab-gui [SCENE] [--scenes DIR] [--size WxH] [--compare a,b,...]
//   clothlab-gui SCENE --screenshot FILE.png --frames N   (runs N frames in the real window, saves it, quits)
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "clothlab/core/input_error.h"
#include "clothlab/gui/app.h"
#include "clothlab/render/imgui_gl.h"
#include "clothlab/render/renderer.h"

#ifndef CLOTHLAB_SCENES_DIR
#define CLOTHLAB_SCENES_DIR "scenes"
#endif

int main(int argc, char** argv) {
    using namespace clothlab;
    CLI::App cli{"clothlab-gui — the interactive cloth lab (GLFW window + Dear ImGui)"};
    std::string scene, scenes = CLOTHLAB_SCENES_DIR, screenshot, size = "1280x800", compare;
    int frames = 0, wave = 0;
    bool edges = false;
    cli.add_option("scene", scene, "Scene file (default: the first in --scenes)");
    cli.add_option("--scenes", scenes, "Folder the scene picker lists");
    std::vector<std::string> sets;
    cli.add_option("--set", sets, "Override a scene field, e.g. --set cloth.nx=32 (repeatable)");
    cli.add_option("--screenshot", screenshot, "Run --frames frames, save the window as PNG and quit");
    cli.add_option("--frames", frames, "Frames to run (0: until the window is closed)")->check(CLI::NonNegativeNumber);
    cli.add_option("--size", size, "Window size WIDTHxHEIGHT");
    cli.add_option("--bench-grid", wave, "Benchmark: show an n x n cloth moved by a wave; prints frames per second")
        ->check(CLI::Range(0, 1024));
    cli.add_flag("--edges", edges, "Start with the spring/constraint overlay shown");
    cli.add_option("--compare", compare, "Run 2 to 4 variants side by side, e.g. pbd,xpbd or pbd:iterations=5,pbd:iterations=50");
    CLI11_PARSE(cli, argc, argv);
    int W = 1280, H = 800;
    if (std::sscanf(size.c_str(), "%dx%d", &W, &H) != 2 || W < 64 || H < 64) {
        std::cerr << "error: command line: --size: expected WIDTHxHEIGHT (got \"" << size << "\")\n";
        return 1;
    }
    if (!screenshot.empty() && frames == 0) frames = 30;

    if (!glfwInit()) {
        std::cerr << "error: display: GLFW cannot start (no DISPLAY?); offscreen: ./lab gui SCENE --screenshot FILE.png\n";
        return 1;
    }
    // OpenGL 3.3 core profile, what the renderer and its ImGui backend are written for (render/imgui_gl.h).
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    GLFWwindow* win = glfwCreateWindow(W, H, "clothlab", nullptr, nullptr);
    if (!win) {
        std::cerr << "error: display: GLFW cannot open an OpenGL 3.3 core window; offscreen: ./lab gui SCENE --screenshot FILE.png\n";
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(win);
    glfwSwapInterval(wave > 0 || frames > 0 ? 0 : 1);  // measuring or screenshots: no vsync
    ImGui::CreateContext();
    setupImGuiStyle();
    ImGui_ImplGlfw_InitForOpenGL(win, true);
    imguiGlInit();

    int code = 0;
    try {
        AppOptions o;
        o.scene = scene;
        o.scenes_dir = scenes;
        o.wave_grid = wave;
        o.sets = sets;
        o.edges = edges ? 1 : -1;
        o.compare = compare;
        o.step_beside_drawing = true;
        App app(o);
        int frame = 0, fw = W, fh = H;
        auto t0 = std::chrono::steady_clock::now();
        while (!glfwWindowShouldClose(win) && (frames == 0 || frame < frames)) {
            if (frame == 3) t0 = std::chrono::steady_clock::now();
            glfwPollEvents();
            imguiGlNewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            glfwGetFramebufferSize(win, &fw, &fh);
            app.frame(fw, fh);
            ImGui::Render();
            imguiGlRender(ImGui::GetDrawData());
            app.endFrame();
            if (!screenshot.empty() && frame + 1 == frames) {
                glReadBuffer(GL_BACK);
                writePng(screenshot, readPixels(fw, fh));
                std::cout << "wrote " << screenshot << " (" << fw << "x" << fh << ", window)\n";
            }
            glfwSwapBuffers(win);
            ++frame;
        }
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (frame > 4)
            std::cout << "app frame " << fw << "x" << fh << (wave > 1 ? ", " + std::to_string(wave) + "x" + std::to_string(wave) + " cloth" : "")
                      << ": " << 1000 * s / (frame - 3) << " ms per frame (" << (frame - 3) / s << " fps, window)\n";
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        code = 1;
    }
    imguiGlShutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(win);
    glfwTerminate();
    return code;
}
