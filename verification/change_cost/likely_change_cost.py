#!/usr/bin/python3
"""NFR5 (maintainability) measured on the likely changes LC1-LC3 as they are made.

Usage: likely_change_cost.py OUT_DIR [--repo DIR]

A commit that makes a likely change says so in a trailer line "Likely-change: LC2". For each
likely change with such commits this program sums, over those commits, the lines added and
deleted in files of the library and its command (src/, include/, apps/) that existed before the
change's first commit: the existing code the change had to touch. New files (also when a later
commit of the change edits them), tests, verification programs,
documents and the SRS data are the change itself, not its cost. The check compares that sum
with 10 % of the lines the same directories held before the change's first commit: NFR5's
"10 % of the original development" read as a share of existing code (erratum E71), because
development time is recorded nowhere.

A commit that restructures existing code so that a likely change can be made, without making
it, says "Prepares-likely-change: LC3". Its cost is measured the same way and reported beside
the change's, not added to it: the restructuring serves every later change as much as this one.
A second check per change states the wider reading, the change's preparation and new files
included, over the same base; both are NFR5's figures.

NFR5 says "should": a goal (srs/nonfunctional.yaml obligation), so the report shows each figure
as "goal met" or "goal missed" and never fails its gate on it. The exit status still says
whether every figure is within the limit.

Beside LC1-LC3 it measures, the same way, one change the SRS does not list: "filter-joint"
(commits with "Likely-change: filter-joint"), a joint kind added after the joints were given their
own files (issue 44's maintainability figure). Its check names a target instead of an SRS label:
under 3 % of the existing lines of src/, include/, apps/, and no edit to the central files
(world.cpp, validation.cpp, the scene reader and writer) beyond one table row each, read as: no
line deleted and at most ROW_LINES lines added per file (an entry of the file's list, such as a
forwarding overload, and the include it needs). A missed target is reported, not a failure.

Writes OUT_DIR/likely_change_cost.json in the verification schema (docs/traceability.md). In a
checkout without the history (a shallow clone) it writes no check and says why.
"""

import json
import os
import subprocess
import sys

CODE_DIRS = ("src", "include", "apps")
LIMIT = 0.10  # NFR5: 10 %
CHANGES = ("LC1", "LC2", "LC3")
# Issue 44's target for one more joint kind (not an SRS item): a share of the existing lines, and
# at most one table row in each central file.
EXTRA_CHANGE = "filter-joint"
EXTRA_LIMIT = 0.03
ROW_LINES = 5
CENTRAL_FILES = ("src/tamias2d/world.cpp", "src/tamias2d/validation.cpp",
                 "src/tamias2d/io/scene_reader.cpp", "src/tamias2d/io/scene_writer.cpp")


def git(repo, *args):
    return subprocess.run(["git", "-C", repo, *args], check=True, capture_output=True,
                          text=True).stdout


def code_lines(repo, rev):
    """Lines of the files under CODE_DIRS at rev."""
    names = git(repo, "ls-tree", "-r", "--name-only", rev, "--", *CODE_DIRS).split()
    total = 0
    for name in names:
        blob = subprocess.run(["git", "-C", repo, "show", f"{rev}:{name}"], check=True,
                              capture_output=True).stdout
        total += blob.count(b"\n")
    return total


def existed(repo, rev, path):
    return subprocess.run(["git", "-C", repo, "cat-file", "-e", f"{rev}:{path}"],
                          capture_output=True).returncode == 0


def measure(repo, label, trailer="Likely-change"):
    commits = git(repo, "log", "--reverse", "--format=%H", f"--grep=^{trailer}: {label}$",
                  "HEAD").split()
    if not commits:
        return None
    per_file = {}
    new_lines = 0
    # Existing means existing before the change began: a file the change itself created stays
    # new however many of its commits then edit it.
    base = f"{commits[0]}^"
    for c in commits:
        parent = f"{c}^"
        for row in git(repo, "diff", "--numstat", parent, c, "--", *CODE_DIRS).splitlines():
            added, deleted, path = row.split("\t", 2)
            if added == "-":  # binary
                continue
            if existed(repo, base, path):
                a, d = per_file.get(path, (0, 0))
                per_file[path] = (a + int(added), d + int(deleted))
            else:
                new_lines += int(added)
    return {"commits": commits, "per_file": per_file, "new_lines": new_lines,
            "base": code_lines(repo, base)}


def figure(share, limit=LIMIT):
    """The figure beside its limit, as the report's goal box shows it."""
    return f"{100 * share:.2f} % {'<=' if share <= limit else '>'} {100 * limit:.0f} %"


def extra_change_check(m):
    """The check of EXTRA_CHANGE's measure m against issue 44's target, and its table."""
    changed = sum(a + d for a, d in m["per_file"].values())
    share = changed / m["base"] if m["base"] else 0.0
    central = {f: m["per_file"].get(f, (0, 0)) for f in CENTRAL_FILES}
    beyond = [f for f, (a, d) in central.items() if d > 0 or a > ROW_LINES]
    passed = share < EXTRA_LIMIT and not beyond
    edited = ", ".join(f"{p} {a + d} (+{a} -{d})" for p, (a, d) in sorted(m["per_file"].items()))
    details = (f"{EXTRA_CHANGE} touched {changed} lines (added + deleted) of "
               f"{len(m['per_file'])} existing files of src/, include/, apps/ in "
               f"{len(m['commits'])} commits: {100 * share:.2f} % of the {m['base']} lines those "
               f"directories held before it (target: under {100 * EXTRA_LIMIT:.0f} %); "
               f"{m['new_lines']} lines in new files, not counted. Central files: "
               + ", ".join(f"{f} +{a} -{d}" for f, (a, d) in central.items())
               + (f"; beyond one table row (> {ROW_LINES} lines added, or a line deleted): "
                  + ", ".join(beyond) if beyond else
                  f"; each within one table row (no line deleted, at most {ROW_LINES} added)")
               + f". Files edited: {edited}")
    check = {"name": f"{EXTRA_CHANGE} changes under {100 * EXTRA_LIMIT:.0f} % of the existing code "
                     "and at most one table row of each central file",
             "labels": [], "passed": passed,
             "target": (f"issue 44: one more joint kind after the redesign touches under "
                        f"{100 * EXTRA_LIMIT:.0f} % of the existing lines of src/, include/, "
                        "apps/, and no more than one table row each of world.cpp, the scene "
                        "reader and writer, validation.cpp"),
             "figure": (f"{100 * share:.2f} % {'<' if share < EXTRA_LIMIT else '>='} "
                        f"{100 * EXTRA_LIMIT:.0f} %; central files beyond a row: {len(beyond)}"),
             "oracle": "git history: lines of pre-existing files changed by the commits marked "
                       f"'Likely-change: {EXTRA_CHANGE}', as for LC1-LC3",
             "details": details}
    table = {"name": f"{EXTRA_CHANGE}: existing files changed",
             "columns": ["file", "lines added", "lines deleted"],
             "rows": [[p, a, d] for p, (a, d) in sorted(m["per_file"].items())]}
    return check, table


def provenance(repo):
    """The commit and tree this run read (a script: no build, so no build id) and the time
    now (UTC)."""
    import datetime
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    from traceability.builds import tree_key
    try:
        commit = git(repo, "rev-parse", "HEAD").strip()
        dirty = bool(git(repo, "status", "--porcelain", "--untracked-files=no").strip())
    except (subprocess.CalledProcessError, FileNotFoundError):
        commit, dirty = "unknown", False
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    return {"commit": commit, "dirty": dirty, "tree": tree_key(repo), "build_id": None,
            "generated": now}


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    out_dir = argv[1]
    repo = argv[argv.index("--repo") + 1] if "--repo" in argv else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..")
    checks, tables, notes = [], [], []
    try:
        shallow = git(repo, "rev-parse", "--is-shallow-repository").strip() == "true"
    except (subprocess.CalledProcessError, FileNotFoundError) as exc:
        shallow, notes = True, [f"no git history: {exc}"]
    if shallow:
        notes.append("the checkout has no complete history (shallow clone): NFR5 not measured")
    else:
        for label in CHANGES:
            m = measure(repo, label)
            if m is None:
                notes.append(f"{label}: no commit carries 'Likely-change: {label}' yet")
                continue
            changed = sum(a + d for a, d in m["per_file"].values())
            prep = measure(repo, label, "Prepares-likely-change")
            prep_changed = sum(a + d for a, d in prep["per_file"].values()) if prep else 0
            prepared = ""
            if prep is not None:
                n = len(prep["commits"])
                prepared = (f"; the {n} commit{'s' if n > 1 else ''} preparing it touched "
                            f"{prep_changed} lines of existing files "
                            f"({100 * prep_changed / prep['base']:.2f} % of {prep['base']})")
                tables.append({"name": f"{label}: existing files changed by its preparation",
                               "columns": ["file", "lines added", "lines deleted"],
                               "rows": [[p, a, d] for p, (a, d) in
                                        sorted(prep["per_file"].items())]})
            share = changed / m["base"] if m["base"] else 0.0
            # Where the cost went: the existing files that took most of it.
            top = sorted(m["per_file"].items(), key=lambda kv: -(kv[1][0] + kv[1][1]))[:4]
            where = ", ".join(f"{p} {a + d}" for p, (a, d) in top)
            details = (f"{label} touched {changed} lines (added + deleted) of {len(m['per_file'])} "
                       f"existing files of src/, include/, apps/ in {len(m['commits'])} commits: "
                       f"{100 * share:.2f} % of the {m['base']} lines those directories held "
                       f"before it (limit {100 * LIMIT:.0f} %); most in {where}; "
                       f"{m['new_lines']} lines in new files of those directories{prepared}, "
                       "neither counted in this reading")
            checks.append({"name": f"{label} changes at most 10 % of the existing code",
                           "labels": ["NFR5"], "passed": share <= LIMIT,
                           "figure": figure(share),
                           "oracle": "git history: lines of pre-existing files changed by the "
                                     f"commits marked 'Likely-change: {label}' (erratum E71)",
                           "details": details})
            # The wider reading: the change's whole size in code, its preparation and its new
            # files included, over the same base (what a reader of "development time" may mean).
            whole = changed + prep_changed + m["new_lines"]
            whole_share = whole / m["base"] if m["base"] else 0.0
            checks.append({"name": f"{label} with its preparation and new files at most 10 % of "
                                   "the existing code",
                           "labels": ["NFR5"], "passed": whole_share <= LIMIT,
                           "figure": figure(whole_share),
                           "oracle": "git history: lines changed by the commits marked "
                                     f"'Likely-change: {label}' or 'Prepares-likely-change: "
                                     f"{label}', new files included (erratum E71)",
                           "details": f"{changed} lines of existing files + {prep_changed} of its "
                                      f"preparation + {m['new_lines']} in new files = {whole} "
                                      f"lines: {100 * whole_share:.2f} % of {m['base']}"})
            tables.append({"name": f"{label}: existing files changed",
                           "columns": ["file", "lines added", "lines deleted"],
                           "rows": [[p, a, d] for p, (a, d) in sorted(m["per_file"].items())]})
            print(("ok   " if share <= LIMIT else "FAIL ") + details)
        m = measure(repo, EXTRA_CHANGE)
        if m is None:
            notes.append(f"{EXTRA_CHANGE}: no commit carries 'Likely-change: {EXTRA_CHANGE}' yet")
        else:
            check, table = extra_change_check(m)
            checks.append(check)
            tables.append(table)
            print(("ok   " if check["passed"] else "MISS ") + check["details"])
    for n in notes:
        print("note " + n)
    doc = {"program": "likely_change_cost", "provenance": provenance(repo),
           "description": "NFR5: the existing code each likely change (LC1-LC3) touched, from "
                          "the commits that make it; beside them, against issue 44's target "
                          f"(no SRS item), one more joint kind ({EXTRA_CHANGE}). "
                          + " ".join(notes),
           "checks": checks, "tables": tables, "series": []}
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "likely_change_cost.json"), "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    return 0 if all(c["passed"] for c in checks) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
