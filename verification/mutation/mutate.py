#!/usr/bin/python3
"""Mutation testing of the model layer and the dynamics: do the SRS-labelled tests notice when
the code that realises an item is wrong?

Each mutant changes one spot of src/tamias2d/model/ or src/tamias2d/dynamics/: an arithmetic
operator swapped (+ -, * /), a comparison turned (< <=, > >=, == !=), a numeric constant
changed (c -> 2c, 0 -> 1), or an assignment statement removed. The mutant is built in a
scratch copy of the repository with its own build directory (never the caller's), and the
CTest entries labelled with the SRS items that the mutated file, or a library header it includes,
names in its \\srs tags are run. A mutant is killed when they fail (or time out), survives when they pass, and is
stillborn when it does not compile (not counted in the score).

    /usr/bin/python3 verification/mutation/mutate.py OUT_DIR [--sample N] [--seed S]
        [--minutes M] [--all] [--scratch DIR] [--list]

By default a seeded sample of N = 20 mutants within M = 30 minutes; --all takes every mutant
(hours on two cores). Writes OUT_DIR/mutation.json in the verification schema
(docs/traceability.md): the score, one row per mutant, the survivors in full. The report
shows it; it is not one of the expected programs (a run on request).
"""
import argparse
import datetime
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TARGET_DIRS = ("src/tamias2d/model", "src/tamias2d/dynamics")
TAG = re.compile(r"\\srs\{([A-Za-z0-9_, ]+)\}")

# (operator name, pattern on a code line, replacement). Binary operators need spaces on both
# sides (the project's clang-format layout), which keeps ++, ->, templates and unary minus out.
OPERATORS = [
    ("arith + to -", r"(?<=\s)\+(?=\s)", "-"),
    ("arith - to +", r"(?<=\s)-(?=\s)", "+"),
    ("arith * to /", r"(?<=\s)\*(?=\s)", "/"),
    ("arith / to *", r"(?<=\s)/(?=\s)", "*"),
    ("compare < to <=", r"(?<=\s)<(?=\s)", "<="),
    ("compare <= to <", r"(?<=\s)<=(?=\s)", "<"),
    ("compare > to >=", r"(?<=\s)>(?=\s)", ">="),
    ("compare >= to >", r"(?<=\s)>=(?=\s)", ">"),
    ("compare == to !=", r"(?<=\s)==(?=\s)", "!="),
    ("compare != to ==", r"(?<=\s)!=(?=\s)", "=="),
]
NUMBER = re.compile(r"(?<![\w.])(\d+\.\d*(?:e[-+]?\d+)?|\d+e[-+]?\d+)(?![\w.])")
ASSIGNMENT = re.compile(r"^\s*[\w.\[\]>()-]+\s*(?:[-+*/]?=)\s*[^=].*;\s*$")


def code_part(line):
    """The line with comments and string literals blanked (positions kept)."""
    out, i, n = list(line), 0, len(line)
    in_str = False
    while i < n:
        c = line[i]
        if in_str:
            if c == "\\":
                out[i] = " "
                if i + 1 < n:
                    out[i + 1] = " "
                i += 2
                continue
            if c == '"':
                in_str = False
            else:
                out[i] = " "
        elif c == '"':
            in_str = True
        elif line.startswith("//", i):
            for k in range(i, n):
                out[k] = " "
            break
        i += 1
    return "".join(out)


def mutants_of(relpath, text):
    """Every mutant of one file: dicts {file, line, op, before, after}."""
    out = []
    in_block = False
    for no, line in enumerate(text.split("\n"), 1):
        stripped = line.strip()
        if in_block:
            if "*/" in line:
                in_block = False
            continue
        if stripped.startswith("/*") and "*/" not in stripped:
            in_block = True
            continue
        if not stripped or stripped.startswith(("#", "//", "*", "template", "static_assert")):
            continue
        code = code_part(line)
        for name, pat, rep in OPERATORS:
            for m in re.finditer(pat, code):
                after = line[:m.start()] + rep + line[m.end():]
                out.append({"file": relpath, "line": no, "op": name, "before": line, "after": after})
        for m in NUMBER.finditer(code):
            v = float(m.group(1))
            new = "1.0" if v == 0.0 else repr(2.0 * v)
            after = line[:m.start()] + new + line[m.end():]
            out.append({"file": relpath, "line": no, "op": "constant " + m.group(1) + " to " + new,
                        "before": line, "after": after})
        if ASSIGNMENT.match(code) and not re.match(r"^\s*(?:const\s+|auto\s|[\w:<>]+\s+\w+\s*=)",
                                                    code):
            out.append({"file": relpath, "line": no, "op": "statement removed",
                        "before": line, "after": ""})
    return out


def all_mutants(root):
    muts = []
    for d in TARGET_DIRS:
        for f in sorted(os.listdir(os.path.join(root, d))):
            if f.endswith((".hpp", ".cpp")):
                rel = f"{d}/{f}"
                with open(os.path.join(root, rel), encoding="utf-8") as fh:
                    muts += mutants_of(rel, fh.read())
    for i, m in enumerate(muts):
        m["id"] = i
    return muts


INCLUDE = re.compile(r'^\s*#\s*include\s+"(tamias2d/[^"]+)"', re.M)


def labels_of(root, relpath):
    """The SRS labels of the file's \\srs tags and of every library header it includes,
    directly or not: the items whose formulas the file realises or calls."""
    found, seen, todo = set(), set(), [relpath]
    while todo:
        rel = todo.pop()
        if rel in seen:
            continue
        seen.add(rel)
        try:
            with open(os.path.join(root, rel), encoding="utf-8") as fh:
                text = fh.read()
        except OSError:
            continue
        for m in TAG.finditer(text):
            found |= {x.strip() for x in m.group(1).split(",") if x.strip()}
        todo += ["src/" + inc for inc in INCLUDE.findall(text)]
    return sorted(found)


def run(cmd, cwd=None, timeout=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return None, "timeout"


def prepare_scratch(root, scratch):
    """A copy of the sources (no .git, builds or reports) and a configured Release build."""
    src = os.path.join(scratch, "src")
    build = os.path.join(scratch, "build")
    ignore = shutil.ignore_patterns(".git", "build*", "reports", "__pycache__")
    if os.path.isdir(src):
        shutil.rmtree(src)
    shutil.copytree(root, src, ignore=ignore)
    # -O1: mutants compile faster; the tests judge behaviour, not speed.
    rc, out = run(["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                   "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG",
                   "-DTAMIAS_BUILD_VERIFICATION=OFF", "-DTAMIAS_BUILD_APPS=OFF",
                   "-DTAMIAS_INSTALL=OFF"])
    if rc != 0:
        raise SystemExit("scratch configure failed:\n" + out[-3000:])
    return src, build


def ctest_entries(build, labels):
    """{test name: executable target} of the CTest entries carrying any of labels."""
    rc, out = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    if rc != 0:
        return {}
    entries = {}
    for t in json.loads(out).get("tests", []):
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        tl = props.get("LABELS", [])
        if isinstance(tl, str):
            tl = [tl]
        if set(tl) & set(labels) and "@" in t["name"]:
            entries[t["name"]] = t["name"].split("@", 1)[0]
    return entries


def judge(m, src, build, labels, test_timeout):
    path = os.path.join(src, m["file"])
    with open(path, encoding="utf-8") as fh:
        original = fh.read()
    lines = original.split("\n")
    assert lines[m["line"] - 1] == m["before"]
    lines[m["line"] - 1] = m["after"]
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("\n".join(lines))
        entries = ctest_entries(build, labels)
        if not entries:
            return "no tests", "", []
        targets = sorted(set(entries.values()))
        rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
        if rc != 0:
            return "stillborn", out[-600:], sorted(entries)
        regex = "^(" + "|".join(re.escape(n) for n in sorted(entries)) + ")$"
        rc, out = run(["ctest", "--test-dir", build, "-R", regex, "--stop-on-failure", "-j2",
                       "--timeout", str(test_timeout)], timeout=test_timeout * len(entries) + 60)
        if rc is None or rc != 0:
            return "killed", out[-600:], sorted(entries)
        return "survived", "", sorted(entries)
    finally:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(original)


def commit_of(root):
    rc, out = run(["git", "-C", root, "rev-parse", "HEAD"])
    rc2, st = run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"])
    return (out.strip() if rc == 0 else "unknown"), bool(st.strip()) if rc2 == 0 else False


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    ap.add_argument("--sample", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--minutes", type=float, default=30.0)
    ap.add_argument("--all", action="store_true", help="every mutant, no time box")
    ap.add_argument("--scratch", default=os.path.join("/tmp", f"tamias-mutation-{os.getuid()}"))
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--test-timeout", type=int, default=300)
    ap.add_argument("--list", action="store_true", help="print the mutants and stop")
    a = ap.parse_args(argv)

    muts = all_mutants(a.root)
    if a.list:
        try:
            for m in muts:
                print(f"{m['id']:5d} {m['file']}:{m['line']} {m['op']}")
            print(f"{len(muts)} mutants")
        except BrokenPipeError:  # piped into head
            pass
        return 0
    chosen = muts if a.all else random.Random(a.seed).sample(muts, min(a.sample, len(muts)))
    deadline = None if a.all else time.monotonic() + 60.0 * a.minutes
    commit, dirty = commit_of(a.root)
    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    src, build = prepare_scratch(a.root, a.scratch)
    rows, results = [], []
    for m in chosen:
        if deadline is not None and time.monotonic() > deadline:
            break
        labels = labels_of(a.root, m["file"])
        t0 = time.monotonic()
        verdict, log, entries = judge(m, src, build, labels, a.test_timeout)
        secs = time.monotonic() - t0
        r = dict(m, verdict=verdict, labels=labels, tests=entries, seconds=round(secs, 1),
                 log=log if verdict in ("survived", "stillborn") else "")
        results.append(r)
        rows.append([m["id"], f"{m['file']}:{m['line']}", m["op"], ", ".join(labels), verdict,
                     round(secs)])
        print(f"{verdict:10s} #{m['id']} {m['file']}:{m['line']} {m['op']} ({secs:.0f} s)",
              flush=True)
    killed = sum(r["verdict"] == "killed" for r in results)
    survived = [r for r in results if r["verdict"] == "survived"]
    counted = killed + len(survived)
    score = killed / counted if counted else 0.0
    finished = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    details = (f"{killed} of {counted} compiled mutants killed ({100 * score:.0f} %), "
               f"{len(survived)} survived, "
               f"{sum(r['verdict'] == 'stillborn' for r in results)} did not compile, "
               f"{sum(r['verdict'] == 'no tests' for r in results)} had no labelled test; "
               f"{len(results)} of {len(chosen)} chosen from {len(muts)} "
               f"({'all' if a.all else f'seed {a.seed}, sample {a.sample}, {a.minutes:g} min box'})")
    doc = {
        "program": "mutation",
        "description": "Mutation testing of src/tamias2d/model/ and dynamics/: mutants (operator "
                       "swaps, constants, comparisons, removed assignments) built in a scratch "
                       "copy, judged by the CTest entries labelled with the SRS items the mutated "
                       "file's \\srs tags, or those of the library headers it includes, name. Survivors are listed in full; the score counts "
                       "compiled mutants only. This run: " + details + ".",
        "provenance": {"commit": commit, "dirty": dirty, "build_id": None, "built": started,
                       "generated": finished},
        "checks": [],
        "tables": [{"name": "Mutants", "columns": ["id", "where", "mutation", "labels (tests run)",
                                                   "verdict", "seconds"], "rows": rows},
                   {"name": "Survivors",
                    "columns": ["id", "where", "before", "after"],
                    "rows": [[r["id"], f"{r['file']}:{r['line']}", r["before"].strip(),
                              r["after"].strip() or "(removed)"] for r in survived]}],
        "series": [],
        "score": score,
        "summary": details,
        "mutants": results,
    }
    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "mutation.json"), "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    print("mutation: " + details)
    return 0


if __name__ == "__main__":
    sys.exit(main())
