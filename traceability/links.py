"""The strength of each trace link (item, test), computed from declared facts.

A label on a test claims that the test exercises Tamias2D's implementation of the item against
an oracle independent of the code under test. Whether a link can bear that claim is computed
here from facts the harness already has, never typed by hand:

* the kinds of oracle the test's oracle statement names (analysis.ORACLE_KINDS): closed form,
  stated rule, GSL reference, conservation law, an independent implementation or property are
  independent of the code; so is the SRS's model ("SRS model": the statement names another
  item's law, or the item's own when the engine or a component is checked, not its module);
  a peer engine is
  independent only where the item itself is a comparison with that peer (NFR1); a golden
  value, an unplaced or a missing oracle is not;
* what the test drives, from where it lives: a model function alone (tests/model/), a library
  component below the world (tests/geometry/, tests/collision/), the scene reader (tests/io/),
  a whole World (the other Boost.Test suites), the command line (CTest entries of apps/), a
  verification program's run of the engine, or the repository's history;
* whether the statement names a tolerance or an exactness (a number, "exact", "bitwise",
  "ulp", "to the printed rounding").

A link is *strong* when its oracle is independent and the test drives the item's
implementation at a level that can show it right: a requirement on the software (R, NFR) needs
the world, the command or a program, not a model function alone; a model item (TM, GD, DD, IM)
may be shown on its module or through the engine, except that one the engine does not evaluate
(srs/ `engine: model-only`) only on its module. Every other link is *weak*, with its reasons.
An item with no strong link is flagged; the report publishes a seeded sample of links with their
facts, for a reviewer to judge against the grades.
"""
from __future__ import annotations

import hashlib
import re

INDEPENDENT = {"closed form", "stated rule", "GSL reference", "conservation law",
               "independent implementation", "property"}
REQUIREMENT_KINDS = {"R", "NFR"}
MODEL_KINDS = {"TM", "GD", "DD", "IM"}
SOFTWARE_LEVELS = {"world", "command", "program"}
# The requirements on receiving and checking input (R2-R4) may also be shown on the scene
# reader, the library's other way in.
INPUT_REQUIREMENTS = {"R2", "R3", "R4"}
TOLERANCE = re.compile(r"\d(?:\.\d+)?e-?\d+|\bexact|bitwise|\bulp\b|to the printed|\btolerance\b|"
                       r"\bwithin\b|\bto \d|%|\bequal", re.I)

# Verification programs: what each one's checks drive.
PROGRAM_LEVELS = {"likely_change_cost": "history", "main_job": "history"}


def level_of(test):
    """What the test drives (see the module's docstring)."""
    origin = test.get("origin")
    f = str(test.get("file") or "")
    if origin == "verification":
        return PROGRAM_LEVELS.get(str(test.get("binary")), "program")
    if origin == "ctest":
        if f.startswith(("apps/", "examples/")) or "cli" in (test.get("labels") or []):
            return "command"
        return "build"
    parts = f.split("/")
    area = parts[1] if len(parts) > 2 and parts[0] == "tests" else ""
    level = {"model": "model", "geometry": "component", "collision": "component",
             "io": "scene reader"}.get(area, "world")
    # A scene-file test that builds or steps a World drives the engine through its input path.
    if level == "scene reader" and test.get("drives_world"):
        return "world"
    return level


# An oracle that names an SRS model item (its statement or formula) rests on the SRS itself.
SRS_MODEL = re.compile(r"\b(T[1-5]|GD\d|DD\d{1,2}|IM\d)\b")


def grade(item, test, peer_reference=False):
    """(grade, reasons, facts) of one link."""
    kinds = set(test.get("oracle_kinds") or [])
    level = level_of(test)
    # The SRS's model is independent of the code that realises it: another item's law checks
    # this item anywhere, and an item's own statement checks the engine and its components
    # (not the item's own module, whose test could be reading the formula back).
    named = set(SRS_MODEL.findall(str(test.get("oracle") or "")))
    label = item.get("label")
    srs_model = bool(named - {label}) or (label in named and level != "model")
    if srs_model:
        kinds = (kinds - {"other"}) | {"SRS model"}
    independent = bool(kinds & INDEPENDENT) or srs_model or (peer_reference and "peer" in kinds)
    tolerance = bool(test.get("oracle")) and bool(TOLERANCE.search(str(test["oracle"])))
    reasons = []
    if not test.get("oracle"):
        reasons.append("states no oracle")
    elif not independent:
        reasons.append("its oracle (" + ", ".join(sorted(kinds)) + ") is not independent of "
                       "the code under test")
    software = SOFTWARE_LEVELS | ({"scene reader"} if item.get("label") in INPUT_REQUIREMENTS
                                  else set())
    if item["kind"] in REQUIREMENT_KINDS and level not in software and level != "history":
        reasons.append(f"a requirement on the software shown on the {level} alone")
    if item.get("engine") == "model-only" and level != "model":
        reasons.append(f"the engine does not evaluate {label} (srs/ engine: model-only): a test "
                       f"at the {level} level is not its verification")
    facts = {"oracle_kinds": sorted(kinds), "level": level, "tolerance_stated": tolerance}
    return ("weak" if reasons else "strong"), reasons, facts


def grade_all(items_by_label, tests, peer_reference):
    """Grades every (item, test) link. Returns {(label, test id): {...}}."""
    out = {}
    for t in tests:
        for lab in t.get("srs_labels") or []:
            it = items_by_label.get(lab)
            if it is None:
                continue
            g, reasons, facts = grade(it, t, lab in peer_reference)
            out[(lab, t["id"])] = {"item": lab, "test": t["id"], "grade": g, "reasons": reasons,
                                   **facts}
    return out


def sample(links, n, seed):
    """n links drawn by a hash of the seed and each link's names: the same seed gives the same
    sample, and a link's draw does not depend on which other links exist."""
    ranked = sorted(links, key=lambda ln: hashlib.sha256(
        f"{seed}\x1f{ln['item']}\x1f{ln['test']}".encode()).hexdigest())
    return ranked[:n]
