# The grading kit: everything grading a submission needs from this build, listed in
# build/grade-kit/kit.json for clothlab-grade (framework/grading/grader/submission.h):
#   - a copy of the public headers only (clothlab/core, clothlab/exercise): a submission is
#     compiled in a sandbox that sees these and its own files, nothing else of the tree; beside
#     them a precompiled header of what the stage headers include (grade_kit_precompiled.h), so
#     that compiling a stage does not parse Eigen again;
#   - the compiler and the flags this build compiles with (same ABI, same numerics);
#   - per stage the object files of its graded tests, its reference (solutions/ compiled here, or in the
#     student copy the objects of framework/reference/, when present)
#     its stub and its proxies (the test side of running the submission in a process of its own);
#   - the graded main(), the framework library and GoogleTest to link the test process with, and
#     the main() of the submission process (framework/grading/: test_process/, submission_process/, wire/).
set(_kit "${CMAKE_BINARY_DIR}/grade-kit")
file(GLOB _public CONFIGURE_DEPENDS
  "${PROJECT_SOURCE_DIR}/framework/include/clothlab/core/*.h"
  "${PROJECT_SOURCE_DIR}/framework/include/clothlab/exercise/*.h")
foreach(_h IN LISTS _public)
  file(RELATIVE_PATH _rel "${PROJECT_SOURCE_DIR}/framework/include" "${_h}")
  configure_file("${_h}" "${_kit}/include/${_rel}" COPYONLY)
endforeach()

string(TOUPPER "${CMAKE_BUILD_TYPE}" _config)
separate_arguments(_flags UNIX_COMMAND "-std=c++${CMAKE_CXX_STANDARD} ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${_config}}")
# kit.json is written as text: a value known here goes in with its \ and " escaped; the paths the
# build makes (object files under the build folder) cannot be escaped in a generator expression, so
# the two folders they sit in must hold neither character.
function(_kit_json_string out value)
  string(REPLACE "\\" "\\\\" value "${value}")
  string(REPLACE "\"" "\\\"" value "${value}")
  set(${out} "\"${value}\"" PARENT_SCOPE)
endfunction()
foreach(_dir IN ITEMS "${PROJECT_SOURCE_DIR}" "${CMAKE_BINARY_DIR}")
  if(_dir MATCHES "[\"\\]")
    message(FATAL_ERROR "${_dir}: (folder): a path with \" or \\ in it; the grading kit (kit.json) cannot name the files in it. Use another folder.")
  endif()
endforeach()
set(_flags_json "")
foreach(_f IN LISTS _flags)
  _kit_json_string(_q "${_f}")
  list(APPEND _flags_json "${_q}")
endforeach()
list(JOIN _flags_json ", " _flags_json)
_kit_json_string(_compiler_json "${CMAKE_CXX_COMPILER}")

# The precompiled header, built with the flags the grader compiles submissions with (kit.json's
# compile_flags): GCC uses a .gch only when the compile matches the one that made it.
set(_pch "${_kit}/include/clothlab_precompiled.h")
configure_file("${PROJECT_SOURCE_DIR}/cmake/grade_kit_precompiled.h" "${_pch}" COPYONLY)
add_custom_command(OUTPUT "${_pch}.gch"
  COMMAND ${CMAKE_CXX_COMPILER} ${_flags} "-I${_kit}/include"
          "-isystem$<JOIN:$<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>,;-isystem>"
          -x c++-header "${_pch}" -o "${_pch}.gch" -MD -MF "${_pch}.d"
  DEPENDS "${_pch}" ${_public}
  DEPFILE "${_pch}.d"
  COMMAND_EXPAND_LISTS
  COMMENT "the grading kit's precompiled header (types.h, Eigen)")
add_custom_target(clothlab_kit_precompiled_header DEPENDS "${_pch}.gch")

# The grader links with gold where binutils has it (faster than ld for these programs; the figures
# are in docs/performance.md).
find_program(CLOTHLAB_GOLD_LINKER ld.gold)
set(_link_flags "\"-pthread\", \"-fopenmp\"")
if(CLOTHLAB_GOLD_LINKER)
  string(APPEND _link_flags ", \"-fuse-ld=gold\"")
endif()

set(_stages_json "")
set(_kit_deps clothlab_kit_precompiled_header clothlab-grade clothlab_test_process_main clothlab_framework clothlab_wire clothlab_test_process
  clothlab_submission_main)
foreach(NN IN LISTS CLOTHLAB_STAGES)
  if(NOT TARGET gradedtests_${NN})
    continue()
  endif()
  set(_ref "[]")
  if(CLOTHLAB_HAS_REFERENCE_${NN})  # solutions/ compiled here, or the student copy's reference objects
    set(_ref "[\"$<JOIN:$<TARGET_OBJECTS:stage_${NN}_solutions>,\", \">\"]")
    if(CLOTHLAB_HAS_SOLUTION_${NN})
      list(APPEND _kit_deps stage_${NN}_solutions)
    endif()
  endif()
  if(_stages_json)
    string(APPEND _stages_json ",\n")
  endif()
  string(APPEND _stages_json "    {\"stage\": \"${NN}\", \"dir\": \"${CLOTHLAB_STAGE_DIR_${NN}}\",
     \"tests\": [\"$<JOIN:$<TARGET_OBJECTS:gradedtests_${NN}>,\", \">\"],
     \"reference\": ${_ref},
     \"stub\": [\"$<JOIN:$<TARGET_OBJECTS:stage_${NN}_stubs>,\", \">\"],
     \"proxy\": [\"$<JOIN:$<TARGET_OBJECTS:clothlab_proxies_${NN}>,\", \">\"]}")
  get_target_property(_stubs stage_${NN}_stubs ALIASED_TARGET)
  if(NOT _stubs)
    set(_stubs stage_${NN}_stubs)
  endif()
  list(APPEND _kit_deps gradedtests_${NN} ${_stubs} clothlab_proxies_${NN})
endforeach()

file(GENERATE OUTPUT "${_kit}/kit.json" CONTENT "{
  \"compiler\": ${_compiler_json},
  \"compile_flags\": [${_flags_json}],
  \"include_dir\": \"${_kit}/include\",
  \"precompiled_header\": \"clothlab_precompiled.h\",
  \"system_includes\": [\"$<JOIN:$<TARGET_PROPERTY:Eigen3::Eigen,INTERFACE_INCLUDE_DIRECTORIES>,\", \">\"],
  \"main_objects\": [\"$<JOIN:$<TARGET_OBJECTS:clothlab_test_process_main>,\", \">\"],
  \"libs\": [\"$<TARGET_FILE:clothlab_framework>\", \"$<TARGET_FILE:tinyobjloader::tinyobjloader_double>\", \"$<TARGET_FILE:GTest::gtest>\"],
  \"link_flags\": [${_link_flags}],
  \"client_objects\": [\"$<JOIN:$<TARGET_OBJECTS:clothlab_wire>;$<TARGET_OBJECTS:clothlab_test_process>,\", \">\"],
  \"server_objects\": [\"$<JOIN:$<TARGET_OBJECTS:clothlab_submission_main>;$<TARGET_OBJECTS:clothlab_wire>,\", \">\"],
  \"server_link_flags\": [\"-lseccomp\"],
  \"points_dir\": \"${PROJECT_SOURCE_DIR}/tests\",
  \"stages\": [
${_stages_json}
  ]
}
")
add_custom_target(clothlab-grade-kit ALL COMMENT "the grading kit: ${_kit}/kit.json")
add_dependencies(clothlab-grade-kit ${_kit_deps})
