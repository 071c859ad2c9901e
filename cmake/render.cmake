# The renderer and the app (optional layer above the simulation).
#   clothlab_render  static library: framework/src/render + framework/src/gui, compiled once against the
#                    GL headers but linking no GL library (one process can use libGL or libOSMesa, not both)
#   clothlab-render  offscreen program (links libOSMesa): render, gui --screenshot, bench
#   clothlab-gui     window program (links GLFW + libGL), only when GLFW is found
# -DCLOTHLAB_RENDER=OFF (the default when the packages are missing) builds none of it.
find_package(PkgConfig QUIET)
set(_render_ok OFF)
if(PkgConfig_FOUND)
  pkg_check_modules(CLOTHLAB_OSMESA QUIET IMPORTED_TARGET GLOBAL osmesa)
  pkg_check_modules(CLOTHLAB_IMGUI QUIET IMPORTED_TARGET GLOBAL imgui stb)
  find_path(CLOTHLAB_GL_INCLUDE GL/gl.h)
  if(CLOTHLAB_OSMESA_FOUND AND CLOTHLAB_IMGUI_FOUND AND CLOTHLAB_GL_INCLUDE)
    set(_render_ok ON)
  endif()
endif()
option(CLOTHLAB_RENDER "Build the renderer (clothlab-render) and the app (clothlab-gui)" ${_render_ok})
if(NOT CLOTHLAB_RENDER)
  message(STATUS "clothlab: renderer off (CLOTHLAB_RENDER=OFF or libosmesa6-dev/libimgui-dev/libstb-dev missing)")
  return()
endif()
if(NOT _render_ok)
  message(FATAL_ERROR "error: CLOTHLAB_RENDER=ON needs the Debian packages libosmesa6-dev libgl-dev libimgui-dev libstb-dev "
                      "(apt-get install them, or configure with -DCLOTHLAB_RENDER=OFF)")
endif()

# Which code each stage runs, for the app's stage panel: "01_hooke=reference;02_mfn=student".
set(_stage_code "")
foreach(NN IN LISTS CLOTHLAB_STAGES)
  if(CLOTHLAB_IMPL_${NN} STREQUAL "stage_${NN}_solutions")
    list(APPEND _stage_code "${CLOTHLAB_STAGE_DIR_${NN}}=reference")
  else()
    list(APPEND _stage_code "${CLOTHLAB_STAGE_DIR_${NN}}=student")
  endif()
endforeach()
string(REPLACE ";" "\\;" _stage_code "${_stage_code}")

file(GLOB _render_src CONFIGURE_DEPENDS src/render/*.cpp src/gui/*.cpp)
list(FILTER _render_src EXCLUDE REGEX "src/render/offscreen\\.cpp$")
add_library(clothlab_render STATIC ${_render_src})
target_include_directories(clothlab_render PUBLIC ${CLOTHLAB_GL_INCLUDE})
target_link_libraries(clothlab_render PUBLIC clothlab_framework PkgConfig::CLOTHLAB_IMGUI)
target_compile_definitions(clothlab_render PRIVATE "CLOTHLAB_STAGE_CODE=\"${_stage_code}\"")

# The OSMesa context, only in programs that link libOSMesa.
add_library(clothlab_offscreen OBJECT src/render/offscreen.cpp)
target_link_libraries(clothlab_offscreen PUBLIC clothlab_render PkgConfig::CLOTHLAB_OSMESA)

add_executable(clothlab-render app/render_main.cpp)
target_link_libraries(clothlab-render PRIVATE clothlab_offscreen clothlab_render PkgConfig::CLOTHLAB_OSMESA CLI11::CLI11)
target_compile_definitions(clothlab-render PRIVATE CLOTHLAB_SCENES_DIR="${PROJECT_SOURCE_DIR}/scenes")
clothlab_link_stages(clothlab-render "")

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
