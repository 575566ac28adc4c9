#!/usr/bin/env bash
# The API reference: Doxygen over include/tamias2d/ (docs/Doxyfile) into OUT_DIR, with the README
# as its main page and the user guide and scene format as pages; fails, listing the warnings,
# when a public name is undocumented or a comment is malformed.
#   scripts/api_reference.sh [OUT_DIR] [BUILD_DIR]      (defaults: reports/api build)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-reports/api}; build=${2:-build}
version=$(sed -n 's/^#define TAMIAS2D_VERSION "\(.*\)"/\1/p' "$build/include/tamias2d/version.hpp")
[ -n "$version" ] || { echo "api_reference: configure $build first (no version.hpp)" >&2; exit 2; }
rm -rf "$out"; mkdir -p "$out"
pages=$(mktemp -d); trap 'rm -rf "$pages"' EXIT
# Doxygen 1.9 gives a Markdown heading an anchor only when written "## Title {#id}", unique over
# all pages; the guides link to their own sections GitHub's way (#title-in-lower-case), so their
# copies get the ids "<page>-<title-in-lower-case>" and their links are rewritten to match.
for md in docs/user-guide.md docs/scene-format.md; do
    /usr/bin/python3 - "$md" "$pages/$(basename "$md")" <<'PY'
import re, sys
src, dst = sys.argv[1:3]
page = re.sub(r"\W", "-", src.rsplit("/", 1)[-1][:-3])
out, fenced = [], False
for line in open(src, encoding="utf-8"):
    if line.startswith("```"):
        fenced = not fenced
    m = None if fenced else re.match(r"^(#{1,6}) (.*?)\s*$", line)
    if m and len(m.group(1)) > 1:
        slug = re.sub(r"[^\w\- ]", "", m.group(2).lower()).replace(" ", "-")
        line = f"{m.group(1)} {m.group(2)} {{#{page}-{slug}}}\n"
    elif not fenced:
        line = re.sub(r"\]\(#([\w\-]+)\)", rf"](#{page}-\1)", line)
    out.append(line)
open(dst, "w", encoding="utf-8").writelines(out)
PY
done
if ! TAMIAS_VERSION=$version TAMIAS_API_OUT=$out TAMIAS_BUILD=$build TAMIAS_PAGES=$pages \
        doxygen docs/Doxyfile || [ -s "$out/warnings.txt" ]; then
    echo "api_reference: Doxygen warnings:" >&2
    sed "s|$PWD/||; s|$pages/|docs/|" "$out/warnings.txt" >&2
    exit 1
fi
rm -f "$out/warnings.txt"
echo "api_reference: $out/index.html ($(find "$out" -name '*.html' | wc -l) pages, no warnings)"
