"""The reference module reach (verification/model_reach/reference/module_reach.json), as data.

The main job perturbs the damping pair only; every module's perturbations take hours on two
cores (docs/verification.md, section 11). The reference is one run of ``module_reach.py`` over
every module on a named commit, kept in the repository (``--resume`` lets it run in several
parts; while it is still going, the file kept is the part judged so far and says so). Like
the mutation reference it is true of its commit: the report shows it with the commit, how many
perturbations were judged, the items not as srs/ states, and the model modules changed in the
checkout since, never as evidence of the checkout.
"""
from __future__ import annotations

import collections
import os

from traceability import reference_runs

REFERENCE = os.path.join("verification", "model_reach", "reference", "module_reach.json")
MODEL_DIR = "src/tamias2d/model"


def collect(source, warnings):
    """The reference's figures, or None when the checkout keeps none."""
    doc = reference_runs.read(source, REFERENCE, ["perturbations", "items", "checks"], warnings)
    if doc is None:
        return None
    rows, items = doc["perturbations"], doc["items"]
    prov = doc.get("provenance") or {}
    judged_check = next((c for c in doc["checks"] if isinstance(c, dict)
                         and c.get("name") == "every perturbation chosen was judged"), {})
    commit = prov.get("commit")
    changed = reference_runs.changed_since(source, commit, [MODEL_DIR]) if commit else None
    modules = {r["module"] for r in rows}
    return {
        "file": REFERENCE,
        "commit": commit,
        "dirty": bool(prov.get("dirty")),
        "generated": prov.get("generated"),
        "judged": len(rows),
        "judged_of_chosen": judged_check.get("details", ""),
        "complete": bool(judged_check.get("passed")),
        "results": dict(collections.Counter(r["result"] for r in rows)),
        "items": [{"label": s["label"], "modules": s["modules"], "expected": s["expected"],
                   "results": s["results"], "as_expected": s["as_expected"],
                   "perturbations": s["perturbations"]} for s in items],
        "not_as_expected": [s["label"] for s in items if not s["as_expected"]],
        "changed_since": None if changed is None else
        sorted(c for c in changed if os.path.basename(c) in modules),
    }


def summary(ref):
    """One sentence on the reference, for both renderings."""
    changed = ref["changed_since"]
    since = reference_runs.since_text(changed, "its perturbed modules")
    res = ", ".join(f"{n} {k}" for k, n in sorted(ref["results"].items()))
    off = ref["not_as_expected"]
    return (f"Commit {str(ref['commit'])[:12]}{' (dirty)' if ref['dirty'] else ''}, "
            f"{ref['generated']}: {ref['judged_of_chosen'] or ref['judged']} perturbations judged"
            f"{'' if ref['complete'] else ' (the run had not finished)'}: {res}; "
            + (f"not as srs/ states: {', '.join(off)}" if off else "every item as srs/ states")
            + f". True of its commit: {since}.")
