#!/usr/bin/env bash
# The test suite: installs what is missing, builds (warnings are errors) and runs every test.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   ASan + UBSan build by Clang 14 in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
build=build; extra=(); skip=()
if [ "${1:-}" = "--sanitize" ]; then
    # Only the C++ that runs: compile-fail checks, the Python harness and lint tests and the
    # consumer builds (plain builds of the same sources) are not repeated. Clang, not GCC: the
    # Release build above is GCC's, so the tests are built by both compilers (and Clang's
    # instrumented build takes about two thirds of GCC's time).
    build=build-asan
    # Without the x86-64-v4 clone: on a machine with AVX-512 these tests then run the AVX2
    # clone of the pack loops, the Release build's tests the x86-64-v4 one (the same bits).
    extra=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Asan -DCMAKE_CXX_FLAGS=-O1 -DTAMIAS_SANITIZE=ON -DTAMIAS_BUILD_VERIFICATION=OFF
           -DTAMIAS_WIDE_X86_64_V4=OFF)
    skip=(-LE "compile_fail|srs|traceability|consumer|docs|lint")
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
cmake -S . -B "$build" -G Ninja -DTAMIAS_WERROR=ON "${extra[@]}" >/dev/null
cmake --build "$build" -j2
ctest --test-dir "$build" -j2 --output-on-failure "${skip[@]}"
