#!/usr/bin/env bash
# The main job's "other platforms" phase (CI leaves it out for time): the portable packs
# (TAMIAS_PORTABLE_LANES: plain structures instead of GCC/Clang vector extensions, as MSVC gets
# them) must give bit for bit the results of the vector build. Builds the CLI with the option into
# build-portable, runs every example scene through it and through build/apps/cli/tamias2d (built by
# the test suite), and fails unless the outputs are byte-identical. It also runs the golden-hash
# test (tests/determinism) in the portable build: the same committed hashes as the vector builds,
# Release and ASan, must come out.
set -euo pipefail
cd "$(dirname "$0")/.."

reference=build/apps/cli/tamias2d
portable=build-portable/apps/cli/tamias2d
steps=200
every=50

if [[ ! -x $reference ]]; then
    echo "portable_check: $reference not found: build the default configuration first" >&2
    exit 1
fi

echo "== portable lanes build (TAMIAS_PORTABLE_LANES=ON)"
cmake -S . -B build-portable -G Ninja -DTAMIAS_WERROR=ON -DTAMIAS_PORTABLE_LANES=ON \
    -DTAMIAS_BUILD_TESTS=ON -DTAMIAS_BUILD_VERIFICATION=OFF >/dev/null
cmake --build build-portable -j2 --target tamias2d_cli determinism_tests

echo "== golden state hashes (tests/determinism/golden_hashes.txt), portable lanes"
golden_ok=1
build-portable/tests/determinism/determinism_tests --color_output=no || golden_ok=0

echo "== example scenes, $steps steps (--every $every): vector lanes vs portable lanes"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0
failed=0
shopt -s nullglob
scenes=(examples/scenes/*.json)
if ((${#scenes[@]} == 0)); then
    echo "portable_check: no scenes in examples/scenes" >&2
    exit 1
fi
for scene in "${scenes[@]}"; do
    name=$(basename "$scene")
    if ! "$reference" run "$scene" --steps "$steps" --every "$every" >"$out/reference.csv"; then
        echo "FAIL $name (the reference CLI failed)"
        failed=$((failed + 1))
    elif ! "$portable" run "$scene" --steps "$steps" --every "$every" >"$out/portable.csv"; then
        echo "FAIL $name (the portable CLI failed)"
        failed=$((failed + 1))
    elif cmp -s "$out/reference.csv" "$out/portable.csv"; then
        echo "ok   $name"
        passed=$((passed + 1))
    else
        echo "FAIL $name (outputs differ: $(cmp "$out/reference.csv" "$out/portable.csv" | head -n 1))"
        failed=$((failed + 1))
    fi
done
echo "$passed passed, $failed failed"
((golden_ok == 1)) || echo "FAIL golden state hashes differ in the portable build (above)"
((failed == 0 && golden_ok == 1))
