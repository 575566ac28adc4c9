#!/usr/bin/env bash
# Installs the Debian packages Tamias2D needs; silent and fast when all are present.
set -euo pipefail
pkgs=()
while read -r p; do
    case "$p" in ''|'#'*) ;; *) pkgs+=("$p") ;; esac
done < "$(dirname "$0")/debian-packages.txt"
missing=()
for p in "${pkgs[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
