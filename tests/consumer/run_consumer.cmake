cmake_minimum_required(VERSION 3.25)
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DEXAMPLE_EXE=... -DRUNNER_EXE=...
#       -DSCENE=... -DMODES="install;pkgconfig;fetchcontent" [-DCXX=...] -P run_consumer.cmake
# CXX: the compiler of the build tree (default c++), for the consumers too: a FetchContent
# build compiles the library again, and its build line (the solver's code path) must match.
# Installs the build tree into WORK_DIR/prefix and builds a separate project against it (the
# CMake package, then the pkg-config file), and against the source tree through FetchContent.
# Oracle: each consumer's programs print exactly what the same programs built inside the
# project's own tree print (same source, same library: the same bits).
foreach(v BUILD_DIR SOURCE_DIR WORK_DIR EXAMPLE_EXE RUNNER_EXE SCENE MODES)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_consumer.cmake: -D${v}=... is required")
  endif()
endforeach()
if(NOT DEFINED CXX)
  find_program(CXX NAMES c++ g++ clang++ REQUIRED)
endif()
set(example_src ${SOURCE_DIR}/apps/examples/two_bodies.cpp)
set(runner_src ${SOURCE_DIR}/tests/consumer/project/scene_runner.cpp)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

run(${EXAMPLE_EXE})
set(expected_example "${out}")
run(${RUNNER_EXE} ${SCENE})
set(expected_runner "${out}")

function(expect_same what exe)
  run(${exe} ${ARGN})
  if(what STREQUAL "example")
    set(expected "${expected_example}")
  else()
    set(expected "${expected_runner}")
  endif()
  if(NOT out STREQUAL expected)
    message(FATAL_ERROR "${exe} printed\n${out}\nbut the project's own build printed\n${expected}")
  endif()
  message(STATUS "OK: ${exe}")
endfunction()

set(prefix ${WORK_DIR}/prefix)
if("install" IN_LIST MODES OR "pkgconfig" IN_LIST MODES)
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  # The exported target carries the no-contraction flag to the game's compilations.
  file(GLOB_RECURSE targets_file ${prefix}/tamias2dTargets.cmake)
  file(READ "${targets_file}" targets_text)
  if(NOT targets_text MATCHES "-ffp-contract=off")
    message(FATAL_ERROR "${targets_file} does not export -ffp-contract=off")
  endif()
  foreach(private units model dynamics collision geometry memory math)
    if(EXISTS ${prefix}/include/tamias2d/${private})
      message(FATAL_ERROR "the install holds the private headers' folder ${private}/")
    endif()
  endforeach()
endif()

if("install" IN_LIST MODES)
  set(b ${WORK_DIR}/package)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${b} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix}
      -DTAMIAS_CONSUMER_MODE=package
      -DTAMIAS_EXAMPLE=${example_src})
  run(${CMAKE_COMMAND} --build ${b})
  expect_same(example ${b}/two_bodies)
  expect_same(runner ${b}/scene_runner ${SCENE})
endif()

if("pkgconfig" IN_LIST MODES)
  file(GLOB_RECURSE pc_file ${prefix}/tamias2d.pc)
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  run(pkg-config --cflags --libs tamias2d)
  string(STRIP "${out}" core_flags)
  if(NOT core_flags MATCHES "-ffp-contract=off")
    message(FATAL_ERROR "pkg-config --cflags tamias2d lacks -ffp-contract=off: ${core_flags}")
  endif()
  separate_arguments(core_flags UNIX_COMMAND "${core_flags}")
  run(pkg-config --cflags --libs tamias2d-io)
  string(STRIP "${out}" io_flags)
  separate_arguments(io_flags UNIX_COMMAND "${io_flags}")
  run(${CXX} -std=c++20 -O2 ${example_src} ${core_flags} -o ${WORK_DIR}/two_bodies_pc)
  expect_same(example ${WORK_DIR}/two_bodies_pc)
  run(${CXX} -std=c++20 -O2 ${runner_src} ${io_flags} -o ${WORK_DIR}/scene_runner_pc)
  expect_same(runner ${WORK_DIR}/scene_runner_pc ${SCENE})
endif()

if("fetchcontent" IN_LIST MODES)
  set(b ${WORK_DIR}/fetchcontent)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer/project -B ${b} -G Ninja
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX} -DTAMIAS_CONSUMER_MODE=fetchcontent
      -DTAMIAS_SOURCE_DIR=${SOURCE_DIR} -DTAMIAS_EXAMPLE=${example_src})
  run(${CMAKE_COMMAND} --build ${b} -j2)
  expect_same(example ${b}/two_bodies)
  expect_same(runner ${b}/scene_runner ${SCENE})
endif()
