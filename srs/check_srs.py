#!/usr/bin/python3
"""Validate Tamias2D's SRS-as-data (srs/*.yaml) and compute its traceability graph.

Exit status: 0 when the data is valid, 1 when it is not, 2 on a usage error.
Disagreements between the seed's hand-typed "Ref. By" rows and the Ref. By computed from
`uses` are findings about the seed, not failures: they are listed, never fatal.

    /usr/bin/python3 srs/check_srs.py                        # validate, print a summary
    /usr/bin/python3 srs/check_srs.py --json out.json        # also write the computed graph
    /usr/bin/python3 srs/check_srs.py --errata-md docs/srs-errata.md        # regenerate doc
    /usr/bin/python3 srs/check_srs.py --check-errata-md docs/srs-errata.md  # fail if stale

Only the standard library and python3-yaml (Debian) are needed.
"""
from __future__ import annotations

import argparse
import glob
import json
import os
import re
import sys

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))

# One file per kind; the file name fixes the kinds it may hold.
ITEM_FILES = {
    "goals.yaml": {"GS"},
    "assumptions.yaml": {"A"},
    "theoretical_models.yaml": {"TM"},
    "general_definitions.yaml": {"GD"},
    "data_definitions.yaml": {"DD"},
    "instance_models.yaml": {"IM"},
    "requirements.yaml": {"R"},
    "nonfunctional.yaml": {"NFR"},
    "changes.yaml": {"LC", "UC"},
    "data_constraints.yaml": {"DC"},
}
KIND_ORDER = ["GS", "A", "TM", "GD", "DD", "IM", "DC", "R", "NFR", "LC", "UC"]
# Label shape per kind (labels become Boost.Test labels: [A-Za-z0-9_] only).
LABEL_RE = re.compile(r"^[A-Za-z0-9_]+$")
KIND_LABEL_RE = {
    "GS": r"GS\d+", "A": r"A\d+", "TM": r"T\d+", "GD": r"GD\d+", "DD": r"DD\d+",
    "IM": r"IM\d+", "R": r"R\d+", "NFR": r"NFR\d+", "LC": r"LC\d+", "UC": r"UC\d+",
    "DC": r"DC[IOX]_[A-Za-z0-9_]+",
}
# Kinds whose seed entries carry a "Ref. By" row, and which need equations and units.
REFBY_KINDS = {"TM", "GD", "DD", "IM"}
MODEL_KINDS = {"TM", "GD", "DD", "IM"}

REQUIRED_KEYS = ["label", "kind", "alias", "title", "equation", "symbols", "uses", "source",
                 "description"]
OPTIONAL_KEYS = {
    "seed_equation", "seed_ref_by", "seed_ref_by_unresolved", "notes", "errata",
    "seed_cites", "seed_cites_unresolved", "alias_ref_by", "inputs", "seed_inputs", "outputs",
    "obligation", "engine", "engine_reason",
}
# Whether the engine evaluates a TM/GD/DD/IM's formula (through its model module, which
# verification/model_reach/module_reach.py checks by perturbing it): absent, it does. With
# `engine_reason` saying why, `engine: model-only` states that it does not, so that the
# engine's tests are not counted as that item's verification; `engine: property` that it does
# not either, but the item is a law the engine's results must satisfy, which engine-level
# tests check with an oracle of their own (they count).
ENGINE_VALUES = ("model-only", "property")
# Requirements carry their obligation as data, from the SRS's own verb (ISO/IEC/IEEE 29148:
# "shall" binds, "should" states a goal, "will" states a fact or intent). A statement with no
# verb or with several must cite an erratum of kind "obligation" giving the reading.
OBLIGATION_KINDS = {"R", "NFR"}
OBLIGATIONS = ("shall", "should", "will")
OBLIGATION_VERB_RE = re.compile(r"\b(shall|should|will)\b", re.IGNORECASE)
DC_KEYS = {"variable", "constraint", "typical", "corrected_constraint"}
DC_REQUIRED = ["variable", "constraint", "typical"]
SYMBOL_KEYS = {"symbol", "unit", "description", "seed_unit", "tamias_unit"}
SOURCE_SEEDS = {"000", "001", "project"}

ERRATUM_KINDS = {"units", "cross-reference", "omission", "typo", "physics", "table",
                 "obligation"}
ERRATUM_REQUIRED = ["id", "items", "kind", "seed_text", "problem", "correct_reading",
                    "compile_fail"]
ERRATUM_OPTIONAL = {"section", "seeds"}
ERRATUM_ID_RE = re.compile(r"^E\d{2,3}$")
ALIAS_RE = re.compile(r"^[A-Z]+:[A-Za-z0-9]+$")

# Units: space-separated tokens, each a known unit with an optional integer exponent.
# Dimensions are vectors over (kg, m, s, rad); plane angle is a base dimension as in
# Boost.Units, so `tamias_unit` may differ from `unit` only in its rad exponent.
UNIT_DIMS = {
    "kg": (1, 0, 0, 0), "m": (0, 1, 0, 0), "s": (0, 0, 1, 0), "rad": (0, 0, 0, 1),
    "N": (1, 1, -2, 0), "J": (1, 2, -2, 0),
}
UNIT_TOKEN_RE = re.compile(r"^([A-Za-z]+)(?:\^(-?\d+))?$")
NON_QUANTITY = "n/a"


def unit_dims(text):
    """Dimension vector of a unit string, or None if it does not parse."""
    if not isinstance(text, str):
        return None
    text = text.strip()
    if text == "1":
        return (0, 0, 0, 0)
    if text == NON_QUANTITY:
        return "n/a"
    dims = [0, 0, 0, 0]
    tokens = text.split()
    if not tokens:
        return None
    for tok in tokens:
        mt = UNIT_TOKEN_RE.match(tok)
        if not mt or mt.group(1) not in UNIT_DIMS:
            return None
        exp = int(mt.group(2)) if mt.group(2) else 1
        for k, d in enumerate(UNIT_DIMS[mt.group(1)]):
            dims[k] += exp * d
    return tuple(dims)


def natural_key(label):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", str(label))]


def item_key(item):
    kind = item.get("kind")
    k = KIND_ORDER.index(kind) if kind in KIND_ORDER else len(KIND_ORDER)
    return (k, natural_key(item.get("label", "")))


class Result:
    """Everything the checker found: errors make the data invalid, the rest are findings."""

    def __init__(self):
        self.errors = []
        self.notes = []
        self.items = {}          # label -> item
        self.order = []          # labels in display order
        self.errata = []         # errata list (as loaded)
        self.meta = {}
        self.ref_by = {}
        self.disagreements = []  # seed 000 Ref. By vs computed
        self.alias_disagreements = []  # seed 001 RefBy vs computed
        self.citation_corrections = []  # seed_cites vs uses
        self.unresolved = []     # seed references to non-existent labels

    def error(self, msg):
        self.errors.append(msg)

    @property
    def valid(self):
        return not self.errors


def _load_yaml(path, res):
    try:
        with open(path, encoding="utf-8") as fh:
            return yaml.safe_load(fh)
    except (OSError, yaml.YAMLError) as exc:
        res.error(f"{os.path.basename(path)}: cannot be read: {exc}")
        return None


def _is_str(v):
    return isinstance(v, str) and v.strip() != ""


def _str_list(v):
    return isinstance(v, list) and all(isinstance(x, str) and x for x in v)


def _check_symbols(where, symbols, res):
    if not isinstance(symbols, list):
        res.error(f"{where}: symbols must be a list")
        return
    for k, sym in enumerate(symbols):
        tag = f"{where}: symbol #{k + 1}"
        if not isinstance(sym, dict):
            res.error(f"{tag} is not a mapping")
            continue
        extra = set(sym) - SYMBOL_KEYS
        if extra:
            res.error(f"{tag}: unknown keys {sorted(extra)}")
        for key in ("symbol", "unit", "description"):
            if not _is_str(sym.get(key)):
                res.error(f"{tag}: missing or empty '{key}'")
        if "symbol" in sym and _is_str(sym.get("symbol")):
            tag = f"{where}: symbol {sym['symbol']!r}"
        dims = unit_dims(sym.get("unit"))
        if sym.get("unit") is not None and dims is None:
            res.error(f"{tag}: unit {sym.get('unit')!r} does not parse "
                      f"(tokens {sorted(UNIT_DIMS)} with ^exponent, '1' or '{NON_QUANTITY}')")
        for key in ("seed_unit", "tamias_unit"):
            if key in sym and unit_dims(sym[key]) is None:
                res.error(f"{tag}: {key} {sym[key]!r} does not parse")
        if "tamias_unit" in sym and dims not in (None, "n/a"):
            tdims = unit_dims(sym["tamias_unit"])
            if isinstance(tdims, tuple) and tdims[:3] != dims[:3]:
                res.error(f"{tag}: tamias_unit {sym['tamias_unit']!r} differs from unit "
                          f"{sym['unit']!r} in more than the radian exponent")
        if sym.get("seed_unit") is not None and sym.get("seed_unit") == sym.get("unit"):
            res.error(f"{tag}: seed_unit equals unit (give seed_unit only when the seed's is wrong)")


def _check_item(fname, idx, raw, res, allowed_kinds):
    where = f"{fname} entry #{idx + 1}"
    if not isinstance(raw, dict):
        res.error(f"{where}: not a mapping")
        return None
    label = raw.get("label")
    if isinstance(label, str):
        where = f"{fname} {label}"
    for key in REQUIRED_KEYS:
        if key not in raw:
            res.error(f"{where}: missing required key '{key}'")
    kind = raw.get("kind")
    allowed = set(REQUIRED_KEYS) | OPTIONAL_KEYS | (DC_KEYS if kind == "DC" else set())
    extra = set(raw) - allowed
    if extra:
        res.error(f"{where}: unknown keys {sorted(extra)}")
    if not isinstance(label, str) or not LABEL_RE.match(label):
        res.error(f"{where}: label {label!r} must match [A-Za-z0-9_]+")
        return None
    if kind not in KIND_LABEL_RE:
        res.error(f"{where}: kind {kind!r} is not one of {' '.join(KIND_ORDER)}")
        return None
    if kind not in allowed_kinds:
        res.error(f"{where}: kind {kind} does not belong in {fname}")
    if not re.fullmatch(KIND_LABEL_RE[kind], label):
        res.error(f"{where}: label does not have the form of kind {kind} ({KIND_LABEL_RE[kind]})")
    alias = raw.get("alias")
    if alias is not None and not (isinstance(alias, str) and ALIAS_RE.match(alias)):
        res.error(f"{where}: alias {alias!r} must be null or like 'DD:name'")
    for key in ("title", "description"):
        if key in raw and not _is_str(raw.get(key)):
            res.error(f"{where}: '{key}' must be a non-empty string")
    eq = raw.get("equation")
    if eq is not None and not _is_str(eq):
        res.error(f"{where}: equation must be a LaTeX string or null")
    if "seed_equation" in raw:
        if not _is_str(raw["seed_equation"]):
            res.error(f"{where}: seed_equation must be a non-empty string")
        elif raw["seed_equation"] == eq:
            res.error(f"{where}: seed_equation equals equation (omit it when they agree)")
    if kind in MODEL_KINDS:
        if not _is_str(eq):
            res.error(f"{where}: a {kind} needs an equation")
        if not raw.get("symbols"):
            res.error(f"{where}: a {kind} needs symbols with units")
    if kind == "DC":
        for key in DC_REQUIRED:
            if key not in raw:
                res.error(f"{where}: a DC item needs '{key}' (null if the seed has none)")
        if not _is_str(raw.get("variable")):
            res.error(f"{where}: 'variable' must be a non-empty string")
        if not raw.get("symbols"):
            res.error(f"{where}: a DC item needs the symbol of its variable with its unit")
        if raw.get("constraint") is None and not _is_str(raw.get("corrected_constraint")):
            res.error(f"{where}: a constraint the seed lacks needs corrected_constraint")
    _check_symbols(where, raw.get("symbols", []), res)
    for key in ("uses", "seed_cites", "seed_cites_unresolved", "seed_ref_by",
                "seed_ref_by_unresolved", "alias_ref_by", "errata"):
        if key in raw and not (isinstance(raw[key], list) and
                               all(isinstance(x, str) and x for x in raw[key])):
            res.error(f"{where}: '{key}' must be a list of labels")
    for key in ("inputs", "outputs"):
        if key in raw and not _str_list(raw[key]):
            res.error(f"{where}: '{key}' must be a list of strings")
    if "seed_inputs" in raw and not _is_str(raw["seed_inputs"]):
        res.error(f"{where}: 'seed_inputs' must be a string")
    if kind in REFBY_KINDS and "seed_ref_by" not in raw:
        res.error(f"{where}: a {kind} needs seed_ref_by (the seed's Ref. By row; [] if empty)")
    if kind not in REFBY_KINDS and ("seed_ref_by" in raw or "seed_ref_by_unresolved" in raw):
        res.error(f"{where}: kind {kind} has no Ref. By row in the seed; omit seed_ref_by")
    if "alias_ref_by" in raw and alias is None:
        res.error(f"{where}: alias_ref_by needs an alias")
    src = raw.get("source")
    if not isinstance(src, dict) or src.get("seed") not in SOURCE_SEEDS:
        res.error(f"{where}: source must be a mapping with seed one of {sorted(SOURCE_SEEDS)}")
    elif src.get("seed") != "project" and not _is_str(str(src.get("section", ""))):
        res.error(f"{where}: source needs the seed section")
    if label.startswith("DCX_") and isinstance(src, dict) and src.get("seed") != "project":
        res.error(f"{where}: DCX_ constraints are the project's: source.seed must be project")
    if label.startswith("DCX_") and not raw.get("errata"):
        res.error(f"{where}: a project constraint must cite the erratum that motivates it")
    if "notes" in raw and not _is_str(raw["notes"]):
        res.error(f"{where}: notes must be a non-empty string")
    if "engine" in raw or "engine_reason" in raw:
        if kind not in MODEL_KINDS:
            res.error(f"{where}: only {', '.join(sorted(MODEL_KINDS))} items carry engine "
                      "(whether the engine evaluates their formula)")
        elif raw.get("engine") not in ENGINE_VALUES:
            res.error(f"{where}: engine must be one of {', '.join(ENGINE_VALUES)} (absent: the "
                      "engine evaluates the formula through its module)")
        elif not _is_str(raw.get("engine_reason")):
            res.error(f"{where}: engine: {raw.get('engine')} needs engine_reason (why the engine "
                      "does not evaluate the formula)")
    if kind in OBLIGATION_KINDS and raw.get("obligation") not in OBLIGATIONS:
        res.error(f"{where}: a {kind} needs obligation, one of {', '.join(OBLIGATIONS)}")
    if kind not in OBLIGATION_KINDS and "obligation" in raw:
        res.error(f"{where}: only requirements ({', '.join(sorted(OBLIGATION_KINDS))}) carry an "
                  "obligation")
    return raw


def obligation_verbs(description):
    """The distinct obligation verbs of a statement, in order of first use."""
    out = []
    for m in OBLIGATION_VERB_RE.finditer(description or ""):
        v = m.group(1).lower()
        if v not in out:
            out.append(v)
    return out


def _find_seed_dir(explicit):
    cands = [explicit] if explicit else []
    cands += [os.environ.get("TAMIAS_SEEDS_DIR"),
              os.path.join(HERE, "..", "..", "shared", "seeds"),
              os.path.join(HERE, "..", "shared", "seeds"),
              "/work/shared/seeds"]
    for c in cands:
        if c and os.path.isdir(c):
            return os.path.abspath(c)
    return None


def _cycles(items):
    """Return one cycle (list of labels) in the uses graph, or None."""
    state = {}
    stack = []

    def visit(lab):
        state[lab] = 1
        stack.append(lab)
        for nxt in items[lab].get("uses", []):
            if nxt not in items:
                continue
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[lab] = 2
        return None

    for lab in sorted(items, key=natural_key):
        if lab not in state:
            found = visit(lab)
            if found:
                return found
    return None


def check(srs_dir=HERE, seeds_dir=None, use_seeds=True):
    res = Result()
    # 1. Items.
    for fname, kinds in ITEM_FILES.items():
        path = os.path.join(srs_dir, fname)
        if not os.path.exists(path):
            res.error(f"{fname}: missing")
            continue
        data = _load_yaml(path, res)
        if data is None:
            continue
        if not isinstance(data, list):
            res.error(f"{fname}: top level must be a list of items")
            continue
        for idx, raw in enumerate(data):
            item = _check_item(fname, idx, raw, res, kinds)
            if item is None:
                continue
            lab = item["label"]
            if lab in res.items:
                res.error(f"duplicate label {lab} ({fname} and {res.items[lab]['_file']})")
                continue
            item = dict(item)
            item["_file"] = fname
            res.items[lab] = item
    res.order = sorted(res.items, key=lambda lab: item_key(res.items[lab]))
    items = res.items

    # 2. References resolve.
    for lab in res.order:
        it = items[lab]
        for key in ("uses", "seed_cites", "seed_ref_by", "alias_ref_by"):
            vals = it.get(key) or []
            if not isinstance(vals, list):
                continue
            if len(set(vals)) != len(vals):
                res.error(f"{lab}: duplicate entries in {key}")
            for ref in vals:
                if ref not in items:
                    res.error(f"{lab}: {key} entry {ref!r} is not an SRS label "
                              f"(record seed references to missing items in "
                              f"{'seed_ref_by_unresolved' if key == 'seed_ref_by' else 'seed_cites_unresolved'})")
            if key == "uses" and lab in vals:
                res.error(f"{lab}: uses itself")
        for key in ("seed_cites_unresolved", "seed_ref_by_unresolved"):
            for ref in it.get(key) or []:
                if ref in items:
                    res.error(f"{lab}: {key} entry {ref!r} resolves; move it to "
                              f"{key.replace('_unresolved', '')}")
                else:
                    res.unresolved.append({"text": ref, "where": f"{lab} ({key})"})
    cyc = _cycles(items)
    if cyc:
        res.error("uses graph has a cycle (a derivation depends on itself): " + " -> ".join(cyc))

    # 3. Aliases: one-to-one, and exactly the Drasil names of seed 001.
    meta_path = os.path.join(srs_dir, "meta.yaml")
    meta = _load_yaml(meta_path, res) if os.path.exists(meta_path) else None
    if not isinstance(meta, dict):
        res.error("meta.yaml: missing or not a mapping")
        meta = {}
    res.meta = meta
    alias_of = {}
    for lab in res.order:
        al = items[lab].get("alias")
        if al is None:
            continue
        if al in alias_of:
            res.error(f"alias {al} is given to both {alias_of[al]} and {lab} (aliases are one-to-one)")
        else:
            alias_of[al] = lab
    names = meta.get("drasil_names") or {}
    if not isinstance(names, dict) or not names:
        res.error("meta.yaml: drasil_names must map every Drasil name of seed 001 to a label")
        names = {}
    for name, lab in names.items():
        if alias_of.get(name) != lab:
            res.error(f"Drasil name {name} should be the alias of {lab} "
                      f"(is {alias_of.get(name) or 'unmapped'})")
    for al, lab in alias_of.items():
        if al not in names:
            res.error(f"{lab}: alias {al} is not a Drasil name of seed 001 (meta.yaml drasil_names)")
    if len(set(names.values())) != len(names):
        res.error("meta.yaml: drasil_names maps two names to one label")
    sdir = _find_seed_dir(seeds_dir) if use_seeds else None
    seed001 = glob.glob(os.path.join(sdir, "001_*.txt")) if sdir else []
    if seed001:
        with open(seed001[0], encoding="utf-8") as fh:
            text = fh.read()
        refnames = set(re.findall(r"Refname(DD:[A-Za-z0-9]+)", text))
        mentioned = set(re.findall(r"\b((?:DD|IM|A|GD|TM|T|R):[A-Za-z0-9]+)", text))
        listed_dd = {n for n in names if n.startswith("DD:")}
        if refnames != listed_dd:
            res.error("meta.yaml drasil_names DD entries differ from seed 001's Refname rows: "
                      f"missing {sorted(refnames - listed_dd)}, extra {sorted(listed_dd - refnames)}")
        for n in sorted(mentioned - set(names)):
            res.error(f"seed 001 mentions {n}, which meta.yaml drasil_names does not map")
        res.notes.append(f"aliases checked against {os.path.basename(seed001[0])}")
    else:
        res.notes.append("seed 001 not found (set TAMIAS_SEEDS_DIR): aliases checked against "
                         "meta.yaml only")

    # 4. Errata: schema, ids, items resolve, both directions agree.
    epath = os.path.join(srs_dir, "errata.yaml")
    edata = _load_yaml(epath, res) if os.path.exists(epath) else None
    if not isinstance(edata, list):
        res.error("errata.yaml: missing or not a list")
        edata = []
    seen = {}
    for k, e in enumerate(edata):
        where = f"errata.yaml entry #{k + 1}"
        if not isinstance(e, dict):
            res.error(f"{where}: not a mapping")
            continue
        eid = e.get("id")
        if isinstance(eid, str):
            where = f"errata.yaml {eid}"
        for key in ERRATUM_REQUIRED:
            if key not in e:
                res.error(f"{where}: missing '{key}'")
        extra = set(e) - set(ERRATUM_REQUIRED) - ERRATUM_OPTIONAL
        if extra:
            res.error(f"{where}: unknown keys {sorted(extra)}")
        if not isinstance(eid, str) or not ERRATUM_ID_RE.match(eid):
            res.error(f"{where}: id must look like E01")
            continue
        if eid in seen:
            res.error(f"duplicate erratum id {eid}")
            continue
        seen[eid] = e
        if e.get("kind") not in ERRATUM_KINDS:
            res.error(f"{where}: kind {e.get('kind')!r} not one of {sorted(ERRATUM_KINDS)}")
        for key in ("seed_text", "problem", "correct_reading"):
            if key in e and not _is_str(e.get(key)):
                res.error(f"{where}: '{key}' must be a non-empty string")
        if not isinstance(e.get("compile_fail"), bool):
            res.error(f"{where}: compile_fail must be true or false")
        if e.get("compile_fail") and e.get("kind") != "units":
            res.error(f"{where}: compile_fail is for dimensional (units) errata")
        its = e.get("items")
        if not isinstance(its, list) or not all(isinstance(x, str) for x in its):
            res.error(f"{where}: items must be a list of labels")
            its = []
        if not its and not e.get("section"):
            res.error(f"{where}: an erratum without items needs a section")
        if "seeds" in e and (not isinstance(e["seeds"], list) or
                             not set(e["seeds"]) <= {"000", "001"} or not e["seeds"]):
            res.error(f"{where}: seeds must be a non-empty subset of ['000', '001']")
        for lab in its:
            if lab not in items:
                res.error(f"{where}: item {lab!r} is not an SRS label")
            elif eid not in (items[lab].get("errata") or []):
                res.error(f"{where} lists {lab}, but {lab}.errata does not list {eid}")
    ids = sorted(seen, key=natural_key)
    expected = [f"E{n:02d}" for n in range(1, len(ids) + 1)]
    if ids != expected:
        res.error(f"errata ids must run E01..E{len(ids):02d} without gaps")
    res.errata = [seen[i] for i in ids]
    for lab in res.order:
        for eid in items[lab].get("errata") or []:
            if eid not in seen:
                res.error(f"{lab}: erratum {eid} is not in errata.yaml")
            elif lab not in (seen[eid].get("items") or []):
                res.error(f"{lab} lists {eid}, but {eid}.items does not list {lab}")
    # The obligation agrees with the statement's verb, or an erratum gives the reading.
    for lab in res.order:
        it = items[lab]
        if it["kind"] not in OBLIGATION_KINDS or it.get("obligation") not in OBLIGATIONS:
            continue
        verbs = obligation_verbs(it.get("description"))
        if len(verbs) == 1:
            if verbs[0] != it["obligation"]:
                res.error(f"{lab}: obligation {it['obligation']} but the statement says "
                          f"'{verbs[0]}'")
            continue
        cited = [seen[e] for e in it.get("errata") or [] if e in seen]
        if not any(e.get("kind") == "obligation" for e in cited):
            found = ", ".join(verbs) if verbs else "no obligation verb"
            res.error(f"{lab}: the statement has {found}: cite an erratum of kind obligation "
                      "that gives the reading")
    for k, u in enumerate(meta.get("seed_unresolved_references") or []):
        if not isinstance(u, dict) or not _is_str(u.get("text")) or not _is_str(u.get("where")):
            res.error(f"meta.yaml seed_unresolved_references #{k + 1}: needs text and where")
            continue
        if u.get("erratum") is not None and u["erratum"] not in seen:
            res.error(f"meta.yaml seed_unresolved_references {u['text']}: unknown erratum {u['erratum']}")
        same = [x for x in res.unresolved if x["text"] == u["text"]]
        if same:  # the item already records it: add the reading
            same[0].update(where=same[0]["where"] + "; " + u["where"],
                           reading=u.get("reading"), erratum=u.get("erratum"))
        else:
            res.unresolved.append({"text": u["text"], "where": u["where"],
                                   "reading": u.get("reading"), "erratum": u.get("erratum")})
    for k, sym in enumerate(meta.get("symbols") or []):
        if isinstance(sym, dict):
            s2 = {x: y for x, y in sym.items() if x != "erratum"}
            _check_symbols(f"meta.yaml symbols #{k + 1}", [s2], res)

    # 5. Computed Ref. By and the findings.
    ref_by = {lab: [] for lab in res.order}
    for lab in res.order:
        for used in items[lab].get("uses") or []:
            if used in ref_by:
                ref_by[used].append(lab)
    order_index = {lab: i for i, lab in enumerate(res.order)}
    for lab in ref_by:
        ref_by[lab] = sorted(set(ref_by[lab]), key=order_index.get)
    res.ref_by = ref_by
    for lab in res.order:
        it = items[lab]
        comp = ref_by[lab]
        if "seed_ref_by" in it and isinstance(it["seed_ref_by"], list):
            seed = it["seed_ref_by"]
            miss = [x for x in comp if x not in seed]
            extra = [x for x in seed if x not in comp]
            if miss or extra or it.get("seed_ref_by_unresolved"):
                res.disagreements.append({
                    "label": lab, "seed_ref_by": seed, "computed_ref_by": comp,
                    "missing_in_seed": miss, "extra_in_seed": extra,
                    "unresolved_in_seed": list(it.get("seed_ref_by_unresolved") or []),
                    "errata": sorted(set(it.get("errata") or []), key=natural_key)})
        if "alias_ref_by" in it and isinstance(it["alias_ref_by"], list):
            seed = it["alias_ref_by"]
            miss = [x for x in comp if x not in seed]
            extra = [x for x in seed if x not in comp]
            if miss or extra:
                res.alias_disagreements.append({
                    "label": lab, "alias": it.get("alias"), "seed_ref_by": seed,
                    "computed_ref_by": comp, "missing_in_seed": miss, "extra_in_seed": extra})
        if "seed_cites" in it and isinstance(it["seed_cites"], list):
            added = [x for x in it.get("uses") or [] if x not in it["seed_cites"]]
            dropped = [x for x in it["seed_cites"] if x not in (it.get("uses") or [])]
            if added or dropped:
                res.citation_corrections.append({"label": lab, "seed_cites": it["seed_cites"],
                                                 "uses": it.get("uses") or [], "added": added,
                                                 "dropped": dropped})
                if dropped and not it.get("errata") and not it.get("notes"):
                    res.error(f"{lab}: drops seed citations {dropped} without errata or notes")
    return res


def _pub(item):
    return {k: v for k, v in item.items() if not k.startswith("_")}


def to_json(res):
    counts = {}
    for lab in res.order:
        counts[res.items[lab]["kind"]] = counts.get(res.items[lab]["kind"], 0) + 1
    return {
        "schema": "tamias2d-srs-graph/1",
        "valid": res.valid,
        "errors": res.errors,
        "counts": {k: counts[k] for k in KIND_ORDER if k in counts},
        "items": [dict(_pub(res.items[lab]), ref_by=res.ref_by[lab]) for lab in res.order],
        "uses": {lab: list(res.items[lab].get("uses") or []) for lab in res.order},
        "ref_by": res.ref_by,
        "seed_ref_by": {lab: res.items[lab]["seed_ref_by"] for lab in res.order
                        if "seed_ref_by" in res.items[lab]},
        "aliases": {res.items[lab]["alias"]: lab for lab in res.order if res.items[lab].get("alias")},
        "disagreements": res.disagreements,
        "disagreement_links": sum(len(d["missing_in_seed"]) + len(d["extra_in_seed"])
                                  for d in res.disagreements),
        "alias_disagreements": res.alias_disagreements,
        "citation_corrections": res.citation_corrections,
        "unresolved_seed_references": res.unresolved,
        "errata": res.errata,
    }


# ---------------------------------------------------------------------------------------
# docs/srs-errata.md generator. The intro is hand-written here so that the whole document
# is regenerated from data and cannot drift from srs/errata.yaml.
ERRATA_INTRO = """\
# SRS errata

<!-- GENERATED by srs/check_srs.py --errata-md docs/srs-errata.md from srs/*.yaml.
     Do not edit by hand: edit srs/errata.yaml (or the intro in srs/check_srs.py) and
     regenerate. CTest's srs_checker fails when this file is stale. -->

Tamias2D is built from two seed documents: the *Software Requirements Specification for
Tamias2D* v1.7 (seed 000, labels GS1-2, A1-A7, T1-T5, GD1-2, DD1-16, IM1-4, R1-8, NFR1-5,
LC1-3, UC1-4) and the Drasil-generated Data Definitions of the same system (seed 001,
names like `DD:linDisp`, recorded as aliases). Neither is free of defects. Where the text is
wrong, Tamias2D implements the physically correct model and records the discrepancy here; it
never silently copies an error. Each erratum names the items concerned, quotes the seed,
states the problem and the reading Tamias2D implements. *Compile-fail* marks dimensional
errors: a unit-typed compile-fail test (tests/compile_fail/) can show that the seed's form is
rejected by the compiler.

Unit conventions of the C++ code (Boost.Units SI with plane angle as a base dimension):
torque is N m rad^-1, moment of inertia kg m^2 rad^-2, angular momentum kg m^2 s^-1 rad^-1.
So tau = (r x F)/rad, and DD8's rotational terms are (r x n / rad)^2 / I. These are
conventions, not seed errors: the seed's units are right in plain SI, where rad = 1.

The second part lists where the seed's hand-typed "Ref. By" rows disagree with the Ref. By
that the project computes from each item's `uses` (Drasil style: never typed by hand).
*Missing in seed*: an item that uses X but is absent from X's Ref. By row; *extra in seed*: an
item listed in X's Ref. By row that does not use X.
"""


def _cell(text):
    if text is None:
        return ""
    s = " ".join(str(text).split())
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("|", "\\|")


def _labels(xs):
    return ", ".join(xs) if xs else "-"


def errata_markdown(res):
    out = [ERRATA_INTRO]
    counts = {}
    for lab in res.order:
        counts[res.items[lab]["kind"]] = counts.get(res.items[lab]["kind"], 0) + 1
    by_kind = {}
    for e in res.errata:
        by_kind[e["kind"]] = by_kind.get(e["kind"], 0) + 1
    links = sum(len(d["missing_in_seed"]) + len(d["extra_in_seed"]) for d in res.disagreements)
    out.append("## Summary\n")
    out.append("- Items: " + ", ".join(f"{k} {counts[k]}" for k in KIND_ORDER if k in counts)
               + f" (total {len(res.order)}).")
    out.append(f"- Errata: {len(res.errata)} ("
               + ", ".join(f"{k} {by_kind[k]}" for k in sorted(by_kind)) + "); "
               f"{sum(1 for e in res.errata if e.get('compile_fail'))} are dimensional "
               "(compile-fail).")
    out.append(f"- Ref. By disagreements with seed 000: {len(res.disagreements)} items "
               f"({links} links).")
    out.append(f"- RefBy disagreements with seed 001 (Drasil): {len(res.alias_disagreements)} items.")
    out.append(f"- Items whose seed citations were corrected: {len(res.citation_corrections)}.")
    out.append(f"- Seed references to labels that do not exist: {len(res.unresolved)}.\n")

    out.append("## Errata\n")
    out.append("| id | items | kind | seed text | problem | reading implemented by Tamias2D | compile-fail |")
    out.append("| --- | --- | --- | --- | --- | --- | --- |")
    for e in res.errata:
        items = _labels(e.get("items") or [])
        where = []
        if e.get("section"):
            where.append(f"§{e['section']}")
        if e.get("seeds", ["000"]) != ["000"]:
            where.append("seeds " + " and ".join(e["seeds"]))
        if where:
            items += f" ({'; '.join(where)})"
        out.append(f"| {e['id']} | {_cell(items)} | {e['kind']} | {_cell(e['seed_text'])} | "
                   f"{_cell(e['problem'])} | {_cell(e['correct_reading'])} | "
                   f"{'yes' if e.get('compile_fail') else 'no'} |")
    out.append("")

    out.append("## Ref. By disagreements (seed 000 vs computed)\n")
    out.append("| item | seed Ref. By | computed Ref. By | missing in seed | extra in seed | errata |")
    out.append("| --- | --- | --- | --- | --- | --- |")
    for d in res.disagreements:
        out.append(f"| {d['label']} | {_labels(d['seed_ref_by'])} | {_labels(d['computed_ref_by'])} | "
                   f"{_labels(d['missing_in_seed'])} | {_labels(d['extra_in_seed'])} | "
                   f"{_labels(d['errata'])} |")
    agree = [lab for lab in res.order if "seed_ref_by" in res.items[lab]
             and lab not in {d["label"] for d in res.disagreements}]
    out.append("")
    out.append("Items whose seed Ref. By agrees with the computed one: " + _labels(agree) + ".\n")

    out.append("## RefBy disagreements (seed 001, Drasil, vs computed)\n")
    out.append("Seed 001's RefBy rows translated to numbered labels (IM:transMot = IM1, "
               "IM:rotMot = IM2, IM:col2D = IM3).\n")
    out.append("| item | alias | seed 001 RefBy | computed Ref. By | missing in seed 001 | extra in seed 001 |")
    out.append("| --- | --- | --- | --- | --- | --- |")
    for d in res.alias_disagreements:
        out.append(f"| {d['label']} | `{d['alias']}` | {_labels(d['seed_ref_by'])} | "
                   f"{_labels(d['computed_ref_by'])} | {_labels(d['missing_in_seed'])} | "
                   f"{_labels(d['extra_in_seed'])} |")
    out.append("")

    out.append("## Citation corrections (what the seed cites vs `uses`)\n")
    out.append("| item | seed cites | uses | added | dropped | errata |")
    out.append("| --- | --- | --- | --- | --- | --- |")
    for c in res.citation_corrections:
        errs = sorted(set(res.items[c["label"]].get("errata") or []), key=natural_key)
        out.append(f"| {c['label']} | {_labels(c['seed_cites'])} | {_labels(c['uses'])} | "
                   f"{_labels(c['added'])} | {_labels(c['dropped'])} | {_labels(errs)} |")
    out.append("")
    out.append("Added links are either corrections of wrong citations (see the errata) or "
               "dependencies the seed leaves implicit (an equation built on another item's "
               "symbol); each is explained in the item's `notes`.\n")

    out.append("## Seed references to labels that do not exist\n")
    out.append("| reference | where | reading | erratum |")
    out.append("| --- | --- | --- | --- |")
    for u in res.unresolved:
        out.append(f"| {_cell(u['text'])} | {_cell(u['where'])} | {_cell(u.get('reading'))} | "
                   f"{_cell(u.get('erratum') or '-')} |")
    out.append("")
    return "\n".join(out)


def summary(res, out=sys.stdout):
    counts = {}
    for lab in res.order:
        counts[res.items[lab]["kind"]] = counts.get(res.items[lab]["kind"], 0) + 1
    print("SRS items: " + ", ".join(f"{k}={counts[k]}" for k in KIND_ORDER if k in counts)
          + f" (total {len(res.order)}); errata: {len(res.errata)}", file=out)
    for n in res.notes:
        print(f"note: {n}", file=out)
    links = sum(len(d["missing_in_seed"]) + len(d["extra_in_seed"]) for d in res.disagreements)
    print(f"Ref. By disagreements with seed 000 (findings, not failures): "
          f"{len(res.disagreements)} items, {links} links", file=out)
    for d in res.disagreements:
        print(f"  {d['label']}: seed [{', '.join(d['seed_ref_by'])}] computed "
              f"[{', '.join(d['computed_ref_by'])}]; missing in seed: "
              f"{_labels(d['missing_in_seed'])}; extra in seed: {_labels(d['extra_in_seed'])}",
              file=out)
    print(f"RefBy disagreements with seed 001 (Drasil): {len(res.alias_disagreements)} items",
          file=out)
    for d in res.alias_disagreements:
        print(f"  {d['label']} ({d['alias']}): missing in seed 001: "
              f"{_labels(d['missing_in_seed'])}; extra: {_labels(d['extra_in_seed'])}", file=out)
    model_only = [lab for lab in res.order if res.items[lab].get("engine") == "model-only"]
    print(f"Model only (the engine does not evaluate the formula): "
          f"{', '.join(model_only) or 'none'}", file=out)
    prop = [lab for lab in res.order if res.items[lab].get("engine") == "property"]
    print(f"Properties (the engine does not evaluate the formula, its results are checked "
          f"against it): {', '.join(prop) or 'none'}", file=out)
    print(f"Seed references to labels that do not exist: "
          + ", ".join(f"{u['text']} ({u['where']})" for u in res.unresolved), file=out)
    if res.errors:
        print(f"INVALID: {len(res.errors)} error(s)", file=out)
        for e in res.errors:
            print(f"  error: {e}", file=out)
    else:
        print("SRS data valid", file=out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--srs-dir", default=HERE, help="directory of the SRS YAML files")
    ap.add_argument("--seeds-dir", default=None, help="directory of the seed documents")
    ap.add_argument("--no-seeds", action="store_true",
                    help="do not cross-check the aliases against the seed 001 text")
    ap.add_argument("--json", metavar="OUT", help="write the computed graph as JSON")
    ap.add_argument("--errata-md", metavar="OUT", help="(re)generate the errata document")
    ap.add_argument("--check-errata-md", metavar="DOC",
                    help="fail if DOC differs from what --errata-md would generate")
    ap.add_argument("-q", "--quiet", action="store_true", help="print errors only")
    args = ap.parse_args(argv)

    res = check(args.srs_dir, args.seeds_dir, use_seeds=not args.no_seeds)
    if args.quiet:
        for e in res.errors:
            print(f"error: {e}", file=sys.stderr)
    else:
        summary(res)
    status = 0 if res.valid else 1
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump(to_json(res), fh, indent=1, ensure_ascii=False)
            fh.write("\n")
    if args.errata_md or args.check_errata_md:
        md = errata_markdown(res)
        if args.errata_md:
            if not res.valid:
                print("not writing the errata document: the SRS data is invalid", file=sys.stderr)
            else:
                with open(args.errata_md, "w", encoding="utf-8") as fh:
                    fh.write(md)
                if not args.quiet:
                    print(f"wrote {args.errata_md}")
        if args.check_errata_md:
            try:
                with open(args.check_errata_md, encoding="utf-8") as fh:
                    current = fh.read()
            except OSError as exc:
                print(f"error: cannot read {args.check_errata_md}: {exc}", file=sys.stderr)
                return 1
            if current != md:
                print(f"error: {args.check_errata_md} is stale; regenerate it with "
                      f"srs/check_srs.py --errata-md {args.check_errata_md}", file=sys.stderr)
                status = 1
            elif not args.quiet:
                print(f"{args.check_errata_md} is up to date")
    return status


if __name__ == "__main__":
    sys.exit(main())
