#!/usr/bin/python3
"""Build the Tamias2D traceability report.

    traceability/build_report.py --source <repo root> --build <build dir> --out <reports dir>

Runs the tests once (every Boost.Test binary with --list_content=DOT and a JUnit logger, the
other CTest entries through ctest --output-junit), joins them with srs/*.yaml, the \\srs{}
code tags and reports/data/*.json, and writes index.html, traceability.md,
traceability.json and tamias2d.reqif into the output directory. Exit status: 0 when every R/IM/TM/GD/DD item has
a passing test and nothing fails, 1 otherwise, 2 on a usage error. See docs/traceability.md.
"""
from __future__ import annotations

import argparse
import datetime as _dt
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(HERE))
    __package__ = "traceability"  # noqa: A001 - allow `python3 traceability/build_report.py`

from traceability import SCHEMA_VERSION  # noqa: E402
from traceability import analysis, builds, evidence, graphs, links, render_html, render_md, srsdata, vvdata  # noqa: E402
from traceability import (bench_records, fingerprints, module_reach_reference,  # noqa: E402
                          mutation_reference, reproducible, reqif, review)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--source", default=os.path.dirname(HERE), help="repository root (default: parent of traceability/)")
    p.add_argument("--build", default=None, help="CMake build directory (default: <source>/build)")
    p.add_argument("--out", default=None, help="report directory (default: <source>/reports)")
    p.add_argument("--srs", default=None, help="SRS directory (default: <source>/srs)")
    p.add_argument("--data", default=None, help="verification results (default: <out>/data)")
    p.add_argument("--results", default=None,
                   help="raw test results directory (default: <out>/raw); written when tests run, read always")
    p.add_argument("--no-run", action="store_true",
                   help="do not run tests; use the results already in --results (e.g. pre-made fixtures)")
    p.add_argument("--no-checker", action="store_true", help="do not call srs/check_srs.py --json")
    p.add_argument("--seed-tables", default=os.path.join(HERE, "seed_tables.yaml"))
    p.add_argument("--config", default=os.path.join(HERE, "config.yaml"))
    p.add_argument("--timeout", type=float, default=1800, help="seconds per test binary (default 1800)")
    p.add_argument("--jobs", type=int, default=1, help="ctest -j for non-Boost entries (default 1)")
    p.add_argument("--junit-level", default="message",
                   help="Boost.Test JUnit log level (default 'message': every case, failures, messages; "
                        "'all' also logs each passing assertion and can reach tens of MB)")
    p.add_argument("--commit", default=None,
                   help="commit the verification results must be of (default: the source's git HEAD)")
    p.add_argument("--date", default=None, help="timestamp to print (default: now, or SOURCE_DATE_EPOCH)")
    p.add_argument("--link-sample", type=int, default=30,
                   help="trace links drawn for review (default 30)")
    p.add_argument("--link-seed", default=None,
                   help="seed of the drawn links (default: the commit's first 8 hex digits)")
    p.add_argument("--reviews", default=None,
                   help="review records of trace links (default <source>/traceability/reviews.yaml)")
    p.add_argument("--suspect-gates", action="store_true",
                   help="suspect links (an end changed since its review) fail the gate")
    p.add_argument("--quiet", action="store_true")
    return p.parse_args(argv)


def git_info(root):
    info = {"root": os.path.abspath(root), "git_commit": None, "git_branch": None, "git_dirty": None}
    try:
        info["git_commit"] = subprocess.run(["git", "-C", root, "rev-parse", "HEAD"], capture_output=True,
                                            text=True, timeout=30).stdout.strip() or None
        info["git_branch"] = subprocess.run(["git", "-C", root, "rev-parse", "--abbrev-ref", "HEAD"],
                                            capture_output=True, text=True, timeout=30).stdout.strip() or None
        st = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no"],
                            capture_output=True, text=True, timeout=60)
        info["git_dirty"] = bool(st.stdout.strip()) if st.returncode == 0 else None
        info["git_commit_date"] = reproducible.commit_date(root)
    except (OSError, subprocess.TimeoutExpired):
        pass
    return info


def timestamp(arg):
    if arg:
        return arg
    sde = os.environ.get("SOURCE_DATE_EPOCH")
    if sde and sde.isdigit():
        return _dt.datetime.fromtimestamp(int(sde), _dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    return _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")


def build(args, log=print):
    source = os.path.abspath(args.source)
    build_dir = os.path.abspath(args.build or os.path.join(source, "build"))
    out = os.path.abspath(args.out or os.path.join(source, "reports"))
    srs_dir = os.path.abspath(args.srs or os.path.join(source, "srs"))
    data_dir = os.path.abspath(args.data or os.path.join(out, "data"))
    results_dir = os.path.abspath(args.results or os.path.join(out, "raw"))
    os.makedirs(out, exist_ok=True)
    warnings = []

    srs = srsdata.load_srs(srs_dir)
    warnings += srs.warnings
    config = analysis.load_config(args.config)

    checker = {"message": "not run (--no-checker)", "disagreements": None}
    if not args.no_checker:
        data, msg = srsdata.run_checker(source)
        checker["message"] = msg
        if isinstance(data, dict):
            checker["disagreements"] = data.get("disagreements")

    code_sites = evidence.scan_code_tags(source)

    build_prov = vvdata.load_build_provenance(build_dir)
    run_manifest = None
    if not args.no_run:
        os.makedirs(results_dir, exist_ok=True)
        run_manifest = evidence.run_tests(build_dir, results_dir, timeout=args.timeout, jobs=args.jobs,
                                          log=(lambda m: None) if args.quiet else log,
                                          junit_level=args.junit_level, build=build_prov)
    tests, ctests, tinfo = evidence.collect_tests(source, results_dir, warnings)
    # The manifest as the results directory holds it: a run and a later --no-run report of
    # its results read the same document.
    run_manifest = tinfo.get("manifest") or run_manifest

    programs, cov = vvdata.load_data_dir(data_dir, warnings)
    source_info = git_info(source)
    source_commit = args.commit or source_info["git_commit"]
    # The tree the report describes: the checkout's, unless --commit names a commit (the
    # fixtures' results are of a made-up commit, with no tree to compare).
    source_tree = None if args.commit else builds.tree_key(source)
    if build_prov is None:
        warnings.append(f"no {os.path.join(build_dir, 'provenance.json')}: the results' build ids "
                        "were not compared with the build's")
    if not source_commit:
        warnings.append("the checkout's commit is unknown: the results' commits were not compared")
    # Verdicts are of the build they ran in: that build must be of this checkout.
    build_problems = builds.judge_build(build_dir, source, build_prov, not args.no_run) \
        if not args.commit else []
    ran_build = (run_manifest or {}).get("build") or {}
    if build_prov and ran_build.get("build_id") and ran_build["build_id"] != build_prov.get("build_id"):
        build_problems.append(f"the test results were run from build {ran_build['build_id']}, the "
                              f"build directory is build {build_prov.get('build_id')}: run them again")
    expected = [str(x) for x in config.get("expected_programs") or []]
    missing = vvdata.judge_provenance(programs, expected, build_prov, source_commit, source_tree)
    tests += vvdata.checks_as_tests(programs, missing)
    coverage = vvdata.coverage_summary(cov)
    if coverage is not None and source_tree:
        cp = coverage.get("provenance") or {}
        if cp.get("tree") != source_tree:
            build_problems.append(
                "coverage (data/coverage.json) is " +
                (f"of tree {str(cp.get('tree'))[:12]}, not the checkout's" if cp.get("tree")
                 else "of no recorded tree (no provenance)") + ": measure it again")
    for k, problem in enumerate(build_problems):
        tests.append({"id": f"build:<up to date>{'#' + str(k + 1) if k else ''}",
                      "name": "<up to date>", "origin": "verification", "binary": "build",
                      "status": "error", "labels": [], "oracle": None, "file": None, "line": None,
                      "details": problem, "samples": None, "enabled": True})
    optional = {str(k): str(v) for k, v in (config.get("optional_programs") or {}).items()}
    present = {p["program"] for p in programs}
    not_run = [{"program": k, "how": v} for k, v in optional.items() if k not in present]
    seen = {}
    for t in tests:  # ids must be unique (anchors, item -> test references)
        n = seen.get(t["id"], 0) + 1
        seen[t["id"]] = n
        if n > 1:
            warnings.append(f"duplicate test id {t['id']}: the {n}. one is renamed {t['id']}#{n}")
            t["id"] = f"{t['id']}#{n}"
    for p in programs:
        for c in p["checks"]:
            c["status"] = ("error" if p.get("refused") else "passed" if c.get("passed") is True
                           else "target-missed" if c.get("target") else "failed")
    vvdata.render_plots(programs, out, warnings)
    # The dated benchmark records of the checkout (verification/bench/results/), beside its own.
    records = bench_records.render(bench_records.collect(source, warnings), out, warnings)
    # The whole mutation analysis of a named commit, beside the checkout's own sample.
    mutation_ref = mutation_reference.collect(source, warnings, tests)
    reach_ref = module_reach_reference.collect(source, warnings)

    res = analysis.analyse(srs, code_sites, tests, config, warnings)
    # Fingerprints of both ends of each link, compared with the review records.
    fingerprints.annotate(srs, res["items"], tests, source)
    reqif.srs_extra(srs, res["items"])
    reviews_file = os.path.abspath(args.reviews or os.path.join(source, review.REVIEWS_FILE))
    reviews = dict(review.judge(res, tests, review.load(reviews_file, warnings), args.suspect_gates),
                   file=reviews_file)
    # A failed check of a "should" requirement only is a missed goal (analysis.GOAL_OBLIGATION).
    goal_missed = {t["id"] for t in tests if t["status"] == "goal-missed"}
    for p in programs:
        for c in p["checks"]:
            if f"{p['program']}:{c.get('name')}" in goal_missed:
                c["status"] = "goal-missed"
    # A fresh sample per commit, the same for every report of that commit.
    link_seed = args.link_seed or (source_commit or "unknown")[:8]
    matrices = analysis.build_matrices(srs)
    seed_cmp = analysis.compare_seed(srs, matrices, analysis.load_seed_tables(args.seed_tables))
    status_of = {i["label"]: i["status"] for i in res["items"]}
    gr = graphs.render_graphs(srs, status_of, out, warnings)
    missing_oracle = res["missing_oracle"]
    if res["missing_oracle_srs"]:
        warnings.append(f"{len(res['missing_oracle_srs'])} SRS-labelled test(s)/check(s) state no "
                        "oracle (weak evidence for their items): " +
                        ", ".join(res["missing_oracle_srs"]))
    if missing_oracle:
        warnings.append(f"{len(missing_oracle)} test(s)/check(s) state no oracle: " +
                        ", ".join(missing_oracle[:10]) + (" ..." if len(missing_oracle) > 10 else ""))

    report = {
        "schema": "tamias2d-traceability",
        "schema_version": SCHEMA_VERSION,
        "generated": timestamp(args.date),
        "source": source_info,
        "inputs": {"srs_dir": srs_dir, "srs_files": srs.files, "build_dir": build_dir,
                   "results_dir": results_dir, "data_dir": data_dir, "out_dir": out,
                   "ran_tests": not args.no_run, "seed_tables": os.path.abspath(args.seed_tables)},
        "gate": res["gate"],
        "summary": {
            "by_status": res["by_status"],
            "by_kind": list(res["by_kind"].values()),
            "tests": res["test_totals"],
            "counts": {"items": len(res["items"]), "code_sites": len(code_sites), "tests": len(tests),
                       "orphan_code_tags": len(res["orphans"]["code_tags"]),
                       "orphan_test_labels": len(res["orphans"]["test_labels"]),
                       "errata": len(srs.errata),
                       "refby_disagreements": 0, "warnings": 0},
        },
        "items": res["items"],
        "tests": tests,
        "code_sites": code_sites,
        "gaps": res["gaps"],
        "links": res["links"],
        "link_summary": res["link_summary"],
        "link_sample": {"seed": link_seed, "size": args.link_sample,
                        "links": links.sample(res["links"], args.link_sample, link_seed)},
        "reviews": reviews,
        "orphans": res["orphans"],
        "category_labels": res["category_labels"],
        "missing_oracle": missing_oracle,
        "missing_oracle_srs": res["missing_oracle_srs"],
        "registration": tinfo["registration"],
        "boost_binaries": tinfo["boost_binaries"],
        "matrices": [{k: m[k] for k in ("id", "number", "caption", "rows", "cols", "row_labels", "col_labels",
                                        "cells", "empty_rows", "empty_cols")} for m in matrices],
        "seed_tables": seed_cmp,
        "errata": srs.errata,
        "refby_disagreements": srsdata.refby_disagreements(srs),
        "checker": checker,
        "graphs": gr,
        "verification": programs,
        "bench_records": records,
        "mutation_reference": mutation_ref,
        "module_reach_reference": reach_ref,
        "builds": builds.evidence_builds(build_dir, build_prov, programs +
                                         ([{"program": "coverage", "provenance": coverage["provenance"]}]
                                          if coverage and coverage.get("provenance") else [])),
        "provenance": {"build": build_prov, "source_commit": source_commit, "source_tree": source_tree,
                       "build_problems": build_problems,
                       "expected_programs": expected, "missing_programs": missing,
                       "optional_programs": list(optional), "not_run_programs": not_run,
                       "refused": [{"program": p["program"], "file": p["file"],
                                    "reason": p["refused"]} for p in programs if p.get("refused")]},
        "coverage": coverage,
        "run": run_manifest,
        "warnings": warnings,
    }
    report["summary"]["counts"]["refby_disagreements"] = len(report["refby_disagreements"])
    checker["agreement"] = compare_checker(report["refby_disagreements"], checker.get("disagreements"))
    if checker["agreement"] and not checker["agreement"]["agrees"]:
        warnings.append("srs/check_srs.py and the harness disagree on Ref. By disagreements: " +
                        checker["agreement"]["summary"])
    report["summary"]["counts"]["warnings"] = len(warnings) + len(tinfo["registration"])
    warnings += tinfo["registration"]

    # Paths under the source root are written relative to it: the same results give the same
    # bytes wherever the checkout lies (reproducible.py); the ReqIF file is of the JSON.
    reproducible.portable(report, source)
    js = dict(report)
    js["graphs"] = [{k: v for k, v in g.items() if k != "inline"} for g in report["graphs"]]
    js["items"] = [{k: v for k, v in i.items()} for i in report["items"]]
    reqif_text = reqif.attach(report, js)
    report["_out_path"] = out  # where render_html looks for files beside the report
    with open(os.path.join(out, "index.html"), "w", encoding="utf-8") as fh:
        fh.write(render_html.render(report))
    with open(os.path.join(out, "traceability.md"), "w", encoding="utf-8") as fh:
        fh.write(render_md.render(report))
    with open(os.path.join(out, "traceability.json"), "w", encoding="utf-8") as fh:
        fh.write(reproducible.dumps(js))
    with open(os.path.join(out, reqif.FILE_NAME), "w", encoding="utf-8") as fh:
        fh.write(reqif_text)
    return report


def compare_checker(own, theirs):
    """Do srs/check_srs.py and the harness flag the same items? (None when not comparable.)"""
    if not isinstance(theirs, list):
        return None
    labels = set()
    for d in theirs:
        if isinstance(d, dict) and d.get("label"):
            labels.add(str(d["label"]))
        elif isinstance(d, str):
            labels.add(d.split(":")[0].strip())
    mine = {d["label"] for d in own}
    only_checker = sorted(labels - mine)
    only_harness = sorted(mine - labels)
    agrees = not only_checker and not only_harness
    summary = (f"both flag the same {len(mine)} item(s)" if agrees else
               f"only the checker flags {', '.join(only_checker) or 'none'}; "
               f"only the harness flags {', '.join(only_harness) or 'none'}")
    return {"agrees": agrees, "only_checker": only_checker, "only_harness": only_harness,
            "summary": summary}


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    if not os.path.isdir(args.source):
        print(f"build_report: --source {args.source} is not a directory", file=sys.stderr)
        return 2
    report = build(args, log=(lambda m: None) if args.quiet else (lambda m: print(m, file=sys.stderr)))
    g = report["gate"]
    if not args.quiet:
        s = report["summary"]["by_status"]
        out = report["_out_path"]
        print(f"[traceability] {len(report['items'])} items: " + ", ".join(f"{v} {k}" for k, v in s.items()),
              file=sys.stderr)
        print(f"[traceability] gate {'PASS' if g['passed'] else 'FAIL'}; report: {os.path.join(out, 'index.html')}",
              file=sys.stderr)
        for r in g["reasons"]:
            print(f"[traceability]   - {r}", file=sys.stderr)
    return g["exit_code"]


if __name__ == "__main__":
    sys.exit(main())
