#!/usr/bin/env bash
# GSL is GPL-3: the library and the CLI must not contain or link any GSL symbol.
set -euo pipefail
build=${1:-build}
status=0
for f in "$build"/src/libtamias2d.a "$build"/apps/cli/tamias2d; do
    [ -e "$f" ] || continue
    if nm -A "$f" 2>/dev/null | grep -q ' gsl_'; then echo "GSL symbol in $f"; status=1; fi
    if [ -x "$f" ] && ldd "$f" | grep -q libgsl; then echo "$f links libgsl"; status=1; fi
done
[ $status -eq 0 ] && echo "no GSL symbol in the library or the CLI"
exit $status
