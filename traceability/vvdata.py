"""Verification-program results (reports/data/*.json), their plots, and gcovr coverage."""
from __future__ import annotations

import json
import math
import os
import re


def _slug(s):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", str(s)).strip("_") or "x"


def validate(doc):
    """Return a list of schema problems (empty when the document is valid)."""
    errs = []
    if not isinstance(doc, dict):
        return ["top level is not an object"]
    if not isinstance(doc.get("program"), str):
        errs.append("'program' missing or not a string")
    for key in ("checks", "tables", "series"):
        if key in doc and not isinstance(doc[key], list):
            errs.append(f"'{key}' is not a list")
    for i, c in enumerate(doc.get("checks") or []):
        if not isinstance(c, dict):
            errs.append(f"checks[{i}] is not an object")
            continue
        if not isinstance(c.get("name"), str):
            errs.append(f"checks[{i}].name missing")
        if not isinstance(c.get("passed"), bool):
            errs.append(f"checks[{i}].passed is not a boolean")
        if not isinstance(c.get("labels", []), list):
            errs.append(f"checks[{i}].labels is not a list")
    for i, t in enumerate(doc.get("tables") or []):
        if not isinstance(t, dict) or not isinstance(t.get("columns"), list) or not isinstance(t.get("rows"), list):
            errs.append(f"tables[{i}] needs 'columns' and 'rows' lists")
    for i, s in enumerate(doc.get("series") or []):
        if not isinstance(s, dict) or not isinstance(s.get("lines"), list):
            errs.append(f"series[{i}] needs a 'lines' list")
            continue
        for j, ln in enumerate(s["lines"]):
            if not isinstance(ln, dict) or len(ln.get("x") or []) != len(ln.get("y") or []):
                errs.append(f"series[{i}].lines[{j}]: x and y must be lists of equal length")
    return errs


def load_data_dir(data_dir, warnings):
    """Returns (programs, coverage). Programs are the valid documents with their file name."""
    programs, coverage = [], None
    if not os.path.isdir(data_dir):
        return programs, coverage
    for fn in sorted(os.listdir(data_dir)):
        if not fn.endswith(".json"):
            continue
        path = os.path.join(data_dir, fn)
        try:
            with open(path, encoding="utf-8") as fh:
                doc = json.load(fh)
        except (OSError, ValueError) as exc:
            warnings.append(f"data/{fn}: unreadable JSON ({exc})")
            programs.append({"file": fn, "program": fn, "invalid": [f"unreadable: {exc}"],
                             "checks": [], "tables": [], "series": []})
            continue
        if fn == "coverage.json":
            coverage = doc
            continue
        errs = validate(doc)
        if errs:
            warnings.append(f"data/{fn}: does not follow the verification schema: " + "; ".join(errs[:5]))
        if not isinstance(doc, dict):
            doc = {}
        prov = doc.get("provenance")
        programs.append({"file": fn, "program": str(doc.get("program") or fn),
                         "description": doc.get("description", ""), "invalid": errs,
                         "provenance": prov if isinstance(prov, dict) else None, "refused": None,
                         "checks": [c for c in doc.get("checks") or [] if isinstance(c, dict)],
                         "tables": [t for t in doc.get("tables") or [] if isinstance(t, dict)],
                         "series": [s for s in doc.get("series") or [] if isinstance(s, dict)]})
    return programs, coverage


def load_build_provenance(build_dir):
    """<build>/provenance.json (cmake/TamiasProvenance.cmake), or None."""
    path = os.path.join(build_dir, "provenance.json")
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError):
        return None
    return doc if isinstance(doc, dict) else None


def judge_provenance(programs, expected, build_prov, source_commit, source_tree=None):
    """Refuses results that are not of this checkout and build; returns the expected programs
    that left no results. Sets p["refused"] (a reason) on each refused program.

    A program's results are refused when they carry no provenance, when their commit is not
    the checkout's (source_commit, when known), when their tree (commit and uncommitted
    changes) is not the checkout's (source_tree, when both are known), or when their build id
    (null for a script or a build of its own) is not the build directory's (build_prov, when
    known)."""
    for p in programs:
        prov = p.get("provenance")
        if p.get("invalid") and not p["checks"]:
            continue  # already an error: unreadable
        if not prov or not prov.get("commit") or "build_id" not in prov or not prov.get("generated"):
            p["refused"] = "no provenance (commit, build id, time): results of unknown origin"
        elif source_commit and prov["commit"] != source_commit:
            p["refused"] = (f"stale: results of commit {str(prov['commit'])[:12]}, the checkout is "
                            f"{source_commit[:12]}")
        elif source_tree and prov.get("tree") and prov["tree"] != source_tree:
            p["refused"] = (f"stale: results of tree {str(prov['tree'])[:12]} (uncommitted changes "
                            f"since), the checkout is tree {source_tree[:12]}")
        elif build_prov and prov.get("build_id") is not None and \
                prov["build_id"] != build_prov.get("build_id"):
            p["refused"] = (f"stale: results of build {prov['build_id']}, the build directory is "
                            f"build {build_prov.get('build_id')}")
    present = {p["program"] for p in programs}
    return [name for name in expected if name not in present]


def checks_as_tests(programs, missing=()):
    tests = []
    for name in missing:
        tests.append({"id": f"{name}:<results file>", "name": "<results file>",
                      "origin": "verification", "binary": name, "status": "error", "labels": [],
                      "oracle": None, "file": None, "line": None,
                      "details": f"expected results missing: no data/*.json of program {name}",
                      "samples": None, "enabled": True})
    for p in programs:
        if p.get("refused"):
            tests.append({"id": f"{p['program']}:<provenance>", "name": "<provenance>",
                          "origin": "verification", "binary": p["program"], "status": "error",
                          "labels": [], "oracle": None, "file": f"data/{p['file']}", "line": None,
                          "details": "refused: " + p["refused"], "samples": None, "enabled": True})
        if p["invalid"] and not p["checks"]:
            # An unreadable result file is evidence of a broken verification run.
            tests.append({"id": f"{p['program']}:<results file>", "name": "<results file>",
                          "origin": "verification", "binary": p["program"], "status": "error",
                          "labels": [], "oracle": None, "file": f"data/{p['file']}", "line": None,
                          "details": "; ".join(p["invalid"]), "samples": None, "enabled": True})
        for c in p["checks"]:
            passed = c.get("passed")
            # A check with a "target" states a goal beyond the SRS (e.g. a speed floor): when
            # missed it is listed as such, apart from the failures that gate the exit status.
            target = c.get("target")
            status = "passed" if passed is True else ("target-missed" if target else "failed")
            details = str(c.get("details") or "")
            if p.get("refused"):  # no evidence, whatever it says
                status, details = "error", f"refused ({p['refused']}): {details}"
            tests.append({"id": f"{p['program']}:{c.get('name')}", "name": str(c.get("name")),
                          "origin": "verification", "binary": p["program"],
                          "status": status, "target": str(target) if target else None,
                          "figure": str(c["figure"]) if c.get("figure") else None,
                          "labels": [str(x) for x in c.get("labels") or []],
                          "oracle": c.get("oracle"), "file": f"data/{p['file']}", "line": None,
                          "details": details, "samples": None, "enabled": True})
    return tests


def _label_short_log_axis(axis, lim, ticker):
    """A log axis of less than two decades shows too few powers of ten to read a value by: its
    ticks are labelled as plain numbers, and the minor ticks at 2 and 5 (also 3 within a decade)."""
    lo, hi = min(lim), max(lim)
    if not (lo > 0 and hi > lo) or math.log10(hi / lo) >= 2:
        return
    keep = {2, 5} if math.log10(hi / lo) > 1 else {2, 3, 5}

    def minor(v, _pos):
        lead = round(v / 10 ** math.floor(math.log10(v) + 1e-9))
        return f"{v:g}" if lead in keep else ""
    axis.set_major_formatter(ticker.FuncFormatter(lambda v, _pos: f"{v:g}"))
    axis.set_minor_formatter(ticker.FuncFormatter(minor))


def render_plots(programs, out_dir, warnings):
    """One SVG per series into <out_dir>/plots/. Sets series['svg'] (relative path)."""
    series_all = [(p, s) for p in programs for s in p["series"]]
    if not series_all:
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        matplotlib.rcParams["svg.hashsalt"] = "tamias2d"
        matplotlib.rcParams["svg.fonttype"] = "none"
        import matplotlib.pyplot as plt
        from matplotlib import ticker
    except Exception as exc:  # pragma: no cover - matplotlib is a Debian package here
        warnings.append(f"matplotlib unavailable, no plots: {exc}")
        return
    plot_dir = os.path.join(out_dir, "plots")
    os.makedirs(plot_dir, exist_ok=True)
    used = set()
    for p, s in series_all:
        name = f"{_slug(p['program'])}__{_slug(s.get('name'))}"
        base, n = name, 2
        while name in used:
            name, n = f"{base}_{n}", n + 1
        used.add(name)
        fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=100)
        try:
            colours = {}  # a line's "group": the lines of one group share a colour
            cycle = matplotlib.rcParams["axes.prop_cycle"].by_key().get("color") or ["C0"]
            for ln in s.get("lines") or []:
                xs, ys = ln.get("x") or [], ln.get("y") or []
                if len(xs) != len(ys):
                    continue
                names = ln.get("point_labels")
                if not isinstance(names, list) or len(names) != len(xs):
                    names = [None] * len(xs)
                pts = [(x, y, t) for x, y, t in zip(xs, ys, names) if x is not None and y is not None]
                if s.get("log_x"):
                    pts = [q for q in pts if q[0] > 0]
                if s.get("log_y"):
                    pts = [q for q in pts if q[1] > 0]
                if not pts:
                    continue
                style = {}
                group = ln.get("group")
                if group is not None:
                    style["color"] = colours.setdefault(str(group), cycle[len(colours) % len(cycle)])
                if ln.get("style") == "points":  # marks only
                    style.update(linestyle="none", marker="o", markersize=4)
                elif ln.get("style") == "line":  # a line only
                    style.update(marker=None, linewidth=1.4)
                else:
                    style.update(marker="o" if len(pts) <= 30 else None, markersize=3, linewidth=1.4)
                line, = ax.plot([q[0] for q in pts], [q[1] for q in pts],
                                label=str(ln.get("label", "")), **style)
                for x, y, t in pts:
                    if t is not None:
                        ax.annotate(str(t), (x, y), textcoords="offset points", xytext=(3, 3),
                                    fontsize=6, color=line.get_color())
            if s.get("log_x"):
                ax.set_xscale("log")
            if s.get("log_y"):
                ax.set_yscale("log")
            for axis, log, lim in ((ax.xaxis, s.get("log_x"), ax.get_xlim()),
                                   (ax.yaxis, s.get("log_y"), ax.get_ylim())):
                if log:
                    _label_short_log_axis(axis, lim, ticker)
            ax.set_xlabel(str(s.get("x_label", "")))
            ax.set_ylabel(str(s.get("y_label", "")))
            ax.set_title(str(s.get("name", "")), fontsize=11)
            ax.grid(True, which="both", alpha=0.3)
            if any(ln.get("label") for ln in s.get("lines") or []):
                ax.legend(fontsize=8)
            fig.tight_layout()
            path = os.path.join(plot_dir, name + ".svg")
            fig.savefig(path, format="svg", metadata={"Date": None})
            s["svg"] = f"plots/{name}.svg"
        except Exception as exc:
            warnings.append(f"plot {p['program']}/{s.get('name')} failed: {exc}")
        finally:
            plt.close(fig)


def coverage_summary(cov):
    """Normalise a gcovr --json-summary document."""
    if not isinstance(cov, dict):
        return None
    files = []
    for f in cov.get("files") or []:
        files.append({k: f.get(k) for k in ("filename", "line_total", "line_covered", "line_percent",
                                            "function_total", "function_covered", "function_percent",
                                            "branch_total", "branch_covered", "branch_percent")})
    files.sort(key=lambda f: (f.get("line_percent") if f.get("line_percent") is not None else 101,
                              f.get("filename") or ""))
    tot = {k: cov.get(k) for k in ("line_total", "line_covered", "line_percent", "function_total",
                                   "function_covered", "function_percent", "branch_total",
                                   "branch_covered", "branch_percent")}
    prov = cov.get("provenance") if isinstance(cov.get("provenance"), dict) else None
    return {"totals": tot, "files": files, "format": cov.get("gcovr/summary_format_version"),
            "provenance": prov}
