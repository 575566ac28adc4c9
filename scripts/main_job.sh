#!/usr/bin/env bash
# The main job: build, run the V&V suite and write the evidence into reports/.
#   scripts/main_job.sh [--quick] [--full-bench]
#     --quick       skips the other platforms' golden hashes, coverage and mutation (their
#                   own builds)
#     --full-bench  runs the peer benchmark (about 20 min on 2 cores) and the work-precision
#                   sweep at full length instead of their --quick forms
#   TAMIAS_MUTATION_MINUTES=M  judges mutants for M minutes (default 4; docs/verification.md)
#   TAMIAS_MUTATION=all        judges every mutant instead (hours); TAMIAS_MUTATION=0 skips it
#   TAMIAS_MUTATION_SEED=S     picks the sample (default 1)
#   TAMIAS_MODULE_REACH=all    perturbs every model module (docs/verification.md, section 11;
#                              a rebuild and the engine's tests per perturbation, hours)
#                              instead of the damping pair (DD17, DD18, the default);
#                              TAMIAS_MODULE_REACH=0 skips it
# It prints each phase's time at the end and writes them to reports/data/main_job.json, which the
# report shows.
set -uo pipefail
cd "$(dirname "$0")/.."
t0=$(date +%s)
phase_names=(); phase_starts=()
phase() {
    phase_names+=("$*"); phase_starts+=("$(date +%s)")
    printf '\n== [%4ds] %s\n' "$(( $(date +%s) - t0 ))" "$*"
}
# "name<TAB>seconds" per phase so far, the last one ended now.
phase_times() {
    local now i end
    now=$(date +%s)
    for i in "${!phase_names[@]}"; do
        end=${phase_starts[$((i + 1))]:-$now}
        printf '%s\t%s\n' "${phase_names[$i]}" "$(( end - ${phase_starts[$i]} ))"
    done
}
quick=0; full_bench=0; coverage_failed=0; api_failed=0; platforms_failed=0
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
    case "$(basename "$prog")" in
        tamias_bench | tamias_work_precision) [ $full_bench -eq 0 ] && args=(--quick) ;;
    esac
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
# (CI does not run them: it replays their seeds and regressions, CTest's fuzz_replay.)
# Reliability evidence beside the programs above, not an expected program: without Clang 14 and
# its fuzzer runtime nothing is written and the report says "not run". A finding is a failed
# check of the report; its input is in build-fuzz/findings/.
./scripts/fuzz.sh --seconds 60 --report reports/data | sed "s/^/   /"

phase "other platforms: golden hashes with portable lanes, on riscv64, in Chromium, by Clang at -O3 and with FMA"
# The golden-hash checks CI leaves out to stay within its time (.ci/run keeps aarch64, Node.js
# and Clang's sanitizer build): each builds the library its own way and must
# reach the same bits; a failure fails the job. --quick skips them.
checks=(portable_check riscv64_check wasm_browser_check clang_check fma_check)
[ $quick -eq 0 ] || { echo "   skipped (--quick)"; checks=(); }
for check in "${checks[@]}"; do
    p0=$(date +%s)
    if ./.ci/$check.sh >"build/$check.log" 2>&1; then
        echo "   $check: passed in $(( $(date +%s) - p0 )) s"
    else
        echo "   $check: FAILED (build/$check.log)"; platforms_failed=1
    fi
done

phase "coverage and mutation: one instrumented scratch build (verification/mutation/mutate.py)"
# One build outside the checkout (/tmp; minutes when new, seconds when it outlives the last run):
# -O1 with the standard library's assertions and gcov's counters. Every test runs once there on
# the unmutated sources (coverage: a test failing only there fails the job, it would lower the
# coverage silently), then a seeded sample of mutants is judged for TAMIAS_MUTATION_MINUTES
# (default 4). The sample's survivors are not judged again in the ASan and UBSan build
# (--no-sanitizer): its first build takes longer than the whole box on 2 cores, and a survivor
# left unjudged can only lower the score. TAMIAS_MUTATION=all judges every mutant (hours, the
# sanitizer build included),
# TAMIAS_MUTATION=0 (or minutes 0) none (the report then says "not run"); --quick skips both.
mutation=${TAMIAS_MUTATION:-sample}
minutes=${TAMIAS_MUTATION_MINUTES:-4}
[ "$mutation" = 0 ] && minutes=0
if [ $quick -eq 1 ]; then
    echo "   skipped (--quick)"
else
    if [ "$mutation" = all ]; then
        margs=(--all)
    else
        margs=(--sample 1000 --seed "${TAMIAS_MUTATION_SEED:-1}" --minutes "$minutes" --no-sanitizer)
    fi
    p0=$(date +%s)
    /usr/bin/python3 verification/mutation/mutate.py reports/data "${margs[@]}" \
        --coverage reports/data/coverage.json reports/coverage.html >build/mutation.log 2>&1
    rc=$?
    grep -E '^coverage:' build/mutation.log | sed "s/^/   /"
    tail -n 1 build/mutation.log | sed "s/^/   /"
    if [ $rc -eq 3 ]; then
        echo "   a test FAILED in the instrumented build (build/mutation.log)"; coverage_failed=1
    elif [ $rc -ne 0 ]; then
        echo "   mutate.py exited $rc (build/mutation.log)"; coverage_failed=1
    fi
    if [ "$minutes" != 0 ] && [ ! -f reports/data/mutation.json ]; then
        # Asked for and not done (the scratch did not build): an error, not "not run".
        printf '{"program": "mutation", "description": "wrote no results (build/mutation.log)", "checks": [{"name": "mutation wrote its results", "labels": [], "passed": false, "oracle": "mutate.py writes reports/data/mutation.json", "details": "exit status %s, no JSON written"}], "tables": [], "series": []}\n' \
            "$rc" > reports/data/mutation.missing.json
    fi
    echo "   coverage and mutation: $(( $(date +%s) - p0 )) s (log: build/mutation.log)"
fi

phase "module reach: each model module perturbed, judged by the engine's tests (reports/data/module_reach.json)"
# verification/model_reach/module_reach.py on the same scratch build (rebuilt incrementally, kept
# instrumented): every model module's formula made wrong in turn, the engine-level tests run;
# an item the engine evaluates must be noticed by its own engine tests, one marked
# engine: model-only or property in srs/ by none (docs/verification.md, section 11). A rebuild
# and the engine's tests per perturbation: by default the damping pair only (DD17, DD18, the
# modules the engine once bypassed), TAMIAS_MODULE_REACH=all every module, TAMIAS_MODULE_REACH=0
# none (the report then has no module reach results); --quick skips it.
reach=${TAMIAS_MODULE_REACH:-damping}
if [ $quick -eq 1 ]; then
    echo "   skipped (--quick)"
elif [ "$reach" = 0 ]; then
    echo "   skipped (TAMIAS_MODULE_REACH=0)"
else
    rargs=()
    [ "$reach" = all ] || rargs=(--subset "$reach")
    p0=$(date +%s)
    /usr/bin/python3 verification/model_reach/module_reach.py reports/data "${rargs[@]}" \
        >build/module_reach.log 2>&1
    rc=$?
    tail -n 1 build/module_reach.log | sed "s/^/   /"
    if [ ! -f reports/data/module_reach.json ]; then
        printf '{"program": "module_reach", "description": "wrote no results (build/module_reach.log)", "checks": [{"name": "module_reach wrote its results", "labels": [], "passed": false, "oracle": "module_reach.py writes reports/data/module_reach.json", "details": "exit status %s, no JSON written"}], "tables": [], "series": []}\n' \
            "$rc" > reports/data/module_reach.missing.json
    elif [ $rc -ne 0 ]; then
        echo "   module_reach.py exited $rc: its checks in the report say which items (build/module_reach.log)"
    fi
    echo "   module reach: $(( $(date +%s) - p0 )) s (log: build/module_reach.log)"
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

# The phases so far, for the report (its own phase is timed by the harness's run manifest).
phase_times | /usr/bin/python3 scripts/phase_times.py reports/data/main_job.json

phase "tests and traceability report"
/usr/bin/python3 traceability/build_report.py --source . --build build --out reports --jobs 2
status=$?
[ $coverage_failed -eq 0 ] || status=1
[ $api_failed -eq 0 ] || status=1
[ $platforms_failed -eq 0 ] || status=1
phase "done (exit $status): open reports/index.html"
echo "   phase times (s):"
phase_times | sed '$d' | awk -F'\t' '{ printf "   %6d  %s\n", $2, $1 }'
echo "   $(( $(date +%s) - t0 )) s in all"
exit $status
