#!/usr/bin/env bash
# The main job's "other platforms" phase (CI leaves it out for time): the determinism tests in
# WebAssembly in a browser: the objects .ci/wasm_check.sh runs in Node.js (scripts/build_wasm.sh:
# Debian 12's emscripten, musl's libm, -O2 -ffp-contract=off) linked a second time for the web
# (scripts/build_wasm.sh --determinism-tests-web: the example scenes, the golden file and the
# recordings embedded in the module), and the page build-wasm/web/determinism_tests.html opened from
# file:// in Debian's headless Chromium. All the cases of tests/determinism/: every example scene at
# every checkpoint (steps 1, 10, every 100th and the last), on one worker and on four (the four run
# one after another on the calling thread: the module has no threads), and the committed recordings
# replayed on one and four workers. The same golden file as the x86-64 builds must come out: the
# script fails unless Boost.Test reports "No errors detected" and main returns 0 before the timeout
# (TAMIAS_BROWSER_TIMEOUT seconds, default 300). Run after .ci/wasm_check.sh (its objects are
# reused: only the link and the page are new), on 2 shared cores: 15 to 25 s to link and 4 to 8 s in
# Chromium, the tests' own share of it about 3.5 s (--log_level=test_suite prints each case's time);
# from nothing (every object compiled) about 2 minutes more. Installs emscripten, nodejs and
# chromium when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
needed=()
for p in emscripten nodejs chromium libboost-dev nlohmann-json3-dev python3; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || needed+=("$p")
done
if ((${#needed[@]})); then
    echo "wasm_browser_check: installing ${needed[*]}"
    SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${needed[@]}" >/dev/null
fi
scripts/build_wasm.sh build-wasm --determinism-tests-web
built=$(date +%s)

page="file://$PWD/build-wasm/web/determinism_tests.html"
work=$(mktemp -d)
log="$work/chromium.log"
browser=""
# Ends Chromium's process group and waits (up to 10 s) until it is gone.
stop_browser() {
    [ -n "$browser" ] || return 0
    kill -- "-$browser" 2>/dev/null || true
    wait "$browser" 2>/dev/null || true
    for _ in $(seq 20); do
        kill -0 -- "-$browser" 2>/dev/null || break
        sleep 0.5
    done
    browser=""
}
cleanup() {
    stop_browser
    rm -rf "$work" 2>/dev/null || true
}
trap cleanup EXIT
echo "== WebAssembly: golden state hashes and recordings in $(chromium --version 2>/dev/null)"
# A process group of its own (setsid), ended as a whole: Chromium does not exit when the page
# is done. Console messages reach stderr through --enable-logging=stderr.
setsid /usr/bin/chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$work/profile" --enable-logging=stderr --v=0 "$page" >"$log" 2>&1 &
browser=$!
timeout=${TAMIAS_BROWSER_TIMEOUT:-300}
# The page's lines, from Chromium's console records ("[...:INFO:CONSOLE:N] "TEXT", source: ...").
console() {
    sed -n 's/^\[[^]]*:INFO:CONSOLE[^]]*\] "\(.*\)", source: .*$/\1/p' "$log"
}
end=""
while [ -z "$end" ]; do
    if (($(date +%s) - built > timeout)); then
        console
        echo "wasm_browser_check: no result after $timeout s"
        exit 1
    fi
    if ! kill -0 "$browser" 2>/dev/null; then
        console
        echo "wasm_browser_check: Chromium exited before the tests ended; its log:"
        cat "$log"
        exit 1
    fi
    sleep 2
    end=$(console | grep -m1 '^determinism_tests: \(exit\|abort\) ' || true)
done
stop_browser
out=$(console)
sed '/^determinism_tests: \(exit\|abort\) /q' <<<"$out"
echo "wasm_browser_check: $((built - start)) s to install and build, $(($(date +%s) - built)) s to run"
if [ "$end" != "determinism_tests: exit 0" ] || ! grep -qx '\*\*\* No errors detected' <<<"$out"; then
    echo "wasm_browser_check: FAILED ($end)"
    exit 1
fi
