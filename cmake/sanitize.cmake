# Sanitizers and the fuzzed scene loader (docs/reliability.md).
#
# CLOTHLAB_SANITIZE=ON: every target is built with AddressSanitizer and UndefinedBehaviorSanitizer,
# and the first report aborts the program (-fno-sanitize-recover; ASAN_OPTIONS/UBSAN_OPTIONS in the
# tests say halt_on_error=1 too). ./lab test --sanitize configures such a build in build-sanitize/.
# CLOTHLAB_FUZZ=ON (clang only): the libFuzzer target scene_fuzz over the scene loader (tests/fuzz/).
option(CLOTHLAB_SANITIZE "build every target with AddressSanitizer + UndefinedBehaviorSanitizer" OFF)
option(CLOTHLAB_FUZZ "build the libFuzzer target scene_fuzz (needs clang; tests/fuzz/run.sh)" OFF)
set(CLOTHLAB_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
if(CLOTHLAB_SANITIZE)
  add_compile_options(${CLOTHLAB_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()
if(CLOTHLAB_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "error: CLOTHLAB_FUZZ=ON needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ (tests/fuzz/run.sh does)")
elseif(CLOTHLAB_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)  # coverage feedback from every file, not only the target's
endif()

# After every test is added: in a sanitized build, the tests that can run under the sanitizers get
# their environment; the graded tests run directly (plain GoogleTest), since the grader's sandbox
# caps the address space at 4 GB (sandbox.h) and ASan reserves terabytes of shadow memory.
function(clothlab_add_sanitize_tests)
  if(CLOTHLAB_FUZZ)
    add_executable(scene_fuzz "${PROJECT_SOURCE_DIR}/tests/fuzz/scene_fuzz.cpp")
    target_compile_options(scene_fuzz PRIVATE -fsanitize=fuzzer)
    target_link_options(scene_fuzz PRIVATE -fsanitize=fuzzer)
    target_link_libraries(scene_fuzz PRIVATE clothlab_framework)
    clothlab_link_stages(scene_fuzz "")
  endif()
  if(NOT CLOTHLAB_CODE STREQUAL "solutions")
    return()  # the student copy: a scene that loads would run into the stubs
  endif()
  # Every input the fuzzer found, through the command line: one error line naming file and field.
  add_test(NAME fuzz.regressions COMMAND bash "${PROJECT_SOURCE_DIR}/tests/fuzz/regressions_test.sh"
           $<TARGET_FILE:clothlab> "${PROJECT_SOURCE_DIR}/tests/fuzz/regressions")
  if(NOT CLOTHLAB_SANITIZE AND NOT CLOTHLAB_FUZZ)
    # The fast sanitizer check of ./lab test (label sanitize): the scene loader, the report writers
    # and the CLI compiled once more with ASan + UBSan (the simulation is the normal build's: a few
    # files to compile, not the framework), run on every scene and every bad input (cli_test.sh);
    # and the fuzz target, built the same way, replays the seeds and the regressions.
    set(_io "${PROJECT_SOURCE_DIR}/framework/src/io/scene_json.cpp" "${PROJECT_SOURCE_DIR}/framework/src/io/report.cpp")
    file(GLOB _cli CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/framework/app/main.cpp" "${PROJECT_SOURCE_DIR}/framework/app/cmd_*.cpp")
    # The loader compiled once for both programs; -O0: these files are template-heavy (JSON, CLI11) and
    # an optimised sanitized build of them took 7 of the build's 25 CPU minutes, for no finding more.
    add_library(clothlab_io_sanitized OBJECT ${_io})
    add_executable(clothlab-sanitized ${_cli})
    add_executable(scene_fuzz_replay "${PROJECT_SOURCE_DIR}/tests/fuzz/scene_fuzz.cpp" "${PROJECT_SOURCE_DIR}/tests/fuzz/replay_main.cpp")
    target_link_libraries(clothlab-sanitized PRIVATE clothlab_reference_stages CLI11::CLI11)
    clothlab_link_extensions(clothlab-sanitized)
    target_link_libraries(clothlab_io_sanitized PRIVATE clothlab_framework)  # its include paths and definitions
    foreach(_t clothlab_io_sanitized clothlab-sanitized scene_fuzz_replay)
      target_compile_options(${_t} PRIVATE ${CLOTHLAB_SANITIZER_FLAGS} -O0)
      # Eigen frees with its own aligned allocator when it sees __SANITIZE_ADDRESS__ and with plain free
      # otherwise: matrices cross between these objects and the normal build's, so both use glibc's
      # (16-byte aligned) malloc and free.
      target_compile_definitions(${_t} PRIVATE EIGEN_MALLOC_ALREADY_ALIGNED=1)
      target_compile_definitions(${_t} PRIVATE CLOTHLAB_REFERENCE_AVAILABLE=$<BOOL:${CLOTHLAB_REFERENCE_AVAILABLE}>)
    endforeach()
    foreach(_t clothlab-sanitized scene_fuzz_replay)
      target_link_options(${_t} PRIVATE -fsanitize=address,undefined)
      # The loader's own objects come first (an object library's objects are linked as files).
      target_link_libraries(${_t} PRIVATE clothlab_io_sanitized clothlab_framework)
      clothlab_link_stages(${_t} "")
    endforeach()
    set(_env "ASAN_OPTIONS=halt_on_error=1:detect_leaks=1" "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1"
             "OMP_NUM_THREADS=1" "OMP_WAIT_POLICY=passive")
    add_test(NAME sanitize.cli_bad_input COMMAND bash "${PROJECT_SOURCE_DIR}/tests/cli/cli_test.sh"
             $<TARGET_FILE:clothlab-sanitized> "${PROJECT_SOURCE_DIR}")
    add_test(NAME sanitize.fuzz_replay COMMAND scene_fuzz_replay "${PROJECT_SOURCE_DIR}/scenes"
             "${PROJECT_SOURCE_DIR}/tests/fuzz/seeds" "${PROJECT_SOURCE_DIR}/tests/fuzz/regressions")
    set_tests_properties(sanitize.cli_bad_input sanitize.fuzz_replay PROPERTIES LABELS sanitize ENVIRONMENT "${_env}")
    # The sanitized command line on every bad input is label heavy too (./lab test --heavy builds it;
    # 75 CPU s to compile, 70 s to run); ./lab test keeps the sanitized loader (fuzz_replay: the seeds,
    # every scene and every fuzzer finding), and ./lab test --sanitize runs everything sanitized.
    set_tests_properties(sanitize.cli_bad_input PROPERTIES LABELS "sanitize;heavy")
    set_target_properties(clothlab-sanitized PROPERTIES EXCLUDE_FROM_ALL TRUE)
    add_dependencies(clothlab_heavy_builds clothlab-sanitized)
    return()
  endif()
  if(NOT CLOTHLAB_SANITIZE)
    return()
  endif()
  # ./lab test --sanitize: with clang there too, the libFuzzer build (tests/fuzz/run.sh, in
  # build-sanitize/fuzz): the seeds and regressions, 10 s of fuzzing, cli_test.sh on its CLI.
  find_program(CLOTHLAB_CLANGXX clang++)
  if(CLOTHLAB_CLANGXX)
    add_test(NAME sanitize.fuzz_check COMMAND bash "${PROJECT_SOURCE_DIR}/tests/fuzz/run.sh" "${PROJECT_BINARY_DIR}/fuzz" check)
    set_tests_properties(sanitize.fuzz_check PROPERTIES LABELS sanitize TIMEOUT 1800)
  endif()
  foreach(NN IN LISTS CLOTHLAB_STAGES)
    if(TARGET grade_${NN}_solutions)
      add_test(NAME sanitize.stage_${NN}.reference_passes COMMAND grade_${NN}_solutions)
      set_tests_properties(sanitize.stage_${NN}.reference_passes PROPERTIES
        ENVIRONMENT "CLOTHLAB_ANSWERS_DIR=${PROJECT_SOURCE_DIR}/solutions/${CLOTHLAB_STAGE_DIR_${NN}}")
    endif()
  endforeach()
endfunction()
