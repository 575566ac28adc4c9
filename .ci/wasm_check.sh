#!/usr/bin/env bash
# CI: the golden state hashes in WebAssembly: the library compiled by Debian 12's emscripten
# (scripts/build_wasm.sh, the live sandbox's build: musl's libm, -O2 -ffp-contract=off) with the
# golden-hash test (tests/determinism/test_golden_hashes.cpp, every example scene at every
# checkpoint, on one worker and on four, the four run one after another on the calling thread:
# the module has no threads), run by Node.js (the nodejs package) on the real file system. The
# same golden file as the x86-64 builds must come out. Installs emscripten and nodejs when
# missing.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
needed=()
for p in emscripten nodejs libboost-dev nlohmann-json3-dev python3; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || needed+=("$p")
done
if ((${#needed[@]})); then
    echo "wasm_check: installing ${needed[*]}"
    SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${needed[@]}" >/dev/null
fi
scripts/build_wasm.sh build-wasm --determinism-tests
built=$(date +%s)
echo "== WebAssembly: golden state hashes under node $(node --version)"
node build-wasm/determinism_tests.js --color_output=no --log_level=message
echo "wasm_check: $((built - start)) s to install and build, $(($(date +%s) - built)) s to run"
