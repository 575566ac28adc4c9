#!/usr/bin/python3
"""Writes the main job's phase times (lines "name<TAB>seconds" on standard input) as
OUT.json in the verification schema (docs/traceability.md), for the report to show.

usage: scripts/main_job.sh's phase_times | phase_times.py OUT.json

The report's own phase (running the tests and writing the report) cannot time itself into its
input: the harness's run manifest records when its test run started and finished.
"""
import datetime
import json
import os
import subprocess
import sys


def git(*args):
    try:
        return subprocess.run(["git", *args], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[3], file=sys.stderr)
        return 2
    rows = []
    for line in sys.stdin:
        name, _, secs = line.rstrip("\n").rpartition("\t")
        if name:
            rows.append([name, int(secs)])
    total = sum(r[1] for r in rows)
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    from traceability.builds import tree_key
    doc = {"program": "main_job",
           "description": f"scripts/main_job.sh's phases before the report: {total} s "
                          f"({total / 60:.1f} min) in all on this machine "
                          f"({os.cpu_count()} processors). The report's own phase is in the run "
                          "manifest (Method & warnings).",
           "provenance": {"commit": git("rev-parse", "HEAD") or "unknown",
                          "dirty": bool(git("status", "--porcelain", "--untracked-files=no")),
                          "tree": tree_key("."), "build_id": None, "generated": now},
           "checks": [],
           "tables": [{"name": "Main job phases", "columns": ["phase", "seconds"],
                       "rows": rows + [["in all, before the report", total]]}],
           "series": []}
    os.makedirs(os.path.dirname(os.path.abspath(sys.argv[1])), exist_ok=True)
    with open(sys.argv[1], "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
