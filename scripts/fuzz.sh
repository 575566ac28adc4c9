#!/usr/bin/env bash
# The libFuzzer targets (tests/fuzz/libfuzzer): builds them with Clang 14 (ASan + UBSan) in
# build-fuzz/ and runs them two at a time (scene and api, then snapshot and recording: the
# machine's two cores), each for the given time, from the seed corpus, the
# regression corpus and what earlier runs kept (build-fuzz/corpus/<target>).
#   scripts/fuzz.sh                  60 s per target (CI's run)
#   scripts/fuzz.sh --minutes 30     the long run
#   scripts/fuzz.sh --seconds 300 --report reports/data
# Prints per target: executions, exec/s, libFuzzer's final coverage (cov: edges, ft: features),
# corpus size and findings (new crash-, timeout-, leak-, oom- and slow-unit- files in
# build-fuzz/findings/<target>/: copy one into tests/fuzz/libfuzzer/regressions/<target>/ to
# keep it replayed by the tests). --report DIR also writes DIR/fuzz.json (verification schema).
# Exit status 1 when a target found something, 2 when the targets could not be built.
set -uo pipefail
cd "$(dirname "$0")/.."
seconds=60; report=""
while [ $# -gt 0 ]; do
    case "$1" in
        --minutes) seconds=$(( $2 * 60 )); shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --report) report=$2; shift 2 ;;
        *) echo "usage: scripts/fuzz.sh [--minutes M | --seconds S] [--report DIR]"; exit 2 ;;
    esac
done
cxx=$(command -v clang++-14 || true)
rt=$(ls /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a 2>/dev/null | head -1)
if [ -z "$cxx" ] || [ -z "$rt" ]; then
    echo "fuzz: needs clang++-14 and libclang-rt-14-dev (scripts/setup.sh installs them)"
    exit 2
fi

build=build-fuzz
dir=tests/fuzz/libfuzzer
built=$(date -u +%Y-%m-%dT%H:%M:%SZ)
# Only the library and the targets: the whole build is instrumented (cmake/TamiasFuzz.cmake).
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Fuzz \
      -DCMAKE_CXX_FLAGS="-O1 -g" -DTAMIAS_WERROR=ON -DTAMIAS_FUZZ_TARGETS=ON \
      -DTAMIAS_BUILD_TESTS=OFF -DTAMIAS_BUILD_VERIFICATION=OFF -DTAMIAS_BUILD_APPS=OFF \
      -DTAMIAS_INSTALL=OFF >/dev/null &&
    cmake --build "$build" -j2 --target tamias_fuzz_scene tamias_fuzz_api tamias_fuzz_snapshot \
        tamias_fuzz_recording >/dev/null ||
    { echo "fuzz: the targets did not build"; exit 2; }

start="$build/run-start"; touch "$start"
for t in scene api snapshot recording; do
    mkdir -p "$build/corpus/$t" "$build/findings/$t"
    if [ $t = scene ]; then
        # Scene files: the example scenes are seeds too; the largest is about 5 kB.
        opts=(-dict="$dir/scene.dict" -max_len=8192 examples/scenes)
    elif [ $t = recording ]; then
        # Recordings of example scenes (corpus/recording, up to 31 kB), some with calls made
        # mid-run, first byte 1: the checksum made right, so that changes reach the records.
        opts=(-max_len=65536)
    elif [ $t = snapshot ]; then
        # Snapshots of example scenes (corpus/snapshot, up to 27 kB), first byte 1: the
        # checksum made right, so that changes reach the sections' reader.
        opts=(-max_len=32768)
    else
        # Up to 256 calls of a few bytes each (api_target.cpp's max_calls), long sequences from
        # the start (-len_control=0): a 60 s run reaches more code than 5 min growing slowly.
        opts=(-max_len=1024 -len_control=0)
    fi
    # Sanitizer reports are fatal (cmake/TamiasFuzz.cmake); leaks are reported at exit. A unit
    # slower than 30 s is a timeout: the largest scenes the format accepts take 9-13 s to load
    # in this build (a pyramid of base 500, rain of 200 000 bodies; about 1.2 s in Release).
    # So a unit counts as slow only past that timeout too: libFuzzer's default, 10 s, lies
    # within the load times of scenes the format accepts.
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        "$build/tests/fuzz/libfuzzer/tamias_fuzz_$t" -max_total_time="$seconds" -timeout=30 \
        -report_slow_units=30 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$build/findings/$t/" \
        "$build/corpus/$t" "${opts[@]}" "$dir/corpus/$t" "$dir/regressions/$t" \
        >"$build/fuzz-$t.log" 2>&1 &
    [ $t = api ] && wait # two at a time
done
wait

rows=""; found=0
for t in scene api snapshot recording; do
    log="$build/fuzz-$t.log"
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    cov=$(grep -o ' cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
    ft=$(grep -o ' ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
    corp=$(grep -o ' corp: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*')
    new=$(find "$build/findings/$t" -type f -newer "$start" | sort)
    n=$(printf '%s' "$new" | grep -c . || true)
    [ "$n" -eq 0 ] || found=1
    printf 'fuzz %-5s %s s: %s executions, %s exec/s, cov: %s, ft: %s, corpus %s, findings: %s\n' \
        "$t" "$seconds" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$n"
    for f in $new; do
        echo "  $f"
        grep -m1 -E 'broken promise|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error' \
            "$log" | sed 's/^/    /'
    done
    rows+="$t $seconds ${execs:-0} ${rate:-0} ${cov:-0} ${ft:-0} ${corp:-0} $n $(echo $new | tr ' ' ',')"$'\n'
done

if [ -n "$report" ]; then
    mkdir -p "$report"
    commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)
    dirty=$([ -n "$(git status --porcelain 2>/dev/null)" ] && echo true || echo false)
    ROWS="$rows" FUZZ_BUILD="$build" FUZZ_CXX="$($cxx --version | head -1)" \
        /usr/bin/python3 - "$report/fuzz.json" "$commit" "$dirty" "$built" <<'EOF'
import datetime, json, os, sys
sys.path.insert(0, os.getcwd())
from traceability.builds import tree_key
out, commit, dirty, built = sys.argv[1], sys.argv[2], sys.argv[3] == "true", sys.argv[4]
what = {"scene": "scene files through io::parse_scene, io::build_world and a few steps",
        "api": "sequences of World calls with any doubles and live, stale, forged and foreign handles",
        "snapshot": "snapshots through World::from_snapshot, World::restore and a few steps",
        "recording": "recordings through Replayer, recorded_calls and up to 40 replayed records"}
rows, checks = [], []
for line in os.environ["ROWS"].splitlines():
    t, secs, execs, rate, cov, ft, corp, n, files = (line.split(" ") + [""])[:9]
    rows.append([t, int(secs), int(execs), int(rate), int(cov), int(ft), int(corp), int(n),
                 files.replace(",", ", ")])
    checks.append({"name": f"libFuzzer target {t}: {int(secs)} s without a finding", "labels": [],
                   "passed": int(n) == 0 and int(execs) > 0,
                   "oracle": "the library's stated promises (no crash or sanitizer report; a "
                             "refusal is a documented error and leaves state_hash() unchanged; "
                             "every state after an accepted call or step is finite), checked "
                             "by tests/fuzz/libfuzzer/" + t + "_target.cpp",
                   "details": f"{what[t]}: {execs} executions ({rate}/s), cov {cov}, ft {ft}, "
                              f"corpus {corp}, findings {n}" + (f": {files}" if files else "")})
now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
doc = {"program": "fuzz",
       "description": "libFuzzer targets with ASan and UBSan (scripts/fuzz.sh): reliability "
                      "evidence, not an SRS item. cov: the edges reached, ft: libFuzzer's "
                      "features; findings: new crash, timeout, leak or out-of-memory inputs.",
       "provenance": {"commit": commit, "dirty": dirty, "tree": tree_key("."), "build_id": None,
                      "built": built, "generated": now,
                      "build": {"name": "libFuzzer targets (Clang 14, ASan + UBSan)",
                                "where": os.environ.get("FUZZ_BUILD", "build-fuzz"),
                                "compiler": os.environ.get("FUZZ_CXX", "clang++-14"),
                                "flags": "-O1 -g -fsanitize=fuzzer-no-link,address,undefined",
                                "options": "CMAKE_BUILD_TYPE=Fuzz TAMIAS_FUZZ_TARGETS=ON"}},
       "checks": checks,
       "tables": [{"name": "libFuzzer runs",
                   "columns": ["target", "seconds", "executions", "exec/s", "cov", "ft",
                               "corpus", "findings", "finding files"], "rows": rows}],
       "series": []}
with open(out, "w", encoding="utf-8") as fh:
    json.dump(doc, fh, indent=1)
EOF
    echo "fuzz: wrote $report/fuzz.json"
fi
exit $found
