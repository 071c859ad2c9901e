# The app for the browser (./lab web): the same framework, renderer and app code as clothlab-gui,
# compiled with Emscripten's em++ (Debian's emscripten) into index.html + clothlab.js/.wasm/.data.
#   emcmake cmake -S . -B build/web -DCLOTHLAB_IMGUI_SOURCE=DIR     (DIR: Debian's imgui source package,
#                                                                    fetched by ./lab web with apt-get source)
# The one build switch of the web build is CLOTHLAB_WEB (set here): the renderer (framework/src/render,
# shaders and buffer objects, Dear ImGui's drawing included: render/imgui_gl.h) is the desktop's source
# compiled for WebGL2 = OpenGL ES 3.0, its shaders in GLSL ES 3.00 (the switch's one place:
# framework/src/render/gl.h), no GL emulation; the simulation runs on one thread (sim/team.cpp: a page
# without cross-origin isolation has no shared memory for threads).
# Header-only Debian packages (Eigen, nlohmann-json, stb, tinyobjloader) are used from /usr/include
# through links in the build folder: /usr/include itself holds the host's C library, not Emscripten's.
# CLOTHLAB_WEB_REFERENCE_ONLY (./lab release): only the stages' targets, for the browser's reference
# objects of the student copy (framework/reference/web/), compiled exactly as the app's build compiles
# them; no Dear ImGui, no app.
set(CLOTHLAB_WEB ON)
option(CLOTHLAB_WEB_REFERENCE_ONLY "only the stages (./lab release: the browser's reference objects)" OFF)
set(CLOTHLAB_IMGUI_SOURCE "" CACHE PATH "Dear ImGui's sources (Debian's imgui source package: imgui.cpp, backends/)")
if(NOT CLOTHLAB_WEB_REFERENCE_ONLY AND NOT EXISTS "${CLOTHLAB_IMGUI_SOURCE}/imgui.cpp")
  message(FATAL_ERROR "error: CLOTHLAB_IMGUI_SOURCE: no imgui.cpp in \"${CLOTHLAB_IMGUI_SOURCE}\" (./lab web fetches Debian's imgui source package)")
endif()
set(_host "${CMAKE_BINARY_DIR}/host-include")
file(MAKE_DIRECTORY "${_host}")
foreach(_h /usr/include/eigen3/Eigen /usr/include/nlohmann /usr/include/tiny_obj_loader.h
           /usr/include/stb/stb_image.h /usr/include/stb/stb_image_write.h)
  if(NOT EXISTS "${_h}")
    message(FATAL_ERROR "error: ${_h}: missing (./lab setup installs the Debian packages)")
  endif()
  get_filename_component(_n "${_h}" NAME)
  file(CREATE_LINK "${_h}" "${_host}/${_n}" SYMBOLIC)
endforeach()
add_library(Eigen3::Eigen INTERFACE IMPORTED)
target_include_directories(Eigen3::Eigen INTERFACE "${_host}")
include(cmake/stages.cmake)

add_compile_options(-fexceptions)  # InputError, NotImplemented: Emscripten does not catch exceptions by default
add_compile_definitions(CLOTHLAB_WEB=1 TINYOBJLOADER_USE_DOUBLE CLOTHLAB_REFERENCE_AVAILABLE=$<BOOL:${CLOTHLAB_REFERENCE_AVAILABLE}>)
if(CLOTHLAB_WEB_REFERENCE_ONLY)
  return()
endif()
configure_file(cmake/reference_stages.cpp.in "${CMAKE_BINARY_DIR}/generated/reference_stages.cpp" @ONLY)
# The implementations Debian ships as libraries of the host (libtinyobjloader, libstb), from their headers.
file(WRITE "${CMAKE_BINARY_DIR}/generated/header_libs.cpp" "#define TINYOBJLOADER_IMPLEMENTATION\n#include <tiny_obj_loader.h>\n"
     "#define STB_IMAGE_IMPLEMENTATION\n#include <stb_image.h>\n#define STB_IMAGE_WRITE_IMPLEMENTATION\n#include <stb_image_write.h>\n")
file(GLOB _web_src CONFIGURE_DEPENDS framework/src/core/*.cpp framework/src/io/*.cpp framework/src/sim/*.cpp
     framework/src/study/*.cpp framework/src/render/*.cpp framework/src/gui/*.cpp)
list(FILTER _web_src EXCLUDE REGEX "src/render/(offscreen_[a-z]+|video)\\.cpp$")
set(_im "${CLOTHLAB_IMGUI_SOURCE}")
add_library(clothlab_web_imgui STATIC ${_im}/imgui.cpp ${_im}/imgui_draw.cpp ${_im}/imgui_tables.cpp
            ${_im}/imgui_widgets.cpp ${_im}/backends/imgui_impl_glfw.cpp)
target_include_directories(clothlab_web_imgui PUBLIC "${_im}" PRIVATE "${_host}")
target_compile_options(clothlab_web_imgui PRIVATE -w)
add_executable(clothlab-web framework/app/web_main.cpp ${_web_src}
               "${CMAKE_BINARY_DIR}/generated/reference_stages.cpp" "${CMAKE_BINARY_DIR}/generated/header_libs.cpp")
target_include_directories(clothlab-web PRIVATE "${_host}")
target_compile_options(clothlab-web PRIVATE -msimd128)
target_link_libraries(clothlab-web PRIVATE clothlab_headers clothlab_web_imgui)
clothlab_link_stages(clothlab-web "")
# The instructor's copy: the batched kernels (solver.kernel "batched", solutions/kernels/) in the page
# too, for the lecture site's demos; the student copy has none, as natively.
include(cmake/extensions.cmake)
set(_font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
set(_preload "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/scenes@/scenes")  # SHELL: CMake would merge the repeated option
if(EXISTS "${_font}")
  list(APPEND _preload "SHELL:--preload-file ${_font}@${_font}")
endif()
target_link_options(clothlab-web PRIVATE -fexceptions -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
  -sALLOW_MEMORY_GROWTH=1 ${_preload})
set_target_properties(clothlab-web PROPERTIES OUTPUT_NAME clothlab SUFFIX .js)
# The page (a change re-runs the configure step, which copies it again).
configure_file(web/index.html "${CMAKE_BINARY_DIR}/bin/index.html" COPYONLY)
