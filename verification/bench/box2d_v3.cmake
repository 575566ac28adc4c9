# Box2D v3 from its source tree (TAMIAS_BOX2D_V3_DIR), never copied into this repository: one
# static library per SIMD build over its src/*.c with its own settings (C17 with extensions,
# -ffp-contract=off as its CMakeLists sets, the build type's optimisation, float), and one engine
# worker executable per library. Its CMakeLists is not added as a subdirectory: its target
# box2d::box2d would clash with Box2D 2.4's imported one, and its install rules would become ours.
# A tree that has gone since the cache was written leaves v3 out (the report then says "not
# measured") instead of failing a configure that does not need it.
if(NOT EXISTS ${TAMIAS_BOX2D_V3_DIR}/include/box2d/box2d.h OR
   NOT EXISTS ${TAMIAS_BOX2D_V3_DIR}/src/physics_world.c)
  message(WARNING "TAMIAS_BOX2D_V3_DIR=${TAMIAS_BOX2D_V3_DIR} is not a Box2D v3 source tree: "
                  "Box2D v3 is not built")
  return()
endif()
enable_language(C)
find_package(Threads REQUIRED)
file(GLOB box2d_v3_sources CONFIGURE_DEPENDS ${TAMIAS_BOX2D_V3_DIR}/src/*.c)

# The AVX2 build only where this machine can run it; tamias_bench checks again at run time.
set(box2d_v3_variants sse2)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64" AND EXISTS /proc/cpuinfo)
  file(READ /proc/cpuinfo cpuinfo)
  if(cpuinfo MATCHES "[ \t]avx2[ \t\n]")
    list(APPEND box2d_v3_variants avx2)
  endif()
endif()

# What the report's set-up table says about v3: version, upstream commit (ORIGIN.md), flags.
file(STRINGS ${TAMIAS_BOX2D_V3_DIR}/CMakeLists.txt v3_version_line REGEX "^[ \t]*VERSION [0-9.]+")
string(REGEX MATCH "[0-9]+\\.[0-9]+\\.[0-9]+" v3_version "${v3_version_line}")
set(v3_commit "")
if(EXISTS ${TAMIAS_BOX2D_V3_DIR}/ORIGIN.md)
  file(READ ${TAMIAS_BOX2D_V3_DIR}/ORIGIN.md v3_origin)
  string(REGEX MATCH "commit [0-9a-f]+" v3_commit "${v3_origin}")
endif()
get_filename_component(v3_dir "${TAMIAS_BOX2D_V3_DIR}" ABSOLUTE)
string(TOUPPER "${CMAKE_BUILD_TYPE}" v3_build_type)
string(STRIP "${CMAKE_C_FLAGS} ${CMAKE_C_FLAGS_${v3_build_type}}" v3_c_flags)

foreach(variant IN LISTS box2d_v3_variants)
  set(lib tamias_box2d_v3_${variant})
  add_library(${lib} STATIC ${box2d_v3_sources})
  target_include_directories(${lib} SYSTEM PUBLIC ${TAMIAS_BOX2D_V3_DIR}/include)
  target_include_directories(${lib} PRIVATE ${TAMIAS_BOX2D_V3_DIR}/src)
  set_target_properties(${lib} PROPERTIES C_STANDARD 17 C_STANDARD_REQUIRED ON C_EXTENSIONS ON)
  target_compile_options(${lib} PRIVATE -ffp-contract=off)
  if(variant STREQUAL "avx2")
    target_compile_definitions(${lib} PRIVATE BOX2D_AVX2)
    target_compile_options(${lib} PRIVATE -mavx2)
  endif()
  target_link_libraries(${lib} PUBLIC m Threads::Threads)

  add_executable(tamias_bench_v3_${variant} engine_worker.cpp box2d_v3_engine.cpp)
  target_link_libraries(tamias_bench_v3_${variant} PRIVATE ${lib} tamias_warnings)
  add_dependencies(tamias_bench tamias_bench_v3_${variant})
  add_dependencies(tamias_thread_bench tamias_bench_v3_${variant})
  add_dependencies(tamias_work_precision tamias_bench_v3_${variant})
  string(TOUPPER ${variant} VARIANT)
  set_property(SOURCE remote_engine.cpp APPEND PROPERTY COMPILE_DEFINITIONS
               "TAMIAS_BENCH_V3_${VARIANT}_WORKER=\"$<TARGET_FILE:tamias_bench_v3_${variant}>\"")
endforeach()
set_property(SOURCE remote_engine.cpp APPEND PROPERTY COMPILE_DEFINITIONS
             "TAMIAS_BENCH_V3_VERSION=\"${v3_version} (${v3_commit})\""
             "TAMIAS_BENCH_V3_SOURCE=\"${v3_dir}\""
             "TAMIAS_BENCH_V3_C_FLAGS=\"C17 ${v3_c_flags} -ffp-contract=off\"")
