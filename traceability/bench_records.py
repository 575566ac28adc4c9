"""The dated benchmark records (verification/bench/results/<machine>/*.json), as data and a plot.

A record's run is true of its commit, machine and date only (verification/bench/results/README.md);
the report shows them beside the checkout's own benchmark so that a reader sees how the step time
of each scene and engine moved from run to run. Only the step times of ``tamias_bench`` runs are
taken (thread CPU time, each engine's defaults, one thread: a run whose command is another
program, such as ``tamias_thread_bench``'s wall-clock runs on several workers or with manifold
reuse off, measures something else): tables whose name says "ms/step" and whose first column is
the scene, in either of the records' two forms:

* one column per engine (``Tamias2D``, ``Chipmunk 7``, ``Box2D 2.4``, ``v3 AVX2`` ...), a number
  per cell; ratio columns (``Tamias2D / v3 AVX2``, ``vs Chipmunk 7``) are not engines;
* a ``figure`` column, the rows whose figure is ``<engine> ms/step``, one column per run: the
  point is the median of the runs (the README's noise rule), with their range.

Cells that are not numbers (several runs or worker counts in one string, wall-clock tables of the
threads) are left out and counted. Written: ``bench_records/ms_per_step.csv`` (every point) and
``bench_records/ms_per_step.svg`` (one panel per scene, ms/step by date, a colour per engine and
a marker per machine).
"""
from __future__ import annotations

import csv
import glob
import io
import json
import os
import re
import statistics
import subprocess

RESULTS = os.path.join("verification", "bench", "results")
OUT_DIR = "bench_records"
CSV_NAME = "ms_per_step.csv"
SVG_NAME = "ms_per_step.svg"
CSV_COLUMNS = ["date", "machine", "scene", "engine", "ms_per_step", "runs", "low", "high",
               "commit", "record", "run", "table"]

# The benchmark program itself, not tamias_thread_bench, tamias_stage_gbench ...
BENCH_COMMAND = re.compile(r"(^|[\s/])tamias_bench(\s|$)")
# Column names of the records, by engine, as the benchmark names the engines.
ENGINE_NAMES = {"Tamias2D": "Tamias2D", "Chipmunk 7": "Chipmunk 7", "Box2D 2.4": "Box2D 2.4",
                "Box2D v3 SSE2": "Box2D v3 SSE2", "v3 SSE2": "Box2D v3 SSE2",
                "Box2D v3 AVX2": "Box2D v3 AVX2", "v3 AVX2": "Box2D v3 AVX2"}


def _number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _engine_of_figure(figure):
    """'Tamias2D ms/step' -> 'Tamias2D'; anything else (speed-ups, ratios) -> None."""
    if not isinstance(figure, str) or not figure.endswith(" ms/step"):
        return None
    return ENGINE_NAMES.get(figure[: -len(" ms/step")].strip())


def points_of_table(table):
    """[(scene, engine, value, runs, low, high)] of one table, and the number of cells left out
    (not numbers). [] when the table is not of ms/step by scene."""
    cols = [str(c) for c in table.get("columns") or []]
    if "ms/step" not in str(table.get("name", "")) or not cols or cols[0] != "scene":
        return [], 0
    out, skipped = [], 0
    if len(cols) > 1 and cols[1] == "figure":
        for row in table.get("rows") or []:
            engine = _engine_of_figure(row[1] if len(row) > 1 else None)
            if engine is None:
                continue
            values = [v for v in row[2:] if _number(v)]
            skipped += len(row[2:]) - len(values)
            if values:
                out.append((str(row[0]), engine, statistics.median(values), len(values),
                            min(values), max(values)))
        return out, skipped
    engines = [(k, ENGINE_NAMES[c]) for k, c in enumerate(cols) if c in ENGINE_NAMES]
    for row in table.get("rows") or []:
        for k, engine in engines:
            v = row[k] if k < len(row) else None
            if _number(v):
                out.append((str(row[0]), engine, float(v), 1, float(v), float(v)))
            elif v is not None:  # null: not run (over the peer's budget)
                skipped += 1
    return out, skipped


def collect(source, warnings=None):
    """Every point of the records under <source>/verification/bench/results, sorted by date,
    machine, scene, engine and record. Returns {"points": [...], "records": n, "left_out": n}."""
    warnings = warnings if warnings is not None else []
    points, records, left_out = [], 0, 0
    for path in sorted(glob.glob(os.path.join(source, RESULTS, "*", "*.json"))):
        rel = os.path.relpath(path, os.path.join(source, "verification", "bench")).replace(os.sep, "/")
        try:
            with open(path, encoding="utf-8") as fh:
                doc = json.load(fh)
        except (OSError, ValueError) as exc:
            warnings.append(f"bench record {rel} unreadable: {exc}")
            continue
        machine = str((doc.get("machine") or {}).get("name") or os.path.basename(os.path.dirname(path)))
        records += 1
        for order, run in enumerate(doc.get("runs") or []):
            if not BENCH_COMMAND.search(str(run.get("command") or "")):
                continue
            for table in run.get("tables") or []:
                found, skipped = points_of_table(table)
                left_out += skipped
                for scene, engine, value, runs, low, high in found:
                    points.append({"date": str(run.get("date")), "machine": machine, "scene": scene,
                                   "engine": engine, "ms_per_step": value, "runs": runs,
                                   "low": low, "high": high, "commit": run.get("commit"),
                                   "record": rel, "run": str(run.get("id")), "order": order,
                                   "table": str(table.get("name", ""))})
    # Within a day, by the commit's time where the checkout knows the commit, else as the files
    # list their runs (the order they were made).
    when = commit_times(source, {p["commit"] for p in points if p["commit"]})
    points.sort(key=lambda p: (p["date"], when.get(p["commit"], 0), p["record"], p["order"],
                               p["machine"], p["scene"], p["engine"]))
    for p in points:
        del p["order"]
    return {"points": points, "records": records, "left_out": left_out}


def commit_times(source, commits):
    """{commit: committer time (s)} of the commits the checkout at source holds; {} without git."""
    commits = sorted(c for c in commits if re.fullmatch(r"[0-9a-f]{7,40}", str(c)))
    if not commits:
        return {}
    try:
        proc = subprocess.run(["git", "-C", source, "show", "-s", "--format=%H %ct", *commits],
                              capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired):
        return {}
    times = {}
    for line in proc.stdout.splitlines():  # an unknown commit ends the listing: what came is kept
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            times[parts[0]] = int(parts[1])
    return {c: t for c in commits for h, t in times.items() if h.startswith(c)}


def csv_text(points):
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS)
    for p in points:
        w.writerow([p["ms_per_step"] if c == "ms_per_step" else
                    ("" if p.get(c) is None else p[c]) for c in CSV_COLUMNS])
    return buf.getvalue()


SCENE_ORDER = ["elastic2", "pyramid20", "pyramid40", "large_pyramid", "rain", "pyramid40_sleep",
               "many_pyramids", "rain_1k", "rain_2k", "rain_4k", "rain_8k", "rain_16k", "joint_grid",
               "chain", "heavy_chain_100", "heavy_chain_1000"]
ENGINE_ORDER = ["Tamias2D", "Box2D v3 AVX2", "Box2D v3 SSE2", "Chipmunk 7", "Box2D 2.4"]
MARKERS = ["o", "s", "^", "D", "v", "P"]


def _run_key(p):
    return (p["date"], p["commit"])


def render(data, out_dir, warnings=None):
    """Writes the CSV and the plot into <out_dir>/bench_records/; sets data["csv"] and
    data["svg"] (relative paths; svg None when nothing to plot or no matplotlib)."""
    warnings = warnings if warnings is not None else []
    points = data["points"]
    d = os.path.join(out_dir, OUT_DIR)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, CSV_NAME), "w", encoding="utf-8") as fh:
        fh.write(csv_text(points))
    data["csv"] = f"{OUT_DIR}/{CSV_NAME}"
    data["svg"] = None
    if not points:
        return data
    try:
        import matplotlib
        matplotlib.use("Agg")
        matplotlib.rcParams["svg.hashsalt"] = "tamias2d"
        matplotlib.rcParams["svg.fonttype"] = "none"
        import matplotlib.pyplot as plt
    except Exception as exc:  # pragma: no cover - matplotlib is a Debian package here
        warnings.append(f"matplotlib unavailable, no plot of the bench records: {exc}")
        return data
    scenes = sorted({p["scene"] for p in points},
                    key=lambda s: (SCENE_ORDER.index(s) if s in SCENE_ORDER else len(SCENE_ORDER), s))
    # One place on the axis per date and commit: runs of one day at two commits stand apart.
    runs = []
    for p in points:  # sorted by date, then as the files list their runs
        if _run_key(p) not in runs:
            runs.append(_run_key(p))
    machines = sorted({p["machine"] for p in points})
    engines = [e for e in ENGINE_ORDER if any(p["engine"] == e for p in points)]
    cycle = matplotlib.rcParams["axes.prop_cycle"].by_key().get("color") or ["C0"]
    colour = {e: cycle[k % len(cycle)] for k, e in enumerate(engines)}
    marker = {m: MARKERS[k % len(MARKERS)] for k, m in enumerate(machines)}
    ncols = 4
    nrows = (len(scenes) + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.2 * ncols, 2.5 * nrows + 0.9), dpi=100,
                             squeeze=False)
    try:
        for k, scene in enumerate(scenes):
            ax = axes[k // ncols][k % ncols]
            for e in engines:
                for m in machines:
                    pts = [p for p in points if p["scene"] == scene and p["engine"] == e
                           and p["machine"] == m]
                    if not pts:
                        continue
                    xs = [runs.index(_run_key(p)) for p in pts]
                    ys = [p["ms_per_step"] for p in pts]
                    lo = [p["ms_per_step"] - p["low"] for p in pts]
                    hi = [p["high"] - p["ms_per_step"] for p in pts]
                    ax.errorbar(xs, ys, yerr=[lo, hi], color=colour[e], marker=marker[m],
                                markersize=4, linewidth=1.0, capsize=2)
            ax.set_title(scene, fontsize=9)
            ax.set_xticks(range(len(runs)))
            ax.set_xticklabels([f"{d[5:]} {(c or 'no commit')[:7]}" for d, c in runs], fontsize=6,
                               rotation=45, ha="right")
            ax.set_xlim(-0.5, len(runs) - 0.5)
            ax.tick_params(axis="y", labelsize=7)
            ax.set_ylim(bottom=0)
            ax.grid(True, alpha=0.3)
            if k % ncols == 0:
                ax.set_ylabel("ms/step", fontsize=8)
        for k in range(len(scenes), nrows * ncols):
            axes[k // ncols][k % ncols].axis("off")
        handles = [plt.Line2D([], [], color=colour[e], linewidth=2, label=e) for e in engines]
        handles += [plt.Line2D([], [], color="#555555", marker=marker[m], linestyle="none", label=m)
                    for m in machines]
        fig.legend(handles=handles, loc="upper center", ncol=min(len(handles), 4), fontsize=7,
                   frameon=False)
        fig.suptitle(f"Dated records: ms/step by date ({runs[0][0][:4]}) and commit, one thread", fontsize=10,
                     y=0.005, va="bottom")
        fig.tight_layout(rect=(0, 0.03, 1, 1 - 0.5 / (2.5 * nrows + 0.9)))
        fig.savefig(os.path.join(d, SVG_NAME), format="svg", metadata={"Date": None})
        data["svg"] = f"{OUT_DIR}/{SVG_NAME}"
    except Exception as exc:
        warnings.append(f"plot of the bench records failed: {exc}")
    finally:
        plt.close(fig)
    return data
