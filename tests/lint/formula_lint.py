#!/usr/bin/python3
"""One formula, one place: fails when an SRS formula is written again outside src/tamias2d/model/.

Every SRS formula lives in one model module (docs/design.md, "One formula, one place"); the
engine calls it through the adapters of dynamics/bridge/ or the model's plain-double forms. This lint
reads the library's C++ (src/, include/, apps/; comments and string literals removed) and
flags each rule's pattern, a hand-written shape of one formula, anywhere but the file allowed to
hold it. A rule with a home (the module that owns its formula) reads model/ too, so that a
module writing another's formula again, instead of calling it, is flagged; one marked
`everywhere` reads every module (a form no module may write); the others leave model/ alone.
Tests are not read: they write their oracles independently on purpose.

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
    # The model modules that own the formula. A rule with a home reads model/ too: the formula
    # written again in another module (which should call the home's) is flagged as well.
    home: tuple = ()
    # Reads model/ without a home: a form no module may write (the formula derived otherwise).
    everywhere: bool = False

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
    Rule("dd08_reach", "DD8 (impulse to reach a target velocity)",
         r"-\s*\(\s*\w+\s*-\s*\w+\s*\)\s*\*\s*\w*mass"),
    Rule("dd12_bounce", "DD12 (separating velocity -C_R v)",
         r"-\s*\w*restitution\w*\s*\*\s*\w+"),
    Rule("dd15_energy", "DD15 (kinetic energy)",
         r"0\.5\s*\*\s*[\w.]*(?:mass|inertia)\w*\s*\*\s*(?:dot\(|[\w.]+\s*\*\s*[\w.]+)"),
    # Read in model/ too: each formula's own module is its home.
    Rule("im3_jumps", "IM3 (velocity jumps of an impulse, DD10's J / m)",
         r"\.(?:v|w|omega)\s*[-+]=\s*\w+\.inv_(?:m|I|mass|inertia)\s*\*",
         home=(MODEL_DIR + "im3_collision_response.hpp",)),
    Rule("dd17_dd18_damping", "DD17/DD18 (damping acceleration -c v)",
         r"-\s*\(\s*[\w.]*(?:c_v|c_omega|damping)\w*\s*\*\s*[\w.]+\s*\)",
         home=(MODEL_DIR + "dd17_linear_damping.hpp", MODEL_DIR + "dd18_angular_damping.hpp")),
    Rule("im5_decay_rate", "IM5 (the decay factor from the rate itself, not DD17/DD18's slope)",
         r"1\.0\s*/\s*\(\s*1\.0\s*\+\s*[\w.]+\s*\*\s*[\w.]+\s*\)", everywhere=True),
    Rule("dd29_motion_bound", "DD29 (the motion bound |dp| + |dphi| r_max)",
         r"\+\s*(?:std::)?(?:abs|fabs)\([^()]*\)\s*\*\s*[\w.]*(?:reach|radius|r_max)\b",
         home=(MODEL_DIR + "dd29_time_of_impact.hpp",)),
    Rule("dd29_sweep", "DD29 (a pose or velocity at the fraction t of the step, x0 + t (x1 - x0))",
         r"\b(?:\w+\.)?(?:c0|a0|v0|w0)\s*\+\s*t\s*\*\s*\(",
         home=(MODEL_DIR + "dd29_time_of_impact.hpp",)),
    Rule("dcx_shape_area", "DCX_shape (a polygon's or triangle's area, the shoelace sum)",
         r"\b\w*(?:area|twice)\w*\s*\+=\s*cross\(|0\.5\s*\*\s*cross\(",
         home=(MODEL_DIR + "dcx_shape_non_degenerate_shapes.hpp",)),
    Rule("im7_target", "IM7 (a point's target velocity: speculative -s/h, push-out bias)",
         r"-\s*\w+\s*\*\s*(?:broadcast<\w+>\(\s*)?[\w.]*\binv_h\b|[\w.]*bias_rate\)?\s*\*\s*min\("
         r"|\{\s*\w+\s*/\s*h\s*,\s*1\.0\s*,\s*0\.0\s*\}",
         home=(MODEL_DIR + "im7_soft_contact.hpp",)),
    Rule("im7_two_point", "IM7 (the two-point complementarity solve, LC1)",
         r"\bk12\s*\*\s*[\w.()]+\s*\+\s*b[12]\b|-\s*\(\s*[\w.]*inv_?(?:k_?)?11\s*\*\s*b1\b"
         r"|-\s*\(\s*[\w.]*k11\s*\*\s*\w+\s*\+\s*[\w.]*k12\s*\*",
         home=(MODEL_DIR + "im7_soft_contact.hpp",)),
    Rule("im6_bias", "IM6 (a joint's biased velocity error Cdot + beta C)",
         r"[\w.]*bias_rate\s*\*\s*[\w.(]|\brate\s*\*\s*(?:current_joint_angle\b|c\b)",
         home=(MODEL_DIR + "im6_motion_with_joints.hpp", MODEL_DIR + "im7_soft_contact.hpp")),
    Rule("im6_reaction", "IM6 (a joint's reaction force, its impulse over the substep)",
         r"(?:impulse|reaction)\w*\([^;{}]*\)\s*\*\s*[\w.>-]*\binv_h\b",
         home=(MODEL_DIR + "im6_motion_with_joints.hpp",)),
    Rule("im6_im7_soft_impulse", "IM6/IM7 (the soft impulse's relaxed share)",
         r"\bimpulse_scale\s*\*\s*[\w.]*accumulated|accumulated[\w.]*\s*\*\s*[\w.]*impulse_scale",
         home=(MODEL_DIR + "im7_soft_contact.hpp",)),
    Rule("dd26_correction_rate", "DD26 (the correction rate c / h)",
         r"\bcorrection\w*\s*/\s*h\b", home=(MODEL_DIR + "dd26_motor_constraint.hpp",)),
    Rule("joint_impulse_bound", "DD21/DD22 (a joint's impulse bound F_max h, tau_max h)",
         r"\bmax_(?:force|motor|torque)\s*\*\s*h\b",
         home=(MODEL_DIR + "dd21_target_constraint.hpp",
               MODEL_DIR + "dd22_angular_constraint.hpp")),
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
    """Findings [(rule, path, line, excerpt)] in one file's text. In model/, only the rules with
    a home read it, and not in their home."""
    in_model = path.startswith(MODEL_DIR)
    code = strip_code(text)
    out = []
    for r in rules:
        if path in r.allowed or (in_model and (not (r.home or r.everywhere) or path in r.home)):
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
