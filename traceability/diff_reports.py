#!/usr/bin/python3
"""What changed between two traceability reports (their traceability.json files).

    traceability/diff_reports.py OLD.json NEW.json [--noise 0.10] [--json]

Lists the items that changed status (and items added or removed), the trace links added,
removed, regraded (strong <-> weak) or suspect in NEW (an end changed since its review; those
not suspect in OLD are marked new), the tests and checks that changed status (added, removed),
and the figures of the verification programs that moved: each check's `figure` and every cell
of their tables, matched by program, table name, row and column.

A figure is a *timing* when its column or table names a time or a rate (time, ms, ns, s/step,
seconds, exec/s, speed-up, wall, CPU, latency, per run): timings are noisy from run to run,
so one is listed only when it moved by more than the noise band (relative, default 10 %,
--noise), and the ones within it are counted. Any other figure (an error, a count, a text) is
deterministic and listed at any change. Exit status: 0 when nothing is listed, 1 when
something is, 2 on a usage error.
"""
from __future__ import annotations

import argparse
import collections
import json
import re
import sys

NOISE = 0.10
TIMING = re.compile(r"\btimes?\b|\bms\b|ms/|/step|per step|\bns\b|µs|\bus\b|second|\bsec\b|"
                    r"exec|speed-?up|\bwall\b|\bcpu\b|latency|per run|duration", re.I)
NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def _num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _first_number(v):
    if _num(v):
        return float(v)
    m = NUMBER.search(str(v)) if v is not None else None
    return float(m.group()) if m else None


def moved(old, new, timing, noise):
    """(listed, relative change or None): whether a figure's change is listed."""
    if old == new:
        return False, 0.0
    if not timing:
        a, b = _first_number(old), _first_number(new)
        return True, (abs(b - a) / abs(a) if a not in (None, 0) and b is not None else None)
    a, b = _first_number(old), _first_number(new)
    if a is None or b is None:
        return True, None
    if a == 0:
        return b != 0, None
    rel = abs(b - a) / abs(a)
    return rel > noise, rel


def _rows_by_key(table_old, table_new):
    """{key: row} for both tables: the leading columns that are text in every row of both
    (at least the first), and the key's occurrence to tell repeated keys apart."""
    rows = [r for t in (table_old, table_new) for r in t.get("rows") or [] if isinstance(r, list)]
    width = min((len(r) for r in rows), default=0)
    k = 0
    while k < width and all(not _num(r[k]) for r in rows):
        k += 1
    k = max(1, k)

    def keyed(t):
        seen, out = collections.Counter(), {}
        for r in t.get("rows") or []:
            r = r if isinstance(r, list) else [r]
            key = tuple(json.dumps(x) for x in r[:k])
            seen[key] += 1
            out[key + (seen[key],)] = r
        return out
    return keyed(table_old), keyed(table_new), k


def _short(name, n=60):
    name = str(name)
    return name if len(name) <= n else name[:n - 1].rstrip() + "…"


def _key_text(key):
    parts = [json.loads(x) for x in key[:-1]]
    return " / ".join(str(p) for p in parts) + (f" (#{key[-1]})" if key[-1] > 1 else "")


def diff_figures(old, new, noise):
    listed, within, tables_changed = [], 0, []
    progs_old = {p["program"]: p for p in old.get("verification") or []}
    progs_new = {p["program"]: p for p in new.get("verification") or []}
    for name in sorted(set(progs_old) | set(progs_new)):
        po, pn = progs_old.get(name), progs_new.get(name)
        if po is None or pn is None:
            tables_changed.append(f"program {name}: {'added' if po is None else 'removed'}")
            continue
        checks_old = {c.get("name"): c for c in po.get("checks") or []}
        for c in pn.get("checks") or []:
            co = checks_old.get(c.get("name"))
            if co is None or co.get("figure") == c.get("figure"):
                continue
            timing = bool(TIMING.search(f"{c.get('name')} {c.get('figure')} {c.get('details')}"))
            hit, rel = moved(co.get("figure"), c.get("figure"), timing, noise)
            if hit:
                listed.append({"program": name, "where": f"check {c.get('name')}: figure",
                               "old": co.get("figure"), "new": c.get("figure"), "timing": timing,
                               "change": rel})
            else:
                within += 1
        tabs_old = {t.get("name"): t for t in po.get("tables") or []}
        tabs_new = {t.get("name"): t for t in pn.get("tables") or []}
        for tname in list(tabs_new) + [t for t in tabs_old if t not in tabs_new]:
            to, tn = tabs_old.get(tname), tabs_new.get(tname)
            if to is None or tn is None:
                tables_changed.append(f"{name}: table {_short(tname)!r} {'added' if to is None else 'removed'}")
                continue
            table_timing = bool(TIMING.search(str(tname)))
            ro, rn, k = _rows_by_key(to, tn)
            cols_o, cols_n = list(to.get("columns") or []), list(tn.get("columns") or [])
            for key in ro.keys() | rn.keys():
                if key not in ro or key not in rn:
                    tables_changed.append(f"{name}: table {_short(tname)!r}: row {_key_text(key)} "
                                          f"{'added' if key not in ro else 'removed'}")
            for key in sorted(ro.keys() & rn.keys()):
                for ci, col in enumerate(cols_n):
                    if ci < k or col not in cols_o:
                        continue
                    a = ro[key][cols_o.index(col)] if cols_o.index(col) < len(ro[key]) else None
                    b = rn[key][ci] if ci < len(rn[key]) else None
                    if a == b:
                        continue
                    timing = table_timing or bool(TIMING.search(str(col)))
                    hit, rel = moved(a, b, timing, noise)
                    if hit:
                        listed.append({"program": name, "where": f"{_short(tname)} / {_key_text(key)} / {col}",
                                       "old": a, "new": b, "timing": timing, "change": rel})
                    else:
                        within += 1
    return listed, within, tables_changed


def diff(old, new, noise=NOISE):
    items_o = {i["label"]: i for i in old.get("items") or []}
    items_n = {i["label"]: i for i in new.get("items") or []}
    tests_o = {t["id"]: t for t in old.get("tests") or []}
    tests_n = {t["id"]: t for t in new.get("tests") or []}
    links_o = {(ln["item"], ln["test"]): ln for ln in old.get("links") or []}
    links_n = {(ln["item"], ln["test"]): ln for ln in new.get("links") or []}

    def review(link):
        rv = (link or {}).get("review")
        return rv.get("status") if isinstance(rv, dict) else None

    figures, within, structure = diff_figures(old, new, noise)
    return {
        "noise": noise,
        "gate": {"old": (old.get("gate") or {}).get("passed"), "new": (new.get("gate") or {}).get("passed")},
        "items_status": [{"label": k, "old": items_o[k]["status"], "new": items_n[k]["status"]}
                         for k in items_n if k in items_o and items_o[k]["status"] != items_n[k]["status"]],
        "items_added": [k for k in items_n if k not in items_o],
        "items_removed": [k for k in items_o if k not in items_n],
        "links_added": [{"item": k[0], "test": k[1], "grade": v.get("grade")}
                        for k, v in links_n.items() if k not in links_o],
        "links_removed": [{"item": k[0], "test": k[1], "grade": v.get("grade")}
                          for k, v in links_o.items() if k not in links_n],
        "links_regraded": [{"item": k[0], "test": k[1], "old": links_o[k].get("grade"), "new": v.get("grade")}
                           for k, v in links_n.items() if k in links_o and links_o[k].get("grade") != v.get("grade")],
        "links_suspect": [{"item": k[0], "test": k[1], "changed": v["review"].get("changed") or [],
                           "new": review(links_o.get(k)) != "suspect"}
                          for k, v in links_n.items() if review(v) == "suspect"],
        "tests_status": [{"id": k, "old": tests_o[k]["status"], "new": v["status"]}
                         for k, v in tests_n.items() if k in tests_o and tests_o[k]["status"] != v["status"]],
        "tests_added": [k for k in tests_n if k not in tests_o],
        "tests_removed": [k for k in tests_o if k not in tests_n],
        "figures": figures,
        "figures_within_noise": within,
        "tables_changed": structure,
    }


LISTS = ("items_status", "items_added", "items_removed", "links_added", "links_removed",
         "links_regraded", "links_suspect", "tests_status", "tests_added", "tests_removed",
         "figures", "tables_changed")


def render(d):
    L = []

    def section(title, rows):
        L.append(f"{title} ({len(rows)})" + (":" if rows else ""))
        L.extend(f"  {r}" for r in rows)

    g = d["gate"]
    if g["old"] != g["new"]:
        L.append(f"Gate: {'PASS' if g['old'] else 'FAIL'} -> {'PASS' if g['new'] else 'FAIL'}")
    section("Items that changed status", [f"{x['label']}: {x['old']} -> {x['new']}" for x in d["items_status"]])
    section("Items added", d["items_added"])
    section("Items removed", d["items_removed"])
    section("Links added", [f"{x['item']} <- {x['test']} ({x['grade']})" for x in d["links_added"]])
    section("Links removed", [f"{x['item']} <- {x['test']} ({x['grade']})" for x in d["links_removed"]])
    section("Links regraded", [f"{x['item']} <- {x['test']}: {x['old']} -> {x['new']}" for x in d["links_regraded"]])
    section("Suspect links in NEW", [f"{x['item']} <- {x['test']}: {', '.join(x['changed'])} changed"
                                     + (" (newly suspect)" if x["new"] else "") for x in d["links_suspect"]])
    section("Tests and checks that changed status", [f"{x['id']}: {x['old']} -> {x['new']}" for x in d["tests_status"]])
    section("Tests and checks added", d["tests_added"])
    section("Tests and checks removed", d["tests_removed"])

    def fig(x):
        rel = f" ({x['change'] * 100:+.1f} %)" if x.get("change") is not None else ""
        return f"{x['program']}: {x['where']}: {x['old']} -> {x['new']}{rel}" + (" [timing]" if x["timing"] else "")
    section(f"Figures that moved (timings beyond the noise band of {d['noise'] * 100:g} %)",
            [fig(x) for x in d["figures"]])
    L.append(f"Timings that moved within the noise band (not listed): {d['figures_within_noise']}")
    section("Tables and programs added or removed, rows added or removed", d["tables_changed"])
    return "\n".join(L) + "\n"


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--noise", type=float, default=NOISE,
                   help="relative noise band of timings (default 0.10: 10 %%)")
    p.add_argument("--json", action="store_true", help="print the differences as JSON")
    args = p.parse_args(argv)
    try:
        with open(args.old, encoding="utf-8") as fh:
            old = json.load(fh)
        with open(args.new, encoding="utf-8") as fh:
            new = json.load(fh)
    except (OSError, ValueError) as exc:
        print(f"diff_reports: {exc}", file=sys.stderr)
        return 2
    d = diff(old, new, args.noise)
    if args.json:
        print(json.dumps(d, indent=1, ensure_ascii=False))
    else:
        sys.stdout.write(render(d))
    return 1 if any(d[k] for k in LISTS) or d["gate"]["old"] != d["gate"]["new"] else 0


if __name__ == "__main__":
    sys.exit(main())
