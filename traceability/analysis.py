"""Join SRS items with code sites and tests; compute statuses, gaps, orphans, matrices, gate."""
from __future__ import annotations

import os
import re

import yaml

from . import links as linkgrades
from .srsdata import KIND_NAMES, KIND_ORDER, natural_key

STATUSES = ["verified", "goal met", "failing", "goal missed", "model only", "untested",
            "assumed", "not testable", "not implemented"]
# A model item (TM, GD, DD, IM) marked `engine: model-only` in srs/ is one whose formula the
# engine does not evaluate (its engine_reason says why; verification/model_reach/ checks that
# perturbing its module goes unnoticed by the engine's tests). Only the tests of its module
# (tests/model/) count for it: passing, it is "model only", never "verified" by an engine test.
# One marked `engine: property` is not evaluated by the engine either, but is a law the engine's
# results must satisfy: engine-level tests that check them with their own oracle count as usual.
MODEL_ONLY = "model-only"
PROPERTY = "property"
# A requirement whose obligation is "should" (srs/: the SRS's own verb) is a goal: measured and
# shown with its figure, judged "goal met" or "goal missed", never a gate failure. A check that
# only such items label is "goal-missed" when it fails; "shall" items gate as before.
GOAL_OBLIGATION = "should"
# Statuses an item without labelled tests may be given by config.yaml's `without_tests`, each
# with its reason: what the item is, instead of "untested" where no test could verify it.
# "untested" with a reason: a test exists in principle (a protocol) but has not been run.
DECLARED_STATUSES = ("assumed", "not testable", "untested")

# The kinds of oracle a test's evidence rests on, recognised in its oracle statement (first
# match of each kind; a test may rest on several). Order is the display order.
ORACLE_KINDS = [
    ("closed form", r"closed[- ]form|hand derivation|derived (?:by hand|here)|by hand|analytic|"
                    r"exact(?:ly)?\b|elliptic|written (?:here|in the test) from|hand-made|"
                    r"hand-written|\bhand (?:values?|cases?|geometry|points|truth table)|"
                    r"the srs text|formula|statics|oscillator|textbook|\bidentit|"
                    r"\bdefinition|dimensional analysis|\bgeometry\b|derivation|hooke's law|"
                    r"\bt1 at rest|voronoi|arithmetic series|defining (?:relation|integral)|"
                    r"\bode\b|parallel-axis|kinematics|symmetr|additiv|equivalence principle|"
                    r"transcribed|written out here|\blimits?\b of|superposition"),
    ("stated rule", r"srs table|\btable [12]\b|\bdc[iox]_\w+|data_constraints|scene-format\.md|"
                    r"\bstated (?:rules?|timing|order|convention)|\bthe (?:documented|stated)\b|"
                    r"\bcontract\b|\bconvention\b|\brfc \d+|srs data constraints|"
                    r"\bspecification\b|the handle rule|user-guide\.md|world\.hpp|"
                    r"\bprecondition\b|data constraints|the scene text|json syntax|"
                    r"\bthe seed's range"),
    ("GSL reference", r"\bgsl\b|rk8pd|reference solution"),
    ("conservation law", r"conserv(?!ative)|\bgd1\b"),
    ("independent implementation", r"brute[- ]force|written in the test|a plain [\w ]+ test|"
                                   r"direct (?:particle )?sums|std::\w+ fed the same|"
                                   r"\bindependent implementation\b"),
    ("property", r"propert|\bbound\b|bounded|never|invariant|promise|monoton|"
                 r"rigidity|keeps its shape|the derivation's corners|determinism by construction|"
                 r"same inputs?,? (?:give|same)"),
    ("peer", r"chipmunk|box2d|\bpeer\b|pymunk"),
    ("regression", r"golden(?!-section)|committed (?:value|hash|file)|previous run"),
]
# Evidence that cannot on its own show Tamias2D right: agreement with another engine, with its
# own earlier output, or an oracle the harness cannot place.
WEAK_ORACLE_KINDS = {"peer", "regression", "other", "unstated"}


def oracle_kinds(text):
    """The kinds of oracle an oracle statement names ("unstated" when there is none)."""
    if not text:
        return ["unstated"]
    low = str(text).lower()
    kinds = [k for k, pat in ORACLE_KINDS if re.search(pat, low)]
    return kinds or ["other"]
# Kinds that must be verified for the gate (exit status) to pass.
GATED_KINDS = ["TM", "GD", "DD", "IM", "R"]
# Kinds with nothing to implement: evidence can only come from tests labelled with them.
LABEL_ONLY_KINDS = {
    "GS": "Goal statements are verified only by tests labelled with the goal itself; the "
          "harness does not infer a goal's status from the items it uses.",
    "A": "Assumptions are verified only by tests labelled with the assumption (e.g. tests that "
         "check the library enforces or documents the simplification).",
    "NFR": "Non-functional requirements are verified only by tests or verification checks "
           "labelled with them (benchmarks, peer comparisons, usability studies).",
    "UC": "Unlikely changes describe the design's stability; they are verified only by tests "
          "labelled with them.",
    "LC": "Likely changes are verified only by tests labelled with them (e.g. a test that the "
          "extension point exists).",
    "DC": "Data constraints are verified by tests labelled with them (input validation).",
}
FAILING = ("failed", "error")


def load_config(path):
    cfg = {"category_labels": []}
    if path and os.path.exists(path):
        with open(path, encoding="utf-8") as fh:
            cfg.update(yaml.safe_load(fh) or {})
    return cfg


def item_status(code_sites, tests, kind=None, declared=None, model_only=False):
    passed = [t for t in tests if t["status"] == "passed"]
    failing = [t for t in tests if t["status"] in FAILING]
    if failing:
        return "failing"
    if model_only:
        # Engine-level tests do not verify what the engine does not evaluate.
        return "model only" if any(linkgrades.level_of(t) == "model" for t in passed) \
            else "untested"
    if passed:
        return "verified"
    # Declared only for items no test can verify, and only while no labelled test exists.
    if declared and not tests:
        return declared
    # An assumption, goal or change is never "implemented": without a test it is untested.
    if code_sites or tests or kind in LABEL_ONLY_KINDS:
        return "untested"
    return "not implemented"


def declared_statuses(config, labels, warnings=None):
    """config.yaml's without_tests: {label: {status, reason}} (checked)."""
    out = {}
    for lab, d in (config.get("without_tests") or {}).items():
        ok = isinstance(d, dict) and d.get("status") in DECLARED_STATUSES and d.get("reason")
        if not ok or lab not in labels:
            if warnings is not None:
                warnings.append(f"config.yaml without_tests: {lab!r} ignored (needs an SRS label, "
                                f"status one of {', '.join(DECLARED_STATUSES)} and a reason)")
            continue
        out[lab] = {"status": d["status"], "reason": str(d["reason"])}
    return out


def analyse(srs, code_sites, tests, config, warnings=None):
    labels = set(srs.items)
    declared = declared_statuses(config, labels, warnings)
    # Items whose requirement is itself a comparison with a peer (NFR1's time ratio): there the
    # peer's figure is the reference the item names, not a stand-in for the model.
    peer_reference = {k: str(v) for k, v in (config.get("peer_is_the_reference") or {}).items()
                      if k in labels and v}
    for t in tests:
        t["oracle_kinds"] = oracle_kinds(t.get("oracle"))
    inherit_oracle_kinds(tests)
    category = set(config.get("category_labels") or [])
    sites_by = {}
    for s in code_sites:
        sites_by.setdefault(s["label"], []).append(s)
    goals = {lab for lab, it in srs.items.items() if it.get("obligation") == GOAL_OBLIGATION}
    tests_by = {}
    for t in tests:
        t["srs_labels"] = [x for x in t["labels"] if x in labels]
        if t["status"] == "failed" and t["srs_labels"] and set(t["srs_labels"]) <= goals:
            t["status"] = "goal-missed"
        for x in t["srs_labels"]:
            tests_by.setdefault(x, []).append(t)

    link_grades = linkgrades.grade_all(srs.items, tests, peer_reference)
    items = []
    for lab in srs.order:
        it = srs.items[lab]
        sites = sites_by.get(lab, [])
        its_tests = sorted(tests_by.get(lab, []), key=lambda t: (t["status"] not in FAILING, t["id"]))
        decl = declared.get(lab)
        model_only = it.get("engine") == MODEL_ONLY
        status = item_status(sites, its_tests, it["kind"], decl["status"] if decl else None,
                             model_only)
        if lab in goals and status != "failing":
            if any(t["status"] == "goal-missed" for t in its_tests):
                status = "goal missed"
            elif status == "verified":
                status = "goal met"
        notes = []
        if decl and status == decl["status"]:
            notes.append(f'{decl["status"]}: {decl["reason"]}')
        elif decl:
            notes.append(f'Declared {decl["status"]} in config.yaml, but labelled tests exist: '
                         f'their results decide.')
        kinds = sorted({k for t in its_tests if t["status"] == "passed" for k in t["oracle_kinds"]},
                       key=_kind_order)
        # Evidence is weak when no passing link is strong (links.py grades each link).
        grades = [link_grades[(lab, t["id"])] for t in its_tests if (lab, t["id"]) in link_grades]
        strong = [g for g in grades if g["grade"] == "strong" and
                  next(t for t in its_tests if t["id"] == g["test"])["status"] in
                  ("passed", "goal-missed")]
        weak = status in ("verified", "goal met", "goal missed", "model only") and not strong
        if model_only:
            notes.append("Model only: the engine does not evaluate this item's formula (srs/ "
                         f"engine: model-only): {it.get('engine_reason')} Its module's tests "
                         "verify it; tests beyond the module do not count.")
        elif it.get("engine") == PROPERTY:
            notes.append("A property of the engine's results: the engine does not evaluate this "
                         f"item's formula (srs/ engine: property): {it.get('engine_reason')}")
        if lab in peer_reference and "peer" in kinds:
            notes.append("A peer's figure is this item's own reference, not weak evidence: " +
                         peer_reference[lab])
        if weak:
            notes.append("Weak evidence: no passing link is strong (an independent oracle on "
                         "the item's implementation at a level that can show it right; the "
                         "links' grades say why each is weak).")
        # A trace link must say why it verifies the item: a labelled test that names no oracle
        # is weak evidence whatever the others show.
        unstated = [t["id"] for t in its_tests if not t.get("oracle")]
        if unstated:
            notes.append(f"Weak evidence: {len(unstated)} labelled test(s) state no oracle: " +
                         ", ".join(unstated) + ".")
        if it["kind"] in LABEL_ONLY_KINDS:
            notes.append(LABEL_ONLY_KINDS[it["kind"]])
        lib_sites = [s for s in sites if s["area"] in ("library", "application")]
        if sites and not lib_sites:
            notes.append("Tagged only outside the library (" +
                         ", ".join(sorted({s['area'] for s in sites})) + "): no src/ or apps/ code names it.")
        skipped = [t for t in its_tests if t["status"] in ("skipped", "notrun")]
        if skipped:
            notes.append(f"{len(skipped)} labelled test(s) did not run (skipped/disabled/not run).")
        if status == "verified" and not sites and it["kind"] in GATED_KINDS:
            notes.append("Verified by tests, but no code carries its \\srs tag.")
        items.append({
            "label": lab, "kind": it["kind"], "alias": it.get("alias"), "title": it.get("title"),
            "status": status, "gated": it["kind"] in GATED_KINDS,
            "obligation": it.get("obligation"),
            "status_reason": (decl["reason"] if decl and status == decl["status"] else
                              it.get("engine_reason") if model_only else None),
            "engine": ("model only" if model_only else "property"
                       if it.get("engine") == PROPERTY else "engine"
                       if it["kind"] in linkgrades.MODEL_KINDS else None),
            "oracle_kinds": kinds, "weak_evidence": weak, "tests_without_oracle": unstated,
            "links": {g["test"]: {k: g[k] for k in ("grade", "reasons", "level",
                                                     "tolerance_stated")} for g in grades},
            "strong_links": len(strong), "weak_links": sum(g["grade"] == "weak" for g in grades),
            "code_sites": sites, "tests": [t["id"] for t in its_tests],
            "tests_passed": sum(t["status"] == "passed" for t in its_tests),
            "tests_failing": sum(t["status"] in FAILING for t in its_tests),
            "tests_other": len(skipped),
            "tests_goal_missed": sum(t["status"] == "goal-missed" for t in its_tests),
            "uses": it["uses"], "ref_by": srs.ref_by.get(lab, []),
            "seed_ref_by": it.get("seed_ref_by"), "errata": it.get("errata", []),
            "source": it.get("source"), "equation": it.get("equation"),
            "seed_equation": it.get("seed_equation"), "description": it.get("description"),
            "srs_notes": it.get("notes"), "symbols": it.get("symbols", []),
            "file": it.get("_file"), "notes": notes,
        })

    # Totals per kind.
    by_kind = {}
    for k in srs.kinds_present():
        row = {"kind": k, "name": KIND_NAMES.get(k, k), "total": 0}
        for s in STATUSES:
            row[s] = 0
        by_kind[k] = row
    by_status = {s: 0 for s in STATUSES}
    for i in items:
        by_kind[i["kind"]]["total"] += 1
        by_kind[i["kind"]][i["status"]] += 1
        by_status[i["status"]] += 1
    for row in by_kind.values():
        row["with_code"] = sum(1 for i in items if i["kind"] == row["kind"] and i["code_sites"])
        row["with_tests"] = sum(1 for i in items if i["kind"] == row["kind"] and i["tests"])
        row["verified_percent"] = round(100.0 * row["verified"] / row["total"], 1) if row["total"] else 0.0

    # Gaps (SRS -> evidence) and orphans (evidence -> SRS).
    gaps = {
        "weak_evidence": [i["label"] for i in items if i["weak_evidence"]],
        "unstated_oracle": [i["label"] for i in items if i["tests_without_oracle"]],
        "no_code": [i["label"] for i in items if not i["code_sites"]],
        "no_test": [i["label"] for i in items if not i["tests"]],
        "no_passing_test": [i["label"] for i in items if i["tests_passed"] == 0],
    }
    orphan_tags = [dict(s, alias_of=srs.aliases.get(s["label"])) for s in code_sites
                   if s["label"] not in labels]
    orphan_labels = {}
    category_use = {}
    for t in tests:
        for x in t["labels"]:
            if x in labels:
                continue
            target = category_use if x in category else orphan_labels
            target.setdefault(x, []).append(t["id"])
    orphans = {
        "code_tags": orphan_tags,
        "test_labels": [{"label": k, "alias_of": srs.aliases.get(k), "tests": v}
                        for k, v in sorted(orphan_labels.items(), key=lambda kv: natural_key(kv[0]))],
        "unlabelled_tests": [t["id"] for t in tests if not t["srs_labels"]
                             and not any(x in category for x in t["labels"])],
    }
    category_labels = [{"label": k, "tests": v} for k, v in sorted(category_use.items())]

    # Test totals.
    test_totals = {}
    for t in tests:
        o = test_totals.setdefault(t["origin"], {"total": 0})
        o["total"] += 1
        o[t["status"]] = o.get(t["status"], 0) + 1
    missing_oracle = [t["id"] for t in tests if not t.get("oracle")]
    # The ones that matter most: tests that claim an SRS item without saying how they know.
    missing_oracle_srs = [t["id"] for t in tests if not t.get("oracle") and t["srs_labels"]]

    # Gate.
    reasons = []
    failing_tests = [t for t in tests if t["status"] in FAILING]
    if failing_tests:
        reasons.append(f"{len(failing_tests)} test(s) or check(s) fail: " +
                       ", ".join(t["id"] for t in failing_tests[:12]) +
                       (" ..." if len(failing_tests) > 12 else ""))
    ungated = [i for i in items if i["gated"] and i["tests_passed"] == 0]
    if ungated:
        reasons.append(f"{len(ungated)} R/IM/TM/GD/DD item(s) have no passing test: " +
                       ", ".join(i["label"] for i in ungated))
    failing_items = [i for i in items if i["gated"] and i["status"] == "failing"]
    if failing_items:
        reasons.append(f"{len(failing_items)} R/IM/TM/GD/DD item(s) have failing tests: " +
                       ", ".join(i["label"] for i in failing_items))
    if not items:
        reasons.append("no SRS items were loaded")
    gate = {"passed": not reasons, "exit_code": 0 if not reasons else 1, "reasons": reasons,
            "gated_kinds": GATED_KINDS, "failing_tests": [t["id"] for t in failing_tests],
            "items_without_passing_test": [i["label"] for i in ungated],
            "items_with_failing_tests": [i["label"] for i in failing_items],
            # Not gate failures, but never hidden: Boost expected_failures(N) cases, each a
            # documented finding (docs/verification.md).
            "known_failures": [t["id"] for t in tests if t["status"] == "known-failure"],
            # Goals beyond the SRS (verification checks with a "target"), missed: listed, not gating.
            "targets_missed": [t["id"] for t in tests if t["status"] == "target-missed"],
            # The SRS's own goals ("should" requirements): each with its checks, met or missed.
            "goals": [{"label": i["label"], "status": i["status"],
                       "checks": [t["id"] for t in tests_by.get(i["label"], [])
                                  if t["status"] in ("passed", "goal-missed")]}
                      for i in items if i["label"] in goals],
            "goals_missed": [t["id"] for t in tests if t["status"] == "goal-missed"]}
    all_links = sorted(link_grades.values(), key=lambda g: (natural_key(g["item"]), g["test"]))
    link_summary = {"total": len(all_links),
                    "strong": sum(g["grade"] == "strong" for g in all_links),
                    "weak": sum(g["grade"] == "weak" for g in all_links)}
    return {"items": items, "by_kind": by_kind, "by_status": by_status, "gaps": gaps,
            "links": all_links, "link_summary": link_summary,
            "orphans": orphans, "category_labels": category_labels, "test_totals": test_totals,
            "missing_oracle": missing_oracle, "missing_oracle_srs": missing_oracle_srs,
            "gate": gate}


AS_REFERENCE = re.compile(r"^as (above|[\w.@:/-]+?)[,:]?(?:\s|$)", re.I)


def inherit_oracle_kinds(tests):
    """An oracle stated as "as above" or "as <test>" rests on the referenced test's oracle
    too: its kinds are added (the statement's own remain). "Above" is the test declared last
    before it in the same file."""
    by_file = {}
    for t in tests:
        if t.get("file") and t.get("line"):
            by_file.setdefault(t["file"], []).append(t)
    for ts in by_file.values():
        ts.sort(key=lambda t: t["line"])
    for t in tests:
        m = AS_REFERENCE.match(str(t.get("oracle") or ""))
        if not m:
            continue
        ref = None
        if m.group(1).lower() == "above":
            same = [u for u in by_file.get(t.get("file"), []) if u["line"] < (t.get("line") or 0)
                    and AS_REFERENCE.match(str(u.get("oracle") or "")) is None]
            ref = same[-1] if same else None
        else:
            name = m.group(1)
            ref = next((u for u in tests if u is not t and u.get("file") == t.get("file") and
                        (u["name"].rsplit("/", 1)[-1] == name or
                         u["name"].rsplit("/", 1)[-1].startswith(name + "_"))), None)
        if ref is not None:
            kinds = [k for k in t["oracle_kinds"] if k != "other"]
            kinds += [k for k in ref["oracle_kinds"] if k not in kinds]
            t["oracle_kinds"] = kinds or ["other"]
            t["oracle_refers_to"] = ref["id"]


def _kind_order(k):
    names = [n for n, _ in ORACLE_KINDS] + ["other", "unstated"]
    return names.index(k) if k in names else len(names)


# --------------------------------------------------------------------------- matrices
MATRIX_SPECS = [
    {"id": "table3", "number": 3, "rows": ["GS", "R"], "cols": ["IM", "R", "DC"],
     "caption": "Goal statements and requirements (rows) against the instance models, "
                "requirements and data constraints they use (columns)"},
    {"id": "table4", "number": 4, "rows": ["TM", "GD", "DD", "IM", "LC"], "cols": ["A"],
     "caption": "Theoretical models, general and data definitions, instance models and likely "
                "changes (rows) against the assumptions they use (columns)"},
    {"id": "table5", "number": 5, "rows": ["TM", "GD", "DD", "IM"], "cols": ["TM", "GD", "DD", "IM"],
     "caption": "Theoretical models, general and data definitions and instance models (rows) "
                "against the items of the same sections they use (columns)"},
]


def build_matrices(srs):
    out = []
    for spec in MATRIX_SPECS:
        rows = [lab for k in spec["rows"] for lab in srs.by_kind(k)]
        cols = [lab for k in spec["cols"] for lab in srs.by_kind(k)]
        colset = set(cols)
        cells = {r: [c for c in srs.items[r]["uses"] if c in colset] for r in rows}
        out.append(dict(spec, row_labels=rows, col_labels=cols, cells=cells,
                        empty_rows=[r for r in rows if not cells[r]],
                        empty_cols=[c for c in cols if not any(c in v for v in cells.values())]))
    return out


def load_seed_tables(path):
    if not path or not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as fh:
        return yaml.safe_load(fh)


def compare_seed(srs, matrices, seed):
    """Differences between the seed's hand-made tables and the regenerated ones."""
    if not seed:
        return []
    regen = {m["id"]: m for m in matrices}
    results = []
    for t in seed.get("tables", []):
        m = regen.get(t["id"])
        res = {"id": t["id"], "number": t.get("number"), "caption": t.get("caption"),
               "missing": bool(t.get("missing")), "notes": t.get("notes", []),
               "seed_lines": t.get("seed_lines"), "seed_columns": t.get("columns", []),
               "seed_rows": t.get("rows", []), "differences": [], "comparison": None}
        results.append(res)
        if t.get("missing") or m is None:
            continue
        groups = t.get("column_groups") or {}

        def data_mark(row, col):
            uses = srs.items[row]["uses"] if row in srs.items else []
            if col in groups:
                kind = groups[col].get("kind")
                return any(srs.items.get(u, {}).get("kind") == kind for u in uses)
            return col in uses

        diffs = res["differences"]
        seen_rows = set()
        unresolved = {}
        for r in t.get("rows", []):
            if r.get("unresolved"):
                key = (r.get("printed_as", r["label"]), tuple(r.get("marks") or []))
                unresolved[key] = unresolved.get(key, 0) + 1
        for (printed, marks), count in unresolved.items():
            times = f" ({count} rows)" if count > 1 else ""
            diffs.append({"row": printed, "column": None, "type": "unresolved seed row",
                          "detail": f"row printed as '{printed}'{times} with marks "
                                    f"{', '.join(marks) if marks else 'none'}: its label is lost in the "
                                    "seed text, so it cannot be compared"})
        for r in t.get("rows", []):
            lab = r["label"]
            if r.get("unresolved"):
                continue
            seen_rows.add(lab)
            if lab not in srs.items:
                diffs.append({"row": lab, "column": None, "type": "row not in SRS data",
                              "detail": f"the seed has a row {lab}, srs/ has no such item"})
                continue
            for c in t.get("columns", []):
                s = c in (r.get("marks") or [])
                d = data_mark(lab, c)
                if s and not d:
                    diffs.append({"row": lab, "column": c, "type": "only in seed",
                                  "detail": f"seed marks {lab} x {c}; srs/ {lab}.uses does not"})
                elif d and not s:
                    diffs.append({"row": lab, "column": c, "type": "only in data",
                                  "detail": f"srs/ {lab}.uses gives {lab} x {c}; the seed has no mark"})
            # Marks in regenerated columns the seed table does not have at all.
            extra = [c for c in m["cells"].get(lab, []) if c not in t.get("columns", [])
                     and not any(srs.items[c]["kind"] == g.get("kind") for g in groups.values())]
            for c in extra:
                diffs.append({"row": lab, "column": c, "type": "column absent from seed",
                              "detail": f"srs/ {lab}.uses gives {lab} x {c}; the seed table has no column {c}"})
        for lab in m["row_labels"]:
            if lab not in seen_rows:
                diffs.append({"row": lab, "column": None, "type": "row absent from seed",
                              "detail": f"{lab} is an SRS item of a row kind but has no row in the seed table"
                                        + (f" (uses {', '.join(m['cells'][lab])})" if m["cells"][lab] else "")})
        # Side-by-side comparison matrix over the union of rows/columns.
        rows = [r["label"] for r in t.get("rows", []) if not r.get("unresolved")]
        rows += [x for x in m["row_labels"] if x not in rows]
        cols = list(t.get("columns", []))
        grouped_kinds = {g.get("kind") for g in groups.values()}
        cols += [c for c in m["col_labels"] if c not in cols and srs.items[c]["kind"] not in grouped_kinds]
        seedmarks = {r["label"]: set(r.get("marks") or []) for r in t.get("rows", []) if not r.get("unresolved")}
        cells = {}
        for r in rows:
            for c in cols:
                s = c in seedmarks.get(r, set())
                d = data_mark(r, c) if r in srs.items else False
                if s or d:
                    cells[f"{r}|{c}"] = "both" if s and d else ("seed" if s else "data")
        res["comparison"] = {"rows": rows, "cols": cols, "cells": cells,
                             "seed_rows": sorted(seedmarks, key=natural_key),
                             "seed_cols": t.get("columns", [])}
    return results
