"""Is the evidence of the tree being reported? The builds a report joins, and their checks.

A build directory records what its last complete build was made of in provenance.json
(cmake/TamiasProvenance.cmake): the commit, the tree (a hash of the commit and the uncommitted
changes to tracked files), a build id, the compiler, flags, options and Debian packages. The
report's verdicts come from running that build's tests, so the harness refuses (one failing
check, which fails the gate) a build that is not of the checkout being reported:
  * its tree is not the checkout's: a source changed (or the commit moved) since it was built;
  * the build system still has work to do (`ninja -n`): a target was built alone since, or a
    source changed and was changed back.
The evidence built elsewhere (coverage and mutation in an instrumented scratch copy, fuzzing in
a Clang build) carries its own provenance with the same tree key; the report lists every build
it joined with its flags.
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess


def _git(root, *args):
    proc = subprocess.run(["git", "-C", root, *args], capture_output=True, timeout=120)
    if proc.returncode != 0:
        raise OSError(proc.stderr.decode("utf-8", "replace").strip())
    return proc.stdout


def tree_key(root):
    """SHA-1 of the commit, the porcelain status and the diff against HEAD, computed as
    cmake/TamiasProvenance.cmake computes it (None without git)."""
    try:
        commit = _git(root, "rev-parse", "HEAD").decode().strip()
        status = _git(root, "status", "--porcelain", "--untracked-files=no")
        diff = _git(root, "diff", "HEAD")
    except (OSError, subprocess.TimeoutExpired):
        return None
    return hashlib.sha1(commit.encode() + b"\n" + status + diff).hexdigest()


def changed_files(root):
    """The tracked files that differ from HEAD (for a message)."""
    try:
        out = _git(root, "status", "--porcelain", "--untracked-files=no").decode()
    except (OSError, subprocess.TimeoutExpired):
        return []
    return [line[3:] for line in out.splitlines() if len(line) > 3]


STAMP = "TamiasProvenance.cmake"
# Steps ninja lists at every dry run of a configured tree: the stamp, and the check of the
# CONFIGURE_DEPENDS globs with the CMake re-run it may lead to (a changed CMakeLists.txt shows
# as another tree instead).
ALWAYS = (STAMP, "tamias_build_stamp", "Re-checking globbed directories", "Re-running CMake")


def _without_regeneration(manifest):
    """build.ninja without its own regeneration edge. A dry run stops at that edge, which the
    CONFIGURE_DEPENDS globs make dirty at every run, before it lists any other work."""
    out, skip = [], False
    for line in manifest.splitlines(keepends=True):
        if line.startswith("build build.ninja:"):
            skip = True
            continue
        if skip and line.startswith("  "):
            continue
        skip = False
        out.append(line)
    return "".join(out)


def pending_steps(build_dir):
    """The build steps `ninja -n` would still run (against the build's own logs and depfiles),
    but the stamp itself, which runs at every build. None when the build is not a Ninja build
    or ninja cannot say."""
    manifest = os.path.join(build_dir, "build.ninja")
    if not os.path.exists(manifest):
        return None
    ninja = shutil.which("ninja") or shutil.which("ninja-build")
    if not ninja:
        return None
    dry = os.path.join(build_dir, "CMakeFiles", "tamias_dry_run.ninja")
    try:
        with open(manifest, encoding="utf-8") as fh:
            text = _without_regeneration(fh.read())
        with open(dry, "w", encoding="utf-8") as fh:
            fh.write(text)
        proc = subprocess.run([ninja, "-C", build_dir, "-f", os.path.relpath(dry, build_dir),
                               "-n"], capture_output=True, text=True, timeout=300)
    except (OSError, subprocess.TimeoutExpired):
        return None
    if proc.returncode != 0:
        return [f"ninja -n failed: {proc.stderr.strip()[:300]}"]
    steps = []
    for line in proc.stdout.splitlines():
        if not line.startswith("["):
            continue
        step = line.split("] ", 1)[-1]
        if any(a in step for a in ALWAYS):
            continue
        steps.append(step)
    return steps


def judge_build(build_dir, source_root, build_prov, ran_tests):
    """Problems that make the build's results not evidence for the checkout (empty when it
    is). build_prov: <build>/provenance.json or None."""
    problems = []
    if build_prov is None:
        if ran_tests:
            problems.append(f"{build_dir} has no provenance.json: its last build did not "
                            "complete, so the results run from it are of an unknown build")
        return problems
    current = tree_key(source_root)
    if current and build_prov.get("tree") != current:
        changed = changed_files(source_root)
        problems.append(
            f"the build in {build_dir} is stale: it was built from tree "
            f"{str(build_prov.get('tree'))[:12]} (commit {str(build_prov.get('commit'))[:12]}"
            f"{', with uncommitted changes' if build_prov.get('dirty') else ''}), the checkout is "
            f"tree {current[:12]}" + (f" (changed: {', '.join(changed[:6])})" if changed else "")
            + "; rebuild before reporting")
    pending = pending_steps(build_dir)
    if pending:
        problems.append(f"the build in {build_dir} is stale: `ninja -n` would still run "
                        f"{len(pending)} step(s), e.g. {pending[0][:160]}")
    return problems


def evidence_builds(build_dir, build_prov, programs):
    """The builds the report joins: the build directory's, and those the results name."""
    out = []
    if build_prov:
        out.append({"name": "build directory (tests, verification programs)",
                    "where": build_dir, **{k: build_prov.get(k) for k in (
                        "commit", "dirty", "tree", "build_id", "built", "compiler", "flags",
                        "options", "packages")}})
    for p in programs:
        prov = p.get("provenance") or {}
        b = prov.get("build")
        if isinstance(b, dict):
            out.append({"name": f"{p['program']}: {b.get('name', 'its own build')}",
                        "where": b.get("where"), "commit": prov.get("commit"),
                        "dirty": prov.get("dirty"), "tree": prov.get("tree"),
                        "build_id": prov.get("build_id"), "built": prov.get("built"),
                        "compiler": b.get("compiler"), "flags": b.get("flags"),
                        "options": b.get("options"), "packages": None})
    return out


def load(path):
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) else None
