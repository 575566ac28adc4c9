#!/usr/bin/python3
"""Mutation testing of the model layer and the dynamics: do the SRS-labelled tests notice when
the code that realises an item is wrong?

Each mutant changes one spot of src/tamias2d/model/ or src/tamias2d/dynamics/: an arithmetic
operator swapped (+ -, * /), a comparison turned (< <=, > >=, == !=), a numeric constant
changed (c -> 2c, 0 -> 1), or an assignment statement removed. The mutant is built in a
scratch copy of the repository with its own build directory (never the caller's), and the
CTest entries labelled with the SRS items that the mutated file, or a library header it
includes, names in its \\srs tags are run (a file that reaches no tag: those of the files that
include it). A mutant is killed when they fail (or time out), survives when they pass, and is
stillborn when it does not compile, not built when its objects come out bit for bit as the
unmutated ones (a line of a #if branch this build skips): neither is counted in the score.
The sample is ranked by a seeded hash of each mutant's file, line text and operator, so an
edit elsewhere leaves it, and the judgements of its survivors, in place. A survivor is judged in
survivors.json ("equivalent", argued, or "gap"); score = killed / (killed + survivors not
judged equivalent).

    /usr/bin/python3 verification/mutation/mutate.py OUT_DIR [--sample N] [--seed S]
        [--minutes M] [--all] [--ids I,J,...] [--scratch DIR] [--list]
        [--coverage JSON HTML]

With --coverage the scratch build is instrumented with gcov and, before any mutant, every test
runs once on the unmutated sources: gcovr's summary and pages of src/ and include/ are the
report's coverage (one build for both analyses). Exit status 3 when a test fails there.

By default a seeded sample of N = 20 mutants judged within M = 30 minutes (after the scratch
build); --all takes every mutant (hours on two cores). Writes OUT_DIR/mutation.json in the
verification schema (docs/traceability.md): the score, one row per mutant, every survivor with
its judgement. The report shows it; the main job runs a time-boxed sample (it is an optional
program of traceability/config.yaml: absent, the report says "not run").
"""
import argparse
import datetime
import fnmatch
import hashlib
import json
import os
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


def sample_of(muts, n, seed):
    """n mutants chosen by seed, stable under edits elsewhere: each mutant is ranked by a hash
    of the seed, its survivor key and which repeat of that key in its file it is (not its id,
    which shifts whenever a target file changes), so a change to one line moves only that
    line's mutants in or out of the sample; the rest keep their ranks and judgements."""
    seen, ranked = {}, []
    for m in muts:
        key = survivor_key(m)
        nth = seen.get(key, 0)
        seen[key] = nth + 1
        text = "\x1f".join((str(seed), *key, str(nth)))
        ranked.append((hashlib.sha256(text.encode("utf-8")).hexdigest(), m["id"], m))
    return [m for _, _, m in sorted(ranked, key=lambda r: r[:2])[:n]]


INCLUDE = re.compile(r'^\s*#\s*include\s+"(tamias2d/[^"]+)"', re.M)


def _tags_reached(root, relpath):
    """The labels of the file's \\srs tags and of every library header it includes, directly
    or not."""
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
    return found


def _users(root, relpath):
    """The library files that include relpath (for x.cpp: that include x.hpp, x.cpp aside)."""
    stem, ext = os.path.splitext(relpath)
    header = (stem + ".hpp") if ext == ".cpp" else relpath
    wanted = header[len("src/"):]
    out = []
    for dirpath, _, files in os.walk(os.path.join(root, "src", "tamias2d")):
        for f in sorted(files):
            if not f.endswith((".hpp", ".cpp")):
                continue
            rel = os.path.relpath(os.path.join(dirpath, f), root)
            if rel in (relpath, header):
                continue
            with open(os.path.join(root, rel), encoding="utf-8") as fh:
                if wanted in INCLUDE.findall(fh.read()):
                    out.append(rel)
    return sorted(out)


def labels_of(root, relpath):
    """The SRS labels of the file's \\srs tags and of every library header it includes,
    directly or not: the items whose formulas the file realises or calls. A file that reaches
    no tag (a store, a data layout, a solver's inner step) serves the code that uses it: it
    takes the labels of the library files that include it (or its header), nearest first."""
    found = _tags_reached(root, relpath)
    seen, frontier = {relpath}, [relpath]
    while not found and frontier:
        nxt = []
        for rel in frontier:
            for u in _users(root, rel):
                if u not in seen:
                    seen.add(u)
                    nxt.append(u)
        for u in nxt:
            found |= _tags_reached(root, u)
        frontier = nxt
    return sorted(found)


def run(cmd, cwd=None, timeout=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return None, "timeout"


IGNORED = (".git", "build*", "reports", "__pycache__")


def sync_tree(root, dest):
    """Makes dest hold root's files (IGNORED names left out) and nothing else. A file whose
    bytes already match is left alone, time included; any other is written anew, with the
    current time. So a file that a mutant once changed, restored since, keeps the time of its
    restoring, which is later than any object built from the mutant: a build never takes a
    mutant's object for the restored source's (keeping root's older times would), and a
    mutant left in place by an interrupted run differs from root and is rewritten."""
    def ignored(name):
        return any(fnmatch.fnmatch(name, pat) for pat in IGNORED)

    os.makedirs(dest, exist_ok=True)
    names = {n for n in os.listdir(root) if not ignored(n)}
    for n in os.listdir(dest):
        if n not in names:
            path = os.path.join(dest, n)
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            else:
                os.remove(path)
    for n in sorted(names):
        s, d = os.path.join(root, n), os.path.join(dest, n)
        if os.path.isdir(s) and not os.path.islink(s):
            if os.path.exists(d) and not os.path.isdir(d):
                os.remove(d)
            sync_tree(s, d)
            continue
        if os.path.isdir(d):
            shutil.rmtree(d)
        with open(s, "rb") as fh:
            data = fh.read()
        if os.path.isfile(d):
            with open(d, "rb") as fh:
                if fh.read() == data:
                    continue
        with open(d, "wb") as fh:
            fh.write(data)
        shutil.copymode(s, d)


def prepare_scratch(root, scratch, coverage=False, build_all=True):
    """A copy of the sources (no .git, builds or reports) and a built Release build (with
    coverage: instrumented by gcov, the command and examples built too, every target built).

    The library is built shared and the test executables do not relink when only it changed
    (LINK_DEPENDS_NO_SHARED): a mutant of a .cpp then recompiles one object and relinks one
    .so instead of every test executable. The copy is synchronised file by file (sync_tree),
    so a scratch that outlives a run rebuilds only what changed since, and never keeps an
    object built from a mutant. Without build_all, nothing is built here: the caller builds
    what it needs, and the digests returned are those of the objects already there."""
    src = os.path.join(scratch, "src")
    build = os.path.join(scratch, "build")
    sync_tree(root, src)
    # -O1: mutants compile faster; the tests judge behaviour, not speed. _GLIBCXX_ASSERTIONS:
    # an index past an array's end (std::vector, LargeArray) stops the test, so a loop bound
    # turned by one is noticed even where the stray element is never used.
    # With coverage the same build is instrumented (the counters change no arithmetic) and also
    # holds the command, whose tests reach the scene library: one build serves both analyses.
    rc, out = run(["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                   f"-DCMAKE_CXX_FLAGS_RELEASE={SCRATCH_FLAGS}", "-DBUILD_SHARED_LIBS=ON",
                   "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON", "-DTAMIAS_BUILD_TESTS=ON",
                   "-DTAMIAS_BUILD_VERIFICATION=OFF",
                   f"-DTAMIAS_BUILD_APPS={'ON' if coverage else 'OFF'}",
                   f"-DTAMIAS_COVERAGE={'ON' if coverage else 'OFF'}",
                   "-DTAMIAS_INSTALL=OFF"])
    if rc != 0:
        raise SystemExit("scratch configure failed:\n" + out[-3000:])
    # Every labelled test executable once, before any mutant: a mutant's time is then its own
    # rebuild and tests.
    rc, out = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    if rc != 0:
        raise SystemExit("ctest cannot list the scratch build's tests:\n" + out[-3000:])
    catalogue = json.loads(out).get("tests", [])
    targets = sorted({t["name"].split("@", 1)[0] for t in catalogue if "@" in t["name"]})
    if not build_all:
        return src, build, catalogue, object_digests(build)
    if coverage:
        targets = ["all"]
    rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
    if rc != 0:
        raise SystemExit("scratch build of the unmutated sources failed:\n" + out[-3000:])
    return src, build, catalogue, object_digests(build)


def measure_coverage(src, build, catalogue, out_json, out_html, provenance=None):
    """Runs every test of the unmutated scratch build once and writes gcovr's summary
    (out_json) and pages (out_html) of src/ and include/. Each Boost.Test executable runs once
    with all its cases (CTest has one entry per SRS label, so a case with four labels would run
    four times), two at a time; then the other CTest entries (the command, examples, scripts)
    but the compile-fail checks and the consumer builds. Returns the tests that failed: a test
    that fails only in this build is a finding too (and would lower the coverage silently)."""
    for dirpath, _, files in os.walk(build):
        for f in files:
            if f.endswith(".gcda"):
                os.remove(os.path.join(dirpath, f))
    binaries = {}
    for t in catalogue:
        if "@" in t["name"] and t.get("command"):
            props = {p["name"]: p["value"] for p in t.get("properties", [])}
            binaries[t["command"][0]] = props.get("WORKING_DIRECTORY") or build
    failed = []

    def one(item):
        path, cwd = item
        rc, _ = run([path, "--color_output=no"], cwd=cwd, timeout=1800)
        return path if rc != 0 else None

    import concurrent.futures
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        failed += [p for p in pool.map(one, sorted(binaries.items())) if p]
    rc, out = run(["ctest", "--test-dir", build, "-j2", "-LE", "compile_fail|consumer", "-E", "@"],
                  timeout=3600)
    if rc != 0:
        failed += [f"ctest: {n}" for n in failed_entries(out)] or ["ctest (other entries)"]
    # gcov 12 can print a function summary with a negative percentage for a function left by
    # an exception; gcovr 5.2 stops at such a line unless told to skip it (it then skips that
    # summary line only; line and branch counts are unaffected).
    os.makedirs(os.path.dirname(os.path.abspath(out_json)), exist_ok=True)
    os.makedirs(os.path.dirname(os.path.abspath(out_html)), exist_ok=True)
    rc, out = run(["gcovr", "-r", src, "--filter", os.path.join(src, "src") + "/",
                   "--filter", os.path.join(src, "include") + "/", "--gcov-ignore-parse-errors",
                   "--json-summary", os.path.abspath(out_json), "--html-details",
                   os.path.abspath(out_html), build], cwd=build)
    if rc != 0:
        failed.append("gcovr: " + out[-300:])
    elif provenance:
        # gcovr's summary, stamped with the build it measured (the report refuses another tree's).
        with open(out_json, encoding="utf-8") as fh:
            doc = json.load(fh)
        doc["provenance"] = provenance
        with open(out_json, "w", encoding="utf-8") as fh:
            json.dump(doc, fh, indent=1)
    return failed


def scratch_build(scratch, coverage):
    """What the scratch build is, for the provenance of its results."""
    rc, out = run(["c++", "--version"])
    return {"name": "mutation" + (" and coverage" if coverage else "") + " scratch build",
            "where": os.path.join(scratch, "build"),
            "compiler": out.splitlines()[0] if rc == 0 and out else "c++",
            "flags": SCRATCH_FLAGS + (" --coverage" if coverage else ""),
            "options": "CMAKE_BUILD_TYPE=Release BUILD_SHARED_LIBS=ON TAMIAS_BUILD_TESTS=ON "
                       f"TAMIAS_BUILD_APPS={'ON' if coverage else 'OFF'} "
                       f"TAMIAS_COVERAGE={'ON' if coverage else 'OFF'}"}


def object_digests(build, since_ns=None):
    """{object file: SHA-256} of the build's objects (those written at or after since_ns only,
    when given)."""
    out = {}
    for dirpath, _, files in os.walk(build):
        for f in files:
            if f.endswith(".o"):
                path = os.path.join(dirpath, f)
                if since_ns is not None and os.stat(path).st_mtime_ns < since_ns:
                    continue
                with open(path, "rb") as fh:
                    out[path] = hashlib.sha256(fh.read()).hexdigest()
    return out


def ctest_entries(catalogue, labels):
    """{test name: executable target} of the CTest entries (ctest --show-only=json-v1's
    "tests") carrying any of labels."""
    entries = {}
    for t in catalogue:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        tl = props.get("LABELS", [])
        if isinstance(tl, str):
            tl = [tl]
        if set(tl) & set(labels) and "@" in t["name"]:
            entries[t["name"]] = t["name"].split("@", 1)[0]
    return entries


def judge(m, src, build, entries, test_timeout, objects):
    """(verdict, log, build seconds, test seconds) of one mutant, run against entries
    ({CTest name: target}); the scratch source is restored afterwards. "not built": every
    object the mutant's build rewrote is bit for bit the unmutated one (objects: their
    digests), so the mutated line is not compiled here (a branch of #if this build does not
    take); no test can tell it apart and it is not counted."""
    if not entries:
        return "no tests", "", 0.0, 0.0
    path = os.path.join(src, m["file"])
    with open(path, encoding="utf-8") as fh:
        original = fh.read()
    lines = original.split("\n")
    assert lines[m["line"] - 1] == m["before"]
    lines[m["line"] - 1] = m["after"]
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("\n".join(lines))
        targets = sorted(set(entries.values()))
        t0 = time.monotonic()
        since = time.time_ns()
        rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
        t1 = time.monotonic()
        if rc != 0:
            return "stillborn", out[-600:], t1 - t0, 0.0
        rebuilt = object_digests(build, since)
        if all(objects.get(path) == digest for path, digest in rebuilt.items()):
            return "not built", f"{len(rebuilt)} objects rebuilt, each as unmutated", t1 - t0, 0.0
        regex = "^(" + "|".join(re.escape(n) for n in sorted(entries)) + ")$"
        rc, out = run(["ctest", "--test-dir", build, "-R", regex, "--stop-on-failure", "-j2",
                       "--timeout", str(test_timeout)], timeout=test_timeout * len(entries) + 60)
        t2 = time.monotonic()
        if rc is None or rc != 0:
            return "killed", out[-600:], t1 - t0, t2 - t1
        return "survived", "", t1 - t0, t2 - t1
    finally:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(original)


FAILED = re.compile(r"^\s*\d+ - (\S+) \(", re.M)


def failed_entries(log):
    """The CTest entries a ctest log lists as failed (killed by a time-out included)."""
    tail = log.split("The following tests FAILED:", 1)
    return sorted(set(FAILED.findall(tail[1]))) if len(tail) == 2 else []


def passes_unmutated(names, build, entries, baseline, test_timeout):
    """Whether every entry of names passes on the unmutated sources (the scratch restored),
    remembered in baseline: a kill by a test that fails anyway is no kill."""
    todo = [n for n in names if n not in baseline]
    if todo:
        targets = sorted({entries[n] for n in todo})
        rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
        if rc != 0:
            raise SystemExit("the unmutated scratch does not build:\n" + out[-3000:])
        regex = "^(" + "|".join(re.escape(n) for n in todo) + ")$"
        rc, out = run(["ctest", "--test-dir", build, "-R", regex, "-j2", "--timeout",
                       str(test_timeout)], timeout=test_timeout * len(todo) + 60)
        bad = set(failed_entries(out)) if rc not in (None, 0) else set()
        if rc is None:
            bad = set(todo)
        for n in todo:
            baseline[n] = n not in bad
    return all(baseline[n] for n in names)


SURVIVORS = os.path.join(HERE, "survivors.json")
WINDOW = 8


def survivor_key(m):
    """A survivor's key: file, the mutated line's text (stripped) and operator, not the id
    (ids shift whenever a target file changes; the line's text and place in its file rarely
    do together)."""
    return (m["file"], m["before"].strip(), m["op"])


def load_judgements(path=SURVIVORS):
    """{key: judgement} from survivors.json: a list of {file, line, op, verdict, reason}, the
    verdict "equivalent" (reason: why no input the code receives tells the mutant apart) or
    "gap" (reason: what the tests lack). A malformed entry is an error, not ignored."""
    if not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as fh:
        doc = json.load(fh)
    out = {}
    for i, j in enumerate(doc.get("survivors", [])):
        for field in ("file", "line", "op", "verdict", "reason"):
            if not isinstance(j.get(field), str) or not j[field].strip():
                raise SystemExit(f"{path}: survivors[{i}].{field} must be a non-empty string")
        if j["verdict"] not in ("equivalent", "gap"):
            raise SystemExit(f"{path}: survivors[{i}].verdict must be \"equivalent\" or "
                             f"\"gap\", not {j['verdict']!r}")
        key = (j["file"], j["line"].strip(), j["op"])
        if key in out:
            raise SystemExit(f"{path}: survivors[{i}] repeats {key}")
        out[key] = j
    return out


def score_of(results, judgements):
    """(score, killed, equivalent, counted): killed / (killed + survivors not judged
    equivalent). A survivor judged "gap" or not judged at all counts against the score;
    stillborn mutants and those without a labelled test are not in it."""
    killed = sum(r["verdict"] == "killed" for r in results)
    survived = [r for r in results if r["verdict"] == "survived"]
    equivalent = sum(judgements.get(survivor_key(r), {}).get("verdict") == "equivalent"
                     for r in survived)
    counted = killed + len(survived) - equivalent
    return (killed / counted if counted else 0.0), killed, equivalent, counted


def commit_of(root):
    rc, out = run(["git", "-C", root, "rev-parse", "HEAD"])
    rc2, st = run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"])
    return (out.strip() if rc == 0 else "unknown"), bool(st.strip()) if rc2 == 0 else False


def tree_of(root):
    """The tree key of traceability/builds.py: the commit and its uncommitted changes."""
    sys.path.insert(0, ROOT)
    from traceability.builds import tree_key
    return tree_key(root)


def default_scratch(root):
    """One scratch per checkout (two checkouts syncing one scratch would build each other's
    trees): /tmp/tamias-mutation-<uid>-<hash of the checkout's path>. The module reach
    (verification/model_reach/) uses the same one."""
    where = hashlib.sha1(os.path.abspath(root).encode()).hexdigest()[:8]
    return os.path.join("/tmp", f"tamias-mutation-{os.getuid()}-{where}")


# The scratch build's flags (prepare_scratch), for the report's list of builds.
SCRATCH_FLAGS = "-O1 -DNDEBUG -D_GLIBCXX_ASSERTIONS"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir")
    ap.add_argument("--sample", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--minutes", type=float, default=30.0)
    ap.add_argument("--all", action="store_true", help="every mutant, no time box")
    # One scratch per checkout: two checkouts syncing one scratch would build each other's trees.
    ap.add_argument("--scratch", default=None,
                    help="scratch copy and build (default /tmp/tamias-mutation-<uid>-<hash of "
                         "the checkout's path>)")
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--test-timeout", type=int, default=300)
    ap.add_argument("--list", action="store_true", help="print the mutants and stop")
    ap.add_argument("--survivors", default=SURVIVORS, help="the judged survivors (JSON)")
    ap.add_argument("--ids", help="judge these mutants (ids of --list, comma-separated) only")
    ap.add_argument("--coverage", nargs=2, metavar=("JSON", "HTML"),
                    help="instrument the scratch build, run every test once on the unmutated "
                         "sources and write gcovr's summary and pages before the mutants")
    a = ap.parse_args(argv)
    if a.scratch is None:
        a.scratch = default_scratch(a.root)

    muts = all_mutants(a.root)
    if a.list:
        try:
            for m in muts:
                print(f"{m['id']:5d} {m['file']}:{m['line']} {m['op']}")
            print(f"{len(muts)} mutants")
        except BrokenPipeError:  # piped into head
            pass
        return 0
    load_judgements(a.survivors)  # a malformed record stops the run before any build
    if a.ids:
        by_id = {m["id"]: m for m in muts}
        chosen = [by_id[int(x)] for x in a.ids.split(",") if x.strip()]
    else:
        chosen = muts if a.all else sample_of(muts, a.sample, a.seed)
    # Within each run of WINDOW sampled mutants, those of one file one after another: restoring
    # the file and building its next mutant are then one rebuild, not two, while a time box
    # still cuts the sample at a window's end, not after a few whole files.
    chosen = [m for k in range(0, len(chosen), WINDOW)
              for m in sorted(chosen[k:k + WINDOW], key=lambda m: (m["file"], m["line"], m["id"]))]
    commit, dirty = commit_of(a.root)
    tree = tree_of(a.root)
    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    t_prep = time.monotonic()
    src, build, catalogue, objects = prepare_scratch(a.root, a.scratch, bool(a.coverage))
    prep_secs = time.monotonic() - t_prep
    coverage_failed = []
    if a.coverage:
        t_cov = time.monotonic()
        now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
        coverage_failed = measure_coverage(
            src, build, catalogue, *a.coverage,
            provenance={"commit": commit, "dirty": dirty, "tree": tree, "build_id": None,
                        "built": started, "generated": now,
                        "build": scratch_build(a.scratch, True)})
        print(f"coverage: every test once in {time.monotonic() - t_cov:.0f} s"
              + (f"; FAILED: {', '.join(coverage_failed)}" if coverage_failed else ""),
              flush=True)
        if not a.all and not a.ids and a.minutes <= 0:
            return 3 if coverage_failed else 0
    # The box is for judging mutants; the scratch build before it is reported apart (minutes
    # when the scratch is new, seconds when it outlives a run).
    deadline = None if a.all else time.monotonic() + 60.0 * a.minutes
    results = []
    baseline = {}  # CTest entry -> passes on the unmutated sources (asked when it kills)
    for m in chosen:
        if deadline is not None and time.monotonic() > deadline:
            break
        labels = labels_of(a.root, m["file"])
        entries = ctest_entries(catalogue, labels)
        t0 = time.monotonic()
        entries = {n: t for n, t in entries.items() if baseline.get(n, True)}
        verdict, log, b_secs, t_secs = judge(m, src, build, entries, a.test_timeout, objects)
        if verdict == "killed" and not passes_unmutated(failed_entries(log), build, entries,
                                                        baseline, a.test_timeout):
            # Killed by a test that fails without the mutant too: judged again without it.
            broken = sorted(n for n in entries if baseline.get(n) is False)
            print(f"   (fails unmutated, left out from now on: {', '.join(broken)})")
            entries = {n: t for n, t in entries.items() if baseline.get(n, True)}
            verdict, log, b_secs, t_secs = judge(m, src, build, entries, a.test_timeout, objects)
        secs = time.monotonic() - t0
        r = dict(m, verdict=verdict, labels=labels, tests=sorted(entries), seconds=round(secs, 1),
                 build_seconds=round(b_secs, 1), test_seconds=round(t_secs, 1),
                 log=log if verdict in ("survived", "stillborn", "not built") else "")
        results.append(r)
        print(f"{verdict:10s} #{m['id']} {m['file']}:{m['line']} {m['op']} ({secs:.0f} s: "
              f"build {b_secs:.0f}, tests {t_secs:.0f})", flush=True)
    # The record as it stands when the run ends (survivors may be judged while it runs).
    judgements = load_judgements(a.survivors)
    for r in results:
        if r["verdict"] == "survived":
            j = judgements.get(survivor_key(r))
            r["judged"] = j["verdict"] if j else "not yet judged"
            r["reason"] = j["reason"] if j else ""
    score, killed, equivalent, counted = score_of(results, judgements)
    survived = [r for r in results if r["verdict"] == "survived"]
    gaps = [r for r in survived if r["judged"] == "gap"]
    unjudged = [r for r in survived if r["judged"] == "not yet judged"]
    judged_runs = [r for r in results
                   if r["verdict"] in ("killed", "survived", "stillborn", "not built")]
    mean = (sum(r["seconds"] for r in judged_runs) / len(judged_runs)) if judged_runs else 0.0
    finished = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    details = (f"{killed} of {counted} non-equivalent compiled mutants killed "
               f"({100 * score:.0f} %); {len(survived)} survived ({equivalent} judged equivalent, "
               f"{len(gaps)} judged gaps, {len(unjudged)} not yet judged), "
               f"{sum(r['verdict'] == 'stillborn' for r in results)} did not compile, "
               f"{sum(r['verdict'] == 'not built' for r in results)} compiled to unchanged "
               f"objects, "
               f"{sum(r['verdict'] == 'no tests' for r in results)} had no labelled test; "
               f"{len(results)} of {len(chosen)} chosen from {len(muts)} "
               f"({'all' if a.all else f'ids {a.ids}' if a.ids else f'seed {a.seed}, sample {a.sample}, {a.minutes:g} min box'}); "
               f"{mean:.0f} s per built mutant, scratch build {prep_secs:.0f} s")
    broken = sorted(n for n, ok in baseline.items() if not ok)
    if broken:
        details += (f"; {len(broken)} CTest entries fail without any mutant and were left out: "
                    + ", ".join(broken))
    doc = {
        "program": "mutation",
        "description": "Mutation testing of src/tamias2d/model/ and dynamics/: mutants (operator "
                       "swaps, constants, comparisons, removed assignments) built in a scratch "
                       "copy, judged by the CTest entries labelled with the SRS items the mutated "
                       "file's \\srs tags, or those of the library headers it includes, name (a "
                       "file that reaches no tag: those of the files that include it). Score: "
                       "killed / (killed + survivors not judged equivalent in "
                       "verification/mutation/survivors.json). This run: " + details + ".",
        "provenance": {"commit": commit, "dirty": dirty, "tree": tree, "build_id": None,
                       "built": started, "generated": finished,
                       "build": scratch_build(a.scratch, bool(a.coverage))},
        "checks": [{"name": "at least 90 % of the non-equivalent mutants killed",
                    "labels": [], "passed": bool(counted) and score >= 0.9 - 1e-12,
                    "target": ">= 90 % killed",
                    "oracle": "the SRS-labelled tests fail on each mutant; survivors judged "
                              "equivalent are argued in verification/mutation/survivors.json",
                    "details": details}],
        "tables": [{"name": "Mutants", "columns": ["id", "where", "mutation", "labels (tests run)",
                                                   "verdict", "seconds (build + tests)"],
                    "rows": [[r["id"], f"{r['file']}:{r['line']}", r["op"],
                              ", ".join(r["labels"]), r["verdict"],
                              f"{r['seconds']:.0f} ({r['build_seconds']:.0f} + "
                              f"{r['test_seconds']:.0f})"] for r in results]},
                   {"name": "Survivors",
                    "columns": ["id", "where", "mutation", "before", "after", "judged", "reason"],
                    "rows": [[r["id"], f"{r['file']}:{r['line']}", r["op"], r["before"].strip(),
                              r["after"].strip() or "(removed)", r["judged"], r["reason"]]
                             for r in survived]}],
        "series": [],
        "score": score,
        "summary": details,
        "seconds_per_mutant": round(mean, 1),
        "failing_unmutated": broken,
        "scratch_build_seconds": round(prep_secs, 1),
        "mutants": results,
    }
    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "mutation.json"), "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    print("mutation: " + details)
    return 3 if coverage_failed else 0


if __name__ == "__main__":
    sys.exit(main())
