#!/usr/bin/env bash
# Installs the Debian packages Tamias2D needs; silent and fast when all are present.
set -euo pipefail
pkgs=(build-essential clang clang-14 libclang-rt-14-dev cmake ninja-build pkg-config clang-format
      libboost-dev libboost-test-dev nlohmann-json3-dev
      libgsl-dev libeigen3-dev libchipmunk-dev libbox2d-dev libbenchmark-dev
      graphviz gcovr doxygen python3-yaml python3-matplotlib python3-jsonschema)
missing=()
for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
