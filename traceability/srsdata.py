"""Load the SRS-as-data (srs/*.yaml) without depending on srs/check_srs.py internals.

The loader is deliberately tolerant: it reports problems as warnings instead of refusing to
build a report, because an auditor needs the report most when the data is broken.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import tempfile
from dataclasses import dataclass, field

import yaml

# Display order and long names of the kinds (seed SRS section order).
KIND_ORDER = ["GS", "A", "TM", "GD", "DD", "IM", "DC", "R", "NFR", "LC", "UC"]
KIND_NAMES = {
    "GS": "Goal statements",
    "A": "Assumptions",
    "TM": "Theoretical models",
    "GD": "General definitions",
    "DD": "Data definitions",
    "IM": "Instance models",
    "DC": "Data constraints",
    "R": "Functional requirements",
    "NFR": "Non-functional requirements",
    "LC": "Likely changes",
    "UC": "Unlikely changes",
}
# One file per kind (the srs/ interface). errata.yaml is loaded separately.
SRS_FILES = [
    "goals.yaml", "assumptions.yaml", "theoretical_models.yaml", "general_definitions.yaml",
    "data_definitions.yaml", "instance_models.yaml", "requirements.yaml", "nonfunctional.yaml",
    "changes.yaml", "data_constraints.yaml",
]


def natural_key(label: str):
    """Sort key so that DD2 < DD10 and NFR1 < NFR2."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", str(label))]


def item_sort_key(item):
    kind = item.get("kind")
    k = KIND_ORDER.index(kind) if kind in KIND_ORDER else len(KIND_ORDER)
    return (k, natural_key(item.get("label", "")))


@dataclass
class Srs:
    items: dict = field(default_factory=dict)      # label -> item dict (as loaded, normalised)
    order: list = field(default_factory=list)      # labels in display order
    errata: list = field(default_factory=list)     # errata dicts
    ref_by: dict = field(default_factory=dict)     # label -> sorted labels of items using it
    warnings: list = field(default_factory=list)
    files: list = field(default_factory=list)      # files read (relative names)
    aliases: dict = field(default_factory=dict)    # alias -> label

    def by_kind(self, kind):
        return [lab for lab in self.order if self.items[lab]["kind"] == kind]

    def kinds_present(self):
        present = {it["kind"] for it in self.items.values()}
        return [k for k in KIND_ORDER if k in present] + sorted(present - set(KIND_ORDER))


def _as_list(value):
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return [v for v in value if v is not None]
    return [value]


def load_srs(srs_dir: str) -> Srs:
    srs = Srs()
    if not os.path.isdir(srs_dir):
        srs.warnings.append(f"SRS directory {srs_dir} does not exist: no SRS items loaded")
        return srs
    names = [n for n in SRS_FILES if os.path.exists(os.path.join(srs_dir, n))]
    # Any other *.yaml with item lists (except errata) is read too, so a new kind is not lost.
    extra = sorted(n for n in os.listdir(srs_dir)
                   if n.endswith((".yaml", ".yml")) and n not in SRS_FILES
                   and n not in ("errata.yaml", "errata.yml"))
    missing = [n for n in SRS_FILES if n not in names]
    if missing:
        srs.warnings.append("SRS files not found: " + ", ".join(missing))
    for name in names + extra:
        path = os.path.join(srs_dir, name)
        try:
            with open(path, encoding="utf-8") as fh:
                data = yaml.safe_load(fh)
        except (OSError, yaml.YAMLError) as exc:
            srs.warnings.append(f"srs/{name}: cannot be read: {exc}")
            continue
        if isinstance(data, dict) and "items" in data:
            data = data["items"]
        if data is None:
            data = []
        if not isinstance(data, list):
            if name in extra:
                continue  # not an item list (e.g. a schema or config file)
            srs.warnings.append(f"srs/{name}: top level is not a list of items")
            continue
        srs.files.append(name)
        for idx, raw in enumerate(data):
            if not isinstance(raw, dict) or "label" not in raw:
                srs.warnings.append(f"srs/{name}: entry #{idx + 1} has no label; skipped")
                continue
            item = dict(raw)
            item["label"] = str(item["label"]).strip()
            item["kind"] = str(item.get("kind") or "?").strip()
            item["uses"] = [str(u).strip() for u in _as_list(item.get("uses"))]
            seed_rb = item.get("seed_ref_by")
            item["seed_ref_by"] = None if seed_rb is None else [str(u).strip() for u in _as_list(seed_rb)]
            item["errata"] = [str(e) for e in _as_list(item.get("errata"))]
            item["symbols"] = _as_list(item.get("symbols"))
            item["_file"] = f"srs/{name}"
            lab = item["label"]
            if lab in srs.items:
                srs.warnings.append(f"duplicate SRS label {lab} in {item['_file']} "
                                    f"(first in {srs.items[lab]['_file']}); the first is kept")
                continue
            if item["kind"] not in KIND_ORDER:
                srs.warnings.append(f"{lab}: unknown kind '{item['kind']}' in {item['_file']}")
            srs.items[lab] = item
            if item.get("alias"):
                srs.aliases[str(item["alias"])] = lab
    srs.order = [it["label"] for it in sorted(srs.items.values(), key=item_sort_key)]
    # Computed Ref.By (Drasil style: never typed by hand).
    ref_by = {lab: [] for lab in srs.order}
    for lab in srs.order:
        for used in srs.items[lab]["uses"]:
            if used in srs.items:
                ref_by[used].append(lab)
            else:
                srs.warnings.append(f"{lab} uses {used}, which is not an SRS item")
    for lab in ref_by:
        ref_by[lab] = sorted(set(ref_by[lab]), key=lambda x: item_sort_key(srs.items[x]))
    srs.ref_by = ref_by
    # Errata.
    epath = os.path.join(srs_dir, "errata.yaml")
    if os.path.exists(epath):
        try:
            with open(epath, encoding="utf-8") as fh:
                edata = yaml.safe_load(fh) or []
            if isinstance(edata, dict) and "errata" in edata:
                edata = edata["errata"]
            for idx, e in enumerate(edata if isinstance(edata, list) else []):
                if not isinstance(e, dict):
                    continue
                e = dict(e)
                e["id"] = str(e.get("id", f"E{idx + 1}"))
                e["items"] = [str(x) for x in _as_list(e.get("items"))]
                srs.errata.append(e)
        except (OSError, yaml.YAMLError) as exc:
            srs.warnings.append(f"srs/errata.yaml: cannot be read: {exc}")
    else:
        srs.warnings.append("srs/errata.yaml not found: no errata listed")
    known_errata = {e["id"] for e in srs.errata}
    unknown = {}
    for lab in srs.order:
        for eid in srs.items[lab]["errata"]:
            if eid not in known_errata:
                unknown.setdefault(eid, []).append(lab)
    if unknown:
        srs.warnings.append(f"{len(unknown)} erratum id(s) cited by items but absent from srs/errata.yaml: " +
                            "; ".join(f"{e} ({', '.join(labs)})" for e, labs in
                                      sorted(unknown.items(), key=lambda kv: natural_key(kv[0]))))
    return srs


def refby_disagreements(srs: Srs):
    """Compare the seed's hand-typed Ref.By with the Ref.By computed from `uses`."""
    out = []
    for lab in srs.order:
        seed = srs.items[lab].get("seed_ref_by")
        if seed is None:
            continue
        computed = srs.ref_by.get(lab, [])
        only_seed = [x for x in seed if x not in computed]
        only_data = [x for x in computed if x not in seed]
        if only_seed or only_data:
            out.append({
                "label": lab,
                "seed_ref_by": seed,
                "computed_ref_by": computed,
                "only_in_seed": only_seed,
                "only_in_data": only_data,
                "unknown_in_seed": [x for x in seed if x not in srs.items],
            })
    return out


def run_checker(source_root: str, timeout: float = 120.0):
    """Run srs/check_srs.py --json if it exists. Returns (data or None, message)."""
    script = os.path.join(source_root, "srs", "check_srs.py")
    if not os.path.exists(script):
        return None, "srs/check_srs.py not present"
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "check.json")
        try:
            proc = subprocess.run(["/usr/bin/python3", script, "--json", out], cwd=source_root,
                                  capture_output=True, text=True, timeout=timeout)
        except (OSError, subprocess.TimeoutExpired) as exc:
            return None, f"srs/check_srs.py could not be run: {exc}"
        if not os.path.exists(out):
            tail = (proc.stderr or proc.stdout or "").strip().splitlines()[-3:]
            return None, f"srs/check_srs.py exited {proc.returncode} without writing JSON: " + " | ".join(tail)
        try:
            with open(out, encoding="utf-8") as fh:
                data = json.load(fh)
        except (OSError, ValueError) as exc:
            return None, f"srs/check_srs.py wrote unreadable JSON: {exc}"
        return data, f"srs/check_srs.py exited {proc.returncode}"
