"""Collect evidence: code tags, test inventories and results, oracles.

Inputs handled here:
  * `\\srs{LABEL}` comment tags in src/, include/, apps/, verification/ -> code sites
  * `ctest --show-only=json-v1`                                          -> CTest inventory
  * Boost.Test `--list_content=DOT` (stderr) per binary                  -> cases + labels
  * Boost.Test `--logger=JUNIT,all,<xml>` per binary                     -> per-case status
  * `ctest --output-junit` for the non-Boost CTest entries               -> status
  * `// Oracle:` comments above test-case macros (tests/**) and above
    add_test() calls in CMake files                                      -> oracle text

Running (run_tests) writes every raw result into a results directory with fixed names; the
parsers only read that directory, so pre-made results (the self-test fixtures) and live runs
take the same path.
"""
from __future__ import annotations

import concurrent.futures
import json
import os
import re
import subprocess
import time
import xml.etree.ElementTree as ET

# include/ is the library's public API: its \\srs tags are the library's too.
CODE_DIRS = ["src", "include", "apps", "verification"]
CMAKE_DIRS = ["cmake", "src", "apps", "tests", "examples", "verification"]
CODE_EXTS = (".hpp", ".h", ".hh", ".hxx", ".cpp", ".cc", ".cxx", ".c", ".ipp", ".inl",
             ".py", ".cmake", ".txt", ".sh")
TEST_SRC_EXTS = (".cpp", ".cc", ".cxx", ".hpp", ".h", ".ipp")
SKIP_DIRS = {".git", "build", "reports", "__pycache__", "node_modules", ".cache"}

SRS_TAG = re.compile(r"\\srs\{([^}]*)\}")

FAILING = ("failed", "error")


def _walk(root, exts):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS)
        for fn in sorted(filenames):
            if fn.endswith(exts) or fn == "CMakeLists.txt":
                yield os.path.join(dirpath, fn)


def area_of(relpath):
    top = relpath.split("/", 1)[0]
    return {"src": "library", "include": "library", "apps": "application",
            "verification": "verification"}.get(top, top)


# --------------------------------------------------------------------------- code tags
def _comment_spans(line, in_block, hash_comments):
    """Character spans of comments on one line. C/C++ (// and /* */, strings skipped) or
    '#' comments for Python/CMake/shell. Returns (spans, in_block_after)."""
    spans = []
    i, n = 0, len(line)
    if hash_comments:
        quote = None
        while i < n:
            ch = line[i]
            if quote:
                if ch == "\\":
                    i += 1
                elif ch == quote:
                    quote = None
            elif ch in "\"'":
                quote = ch
            elif ch == "#":
                return [(i, n)], False
            i += 1
        return [], False
    start = 0 if in_block else None
    quote = None
    while i < n:
        if in_block:
            j = line.find("*/", i)
            if j < 0:
                spans.append((start, n))
                return spans, True
            spans.append((start, j + 2))
            in_block = False
            i = j + 2
            continue
        ch = line[i]
        if quote:
            if ch == "\\":
                i += 2
                continue
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif line.startswith("//", i):
            spans.append((i, n))
            return spans, False
        elif line.startswith("/*", i):
            in_block, start = True, i
            i += 2
            continue
        i += 1
    return spans, in_block


def scan_code_tags(source_root):
    """Return a list of {label, file, line, area, text} for every \\srs{} tag in a comment."""
    sites = []
    for d in CODE_DIRS:
        base = os.path.join(source_root, d)
        if not os.path.isdir(base):
            continue
        for path in _walk(base, CODE_EXTS):
            rel = os.path.relpath(path, source_root).replace(os.sep, "/")
            hash_comments = path.endswith((".py", ".cmake", ".sh", "CMakeLists.txt", ".txt"))
            try:
                with open(path, encoding="utf-8", errors="replace") as fh:
                    lines = fh.read().split("\n")
            except OSError:
                continue
            in_block = False
            for no, line in enumerate(lines, 1):
                spans, in_block = _comment_spans(line, in_block, hash_comments)
                if "\\srs{" not in line:
                    continue
                for m in SRS_TAG.finditer(line):
                    if not any(a <= m.start() < b for a, b in spans):
                        continue  # in code or a string literal, not a comment tag
                    text = line[m.end():].strip()
                    text = re.sub(r"\*+/\s*$", "", text).strip()
                    for lab in re.split(r"[,\s]+", m.group(1).strip()):
                        if lab:
                            sites.append({"label": lab, "file": rel, "line": no,
                                          "area": area_of(rel), "text": text})
    return sites


# --------------------------------------------------------------------------- oracles
TEST_MACRO = re.compile(
    r"^\s*(BOOST_(?:AUTO_TEST_CASE_TEMPLATE|AUTO_TEST_CASE|DATA_TEST_CASE_F|DATA_TEST_CASE|"
    r"FIXTURE_TEST_CASE_TEMPLATE|FIXTURE_TEST_CASE|PARAM_TEST_CASE))\s*\(\s*([A-Za-z_]\w*)"
    r"(?:\s*,\s*([A-Za-z_]\w*))?")
ORACLE = re.compile(r"Oracle\s*:\s*(.*)$")
EXPECTED_FAILURES = re.compile(r"expected_failures\s*\(\s*(\d+)\s*\)")
# A test case whose body builds or steps a World drives the engine (traceability/links.py).
DRIVES_WORLD = re.compile(r"\bWorld\b|\bbuild_world\s*\(|\.step\s*\(")


def _comment_block_above(lines, idx):
    """Lines of the comment block directly above lines[idx] (0-based), top to bottom."""
    block = []
    j = idx - 1
    # BOOST_TEST_DECORATOR(...) lines may sit between the comment and the macro.
    while j >= 0 and lines[j].strip().startswith("BOOST_TEST_DECORATOR"):
        j -= 1
    in_c = False
    while j >= 0:
        s = lines[j].strip()
        if in_c:
            block.append(s)
            if s.startswith("/*"):
                in_c = False
            j -= 1
            continue
        if s.startswith("//"):
            block.append(s)
        elif s.endswith("*/"):
            block.append(s)
            if not s.startswith("/*"):
                in_c = True
        else:
            break
        j -= 1
    return list(reversed(block))


def _oracle_from_block(block):
    text = None
    for s in block:
        body = re.sub(r"^(///?|/\*+|\*+/?)\s?", "", s).rstrip("*/").strip()
        if text is None:
            m = ORACLE.search(body)
            if m:
                text = m.group(1).strip()
        else:
            # continuation lines: until an empty line or another "Key:" line
            if not body or re.match(r"^[A-Z][\w -]{0,20}:\s", body):
                break
            text += " " + body
    return text


def scan_test_sources(source_root):
    """Return {relpath: [ {name, macro, line, oracle} ]} for test-case macros in tests/."""
    out = {}
    base = os.path.join(source_root, "tests")
    if not os.path.isdir(base):
        return out
    for path in _walk(base, TEST_SRC_EXTS):
        if path.endswith("CMakeLists.txt"):
            continue
        rel = os.path.relpath(path, source_root).replace(os.sep, "/")
        try:
            with open(path, encoding="utf-8", errors="replace") as fh:
                lines = fh.read().split("\n")
        except OSError:
            continue
        decls = []
        starts = [i for i, line in enumerate(lines) if TEST_MACRO.match(line)]
        for k, i in enumerate(starts):
            line = lines[i]
            m = TEST_MACRO.match(line)
            macro, a1, a2 = m.group(1), m.group(2), m.group(3)
            name = a2 if macro == "BOOST_DATA_TEST_CASE_F" and a2 else a1
            # Boost's expected_failures(N) decorator: the case passes in Boost's terms with N
            # known failing assertions (documented findings); the report shows them as such.
            head = " ".join(lines[i:i + 4])
            xf = EXPECTED_FAILURES.search(head[:head.find("{")] if "{" in head else head)
            body = "\n".join(lines[i:starts[k + 1] if k + 1 < len(starts) else len(lines)])
            decls.append({"name": name, "macro": macro, "line": i + 1,
                          "oracle": _oracle_from_block(_comment_block_above(lines, i)),
                          "expected_failures": int(xf.group(1)) if xf else 0,
                          "drives_world": bool(DRIVES_WORLD.search(body))})
        if decls:
            out[rel] = decls
    return out


CMAKE_CALL = re.compile(r"^\s*([A-Za-z_]\w*)\s*\(\s*(?:NAME\s+)?([^\s)]+)")


def scan_cmake_oracles(source_root):
    """`# Oracle:` comment blocks directly above add_test(NAME x ...) in CMake files."""
    out = {}
    paths = [os.path.join(source_root, "CMakeLists.txt")]
    for d in CMAKE_DIRS:
        if os.path.isdir(os.path.join(source_root, d)):
            paths += list(_walk(os.path.join(source_root, d), (".cmake",)))
    for path in paths:
        if not os.path.exists(path) or not (path.endswith("CMakeLists.txt") or path.endswith(".cmake")):
            continue
        try:
            with open(path, encoding="utf-8", errors="replace") as fh:
                lines = fh.read().split("\n")
        except OSError:
            continue
        for i, line in enumerate(lines):
            m = CMAKE_CALL.match(line)
            if not m or m.group(1).lower() in ("if", "elseif", "else", "endif", "foreach", "endforeach",
                                                "function", "endfunction", "macro", "endmacro", "set"):
                continue
            block = []
            j = i - 1
            while j >= 0 and lines[j].strip().startswith("#"):
                block.append(lines[j].strip().lstrip("#").strip())
                j -= 1
            block.reverse()
            text = None
            for b in block:
                if text is None:
                    mm = ORACLE.search(b)
                    if mm:
                        text = mm.group(1).strip()
                elif b and not re.match(r"^[A-Z][\w -]{0,20}:\s", b):
                    text += " " + b
                else:
                    break
            if text:
                key = m.group(2)
                rec = {"oracle": text, "file": os.path.relpath(path, source_root).replace(os.sep, "/"),
                       "line": i + 1, "call": m.group(1)}
                if key not in out or m.group(1).lower() == "add_test":
                    out[key] = rec
    return out


def cmake_oracle_for(name, cmake_oracles):
    """The oracle of a CTest entry: above add_test(NAME <name>), or above the helper call that
    registered it, whose first argument is the name or its part after the first '.'
    (tamias_add_compile_fail(dd08_x ...) registers compile_fail.dd08_x)."""
    if name in cmake_oracles:
        return cmake_oracles[name]
    if "." in name:
        return cmake_oracles.get(name.split(".", 1)[1])
    return None


# --------------------------------------------------------------------------- CTest inventory
def parse_ctest_json(path):
    with open(path, encoding="utf-8") as fh:
        data = json.load(fh)
    tests = []
    for idx, t in enumerate(data.get("tests", []), 1):
        props = {p.get("name"): p.get("value") for p in t.get("properties", [])}
        labels = props.get("LABELS") or []
        if isinstance(labels, str):
            labels = labels.split(";")
        cmd = t.get("command") or []
        name = t.get("name") or ""
        blabel = _boost_label(cmd)
        if not cmd and "@" in name:
            # ctest omits "command" when the executable does not exist (not built yet):
            # keep it a Boost entry so that the report says "not built".
            blabel = name.rsplit("@", 1)[1]
        tests.append({"index": idx, "name": name, "command": cmd,
                      "labels": [str(x) for x in labels],
                      "cwd": props.get("WORKING_DIRECTORY"),
                      "disabled": bool(props.get("DISABLED")),
                      "will_fail": bool(props.get("WILL_FAIL")),
                      "boost_label": blabel})
    return tests


def _boost_label(cmd):
    for arg in cmd[1:]:
        if arg.startswith("--run_test=@"):
            return arg[len("--run_test=@"):]
    return None


def boost_binaries(ctests):
    """Distinct Boost.Test executables: {key: {path, cwd, labels: [registered labels]}}."""
    by_path = {}
    for t in ctests:
        if t["boost_label"] is None:
            continue
        path = t["command"][0] if t["command"] else t["name"].rsplit("@", 1)[0]
        b = by_path.setdefault(path, {"path": path, "cwd": t["cwd"],
                                                 "labels": [], "ctest_names": []})
        b["labels"].append(t["boost_label"])
        b["ctest_names"].append(t["name"])
    # Keys: basename, disambiguated with parent directories on collision.
    keys = {}
    paths = sorted(by_path)
    for p in paths:
        parts = p.replace("\\", "/").split("/")
        depth = 1
        while True:
            key = "__".join(parts[-depth:])
            clash = [q for q in paths if q != p and "__".join(q.replace("\\", "/").split("/")[-depth:]) == key]
            if not clash or depth >= len(parts):
                break
            depth += 1
        keys[key] = by_path[p]
        by_path[p]["key"] = key
    return keys


# --------------------------------------------------------------------------- Boost DOT
DOT_NODE = re.compile(r'^\s*(tu\d+)\s*\[(.*)\]\s*;\s*$')
DOT_EDGE = re.compile(r'^\s*(tu\d+)\s*->\s*(tu\d+)\s*;\s*$')
DOT_LABEL = re.compile(r'label="(.*)"')
DOT_COLOR = re.compile(r'color=(\w+)')


def parse_boost_dot(text):
    """Parse Boost.Test --list_content=DOT. Returns (ids in order, {id: unit}); a unit has
    id, name, file, line, labels (own), parent, children, enabled, master."""
    units = {}
    order = []
    edges = []
    for line in text.splitlines():
        m = DOT_NODE.match(line)
        if m:
            attrs = m.group(2)
            lm = DOT_LABEL.search(attrs)
            label = lm.group(1) if lm else ""
            parts = label.split("|")
            name = parts[0]
            file = line_no = None
            labels = []
            for p in parts[1:]:
                p = p.strip()
                if p.startswith("labels:"):
                    labels = [x.lstrip("@") for x in p[len("labels:"):].split()]
                else:
                    fm = re.match(r"^(.*)\((\d+)\)$", p)
                    if fm:
                        file, line_no = fm.group(1), int(fm.group(2))
            cm = DOT_COLOR.search(attrs)
            units[m.group(1)] = {"id": m.group(1), "num": int(m.group(1)[2:]), "name": name,
                                 "file": file, "line": line_no, "labels": labels,
                                 "enabled": (cm.group(1) if cm else "green") != "yellow",
                                 "master": "ellipse" in attrs, "parent": None, "children": []}
            order.append(m.group(1))
            continue
        m = DOT_EDGE.match(line)
        if m:
            edges.append((m.group(1), m.group(2)))
    for a, b in edges:
        if a in units and b in units:
            units[b]["parent"] = a
            units[a]["children"].append(b)
    return order, units


def boost_cases(text):
    """Flatten a DOT listing into test cases with effective (inherited) labels.

    A data-driven test case (BOOST_DATA_TEST_CASE) appears as a suite whose children are
    `_0`, `_1`, ... at the same file/line; it is returned as ONE case with `samples`.
    """
    order, units = parse_boost_dot(text)
    cases = []

    def path_of(u):
        names = []
        while u is not None and not units[u]["master"]:
            names.append(units[u]["name"])
            u = units[u]["parent"]
        return list(reversed(names))

    def eff_labels(u):
        labs = []
        while u is not None:
            for x in units[u]["labels"]:
                if x not in labs:
                    labs.append(x)
            u = units[u]["parent"]
        return labs

    def eff_enabled(u):
        while u is not None:
            if not units[u]["enabled"]:
                return False
            u = units[u]["parent"]
        return True

    consumed = set()
    for uid in order:
        u = units[uid]
        if u["master"] or uid in consumed:
            continue
        kids = [units[k] for k in u["children"]]
        is_data = bool(kids) and all(re.fullmatch(r"_\d+", k["name"]) and not k["children"]
                                     for k in kids)
        if is_data:
            consumed.update(u["children"])
            labs = eff_labels(uid)
            for k in kids:  # BOOST_TEST_DECORATOR labels land on the samples
                labs += [x for x in k["labels"] if x not in labs]
            cases.append({"path": path_of(uid), "file": u["file"], "line": u["line"],
                          "labels": labs, "enabled": eff_enabled(uid) and any(k["enabled"] for k in kids),
                          "decl_names": [u["name"]],
                          "samples": [path_of(k) for k in u["children"]]})
        elif not kids and u["num"] >= 0x10000:
            cases.append({"path": path_of(uid), "file": u["file"], "line": u["line"],
                          "labels": eff_labels(uid), "enabled": eff_enabled(uid),
                          "decl_names": [u["name"], u["name"].split("<")[0]],
                          "samples": None})
    return cases


# --------------------------------------------------------------------------- JUnit
def parse_junit(path):
    """Return {tuple(path): {status, message, time}} from a JUnit XML file.
    Boost.Test: classname = suite path joined by '.', name = case name.
    CTest: classname = name = test name (the key is then (name,))."""
    tree = ET.parse(path)
    root = tree.getroot()
    results = {}
    for tc in root.iter("testcase"):
        name = tc.get("name", "")
        classname = tc.get("classname") or ""
        status = "passed"
        message = ""
        if tc.find("failure") is not None:
            status = "failed"
            el = tc.find("failure")
            message = (el.get("message") or "") + "\n" + (el.text or "")
        elif tc.find("error") is not None:
            status = "error"
            el = tc.find("error")
            message = (el.get("message") or "") + "\n" + (el.text or "")
        elif tc.find("skipped") is not None:
            status = "skipped"
            so = tc.find("system-out")
            why = tc.find("skipped").get("message") or ""
            message = why + "\n" + ((so.text or "") if so is not None else "")
            if why.startswith(("Unable to find executable", "Required files missing",
                               "Fixture dependency failed", "Failed to start")):
                status = "error"  # registered but could not run: not a legitimate skip
        # Boost.Test counts the assertions a case evaluated: a case that passed without one
        # checked nothing, so it cannot stand as evidence (CTest's entries carry no count).
        if status == "passed" and tc.get("assertions") == "0":
            status = "error"
            message = "passed without evaluating a single assertion: it verifies nothing"
        # CTest's JUnit carries status="run|fail|disabled|notrun"
        cstat = tc.get("status")
        if cstat == "fail" and status == "passed":
            status = "failed"
        elif cstat in ("disabled", "notrun") and status == "passed":
            status = "skipped" if cstat == "disabled" else "notrun"
        if classname and classname != name:
            key = tuple(classname.split(".")) + (name,)
        else:
            key = (name,)
        results[key] = {"status": status, "message": message.strip()[:2000],
                        "time": tc.get("time")}
    return results


# --------------------------------------------------------------------------- running
def _run(cmd, cwd, timeout, log=None, stderr_to=None):
    t0 = time.time()
    try:
        # A property-test replay seed would shrink the seeded properties to one scene: the
        # report's runs never see it.
        env = {k: v for k, v in os.environ.items() if k != "TAMIAS_PROPERTY_SEED"}
        proc = subprocess.run(cmd, cwd=cwd or None, capture_output=True, text=True, env=env,
                              timeout=timeout, errors="replace")
        rc, out, err = proc.returncode, proc.stdout, proc.stderr
    except subprocess.TimeoutExpired as exc:
        rc, out, err = "timeout", exc.stdout or "", (exc.stderr or "")
        if isinstance(out, bytes):
            out = out.decode("utf-8", "replace")
        if isinstance(err, bytes):
            err = err.decode("utf-8", "replace")
    except OSError as exc:
        rc, out, err = "oserror", "", str(exc)
    if stderr_to:
        with open(stderr_to, "w", encoding="utf-8") as fh:
            fh.write(err)
    if log:
        with open(log, "w", encoding="utf-8") as fh:
            fh.write(f"$ {' '.join(cmd)}\n# cwd: {cwd}\n# exit: {rc}\n--- stdout ---\n{out}\n--- stderr ---\n{err}\n")
    return rc, round(time.time() - t0, 3), out, err


def run_tests(build_dir, results_dir, timeout=1800, jobs=1, log=print, junit_level="message",
              build=None):
    """Run everything once and write raw results into results_dir. Returns the manifest, which
    records the build's provenance (build: <build>/provenance.json) the results are of."""
    os.makedirs(os.path.join(results_dir, "boost"), exist_ok=True)
    manifest = {"build_dir": os.path.abspath(build_dir), "started": time.strftime("%Y-%m-%dT%H:%M:%S"),
                "build": build, "commands": [], "binaries": {}, "ctest_junit": None, "errors": []}
    ctest_json = os.path.join(results_dir, "ctest.json")
    # Never let results of an earlier run pass for this one.
    stale = [ctest_json, os.path.join(results_dir, "ctest_junit.xml")]
    stale += [os.path.join(results_dir, "boost", f) for f in os.listdir(os.path.join(results_dir, "boost"))]
    for f in stale:
        if os.path.isfile(f):
            os.remove(f)
    if not os.path.isdir(build_dir):
        manifest["errors"].append(f"build directory {build_dir} does not exist: no tests were run")
        _write_json(os.path.join(results_dir, "runs.json"), manifest)
        return manifest
    cmd = ["ctest", "--test-dir", build_dir, "--show-only=json-v1"]
    rc, dur, out, err = _run(cmd, None, 300)
    manifest["commands"].append({"cmd": cmd, "exit": rc, "seconds": dur})
    if rc != 0 or not out.strip().startswith("{"):
        manifest["errors"].append(f"`{' '.join(cmd)}` failed (exit {rc}): {err.strip()[:500]}")
        _write_json(os.path.join(results_dir, "runs.json"), manifest)
        return manifest
    with open(ctest_json, "w", encoding="utf-8") as fh:
        fh.write(out)
    ctests = parse_ctest_json(ctest_json)

    def run_binary(key, b):
        """List and run one Boost.Test binary; returns its manifest entry and commands."""
        dot = os.path.join(results_dir, "boost", key + ".dot")
        junit = os.path.join(results_dir, "boost", key + ".junit.xml")
        if os.path.exists(junit):
            os.remove(junit)
        if not os.path.exists(b["path"]):
            msg = f"{key}: test binary {b['path']} does not exist (not built?)"
            for f in (dot, junit):
                if os.path.exists(f):
                    os.remove(f)
            log(f"[traceability] {msg}")
            return {"path": b["path"], "cwd": b["cwd"], "missing": True}, [], msg
        log(f"[traceability] {key}: listing and running")
        c1 = [b["path"], "--list_content=DOT"]
        rc1, d1, _, _ = _run(c1, b["cwd"], 300, stderr_to=dot)
        c2 = [b["path"], f"--logger=JUNIT,{junit_level},{os.path.abspath(junit)}", "--report_level=no"]
        rc2, d2, _, _ = _run(c2, b["cwd"], timeout, log=os.path.join(results_dir, "boost", key + ".log"))
        entry = {"path": b["path"], "cwd": b["cwd"], "list_exit": rc1, "run_exit": rc2,
                 "seconds": d2, "dot": f"boost/{key}.dot", "junit": f"boost/{key}.junit.xml"}
        return entry, [{"cmd": c1, "exit": rc1, "seconds": d1},
                       {"cmd": c2, "exit": rc2, "seconds": d2}], None

    # The binaries are independent processes: `jobs` of them at a time (the manifest keeps
    # their sorted order whatever order they finish in).
    binaries = sorted(boost_binaries(ctests).items())
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        done = list(pool.map(lambda kb: run_binary(*kb), binaries))
    for (key, _), (entry, commands, error) in zip(binaries, done):
        manifest["binaries"][key] = entry
        manifest["commands"] += commands
        if error:
            manifest["errors"].append(error)
    others = [t for t in ctests if t["boost_label"] is None]
    if others:
        cj = os.path.join(results_dir, "ctest_junit.xml")
        if os.path.exists(cj):
            os.remove(cj)
        nums = ",".join(str(t["index"]) for t in others)
        c3 = ["ctest", "--test-dir", build_dir, "-I", f"0,0,0,{nums}", "-j", str(jobs),
              "--output-junit", os.path.abspath(cj), "--timeout", str(timeout)]
        log(f"[traceability] ctest: {len(others)} non-Boost entries")
        rc3, d3, _, _ = _run(c3, None, timeout * 2, log=os.path.join(results_dir, "ctest_run.log"))
        manifest["commands"].append({"cmd": c3, "exit": rc3, "seconds": d3})
        manifest["ctest_junit"] = "ctest_junit.xml"
    manifest["finished"] = time.strftime("%Y-%m-%dT%H:%M:%S")
    _write_json(os.path.join(results_dir, "runs.json"), manifest)
    return manifest


def _write_json(path, data):
    with open(path, "w", encoding="utf-8") as fh:
        json.dump(data, fh, indent=2, sort_keys=True)


# --------------------------------------------------------------------------- assembly
def _resolve_test_file(file, source_root, test_sources):
    if not file:
        return None
    f = file.replace("\\", "/")
    if os.path.isabs(f):
        try:
            rel = os.path.relpath(f, source_root).replace(os.sep, "/")
        except ValueError:
            rel = f
        if rel in test_sources:
            return rel
    if f in test_sources:
        return f
    cands = [r for r in test_sources if r.endswith("/" + f.split("/")[-1]) or r == f.split("/")[-1]]
    # prefer the longest common suffix
    best, best_len = None, -1
    for r in cands:
        a, b = r.split("/")[::-1], f.split("/")[::-1]
        n = 0
        while n < min(len(a), len(b)) and a[n] == b[n]:
            n += 1
        if n > best_len:
            best, best_len = r, n
    return best


def collect_tests(source_root, results_dir, warnings):
    """Build the test list from the results directory. Returns (tests, ctest_entries, info)."""
    tests = []
    info = {"boost_binaries": {}, "ctest_entries": 0, "manifest": None, "registration": []}
    manifest_path = os.path.join(results_dir, "runs.json")
    if os.path.exists(manifest_path):
        with open(manifest_path, encoding="utf-8") as fh:
            info["manifest"] = json.load(fh)
        for e in info["manifest"].get("errors", []):
            warnings.append(e)
    ctest_json = os.path.join(results_dir, "ctest.json")
    if not os.path.exists(ctest_json):
        warnings.append(f"no CTest inventory ({ctest_json}): no test results are included")
        return tests, [], info
    ctests = parse_ctest_json(ctest_json)
    info["ctest_entries"] = len(ctests)
    test_sources = scan_test_sources(source_root)
    cmake_oracles = scan_cmake_oracles(source_root)
    runs = (info["manifest"] or {}).get("binaries", {})

    for key, b in sorted(boost_binaries(ctests).items()):
        dot_path = os.path.join(results_dir, "boost", key + ".dot")
        junit_path = os.path.join(results_dir, "boost", key + ".junit.xml")
        run = runs.get(key, {})
        binfo = {"path": b["path"], "registered_labels": sorted(b["labels"]),
                 "run_exit": run.get("run_exit"), "cases": 0, "problems": []}
        info["boost_binaries"][key] = binfo
        if not os.path.exists(dot_path) or os.path.getsize(dot_path) == 0:
            if run.get("missing"):
                msg = f"{key}: test binary {b['path']} was not built; its test cases are unknown"
            else:
                msg = f"{key}: no --list_content=DOT listing; its test cases are unknown"
            warnings.append(msg)
            binfo["problems"].append(msg)
            for lab in b["labels"]:
                tests.append(_synthetic(key, lab, "error", msg))
            continue
        with open(dot_path, encoding="utf-8", errors="replace") as fh:
            cases = boost_cases(fh.read())
        junit = None
        if os.path.exists(junit_path):
            try:
                junit = parse_junit(junit_path)
            except ET.ParseError as exc:
                msg = f"{key}: JUnit file unreadable ({exc}); binary exit {run.get('run_exit')}"
                warnings.append(msg)
                binfo["problems"].append(msg)
        else:
            msg = f"{key}: no JUnit result (binary exit {run.get('run_exit', 'unknown')})"
            warnings.append(msg)
            binfo["problems"].append(msg)
        binfo["cases"] = len(cases)
        if not cases:
            msg = (f"{key}: the --list_content=DOT listing names no test case (list exit "
                   f"{run.get('list_exit', 'unknown')}); its registered labels get an error entry")
            warnings.append(msg)
            binfo["problems"].append(msg)
            for lab in b["labels"]:
                tests.append(_synthetic(key, lab, "error", msg))
            continue
        case_labels = set()
        for c in cases:
            status, message, samples_summary = _case_status(c, junit)
            decl = _find_decl(c, source_root, test_sources)
            rel_file = decl[0] if decl else _resolve_test_file(c["file"], source_root, test_sources)
            oracle = decl[1]["oracle"] if decl else None
            xfail = decl[1].get("expected_failures", 0) if decl else 0
            if xfail and status == "failed" and run.get("run_exit") == 0:
                # Boost accepted exactly the declared number of failures (else it exits non-zero).
                status = "known-failure"
                message = (f"{xfail} expected failure(s), documented findings: " + message)[:2000]
            name = "/".join(c["path"])
            t = {"id": f"{key}:{name}", "name": name, "origin": "boost", "binary": key,
                 "status": status, "labels": c["labels"], "oracle": oracle,
                 "file": rel_file or c["file"], "line": decl[1]["line"] if decl else c["line"],
                 "details": message, "samples": samples_summary, "enabled": c["enabled"],
                 "drives_world": decl[1].get("drives_world") if decl else None}
            tests.append(t)
            if c["enabled"]:
                case_labels.update(c["labels"])
        rc = run.get("run_exit")
        if junit is not None and rc not in (None, 0) and not any(
                t["status"] in FAILING for t in tests if t.get("binary") == key):
            msg = (f"{key}: exited with status {rc} although its JUnit result shows no failing case "
                   "(crash at exit, leak report or a Boost.Test usage error)")
            warnings.append(msg)
            binfo["problems"].append(msg)
            tests.append({"id": f"{key}:<process exit>", "name": "<process exit>", "origin": "boost",
                          "binary": key, "status": "error", "labels": [], "oracle": None,
                          "file": None, "line": None, "details": msg, "samples": None, "enabled": True})
        reg = set(b["labels"])
        for lab in sorted(case_labels - reg):
            info["registration"].append(f"{key}: label @{lab} is on test cases but has no CTest "
                                        f"entry {key}@{lab}, so `ctest -L {lab}` will not run them")
        for lab in sorted(reg - case_labels):
            info["registration"].append(f"{key}: CTest entry for @{lab} selects no enabled test case")

    others = [t for t in ctests if t["boost_label"] is None]
    cj_path = os.path.join(results_dir, "ctest_junit.xml")
    cj = {}
    if others:
        if os.path.exists(cj_path):
            try:
                cj = parse_junit(cj_path)
            except ET.ParseError as exc:
                warnings.append(f"ctest_junit.xml unreadable: {exc}")
        else:
            warnings.append("no JUnit result for the non-Boost CTest entries (ctest_junit.xml)")
    for t in others:
        r = cj.get((t["name"],))
        status = r["status"] if r else ("skipped" if t["disabled"] else "notrun")
        co = cmake_oracle_for(t["name"], cmake_oracles)
        tests.append({"id": f"ctest:{t['name']}", "name": t["name"], "origin": "ctest",
                      "binary": None, "status": status, "labels": t["labels"],
                      "oracle": co["oracle"] if co else None,
                      "file": co["file"] if co else None, "line": co["line"] if co else None,
                      "details": (r or {}).get("message", "") if r else "no result recorded",
                      "samples": None, "enabled": not t["disabled"],
                      "command": " ".join(t["command"]), "will_fail": t["will_fail"]})
    return tests, ctests, info


def _synthetic(key, lab, status, msg):
    return {"id": f"{key}@{lab}", "name": f"{key}@{lab}", "origin": "boost", "binary": key,
            "status": status, "labels": [lab], "oracle": None, "file": None, "line": None,
            "details": msg, "samples": None, "enabled": True}


def _case_status(case, junit):
    if not case["enabled"]:
        return "skipped", "disabled in the test source", None
    if junit is None:
        return "error", "no JUnit result for this binary (crashed or not run)", None
    if case["samples"] is None:
        r = junit.get(tuple(case["path"]))
        if r is None:
            return "notrun", "absent from the JUnit result", None
        return r["status"], r["message"], None
    counts = {}
    msgs = []
    for s in case["samples"]:
        r = junit.get(tuple(s))
        st = r["status"] if r else "notrun"
        counts[st] = counts.get(st, 0) + 1
        if r and st in FAILING and len(msgs) < 3:
            msgs.append(f"{s[-1]}: {r['message'][:300]}")
    n = len(case["samples"])
    if counts.get("error"):
        st = "error"
    elif counts.get("failed"):
        st = "failed"
    elif counts.get("passed", 0) == n:
        st = "passed"
    elif counts.get("passed"):
        st = "failed"  # some samples did not run although others did
    else:
        st = "notrun" if counts.get("notrun") else "skipped"
    summary = ", ".join(f"{v} {k}" for k, v in sorted(counts.items()))
    return st, "\n".join(msgs), f"{n} samples: {summary}"


def _find_decl(case, source_root, test_sources):
    rel = _resolve_test_file(case["file"], source_root, test_sources)
    candidates = []
    if rel:
        candidates = [(rel, d) for d in test_sources[rel] if d["name"] in case["decl_names"]]
    if not candidates:
        candidates = [(r, d) for r, ds in test_sources.items() for d in ds
                      if d["name"] in case["decl_names"][:2]]
        if len(candidates) != 1:
            return None
    line = case["line"] or 0
    candidates.sort(key=lambda rd: (abs(rd[1]["line"] - line), rd[1]["line"]))
    # A multi-line macro invocation may report a later line: prefer the closest at/before it.
    before = [rd for rd in candidates if rd[1]["line"] <= line]
    return before[0] if before and (line - before[0][1]["line"]) < 40 else candidates[0]
