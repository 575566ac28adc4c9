#!/usr/bin/env bash
# The golden state hashes (tests/determinism/golden_hashes.txt, every example scene at every
# checkpoint, on one worker and on four) on another architecture: the library cross-compiled by
# Debian 12's GCC 12 cross compiler for ARCH with the project's own CMake rules (.ci/cross/:
# Release, -ffp-contract=off, warnings as errors) and determinism_tests run under qemu-user;
# then the libm check (tests/determinism/check_libm_calls.py) on the cross-built libraries.
#   .ci/cross_determinism.sh aarch64|riscv64
# Installs the cross compiler, its C library (libc6-dev-<arch>-cross, a dependency) and
# qemu-user when missing. Boost and nlohmann-json are header-only here: the host's headers
# serve (Boost.Test included as a header, .ci/cross/boost_test_main.cpp), so no package of the
# target architecture (dpkg --add-architecture) is needed, which riscv64 could not have:
# Debian 12 does not release it as an architecture, only its cross toolchain.
set -euo pipefail
cd "$(dirname "$0")/.."
arch=${1:?usage: .ci/cross_determinism.sh aarch64|riscv64}
case $arch in
aarch64) triple=aarch64-linux-gnu package=g++-aarch64-linux-gnu ;;
riscv64) triple=riscv64-linux-gnu package=g++-riscv64-linux-gnu ;;
*) echo "cross_determinism: unknown architecture $arch" >&2; exit 2 ;;
esac
start=$(date +%s)
needed=()
for p in "$package" qemu-user cmake ninja-build libboost-dev libboost-test-dev nlohmann-json3-dev python3; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || needed+=("$p")
done
if ((${#needed[@]})); then
    echo "cross_determinism: installing ${needed[*]}"
    SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${needed[@]}" >/dev/null
fi

build=build-$arch
mkdir -p "$build"
cat >"$build/toolchain.cmake" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR $arch)
set(CMAKE_CXX_COMPILER $triple-g++)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-$arch -L /usr/$triple)
TOOLCHAIN
cmake -S .ci/cross -B "$build" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$PWD/$build/toolchain.cmake" >/dev/null
nice -n 5 cmake --build "$build" -j2 --target determinism_tests
built=$(date +%s)
echo "== $arch: golden state hashes under qemu-$arch"
qemu-"$arch" -L /usr/"$triple" "$build/determinism_tests" --color_output=no --log_level=message
echo "== $arch: the libraries call no libm function outside the exactly rounded set"
/usr/bin/python3 tests/determinism/check_libm_calls.py --nm "$triple-nm" \
    "$build/tamias2d/src/libtamias2d.a" "$build/tamias2d/src/libtamias2d_io.a"
echo "cross_determinism: $arch: $((built - start)) s to install and build, $(($(date +%s) - built)) s to run"
