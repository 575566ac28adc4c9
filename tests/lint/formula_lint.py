#!/usr/bin/python3
"""One formula, one place: fails when an SRS formula is written again outside src/tamias2d/model/.

Every SRS formula lives in one model module (docs/design.md, "One formula, one place"); the
engine calls it through dynamics/model_bridge.hpp or the model's plain-double forms. This lint
reads the library's C++ (src/, include/, apps/; comments and string literals removed) and
flags each rule's pattern, a hand-written shape of one formula, anywhere but the file allowed to
hold it. Tests are not read: they write their oracles independently on purpose.

KNOWN lists duplicates that are known and waiting, each with its reason; an entry that no
longer matches fails the lint too, so the list can only shrink.

    /usr/bin/python3 tests/lint/formula_lint.py [--root DIR] [--json FILE]
"""
import argparse
import json
import os
import re
import sys
from dataclasses import dataclass, field

MODEL_DIR = "src/tamias2d/model/"
SCANNED = ("src", "include", "apps")
EXTENSIONS = (".hpp", ".cpp", ".h", ".cc")


@dataclass
class Rule:
    name: str
    item: str  # the SRS item (or convention) whose formula the pattern writes
    pattern: str
    allowed: dict = field(default_factory=dict)  # path -> why the formula may live there

    def regex(self):
        return re.compile(self.pattern)


RULES = [
    Rule("cross_2d", "E42 (2D cross product)",
         r"\b(\w+)\.x\s*\*\s*(\w+)\.y\s*-\s*\1\.y\s*\*\s*\2\.x\b",
         {"include/tamias2d/vec2.hpp": "the one definition, public (model/ uses it through "
                                      "units/vec2.hpp)"}),
    Rule("gd2_g", "GD2 (the SRS's g)", r"(?<![\w.])9\.81(?![\d])",
         {"include/tamias2d/world_def.hpp": "srs_gravity, the one literal (public: WorldDef's "
                                            "default needs it without Boost.Units)"}),
    Rule("t5_disc", "T5 (p in a disc)",
         r"dot\(\s*(\w+)\s*,\s*\1\s*\)\s*<=\s*[\w.]*radius\s*\*\s*[\w.]*radius"),
    Rule("t5_polygon", "T5 (p in a convex polygon)",
         r"dot\([^;{}]*normals\[[^;{}]*vertices\[[^;{}]*\)\s*>\s*0\.0\s*\)\s*return\s+false"),
    Rule("im4_overlap", "IM4 (AABB overlap)",
         r"(\w+)\.min_x\s*<\s*(\w+)\.max_x\s*&&\s*\1\.max_x\s*>\s*\2\.min_x"),
    Rule("im7_softness", "IM7 (soft constraint coefficients)",
         r"2\.0\s*\*\s*\w*(?:damping|zeta)\w*\s*\+\s*\w+\s*\*\s*omega"),
    Rule("im1_im2_halves", "IM1/IM2 (semi-implicit Euler halves, DD3/DD4/DD6/DD7)",
         r"\b(?:v|w|dp|dq|center|angle|position|velocity)\s*\+=\s*[^;{}]*\*\s*h\s*;"),
    Rule("im3_apply", "IM3 (velocity jumps of an impulse)",
         r"\.(?:v|w)\s*[-+]=\s*\w+\.inv_(?:m|I|mass|inertia)\s*\*"),
    Rule("dd08_reach", "DD8 (impulse to reach a target velocity)",
         r"-\s*\(\s*\w+\s*-\s*\w+\s*\)\s*\*\s*\w*mass"),
    Rule("dd12_bounce", "DD12 (separating velocity -C_R v)",
         r"-\s*\w*restitution\w*\s*\*\s*\w+"),
    Rule("dd15_energy", "DD15 (kinetic energy)",
         r"0\.5\s*\*\s*[\w.]*(?:mass|inertia)\w*\s*\*\s*(?:dot\(|[\w.]+\s*\*\s*[\w.]+)"),
]

# (rule, path) -> reason, for a duplicate known and waiting; none today.
KNOWN = {}

_COMMENT_OR_STRING = re.compile(
    r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)


def strip_code(text):
    """Comments and literals blanked, newlines kept (so line numbers survive)."""
    def blank(m):
        s = m.group(0)
        if s.startswith('"') or s.startswith("'"):
            return '""'
        return re.sub(r"[^\n]", " ", s)
    return _COMMENT_OR_STRING.sub(blank, text)


def scan_text(path, text, rules=RULES):
    """Findings [(rule, path, line, excerpt)] in one file's text."""
    if path.startswith(MODEL_DIR):
        return []
    code = strip_code(text)
    out = []
    for r in rules:
        if path in r.allowed:
            continue
        for m in r.regex().finditer(code):
            line = code.count("\n", 0, m.start()) + 1
            excerpt = " ".join(m.group(0).split())
            out.append((r.name, path, line, excerpt))
    return out


def scan_tree(root, rules=RULES):
    findings = []
    for top in SCANNED:
        base = os.path.join(root, top)
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames.sort()
            for f in sorted(filenames):
                if not f.endswith(EXTENSIONS):
                    continue
                full = os.path.join(dirpath, f)
                rel = os.path.relpath(full, root).replace(os.sep, "/")
                with open(full, encoding="utf-8", errors="replace") as fh:
                    findings += scan_text(rel, fh.read(), rules)
    return findings


def judge(findings, known=KNOWN):
    """(new findings, known findings, stale known entries)."""
    new, old = [], []
    seen = set()
    for f in findings:
        key = (f[0], f[1])
        if key in known:
            old.append(f)
            seen.add(key)
        else:
            new.append(f)
    stale = sorted(k for k in known if k not in seen)
    return new, old, stale


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(__file__)))))
    ap.add_argument("--json", help="write the findings here")
    a = ap.parse_args(argv)
    new, old, stale = judge(scan_tree(a.root))
    items = {r.name: r.item for r in RULES}
    for rule, path, line, text in new:
        print(f"{path}:{line}: {items[rule]} written outside model/ [{rule}]: {text}")
    for rule, path, line, text in old:
        print(f"{path}:{line}: known [{rule}] ({KNOWN[(rule, path)]})")
    for rule, path in stale:
        print(f"stale KNOWN entry: [{rule}] {path} no longer matches; remove it")
    if a.json:
        with open(a.json, "w") as fh:
            json.dump({"rules": len(RULES), "new": new, "known": old, "stale": stale}, fh,
                      indent=1)
    ok = not new and not stale
    print(f"formula lint: {len(RULES)} rules, {len(new)} new, {len(old)} known, "
          f"{len(stale)} stale: {'pass' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
