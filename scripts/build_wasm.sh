#!/usr/bin/env bash
# The live sandbox (docs/viewer.md, "Live sandbox"): the library's own sources (src/tamias2d/,
# scene reader included) and apps/wasm/sandbox_bindings.cpp compiled to WebAssembly with
# Debian's emscripten, and one self-contained page, build-wasm/sandbox.html, that runs them.
#   scripts/build_wasm.sh [BUILD_DIR] [--determinism-tests] [--determinism-tests-web]
#                                                                (default build-wasm/)
# --determinism-tests: also BUILD_DIR/determinism_tests.js, the determinism tests
# (tests/determinism/test_golden_hashes.cpp and test_recordings.cpp, Boost.Test header-only)
# compiled from the same objects for Node.js, which runs them on the real file system
# (.ci/wasm_check.sh).
# --determinism-tests-web: also BUILD_DIR/web/determinism_tests.html, the same test objects
# linked for a browser (the example scenes, the golden file and the recordings embedded in the
# module, .wasm included, at the paths the tests were compiled with), which Chromium runs
# (.ci/wasm_browser_check.sh).
# Installs emscripten when em++ is missing (about 30 s on a machine that has clang 14; it is
# not in scripts/setup.sh: nothing else needs it).
#
# em++ directly, not emcmake + the project's CMake: its find_package(Boost) and
# find_package(nlohmann_json) would either fail inside emscripten's sysroot or put /usr/include
# on the include path, whose glibc headers clash with emscripten's libc. Here only the two
# header-only libraries are exposed, through a directory of symlinks added with -isystem.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=build-wasm
determinism_tests=0
determinism_tests_web=0
for arg in "$@"; do
    case $arg in
    --determinism-tests) determinism_tests=1 ;;
    --determinism-tests-web) determinism_tests_web=1 ;;
    *) out=$arg ;;
    esac
done
mkdir -p "$out/obj" "$out/include/tamias2d" "$out/host"
out=$(cd "$out" && pwd)

if ! command -v em++ >/dev/null; then
    echo "build_wasm: installing emscripten"
    SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq emscripten >/dev/null
fi
for p in libboost-dev nlohmann-json3-dev; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || ./scripts/setup.sh
done
# Debian's emscripten runs its JavaScript tools with node and finds their modules (acorn) in
# /usr/share/nodejs, where Debian's nodejs looks by itself but another build of node does not.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

ln -sfn /usr/include/boost "$out/host/boost"
ln -sfn /usr/include/nlohmann "$out/host/nlohmann"
version=$(sed -n 's/^project(tamias2d VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
IFS=. read -r major minor patch <<<"$version"
sed -e "s/@PROJECT_VERSION_MAJOR@/$major/" -e "s/@PROJECT_VERSION_MINOR@/$minor/" \
    -e "s/@PROJECT_VERSION_PATCH@/$patch/" -e "s/@PROJECT_VERSION@/$version/" \
    cmake/version.hpp.in >"$out/include/tamias2d/version.hpp.new"
cmp -s "$out/include/tamias2d/version.hpp.new" "$out/include/tamias2d/version.hpp" ||
    mv "$out/include/tamias2d/version.hpp.new" "$out/include/tamias2d/version.hpp"
rm -f "$out/include/tamias2d/version.hpp.new"
# tamias2d/config.hpp as CMake's default TAMIAS2D_EXCEPTIONS=ON generates it (cmake/config.hpp.in).
sed -e "s/@TAMIAS2D_EXCEPTIONS@/ON/" -e "s/@TAMIAS2D_EXCEPTIONS_VALUE@/1/" cmake/config.hpp.in \
    >"$out/include/tamias2d/config.hpp.new"
cmp -s "$out/include/tamias2d/config.hpp.new" "$out/include/tamias2d/config.hpp" ||
    mv "$out/include/tamias2d/config.hpp.new" "$out/include/tamias2d/config.hpp"
rm -f "$out/include/tamias2d/config.hpp.new"
# The export macros (GenerateExportHeader's tamias2d/export.hpp and tamias2d/io/export.hpp in
# the CMake build): empty, as for a static library, since everything links into one module.
mkdir -p "$out/include/tamias2d/io"
printf '#pragma once\n#define TAMIAS2D_EXPORT\n' >"$out/include/tamias2d/export.hpp"
printf '#pragma once\n#define TAMIAS2D_IO_EXPORT\n' >"$out/include/tamias2d/io/export.hpp"

# The flags that decide the results' bits are the native build's (src/CMakeLists.txt): no
# contraction into fused multiply-adds, no -ffast-math. -fexceptions: the library reports bad
# input by exceptions, which the binding turns into messages.
# charconv_compat.hpp: floating-point to_chars/from_chars, which emscripten's libc++ lacks.
flags=(-std=c++20 -O2 -ffp-contract=off -fexceptions -DNDEBUG
       -I"$root/include" -I"$out/include" -I"$root/src" -isystem "$out/host"
       -include "$root/apps/wasm/charconv_compat.hpp")
sources=$(find src/tamias2d -name '*.cpp' | sort)
sources="$sources apps/cli/view_geometry.cpp apps/wasm/sandbox_bindings.cpp"
start=$(date +%s)
# Two compilers at a time, each object rebuilt only when its source or a header is newer.
for s in $sources; do
    o="$out/obj/$(echo "${s%.cpp}" | tr / _).o"
    if [ ! -f "$o" ] || [ -n "$(find "$s" include src apps/wasm -newer "$o" -name '*.[ch]pp' -print -quit)" ]; then
        echo "$s $o"
    fi
done | nice -n 5 xargs -r -P 2 -n 2 sh -c 'echo "em++ $0"; em++ '"${flags[*]}"' -c "$0" -o "$1"'

exports=$(sed -n 's/^TAMIAS_EXPORT [^(]* \**\(tamias_[a-z_]*\)(.*/_\1/p' apps/wasm/sandbox_bindings.cpp |
          paste -sd, -)
# SINGLE_FILE: the .wasm travels inside the .js as base64, so that the page opens from disk
# (a browser does not fetch a file beside a file:// page).
nice -n 5 em++ "${flags[@]}" "$out"/obj/*.o -o "$out/tamias_sandbox.js" \
    -sMODULARIZE=1 -sEXPORT_NAME=createTamiasSandbox -sALLOW_MEMORY_GROWTH=1 \
    -sSINGLE_FILE=1 -sENVIRONMENT=web -sEXPORTED_FUNCTIONS="$exports" \
    -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,UTF8ToString
# The same link without SINGLE_FILE gives the .wasm alone, to measure it.
nice -n 5 em++ "${flags[@]}" "$out"/obj/*.o -o "$out/tamias_sandbox_size.js" \
    -sMODULARIZE=1 -sEXPORT_NAME=createTamiasSandbox -sALLOW_MEMORY_GROWTH=1 \
    -sENVIRONMENT=web -sEXPORTED_FUNCTIONS="$exports" \
    -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,UTF8ToString
mv "$out/tamias_sandbox_size.wasm" "$out/tamias_sandbox.wasm"
rm -f "$out/tamias_sandbox_size.js"

# The page: apps/wasm/sandbox.html with the player's styles and drawing code
# (apps/cli/player/), the module and the example scenes inlined.
python3 apps/wasm/assemble_sandbox.py --template apps/wasm/sandbox.html \
    --css apps/cli/player/player.css --player-js apps/cli/player/player.js \
    --sandbox-js apps/wasm/sandbox.js --module "$out/tamias_sandbox.js" \
    --scenes examples/scenes -o "$out/sandbox.html"
if ((determinism_tests || determinism_tests_web)); then
    # Boost.Test as a header (no Boost library for WebAssembly): its implementation in one
    # object, the test in another, both rebuilt only when older than their sources.
    test_flags=("${flags[@]}" -I"$root/tests" -DTAMIAS_EXAMPLE_SCENES="\"$root/examples/scenes\""
                -DTAMIAS_GOLDEN_HASHES="\"$root/tests/determinism/golden_hashes.txt\""
                -DTAMIAS_RECORDINGS="\"$root/tests/determinism/recordings\"")
    for s in tests/determinism/test_golden_hashes.cpp tests/determinism/test_recordings.cpp \
             .ci/cross/boost_test_main.cpp; do
        o="$out/test_$(basename "${s%.cpp}").o"
        if [ ! -f "$o" ] || [ -n "$(find "$s" include src -newer "$o" -name '*.[ch]pp' -print -quit)" ]; then
            echo "em++ $s"
            nice -n 5 em++ "${test_flags[@]}" -c "$s" -o "$o"
        fi
    done
    library_objects=$(ls "$out"/obj/src_tamias2d_*.o)
    test_objects=("$out/test_test_golden_hashes.o" "$out/test_test_recordings.o"
                  "$out/test_boost_test_main.o")
fi
if ((determinism_tests)); then
    # NODERAWFS: the module reads the scenes and the golden file where they are; EXIT_RUNTIME:
    # node's exit status is the test's; WASM_ASYNC_COMPILATION=0: the .wasm is read from disk
    # (emscripten 3.1.6 would fetch() it, by a path, in a node that has fetch).
    nice -n 5 em++ "${flags[@]}" $library_objects "${test_objects[@]}" \
        -o "$out/determinism_tests.js" -sENVIRONMENT=node \
        -sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1 -sWASM_ASYNC_COMPILATION=0
    echo "build_wasm: $out/determinism_tests.js (run it with node)"
fi
if ((determinism_tests_web)); then
    # The data the tests read, embedded at the absolute paths compiled into them (SRC@DST);
    # SINGLE_FILE: the .wasm inside the .js, so the page runs from file:// (a browser fetches
    # nothing beside a file:// page); EXIT_RUNTIME: main's status reaches the page's onExit.
    mkdir -p "$out/web"
    embeds=()
    for d in examples/scenes tests/determinism/golden_hashes.txt tests/determinism/recordings; do
        embeds+=(--embed-file "$root/$d@$root/$d")
    done
    nice -n 5 em++ "${flags[@]}" $library_objects "${test_objects[@]}" \
        -o "$out/web/determinism_tests.js" -sENVIRONMENT=web -sSINGLE_FILE=1 \
        -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1 "${embeds[@]}"
    cp apps/wasm/determinism_tests.html "$out/web/determinism_tests.html"
    echo "build_wasm: $out/web/determinism_tests.html (run it in a browser)"
fi
echo "build_wasm: $out/sandbox.html ($(stat -c %s "$out/sandbox.html") bytes; wasm" \
     "$(stat -c %s "$out/tamias_sandbox.wasm") bytes) in $(( $(date +%s) - start )) s"
