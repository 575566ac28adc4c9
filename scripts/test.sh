#!/usr/bin/env bash
# The test suite: installs what is missing, builds (warnings are errors) and runs every test.
#   scripts/test.sh              Release build in build/
#   scripts/test.sh --sanitize   ASan + UBSan build in build-asan/
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
build=build; extra=()
if [ "${1:-}" = "--sanitize" ]; then
    build=build-asan
    extra=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAMIAS_SANITIZE=ON -DTAMIAS_BUILD_VERIFICATION=OFF)
    export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
fi
cmake -S . -B "$build" -G Ninja -DTAMIAS_WERROR=ON "${extra[@]}" >/dev/null
cmake --build "$build" -j2
ctest --test-dir "$build" -j2 --output-on-failure
