"""reports/traceability.md: the same content as index.html in a diffable form."""
from __future__ import annotations

from . import module_reach_reference, mutation_reference, render_audit
from .srsdata import KIND_NAMES


def _esc(s):
    return str(s if s is not None else "").replace("|", "\\|").replace("\n", " ")


def _table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(_esc(c) for c in row) + " |" for row in rows]
    return "\n".join(out) + "\n"


def render(r):
    L = []
    w = L.append
    src = r["source"]
    w("# Tamias2D: SRS traceability and V&V evidence\n")
    w(f"Generated {r['generated']} · commit `{(src.get('git_commit') or 'unknown')[:12]}`"
      f"{' (dirty tree)' if src.get('git_dirty') else ''} · "
      f"{'tests run' if r['inputs']['ran_tests'] else 'pre-recorded results'} · schema {r['schema_version']}\n")
    g = r["gate"]
    def bullets(heading, lines):
        w(heading + "\n")
        for x in lines:
            w(f"- {x}")
        w("")

    if g["passed"]:
        w("**Gate: PASS (exit 0).** Every R/IM/TM/GD/DD item has a passing test and nothing fails.\n")
    else:
        bullets(f"**Gate: FAIL (exit {g['exit_code']}).** Reasons:", g["reasons"])
    if g.get("known_failures"):
        bullets("**Known failures (documented findings, docs/verification.md; declared with "
                "Boost's expected_failures):**", g["known_failures"])
    if g.get("targets_missed"):
        bullets("**Targets not met (goals beyond the SRS, e.g. the project's speed "
                "floors; reported, not gating):**", g["targets_missed"])
    if g.get("goals"):
        tests_by_id = {t["id"]: t for t in r["tests"]}
        lines = []
        for goal in g["goals"]:
            figs = "; ".join(f'{c}: {tests_by_id[c].get("figure") or tests_by_id[c]["status"]}'
                             for c in goal["checks"] if c in tests_by_id)
            lines.append(f'{goal["label"]} {goal["status"]}' + (f" ({figs})" if figs else ""))
        bullets('**Goals of the SRS ("should" requirements: measured and shown, never gating):**',
                lines)
    w(render_audit.md_gate(r))
    s = r["summary"]
    w("## 1. Summary\n")
    w("Items by status: " + ", ".join(f"{k}: {v}" for k, v in s["by_status"].items()) +
      f" (of {len(r['items'])}).\n")
    w(_table(["Kind", "Name", "Items", "Verified", "Goal met", "Failing", "Goal missed",
              "Model only", "Untested",
              "Assumed", "Not testable", "Not impl.", "With code", "With tests", "Verified %"],
             [[k["kind"], k["name"], k["total"], k["verified"], k["goal met"], k["failing"],
               k["goal missed"], k["model only"], k["untested"],
               k["assumed"], k["not testable"], k["not implemented"], k["with_code"], k["with_tests"],
               k["verified_percent"]] for k in s["by_kind"]]))
    w(_table(["Origin", "Total", "Passed", "Failed", "Error", "Skipped", "Not run", "Known failure",
              "Target missed", "Goal missed"],
             [[o, t.get("total", 0), t.get("passed", 0), t.get("failed", 0), t.get("error", 0),
               t.get("skipped", 0), t.get("notrun", 0), t.get("known-failure", 0),
               t.get("target-missed", 0), t.get("goal-missed", 0)]
              for o, t in sorted(s["tests"].items())]))
    tests = {t["id"]: t for t in r["tests"]}
    w("## 2. Items\n")
    w(_table(["Label", "Kind", "Alias", "Title", "Status", "Oracle kinds", "Code sites", "Tests (status)",
              "Errata"],
             [[i["label"], i["kind"], i.get("alias") or "", i.get("title") or "",
               i["status"] + (f": {i['status_reason']}" if i.get("status_reason") else ""),
               ", ".join(i.get("oracle_kinds") or []) + (" (weak)" if i.get("weak_evidence") else "") +
               (f" ({len(i['tests_without_oracle'])} without oracle)" if i.get("tests_without_oracle") else ""),
               "; ".join(f"{c['file']}:{c['line']}" for c in i["code_sites"]) or "—",
               "; ".join(f"{t} ({tests[t]['status']})" for t in i["tests"]) or "—",
               ", ".join(i["errata"])] for i in r["items"]]))
    notes = [(i["label"], n) for i in r["items"] for n in i["notes"]]
    if notes:
        w("Notes:\n")
        for lab, n in notes:
            w(f"- {lab}: {n}")
        w("")
    w("### Oracles of the labelled tests\n")
    rows = []
    for i in r["items"]:
        for t in i["tests"]:
            rows.append([i["label"], t, tests[t]["status"], ", ".join(tests[t].get("oracle_kinds") or []),
                         tests[t].get("oracle") or "(none stated)"])
    w(_table(["Item", "Test / check", "Status", "Oracle kind", "Oracle"], rows) if rows else "None.\n")
    w("## 3. Gaps and orphans\n")
    gp = r["gaps"]
    w(f"- No code tag ({len(gp['no_code'])}): {', '.join(gp['no_code']) or 'none'}")
    w(f"- No labelled test or check ({len(gp['no_test'])}): {', '.join(gp['no_test']) or 'none'}")
    w(f"- No passing test or check ({len(gp['no_passing_test'])}): {', '.join(gp['no_passing_test']) or 'none'}")
    w(f"- Verified only by weak evidence ({len(gp['weak_evidence'])}): {', '.join(gp['weak_evidence']) or 'none'}")
    w(f"- Weak evidence: a labelled test states no oracle ({len(gp.get('unstated_oracle', []))}): "
      f"{', '.join(gp.get('unstated_oracle', [])) or 'none'}")
    o = r["orphans"]
    w(f"- Orphan code tags ({len(o['code_tags'])}): " +
      (", ".join(f"`\\srs{{{x['label']}}}` at {x['file']}:{x['line']}" for x in o["code_tags"]) or "none"))
    w(f"- Orphan test labels ({len(o['test_labels'])}): " +
      (", ".join(f"{x['label']} ({', '.join(x['tests'])})" for x in o["test_labels"]) or "none"))
    srs_missing = r.get("missing_oracle_srs", [])
    w(f"- SRS-labelled tests without an oracle ({len(srs_missing)}): {', '.join(srs_missing) or 'none'}")
    w(f"- Tests without an oracle, labelled or not ({len(r['missing_oracle'])}): {', '.join(r['missing_oracle']) or 'none'}")
    for x in r["registration"]:
        w(f"- Registration: {x}")
    w("")
    w(render_audit.md(r))
    w("## 4. Traceability matrices\n")
    seed = {t["id"]: t for t in r["seed_tables"]}
    for m in r["matrices"]:
        w(f"### Table {m['number']} (regenerated from srs/ `uses`): {m['caption']}\n")
        if m["row_labels"] and m["col_labels"]:
            w(_table([""] + m["col_labels"],
                     [[row] + ["X" if c in m["cells"][row] else "" for c in m["col_labels"]] for row in m["row_labels"]]))
        else:
            w("No items of these kinds yet.\n")
        st = seed.get(m["id"])
        if not st:
            continue
        if st["missing"]:
            w(f"**Seed Table {m['number']} is missing from the seed text.** " + " ".join(st["notes"]) + "\n")
            continue
        w(f"Seed Table {m['number']} as printed (traceability/seed_tables.yaml):\n")
        w(_table([""] + st["seed_columns"],
                 [[row.get("printed_as") or row["label"]] + ["X" if c in (row.get("marks") or []) else "" for c in st["seed_columns"]]
                  for row in st["seed_rows"]]))
        if st["differences"]:
            w(f"Differences, seed vs regenerated ({len(st['differences'])}):\n")
            w(_table(["Row", "Column", "Type", "Detail"],
                     [[d["row"], d["column"] or "", d["type"], d["detail"]] for d in st["differences"]]))
        for n in st["notes"]:
            w(f"- {n}")
        w("")
    w("## 5. Graphs\n")
    for gph in r["graphs"]:
        w(f"- {gph['title']}: [{gph['svg'] or gph['dot']}]({gph['svg'] or gph['dot']}) ({gph['nodes']} nodes, {gph['edges']} edges)")
    w("")
    w("## 6. SRS errata\n")
    if r["errata"]:
        w(_table(["Id", "Items", "Kind", "Seed text", "Problem", "Correct reading", "Compile-fail"],
                 [[e["id"], ", ".join(e.get("items", [])), e.get("kind") or "", e.get("seed_text") or "",
                   e.get("problem") or "", e.get("correct_reading") or "", e.get("compile_fail") or ""]
                  for e in r["errata"]]))
    else:
        w("No errata loaded.\n")
    w(f"### Ref. By disagreements (seed vs computed from `uses`): {len(r['refby_disagreements'])}\n")
    if r["refby_disagreements"]:
        w(_table(["Item", "Seed Ref. By", "Computed Ref. By", "Only in seed", "Only computed"],
                 [[d["label"], ", ".join(d["seed_ref_by"]), ", ".join(d["computed_ref_by"]),
                   ", ".join(d["only_in_seed"]), ", ".join(d["only_in_data"])] for d in r["refby_disagreements"]]))
    ag = r["checker"].get("agreement")
    w(f"srs/check_srs.py cross-check: {r['checker']['message']}" +
      (f"; {'agrees' if ag['agrees'] else 'DIFFERS'}: {ag['summary']}" if ag else "") + "\n")
    w("## 7. V&V evidence\n")
    prov = r.get("provenance") or {}
    w(f"Accepted only from commit {str(prov.get('source_commit') or 'unknown')[:12]} and build "
      f"{(prov.get('build') or {}).get('build_id') or 'unknown'}; expected programs: "
      f"{', '.join(prov.get('expected_programs') or []) or 'none'}; missing: "
      f"{', '.join(prov.get('missing_programs') or []) or 'none'}; refused: "
      f"{', '.join(x['program'] + ' (' + x['reason'] + ')' for x in prov.get('refused') or []) or 'none'}; "
      f"not run: {'; '.join(x['program'] + ' (' + x['how'] + ')' for x in prov.get('not_run_programs') or []) or 'none'}.\n")
    if not r["verification"]:
        w("No verification results in reports/data/.\n")
    for p in r["verification"]:
        w(f"### {p['program']}\n\n{p.get('description') or ''} (data/{p['file']})\n")
        if p["checks"]:
            w(_table(["Check", "Labels", "Status", "Oracle", "Details"],
                     [[c.get("name"), ", ".join(c.get("labels") or []), c["status"], c.get("oracle") or "",
                       c.get("details") or ""] for c in p["checks"]]))
        for t in p["tables"]:
            w(f"**{t.get('name', '')}**\n")
            w(_table([str(c) for c in t.get("columns", [])],
                     [row if isinstance(row, list) else [row] for row in t.get("rows", [])]))
        for s_ in p["series"]:
            if s_.get("svg"):
                w(f"![{s_.get('name')}]({s_['svg']})\n")
    br = r.get("bench_records") or {}
    w("### Dated benchmark records\n")
    w(f"{len(br.get('points') or [])} step times of tamias_bench runs from {br.get('records', 0)} "
      "record file(s) under verification/bench/results/, each true of its commit, machine and date "
      f"only; data: {br.get('csv') or 'none'}.\n")
    if br.get("svg"):
        w(f"![ms/step by date and commit, per scene and engine]({br['svg']})\n")
    ref = r.get("mutation_reference")
    w("### Mutation: the reference analysis\n")
    if ref:
        w(f"{mutation_reference.summary(ref)} ({ref['file']})\n")
        if ref["survivors"]:
            w(_table(["File:line", "Operator", "Line", "Judgement", "Reason"],
                     [[f"{s_['file']}:{s_['line']}", s_["op"], s_["before"],
                       mutation_reference.judgement_text(s_), s_["reason"]]
                      for s_ in ref["survivors"]]))
    else:
        w(f"No reference analysis is kept ({mutation_reference.REFERENCE}).\n")
    ref = r.get("module_reach_reference")
    w("### Module reach: the reference run\n")
    if ref:
        w(f"{module_reach_reference.summary(ref)} ({ref['file']})\n")
        w(_table(["Item", "Module", "srs/ expects", "Perturbations", "Result"],
                 [[s_["label"], ", ".join(s_["modules"]), s_["expected"], s_["perturbations"],
                   ", ".join(s_["results"]) + ("" if s_["as_expected"] else " (not as srs/ states)")]
                  for s_ in ref["items"]]))
    else:
        w(f"No reference run is kept ({module_reach_reference.REFERENCE}).\n")
    w("## 8. Coverage\n")
    cov = r["coverage"]
    if cov:
        t = cov["totals"]
        w(f"Lines {t.get('line_percent')}% ({t.get('line_covered')}/{t.get('line_total')}), "
          f"functions {t.get('function_percent')}%, branches {t.get('branch_percent')}%.\n")
    else:
        w("No reports/data/coverage.json.\n")
    w("## 9. Warnings\n")
    for x in r["warnings"]:
        w(f"- {x}")
    if not r["warnings"]:
        w("None.")
    w("")
    return "\n".join(L)


__all__ = ["render", "KIND_NAMES"]
