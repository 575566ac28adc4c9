#!/usr/bin/env bash
# CI: worlds in threads under ThreadSanitizer. Builds the library and tests/reliability with
# -fsanitize=thread (GCC) and runs the suite of worlds stepped in parallel (`threads`) and that
# of one world stepped on several threads (`parallel_step`: the World's pool and a game's task
# system); a data race between worlds (the shared pool of large blocks, counters) or within a
# step's parallel loops fails it.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAMIAS_TSAN=ON \
    -DTAMIAS_WERROR=ON -DTAMIAS_BUILD_VERIFICATION=OFF -DTAMIAS_BUILD_APPS=OFF \
    -DTAMIAS_TEST_PCH=OFF >/dev/null
cmake --build build-tsan -j2 --target reliability_tests
TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
    build-tsan/tests/reliability/reliability_tests --run_test=threads:parallel_step --color_output=no
