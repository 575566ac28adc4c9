#!/usr/bin/python3
"""Reviews of trace links, and the links whose ends changed since (suspect links).

A person who has read an SRS item and a test labelled with it, and judged that the test
verifies the item, records it:

    traceability/review.py mark IM3 'system_tests:collisions/head_on' --reviewer "A. Person"
    traceability/review.py mark-all --reviewer "A. Person" --item IM3     # every link of IM3
    traceability/review.py mark-all --reviewer "A. Person" --only suspect # every suspect link
    traceability/review.py list --only suspect
    traceability/review.py prune          # drop records of links that no longer exist

The record (traceability/reviews.yaml: link, reviewer, date, the fingerprints of both ends,
fingerprints.py) says what was reviewed. The report compares each link's fingerprints with its
record: *reviewed* (both ends as reviewed), *suspect* (an end changed since: the item, the
test or both; listed and counted, never hidden; `build_report.py --suspect-gates` makes them
fail the gate) or *unreviewed* (no record). `mark` reads the links from the last report
(reports/traceability.json) and refuses when the sources changed since it was built: the
review is of what the report shows. See docs/traceability.md.
"""
from __future__ import annotations

import argparse
import datetime as _dt
import json
import os
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(HERE))
    __package__ = "traceability"  # noqa: A001 - allow `python3 traceability/review.py`

from traceability import fingerprints, srsdata  # noqa: E402
from traceability.srsdata import natural_key  # noqa: E402

REVIEWS_FILE = os.path.join("traceability", "reviews.yaml")
STATES = ("reviewed", "suspect", "unreviewed")
HEADER = """\
# Reviews of trace links (item, test): who judged that the test verifies the item, when, and
# the fingerprints of both ends as they were then (traceability/fingerprints.py). Written by
# traceability/review.py after a person has looked; a link whose end changed since is shown
# as suspect in the report (docs/traceability.md, "Suspect links and reviews").
"""


# --------------------------------------------------------------------------- records
def load(path, warnings=None):
    """The review records of path ([] when it does not exist)."""
    if not path or not os.path.exists(path):
        return []
    try:
        with open(path, encoding="utf-8") as fh:
            doc = yaml.safe_load(fh) or {}
    except (OSError, yaml.YAMLError) as exc:
        if warnings is not None:
            warnings.append(f"{path}: cannot be read ({exc}); no link counts as reviewed")
        return []
    out = []
    for n, r in enumerate((doc.get("reviews") if isinstance(doc, dict) else None) or [], 1):
        if not isinstance(r, dict) or not all(r.get(k) for k in ("item", "test", "reviewer")):
            if warnings is not None:
                warnings.append(f"{os.path.basename(path)}: review #{n} needs item, test and "
                                "reviewer; ignored")
            continue
        out.append({"item": str(r["item"]), "test": str(r["test"]),
                    "reviewer": str(r["reviewer"]), "date": str(r.get("date") or ""),
                    "item_fingerprint": str(r.get("item_fingerprint") or ""),
                    "test_fingerprint": str(r.get("test_fingerprint") or ""),
                    **({"note": str(r["note"])} if r.get("note") else {})})
    return out


def save(path, records):
    """Writes the records sorted by item and test, one per link."""
    records = sorted(records, key=lambda r: (natural_key(r["item"]), r["test"]))
    body = yaml.safe_dump({"reviews": records}, sort_keys=False, allow_unicode=True, width=100)
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(HEADER + body)


# --------------------------------------------------------------------------- judging
def judge(res, tests, records, suspect_gates=False):
    """Compares each link's fingerprints with its review record. Sets link["item_fingerprint"],
    link["test_fingerprint"] and link["review"] on res["links"] and on each item's links, adds
    gate.suspect_links (and a gate reason when suspect_gates); returns the report's
    `reviews` section."""
    fp_item = {i["label"]: i.get("fingerprint") for i in res["items"]}
    fp_test = {t["id"]: t.get("fingerprint") for t in tests}
    by_link = {(r["item"], r["test"]): r for r in records}
    counts = {s: 0 for s in STATES}
    suspect = []
    for ln in res["links"]:
        key = (ln["item"], ln["test"])
        ln["item_fingerprint"], ln["test_fingerprint"] = fp_item.get(key[0]), fp_test.get(key[1])
        rec = by_link.get(key)
        if rec is None:
            review = {"status": "unreviewed"}
        else:
            changed = [end for end, now, then in (
                ("item", ln["item_fingerprint"], rec["item_fingerprint"]),
                ("test", ln["test_fingerprint"], rec["test_fingerprint"])) if now != then]
            review = {"status": "suspect" if changed else "reviewed", "changed": changed,
                      "reviewer": rec["reviewer"], "date": rec["date"],
                      "reviewed_item_fingerprint": rec["item_fingerprint"],
                      "reviewed_test_fingerprint": rec["test_fingerprint"]}
            if rec.get("note"):
                review["note"] = rec["note"]
            if changed:
                suspect.append({"item": key[0], "test": key[1], "changed": changed,
                                "reviewer": rec["reviewer"], "date": rec["date"]})
        ln["review"] = review
        counts[review["status"]] += 1
    items = {i["label"]: i for i in res["items"]}
    for ln in res["links"]:
        entry = (items.get(ln["item"], {}).get("links") or {}).get(ln["test"])
        if entry is not None:
            entry["review"] = ln["review"]["status"]
            if ln["review"].get("changed"):
                entry["changed"] = ln["review"]["changed"]
    links = {(ln["item"], ln["test"]) for ln in res["links"]}
    orphans = [r for r in records if (r["item"], r["test"]) not in links]
    gate = res["gate"]
    gate["suspect_links"] = suspect
    gate["suspect_gates"] = bool(suspect_gates)
    if suspect and suspect_gates:
        gate["reasons"].append(f"{len(suspect)} suspect trace link(s) (an end changed since its "
                               "review; --suspect-gates): " +
                               ", ".join(f"{s['item']} <- {s['test']}" for s in suspect[:12]) +
                               (" ..." if len(suspect) > 12 else ""))
        gate["passed"], gate["exit_code"] = False, 1
    return {"records": len(records), **counts, "suspect_links": suspect,
            "orphan_records": orphans, "gates": bool(suspect_gates)}


# --------------------------------------------------------------------------- command line
def _report(path):
    with open(path, encoding="utf-8") as fh:
        return json.load(fh)


def _current(report, source):
    """{(item, test): (item fingerprint, test fingerprint)} computed from the sources now, for
    the links of the report."""
    srs_dir = report.get("inputs", {}).get("srs_dir") or "srs"
    srs = srsdata.load_srs(srs_dir if os.path.isabs(srs_dir) else os.path.join(source, srs_dir))
    texts = fingerprints.SourceTexts(source)
    tests = {t["id"]: t for t in report.get("tests", [])}
    out = {}
    for ln in report.get("links", []):
        raw = srs.items.get(ln["item"])
        t = tests.get(ln["test"])
        out[(ln["item"], ln["test"])] = (
            fingerprints.item_fingerprint(raw) if raw is not None else None,
            fingerprints.test_fingerprint(t, texts)[0] if t is not None else None)
    return out


def _select(report, args):
    links = report.get("links", [])
    if getattr(args, "item", None):
        links = [ln for ln in links if ln["item"] in args.item]
    if getattr(args, "test", None):
        links = [ln for ln in links if ln["test"] in args.test]
    only = getattr(args, "only", "all")
    if only != "all":
        links = [ln for ln in links if (ln.get("review") or {}).get("status") == only]
    return links


def cmd_mark(args, links):
    report = _report(args.report)
    if not report.get("links") or "item_fingerprint" not in report["links"][0]:
        print(f"review: {args.report} has no link fingerprints (report schema "
              f"{report.get('schema_version')}): build the report again", file=sys.stderr)
        return 2
    if not links:
        print("review: no link matches", file=sys.stderr)
        return 2
    now = _current(report, args.source)
    stale = [ln for ln in links if now.get((ln["item"], ln["test"])) !=
             (ln["item_fingerprint"], ln["test_fingerprint"])]
    if stale:
        print(f"review: the sources changed since {args.report} was built ("
              + ", ".join(f"{ln['item']} <- {ln['test']}" for ln in stale[:5])
              + "): build the report again (build_report.py --no-run) and look at what it shows",
              file=sys.stderr)
        return 1
    records = {(r["item"], r["test"]): r for r in load(args.reviews)}
    date = args.date or _dt.date.today().isoformat()
    for ln in links:
        rec = {"item": ln["item"], "test": ln["test"], "reviewer": args.reviewer, "date": date,
               "item_fingerprint": ln["item_fingerprint"], "test_fingerprint": ln["test_fingerprint"]}
        if args.note:
            rec["note"] = args.note
        records[(ln["item"], ln["test"])] = rec
    save(args.reviews, records.values())
    for ln in links:
        print(f"reviewed: {ln['item']} <- {ln['test']} ({args.reviewer}, {date})")
    return 0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--source", default=os.path.dirname(HERE), help="repository root")
    p.add_argument("--report", default=None,
                   help="the report's JSON (default <source>/reports/traceability.json)")
    p.add_argument("--reviews", default=None,
                   help="review records (default <source>/traceability/reviews.yaml)")
    sub = p.add_subparsers(dest="cmd", required=True)
    m = sub.add_parser("mark", help="record the review of one link")
    m.add_argument("item")
    m.add_argument("test")
    ma = sub.add_parser("mark-all", help="record the review of every matching link")
    ma.add_argument("--item", action="append", help="only links of this item (repeatable)")
    ma.add_argument("--test", action="append", help="only links of this test (repeatable)")
    ma.add_argument("--only", choices=("all",) + STATES, default="all",
                    help="only links in this review state (default all)")
    for q in (m, ma):
        q.add_argument("--reviewer", required=True, help="who looked")
        q.add_argument("--date", default=None, help="date of the review (default today)")
        q.add_argument("--note", default=None, help="what was judged (optional)")
    ls = sub.add_parser("list", help="the links and their review state")
    ls.add_argument("--only", choices=("all",) + STATES, default="all")
    sub.add_parser("prune", help="drop the records of links the report no longer has")
    args = p.parse_args(argv)
    args.source = os.path.abspath(args.source)
    args.report = args.report or os.path.join(args.source, "reports", "traceability.json")
    args.reviews = args.reviews or os.path.join(args.source, REVIEWS_FILE)
    if not os.path.exists(args.report):
        print(f"review: no report at {args.report}: build it first (traceability/build_report.py)",
              file=sys.stderr)
        return 2
    if args.cmd == "mark":
        links = [ln for ln in _report(args.report).get("links", [])
                 if ln["item"] == args.item and ln["test"] == args.test]
        return cmd_mark(args, links)
    if args.cmd == "mark-all":
        return cmd_mark(args, _select(_report(args.report), args))
    if args.cmd == "list":
        for ln in _select(_report(args.report), args):
            rv = ln.get("review") or {}
            extra = f" ({', '.join(rv['changed'])} changed)" if rv.get("changed") else ""
            print(f"{rv.get('status', '?'):10} {ln['grade']:6} {ln['item']} <- {ln['test']}{extra}")
        return 0
    report = _report(args.report)
    links = {(ln["item"], ln["test"]) for ln in report.get("links", [])}
    records = load(args.reviews)
    kept = [r for r in records if (r["item"], r["test"]) in links]
    save(args.reviews, kept)
    print(f"pruned {len(records) - len(kept)} record(s) of links that no longer exist")
    return 0


if __name__ == "__main__":
    sys.exit(main())
