#!/usr/bin/env bash
# The main job's "other platforms" phase (CI leaves it out for time): fused multiply-add changes no
# bit. On a processor with AVX2 and FMA, the library and the golden-hash test are built by Clang
# with -march=haswell: Clang contracts a * b + c into an FMA by default (GCC does not in ISO C++
# mode), so only the library's -ffp-contract=off keeps the golden bits here. Checks that the library
# holds no FMA instruction and that the golden state hashes (tests/determinism) still pass. Skipped,
# and says so, on a processor without them.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! grep -qw avx2 /proc/cpuinfo || ! grep -qw fma /proc/cpuinfo; then
    echo "fma_check: SKIPPED: this processor lacks AVX2 or FMA (/proc/cpuinfo)"
    exit 0
fi
cmake -S . -B build-haswell -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS=-march=haswell -DTAMIAS_WERROR=ON -DTAMIAS_BUILD_VERIFICATION=OFF \
    -DTAMIAS_BUILD_APPS=OFF -DTAMIAS_TEST_PCH=OFF >/dev/null
cmake --build build-haswell -j2 --target determinism_tests
fma=$(objdump -d build-haswell/src/libtamias2d.a | grep -c 'vfn\?m\(add\|sub\)[0-9]' || true)
if [ "$fma" -ne 0 ]; then
    echo "FAIL: the -march=haswell library holds $fma fused multiply-add instructions"
    exit 1
fi
echo "the -march=haswell library holds no fused multiply-add instruction"
build-haswell/tests/determinism/determinism_tests --color_output=no
