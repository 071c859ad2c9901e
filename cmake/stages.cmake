# The stage mechanism. Every folder exercises/NN_name is a stage; its .cpp files implement the
# functions declared in framework/include/clothlab/exercise/NN_name.h. Each stage is compiled as
# OBJECT libraries, one per source of code:
#   stage_NN_exercises   the student stubs (exercises/NN_name)
#   stage_NN_solutions   the reference (solutions/NN_name), when present
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
  set(_has_solution OFF)
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/solutions/${_dir}")
    clothlab_stage_library(stage_${NN}_solutions "${PROJECT_SOURCE_DIR}/solutions/${_dir}")
    set(_has_solution ON)
  endif()
  set(CLOTHLAB_HAS_SOLUTION_${NN} ${_has_solution} CACHE INTERNAL "")

  set(_reference OFF)
  if(NOT _has_solution AND NN IN_LIST CLOTHLAB_REFERENCE_STAGES)
    message(WARNING "clothlab: --reference ${NN}: there is no solutions/${_dir} here; stage ${NN} uses the student code")
  endif()
  if(_has_solution AND ("all" IN_LIST CLOTHLAB_REFERENCE_STAGES OR NN IN_LIST CLOTHLAB_REFERENCE_STAGES))
    set(_reference ON)
  endif()
  if(_has_solution AND CLOTHLAB_CODE STREQUAL "solutions")
    set(_impl stage_${NN}_solutions)
  else()
    set(_impl stage_${NN}_exercises)
  endif()
  if(_reference)
    set(_impl stage_${NN}_solutions)
  endif()
  set(CLOTHLAB_IMPL_${NN} ${_impl} CACHE INTERNAL "")
endforeach()
# Whether any stage has its reference here (the instructor's tree; not the student copy).
set(CLOTHLAB_REFERENCE_AVAILABLE OFF)
foreach(NN IN LISTS CLOTHLAB_STAGES)
  if(CLOTHLAB_HAS_SOLUTION_${NN})
    set(CLOTHLAB_REFERENCE_AVAILABLE ON)
  endif()
endforeach()
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
