# The renderer and the app (optional layer above the simulation).
#   clothlab_render      static library: framework/src/render + framework/src/gui, compiled once against
#                        the GL headers but linking no GL library (one process can use libGL/libOpenGL or
#                        libOSMesa, not both: each defines the gl* functions)
#   clothlab-render      offscreen program through OSMesa (links libOSMesa): render, gui --screenshot,
#                        bench; only where libosmesa6-dev is installed (Mesa 25.1 dropped OSMesa)
#   clothlab-render-egl  the same program through EGL without a window (links libEGL + libOpenGL,
#                        Mesa's surfaceless platform, a framebuffer object); ./lab picks one of the two
#                        at run time (docs/render.md)
#   clothlab-gui         window program (links GLFW + libGL), only when GLFW is found
# The renderer needs ImGui, stb, GL/gl.h and at least one offscreen backend (OSMesa or EGL);
# -DCLOTHLAB_WITH_OSMESA=OFF / -DCLOTHLAB_WITH_EGL=OFF leave one out even where it is installed.
# -DCLOTHLAB_RENDER=OFF (the default when the packages are missing) builds none of it.
option(CLOTHLAB_WITH_OSMESA "Build clothlab-render (OSMesa) where libosmesa6-dev is installed" ON)
option(CLOTHLAB_WITH_EGL "Build clothlab-render-egl (EGL surfaceless) where libegl-dev and libopengl-dev are installed" ON)
find_package(PkgConfig QUIET)
set(_render_ok OFF)
set(CLOTHLAB_HAVE_OSMESA OFF)
set(CLOTHLAB_HAVE_EGL OFF)
if(PkgConfig_FOUND)
  pkg_check_modules(CLOTHLAB_OSMESA QUIET IMPORTED_TARGET GLOBAL osmesa)
  pkg_check_modules(CLOTHLAB_EGL QUIET IMPORTED_TARGET GLOBAL egl opengl)
  pkg_check_modules(CLOTHLAB_IMGUI QUIET IMPORTED_TARGET GLOBAL imgui stb)
  find_path(CLOTHLAB_GL_INCLUDE GL/gl.h)
  if(CLOTHLAB_WITH_OSMESA AND CLOTHLAB_OSMESA_FOUND)
    set(CLOTHLAB_HAVE_OSMESA ON)
  endif()
  if(CLOTHLAB_WITH_EGL AND CLOTHLAB_EGL_FOUND)
    set(CLOTHLAB_HAVE_EGL ON)
  endif()
  if((CLOTHLAB_HAVE_OSMESA OR CLOTHLAB_HAVE_EGL) AND CLOTHLAB_IMGUI_FOUND AND CLOTHLAB_GL_INCLUDE)
    set(_render_ok ON)
  endif()
endif()
option(CLOTHLAB_RENDER "Build the renderer (clothlab-render, clothlab-render-egl) and the app (clothlab-gui)" ${_render_ok})
if(NOT CLOTHLAB_RENDER)
  message(STATUS "clothlab: renderer off (CLOTHLAB_RENDER=OFF, or libimgui-dev/libstb-dev or both of "
                 "libosmesa6-dev and libegl-dev/libopengl-dev missing)")
  return()
endif()
if(NOT _render_ok)
  message(FATAL_ERROR "error: CLOTHLAB_RENDER=ON needs the Debian packages libimgui-dev libstb-dev libgl-dev and "
                      "libosmesa6-dev or libegl-dev libopengl-dev (apt-get install them, or configure with -DCLOTHLAB_RENDER=OFF)")
endif()
message(STATUS "clothlab: offscreen renderer: OSMesa ${CLOTHLAB_HAVE_OSMESA} (clothlab-render), "
               "EGL ${CLOTHLAB_HAVE_EGL} (clothlab-render-egl)")

file(GLOB _render_src CONFIGURE_DEPENDS src/render/*.cpp src/gui/*.cpp)
list(FILTER _render_src EXCLUDE REGEX "src/render/offscreen_[a-z]+\\.cpp$")
add_library(clothlab_render STATIC ${_render_src})
target_include_directories(clothlab_render PUBLIC ${CLOTHLAB_GL_INCLUDE})
target_link_libraries(clothlab_render PUBLIC clothlab_framework clothlab_reference_stages PkgConfig::CLOTHLAB_IMGUI)

# The offscreen context (render/offscreen.h), one object library per backend: a program or test links
# exactly one of them with its GL library. CLOTHLAB_OFFSCREEN_DEFAULT is the backend of the render tests
# (OSMesa where it is built).
if(CLOTHLAB_HAVE_OSMESA)
  add_library(clothlab_offscreen_osmesa OBJECT src/render/offscreen_osmesa.cpp)
  target_link_libraries(clothlab_offscreen_osmesa PUBLIC clothlab_render PkgConfig::CLOTHLAB_OSMESA)
endif()
if(CLOTHLAB_HAVE_EGL)
  add_library(clothlab_offscreen_egl OBJECT src/render/offscreen_egl.cpp)
  target_link_libraries(clothlab_offscreen_egl PUBLIC clothlab_render PkgConfig::CLOTHLAB_EGL)
endif()
if(CLOTHLAB_HAVE_OSMESA)
  set(CLOTHLAB_OFFSCREEN_DEFAULT osmesa CACHE INTERNAL "")
else()
  set(CLOTHLAB_OFFSCREEN_DEFAULT egl CACHE INTERNAL "")
endif()
set(CLOTHLAB_HAVE_OSMESA ${CLOTHLAB_HAVE_OSMESA} CACHE INTERNAL "")
set(CLOTHLAB_HAVE_EGL ${CLOTHLAB_HAVE_EGL} CACHE INTERNAL "")

# The offscreen program, compiled once and linked with each backend.
add_library(clothlab_render_main OBJECT app/render_main.cpp)
target_link_libraries(clothlab_render_main PUBLIC clothlab_render CLI11::CLI11)  # objects and usage, linked below
target_compile_definitions(clothlab_render_main PRIVATE CLOTHLAB_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes")
set(_render_programs "")
if(CLOTHLAB_HAVE_OSMESA)
  add_executable(clothlab-render)
  target_link_libraries(clothlab-render PRIVATE clothlab_render_main clothlab_offscreen_osmesa clothlab_render PkgConfig::CLOTHLAB_OSMESA)
  list(APPEND _render_programs clothlab-render)
endif()
if(CLOTHLAB_HAVE_EGL)
  add_executable(clothlab-render-egl)
  target_link_libraries(clothlab-render-egl PRIVATE clothlab_render_main clothlab_offscreen_egl clothlab_render PkgConfig::CLOTHLAB_EGL)
  list(APPEND _render_programs clothlab-render-egl)
endif()
foreach(_p IN LISTS _render_programs)
  clothlab_link_stages(${_p} "")
endforeach()

find_package(glfw3 3.3 QUIET)
find_package(OpenGL QUIET COMPONENTS OpenGL)
if(glfw3_FOUND AND TARGET OpenGL::GL)
  add_executable(clothlab-gui app/gui_main.cpp)
  target_link_libraries(clothlab-gui PRIVATE clothlab_render glfw OpenGL::GL CLI11::CLI11)
  target_compile_definitions(clothlab-gui PRIVATE CLOTHLAB_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes")
  clothlab_link_stages(clothlab-gui "")
  set(CLOTHLAB_HAVE_GUI ON CACHE INTERNAL "")
else()
  message(STATUS "clothlab: GLFW or libGL not found: no clothlab-gui (the offscreen renderer is built)")
  set(CLOTHLAB_HAVE_GUI OFF CACHE INTERNAL "")
endif()
