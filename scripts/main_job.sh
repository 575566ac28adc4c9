#!/usr/bin/env bash
# The main job: build, run the V&V suite and write the evidence into reports/.
#   scripts/main_job.sh [--quick] [--full-bench]
#     --quick       skips the coverage build
#     --full-bench  runs the peer benchmark at full length (about 20 min on 2 cores) instead of
#                   its --quick form, which keeps the main job near 10 minutes
#   TAMIAS_MUTATION_MINUTES=M  judges mutants for M minutes (default 8; docs/verification.md)
#   TAMIAS_MUTATION=all        judges every mutant instead (hours); TAMIAS_MUTATION=0 skips it
#   TAMIAS_MUTATION_SEED=S     picks the sample (default 1)
set -uo pipefail
cd "$(dirname "$0")/.."
t0=$(date +%s)
phase() { printf '\n== [%4ds] %s\n' "$(( $(date +%s) - t0 ))" "$*"; }
quick=0; full_bench=0; coverage_failed=0; api_failed=0
for arg in "$@"; do
    case "$arg" in
        --quick) quick=1 ;;
        --full-bench) full_bench=1 ;;
        *) echo "usage: scripts/main_job.sh [--quick] [--full-bench]"; exit 2 ;;
    esac
done

phase "set-up (Debian packages)"
./scripts/setup.sh || exit 1
phase "build (Release)"
# Box2D v3 runs in tamias_bench beside the other engines when its source tree is there (an empty
# value builds nothing of it, and the benchmark reports it as not measured).
v3_dir=$(cd ../shared/peers/box2d-v3 2>/dev/null && pwd)
cmake -S . -B build -G Ninja -DTAMIAS_WERROR=ON -DTAMIAS_BUILD_VERIFICATION=ON \
      -DTAMIAS_BOX2D_V3_DIR="$v3_dir" >/dev/null &&
    cmake --build build -j2 || exit 1
mkdir -p reports/data
rm -f reports/data/*.json

phase "verification programs"
while read -r prog; do
    [ -n "$prog" ] || continue
    p0=$(date +%s)
    args=()
    [ "$(basename "$prog")" = tamias_bench ] && [ $full_bench -eq 0 ] && args=(--quick)
    before=$(ls reports/data | wc -l)
    "$prog" reports/data "${args[@]}"
    rc=$?
    [ $rc -eq 0 ] || echo "   $(basename "$prog") exited $rc (its checks say why)"
    if [ "$(ls reports/data | wc -l)" -eq "$before" ]; then
        # A program that wrote nothing (a crash) must not vanish from the report: one failed
        # check stands for it.
        name=$(basename "$prog")
        printf '{"program": "%s", "description": "wrote no results", "checks": [{"name": "%s wrote its results", "labels": [], "passed": false, "oracle": "the program writes reports/data/<program>.json", "details": "exit status %s, no JSON written"}], "tables": [], "series": []}\n' \
            "$name" "$name" "$rc" > "reports/data/$name.missing.json"
    fi
    echo "   $(basename "$prog"): $(( $(date +%s) - p0 )) s"
done < build/verification_programs.txt

phase "fuzzing: the libFuzzer targets, 60 s each (reports/data/fuzz.json)"
# Reliability evidence beside the programs above, not an expected program: without Clang 14 and
# its fuzzer runtime nothing is written and the report says "not run". A finding is a failed
# check of the report; its input is in build-fuzz/findings/.
./scripts/fuzz.sh --seconds 60 --report reports/data | sed "s/^/   /"

phase "mutation testing (verification/mutation/mutate.py)"
# A seeded sample judged for TAMIAS_MUTATION_MINUTES (default 8) after the scratch build (in
# /tmp, outside the checkout; minutes when new, seconds when it outlives the last run);
# TAMIAS_MUTATION=all judges every mutant (hours), TAMIAS_MUTATION=0 (or minutes 0) skips it
# (the report then says "not run").
mutation=${TAMIAS_MUTATION:-sample}
if [ "$mutation" = 0 ] || { [ "$mutation" != all ] && [ "${TAMIAS_MUTATION_MINUTES:-8}" = 0 ]; }; then
    echo "   skipped (TAMIAS_MUTATION=0 or TAMIAS_MUTATION_MINUTES=0)"
else
    if [ "$mutation" = all ]; then
        margs=(--all)
    else
        margs=(--sample 1000 --seed "${TAMIAS_MUTATION_SEED:-1}"
               --minutes "${TAMIAS_MUTATION_MINUTES:-8}")
    fi
    p0=$(date +%s)
    /usr/bin/python3 verification/mutation/mutate.py reports/data "${margs[@]}" \
        >build/mutation.log 2>&1
    rc=$?
    tail -n 1 build/mutation.log | sed "s/^/   /"
    if [ ! -f reports/data/mutation.json ]; then
        # Asked for and not done (the scratch did not build): an error, not "not run".
        printf '{"program": "mutation", "description": "wrote no results (build/mutation.log)", "checks": [{"name": "mutation wrote its results", "labels": [], "passed": false, "oracle": "mutate.py writes reports/data/mutation.json", "details": "exit status %s, no JSON written"}], "tables": [], "series": []}\n' \
            "$rc" > reports/data/mutation.missing.json
    fi
    echo "   mutation: $(( $(date +%s) - p0 )) s (log: build/mutation.log)"
fi

if [ $quick -eq 0 ]; then
    phase "coverage build and run (gcovr)"
    cmake -S . -B build-coverage -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTAMIAS_COVERAGE=ON \
          -DTAMIAS_BUILD_VERIFICATION=OFF >/dev/null &&
        cmake --build build-coverage -j2 >/dev/null || echo "   coverage build failed"
    # Each Boost.Test executable once, all its cases (CTest runs one entry per SRS label, so a
    # case with four labels would run four times), two at a time; then the other CTest entries
    # (CLI, examples, scripts). The report's run is the verdict, but a test that fails only in
    # this unoptimised build is a bug too (and would silently lower the coverage): it fails the
    # job.
    find build-coverage/tests -name '*_tests' -type f -perm -u+x | sort |
        xargs -P 2 -I{} sh -c '"{}" --color_output=no >/dev/null 2>&1 || echo "{}" >&2' \
            2>build-coverage/failures.txt || true
    ctest --test-dir build-coverage -j2 -LE 'compile_fail|consumer' -E '@' >/dev/null ||
        echo "ctest (coverage build)" >>build-coverage/failures.txt
    if [ -s build-coverage/failures.txt ]; then
        echo "   FAILED in the coverage build (-O0):"; sed "s/^/     /" build-coverage/failures.txt
        coverage_failed=1
    fi
    rm -f build-coverage/failures.txt
    # gcov 12 can print a function summary with a negative percentage ("returned -1857409%") for
    # a function left by an exception; gcovr 5.2 stops at such a line unless told to skip it
    # (it then skips that summary line only; line and branch counts are unaffected).
    gcovr -r . --filter 'src/' --filter 'include/' --gcov-ignore-parse-errors \
          --json-summary reports/data/coverage.json \
          --html-details reports/coverage.html build-coverage >/dev/null 2>&1 ||
        echo "   gcovr failed"
    # gcov writes its .gcov files into the working directory; gcovr leaves some of them there.
    find . -maxdepth 1 -name '*.gcov' -delete
fi

phase "API reference (Doxygen) into reports/api"
./scripts/api_reference.sh reports/api build || api_failed=1

phase "recorded runs: a player per example scene, checked in Chromium (reports/players)"
# tamias2d view writes each page; tests/viewer/check_player.py checks it in headless Chromium
# (states against tamias2d run's CSV, screenshots) and lists it for the report. Every scene is
# recorded at every step but two, both without contact points (pyramid20 shows them): rain every
# 10 steps (1.4 MB) and pyramid40 every 3 (0.7 MB); large_pyramid (5051 bodies: 2 MB at 31
# frames even without contacts) is left out, pyramid40 shows the same.
p0=$(date +%s)
if [ ! -x /usr/bin/chromium ]; then
    echo "   installing chromium (Debian package) for the browser check"
    if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
    { $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium; } \
        >/dev/null 2>&1 || echo "   could not install chromium: the pages are written unchecked"
fi
rm -rf reports/players && mkdir -p reports/players
cases=()
for scene in examples/scenes/*.json; do
    case "$(basename "$scene" .json)" in
        large_pyramid) ;;
        rain) cases+=("$scene:--every 10 --max-contacts 0") ;;
        pyramid40) cases+=("$scene:--every 3 --max-contacts 0") ;;
        *) cases+=("$scene:--every 1") ;;
    esac
done
/usr/bin/python3 tests/viewer/check_player.py --cli build/apps/cli/tamias2d --out reports/players \
    --index reports/players/index.json "${cases[@]}" | sed "s/^/   /"
echo "   players: $(du -sh reports/players | cut -f1) in $(( $(date +%s) - p0 )) s"

phase "tests and traceability report"
/usr/bin/python3 traceability/build_report.py --source . --build build --out reports
status=$?
[ $coverage_failed -eq 0 ] || status=1
[ $api_failed -eq 0 ] || status=1
phase "done (exit $status): open reports/index.html"
exit $status
