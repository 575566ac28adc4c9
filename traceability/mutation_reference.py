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
"""
from __future__ import annotations

import collections
import os
import sys

from traceability import reference_runs

REFERENCE = os.path.join("verification", "mutation", "reference", "mutation.json")
TARGETS = ("src/tamias2d/model", "src/tamias2d/dynamics")


def _mutate(source):
    sys.path.insert(0, os.path.join(source, "verification", "mutation"))
    import mutate  # noqa: E402  (the scoring rules live there, once)
    return mutate


def collect(source, warnings):
    """The reference's figures, or None when the checkout keeps none."""
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
    survivors = []
    for r in rows:
        if r.get("verdict") != "survived":
            continue
        j = judgements.get(mutate.survivor_key(r)) or {}
        survivors.append({"file": r["file"], "line": r["line"], "op": r["op"],
                          "before": r["before"].strip(), "occurrence": r["occurrence"],
                          "judgement": j.get("verdict", "not judged"),
                          "reason": j.get("reason", "")})
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
        "not_judged": sum(s["judgement"] == "not judged" for s in survivors),
        "survivors": survivors,
        "seconds_per_mutant": doc.get("seconds_per_mutant"),
        "changed_since": changed,
    }


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
            f"{ref['equivalent']} judged equivalent, {ref['gaps']} judged gaps, "
            f"{ref['not_judged']} not yet judged. The {pct(ref['floor'])} floor, on the "
            f"{ref['floor_applies_to']}: {'met' if ref['floor_met'] else 'not met'}. "
            f"True of its commit: {since}.")
