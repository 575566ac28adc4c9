#!/usr/bin/python3
"""Module reach: does the engine run each labelled model module, and do the engine's tests of
its item notice when the module's formula is wrong?

An item's engine tests pass on a module only if the engine evaluates that module: a formula
written again elsewhere would pass them whatever the module says. So each perturbation of
perturbations.py (a sign flipped, a term negated: the module's formula made wrong) is built in
a scratch copy of the repository (verification/mutation/mutate.py's scratch, sync and build)
and judged by the engine-level tests, every CTest entry but the model unit tests
(model_tests@...) and the compile-fail checks:

  verified     an entry labelled with the module's item fails: the engine runs the module and
               the item's engine tests notice (a perturbation may name the items that judge
               it instead, `judged_by`: a module function the engine runs for another item);
  reached      no entry of the item fails, another engine test does (the golden hashes, another
               item's): the engine runs the module, but the item's engine tests do not notice;
  not reached  no engine test fails (or nothing the perturbation touches is compiled into them):
               the engine does not evaluate the formula there.

An item marked `engine: model-only` or `engine: property` in srs/ (srs/README.md: the engine
does not evaluate its formula) must come out "not reached" (a perturbation noticed by the engine
means the marking is wrong); every other item must come out "verified". Without a build (--check), the perturbations are checked against the tree: each
applies exactly once, every model module has at least one, and every TM, GD, DD and IM item of
srs/ has a module.

    /usr/bin/python3 verification/model_reach/module_reach.py OUT_DIR [--subset damping]
        [--only LABEL,...] [--first LABEL,...] [--breadth] [--lazy] [--resume]
        [--scratch DIR] [--test-timeout S]
    /usr/bin/python3 verification/model_reach/module_reach.py --check
    /usr/bin/python3 verification/model_reach/module_reach.py --list

Writes OUT_DIR/module_reach.json in the verification schema (docs/traceability.md), again
after each perturbation (a run cut short says how many it judged; --resume keeps the rows of
that file when it is of the same tree and judges the rest). The scratch is mutate.py's
(/tmp/tamias-mutation-<uid>-<hash of the checkout's path>, the main job's coverage and mutation
build, kept instrumented when it is): after a mutation run it rebuilds in seconds. It is locked
for the run: a second module reach on it stops.
"""
import argparse
import datetime
import fnmatch
import json
import os
import re
import sys
import time

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "verification", "mutation"))
sys.path.insert(0, HERE)
import mutate  # noqa: E402
import perturbations as spec  # noqa: E402

MODEL_DIR = "src/tamias2d/model"
TAG = re.compile(r"\\srs\{([A-Za-z0-9_]+)\}")
MODEL_KINDS = {"TM", "GD", "DD", "IM"}
# srs/'s engine values of items whose formula the engine does not evaluate (srs/README.md).
ENGINE_NOT_EVALUATED = ("model-only", "property")
SRS_FILES = ("theoretical_models.yaml", "general_definitions.yaml", "data_definitions.yaml",
             "instance_models.yaml", "data_constraints.yaml")
# Entries that are not the engine's: the model unit tests (the modules alone) and the
# compile-fail checks (the types alone).
NOT_ENGINE = re.compile(r"^(model_tests@|model_tests\.|compile_fail\.)")


# ------------------------------------------------------------------------------- the tree
def module_files(root):
    d = os.path.join(root, MODEL_DIR)
    return sorted(f for f in os.listdir(d) if f.endswith(".hpp"))


def module_label(root, name):
    """The one SRS label a module's \\srs tags name (a module is one item's)."""
    with open(os.path.join(root, MODEL_DIR, name), encoding="utf-8") as fh:
        labels = sorted(set(TAG.findall(fh.read())))
    if len(labels) != 1:
        raise SystemExit(f"{MODEL_DIR}/{name}: its \\srs tags name {labels or 'no item'}, "
                         "not exactly one")
    return labels[0]


def srs_items(root):
    """{label: item} of srs/'s TM, GD, DD, IM and DC items."""
    out = {}
    for f in SRS_FILES:
        with open(os.path.join(root, "srs", f), encoding="utf-8") as fh:
            for it in yaml.safe_load(fh) or []:
                out[it["label"]] = it
    return out


def apply(text, p):
    """The module's text with perturbation p applied; an error unless its `old` occurs exactly
    once."""
    n = text.count(p.old)
    if n != 1:
        raise ValueError(f"{p.module}: {p.name}: the text to perturb occurs {n} times, not once")
    if p.old == p.new:
        raise ValueError(f"{p.module}: {p.name}: the perturbation changes nothing")
    return text.replace(p.old, p.new, 1)


def check_tree(root, perturbations=None, subsets=None):
    """Problems of the perturbations against the tree (no build): each applies exactly once, every
    module has one, every module is one item's, every TM/GD/DD/IM item has a module."""
    perturbations = spec.PERTURBATIONS if perturbations is None else perturbations
    subsets = spec.SUBSETS if subsets is None else subsets
    problems = []
    files = module_files(root)
    labels = {}
    for f in files:
        try:
            labels[f] = module_label(root, f)
        except SystemExit as e:
            problems.append(str(e))
    seen = set()
    for p in perturbations:
        if p.module not in files:
            problems.append(f"{p.name}: no model module {p.module}")
            continue
        seen.add(p.module)
        with open(os.path.join(root, MODEL_DIR, p.module), encoding="utf-8") as fh:
            try:
                apply(fh.read(), p)
            except ValueError as e:
                problems.append(str(e))
    for f in files:
        if f not in seen:
            problems.append(f"{MODEL_DIR}/{f}: no perturbation (perturbations.py)")
    names = [(p.module, p.name) for p in perturbations]
    for dup in sorted({n for n in names if names.count(n) > 1}):
        problems.append(f"{dup[0]}: two perturbations named {dup[1]}")
    items = srs_items(root)
    have = set(labels.values())
    for lab, it in sorted(items.items()):
        if it.get("kind") in MODEL_KINDS and lab not in have:
            problems.append(f"{lab}: no model module in {MODEL_DIR}")
    for p in perturbations:
        for lab in p.judged_by:
            if lab not in items:
                problems.append(f"{p.module}: {p.name}: judged by {lab}, not an SRS item")
    for f, lab in labels.items():
        if lab not in items:
            problems.append(f"{MODEL_DIR}/{f}: {lab} is not an SRS item of {SRS_FILES}")
    for subset, names in sorted(subsets.items()):
        for name in names:
            if name not in have:
                problems.append(f"subset {subset}: {name} has no module")
    return problems


# ------------------------------------------------------------------------------- judging
def engine_entries(catalogue):
    """{CTest name: target} of the engine-level entries (labelled or not)."""
    out = {}
    for t in catalogue:
        name = t["name"]
        if NOT_ENGINE.match(name) or ("@" not in name and not name.endswith(".unlabelled")):
            continue
        out[name] = name.rsplit("@", 1)[0].rsplit(".unlabelled", 1)[0]
    return out


def build_targets(build, entries):
    """Builds the entries' targets; seconds taken."""
    if not entries:
        return 0.0
    t0 = time.monotonic()
    rc, out = mutate.run(["nice", "-n", "5", "cmake", "--build", build, "-j2", "--target",
                          *sorted(set(entries.values()))])
    if rc != 0:
        raise RuntimeError("build failed:\n" + out[-2000:])
    return time.monotonic() - t0


def run_entries(build, entries, timeout):
    """(the first failing entry or None, seconds): runs the entries until one fails."""
    if not entries:
        return None, 0.0
    t0 = time.monotonic()
    regex = "^(" + "|".join(re.escape(n) for n in sorted(entries)) + ")$"
    rc, out = mutate.run(["ctest", "--test-dir", build, "-R", regex, "--stop-on-failure", "-j2",
                          "--timeout", str(timeout)], timeout=timeout * len(entries) + 60)
    secs = time.monotonic() - t0
    if rc is None:
        return "(time-out)", secs
    if rc != 0:
        failed = mutate.failed_entries(out)
        return (failed[0] if failed else f"(ctest exit {rc})"), secs
    return None, secs


def passes_unperturbed(name, build, engine, baseline, timeout):
    """Whether entry name passes on the unperturbed sources (the module restored), asked once
    per entry and remembered in baseline: a failure of a test that fails anyway is no notice."""
    if name not in baseline:
        build_targets(build, {name: engine[name]})
        failed, _ = run_entries(build, {name: engine[name]}, timeout)
        baseline[name] = failed is None
    return baseline[name]


def judge(p, label, src, build, engine, objects, baseline, timeout, unmutated=None):
    """The reach of one perturbation: a result row (dict). The item's own engine entries run
    first, then (if none fails) every other engine entry. A stage whose objects all come out
    bit for bit as the unperturbed ones (the perturbed module is compiled into none of them) is
    not run: its tests would pass as they do unperturbed."""
    judges = set(p.judged_by) or {label}
    own = {n: t for n, t in engine.items() if "@" in n and n.split("@", 1)[1] in judges}
    other = {n: t for n, t in engine.items() if n not in own}
    path = os.path.join(src, MODEL_DIR, p.module)
    with open(path, encoding="utf-8") as fh:
        original = fh.read()
    times = os.stat(path)
    since = None
    row = {"module": p.module, "function": p.name, "label": label, "why": p.why,
           "judged_by": sorted(judges),
           "own_entries": sorted(own), "failed": None, "result": "not reached",
           "build_seconds": 0.0, "test_seconds": 0.0}
    try:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(apply(original, p))
        since = time.time_ns()
        for stage, entries in (("own", own), ("other", other)):
            try:
                row["build_seconds"] += round(build_targets(build, entries), 1)
            except RuntimeError as e:
                row["result"], row["log"] = "does not compile", str(e)[-1500:]
                return row
            rebuilt = mutate.object_digests(build, since)
            if all(objects.get(o) == d for o, d in rebuilt.items()):
                continue
            entries = {n: t for n, t in entries.items() if baseline.get(n, True)}
            failed, secs = run_entries(build, entries, timeout)
            row["test_seconds"] += round(secs, 1)
            if failed in entries and failed not in baseline:
                # Whether it passes unperturbed is asked by judge_reach once the outputs are
                # restored: then it costs no build.
                row["pending"] = failed
            if failed:
                row["failed"] = failed
                row["result"] = "verified" if stage == "own" else "reached"
                return row
        return row
    finally:
        # The source first, with a new time; with unmutated (mutate.Unmutated of the build) the
        # outputs the perturbed build rewrote are put back and the source gets its own time
        # back, so the next perturbation's build compiles only itself, not this restore too.
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(original)
        if unmutated is not None and since is not None and unmutated.restore(since):
            os.utime(path, ns=(times.st_atime_ns, times.st_mtime_ns))


def judge_reach(p, label, src, build, engine, objects, baseline, timeout, unmutated=None):
    """judge(), with a failure that names an entry whose unperturbed run is not yet known
    checked on the restored build (asked once per entry, remembered in baseline): a failure of a
    test that fails anyway is no notice, and the perturbation is judged again without it."""
    while True:
        row = judge(p, label, src, build, engine, objects, baseline, timeout, unmutated)
        name = row.pop("pending", None)
        if name is None or passes_unperturbed(name, build, engine, baseline, timeout):
            return row


def resumed(out_dir, tree, chosen):
    """{(module, function): row} of OUT_DIR/module_reach.json's perturbations, when that file
    is of this tree (a run stopped before its end: --resume), among the chosen ones."""
    try:
        with open(os.path.join(out_dir, "module_reach.json"), encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError):
        return {}
    if (doc.get("provenance") or {}).get("tree") != tree:
        print(f"module reach: {out_dir}/module_reach.json is of another tree: not resumed",
              flush=True)
        return {}
    keys = {(p.module, p.name) for p in chosen}
    return {(r["module"], r["function"]): r for r in doc.get("perturbations", [])
            if (r.get("module"), r.get("function")) in keys}


def hold_scratch(root, scratch):
    """An exclusive lock on the scratch for this run (released when the process ends), and a
    refusal of a scratch inside the tree that the copy would take in."""
    rel = os.path.relpath(os.path.abspath(scratch), os.path.abspath(root))
    if not rel.startswith(".."):
        top = rel.split(os.sep, 1)[0]
        if not any(fnmatch.fnmatch(top, pat) for pat in mutate.IGNORED_AT_TOP):
            raise SystemExit(f"the scratch {scratch} lies inside {root}, where the copy would "
                             "take it in: choose one outside, or under build*/")
    return mutate.lock_scratch(scratch)


def expected(label, items):
    it = items.get(label, {})
    return "not reached" if it.get("engine") in ENGINE_NOT_EVALUATED else "verified"


# ------------------------------------------------------------------------------- main
def breadth_first(chosen):
    """The perturbations reordered: each module's first (in the order given), then each
    module's second, and so on; the order given kept within each rank."""
    nth, seen = {}, {}
    for p in chosen:
        nth[(p.module, p.name)] = seen[p.module] = seen.get(p.module, -1) + 1
    return sorted(chosen, key=lambda p: nth[(p.module, p.name)])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out_dir", nargs="?")
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--scratch", default=None,
                    help="scratch copy and build (default: mutate.py's, /tmp/tamias-mutation-"
                         "<uid>-<hash of the checkout's path>, so that the main job's mutation "
                         "build serves both)")
    ap.add_argument("--subset", choices=sorted(spec.SUBSETS), help="a named subset of items")
    ap.add_argument("--only", help="these items only (comma-separated labels)")
    ap.add_argument("--first", help="judge these items' perturbations before the others "
                                    "(comma-separated labels: a run that may be cut short)")
    ap.add_argument("--breadth", action="store_true",
                    help="judge every module's first perturbation before any module's second, "
                         "and so on (after --first's order): a run that may be cut short "
                         "reaches every module first")
    ap.add_argument("--lazy", action="store_true",
                    help="build the scratch's test executables as the perturbations need them, "
                         "not all of them first: a run that may be cut short starts judging "
                         "sooner (an object first built perturbed is then taken as changed, so "
                         "its tests run)")
    ap.add_argument("--resume", action="store_true",
                    help="keep the rows of OUT_DIR/module_reach.json when it is of this tree (a "
                         "run stopped before its end) and judge only the other perturbations")
    ap.add_argument("--test-timeout", type=int, default=600)
    ap.add_argument("--check", action="store_true", help="check the perturbations, no build")
    ap.add_argument("--list", action="store_true", help="print the perturbations and stop")
    a = ap.parse_args(argv)
    if a.scratch is None:
        a.scratch = mutate.default_scratch(a.root)

    problems = check_tree(a.root)
    if a.check or a.list:
        for p in spec.PERTURBATIONS:
            if a.list:
                print(f"{p.module:48s} {p.name}")
        for msg in problems:
            print("problem: " + msg)
        print(f"module reach: {len(spec.PERTURBATIONS)} perturbations of "
              f"{len(module_files(a.root))} modules; {len(problems)} problems: "
              f"{'FAIL' if problems else 'pass'}")
        return 1 if problems else 0
    if problems:
        raise SystemExit("the perturbations do not fit the tree:\n  " + "\n  ".join(problems))
    if not a.out_dir:
        ap.error("OUT_DIR is required unless --check or --list")
    labels = {f: module_label(a.root, f) for f in module_files(a.root)}
    wanted = None
    if a.subset:
        wanted = set(spec.SUBSETS[a.subset])
    if a.only:
        wanted = (wanted or set()) | {x.strip() for x in a.only.split(",") if x.strip()}
    chosen = [p for p in spec.PERTURBATIONS if wanted is None or labels[p.module] in wanted]
    if a.first:
        first = [x.strip() for x in a.first.split(",") if x.strip()]
        rank = {lab: i for i, lab in enumerate(first)}
        chosen.sort(key=lambda p: rank.get(labels[p.module], len(rank)))  # stable
    if a.breadth:
        chosen = breadth_first(chosen)
    items = srs_items(a.root)
    lock = hold_scratch(a.root, a.scratch)  # noqa: F841 (held until the process ends)
    coverage = instrumented(a.scratch)
    commit, dirty = mutate.commit_of(a.root)
    run = {"commit": commit, "dirty": dirty, "tree": mutate.tree_of(a.root),
           "build": mutate.scratch_build(a.scratch, coverage), "chosen": len(chosen),
           "started": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")}
    t_prep = time.monotonic()
    src, build, catalogue, objects = mutate.prepare_scratch(a.root, a.scratch, coverage,
                                                            build_all=not a.lazy)
    run["prep_secs"] = time.monotonic() - t_prep
    engine = engine_entries(catalogue)
    # A lazy scratch holds no outputs to restore: each perturbation's build then rebuilds the
    # restored module as well, as an interrupted restore does.
    unmutated = None if a.lazy else mutate.Unmutated(build)
    done = resumed(a.out_dir, run["tree"], chosen) if a.resume else {}
    if a.resume:
        print(f"module reach: {len(done)} of {len(chosen)} perturbations judged before",
              flush=True)
    baseline = {}
    rows = []
    t_judging = time.monotonic()
    for p in chosen:
        if (p.module, p.name) in done:
            rows.append(done[(p.module, p.name)])
            continue
        t0 = time.monotonic()
        row = judge_reach(p, labels[p.module], src, build, engine, objects, baseline,
                          a.test_timeout, unmutated)
        row["expected"] = expected(row["label"], items)
        row["seconds"] = round(time.monotonic() - t0, 1)
        rows.append(row)
        print(f"{row['result']:12s} {row['label']:10s} {p.module}:{p.name} ({row['seconds']:.0f} s"
              f"{', ' + row['failed'] if row['failed'] else ''})", flush=True)
        # Written after each perturbation: a run cut short leaves what it judged, and says so.
        run["judging_secs"] = time.monotonic() - t_judging
        write(a, rows, items, labels, run, quiet=True)
    write(a, rows, items, labels, run)
    bad = [r for r in rows if r["result"] != r["expected"]]
    return 1 if bad else 0


def instrumented(scratch):
    """Whether the scratch build is the instrumented one (the main job's coverage and mutation
    build): configured so again, it is rebuilt incrementally instead of from the start."""
    try:
        with open(os.path.join(scratch, "build", "CMakeCache.txt"), encoding="utf-8") as fh:
            return "TAMIAS_COVERAGE:BOOL=ON" in fh.read()
    except OSError:
        return False


def summarise(rows, items, labels):
    """Per item: the results of its perturbations, and whether they are what srs/ says."""
    per = {}
    for r in rows:
        per.setdefault(r["label"], []).append(r)
    out = []
    for lab in sorted(per, key=mutate_key):
        rs = per[lab]
        exp = expected(lab, items)
        results = sorted({r["result"] for r in rs})
        ok = all(r["result"] == exp for r in rs)
        out.append({"label": lab, "modules": sorted({r["module"] for r in rs}),
                    "expected": exp, "results": results, "as_expected": ok,
                    "perturbations": len(rs)})
    return out


def mutate_key(label):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", label)]


def write(a, rows, items, labels, run, quiet=False):
    finished = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
    per_item = summarise(rows, items, labels)
    engine_items = [s for s in per_item if s["expected"] == "verified"]
    model_only = [s for s in per_item if s["expected"] == "not reached"]
    off = [r for r in rows if r["result"] != r["expected"]]
    scope = a.subset and f"subset {a.subset}" or (a.only and f"items {a.only}") or "every module"
    cut = len(rows) < run["chosen"]
    cut_note = f", cut short: {len(rows)} of {run['chosen']} judged" if cut else ""
    details = (f"{len(rows)} perturbations of {len({r['module'] for r in rows})} modules "
               f"({scope}{cut_note}); "
               f"{sum(r['result'] == 'verified' for r in rows)} verified through the "
               f"engine by their item's tests, {sum(r['result'] == 'reached' for r in rows)} "
               f"reached by other engine tests only, "
               f"{sum(r['result'] == 'not reached' for r in rows)} not reached; "
               f"{len(off)} not as srs/ states; scratch build {run['prep_secs']:.0f} s, "
               f"{run.get('judging_secs', 0.0):.0f} s judging")
    doc = {
        "program": "module_reach",
        "description": "Each model module's formula perturbed (a sign flipped) in a scratch "
                       "copy and judged by the engine-level tests (every CTest entry but the "
                       "model unit tests): verified (the item's own engine tests fail), reached "
                       "(only other engine tests fail) or not reached (none does). An item "
                       "marked engine: model-only or property in srs/ must be not reached, every other "
                       "verified. This run: " + details + ".",
        "provenance": {"commit": run["commit"], "dirty": run["dirty"], "tree": run["tree"],
                       "build_id": None, "built": run["started"], "generated": finished,
                       "build": run["build"]},
        "checks": [
            {"name": "every perturbation chosen was judged", "labels": [], "passed": not cut,
             "oracle": "the run's own count", "details": f"{len(rows)} of {run['chosen']}"},
            {"name": "every module the engine runs is noticed by its item's engine tests",
             "labels": [], "passed": all(s["as_expected"] for s in engine_items),
             "target": "verified", "oracle": "the item's own engine-level tests fail on the "
             "perturbed module", "details": "; ".join(
                 f"{s['label']}: {', '.join(s['results'])}" for s in engine_items
                 if not s["as_expected"]) or "all verified"},
            {"name": "every module the engine does not evaluate (srs/: model-only, property) "
                     "is unnoticed by the engine's tests",
             "labels": [], "passed": all(s["as_expected"] for s in model_only),
             "target": "not reached", "oracle": "no engine-level test fails on the perturbed "
             "module", "details": "; ".join(
                 f"{s['label']}: {', '.join(s['results'])}" for s in model_only
                 if not s["as_expected"]) or "all not reached"},
        ],
        "tables": [
            {"name": "Items", "columns": ["item", "module", "srs/ says", "perturbations",
                                          "result"],
             "rows": [[s["label"], ", ".join(s["modules"]),
                       (items.get(s["label"], {}).get("engine") or "engine").replace("-", " "),
                       s["perturbations"], ", ".join(s["results"])] for s in per_item]},
            {"name": "Perturbations", "columns": ["item", "module", "function", "perturbation",
                                                  "judged by", "result", "first failing entry",
                                                  "seconds"],
             "rows": [[r["label"], r["module"], r["function"], r["why"],
                       ", ".join(r["judged_by"]), r["result"], r["failed"] or "", r["seconds"]]
                      for r in rows]},
        ],
        "series": [],
        "summary": details,
        "scratch_build_seconds": round(run["prep_secs"], 1),
        "judging_seconds": round(run.get("judging_secs", 0.0), 1),
        "perturbations": rows,
        "items": per_item,
    }
    os.makedirs(a.out_dir, exist_ok=True)
    with open(os.path.join(a.out_dir, "module_reach.json"), "w", encoding="utf-8") as fh:
        json.dump(doc, fh, indent=1)
    if not quiet:
        print("module reach: " + details)


if __name__ == "__main__":
    sys.exit(main())
