#!/usr/bin/python3
"""Mutation testing of the model layer and the dynamics: do the tests notice when the code that
realises an item is wrong?

Each mutant changes one spot of src/tamias2d/model/ or src/tamias2d/dynamics/: an arithmetic
operator swapped (+ -, * /), a comparison turned (< <=, > >=, == !=), a numeric constant
changed (c -> 2c, 0 -> 1), or an assignment statement removed. The mutant is built in a
scratch copy of the repository with its own build directory (never the caller's) and judged
by the CTest entries labelled with the SRS items that the mutated file, or a library header it
includes, names in its \\srs tags (a file that reaches no tag: those of the files that include
it) and by the cases without a label or with a category label (traceability/config.yaml) in
the same test executables, by the golden state hashes of tests/determinism and by the snapshot
suite of tests/snapshot. A mutant is killed when they
fail (or time out); one that passes is judged again in an ASan and UBSan build of the same copy,
where a sanitizer report kills it; it survives when it passes there too. A mutant is stillborn
when it does not compile, not built when its objects come out bit for bit as the unmutated ones
(a line of a #if branch this build skips): neither is counted in the score.
The sample is ranked by a seeded hash of each mutant's file, line text, operator and
occurrence, so an edit elsewhere leaves it, and the judgements of its survivors, in place. A
survivor is judged in survivors.json ("equivalent", argued, or "gap"), one record per mutant;
score = killed / (killed + survivors not judged equivalent), with its Wilson 95 % interval: the
90 % floor applies to the interval's lower bound for a sample, to the score for every mutant.

    /usr/bin/python3 verification/mutation/mutate.py OUT_DIR [--sample N] [--seed S]
        [--minutes M] [--all] [--ids I,J,...] [--shard I/N] [--resume] [--scratch DIR]
        [--resume-from FILE...] [--list] [--coverage JSON HTML]
    /usr/bin/python3 verification/mutation/mutate.py --merge OUT_DIR SHARD_FILE...

With --coverage the scratch build is instrumented with gcov and, before any mutant, every test
runs once on the unmutated sources: gcovr's summary and pages of src/ and include/ are the
report's coverage (one build for both analyses). Exit status 3 when a test fails there.

By default a seeded sample of N = 20 mutants judged within M = 30 minutes (after the scratch
build); --all takes every mutant (hours on two cores) in the seed's rank order, so that a run
stopped early has judged a seeded sample, --ids the given ones (no box). The result is written
after each mutant. With
--shard I/N only the I-th of N disjoint shards of those (a hash of each mutant's key) is judged
and written to OUT_DIR/mutation-shard-I-of-N.json; --merge joins shards of one tree into
OUT_DIR/mutation.json. Each verdict is also appended to a journal beside that file as it is
reached; --resume keeps a journal's verdicts (of the same tree, selection and shard) and
judges only the rest; --resume-from FILE... keeps those of results files of the same tree and
selection (a partial reference, from any machine) likewise. Writes OUT_DIR/mutation.json in the
verification schema (docs/traceability.md): the score and its interval, one row per mutant,
every survivor with its judgement. The report shows it; the main job runs a time-boxed sample
(it is an optional program of traceability/config.yaml: absent, the report says "not run").
"""
import argparse
import datetime
import fcntl
import fnmatch
import hashlib
import json
import math
import os
import re
import shutil
import socket
import stat
import subprocess
import sys
import tempfile
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
    """Every mutant of one file: dicts {file, line, op, before, after, occurrence}; occurrence
    counts the mutants of the same line text and operator in the file, 1 for the first (in
    line order, then left to right), so that file, line text, operator and occurrence name one
    mutant."""
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
    seen = {}
    for m in out:
        key = line_key(m)
        seen[key] = seen.get(key, 0) + 1
        m["occurrence"] = seen[key]
    return out


def all_mutants(root):
    muts = []
    for d in TARGET_DIRS:
        # The whole tree under each target: dynamics/ keeps its joints and contacts in folders.
        rels = []
        for here, _dirs, files in os.walk(os.path.join(root, d)):
            sub = os.path.relpath(here, root)
            rels += [f"{sub}/{f}" for f in files if f.endswith((".hpp", ".cpp"))]
        for rel in sorted(rels):
            with open(os.path.join(root, rel), encoding="utf-8") as fh:
                muts += mutants_of(rel, fh.read())
    for i, m in enumerate(muts):
        m["id"] = i
    return muts


def sample_of(muts, n, seed):
    """n mutants chosen by seed, stable under edits elsewhere: each mutant is ranked by a hash
    of the seed, its file, line text and operator and which repeat of those in its file it is
    (its occurrence less one; not its id, which shifts whenever a target file changes), so a
    change to one line moves only that line's mutants in or out of the sample; the rest keep
    their ranks and judgements."""
    seen, ranked = {}, []
    for m in muts:
        key = line_key(m)
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


def run(cmd, cwd=None, timeout=None, env=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout,
                           env=None if env is None else {**os.environ, **env})
        return p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        return None, "timeout"


# Left out of the copy: the checkout's own builds and reports at its top (a source file may be
# named build_*, e.g. include/tamias2d/build_info.hpp) and, at any depth, git's and Python's.
IGNORED_AT_TOP = (".git", "build*", "reports")
IGNORED = (".git", "__pycache__")


def sync_tree(root, dest, top=True):
    """Makes dest hold root's files (IGNORED names left out, IGNORED_AT_TOP at the top) and
    nothing else. A file whose
    bytes already match is left alone, time included; any other is written anew, with the
    current time. So a file that a mutant once changed, restored since, keeps the time of its
    restoring, which is later than any object built from the mutant: a build never takes a
    mutant's object for the restored source's (keeping root's older times would), and a
    mutant left in place by an interrupted run differs from root and is rewritten."""
    def ignored(name):
        return any(fnmatch.fnmatch(name, pat) for pat in (IGNORED_AT_TOP if top else IGNORED))

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
            sync_tree(s, d, top=False)
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
    # File by file (no unity batches): a mutant recompiles its own file only, and its object
    # is compared with the unmutated one's.
    rc, out = run(["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                   f"-DCMAKE_CXX_FLAGS_RELEASE={SCRATCH_FLAGS}", "-DBUILD_SHARED_LIBS=ON",
                   "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON", "-DTAMIAS_BUILD_TESTS=ON",
                   "-DTAMIAS_BUILD_VERIFICATION=OFF",
                   f"-DTAMIAS_BUILD_APPS={'ON' if coverage else 'OFF'}",
                   f"-DTAMIAS_COVERAGE={'ON' if coverage else 'OFF'}",
                   "-DTAMIAS_INSTALL=OFF", "-DTAMIAS_UNITY_BUILD=OFF"])
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
    # Listed again now that the executables exist: ctest names an entry's command only then.
    rc, out = run(["ctest", "--test-dir", build, "--show-only=json-v1"])
    if rc != 0:
        raise SystemExit("ctest cannot list the scratch build's tests:\n" + out[-3000:])
    catalogue = json.loads(out).get("tests", [])
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


# The second judge's build: the scratch build's flags with ASan and UBSan (TAMIAS_SANITIZE:
# -fsanitize=address,undefined -fno-sanitize-recover=all, the sanitizers scripts/test.sh
# --sanitize builds with, by the scratch's compiler, GCC), a report fatal. A mutant that reads or writes out of bounds, overflows a signed integer
# or leaks, and passes the tests in the scratch build (a stray read can return a harmless value,
# a stray write land on a field that is overwritten anyway), is killed there.
SANITIZER_OPTIONS = ["-DTAMIAS_SANITIZE=ON", "-DTAMIAS_WIDE_X86_64_V4=OFF"]
SANITIZER_ENV = {"ASAN_OPTIONS": "detect_leaks=1:abort_on_error=1",
                 "UBSAN_OPTIONS": "print_stacktrace=1:halt_on_error=1"}
SANITIZER_REPORT = re.compile(r"(?:ERROR|SUMMARY): (?:Address|Leak|UndefinedBehavior)"
                              r"Sanitizer[^\n]*|[^\n]*runtime error:[^\n]*")


class SanitizerScratch:
    """The ASan and UBSan build of the scratch's sources (<scratch>/build-asan), configured and
    built lazily: nothing until a survivor needs it, then only the test executables that
    survivor's entries need (from the unmutated sources, as the scratch build). It shares the
    scratch's source copy, so a mutant written there is built in both."""

    def __init__(self, scratch, src):
        self.src, self.build = src, os.path.join(scratch, "build-asan")
        self.configured, self.built, self.baseline, self.commands = False, set(), {}, {}
        self.unmutated = None
        self.seconds = 0.0  # spent configuring and building it unmutated

    def ensure(self, targets):
        """Configures the build and builds targets from the unmutated sources, once each."""
        t0 = time.monotonic()
        try:
            if not self.configured:
                rc, out = run(["cmake", "-S", self.src, "-B", self.build, "-G", "Ninja",
                               "-DCMAKE_BUILD_TYPE=Release",
                               f"-DCMAKE_CXX_FLAGS_RELEASE={SCRATCH_FLAGS}",
                               "-DBUILD_SHARED_LIBS=ON", "-DCMAKE_LINK_DEPENDS_NO_SHARED=ON",
                               "-DTAMIAS_BUILD_TESTS=ON", "-DTAMIAS_BUILD_VERIFICATION=OFF",
                               "-DTAMIAS_BUILD_APPS=OFF", "-DTAMIAS_COVERAGE=OFF",
                               "-DTAMIAS_INSTALL=OFF", "-DTAMIAS_UNITY_BUILD=OFF",
                               *SANITIZER_OPTIONS])
                if rc != 0:
                    raise SystemExit("sanitizer scratch configure failed:\n" + out[-3000:])
                self.configured = True
            todo = sorted(set(targets) - self.built)
            if todo:
                rc, out = run(["nice", "-n", "5", "cmake", "--build", self.build, "-j2",
                               "--target", *todo])
                if rc != 0:
                    raise SystemExit("sanitizer scratch build of the unmutated sources failed:\n"
                                     + out[-3000:])
                self.built |= set(todo)
                rc, out = run(["ctest", "--test-dir", self.build, "--show-only=json-v1"])
                if rc != 0:
                    raise SystemExit("ctest cannot list the sanitizer build's tests:\n"
                                     + out[-3000:])
                self.commands = commands_of(json.loads(out).get("tests", []))
                self.unmutated = Unmutated(self.build)
        finally:
            self.seconds += time.monotonic() - t0

    def judge(self, m, entries, test_timeout):
        """(killed, log, build seconds, test seconds, failed entries): whether the tests of
        entries fail on the mutant in this build (a sanitizer report, or a failure of an
        executable whose entries pass on the unmutated sources here), and the report's lines."""
        b = t = 0.0
        for _ in range(2):
            entries = {n: x for n, x in entries.items() if self.baseline.get(n, True)}
            self.ensure(set(entries.values()))
            verdict, log, b1, t1, failed = judge(m, self.src, self.build, entries, test_timeout,
                                                 env=SANITIZER_ENV, commands=self.commands,
                                                 unmutated=self.unmutated)
            b, t = b + b1, t + t1
            if verdict == "stillborn":
                raise SystemExit(f"mutant #{m['id']} compiles in the scratch build but not in "
                                 f"the sanitizer build:\n{log[-3000:]}")
            if verdict != "killed":
                return False, "", b, t, []
            if passes_unmutated(failed, self.build, entries, self.baseline, test_timeout,
                                env=SANITIZER_ENV, commands=self.commands):
                reports = [r.strip() for r in SANITIZER_REPORT.findall(log)]
                summary = "; ".join(dict.fromkeys(reports)) if reports else (
                    "failed in the sanitizer build only: " + ", ".join(failed))
                return True, summary[:600], b, t, failed
            # Killed by a test that fails here without the mutant too: judged again without it.
        return False, "", b, t, []

    def description(self):
        return {"name": "mutation scratch build with ASan and UBSan (the survivors' second judge)",
                "where": self.build, "flags": SCRATCH_FLAGS + " -fsanitize=address,undefined "
                "-fno-sanitize-recover=all -fno-omit-frame-pointer",
                "options": "CMAKE_BUILD_TYPE=Release BUILD_SHARED_LIBS=ON TAMIAS_BUILD_TESTS=ON "
                           "TAMIAS_SANITIZE=ON TAMIAS_WIDE_X86_64_V4=OFF",
                "environment": " ".join(f"{k}={v}" for k, v in SANITIZER_ENV.items()),
                "seconds": round(self.seconds, 1), "targets": sorted(self.built)}


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


def is_output(name, mode):
    """Whether a file of a build directory is a build output a mutant's build can rewrite: an
    object, its coverage notes, a library, an executable, a precompiled header."""
    return (name.endswith((".o", ".gcno", ".gch", ".a")) or ".so" in name
            or bool(mode & 0o111))


class Unmutated:
    """The bytes of a built scratch's outputs as the unmutated sources build them (precompiled
    headers aside: large, and no target file reaches them). After a mutant, restore() puts back
    every output its build rewrote, each keeping the time that build gave it, and the source
    then gets its own time back: to ninja the build is as the unmutated sources left it, so the
    next mutant's build compiles only that mutant, not the restored file too (for a header,
    every file that includes it, twice). Ninja keeps deciding what is out of date as always:
    an output is rebuilt when an input is newer than it (or than the time its log records)."""

    def __init__(self, build):
        self.build, self.files = build, {}
        for dirpath, _, files in os.walk(build):
            for f in files:
                path = os.path.join(dirpath, f)
                st = os.lstat(path)
                if stat.S_ISREG(st.st_mode) and is_output(f, st.st_mode) \
                        and not f.endswith(".gch"):
                    with open(path, "rb") as fh:
                        self.files[path] = fh.read()

    def written_since(self, since_ns):
        out = []
        for dirpath, _, files in os.walk(self.build):
            for f in files:
                path = os.path.join(dirpath, f)
                st = os.lstat(path)
                if stat.S_ISREG(st.st_mode) and st.st_mtime_ns >= since_ns \
                        and is_output(f, st.st_mode):
                    out.append(path)
        return out

    def restore(self, since_ns):
        """Puts back the unmutated bytes of every output written at or after since_ns, each
        with its current time; False, with nothing done, when one of them is not held (the
        source must then keep a new time, so that the next build rebuilds from it)."""
        written = self.written_since(since_ns)
        if any(path not in self.files for path in written):
            return False
        for path in written:
            st = os.stat(path)
            with open(path, "r+b") as fh:
                fh.write(self.files[path])
                fh.truncate()
            os.utime(path, ns=(st.st_atime_ns, st.st_mtime_ns))
        return True


SCRATCH_LOCK = ".lock"


def lock_scratch(scratch):
    """An exclusive lock on the scratch (an open file; released when it is closed or the
    process ends). One run per scratch, of this script or of module_reach.py, which shares
    it: two runs in one copy would build each other's mutants and overwrite each other's
    sources."""
    os.makedirs(scratch, exist_ok=True)
    fh = open(os.path.join(scratch, SCRATCH_LOCK), "w")
    try:
        fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        fh.close()
        raise SystemExit(f"the scratch {scratch} is in use by another mutation or module reach "
                         "run: pass --scratch DIR")
    return fh


UNLABELLED = ".unlabelled"  # the CTest entry of an executable's cases without a label


def ctest_entries(catalogue, labels, targets=(), categories=()):
    """{test name: executable target} of the CTest entries (ctest --show-only=json-v1's
    "tests") carrying any of labels, every labelled entry of the executables targets, and, of
    every executable so chosen, the unlabelled entry (`<target>.unlabelled`: its cases that
    carry no label) and the entries of category labels (categories: traceability/config.yaml's
    category_labels, such as internals or reliability). A case without an SRS label (the
    sleeping, the API's guarantees, the packs against their plain form) is a test with an
    oracle all the same, and one that kills a mutant kills it."""
    entries = {}
    unlabelled = set()
    by_category = []
    for t in catalogue:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        tl = props.get("LABELS", [])
        if isinstance(tl, str):
            tl = [tl]
        if t["name"].endswith(UNLABELLED):
            unlabelled.add(t["name"])
        if "@" not in t["name"]:
            continue
        target = t["name"].split("@", 1)[0]
        if set(tl) & set(labels) or target in targets:
            entries[t["name"]] = target
        elif tl and set(tl) <= set(categories):
            by_category.append((t["name"], target))
    chosen = set(entries.values())
    for name, target in by_category:
        if target in chosen:
            entries[name] = target
    for target in chosen:
        if target + UNLABELLED in unlabelled:
            entries[target + UNLABELLED] = target
    return entries


def category_labels(root):
    """The test labels that are categories, not SRS items: traceability/config.yaml's, read
    by the harness's own loader (none in a tree without that file)."""
    sys.path.insert(0, ROOT)
    from traceability.analysis import load_config
    path = os.path.join(root, "traceability", "config.yaml")
    return tuple(load_config(path)["category_labels"] or ())


# The golden state hashes of the example scenes (tests/determinism): a project rule, not an SRS
# item, so their entries carry the category label "determinism", not an item's. Every mutant
# of the model and the dynamics is judged by them too: a change in any step's arithmetic shows
# in a hash, also where no labelled test looks (a joint's generation, an unread default that
# the hash reads). So is it by the snapshot suite (tests/snapshot, the category labels
# determinism, reliability and scene): each store of the dynamics writes and reads its part of
# a snapshot, and that suite's oracles (a restored world continues with the same bits and
# writes the same bytes; a forged snapshot is refused, naming its field) are the only tests of
# that code.
GOLDEN_TARGETS = ("determinism_tests", "snapshot_tests")
# The suites of the World API's own guarantees: its events, its recording and replay, its
# behaviour out of memory, its definitions' checks, its embedding (allocator and error hooks)
# and its contact hooks. Their cases carry category labels, or SRS labels that a file's own
# labels need not share (an event's DD11 for the events' bookkeeping), yet each drives the
# dynamics through the API against its own oracle, and each kills mutants there that the
# labelled tests miss (the step events' flags, the snapshot writer's growth, a pair kept over a
# failed allocation, a joint's creation). They cost a few seconds per mutant.
API_TARGETS = ("events_tests", "recording_tests", "reliability_oom_tests", "definition_tests",
               "embedding_tests", "contact_hooks_tests")


def entries_of(catalogue, labels, relpath, categories=()):
    """The CTest entries that judge a mutant of relpath: those of its labels, and the golden
    hashes, the snapshot suite and the API suites for a file of the model or the dynamics (with
    the category entries of their executables, ctest_entries)."""
    whole = relpath.startswith(tuple(d + "/" for d in TARGET_DIRS))
    return ctest_entries(catalogue, labels, GOLDEN_TARGETS + API_TARGETS if whole else (),
                         categories)


def judge(m, src, build, entries, test_timeout, objects=None, env=None, commands=None,
          unmutated=None):
    """(verdict, log, build seconds, test seconds, failed entries) of one mutant, run against
    entries ({CTest name: target}) in build (commands: {CTest name: (executable, directory)},
    see run_tests; env: the tests' variables); the scratch source is restored afterwards, and
    with unmutated (an Unmutated of build) the outputs too, so that the source keeps its time.
    "not built" (only when objects, the unmutated objects' digests, are given): every object
    the mutant's build rewrote is bit for bit the unmutated one, so the mutated line is not
    compiled here (a branch of #if this build does not take); no test can tell it apart and it
    is not counted."""
    if not entries:
        return "no tests", "", 0.0, 0.0, []
    path = os.path.join(src, m["file"])
    with open(path, encoding="utf-8") as fh:
        original = fh.read()
    times = os.stat(path)
    lines = original.split("\n")
    assert lines[m["line"] - 1] == m["before"]
    lines[m["line"] - 1] = m["after"]
    since = None
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write("\n".join(lines))
        targets = sorted(set(entries.values()))
        t0 = time.monotonic()
        since = time.time_ns()
        rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
        t1 = time.monotonic()
        if rc != 0:
            return "stillborn", out[-600:], t1 - t0, 0.0, []
        if objects is not None:
            rebuilt = object_digests(build, since)
            if all(objects.get(path) == digest for path, digest in rebuilt.items()):
                return ("not built", f"{len(rebuilt)} objects rebuilt, each as unmutated",
                        t1 - t0, 0.0, [])
        failed, out = run_tests(entries, commands, test_timeout, env=env,
                                key=(m["file"], env is not None))
        t2 = time.monotonic()
        if failed:
            return "killed", out, t1 - t0, t2 - t1, failed
        return "survived", "", t1 - t0, t2 - t1, []
    finally:
        # The source first, with a new time: whatever happens next, the build then rebuilds
        # from it. Its own time back only once every output it reached is unmutated again.
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(original)
        if unmutated is not None and since is not None and unmutated.restore(since):
            os.utime(path, ns=(times.st_atime_ns, times.st_mtime_ns))


def commands_of(catalogue):
    """{CTest name: (executable, working directory, own run)} of the catalogue's labelled and
    unlabelled entries whose executable exists (ctest --show-only names a command only then).
    The own run is the unlabelled entry's (arguments: its filter of the cases that carry no
    label; skip: the pattern of its output that CTest reads as skipped, such as Boost.Test's
    "no test cases matching filter" when every case has a label), None for a labelled entry
    (run_tests filters by its label)."""
    out = {}
    for t in catalogue:
        unlabelled = t["name"].endswith(UNLABELLED)
        if ("@" not in t["name"] and not unlabelled) or not t.get("command"):
            continue
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        own = None
        if unlabelled:
            skip = props.get("SKIP_REGULAR_EXPRESSION") or []
            own = {"args": list(t["command"][1:]),
                   "skip": [skip] if isinstance(skip, str) else list(skip)}
        out[t["name"]] = (t["command"][0], props.get("WORKING_DIRECTORY"), own)
    return out


# Seconds each test executable took at its last run with its entries' labels (per label; to its
# first failure when it failed), and how often it ran on a mutant of each file and how often it
# killed it there: the run order below.
_COSTS = {}
_KILLS = {}  # (key, executable target) -> [kills, runs to the end or to a failure]

# Boost.Test's report of a failed check or of an uncaught exception or signal, as it is logged
# (at its default log level, each line flushed as the check fails): the executable will exit
# with a failure whatever its other cases do.
FIRST_FAILURE = re.compile(rb'(?:^|\n)[^\n]*: (?:fatal )?error: in "')


def _order(units, key):
    """The executables of units in their run order: the most kills per second on mutants of key
    (the mutated file and which build) first, from the runs so far (the Laplace estimate of the
    kill rate, (k + 1) / (n + 2), over the executable's last time), so a mutant that some test
    kills is most often killed by the first executable that runs; the longest first among
    equals, so a survivor's two-at-a-time run ends soonest."""
    def rank(kv):
        target, u = kv
        cost = _COSTS.get(target, 1.0) * max(1, len(u["labels"]))
        k, n = _KILLS.get((key, target), (0, 0))
        return (-(k + 1) / (n + 2) / max(cost, 0.05), -cost, target)
    return sorted(units.items(), key=rank)


def run_tests(entries, commands, test_timeout, env=None, jobs=2, key=None):
    """Runs the tests of entries ({CTest name: target}) and returns (failed, log): the entries
    of the executables that failed or ran past test_timeout (none when all pass) and their
    output. Each executable runs once, with the union of its entries' labels
    (--run_test=@A:@B), not once per entry as CTest would: a case that carries several of the
    labels runs once. Two run at a time, in the order of _order (key: the mutated file and the
    build). An executable is stopped as soon as it logs a failed check (it has failed: its exit
    status could only say so later), and at the first failure the others are stopped."""
    units = {}
    for n, target in sorted(entries.items()):
        exe, cwd, *rest = commands[n]
        own = rest[0] if rest else None
        if own is not None:  # an unlabelled entry: a run of its own, with its own filter
            units[n] = {"exe": exe, "cwd": cwd, "labels": [], "names": [n], **own}
            continue
        u = units.setdefault(target, {"exe": exe, "cwd": cwd, "labels": [], "names": []})
        u["labels"].append(n.split("@", 1)[1])
        u["names"].append(n)
    todo = _order(units, key)
    full_env = None if env is None else {**os.environ, **env}
    running, failed, log = [], [], []
    try:
        while todo or running:
            while todo and len(running) < jobs and not failed:
                target, u = todo.pop(0)
                # Bytes: it is read while being written, perhaps within a character.
                out = tempfile.TemporaryFile(mode="w+b")
                args = u.get("args") or ["--run_test=" + ":".join("@" + x for x in u["labels"]),
                                         "--color_output=no"]
                p = subprocess.Popen([u["exe"], *args], cwd=u["cwd"] or None, stdout=out,
                                     stderr=subprocess.STDOUT, env=full_env)
                running.append([p, target, u, out, time.monotonic(), 0, b""])
            if failed:
                break
            time.sleep(0.02)
            for item in list(running):
                p, target, u, out, t0, seen, tail = item
                rc = p.poll()
                late = rc is None and time.monotonic() - t0 > test_timeout
                early = False
                if rc is None and not late:
                    out.seek(seen)
                    new = out.read()
                    item[5] = out.tell()
                    early = FIRST_FAILURE.search(tail + new) is not None
                    item[6] = (tail + new)[-400:]
                    if not early:
                        continue
                running.remove(item)
                if late or early:
                    p.kill()
                    p.wait()
                if not late:  # to its end or to its first failure: what a kill costs
                    _COSTS[target] = (time.monotonic() - t0) / max(1, len(u["labels"]))
                stats = _KILLS.setdefault((key, target), [0, 0])
                stats[1] += 1
                if rc not in (None, 0) and not early and u.get("skip"):
                    # Skipped as CTest would (no case matched the unlabelled entry's filter).
                    out.seek(0)
                    text = out.read().decode("utf-8", "replace")
                    if any(re.search(x, text) for x in u["skip"]):
                        rc = 0
                if late or early or rc != 0:
                    stats[0] += 1
                    failed += u["names"]
                    out.seek(0)
                    text = out.read().decode("utf-8", "replace")
                    log.append(f"{target} {' '.join('@' + x for x in u['labels'])}: "
                               + (f"time-out after {test_timeout} s" if late else
                                  "stopped at its first failed check" if early else
                                  f"exit status {rc}") + "\n" + text[-20000:])
                out.close()
    finally:
        for p, _, _, out, *_ in running:
            p.kill()
            p.wait()
            out.close()
    return sorted(failed), "\n".join(log)


FAILED = re.compile(r"^\s*\d+ - (\S+) \(", re.M)


def failed_entries(log):
    """The CTest entries a ctest log lists as failed (killed by a time-out included)."""
    tail = log.split("The following tests FAILED:", 1)
    return sorted(set(FAILED.findall(tail[1]))) if len(tail) == 2 else []


def passes_unmutated(names, build, entries, baseline, test_timeout, env=None, commands=None):
    """Whether every entry of names (those of the executables that failed on a mutant) passes
    on the unmutated sources (the scratch restored), remembered in baseline: a kill by a test
    that fails anyway is no kill. They run as on the mutant (run_tests); when they fail, each
    entry alone tells which."""
    todo = {n: entries[n] for n in names if n not in baseline}
    if todo:
        targets = sorted(set(todo.values()))
        rc, out = run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target", *targets])
        if rc != 0:
            raise SystemExit("the unmutated scratch does not build:\n" + out[-3000:])
        failed, _ = run_tests(todo, commands, test_timeout, env=env)
        if failed:
            alone = {n: not run_tests({n: todo[n]}, commands, test_timeout, env=env)[0]
                     for n in failed}
            # Failing together but each passing alone (a time-out of the union): none is
            # trusted to kill.
            bad = [n for n, ok in alone.items() if not ok] or failed
            for n in bad:
                baseline[n] = False
        for n in todo:
            baseline.setdefault(n, True)
    return all(baseline[n] for n in names)


SURVIVORS = os.path.join(HERE, "survivors.json")
WINDOW = 8


def line_key(m):
    """File, the mutated line's text (stripped) and operator: what a mutant changes, not where
    (ids and line numbers shift whenever a target file changes; a line's text rarely does)."""
    return (m["file"], m["before"].strip(), m["op"])


def survivor_key(m):
    """A judgement's key: line_key and the occurrence, so that one judgement stands for exactly
    one mutant, also where a line text repeats in its file or holds the operator twice."""
    return (*line_key(m), m["occurrence"])


RECORD_FIELDS = ("file", "line", "op", "occurrence", "verdict", "reason", "closed_by")
# A test the report knows by its id: the Boost.Test executable, then the case's path.
CLOSING_TEST = re.compile(r"[A-Za-z_][\w-]*:[A-Za-z_]\w*(?:/[A-Za-z_]\w*)+")


def load_judgements(path=SURVIVORS):
    """{key: judgement} from survivors.json: a list of {file, line, op, occurrence, verdict,
    reason}, the verdict "equivalent" (reason: why no input the code receives tells the mutant
    apart) or "gap" (reason: what the tests lack). A gap that a later test closes keeps its
    record (it judges the mutant in trees without that test) and names the test in closed_by,
    a list of the report's test ids (executable:suite/case), so that the report can show
    whether it passed in its run. A malformed entry is an error, not ignored; so is one that
    repeats a key or has a field of its own (a misspelt one would go unread)."""
    if not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as fh:
        doc = json.load(fh)
    out = {}
    for i, j in enumerate(doc.get("survivors", [])):
        if not isinstance(j, dict):
            raise SystemExit(f"{path}: survivors[{i}] must be an object")
        for field in ("file", "line", "op", "verdict", "reason"):
            if not isinstance(j.get(field), str) or not j[field].strip():
                raise SystemExit(f"{path}: survivors[{i}].{field} must be a non-empty string")
        occ = j.get("occurrence")
        if not isinstance(occ, int) or isinstance(occ, bool) or occ < 1:
            raise SystemExit(f"{path}: survivors[{i}].occurrence must be an integer >= 1 (which "
                             f"mutant of that line text and operator in the file, 1 for the "
                             f"first), not {occ!r}")
        extra = sorted(set(j) - set(RECORD_FIELDS))
        if extra:
            raise SystemExit(f"{path}: survivors[{i}] has unknown fields {extra}")
        if j["verdict"] not in ("equivalent", "gap"):
            raise SystemExit(f"{path}: survivors[{i}].verdict must be \"equivalent\" or "
                             f"\"gap\", not {j['verdict']!r}")
        if "closed_by" in j:
            closing = j["closed_by"]
            if j["verdict"] != "gap":
                raise SystemExit(f"{path}: survivors[{i}].closed_by belongs to a gap only (an "
                                 f"equivalent mutant has no test to close it)")
            if (not isinstance(closing, list) or not closing or
                    not all(isinstance(t, str) and CLOSING_TEST.fullmatch(t) for t in closing)):
                raise SystemExit(f"{path}: survivors[{i}].closed_by must be a non-empty list of "
                                 f"test ids, executable:suite/case, not {closing!r}")
        key = (j["file"], j["line"].strip(), j["op"], occ)
        if key in out:
            raise SystemExit(f"{path}: survivors[{i}] repeats {key}")
        out[key] = j
    return out


REFERENCE = os.path.join("verification", "mutation", "reference", "mutation.json")


def reference_survivors(root):
    """The survivor keys of the reference analysis kept in root (REFERENCE; none when it keeps
    none): the record judges them for the reference's own tree, also after their lines change
    in the checkout."""
    path = os.path.join(root, REFERENCE)
    if not os.path.exists(path):
        return set()
    with open(path, encoding="utf-8") as fh:
        rows = json.load(fh).get("mutants", [])
    return {survivor_key(r) for r in rows if r.get("verdict") == "survived"}


def stale_judgements(judgements, muts, reference=()):
    """The keys of judgements that name no mutant of muts nor a survivor of the reference
    (keys): the line changed, or the occurrence is past the number of such mutants in the
    file. A stale record is an error."""
    keys = {survivor_key(m) for m in muts} | set(reference)
    return sorted(k for k in judgements if k not in keys)


def check_record(path, muts, reference=()):
    """load_judgements, and a stale record an error too."""
    judgements = load_judgements(path)
    stale = stale_judgements(judgements, muts, reference)
    if stale:
        raise SystemExit(f"{path}: {len(stale)} judgement(s) name no mutant of this tree nor a "
                         f"survivor of its reference analysis (the line changed or the "
                         f"occurrence is past its last): "
                         + "; ".join(f"{f} '{t}' {o} occurrence {n}" for f, t, o, n in stale[:5]))
    return judgements


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


# The floor of the kill rate, and how sure a sample must make it: the check applies the floor
# to the lower bound of the score's 95 % interval when a sample was judged, and to the score
# itself only when every mutant was.
FLOOR = 0.9
CONFIDENCE = 0.95
Z = 1.959963984540054  # the standard normal quantile of 0.975


def floor_verdict(score, low, counted, complete):
    """(what the floor applies to, whether it holds): the score itself when every mutant was
    judged, the lower bound of its interval for a sample; never met with nothing counted."""
    on = "point estimate" if complete else "lower bound"
    return on, bool(counted) and (score if complete else low) >= FLOOR - 1e-12


def wilson(k, n, z=Z):
    """The Wilson score interval (95 % with the default z) of a kill rate k/n: where the rate of
    the mutants a random sample of n counted ones was drawn from lies. (0, 1) for n = 0."""
    if n <= 0:
        return (0.0, 1.0)
    p = k / n
    d = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / d
    half = z * math.sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / d
    return (max(0.0, centre - half), min(1.0, centre + half))


def shard_of(m, count):
    """Which of count shards (0 to count - 1) a mutant belongs to: a hash of its key (file, line
    text, operator, occurrence), so the split is the same on every machine, the shards are
    disjoint and together hold every mutant, and neither the seed, the ids nor an edit
    elsewhere moves a mutant to another shard. A shard is thus a random sample too."""
    text = "\x1f".join(("shard", *map(str, survivor_key(m))))
    return int(hashlib.sha256(text.encode("utf-8")).hexdigest(), 16) % count


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


def now_utc():
    return datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


def selection_text(sel):
    if sel["mode"] == "all":
        return f"all, in the rank order of seed {sel['seed']}" if "seed" in sel else "all"
    if sel["mode"] == "ids":
        return f"ids {sel['ids']}"
    return f"seed {sel['seed']}, sample {sel['sample']}, {sel['minutes']:g} min box"


def make_doc(results, judgements, *, population, chosen, selection, complete, provenance,
             prep_secs, sanitizer, broken, shard=None, shards=None):
    """The verification-schema document of judged mutants (results) with the record's
    judgements applied: the score, its 95 % interval and which of them the floor applies to."""
    for r in results:
        if r["verdict"] == "survived":
            j = judgements.get(survivor_key(r))
            r["judged"] = j["verdict"] if j else "not yet judged"
            r["reason"] = j["reason"] if j else ""
        else:
            r.pop("judged", None)
            r.pop("reason", None)
    score, killed, equivalent, counted = score_of(results, judgements)
    lo, hi = wilson(killed, counted)
    survived = [r for r in results if r["verdict"] == "survived"]
    gaps = [r for r in survived if r["judged"] == "gap"]
    unjudged = [r for r in survived if r["judged"] == "not yet judged"]
    by_sanitizer = sum(r.get("killed_by") == "sanitizer" for r in results)
    # A judgement of a mutant that the tests or the sanitizer build now kill: the record to
    # update (it does not count; the kill does). A gap that names the tests closing it is
    # expected to be killed where they exist: its record stays for the trees without them.
    judged_killed = [f"#{r['id']} {r['file']}:{r['line']} {r['op']} (occurrence "
                     f"{r['occurrence']})" for r in results
                     if r["verdict"] == "killed" and survivor_key(r) in judgements and
                     not judgements[survivor_key(r)].get("closed_by")]
    judged_runs = [r for r in results
                   if r["verdict"] in ("killed", "survived", "stillborn", "not built")]
    mean = (sum(r["seconds"] for r in judged_runs) / len(judged_runs)) if judged_runs else 0.0
    floor_on, passed = floor_verdict(score, lo, counted, complete)
    pct = lambda x: f"{100 * x:.1f} %"  # noqa: E731
    figure = (f"{pct(score)} ({killed} of {counted}), 95 % interval {100 * lo:.1f}-"
              f"{100 * hi:.1f} %")
    if complete:
        rule = (f"every mutant judged: the floor ({100 * FLOOR:.0f} %) applies to the score, "
                f"{pct(score)}")
    else:
        what = (f"shards {', '.join(str(i) for i in shards['merged'])} of {shards['count']}"
                if shards else f"shard {shard['index']} of {shard['count']}" if shard else
                "a sample")
        rule = (f"{what}, {len(results)} of {population} mutants judged: the floor "
                f"({100 * FLOOR:.0f} %) applies to the lower bound of the score's 95 % "
                f"interval, {pct(lo)}")
    details = (f"{killed} of {counted} non-equivalent compiled mutants killed ({pct(score)}, "
               f"95 % Wilson interval {100 * lo:.1f}-{100 * hi:.1f} %"
               f"{f'; {by_sanitizer} by the sanitizer build' if by_sanitizer else ''}); {rule} "
               f"({'met' if passed else 'not met'}); "
               f"{len(survived)} survived ({equivalent} judged equivalent, "
               f"{len(gaps)} judged gaps, {len(unjudged)} not yet judged), "
               f"{sum(r['verdict'] == 'stillborn' for r in results)} did not compile, "
               f"{sum(r['verdict'] == 'not built' for r in results)} compiled to unchanged "
               f"objects, "
               f"{sum(r['verdict'] == 'no tests' for r in results)} had no test; "
               f"{len(results)} of {chosen} chosen from {population} "
               f"({selection_text(selection)}); "
               f"{mean:.0f} s per built mutant, scratch build {prep_secs:.0f} s")
    if shards and shards["missing"]:
        details += (f"; shards missing: {', '.join(str(i) for i in shards['missing'])} of "
                    f"{shards['count']}")
    if sanitizer:
        details += f", sanitizer build {sanitizer['seconds']:.0f} s"
    if broken:
        details += (f"; {len(broken)} CTest entries fail without any mutant and were left out: "
                    + ", ".join(broken))
    if judged_killed:
        details += (f"; {len(judged_killed)} judged in survivors.json but killed now: "
                    + ", ".join(judged_killed))
    doc = {
        "program": "mutation",
        "description": "Mutation testing of src/tamias2d/model/ and dynamics/: mutants (operator "
                       "swaps, constants, comparisons, removed assignments) built in a scratch "
                       "copy, judged by the CTest entries labelled with the SRS items the mutated "
                       "file's \\srs tags, or those of the library headers it includes, name (a "
                       "file that reaches no tag: those of the files that include it) and by the "
                       "cases without a label in the same test executables, and by the golden "
                       "state hashes (tests/determinism) and the snapshot suite (tests/snapshot); "
                       + ("a survivor is judged again in an ASan and UBSan build, where a "
                          "sanitizer report kills it" if selection.get("sanitizer", True) else
                          "survivors not judged again in an ASan and UBSan build (--no-sanitizer: "
                          "a survivor counts against the score, which can only be lower for it)")
                       + ". Score: "
                       "killed / (killed + survivors not judged equivalent in "
                       "verification/mutation/survivors.json), with its 95 % Wilson interval; the "
                       f"{100 * FLOOR:.0f} % floor applies to the interval's lower bound for a "
                       "sample, to the score when every mutant is judged. This run: "
                       + details + ".",
        "provenance": provenance,
        "checks": [{"name": f"at least {100 * FLOOR:.0f} % of the non-equivalent mutants killed",
                    "labels": [], "passed": passed,
                    "target": (f">= {100 * FLOOR:.0f} % killed: "
                               + ("the score (every mutant judged)" if complete else
                                  "the lower bound of the score's 95 % interval (a sample)")),
                    "figure": figure,
                    "oracle": "the SRS-labelled tests, the golden state hashes, the snapshot "
                              "suite or the API suites fail on each "
                              "mutant, or a survivor's tests report an error in the sanitizer "
                              "build; survivors judged equivalent are argued in "
                              "verification/mutation/survivors.json",
                    "details": details}],
        "tables": [{"name": "Mutants", "columns": ["id", "where", "mutation", "labels (tests run)",
                                                   "verdict", "seconds (build + tests)"],
                    "rows": [[r["id"], f"{r['file']}:{r['line']}", r["op"],
                              ", ".join(r["labels"] + (["golden hashes, snapshots"] if any(
                                  t.split("@", 1)[0] in GOLDEN_TARGETS for t in r["tests"])
                                  else [])),
                              r["verdict"] + (" (sanitizer)" if r.get("killed_by") == "sanitizer"
                                              else ""),
                              f"{r['seconds']:.0f} ({r['build_seconds']:.0f} + "
                              f"{r['test_seconds']:.0f})"] for r in results]},
                   {"name": "Survivors",
                    "columns": ["id", "where", "mutation", "occurrence", "before", "after",
                                "judged", "reason"],
                    "rows": [[r["id"], f"{r['file']}:{r['line']}", r["op"], r["occurrence"],
                              r["before"].strip(), r["after"].strip() or "(removed)",
                              r["judged"], r["reason"]] for r in survived]}],
        "series": [],
        "score": score,
        "killed": killed,
        "counted": counted,
        "interval": [lo, hi],
        "confidence": CONFIDENCE,
        "floor": FLOOR,
        "floor_applies_to": floor_on,
        "sample_size": len(results),
        "chosen": chosen,
        "population": population,
        "complete": complete,
        "selection": selection,
        "killed_by_sanitizer": by_sanitizer,
        "judged_but_killed": judged_killed,
        "summary": details,
        "seconds_per_mutant": round(mean, 1),
        "failing_unmutated": broken,
        "scratch_build_seconds": round(prep_secs, 1),
        "sanitizer_build": sanitizer,
        "mutants": results,
    }
    if shard:
        doc["shard"] = shard
    if shards:
        doc["shards"] = shards
    return doc


def parse_shard(text):
    m = re.fullmatch(r"(\d+)/(\d+)", text or "")
    if not m or int(m.group(2)) < 1 or int(m.group(1)) >= int(m.group(2)):
        raise SystemExit(f"--shard {text!r}: I/N with 0 <= I < N (e.g. 0/8 to 7/8)")
    return int(m.group(1)), int(m.group(2))


def shard_file(index, count):
    return f"mutation-shard-{index}-of-{count}.json"


def merge(out_dir, files, survivors=SURVIVORS):
    """Merges the results of shards (mutate.py --shard I/N) into out_dir/mutation.json with the
    record's judgements as they stand. Refuses shards of different trees or commits, of
    different selections or shard counts, and overlapping shards (an index twice, or a mutant in
    two files); a missing shard is reported, and the result is then not complete."""
    docs = []
    for f in files:
        try:
            with open(f, encoding="utf-8") as fh:
                doc = json.load(fh)
        except (OSError, ValueError) as exc:
            raise SystemExit(f"--merge: {f}: unreadable ({exc})")
        sh = doc.get("shard") if isinstance(doc, dict) else None
        if doc.get("program") != "mutation" or not isinstance(sh, dict):
            raise SystemExit(f"--merge: {f} is not the results of a shard (mutate.py --shard)")
        docs.append((f, doc))
    if not docs:
        raise SystemExit("--merge: no shard results given")

    def refuse_unless_same(what, value):
        seen = {}
        for f, d in docs:
            seen.setdefault(json.dumps(value(d), sort_keys=True), []).append(f)
        if len(seen) > 1:
            raise SystemExit(f"--merge: the shards are of different {what}: " + "; ".join(
                f"{v} ({', '.join(fs)})" for v, fs in seen.items()))

    refuse_unless_same("commits", lambda d: d["provenance"].get("commit"))
    refuse_unless_same("trees (commit and uncommitted changes)",
                       lambda d: d["provenance"].get("tree"))
    refuse_unless_same("shard counts", lambda d: d["shard"]["count"])
    refuse_unless_same("selections", lambda d: {k: v for k, v in d["selection"].items()
                                                if k != "minutes"})
    refuse_unless_same("populations", lambda d: d["population"])
    count = docs[0][1]["shard"]["count"]
    where = {}
    for f, d in docs:
        where.setdefault(d["shard"]["index"], []).append(f)
    twice = {i: fs for i, fs in where.items() if len(fs) > 1}
    if twice:
        raise SystemExit("--merge: overlapping shards: " + "; ".join(
            f"shard {i} in {', '.join(fs)}" for i, fs in sorted(twice.items())))
    owner = {}
    for f, d in docs:
        for r in d["mutants"]:
            key = survivor_key(r)
            if key in owner:
                raise SystemExit(f"--merge: overlapping shards: mutant #{r['id']} {r['file']}:"
                                 f"{r['line']} {r['op']} is in {owner[key]} and {f}")
            owner[key] = f
    missing = sorted(set(range(count)) - set(where))
    results = sorted((r for _, d in docs for r in d["mutants"]), key=lambda r: r["id"])
    first = docs[0][1]
    sel = first["selection"]
    complete = (sel["mode"] == "all" and not missing
                and all(d["shard"].get("complete") for _, d in docs))
    builds = [d["provenance"].get("build") or {} for _, d in docs]

    def joined(key):
        return "; ".join(dict.fromkeys(str(b.get(key)) for b in builds if b.get(key)))
    provenance = {"commit": first["provenance"].get("commit"),
                  "dirty": first["provenance"].get("dirty"),
                  "tree": first["provenance"].get("tree"), "build_id": None,
                  "built": min(d["provenance"].get("built") or "" for _, d in docs),
                  "generated": now_utc(),
                  "build": {"name": f"mutation scratch builds of {len(docs)} shard(s)",
                            "where": joined("where"), "compiler": joined("compiler"),
                            "flags": joined("flags"), "options": joined("options")}}
    sanitizers = [d.get("sanitizer_build") for _, d in docs if d.get("sanitizer_build")]
    sanitizer = None
    if sanitizers:
        sanitizer = dict(sanitizers[0],
                         where="; ".join(dict.fromkeys(s["where"] for s in sanitizers)),
                         seconds=round(sum(s["seconds"] for s in sanitizers), 1),
                         targets=sorted({t for s in sanitizers for t in s.get("targets", [])}))
    shards = {"count": count, "merged": sorted(where), "missing": missing,
              "files": [os.path.basename(f) for f, _ in docs],
              "hosts": sorted({str(d.get("host")) for _, d in docs if d.get("host")})}
    doc = make_doc(results, load_judgements(survivors), population=first["population"],
                   chosen=sum(d["chosen"] for _, d in docs), selection=sel, complete=complete,
                   provenance=provenance,
                   prep_secs=sum(d["scratch_build_seconds"] for _, d in docs),
                   sanitizer=sanitizer,
                   broken=sorted({n for _, d in docs for n in d["failing_unmutated"]}),
                   shards=shards)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "mutation.json"), "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    print(f"mutation: merged {len(docs)} of {count} shards"
          + (f" (missing: {', '.join(map(str, missing))})" if missing else "") + "; "
          + doc["summary"])
    return 0


def results_to_resume(path, tree, selection, chosen):
    """{mutant id: result} of the chosen mutants judged in a results file (a run's
    mutation.json, a shard's file or a merge of shards, from any machine) of this tree and
    selection: a reference judged in part goes on where it stopped, on another machine. A file
    of another tree or selection is refused, not ignored: it was asked for by name."""
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError) as exc:
        raise SystemExit(f"--resume-from: {path}: unreadable ({exc})")
    if not isinstance(doc, dict) or doc.get("program") != "mutation":
        raise SystemExit(f"--resume-from: {path} is not the results of mutate.py")
    theirs = (doc.get("provenance") or {}).get("tree")
    if theirs != tree:
        raise SystemExit(f"--resume-from: {path} is of tree {theirs}, this run's is {tree}: "
                         "its verdicts need not hold here")

    def kind(sel):
        return {k: v for k, v in (sel or {}).items() if k != "minutes"}
    if kind(doc.get("selection")) != kind(selection):
        raise SystemExit(f"--resume-from: {path} is of selection "
                         f"{json.dumps(doc.get('selection'))}, this run's is "
                         f"{json.dumps(selection)}")
    by_id = {m["id"]: m for m in chosen}
    return {r["id"]: r for r in doc.get("mutants", [])
            if r.get("id") in by_id and survivor_key(by_id[r["id"]]) == survivor_key(r)}


class Journal:
    """The judged mutants of a run as they are judged, one JSON line each after a header line
    (the tree, the selection and the shard), so a run that is stopped (a batch job's time
    limit, a preempted machine, a closed laptop) and started again with --resume judges only
    the mutants it had not judged. A journal of another tree, selection or shard is not
    resumed: its mutants' verdicts need not hold for this one."""

    def __init__(self, path, header):
        self.path, self.header = path, header

    def resume(self, chosen):
        """{mutant id: result} of the journal's mutants that are in chosen, when the journal
        is of this run's tree, selection and shard; {} otherwise."""
        try:
            with open(self.path, encoding="utf-8") as fh:
                lines = fh.read().split("\n")
        except FileNotFoundError:
            return {}
        try:
            if json.loads(lines[0]) != self.header:
                print(f"mutation: {self.path} is of another tree, selection or shard: "
                      "not resumed", flush=True)
                return {}
        except ValueError:
            return {}
        by_id = {m["id"]: m for m in chosen}
        done = {}
        for line in lines[1:]:
            try:
                r = json.loads(line)
            except ValueError:  # the line being written when the run stopped
                continue
            m = by_id.get(r.get("id"))
            if m is not None and survivor_key(m) == survivor_key(r):
                done[m["id"]] = r
        return done

    def start(self, done):
        """Writes the header and the results carried over (done), replacing the file."""
        with open(self.path, "w", encoding="utf-8") as fh:
            fh.write(json.dumps(self.header) + "\n")
            for r in done.values():
                fh.write(json.dumps(r) + "\n")

    def add(self, r):
        with open(self.path, "a", encoding="utf-8") as fh:
            fh.write(json.dumps(r) + "\n")
            fh.flush()
            os.fsync(fh.fileno())


def judge_run(a, muts, chosen, selection, shard):
    """Builds the scratch, judges the chosen mutants (within the box, if any) and writes
    mutation.json or the shard's file to a.out_dir; the exit status."""
    commit, dirty = commit_of(a.root)
    tree = tree_of(a.root)
    started = now_utc()
    t_prep = time.monotonic()
    src, build, catalogue, objects = prepare_scratch(a.root, a.scratch, bool(a.coverage))
    prep_secs = time.monotonic() - t_prep
    coverage_failed = []
    if a.coverage:
        t_cov = time.monotonic()
        coverage_failed = measure_coverage(
            src, build, catalogue, *a.coverage,
            provenance={"commit": commit, "dirty": dirty, "tree": tree, "build_id": None,
                        "built": started, "generated": now_utc(),
                        "build": scratch_build(a.scratch, True)})
        print(f"coverage: every test once in {time.monotonic() - t_cov:.0f} s"
              + (f"; FAILED: {', '.join(coverage_failed)}" if coverage_failed else ""),
              flush=True)
        if not a.all and not a.ids and a.minutes <= 0:
            return 3 if coverage_failed else 0
    # The box is for judging mutants; the scratch builds are reported apart (minutes when the
    # scratch is new, seconds when it outlives a run): the sanitizer build's first build of a
    # test executable moves the deadline on by its time.
    deadline = None if (a.all or a.ids) else time.monotonic() + 60.0 * a.minutes
    sanitizer = SanitizerScratch(a.scratch, src)
    commands = commands_of(catalogue)
    categories = category_labels(a.root)
    unmutated = Unmutated(build)
    os.makedirs(a.out_dir, exist_ok=True)
    name = shard_file(*shard) if shard else "mutation.json"
    journal = Journal(os.path.join(a.out_dir, name[:-len(".json")] + ".journal"),
                      {"tree": tree, "selection": selection,
                       "shard": list(shard) if shard else None})
    done = journal.resume(chosen) if a.resume else {}
    if a.resume:
        print(f"mutation: {len(done)} of {len(chosen)} mutants judged before, from "
              f"{journal.path}", flush=True)
    for f in a.resume_from or ():
        kept = results_to_resume(f, tree, selection, chosen)
        print(f"mutation: {len(kept)} of {len(chosen)} mutants judged before, from {f}",
              flush=True)
        done.update(kept)
    journal.start(done)
    results = []
    baseline = {}  # CTest entry -> passes on the unmutated sources (asked when it kills)
    build_description = scratch_build(a.scratch, bool(a.coverage))

    def write_result():
        """Writes the result of the mutants judged so far, with the record's judgements as they
        stand (survivors may be judged while the run goes on): after each mutant, so a run
        stopped before its end leaves the sample it judged."""
        complete = selection["mode"] == "all" and not shard and len(results) == len(chosen)
        provenance = {"commit": commit, "dirty": dirty, "tree": tree, "build_id": None,
                      "built": started, "generated": now_utc(), "build": build_description}
        doc = make_doc(results, load_judgements(a.survivors), population=len(muts),
                       chosen=len(chosen), selection=selection, complete=complete,
                       provenance=provenance, prep_secs=prep_secs,
                       sanitizer=sanitizer.description() if sanitizer.configured else None,
                       broken=sorted(n for n, ok in baseline.items() if not ok),
                       shard={"index": shard[0], "count": shard[1],
                              "complete": len(results) == len(chosen)} if shard else None)
        if shard:
            doc["host"] = socket.gethostname()
        path = os.path.join(a.out_dir, name)
        with open(path + ".tmp", "w", encoding="utf-8") as fh:
            json.dump(doc, fh, indent=1)
        os.replace(path + ".tmp", path)
        return doc

    for m in chosen:
        if m["id"] in done:
            results.append(done[m["id"]])
            continue
        if deadline is not None and time.monotonic() > deadline:
            break
        labels = labels_of(a.root, m["file"])
        entries = entries_of(catalogue, labels, m["file"], categories)
        t0 = time.monotonic()
        entries = {n: t for n, t in entries.items() if baseline.get(n, True)}
        verdict, log, b_secs, t_secs, failed = judge(m, src, build, entries, a.test_timeout,
                                                     objects, commands=commands,
                                                     unmutated=unmutated)
        if verdict == "killed" and not passes_unmutated(failed, build, entries, baseline,
                                                        a.test_timeout, commands=commands):
            # Killed by a test that fails without the mutant too: judged again without it.
            broken = sorted(n for n in entries if baseline.get(n) is False)
            print(f"   (fails unmutated, left out from now on: {', '.join(broken)})")
            entries = {n: t for n, t in entries.items() if baseline.get(n, True)}
            verdict, log, b_secs, t_secs, failed = judge(m, src, build, entries, a.test_timeout,
                                                         objects, commands=commands,
                                                         unmutated=unmutated)
        killed_by = "tests" if verdict == "killed" else None
        prep_before = sanitizer.seconds
        if verdict == "survived" and a.sanitizer:
            # The second judge: the same tests in the ASan and UBSan build.
            killed, log, b2, t2, san_failed = sanitizer.judge(m, entries, a.test_timeout)
            b_secs, t_secs = b_secs + b2, t_secs + t2
            if killed:
                verdict, killed_by = "killed", "sanitizer"
        prep = sanitizer.seconds - prep_before
        if deadline is not None:
            deadline += prep
        secs = time.monotonic() - t0 - prep
        r = dict(m, verdict=verdict, labels=labels, tests=sorted(entries), seconds=round(secs, 1),
                 build_seconds=round(b_secs, 1), test_seconds=round(t_secs, 1),
                 log=log[-600:] if verdict in ("survived", "stillborn", "not built")
                 or killed_by == "sanitizer" else "")
        if killed_by:
            r["killed_by"] = killed_by
            r["failed"] = failed if killed_by == "tests" else san_failed
        if verdict == "survived":
            r["sanitizer"] = "passed"
        results.append(r)
        journal.add(r)
        write_result()
        print(f"{verdict:10s} #{m['id']} {m['file']}:{m['line']} {m['op']}"
              + (" (sanitizer)" if killed_by == "sanitizer" else "")
              + f" ({secs:.0f} s: build {b_secs:.0f}, tests {t_secs:.0f})"
              + (f" [sanitizer build {prep:.0f} s]" if prep >= 1 else ""), flush=True)
    doc = write_result()
    print("mutation: " + doc["summary"])
    return 3 if coverage_failed else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir", nargs="?")
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
    # The sanitizer build's first build of a test executable takes minutes to tens of minutes
    # on 2 cores; a short box (the main job's) leaves it out and counts survivors as survivors.
    ap.add_argument("--no-sanitizer", dest="sanitizer", action="store_false",
                    help="do not judge survivors again in the ASan and UBSan build")
    ap.add_argument("--survivors", default=SURVIVORS, help="the judged survivors (JSON)")
    ap.add_argument("--resume", action="store_true",
                    help="keep the verdicts of OUT_DIR's journal of this tree, selection and "
                         "shard (a run stopped before its end) and judge only the rest")
    ap.add_argument("--resume-from", nargs="+", metavar="FILE",
                    help="keep the verdicts of these results files (mutation.json, a shard's "
                         "file or a merge, e.g. the repository's reference) of this tree and "
                         "selection and judge only the rest")
    ap.add_argument("--ids", help="judge these mutants (ids of --list, comma-separated) only")
    ap.add_argument("--shard", metavar="I/N",
                    help="judge the I-th (0 to N-1) of N disjoint shards of the chosen mutants "
                         "and write OUT_DIR/mutation-shard-I-of-N.json")
    ap.add_argument("--merge", nargs="+", metavar=("OUT_DIR", "FILE"),
                    help="merge shards' results into OUT_DIR/mutation.json (no mutant is built)")
    ap.add_argument("--coverage", nargs=2, metavar=("JSON", "HTML"),
                    help="instrument the scratch build, run every test once on the unmutated "
                         "sources and write gcovr's summary and pages before the mutants")
    a = ap.parse_args(argv)
    if a.scratch is None:
        a.scratch = default_scratch(a.root)
    if a.merge:
        if a.out_dir or len(a.merge) < 2:
            ap.error("--merge OUT_DIR FILE...")
        return merge(a.merge[0], a.merge[1:], a.survivors)
    if not a.out_dir:
        ap.error("OUT_DIR is required")
    shard = parse_shard(a.shard) if a.shard else None

    muts = all_mutants(a.root)
    if a.list:
        try:
            for m in muts:
                if shard and shard_of(m, shard[1]) != shard[0]:
                    continue
                print(f"{m['id']:5d} {m['file']}:{m['line']} {m['op']}"
                      + (f" (occurrence {m['occurrence']})" if m["occurrence"] > 1 else ""))
            if shard:
                print(f"{sum(shard_of(m, shard[1]) == shard[0] for m in muts)} of "
                      f"{len(muts)} mutants in shard {shard[0]}/{shard[1]}")
            else:
                print(f"{len(muts)} mutants")
        except BrokenPipeError:  # piped into head
            pass
        return 0
    # A malformed or stale record stops the run before any build.
    check_record(a.survivors, muts, reference_survivors(a.root))
    if a.ids:
        by_id = {m["id"]: m for m in muts}
        chosen = [by_id[int(x)] for x in a.ids.split(",") if x.strip()]
        selection = {"mode": "ids", "ids": a.ids}
    elif a.all:
        # In the seed's rank order, as a sample: a run stopped before its end (a time limit, a
        # preempted machine) has judged a seeded random sample, whose interval says what it
        # shows of the whole.
        chosen, selection = sample_of(muts, len(muts), a.seed), {"mode": "all", "seed": a.seed}
    else:
        chosen = sample_of(muts, a.sample, a.seed)
        selection = {"mode": "sample", "seed": a.seed, "sample": a.sample, "minutes": a.minutes}
    if not a.sanitizer:
        selection["sanitizer"] = False
    if shard:
        chosen = [m for m in chosen if shard_of(m, shard[1]) == shard[0]]
    # Within each run of WINDOW sampled mutants, those of one file one after another: restoring
    # the file and building its next mutant are then one rebuild, not two, while a time box
    # still cuts the sample at a window's end, not after a few whole files.
    chosen = [m for k in range(0, len(chosen), WINDOW)
              for m in sorted(chosen[k:k + WINDOW], key=lambda m: (m["file"], m["line"], m["id"]))]
    lock = lock_scratch(a.scratch)
    try:
        return judge_run(a, muts, chosen, selection, shard)
    finally:
        lock.close()


if __name__ == "__main__":
    sys.exit(main())
