#!/usr/bin/env bash
# The library-only recipe of docs/user-guide.md ("Using Tamias2D in a project"), run as written
# on a fresh Debian 12: a minbase root made by debootstrap under /tmp, the repository's tracked
# files (as they are in the working tree) copied into /root/tamias2d, the recipe's files written
# to the paths its markers name, and its commands run by bash -e as root in a chroot from the
# source directory, with a clean environment. Passes only when every command succeeds and the
# output ends with the text the guide's output block shows. Nothing is cached: the root is made
# anew and removed on exit. Needs root (or sudo, which it then runs itself under), debootstrap
# (installed when missing) and access to deb.debian.org.
#   .ci/library_recipe_check.sh
set -euo pipefail
cd "$(dirname "$0")/.."
[ "$(id -u)" -eq 0 ] || exec sudo "$PWD/.ci/library_recipe_check.sh" "$@"
start=$(date +%s)
if ! command -v debootstrap >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
fi

work=$(mktemp -d /tmp/tamias_recipe.XXXXXX)
root=$work/root
# Unmounts whatever is mounted under the root (its /proc; debootstrap's own if it failed), deepest
# first, then removes it without crossing into a mount that is still there.
cleanup() {
    for m in $(awk -v r="$root/" 'index($2, r) == 1 { print $2 }' /proc/mounts | sort -r); do
        umount "$m" || umount -l "$m"
    done
    rm -rf --one-file-system "$work"
    echo "library_recipe_check: $(($(date +%s) - start)) s in all, the root's removal included"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

echo "library_recipe_check: debootstrap bookworm into $root"
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$work/debootstrap.log" 2>&1 ||
    { tail -20 "$work/debootstrap.log" >&2; exit 1; }
cp -L /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"

mkdir -p "$root/root/tamias2d"
# (root reading a checkout of another user's: git wants the directory named safe.)
git -c safe.directory="$PWD" ls-files -z | tar --null -T - -c | tar -x -C "$root/root/tamias2d"

# The guide's blocks: each fenced block right after a "<!-- recipe: library-only... -->" line.
/usr/bin/python3 - "$root/root/tamias2d/docs/user-guide.md" "$root" "$work" <<'PY'
import pathlib, re, sys
guide, root, work = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
lines = guide.read_text(encoding="utf-8").splitlines(keepends=True)
blocks = {}
for i, line in enumerate(lines):
    m = re.fullmatch(r"<!-- recipe: library-only(?:, (.*?))? -->\s*", line)
    if not m:
        continue
    if not lines[i + 1].startswith("```"):
        sys.exit(f"{guide}:{i + 1}: no fenced block after the recipe marker")
    end = next(j for j in range(i + 2, len(lines)) if lines[j].startswith("```"))
    blocks[m.group(1) or "commands"] = "".join(lines[i + 2:end])
for key in ("commands", "output"):
    if key not in blocks:
        sys.exit(f"{guide}: no recipe block '{key}'")
for key, text in blocks.items():
    if key.startswith("file "):
        path = root / "root" / key[len("file "):].removeprefix("~/")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        print(f"library_recipe_check: wrote {key[len('file '):]} ({len(text.splitlines())} lines)")
(root / "root" / "recipe.sh").write_text(blocks["commands"], encoding="utf-8")
(work / "expected.txt").write_text(blocks["output"], encoding="utf-8")
PY

echo "library_recipe_check: running the recipe ($(grep -c '' "$root/root/recipe.sh") lines) in the chroot"
status=0
env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
    chroot "$root" /bin/bash -c 'cd /root/tamias2d && exec /bin/bash -e -o pipefail /root/recipe.sh' \
    >"$work/recipe.out" 2>"$work/recipe.err" || status=$?
elapsed=$(($(date +%s) - start))
if [ $status -ne 0 ]; then
    echo "library_recipe_check: the recipe failed (exit status $status) after $elapsed s:" >&2
    tail -25 "$work/recipe.out" >&2
    tail -25 "$work/recipe.err" >&2
    exit 1
fi
expected_lines=$(grep -c '' "$work/expected.txt")
if ! tail -n "$expected_lines" "$work/recipe.out" | cmp -s - "$work/expected.txt"; then
    echo "library_recipe_check: the recipe's output ends with" >&2
    tail -n "$expected_lines" "$work/recipe.out" >&2
    echo "but the guide says it prints" >&2
    cat "$work/expected.txt" >&2
    exit 1
fi
echo "library_recipe_check: OK: the recipe built, installed and ran the game, which printed:"
cat "$work/expected.txt"
echo "library_recipe_check: $elapsed s for debootstrap, the packages and the builds"
