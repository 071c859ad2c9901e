# Extensions: faster implementations that register themselves at the solver's extension point
# (framework/include/clothlab/sim/kernel_registry.h). The framework never names them; this file links
# them into the programs. They are solved exercises, so they live in solutions/kernels/ and the
# student copy (./lab release) has none: there, solver.kernel allows only "exercise".
#
# clothlab_kernels: the batched distance and bending kernels and self-collision pairs (solver.kernel "batched"). An OBJECT library,
# so that its registering static initialiser is linked into every program that links it.
# Compiled for speed: vector loops (`#pragma omp simd`), the blocks of a colour group on all cores
# (`#pragma omp parallel for`, OpenMP), sqrt without errno.
if(NOT IS_DIRECTORY "${PROJECT_SOURCE_DIR}/solutions/kernels")
  function(clothlab_link_extensions target)
  endfunction()
  return()
endif()

add_library(clothlab_kernels OBJECT
  "${PROJECT_SOURCE_DIR}/solutions/kernels/bending_batched.cpp"
  "${PROJECT_SOURCE_DIR}/solutions/kernels/distance_batched.cpp"
  "${PROJECT_SOURCE_DIR}/solutions/kernels/neighbour_pairs_batched.cpp"
  "${PROJECT_SOURCE_DIR}/solutions/kernels/register_batched.cpp")
target_include_directories(clothlab_kernels PUBLIC "${PROJECT_SOURCE_DIR}/solutions/kernels")
target_link_libraries(clothlab_kernels PUBLIC clothlab_headers)
if(EMSCRIPTEN)  # the browser (./lab web): one thread, so OpenMP's vector pragmas only, WebAssembly SIMD
  target_compile_options(clothlab_kernels PRIVATE -O3 -fno-math-errno -fno-trapping-math -fopenmp-simd -msimd128
                         -Wno-source-uses-openmp)
elseif(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(clothlab_kernels PRIVATE -O3 -fno-math-errno -fno-trapping-math)
  find_package(OpenMP REQUIRED)
  target_link_libraries(clothlab_kernels PRIVATE OpenMP::OpenMP_CXX)
endif()
# No fused multiply-adds in the distance sweep: its vector loop and scalar remainder then round alike,
# whichever link starts a thread's share (bit-identical for every number of threads).
set_source_files_properties("${PROJECT_SOURCE_DIR}/solutions/kernels/distance_batched.cpp" PROPERTIES COMPILE_OPTIONS -ffp-contract=off)
# Never link-time optimised: the link step would recompile it without the flags above and lose its
# vector loops.
set_property(TARGET clothlab_kernels PROPERTY INTERPROCEDURAL_OPTIMIZATION OFF)

# Links the extensions into a program (called for the CLI, the renderer, the app, the framework
# tests and the benchmarks).
function(clothlab_link_extensions target)
  if(TARGET ${target})
    target_link_libraries(${target} PRIVATE clothlab_kernels)
  endif()
endfunction()
foreach(_t clothlab clothlab-render clothlab-render-egl clothlab-gui clothlab-web)
  clothlab_link_extensions(${_t})
endforeach()
