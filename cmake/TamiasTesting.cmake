# Test registration. Every Boost.Test case carries the SRS labels it verifies
# (`* boost::unit_test::label("DD8")`); tamias_add_boost_test reads them from the sources and
# registers one CTest entry per label, `<target>@<LABEL>`, running `--run_test=@<LABEL>`, so that
# `ctest -L DD8` runs exactly the test cases that verify DD8.

# One shared Boost.Test main, compiled once.
function(_tamias_test_main)
  if(NOT TARGET tamias_test_main)
    add_library(tamias_test_main OBJECT ${PROJECT_SOURCE_DIR}/tests/support/test_main.cpp)
    target_link_libraries(tamias_test_main PUBLIC Boost::unit_test_framework)
    target_compile_definitions(tamias_test_main PUBLIC BOOST_TEST_DYN_LINK)
  endif()
  # One precompiled header for every test executable (compiled once, reused): the same flags
  # as the tests, so that GCC accepts it everywhere.
  if(NOT TARGET tamias_test_pch AND TAMIAS_TEST_PCH)
    add_library(tamias_test_pch OBJECT ${PROJECT_SOURCE_DIR}/tests/support/test_pch.cpp)
    target_link_libraries(tamias_test_pch PRIVATE tamias_test_main tamias2d_internal
                                                  tamias_warnings)
    target_include_directories(tamias_test_pch PRIVATE ${PROJECT_SOURCE_DIR}/tests)
    target_precompile_headers(tamias_test_pch PRIVATE
                              ${PROJECT_SOURCE_DIR}/tests/support/test_pch.hpp)
  endif()
endfunction()

function(tamias_labels_of out)
  set(labels "")
  foreach(src IN LISTS ARGN)
    file(READ ${src} text)
    string(REGEX MATCHALL "label\\(\"[A-Za-z0-9_]+\"\\)" found "${text}")
    foreach(f IN LISTS found)
      string(REGEX REPLACE "label\\(\"([A-Za-z0-9_]+)\"\\)" "\\1" l "${f}")
      list(APPEND labels ${l})
    endforeach()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${src})
  endforeach()
  list(REMOVE_DUPLICATES labels)
  list(SORT labels)
  set(${out} "${labels}" PARENT_SCOPE)
endfunction()

# tamias_add_boost_test(<target> [UNLABELLED] SOURCES a.cpp b.cpp [LIBS ...])
# UNLABELLED: the cases verify no SRS item (reliability, plumbing) and carry no label; they are
# registered as one CTest entry, `<target>.unlabelled`.
function(tamias_add_boost_test target)
  cmake_parse_arguments(T "UNLABELLED" "" "SOURCES;LIBS" ${ARGN})
  _tamias_test_main()
  add_executable(${target} ${T_SOURCES})
  target_link_libraries(${target} PRIVATE tamias_test_main tamias2d_internal tamias_warnings ${T_LIBS})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests)
  if(TAMIAS_TEST_PCH)
    target_precompile_headers(${target} REUSE_FROM tamias_test_pch)
  endif()
  set(abs_sources "")
  foreach(s IN LISTS T_SOURCES)
    get_filename_component(a ${s} ABSOLUTE)
    list(APPEND abs_sources ${a})
  endforeach()
  tamias_labels_of(labels ${abs_sources})
  if(T_UNLABELLED)
    if(labels)
      message(FATAL_ERROR "${target}: UNLABELLED, but its cases carry ${labels}")
    endif()
    add_test(NAME ${target}.unlabelled COMMAND ${target} --color_output=no)
    return()
  endif()
  if(NOT labels)
    message(FATAL_ERROR "${target}: no SRS label in its test cases")
  endif()
  set(disablers "")
  foreach(l IN LISTS labels)
    add_test(NAME ${target}@${l} COMMAND ${target} --run_test=@${l} --color_output=no)
    set_tests_properties(${target}@${l} PROPERTIES LABELS "${l}")
    list(APPEND disablers "!@${l}")
  endforeach()
  # The cases that carry no SRS label (plumbing, API behaviour): every label disabled leaves
  # exactly them. Skipped, not failed, when the executable has none.
  list(JOIN disablers ":" filter)
  add_test(NAME ${target}.unlabelled COMMAND ${target} --run_test=${filter} --color_output=no)
  set_tests_properties(${target}.unlabelled PROPERTIES
                       SKIP_REGULAR_EXPRESSION "no test cases matching filter")
endfunction()

# tamias_add_compile_fail(<name> SOURCE f.cpp LABELS DD2 ...)
# The file must compile as is (its correct, unit-checked form: a positive control built with
# everything else) and must NOT compile with TAMIAS_WRONG_FORM defined (the seed's form).
function(tamias_add_compile_fail name)
  cmake_parse_arguments(T "" "SOURCE" "LABELS" ${ARGN})
  add_library(${name}_correct OBJECT ${T_SOURCE})
  target_link_libraries(${name}_correct PRIVATE tamias2d_internal tamias_warnings)
  add_library(${name}_wrong OBJECT EXCLUDE_FROM_ALL ${T_SOURCE})
  target_link_libraries(${name}_wrong PRIVATE tamias2d_internal)
  target_compile_definitions(${name}_wrong PRIVATE TAMIAS_WRONG_FORM)
  add_test(NAME compile_fail.${name}
           COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target ${name}_wrong)
  # Passes only when the build fails on a Boost.Units quantity (not a typo or a missing file).
  # Concurrent builds in one tree are unsafe: serialise the compile-fail tests.
  set_tests_properties(compile_fail.${name} PROPERTIES
                       PASS_REGULAR_EXPRESSION "error: [^\n]*quantity<"
                       LABELS "${T_LABELS};compile_fail" RESOURCE_LOCK build_tree)
endfunction()
