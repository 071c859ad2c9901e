# Test hygiene: the tests write only into temp or build folders, never into the source tree.
# Where the source is a git checkout, the CTest fixture `clean_source_tree` records
# `git status --porcelain` before the tests (hygiene.source_tree_snapshot) and fails after them
# if it changed (hygiene.source_tree_unchanged). Every test requires the fixture, so both run
# around any selection of tests (ctest -R ...).
set(CLOTHLAB_TREE_CHECK OFF)
find_package(Git QUIET)
if(GIT_FOUND AND EXISTS "${PROJECT_SOURCE_DIR}/.git")  # .git is a file in a worktree
  set(CLOTHLAB_TREE_CHECK ON)
endif()

# A build folder inside the source tree that .gitignore does not cover (e.g. ./mybuild) would show
# up in `git status` as soon as a test writes there: it ignores itself, as meson's do.
file(RELATIVE_PATH _rel "${PROJECT_SOURCE_DIR}" "${PROJECT_BINARY_DIR}")
if(NOT _rel MATCHES "^\\.\\./" AND NOT IS_ABSOLUTE "${_rel}" AND NOT _rel STREQUAL "")
  file(WRITE "${PROJECT_BINARY_DIR}/.gitignore" "# clothlab build folder: ignored by git\n*\n")
endif()

# Call at the end of every CMakeLists.txt that adds tests with add_test(): its tests require the fixture.
# (gtest_discover_tests(... PROPERTIES ${CLOTHLAB_TREE_FIXTURE}) does the same for discovered tests.)
# Without git the fixture has no tests, and CTest ignores it.
function(clothlab_require_clean_tree)
  get_property(_tests DIRECTORY PROPERTY TESTS)
  list(REMOVE_ITEM _tests hygiene.source_tree_snapshot hygiene.source_tree_unchanged)
  if(_tests)
    set_property(TEST ${_tests} APPEND PROPERTY FIXTURES_REQUIRED clean_source_tree)
  endif()
endfunction()
set(CLOTHLAB_TREE_FIXTURE FIXTURES_REQUIRED clean_source_tree)

# The fixture's two tests; call once, after every test is added (end of the top-level CMakeLists.txt).
# Tests of folders that do not call clothlab_require_clean_tree() still run before the check (DEPENDS).
function(clothlab_add_source_tree_check)
  if(NOT CLOTHLAB_TREE_CHECK)
    return()
  endif()
  set(_script "${PROJECT_SOURCE_DIR}/tests/structure/source_tree_check.sh")
  set(_snapshot "${PROJECT_BINARY_DIR}/hygiene/git_status_before.txt")
  add_test(NAME hygiene.source_tree_snapshot COMMAND bash "${_script}" snapshot "${PROJECT_SOURCE_DIR}" "${_snapshot}")
  add_test(NAME hygiene.source_tree_unchanged COMMAND bash "${_script}" compare "${PROJECT_SOURCE_DIR}" "${_snapshot}")
  set_tests_properties(hygiene.source_tree_snapshot PROPERTIES FIXTURES_SETUP clean_source_tree)
  set_tests_properties(hygiene.source_tree_unchanged PROPERTIES FIXTURES_CLEANUP clean_source_tree)
  set(_all "")
  set(_dirs "${PROJECT_SOURCE_DIR}")
  while(_dirs)
    list(POP_FRONT _dirs _d)
    get_property(_sub DIRECTORY "${_d}" PROPERTY SUBDIRECTORIES)
    get_property(_t DIRECTORY "${_d}" PROPERTY TESTS)
    list(APPEND _dirs ${_sub})
    list(APPEND _all ${_t})
  endwhile()
  list(REMOVE_ITEM _all hygiene.source_tree_snapshot hygiene.source_tree_unchanged)
  if(_all)
    set_tests_properties(hygiene.source_tree_unchanged PROPERTIES DEPENDS "${_all}")
  endif()
endfunction()
