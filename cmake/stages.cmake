# The stage mechanism. Every folder exercises/NN_name is a stage; its .cpp files implement the
# functions declared in framework/include/clothlab/exercise/NN_name.h. Each stage is compiled as
# OBJECT libraries, one per source of code:
#   stage_NN_exercises   the student stubs (exercises/NN_name)
#   stage_NN_solutions   the reference: solutions/NN_name (the instructor's tree), or in the student
#                        copy its compiled objects framework/reference/NN_name/*.o (./lab release),
#                        an IMPORTED object library
#   stage_NN_stubs       the untouched stubs (framework/stubs/NN_name in the student copy, else exercises/)
# and CLOTHLAB_IMPL_NN names the one the apps and the other stages' tests link.

file(GLOB _stage_dirs RELATIVE "${PROJECT_SOURCE_DIR}/exercises" "${PROJECT_SOURCE_DIR}/exercises/[0-9][0-9]_*")
list(SORT _stage_dirs)
set(CLOTHLAB_STAGES "")

# Headers every stage sees: the exercise API and the core types (Eigen only, no GL).
add_library(clothlab_headers INTERFACE)
target_include_directories(clothlab_headers INTERFACE "${PROJECT_SOURCE_DIR}/framework/include")
target_link_libraries(clothlab_headers INTERFACE Eigen3::Eigen)

function(clothlab_stage_library target dir)
  file(GLOB _src CONFIGURE_DEPENDS "${dir}/*.cpp")
  if(NOT _src)
    message(FATAL_ERROR "clothlab: no .cpp files in ${dir}")
  endif()
  add_library(${target} OBJECT ${_src})
  target_link_libraries(${target} PUBLIC clothlab_headers)
endfunction()

# The reference as compiled objects (the student copy; ./lab release --no-reference-objects leaves them
# out): framework/reference/compiler.txt records the compiler that made them. They link only with the
# same compiler (C++ ABI, the inlined Eigen and standard library code), so with another compiler they
# are ignored, with a warning.
option(CLOTHLAB_REFERENCE_OBJECTS "use the reference objects of framework/reference/ (student copy)" ON)
# The browser's build (cmake/web.cmake, em++) has its own: framework/reference/web/ (./lab release where
# Emscripten is installed).
set(_refobj_root "${PROJECT_SOURCE_DIR}/framework/reference")
set(_refobj_name "framework/reference/")
if(CLOTHLAB_WEB)
  set(_refobj_root "${_refobj_root}/web")
  set(_refobj_name "framework/reference/web/")
endif()
set(_refobj_ok OFF)
if(CLOTHLAB_REFERENCE_OBJECTS AND EXISTS "${_refobj_root}/compiler.txt")
  file(STRINGS "${_refobj_root}/compiler.txt" _lines REGEX "^[a-z_]+=")
  foreach(_l IN LISTS _lines)
    string(REGEX MATCH "^([a-z_]+)=(.*)$" _ "${_l}")
    set(_refobj_${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
  endforeach()
  set(_ours "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} (${CMAKE_SYSTEM_PROCESSOR}, C++${CMAKE_CXX_STANDARD}, CXXFLAGS '${CMAKE_CXX_FLAGS}')")
  set(_theirs "${_refobj_compiler_id} ${_refobj_compiler_version} (${_refobj_processor}, C++${_refobj_cxx_standard}, CXXFLAGS '${_refobj_cxx_flags}')")
  if(_ours STREQUAL _theirs)
    set(_refobj_ok ON)
  else()
    message(WARNING "clothlab: ${_refobj_name} holds the reference stages compiled by ${_theirs} "
      "on ${_refobj_system}; this build uses ${_ours}. Objects of another compiler do not link safely, so "
      "they are not used: --reference and grading with the reference for the other stages are unavailable. "
      "Build with that compiler (CXX=..., a fresh build folder), or ask for a copy released on your system.")
  endif()
endif()
# Where CMake writes what ./lab release copies into the student copy (instructor's tree).
set(_refobj_out "${CMAKE_BINARY_DIR}/reference-objects")

foreach(_dir IN LISTS _stage_dirs)
  string(SUBSTRING "${_dir}" 0 2 NN)
  list(APPEND CLOTHLAB_STAGES ${NN})
  set(CLOTHLAB_STAGE_DIR_${NN} "${_dir}" CACHE INTERNAL "")
  clothlab_stage_library(stage_${NN}_exercises "${PROJECT_SOURCE_DIR}/exercises/${_dir}")
  # The untouched stubs, for the grading kit (a stage's functions; the stand-in for a stage that does
  # not compile). In the student copy exercises/ is the student's work: ./lab release keeps the
  # pristine stubs in framework/stubs/, so grading never waits for the student's files to compile.
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/framework/stubs/${_dir}")
    clothlab_stage_library(stage_${NN}_stubs "${PROJECT_SOURCE_DIR}/framework/stubs/${_dir}")
  else()
    add_library(stage_${NN}_stubs ALIAS stage_${NN}_exercises)
  endif()
  # CLOTHLAB_HAS_SOLUTION_NN: the reference SOURCE is here (the instructor's tree; its own tests need it).
  # CLOTHLAB_HAS_REFERENCE_NN: a reference to link is here, source or objects (--reference, grading).
  set(_has_solution OFF)
  set(_has_objects OFF)
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/solutions/${_dir}")
    clothlab_stage_library(stage_${NN}_solutions "${PROJECT_SOURCE_DIR}/solutions/${_dir}")
    set(_has_solution ON)
    file(GENERATE OUTPUT "${_refobj_out}/${_dir}.txt" CONTENT "$<JOIN:$<TARGET_OBJECTS:stage_${NN}_solutions>,\n>\n")
  elseif(_refobj_ok)
    file(GLOB _objs "${_refobj_root}/${_dir}/*.o")
    if(_objs)
      add_library(stage_${NN}_solutions OBJECT IMPORTED GLOBAL)
      set_target_properties(stage_${NN}_solutions PROPERTIES IMPORTED_OBJECTS "${_objs}")
      target_link_libraries(stage_${NN}_solutions INTERFACE clothlab_headers)
      set(_has_objects ON)
    endif()
  endif()
  set(CLOTHLAB_HAS_SOLUTION_${NN} ${_has_solution} CACHE INTERNAL "")
  set(CLOTHLAB_HAS_REFERENCE_OBJECTS_${NN} ${_has_objects} CACHE INTERNAL "")
  set(_has_reference OFF)
  if(_has_solution OR _has_objects)
    set(_has_reference ON)
  endif()
  set(CLOTHLAB_HAS_REFERENCE_${NN} ${_has_reference} CACHE INTERNAL "")

  set(_reference OFF)
  if(NOT _has_reference AND NN IN_LIST CLOTHLAB_REFERENCE_STAGES)
    message(WARNING "clothlab: --reference ${NN}: this copy has no reference for stage ${NN} (no solutions/${_dir}, "
      "no usable ${_refobj_name}${_dir}/*.o); stage ${NN} uses your code in exercises/${_dir}")
  endif()
  if(_has_reference AND ("all" IN_LIST CLOTHLAB_REFERENCE_STAGES OR NN IN_LIST CLOTHLAB_REFERENCE_STAGES))
    set(_reference ON)
  endif()
  if(_has_solution AND CLOTHLAB_CODE STREQUAL "solutions")  # the framework tests need the source
    set(_impl stage_${NN}_solutions)
  else()
    set(_impl stage_${NN}_exercises)
  endif()
  if(_reference)
    set(_impl stage_${NN}_solutions)
  endif()
  set(CLOTHLAB_IMPL_${NN} ${_impl} CACHE INTERNAL "")
endforeach()
# Whether any stage has a reference here (source or objects), which stages have one ("01,02,...") and
# which this build uses (the programs' advice on an unfinished task, framework/app/stub_advice.h).
set(CLOTHLAB_REFERENCE_AVAILABLE OFF)
set(CLOTHLAB_REFERENCE_HAVE "")
set(CLOTHLAB_REFERENCE_USED "")
foreach(NN IN LISTS CLOTHLAB_STAGES)
  if(CLOTHLAB_HAS_REFERENCE_${NN})
    set(CLOTHLAB_REFERENCE_AVAILABLE ON)
    list(APPEND CLOTHLAB_REFERENCE_HAVE ${NN})
  endif()
  if(CLOTHLAB_IMPL_${NN} STREQUAL "stage_${NN}_solutions")
    list(APPEND CLOTHLAB_REFERENCE_USED ${NN})
  endif()
endforeach()
string(REPLACE ";" "," CLOTHLAB_REFERENCE_HAVE "${CLOTHLAB_REFERENCE_HAVE}")
string(REPLACE ";" "," CLOTHLAB_REFERENCE_USED "${CLOTHLAB_REFERENCE_USED}")
# Which code each stage runs, for the app's stage panel: "01_hooke=reference;02_mfn=student".
set(CLOTHLAB_STAGE_CODE "")
foreach(NN IN LISTS CLOTHLAB_STAGES)
  if(CLOTHLAB_IMPL_${NN} STREQUAL "stage_${NN}_solutions")
    string(APPEND CLOTHLAB_STAGE_CODE "${CLOTHLAB_STAGE_DIR_${NN}}=reference;")
  else()
    string(APPEND CLOTHLAB_STAGE_CODE "${CLOTHLAB_STAGE_DIR_${NN}}=student;")
  endif()
endforeach()
# The compiler of this build, for ./lab release (framework/reference/compiler.txt in the student copy).
cmake_host_system_information(RESULT _distro QUERY DISTRIB_PRETTY_NAME)
file(CONFIGURE OUTPUT "${_refobj_out}/compiler.txt" CONTENT "compiler_id=${CMAKE_CXX_COMPILER_ID}
compiler_version=${CMAKE_CXX_COMPILER_VERSION}
processor=${CMAKE_SYSTEM_PROCESSOR}
cxx_standard=${CMAKE_CXX_STANDARD}
cxx_flags=${CMAKE_CXX_FLAGS}
build_type=${CMAKE_BUILD_TYPE}
system=${_distro}
" @ONLY)
message(STATUS "clothlab: stages ${CLOTHLAB_STAGES}")
foreach(NN IN LISTS CLOTHLAB_STAGES)
  message(STATUS "clothlab:   stage ${NN} (${CLOTHLAB_STAGE_DIR_${NN}}) uses ${CLOTHLAB_IMPL_${NN}}")
endforeach()

# Links every stage's chosen implementation into `target`, except stage `except` (or none: "").
function(clothlab_link_stages target except)
  foreach(NN IN LISTS CLOTHLAB_STAGES)
    if(NOT NN STREQUAL except)
      target_link_libraries(${target} PRIVATE ${CLOTHLAB_IMPL_${NN}})
    endif()
  endforeach()
endfunction()
