"""The reference mutation analysis (verification/mutation/reference/mutation.json), as data.

The main job judges a seeded sample of the mutants in a few minutes; the whole analysis takes
many hours on two cores (docs/verification.md, "Mutation testing"). The reference is one run of
``mutate.py --all`` on a named commit, kept in the repository: every mutant of that tree when the
run finished, or, when it is still going, the seeded random sample it has judged so far (a whole
run judges in the seed's rank order). It is true of its commit: the report shows it beside the
checkout's own sample with the commit, the share of the mutants judged, and the target files
(src/tamias2d/model, src/tamias2d/dynamics) changed since, never as evidence of the checkout.

Its score is counted again here with the checkout's record of judged survivors
(verification/mutation/survivors.json), so a survivor judged after the run counts as judged.
A gap that a later test kills keeps its record (it judges the reference's tree, which lacks the
test) and names that test (closed_by); the report looks each one up among its own run's tests,
and counts the gap closed only where every test it names passed in that run.
"""
from __future__ import annotations

import collections
import os
import re
import sys

from traceability import evidence, reference_runs


def _mutate(source):
    sys.path.insert(0, os.path.join(source, "verification", "mutation"))
    import mutate  # noqa: E402  (the scoring rules live there, once)
    return mutate


# The reference's file and the mutated directories, as the tool names them.
_TOOL = _mutate(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REFERENCE = _TOOL.REFERENCE
TARGETS = _TOOL.TARGET_DIRS


def collect(source, warnings, tests=None):
    """The reference's figures, or None when the checkout keeps none. tests: the report's
    tests of this run ({id, status}), for the gaps that name the tests closing them; None
    when the report ran none (each such gap is then counted open, its tests "not run")."""
    doc = reference_runs.read(source, REFERENCE, ["mutants"], warnings)
    if doc is None:
        return None
    rows = doc["mutants"]
    prov = doc.get("provenance") or {}
    mutate = _mutate(source)
    try:
        judgements = mutate.load_judgements(os.path.join(source, "verification", "mutation",
                                                         "survivors.json"))
    except SystemExit as e:
        warnings.append(f"the survivors record is malformed ({e}); the reference is scored "
                        "without it")
        judgements = {}
    score, killed, equivalent, counted = mutate.score_of(rows, judgements)
    low, high = mutate.wilson(killed, counted)
    status_of = {t["id"]: t["status"] for t in tests or ()}
    ran = {t.get("binary") for t in tests or ()}
    survivors = []
    for r in rows:
        if r.get("verdict") != "survived":
            continue
        j = judgements.get(mutate.survivor_key(r)) or {}
        closing = [{"test": t, "status": status_of.get(t, "not run")}
                   for t in j.get("closed_by", ())]
        for c in closing:
            if c["status"] == "not run" and c["test"].split(":", 1)[0] in ran:
                warnings.append(f"survivors.json names {c['test']} as closing the gap at "
                                f"{r['file']}:{r['line']}, and its executable ran without such "
                                "a test")
        survivors.append({"file": r["file"], "line": r["line"], "op": r["op"],
                          "before": r["before"].strip(), "occurrence": r["occurrence"],
                          "judgement": j.get("verdict", "not judged"),
                          "reason": j.get("reason", ""), "closed_by": closing,
                          "closed": bool(closing) and all(c["status"] == "passed"
                                                          for c in closing)})
    judged = len(rows)
    population = doc.get("population") or judged
    complete = bool(doc.get("complete"))
    floor_on, floor_met = mutate.floor_verdict(score, low, counted, complete)
    commit = prov.get("commit")
    changed = reference_runs.changed_since(source, commit, TARGETS) if commit else None
    counts = dict(collections.Counter(r.get("verdict") for r in rows))
    return {
        "file": REFERENCE,
        "commit": commit,
        "dirty": bool(prov.get("dirty")),
        "generated": prov.get("generated"),
        "started": prov.get("built"),
        "build": prov.get("build"),
        "selection": doc.get("selection"),
        "judged": judged,
        "population": population,
        "complete": complete,
        "verdicts": counts,
        "killed": killed,
        "killed_by_sanitizer": sum(r.get("killed_by") == "sanitizer" for r in rows),
        "equivalent": equivalent,
        "counted": counted,
        "score": score,
        "interval": [low, high],
        "confidence": mutate.CONFIDENCE,
        "floor": mutate.FLOOR,
        "floor_applies_to": floor_on,
        "floor_met": floor_met,
        "gaps": sum(s["judgement"] == "gap" for s in survivors),
        "gaps_closed": sum(s["judgement"] == "gap" and s["closed"] for s in survivors),
        "not_judged": sum(s["judgement"] == "not judged" for s in survivors),
        "survivors": survivors,
        "seconds_per_mutant": doc.get("seconds_per_mutant"),
        "changed_since": changed,
    }


SUITE = re.compile(r"^\s*BOOST_AUTO_TEST_SUITE\s*\(\s*([A-Za-z_]\w*)")
SUITE_END = re.compile(r"^\s*BOOST_AUTO_TEST_SUITE_END\s*\(")
EXECUTABLE = re.compile(r"^\s*tamias_add_boost_test\s*\(\s*([A-Za-z_][\w-]*)")


def declared_tests(source):
    """The report's ids (executable:suite/case) of the test cases declared in the checkout's
    sources: a file's cases belong to the executables (tamias_add_boost_test) of the nearest
    CMakeLists.txt above it under tests/ that names any, each case to its suites' path."""
    out = set()
    base = os.path.join(source, "tests")
    exes_of = {}
    for root, _dirs, files in os.walk(base):
        exes = []
        if "CMakeLists.txt" in files:
            with open(os.path.join(root, "CMakeLists.txt"), encoding="utf-8") as fh:
                exes = [m.group(1) for m in map(EXECUTABLE.match, fh) if m]
        # os.walk lists a directory before those under it: the parent's are known.
        exes_of[root] = exes or exes_of.get(os.path.dirname(root), [])
        for name in files:
            if not name.endswith(".cpp"):
                continue
            with open(os.path.join(root, name), encoding="utf-8", errors="replace") as fh:
                stack = []
                for line in fh:
                    if m := SUITE.match(line):
                        stack.append(m.group(1))
                    elif SUITE_END.match(line) and stack:
                        stack.pop()
                    elif m := evidence.TEST_MACRO.match(line):
                        path = "/".join(stack + [m.group(2)])
                        out.update(f"{exe}:{path}" for exe in exes_of[root])
    return out


def undeclared_closing_tests(source):
    """The closed_by tests of the checkout's survivors record that its sources do not
    declare: a record naming a renamed or removed test."""
    mutate = _mutate(source)
    judgements = mutate.load_judgements(os.path.join(source, "verification", "mutation",
                                                     "survivors.json"))
    declared = declared_tests(source)
    return sorted({t for j in judgements.values() for t in j.get("closed_by", ())
                   if t not in declared})


def judgement_text(s):
    """A survivor's judgement as both renderings show it: with the tests that close a gap at
    the checkout and their status in this run."""
    if not s.get("closed_by"):
        return s["judgement"]
    tests = "; ".join(f"{c['test']} ({c['status']})" for c in s["closed_by"])
    closed = "closed" if s["closed"] else "not closed"
    return f"{s['judgement']}, {closed} at the checkout by {tests}"


def summary(ref):
    """One sentence on the reference, for both renderings."""
    pct = lambda x: f"{100.0 * x:.1f} %"  # noqa: E731
    what = ("every mutant" if ref["complete"] else
            f"{ref['judged']} of {ref['population']} mutants, a seeded random sample "
            "(the run judges in the seed's rank order and had not finished)")
    changed = ref["changed_since"]
    since = reference_runs.since_text(changed, "the mutated files")
    return (f"Commit {str(ref['commit'])[:12]}{' (dirty)' if ref['dirty'] else ''}, "
            f"{ref['generated']}: {what}; {ref['killed']} of {ref['counted']} counted mutants "
            f"killed ({pct(ref['score'])}, {round(100 * ref['confidence'])} % Wilson interval "
            f"{pct(ref['interval'][0])}-{pct(ref['interval'][1])}); survivors: "
            f"{ref['equivalent']} judged equivalent, {ref['gaps']} judged gaps "
            f"({ref['gaps_closed']} closed at the checkout by tests that passed in this run, "
            f"{ref['gaps'] - ref['gaps_closed']} open), {ref['not_judged']} not yet judged. "
            f"The {pct(ref['floor'])} floor, on the {ref['floor_applies_to']}: "
            f"{'met' if ref['floor_met'] else 'not met'}. True of its commit: {since}.")
