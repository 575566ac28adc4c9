#!/usr/bin/env bash
# CI: worlds in threads under ThreadSanitizer. Builds the library and tests/reliability with
# -fsanitize=thread (GCC) and runs the suite of worlds stepped in parallel (`threads`) and that
# of one world stepped on several threads (`parallel_step`: the World's pool and a game's task
# system); a data race between worlds (the shared pool of large blocks, counters) or within a
# step's parallel loops fails it. Each case is a process of its own, two at a time, the joint
# cases (the longest) first: under ThreadSanitizer a process keeps about one core busy.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTAMIAS_TSAN=ON \
    -DTAMIAS_WERROR=ON -DTAMIAS_BUILD_VERIFICATION=OFF -DTAMIAS_BUILD_APPS=OFF \
    -DTAMIAS_TEST_PCH=OFF >/dev/null
cmake --build build-tsan -j2 --target reliability_tests
tests=build-tsan/tests/reliability/reliability_tests
cases=$("$tests" --list_content 2>&1 | awk '
    /^[^ ]/ { suite = $1; sub(/\*$/, "", suite); next }
    suite == "threads" || suite == "parallel_step" { c = $1; sub(/\*$/, "", c); print suite "/" c }' |
    awk '{ print (/joint/ ? 0 : 1) "\t" $0 }' | sort -s -k1,1n | cut -f2)
[ -n "$cases" ] || { echo "tsan_check: no test cases listed"; exit 1; }
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 tests logs
status=0
printf '%s\n' "$cases" | xargs -P 2 -I{} bash -c '
    log="$logs/$(echo "{}" | tr / _).log"
    if "$tests" --run_test="{}" --color_output=no >"$log" 2>&1; then
        echo "tsan_check: {} passed"
    else
        echo "tsan_check: {} FAILED"; cat "$log"; exit 1
    fi' || status=1
echo "tsan_check: $(printf '%s\n' "$cases" | wc -l) cases, $([ $status -eq 0 ] && echo "no failure" || echo "FAILED")"
exit $status
