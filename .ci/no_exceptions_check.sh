#!/usr/bin/env bash
# CI: the library configured with TAMIAS2D_EXCEPTIONS=OFF, as a game built without exceptions
# takes it: its public headers declare only the error-returning `try_` forms. Builds, in
# build-noexcept, the library, the tests compiled with -fno-exceptions, the compile-fail test's
# correct form and the example game loop (apps/examples/no_exceptions.cpp), and runs them with
# the lint of the `try_` forms (ctest -L error_returning): only those targets, so that the lane
# stays short. Checks that the generated config.hpp and the CMake package file record the option,
# and that the library still defines the throwing forms (one binary for both settings). Built
# without the library's precompiled header and file by file (TAMIAS_LIBRARY_PCH=OFF,
# TAMIAS_UNITY_BUILD=OFF): every library file then compiles from its own includes, which the
# other builds' shared header and batches would hide.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
build=build-noexcept
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTAMIAS2D_EXCEPTIONS=OFF \
    -DTAMIAS_WERROR=ON -DTAMIAS_BUILD_VERIFICATION=OFF -DTAMIAS_TEST_PCH=OFF \
    -DTAMIAS_LIBRARY_PCH=OFF -DTAMIAS_UNITY_BUILD=OFF >/dev/null
grep -q "^#if 0 && " "$build/include/tamias2d/config.hpp" || {
    echo "FAIL: $build/include/tamias2d/config.hpp does not record TAMIAS2D_EXCEPTIONS=OFF"
    exit 1
}
cmake --build "$build" -j2 --target tamias2d error_returning_kinds \
    error_returning_undeclared_correct example_no_exceptions
ctest --test-dir "$build" -j2 --output-on-failure -L error_returning
# The package records the option: the tamias2dConfig.cmake that `cmake --install` copies sets
# TAMIAS2D_EXCEPTIONS OFF, and config.hpp (installed beside export.hpp) is the one checked above.
grep -q "^set(TAMIAS2D_EXCEPTIONS OFF)" "$build/tamias2dConfig.cmake" || {
    echo "FAIL: $build/tamias2dConfig.cmake does not record TAMIAS2D_EXCEPTIONS OFF"
    exit 1
}
grep -q "include/tamias2d/config.hpp" cmake/TamiasInstall.cmake || {
    echo "FAIL: cmake/TamiasInstall.cmake does not install config.hpp"
    exit 1
}
# The library defines both forms whatever the option: World::create_body beside its try_ form.
nm -C "$build/src/libtamias2d.a" | grep " T tamias2d::World::create_body(" >/dev/null || {
    echo "FAIL: the library does not define World::create_body"
    exit 1
}
echo "no_exceptions_check: passed in $(( $(date +%s) - start )) s"
