"""Fingerprints of the two ends of every trace link (item, test).

A review of a link (traceability/review.py) is a review of what both ends said when a person
looked. Each end has a fingerprint, the first 16 hex digits of the SHA-256 of its normative
text, so that a later change to either end shows the link as suspect:

* an SRS item: its statement (`description`), `equation`, `symbols`, `uses` (as a set) and
  `obligation`, with runs of whitespace read as one space: rewording a statement, changing
  a symbol's unit or a dependency changes it; a new title, note or erratum id does not;
* a Boost.Test case: its source text from the comment block above its declaration (the
  oracle) to the comment block of the next test-case macro of the file (or the file's end);
  lines are compared without trailing blanks, so moving a test leaves it unchanged;
* another CTest entry: the comment block above its `add_test(...)` (or the helper call that
  registers it) and the call itself, to its closing parenthesis;
* a verification check: the source files of its program (the files under verification/, else
  scripts/, that name the program as a quoted string) and the check's declared name, labels,
  oracle and target, not its measured details.

The test fingerprint does not follow code the test calls (fixtures, helpers, the library):
a changed helper leaves the link's review standing. Each test records what was hashed
(`fingerprint_source`); an end whose text cannot be found is hashed from what the harness
knows of it (its id, labels and oracle) and says so.
"""
from __future__ import annotations

import hashlib
import json
import os
import re

from . import evidence

DIGITS = 16
SOURCE_EXTS = (".cpp", ".hpp", ".h", ".cc", ".py", ".sh", ".cmake")
PROGRAM_DIRS = ("verification", "scripts")


def _ws(x):
    """Runs of whitespace in every string of x read as one space."""
    if isinstance(x, str):
        return " ".join(x.split())
    if isinstance(x, list):
        return [_ws(v) for v in x]
    if isinstance(x, dict):
        return {str(k): _ws(v) for k, v in x.items()}
    return x


def digest(obj):
    text = json.dumps(obj, sort_keys=True, ensure_ascii=False, separators=(",", ":"), default=str)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:DIGITS]


def item_normative(item):
    """The normative fields of an SRS item (an srs/ record or a report item)."""
    return _ws({"statement": item.get("description"), "equation": item.get("equation"),
                "symbols": item.get("symbols") or [],
                "uses": sorted(str(u) for u in item.get("uses") or []),
                "obligation": item.get("obligation")})


def item_fingerprint(item):
    return digest(item_normative(item))


class SourceTexts:
    """Reads (and caches) the repository's files for the test fingerprints."""

    def __init__(self, root):
        self.root = root
        self._lines = {}
        self._cmake = None
        self._programs = {}

    def lines(self, rel):
        if rel not in self._lines:
            try:
                with open(os.path.join(self.root, rel), encoding="utf-8", errors="replace") as fh:
                    self._lines[rel] = fh.read().split("\n")
            except OSError:
                self._lines[rel] = None
        return self._lines[rel]

    def cmake_files(self):
        if self._cmake is None:
            files = ["CMakeLists.txt"] if os.path.exists(os.path.join(self.root, "CMakeLists.txt")) else []
            for d in evidence.CMAKE_DIRS:
                base = os.path.join(self.root, d)
                if os.path.isdir(base):
                    files += [os.path.relpath(p, self.root).replace(os.sep, "/")
                              for p in evidence._walk(base, (".cmake",))
                              if p.endswith(("CMakeLists.txt", ".cmake"))]
            self._cmake = files
        return self._cmake

    def program_sources(self, program):
        """The files that name the program as a quoted string: verification/ first, else
        scripts/."""
        if program not in self._programs:
            pat = re.compile(r"[\"']" + re.escape(str(program)) + r"[\"']")
            found = []
            for d in PROGRAM_DIRS:
                base = os.path.join(self.root, d)
                if not os.path.isdir(base):
                    continue
                for p in evidence._walk(base, SOURCE_EXTS):
                    rel = os.path.relpath(p, self.root).replace(os.sep, "/")
                    text = self.lines(rel)
                    if text is not None and pat.search("\n".join(text)):
                        found.append(rel)
                if found:
                    break
            self._programs[program] = found
        return self._programs[program]


def _block_start(lines, idx):
    """First line of the comment block (and decorators) directly above lines[idx]."""
    j = idx
    while j > 0 and lines[j - 1].strip().startswith("BOOST_TEST_DECORATOR"):
        j -= 1
    return j - len(evidence._comment_block_above(lines, idx))


def _span_text(lines):
    return "\n".join(line.rstrip() for line in lines).strip("\n")


def boost_case_text(lines, line):
    """The source text of the test case declared at 1-based `line`, or None."""
    idx = line - 1
    if not (0 <= idx < len(lines)) or not evidence.TEST_MACRO.match(lines[idx]):
        return None
    end = len(lines)
    for j in range(idx + 1, len(lines)):
        if evidence.TEST_MACRO.match(lines[j]):
            end = _block_start(lines, j)
            break
    return _span_text(lines[_block_start(lines, idx):end])


def _call_end(lines, idx):
    """Index after the line where the CMake call starting at lines[idx] closes."""
    depth, quote = 0, False
    for j in range(idx, len(lines)):
        text = lines[j].split("#", 1)[0] if not quote else lines[j]
        for k, ch in enumerate(text):
            if ch == '"' and (k == 0 or text[k - 1] != "\\"):
                quote = not quote
            elif not quote and ch == "(":
                depth += 1
            elif not quote and ch == ")":
                depth -= 1
                if depth == 0:
                    return j + 1
    return len(lines)


def cmake_entry_text(lines, line):
    idx = line - 1
    if not (0 <= idx < len(lines)):
        return None
    start = idx
    while start > 0 and lines[start - 1].strip().startswith("#"):
        start -= 1
    return _span_text(lines[start:_call_end(lines, idx)])


def find_cmake_entry(texts, name):
    """(file, line) of add_test(NAME name ...) or of the helper call registering it."""
    short = name.split(".", 1)[1] if "." in name else None
    helper = None
    for rel in texts.cmake_files():
        lines = texts.lines(rel) or []
        for i, text in enumerate(lines):
            m = evidence.CMAKE_CALL.match(text)
            if not m:
                continue
            if m.group(1).lower() == "add_test" and m.group(2) == name:
                return rel, i + 1
            if helper is None and m.group(2) in (name, short) and m.group(1).lower() not in (
                    "if", "elseif", "foreach", "function", "macro", "set", "set_tests_properties"):
                helper = (rel, i + 1)
    return helper


def test_fingerprint(test, texts):
    """(fingerprint, what was hashed) of a test or check."""
    origin = test.get("origin")
    declared = {"id": test.get("id"), "labels": test.get("labels") or [],
                "oracle": test.get("oracle")}
    if origin == "boost" and test.get("file") and test.get("line"):
        lines = texts.lines(test["file"])
        text = boost_case_text(lines, test["line"]) if lines else None
        if text is not None:
            return digest({"source": text}), f"{test['file']}:{test['line']} (test case source)"
    elif origin == "ctest":
        where = (test["file"], test["line"]) if test.get("file") and test.get("line") else \
            find_cmake_entry(texts, str(test.get("name")))
        if where:
            lines = texts.lines(where[0])
            text = cmake_entry_text(lines, where[1]) if lines else None
            if text is not None:
                return digest({"source": text}), f"{where[0]}:{where[1]} (add_test block)"
    elif origin == "verification":
        files = texts.program_sources(test.get("binary"))
        check = {"name": test.get("name"), "labels": test.get("labels") or [],
                 "oracle": test.get("oracle"), "target": test.get("target")}
        if files:
            return (digest({"sources": {f: _span_text(texts.lines(f) or []) for f in files},
                            "check": check}),
                    ", ".join(files) + " (program source) and the check's declaration")
        return digest({"check": check}), "the check's declaration (no program source found)"
    return digest({"declared": declared}), "its id, labels and oracle (no source text found)"


def annotate(srs, items, tests, source_root):
    """Sets items[].fingerprint, tests[].fingerprint and tests[].fingerprint_source."""
    texts = SourceTexts(source_root)
    for it in items:
        raw = srs.items.get(it["label"])
        it["fingerprint"] = item_fingerprint(raw if raw is not None else it)
    for t in tests:
        if t.get("srs_labels"):
            t["fingerprint"], t["fingerprint_source"] = test_fingerprint(t, texts)
        else:  # no trace link to review
            t["fingerprint"], t["fingerprint_source"] = None, None
