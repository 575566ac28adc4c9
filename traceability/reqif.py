#!/usr/bin/python3
"""The traceability report as ReqIF 1.2 (OMG Requirements Interchange Format), and back.

    traceability/reqif.py export --report reports/traceability.json --out reports/tamias2d.reqif
    traceability/reqif.py import FILE [--out DIR] [--json FILE]
    traceability/reqif.py validate FILE --schema ../shared/standards/reqif/reqif.xsd

`export` writes what a requirements tool (DOORS, Polarion, Codebeamer, Jama, StrictDoc...)
imports: every SRS item, test, verification check and code site as a SPEC-OBJECT, the trace
links as typed SPEC-RELATIONs (verifies: test -> item, with the link's grade and review state;
refines and uses: item -> item, from `uses`; implements: code site -> item), one SPECIFICATION
per SRS section in the SRS's order, one for the tests and checks and one for the code sites.
The output is a function of the report's JSON alone: identifiers are derived from labels and
test ids, elements are sorted, and the one time that varies is CREATION-TIME (the report's
`generated`); the LAST-CHANGE the schema requires on every element is the reported commit's
date. build_report.py writes reports/tamias2d.reqif after the report, from the same JSON.

`import` reads a ReqIF file back into srs/-style item records (and the tests, links and code
sites of a file this module wrote), and lists everything it cannot map: objects without a
label or kind, attributes with no counterpart, relation types it does not know, hierarchies.
See docs/traceability.md, "ReqIF".
"""
from __future__ import annotations

import argparse
import collections
import json
import os
import re
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
if __package__ in (None, ""):
    sys.path.insert(0, os.path.dirname(HERE))
    __package__ = "traceability"  # noqa: A001 - allow `python3 traceability/reqif.py`

from traceability import links as linkgrades  # noqa: E402
from traceability.reproducible import EPOCH, dumps, iso_utc  # noqa: E402
from traceability.srsdata import KIND_NAMES, KIND_ORDER, SRS_FILES, natural_key  # noqa: E402

REQIF_NS = "http://www.omg.org/spec/ReqIF/20110401/reqif.xsd"
XHTML_NS = "http://www.w3.org/1999/xhtml"
FILE_NAME = "tamias2d.reqif"
TOOL_ID = "Tamias2D traceability harness (traceability/reqif.py)"

ITEM_TYPE = "Tamias2D SRS item"
TEST_TYPE = "Tamias2D test or check"
CODE_TYPE = "Tamias2D code site"
SPEC_TYPE = "Tamias2D specification"
RELATIONS = ("verifies", "refines", "uses", "implements")
# A `uses` edge is a refinement where the SRS template refines theory into instance models:
# an instance model using a theoretical model, general definition or another instance model
# (IM5 and IM7 say so of IM1-IM3), a general definition using a theoretical model.
REFINES = {("IM", "TM"), ("IM", "GD"), ("IM", "IM"), ("GD", "TM")}

# srs/ fields the item type carries as attributes of their own; any other field of an item
# travels in "Other SRS fields" (JSON), so that an import loses nothing.
ITEM_FIELDS = ("label", "kind", "alias", "title", "equation", "seed_equation", "symbols", "uses",
               "seed_ref_by", "source", "description", "notes", "errata", "obligation")
SOURCE_FIELDS = {"seed": str, "section": str, "table": int, "url": str}
SYMBOL_KEYS = ("symbol", "unit", "description", "seed_unit", "tamias_unit")

ENUMS = {  # datatype -> its fixed values (values found in the report are appended)
    "Kind": list(KIND_ORDER),
    "Obligation": ["shall", "should", "will"],
    "Item status": ["verified", "goal met", "failing", "goal missed", "model only", "untested",
                    "assumed", "not testable", "not implemented"],
    "Test status": ["passed", "failed", "error", "skipped", "notrun", "known-failure",
                    "target-missed", "goal-missed"],
    "Origin": ["boost", "ctest", "verification"],
    "Grade": ["strong", "weak"],
    "Review": ["reviewed", "suspect", "unreviewed"],
}

# (attribute name, datatype) per spec type; datatype: String, XHTML, Integer, Boolean or an
# enumeration of ENUMS.
ITEM_ATTRS = [
    ("ReqIF.ForeignID", "String"), ("ReqIF.Name", "String"), ("ReqIF.Text", "XHTML"),
    ("Kind", "Kind"), ("Alias", "String"), ("Obligation", "Obligation"),
    ("Equation", "XHTML"), ("Seed equation", "XHTML"), ("Symbols", "XHTML"),
    ("Uses", "String"), ("Seed Ref. By", "String"), ("Ref. By", "String"),
    ("Source seed", "String"), ("Source section", "String"), ("Source table", "Integer"),
    ("Source URL", "String"), ("Errata", "String"), ("Errata text", "XHTML"),
    ("Notes", "XHTML"), ("SRS file", "String"), ("Other SRS fields", "String"),
    ("Status", "Item status"), ("Status reason", "String"), ("Oracle kinds", "String"),
    ("Weak evidence", "Boolean"), ("Evidence notes", "String"), ("Fingerprint", "String"),
]
TEST_ATTRS = [
    ("ReqIF.ForeignID", "String"), ("ReqIF.Name", "String"), ("Origin", "Origin"),
    ("Status", "Test status"), ("Labels", "String"), ("SRS labels", "String"),
    ("Oracle", "String"), ("Oracle kinds", "String"), ("Level", "String"),
    ("Tolerance stated", "Boolean"), ("Source", "String"), ("Command", "String"),
    ("Binary or program", "String"), ("Enabled", "Boolean"), ("Samples", "String"),
    ("Figure", "String"), ("Target", "String"), ("Details", "String"),
    ("Fingerprint", "String"), ("Fingerprint source", "String"),
]
CODE_ATTRS = [
    ("ReqIF.ForeignID", "String"), ("Label", "String"), ("File", "String"), ("Line", "Integer"),
    ("Area", "String"), ("Text", "String"), ("Names an SRS item", "Boolean"),
]
VERIFIES_ATTRS = [
    ("Grade", "Grade"), ("Grade reasons", "String"), ("Level", "String"),
    ("Oracle kinds", "String"), ("Tolerance stated", "Boolean"), ("Review", "Review"),
    ("Changed ends", "String"), ("Reviewer", "String"), ("Review date", "String"),
    ("Item fingerprint", "String"), ("Test fingerprint", "String"),
]
SPEC_ATTRS = [("ReqIF.Name", "String"), ("Section", "String")]
TYPES = [  # (identifier, element, long name, attributes)
    ("SOT-ITEM", "SPEC-OBJECT-TYPE", ITEM_TYPE, ITEM_ATTRS),
    ("SOT-TEST", "SPEC-OBJECT-TYPE", TEST_TYPE, TEST_ATTRS),
    ("SOT-CODE", "SPEC-OBJECT-TYPE", CODE_TYPE, CODE_ATTRS),
    ("SRT-VERIFIES", "SPEC-RELATION-TYPE", "verifies", VERIFIES_ATTRS),
    ("SRT-REFINES", "SPEC-RELATION-TYPE", "refines", []),
    ("SRT-USES", "SPEC-RELATION-TYPE", "uses", []),
    ("SRT-IMPLEMENTS", "SPEC-RELATION-TYPE", "implements", []),
    ("SPT-SPEC", "SPECIFICATION-TYPE", SPEC_TYPE, SPEC_ATTRS),
]
SIMPLE = {"String": "STRING", "XHTML": "XHTML", "Integer": "INTEGER", "Boolean": "BOOLEAN"}


# --------------------------------------------------------------------------- identifiers
def ident(prefix, *parts):
    """An xsd:ID from a prefix and names: letters, digits and '_' kept, every other character
    written as .HH (.uHHHHHH beyond Latin-1), parts joined by '-': one name, one identifier."""
    def esc(s):
        out = []
        for ch in str(s):
            if ch.isascii() and (ch.isalnum() or ch == "_"):
                out.append(ch)
            elif ord(ch) < 256:
                out.append(f".{ord(ch):02x}")
            else:
                out.append(f".u{ord(ch):06x}")
        return "".join(out)
    return "-".join([prefix] + [esc(p) for p in parts])


# --------------------------------------------------------------------------- XML writing
class X:
    """An XML element: tag, attributes (ordered pairs), children (elements or text)."""
    __slots__ = ("tag", "attrs", "kids")

    def __init__(self, tag, attrs=(), kids=()):
        self.tag, self.attrs, self.kids = tag, list(attrs), list(kids)


_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def _text(s):
    s = _BAD.sub(lambda m: f"\\x{ord(m.group()):02x}", str(s))
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def _attr(s):
    return (_text(s).replace('"', "&quot;").replace("\n", "&#10;").replace("\r", "&#13;")
            .replace("\t", "&#9;"))


def _open(el):
    return "<" + el.tag + "".join(f' {k}="{_attr(v)}"' for k, v in el.attrs)


def _inline(el):
    if isinstance(el, str):
        return _text(el)
    if not el.kids:
        return _open(el) + "/>"
    return _open(el) + ">" + "".join(_inline(k) for k in el.kids) + f"</{el.tag}>"


def serialize(el, depth=0, out=None):
    """Indented lines for the ReqIF structure; XHTML content on one line, as written."""
    out = [] if out is None else out
    pad = "  " * depth
    if el.tag.startswith("xhtml:") or not el.kids or any(isinstance(k, str) for k in el.kids):
        out.append(pad + _inline(el))
    else:
        out.append(pad + _open(el) + ">")
        for k in el.kids:
            serialize(k, depth + 1, out)
        out.append(f"{pad}</{el.tag}>")
    return out


def h(tag, *kids, **attrs):
    """An XHTML element."""
    return X("xhtml:" + tag, [(k.rstrip("_"), v) for k, v in attrs.items()], kids)


def text_xhtml(text):
    """Plain text as XHTML: paragraphs at blank lines, <br/> at single line breaks; the
    import reads it back character for character."""
    paras = []
    for para in str(text).split("\n\n"):
        kids = []
        for n, line in enumerate(para.split("\n")):
            if n:
                kids.append(h("br"))
            if line:
                kids.append(line)
        paras.append(h("p", *kids))
    return h("div", *paras)


def code_xhtml(text):
    return h("div", h("code", str(text)), class_="equation")


def _cell(v, tag="td"):
    if v is _ABSENT:
        return h(tag, class_="absent")
    if isinstance(v, str):
        return h(tag, v) if v else h(tag)
    return h(tag, json.dumps(v, ensure_ascii=False), class_="json")


_ABSENT = object()


def symbols_xhtml(symbols):
    """The symbols as an XHTML table, one column per key (symbol, unit, description, the
    seed's and Tamias2D's unit where given, then any other key)."""
    keys = [k for k in SYMBOL_KEYS if any(k in s for s in symbols)]
    keys += sorted({k for s in symbols for k in s if k not in SYMBOL_KEYS})
    head = h("tr", *[h("th", k) for k in keys])
    rows = [h("tr", *[_cell(s.get(k, _ABSENT)) for k in keys]) for s in symbols]
    return h("div", h("table", h("thead", head), h("tbody", *rows)) if rows else h("p"),
             class_="symbols")


# --------------------------------------------------------------------------- export
def _join(xs):
    return ", ".join(str(x) for x in xs)


class _Writer:
    def __init__(self, stamp):
        self.stamp = stamp
        self.attr_ids = {}
        self.enum_values = {name: list(vals) for name, vals in ENUMS.items()}

    def see(self, enum, value):
        if value is not None and value not in self.enum_values[enum]:
            self.enum_values[enum].append(value)

    def values(self, type_id, attrs, vals):
        """ATTRIBUTE-VALUE-* elements for the non-None values, in the type's order."""
        kinds = dict(attrs)
        out = []
        for name, _ in attrs:
            v = vals.get(name)
            if v is None:
                continue
            dt = kinds[name]
            ref = ident("AD", type_id.split("-", 1)[1], name)
            if dt == "XHTML":
                out.append(X("ATTRIBUTE-VALUE-XHTML", kids=[
                    X("DEFINITION", kids=[X("ATTRIBUTE-DEFINITION-XHTML-REF", kids=[ref])]),
                    X("THE-VALUE", kids=[v])]))
            elif dt in SIMPLE:
                s = ("true" if v else "false") if dt == "Boolean" else str(v)
                t = SIMPLE[dt]
                out.append(X(f"ATTRIBUTE-VALUE-{t}", [("THE-VALUE", s)], [
                    X("DEFINITION", kids=[X(f"ATTRIBUTE-DEFINITION-{t}-REF", kids=[ref])])]))
            else:
                out.append(X("ATTRIBUTE-VALUE-ENUMERATION", kids=[
                    X("DEFINITION", kids=[X("ATTRIBUTE-DEFINITION-ENUMERATION-REF", kids=[ref])]),
                    X("VALUES", kids=[X("ENUM-VALUE-REF", kids=[ident("EV", dt, v)])])]))
        return X("VALUES", kids=out)

    def ident_el(self, tag, identifier, long_name=None, kids=(), extra=()):
        attrs = [("IDENTIFIER", identifier), ("LAST-CHANGE", self.stamp)]
        if long_name is not None:
            attrs.append(("LONG-NAME", long_name))
        return X(tag, attrs + list(extra), kids)

    def datatypes(self):
        out = [self.ident_el("DATATYPE-DEFINITION-BOOLEAN", "DT-Boolean", "Boolean"),
               self.ident_el("DATATYPE-DEFINITION-INTEGER", "DT-Integer", "Integer",
                             extra=[("MAX", "2147483647"), ("MIN", "-2147483648")]),
               self.ident_el("DATATYPE-DEFINITION-STRING", "DT-String", "String",
                             extra=[("MAX-LENGTH", "1000000")]),
               self.ident_el("DATATYPE-DEFINITION-XHTML", "DT-XHTML", "XHTML")]
        for name in sorted(self.enum_values):
            vals = [self.ident_el("ENUM-VALUE", ident("EV", name, v), v, kids=[
                X("PROPERTIES", kids=[X("EMBEDDED-VALUE", [("KEY", str(n)), ("OTHER-CONTENT", "")])])])
                for n, v in enumerate(self.enum_values[name])]
            out.append(self.ident_el("DATATYPE-DEFINITION-ENUMERATION", ident("DT", name), name,
                                     kids=[X("SPECIFIED-VALUES", kids=vals)]))
        return X("DATATYPES", kids=out)

    def spec_types(self):
        out = []
        for type_id, tag, name, attrs in TYPES:
            defs = []
            for aname, dt in attrs:
                t = SIMPLE.get(dt, "ENUMERATION")
                dref = f"DT-{dt}" if dt in SIMPLE else ident("DT", dt)
                extra = [("MULTI-VALUED", "false")] if t == "ENUMERATION" else []
                defs.append(self.ident_el(f"ATTRIBUTE-DEFINITION-{t}", ident("AD", type_id.split("-", 1)[1], aname), aname,
                                          kids=[X("TYPE", kids=[X(f"DATATYPE-DEFINITION-{t}-REF", kids=[dref])])],
                                          extra=extra))
            kids = [X("SPEC-ATTRIBUTES", kids=defs)] if defs else []
            out.append(self.ident_el(tag, type_id, name, kids=kids))
        return X("SPEC-TYPES", kids=out)


def _errata_xhtml(ids, errata):
    rows = []
    for e in ids:
        d = errata.get(e)
        if d:
            rows.append(h("li", f"{e} ({d.get('kind') or ''}): {d.get('problem') or ''} "
                                f"Correct reading: {d.get('correct_reading') or ''}"))
        else:
            rows.append(h("li", f"{e}: not in srs/errata.yaml"))
    return h("div", h("ul", *rows)) if rows else None


def _item_values(it, errata):
    extra = dict(it.get("srs_extra") or {})
    raw = it.get("source")
    src = {k: v for k, v in (raw or {}).items() if isinstance(v, SOURCE_FIELDS[k])
           and not isinstance(v, bool)} if isinstance(raw, dict) else {}
    rest = {k: v for k, v in raw.items() if k not in src} if isinstance(raw, dict) else raw
    if rest is not None and (rest or not src):
        extra["source"] = rest  # fields of no attribute of their own (or {}: no field at all)
    v = {"ReqIF.ForeignID": it["label"], "ReqIF.Name": it.get("title"),
         "Kind": it["kind"], "Alias": it.get("alias"), "Obligation": it.get("obligation"),
         "Uses": _join(it.get("uses") or []), "Ref. By": _join(it.get("ref_by") or []),
         "Seed Ref. By": None if it.get("seed_ref_by") is None else _join(it["seed_ref_by"]),
         "Source seed": src.get("seed"), "Source section": src.get("section"),
         "Source table": src.get("table"), "Source URL": src.get("url"),
         "Errata": _join(it.get("errata") or []),
         "Errata text": _errata_xhtml(it.get("errata") or [], errata),
         "SRS file": it.get("file"), "Status": it.get("status"),
         "Status reason": it.get("status_reason"),
         "Oracle kinds": _join(it.get("oracle_kinds") or []),
         "Weak evidence": bool(it.get("weak_evidence")),
         "Evidence notes": "\n".join(it.get("notes") or []) or None,
         "Fingerprint": it.get("fingerprint")}
    for field, attr, make in (("description", "ReqIF.Text", text_xhtml),
                              ("equation", "Equation", code_xhtml),
                              ("seed_equation", "Seed equation", code_xhtml),
                              ("srs_notes", "Notes", text_xhtml)):
        val = it.get(field)
        if isinstance(val, str):
            v[attr] = make(val)
        elif val is not None:
            extra["notes" if field == "srs_notes" else field] = val
    syms = it.get("symbols")
    if isinstance(syms, list) and all(isinstance(s, dict) for s in syms):
        v["Symbols"] = symbols_xhtml(syms)
    elif syms is not None:
        extra["symbols"] = syms
    if extra:
        v["Other SRS fields"] = json.dumps(extra, sort_keys=True, ensure_ascii=False)
    return v


def _test_values(t):
    src = f"{t['file']}:{t['line']}" if t.get("file") and t.get("line") else t.get("file")
    return {"ReqIF.ForeignID": t["id"], "ReqIF.Name": t.get("name"), "Origin": t.get("origin"),
            "Status": t.get("status"), "Labels": _join(t.get("labels") or []),
            "SRS labels": _join(t.get("srs_labels") or []), "Oracle": t.get("oracle"),
            "Oracle kinds": _join(t.get("oracle_kinds") or []), "Level": linkgrades.level_of(t),
            "Tolerance stated": bool(t.get("oracle")) and bool(linkgrades.TOLERANCE.search(str(t["oracle"]))),
            "Source": src, "Command": t.get("command"), "Binary or program": t.get("binary"),
            "Enabled": t.get("enabled"), "Samples": t.get("samples"), "Figure": t.get("figure"),
            "Target": t.get("target"), "Details": t.get("details") or None,
            "Fingerprint": t.get("fingerprint"), "Fingerprint source": t.get("fingerprint_source")}


def _sections(items):
    """[(kind, section number, items)] in the SRS's order."""
    by_kind = collections.OrderedDict()
    for k in KIND_ORDER + sorted({i["kind"] for i in items} - set(KIND_ORDER)):
        its = [i for i in items if i["kind"] == k]
        if not its:
            continue
        secs = collections.Counter(str((i.get("source") or {}).get("section")) for i in its
                                   if isinstance(i.get("source"), dict) and (i["source"] or {}).get("section"))
        sec = sorted(secs.items(), key=lambda kv: (-kv[1], natural_key(kv[0])))[0][0] if secs else ""
        by_kind[k] = (sec, its)
    return [(k, sec, its) for k, (sec, its) in by_kind.items()]


def code_ids(code_sites):
    """Stable identifiers of the code sites: file, label and the tag's rank among the file's
    tags of that label (lines move, the rank rarely does)."""
    rank, out = collections.Counter(), []
    for s in sorted(code_sites, key=lambda s: (s["file"], s["line"], s["label"])):
        rank[(s["file"], s["label"])] += 1
        out.append((ident("CODE", s["file"], s["label"], rank[(s["file"], s["label"])]), s))
    return out


def build(report):
    """(REQ-IF element, summary) of a report (the traceability.json document)."""
    src = report.get("source") or {}
    stamp = src.get("git_commit_date") or EPOCH
    w = _Writer(stamp)
    items = report.get("items") or []
    tests = sorted(report.get("tests") or [], key=lambda t: t["id"])
    errata = {e.get("id"): e for e in report.get("errata") or []}
    labels = {i["label"]: i for i in items}
    for i in items:
        w.see("Kind", i["kind"])
        w.see("Obligation", i.get("obligation"))
        w.see("Item status", i.get("status"))
    for t in tests:
        w.see("Test status", t.get("status"))
        w.see("Origin", t.get("origin"))
    for ln in report.get("links") or []:
        w.see("Grade", ln.get("grade"))
        w.see("Review", (ln.get("review") or {}).get("status"))

    objects = []
    for it in items:
        objects.append(w.ident_el("SPEC-OBJECT", ident("SRS", it["label"]), it["label"], kids=[
            X("TYPE", kids=[X("SPEC-OBJECT-TYPE-REF", kids=["SOT-ITEM"])]),
            w.values("SOT-ITEM", ITEM_ATTRS, _item_values(it, errata))]))
    for t in tests:
        objects.append(w.ident_el("SPEC-OBJECT", ident("TEST", t["id"]), t["id"], kids=[
            X("TYPE", kids=[X("SPEC-OBJECT-TYPE-REF", kids=["SOT-TEST"])]),
            w.values("SOT-TEST", TEST_ATTRS, _test_values(t))]))
    codes = code_ids(report.get("code_sites") or [])
    for cid, s in codes:
        vals = {"ReqIF.ForeignID": f"{s['file']}:{s['line']} {s['label']}", "Label": s["label"],
                "File": s["file"], "Line": s["line"], "Area": s.get("area"),
                "Text": s.get("text"), "Names an SRS item": s["label"] in labels}
        objects.append(w.ident_el("SPEC-OBJECT", cid, f"{s['file']}:{s['line']}", kids=[
            X("TYPE", kids=[X("SPEC-OBJECT-TYPE-REF", kids=["SOT-CODE"])]),
            w.values("SOT-CODE", CODE_ATTRS, vals)]))

    relations = []

    def relation(kind, source, target, vals=None):
        type_id = "SRT-" + kind.upper()
        kids = [X("SOURCE", kids=[X("SPEC-OBJECT-REF", kids=[source])]),
                X("TARGET", kids=[X("SPEC-OBJECT-REF", kids=[target])]),
                X("TYPE", kids=[X("SPEC-RELATION-TYPE-REF", kids=[type_id])])]
        if vals is not None:
            kids.insert(0, w.values(type_id, VERIFIES_ATTRS, vals))
        relations.append(w.ident_el("SPEC-RELATION", ident("REL", kind, source, target), kind, kids=kids))

    test_ids = {t["id"] for t in tests}
    for ln in report.get("links") or []:
        if ln["item"] not in labels or ln["test"] not in test_ids:
            continue
        rv = ln.get("review") or {}
        relation("verifies", ident("TEST", ln["test"]), ident("SRS", ln["item"]), {
            "Grade": ln.get("grade"), "Grade reasons": "; ".join(ln.get("reasons") or []),
            "Level": ln.get("level"), "Oracle kinds": _join(ln.get("oracle_kinds") or []),
            "Tolerance stated": ln.get("tolerance_stated"), "Review": rv.get("status"),
            "Changed ends": _join(rv.get("changed") or []) if rv.get("status") == "suspect" else None,
            "Reviewer": rv.get("reviewer"), "Review date": rv.get("date"),
            "Item fingerprint": ln.get("item_fingerprint"), "Test fingerprint": ln.get("test_fingerprint")})
    for it in items:
        for used in dict.fromkeys(it.get("uses") or []):
            if used in labels:
                kind = "refines" if (it["kind"], labels[used]["kind"]) in REFINES else "uses"
                relation(kind, ident("SRS", it["label"]), ident("SRS", used))
    for cid, s in codes:
        if s["label"] in labels:
            relation("implements", cid, ident("SRS", s["label"]))

    specs = []

    def specification(spec_id, name, section, object_ids):
        kids = [w.ident_el("SPEC-HIERARCHY", "H-" + oid, kids=[
            X("OBJECT", kids=[X("SPEC-OBJECT-REF", kids=[oid])])]) for oid in object_ids]
        vals = w.values("SPT-SPEC", SPEC_ATTRS, {"ReqIF.Name": name, "Section": section or None})
        el = [vals, X("TYPE", kids=[X("SPECIFICATION-TYPE-REF", kids=["SPT-SPEC"])])]
        if kids:
            el.append(X("CHILDREN", kids=kids))
        specs.append(w.ident_el("SPECIFICATION", spec_id, name, kids=el))

    for kind, sec, its in _sections(items):
        name = f"{sec} {KIND_NAMES.get(kind, kind)}".strip()
        specification(ident("SPEC", kind), name, sec, [ident("SRS", i["label"]) for i in its])
    specification("SPEC-tests", "Tests and verification checks", None, [ident("TEST", t["id"]) for t in tests])
    specification("SPEC-code", "Code sites (\\srs tags)", None, [cid for cid, _ in codes])

    objects.sort(key=lambda e: e.attrs[0][1])
    relations.sort(key=lambda e: e.attrs[0][1])
    created = iso_utc(report.get("generated")) or stamp
    header = X("REQ-IF-HEADER", [("IDENTIFIER", "tamias2d-traceability")], [
        X("COMMENT", kids=[f"Tamias2D traceability report (schema {report.get('schema_version')}) "
                           "as ReqIF; docs/traceability.md"]),
        X("CREATION-TIME", kids=[created]),
        X("REPOSITORY-ID", kids=["tamias2d"]),
        X("REQ-IF-TOOL-ID", kids=[TOOL_ID]),
        X("REQ-IF-VERSION", kids=["1.0"]),
        X("SOURCE-TOOL-ID", kids=[TOOL_ID]),
        X("TITLE", kids=[f"Tamias2D SRS traceability, commit {str(src.get('git_commit') or 'unknown')[:12]}"])])
    content = X("REQ-IF-CONTENT", kids=[w.datatypes(), w.spec_types(), X("SPEC-OBJECTS", kids=objects),
                                        X("SPEC-RELATIONS", kids=relations),
                                        X("SPECIFICATIONS", kids=specs)])
    root = X("REQ-IF", [("xmlns", REQIF_NS), ("xmlns:xhtml", XHTML_NS)], [
        X("THE-HEADER", kids=[header]), X("CORE-CONTENT", kids=[content])])
    counts = collections.Counter(e.attrs[2][1] for e in relations)
    summary = {"file": FILE_NAME, "last_change": stamp,
               "spec_objects": {"items": len(items), "tests": len(tests), "code_sites": len(codes)},
               "spec_relations": {k: counts.get(k, 0) for k in RELATIONS},
               "specifications": [e.attrs[2][1] for e in specs]}
    return root, summary


def export_text(report):
    """(the ReqIF document's text, summary)."""
    root, summary = build(report)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + "\n".join(serialize(root)) + "\n", summary


def srs_extra(srs, items):
    """Sets items[].srs_extra: the item's srs/ fields the report has no other key for (a DC
    item's variable and constraint, an IM's inputs, seed_cites...), so the export is whole."""
    for it in items:
        raw = srs.items.get(it["label"]) or {}
        it["srs_extra"] = {k: v for k, v in raw.items() if k not in ITEM_FIELDS and not k.startswith("_")}


def attach(report, js):
    """Called by build_report.py: the ReqIF text of the report's JSON document js (read back
    as a file would be), with its summary set as report["reqif"] and js["reqif"]."""
    text, summary = export_text(json.loads(dumps(js)))
    report["reqif"] = js["reqif"] = summary
    return text


# --------------------------------------------------------------------------- import
def _q(tag):
    return f"{{{REQIF_NS}}}{tag}"


def xhtml_text(el):
    """The text of an XHTML value: paragraphs joined by a blank line, <br/> as a line break."""
    if el is None:
        return None
    kids = [k for k in el if k.tag.startswith(f"{{{XHTML_NS}}}")]
    local = el.tag.split("}")[-1]
    if local in ("div", "THE-VALUE", "body") and kids and all(
            k.tag.split("}")[-1] in ("p", "div", "ul", "ol", "table", "pre") for k in kids):
        return "\n\n".join(xhtml_text(k) for k in kids)
    parts = [el.text or ""]
    for k in el:
        name = k.tag.split("}")[-1]
        if name == "br":
            parts.append("\n")
        elif name == "li":
            parts.append("\n- " + (xhtml_text(k) or ""))
        else:
            parts.append(xhtml_text(k) or "")
        parts.append(k.tail or "")
    return "".join(parts)


def _symbols(div):
    table = div.find(f"{{{XHTML_NS}}}table")
    if table is None:
        return []
    head = table.find(f"{{{XHTML_NS}}}thead/{{{XHTML_NS}}}tr")
    keys = [th.text or "" for th in head] if head is not None else []
    out = []
    for tr in table.iterfind(f"{{{XHTML_NS}}}tbody/{{{XHTML_NS}}}tr"):
        sym = {}
        for k, td in zip(keys, tr):
            cls = td.get("class")
            if cls == "absent":
                continue
            sym[k] = json.loads(td.text) if cls == "json" else (td.text or "")
        out.append(sym)
    return out


def _split(s):
    return [x for x in str(s).split(", ") if x] if s else []


class ReqifFile:
    """A parsed ReqIF file: datatypes, types, objects, relations, specifications."""

    def __init__(self, path):
        self.root = ET.parse(path).getroot()
        if self.root.tag != _q("REQ-IF"):
            raise ValueError(f"{path}: the root element is {self.root.tag}, not REQ-IF")
        self.problems = []
        content = self.root.find(f"{_q('CORE-CONTENT')}/{_q('REQ-IF-CONTENT')}")
        if content is None:
            raise ValueError(f"{path}: no CORE-CONTENT/REQ-IF-CONTENT")
        self.enum_names = {}
        for dt in content.iterfind(f"{_q('DATATYPES')}/*"):
            for ev in dt.iter(_q("ENUM-VALUE")):
                self.enum_names[ev.get("IDENTIFIER")] = ev.get("LONG-NAME") or ev.get("IDENTIFIER")
        self.types, self.attr_defs = {}, {}
        for t in content.iterfind(f"{_q('SPEC-TYPES')}/*"):
            self.types[t.get("IDENTIFIER")] = (t.tag.split("}")[-1], t.get("LONG-NAME") or t.get("IDENTIFIER"))
            for ad in t.iterfind(f"{_q('SPEC-ATTRIBUTES')}/*"):
                kind = ad.tag.split("}")[-1].replace("ATTRIBUTE-DEFINITION-", "")
                self.attr_defs[ad.get("IDENTIFIER")] = (ad.get("LONG-NAME") or ad.get("IDENTIFIER"), kind)
        self.objects = collections.OrderedDict()
        for o in content.iterfind(f"{_q('SPEC-OBJECTS')}/{_q('SPEC-OBJECT')}"):
            ref = o.findtext(f"{_q('TYPE')}/{_q('SPEC-OBJECT-TYPE-REF')}")
            self.objects[o.get("IDENTIFIER")] = {"id": o.get("IDENTIFIER"), "type": self.types.get(ref, ("", ref))[1],
                                                 "long_name": o.get("LONG-NAME"), "values": self._values(o)}
        self.relations = []
        for r in content.iterfind(f"{_q('SPEC-RELATIONS')}/{_q('SPEC-RELATION')}"):
            ref = r.findtext(f"{_q('TYPE')}/{_q('SPEC-RELATION-TYPE-REF')}")
            self.relations.append({"id": r.get("IDENTIFIER"), "type": self.types.get(ref, ("", ref))[1],
                                   "source": r.findtext(f"{_q('SOURCE')}/{_q('SPEC-OBJECT-REF')}"),
                                   "target": r.findtext(f"{_q('TARGET')}/{_q('SPEC-OBJECT-REF')}"),
                                   "values": self._values(r)})
        self.specifications = []
        for s in content.iterfind(f"{_q('SPECIFICATIONS')}/{_q('SPECIFICATION')}"):
            order = [x.findtext(f"{_q('OBJECT')}/{_q('SPEC-OBJECT-REF')}") for x in s.iter(_q("SPEC-HIERARCHY"))]
            nested = any(x.find(_q("CHILDREN")) is not None for x in s.iter(_q("SPEC-HIERARCHY")))
            self.specifications.append({"id": s.get("IDENTIFIER"), "name": s.get("LONG-NAME"),
                                        "objects": order, "nested": nested})
        self.tool_extensions = self.root.find(_q("TOOL-EXTENSIONS")) is not None

    def _values(self, el):
        vals = {}
        for v in el.iterfind(f"{_q('VALUES')}/*"):
            kind = v.tag.split("}")[-1].replace("ATTRIBUTE-VALUE-", "")
            ref = v.findtext(f"{_q('DEFINITION')}/*")
            name, _ = self.attr_defs.get(ref, (None, None))
            if name is None:
                self.problems.append(f"value of an undefined attribute {ref!r} ignored")
                continue
            if kind == "XHTML":
                tv = v.find(_q("THE-VALUE"))
                vals[name] = (kind, tv[0] if tv is not None and len(tv) else None)
            elif kind == "ENUMERATION":
                vals[name] = (kind, [self.enum_names.get(x.text, x.text)
                                     for x in v.iterfind(f"{_q('VALUES')}/{_q('ENUM-VALUE-REF')}")])
            elif kind == "INTEGER":
                vals[name] = (kind, int(v.get("THE-VALUE")))
            elif kind == "BOOLEAN":
                vals[name] = (kind, v.get("THE-VALUE") in ("true", "1"))
            elif kind == "REAL":
                vals[name] = (kind, float(v.get("THE-VALUE")))
            else:
                vals[name] = (kind, v.get("THE-VALUE"))
        return vals


def _plain(val):
    """An attribute value as plain Python data (XHTML as text, a one-value enum as a string)."""
    kind, v = val
    if kind == "XHTML":
        return xhtml_text(v)
    if kind == "ENUMERATION":
        return v[0] if len(v) == 1 else v
    return v


KIND_OF_LABEL = re.compile(r"^(GS|TM|GD|DD|IM|NFR|LC|UC|DC|T|A|R)(?=[0-9_IOX])")
LABEL_ATTRS = ("ReqIF.ForeignID", "Label", "ID", "Identifier", "UID")
TITLE_ATTRS = ("ReqIF.Name", "Title", "ReqIF.ChapterName", "Heading")
TEXT_ATTRS = ("ReqIF.Text", "Statement", "Text", "Description", "ReqIF.Description")


def _own_item(vals):
    g = {k: _plain(v) for k, v in vals.items()}
    item = {"label": g.get("ReqIF.ForeignID"), "kind": g.get("Kind")}
    if "Alias" in g:
        item["alias"] = g["Alias"]
    if "ReqIF.Name" in g:
        item["title"] = g["ReqIF.Name"]
    if "Equation" in vals:
        item["equation"] = g["Equation"]
    if "Seed equation" in vals:
        item["seed_equation"] = g["Seed equation"]
    if "Symbols" in vals:
        item["symbols"] = _symbols(vals["Symbols"][1]) if vals["Symbols"][1] is not None else []
    item["uses"] = _split(g.get("Uses"))
    if "Seed Ref. By" in g:
        item["seed_ref_by"] = _split(g["Seed Ref. By"])
    source = {k: g[a] for k, a in (("seed", "Source seed"), ("section", "Source section"),
                                   ("table", "Source table"), ("url", "Source URL")) if a in g}
    if source:
        item["source"] = source
    if "ReqIF.Text" in vals:
        item["description"] = g["ReqIF.Text"]
    if "Notes" in vals:
        item["notes"] = g["Notes"]
    item["errata"] = _split(g.get("Errata"))
    if "Obligation" in g:
        item["obligation"] = g["Obligation"]
    extra = json.loads(g["Other SRS fields"]) if g.get("Other SRS fields") else {}
    if isinstance(extra.get("source"), dict) and isinstance(item.get("source"), dict):
        item["source"].update(extra.pop("source"))
    item.update(extra)
    evidence = {"status": g.get("Status"), "status_reason": g.get("Status reason"),
                "fingerprint": g.get("Fingerprint"), "file": g.get("SRS file"),
                "ref_by": _split(g.get("Ref. By"))}
    return item, evidence


def read(path):
    """The project's data in a ReqIF file: {items, tests, links, code_sites, sections,
    unmapped[], summary}. Raises ValueError when the file is not ReqIF."""
    try:
        f = ReqifFile(path)
    except ET.ParseError as exc:
        raise ValueError(f"{path}: not XML ({exc})") from exc
    unmapped = list(dict.fromkeys(f.problems))
    items, evidence, tests, codes = [], {}, [], {}
    obj_label = {}
    skipped_attrs = collections.Counter()
    unmapped_objects = []
    for o in f.objects.values():
        vals = o["values"]
        if o["type"] == ITEM_TYPE:
            item, ev = _own_item(vals)
            items.append(item)
            evidence[item["label"]] = ev
            obj_label[o["id"]] = item["label"]
            known = {a for a, _ in ITEM_ATTRS}
        elif o["type"] == TEST_TYPE:
            g = {k: _plain(v) for k, v in vals.items()}
            tests.append({"id": g.get("ReqIF.ForeignID"), "name": g.get("ReqIF.Name"),
                          "origin": g.get("Origin"), "status": g.get("Status"),
                          "labels": _split(g.get("Labels")), "oracle": g.get("Oracle"),
                          "source": g.get("Source"), "fingerprint": g.get("Fingerprint")})
            obj_label[o["id"]] = "test:" + str(g.get("ReqIF.ForeignID"))
            known = {a for a, _ in TEST_ATTRS}
        elif o["type"] == CODE_TYPE:
            g = {k: _plain(v) for k, v in vals.items()}
            codes[o["id"]] = {"label": g.get("Label"), "file": g.get("File"), "line": g.get("Line"),
                              "area": g.get("Area"), "text": g.get("Text")}
            known = {a for a, _ in CODE_ATTRS}
        else:
            # Another tool's object: an SRS item when it has a label of an SRS kind.
            g = {k: _plain(v) for k, v in vals.items()}
            label = next((str(g[a]).strip() for a in LABEL_ATTRS if g.get(a) not in (None, "")), None)
            kind = g.get("Kind") or (KIND_OF_LABEL.match(label).group(1) if label and KIND_OF_LABEL.match(label) else None)
            kind = {"T": "TM"}.get(kind, kind)
            used_attrs = set(LABEL_ATTRS) | {"Kind"}
            if not label or not kind:
                why = "no label attribute (" + " / ".join(LABEL_ATTRS[:2]) + ")" if not label else \
                    f"label {label!r} is of no SRS kind and no Kind attribute gives one"
                names = ", ".join(sorted(vals)) or "none"
                unmapped_objects.append(f"object {o['id']} (type {o['type']!r}; attributes: {names}): "
                                        f"{why}; not an SRS item")
                continue
            item = {"label": label, "kind": kind, "uses": [], "errata": []}
            title = next((a for a in TITLE_ATTRS if g.get(a) not in (None, "")), None)
            text = next((a for a in TEXT_ATTRS if g.get(a) not in (None, "")), None)
            if title:
                item["title"] = str(g[title])
                used_attrs.add(title)
            if text:
                item["description"] = str(g[text])
                used_attrs.add(text)
            items.append(item)
            obj_label[o["id"]] = label
            known = used_attrs
        for name in vals:
            if name not in known:
                skipped_attrs[(o["type"], name)] += 1
    labels = {i["label"] for i in items}
    links, rel_uses = [], collections.defaultdict(list)
    other_rel = collections.Counter()
    dangling = 0
    for r in f.relations:
        s, t = obj_label.get(r["source"]), obj_label.get(r["target"])
        typ = str(r["type"]).lower()
        if typ not in RELATIONS:
            other_rel[r["type"]] += 1
            continue
        if typ == "implements" and r["source"] in codes and t in labels:
            continue
        if s is None or t is None or t not in labels:
            dangling += 1
            continue
        if typ == "verifies" and s.startswith("test:"):
            g = {k: _plain(v) for k, v in r["values"].items()}
            links.append({"item": t, "test": s[5:], "grade": g.get("Grade"),
                          "review": g.get("Review"), "item_fingerprint": g.get("Item fingerprint"),
                          "test_fingerprint": g.get("Test fingerprint")})
        elif typ in ("uses", "refines") and s in labels:
            rel_uses[s].append(t)
        else:
            dangling += 1
    for item in items:
        if item["label"] in evidence:
            # This module's own file: `uses` is the item's attribute; the relations must agree.
            if sorted(set(rel_uses.get(item["label"], []))) != sorted({u for u in item["uses"] if u in labels}):
                unmapped.append(f"{item['label']}: its uses/refines relations differ from its Uses attribute")
        else:
            item["uses"] = list(dict.fromkeys(rel_uses.get(item["label"], [])))
    for (typ, name), n in sorted(skipped_attrs.items()):
        unmapped.append(f"attribute {name!r} of type {typ!r} ({n} object(s)): no counterpart in srs/ items")
    unmapped += unmapped_objects
    for typ, n in sorted(other_rel.items()):
        unmapped.append(f"relation type {typ!r} ({n} relation(s)): not one of {', '.join(RELATIONS)}")
    if dangling:
        unmapped.append(f"{dangling} relation(s) between objects that are not SRS items, tests or code sites")
    header = f.root.find(f"{_q('THE-HEADER')}/{_q('REQ-IF-HEADER')}")
    own = header is not None and header.findtext(_q("REQ-IF-TOOL-ID")) == TOOL_ID
    for s in f.specifications:
        if not own:
            unmapped.append(f"specification {s['name'] or s['id']!r} ({len(s['objects'])} object(s)"
                            + (", nested" if s["nested"] else "") + "): its hierarchy has no "
                            "counterpart (items are ordered by kind and label)")
    if f.tool_extensions:
        unmapped.append("TOOL-EXTENSIONS: ignored")
    summary = {"title": header.findtext(_q("TITLE")) if header is not None else None,
               "tool": header.findtext(_q("REQ-IF-TOOL-ID")) if header is not None else None,
               "objects": len(f.objects), "relations": len(f.relations),
               "specifications": len(f.specifications), "items": len(items), "tests": len(tests),
               "links": len(links), "code_sites": len(codes)}
    return {"items": items, "evidence": evidence, "tests": tests, "links": links,
            "code_sites": list(codes.values()), "unmapped": unmapped, "summary": summary}


def normal_item(item):
    """An item as compared by the round trip: its srs/ fields without None values."""
    return {k: v for k, v in item.items() if v is not None and not k.startswith("_")}


def compare_items(expected, imported):
    """Differences between srs/ items ({label: record}) and imported ones (list)."""
    got = {i["label"]: normal_item(i) for i in imported}
    diffs = []
    for lab, it in expected.items():
        want = normal_item(it)
        if lab not in got:
            diffs.append(f"{lab}: missing from the import")
            continue
        for k in sorted(set(want) | set(got[lab])):
            if want.get(k) != got[lab].get(k):
                diffs.append(f"{lab}.{k}: {want.get(k)!r} became {got[lab].get(k)!r}")
    diffs += [f"{lab}: not in srs/" for lab in got if lab not in expected]
    return diffs


def write_srs(items, out_dir, evidence=None):
    """srs/-style YAML files of imported items: the file each came from (when the ReqIF file
    says), else one per kind."""
    import yaml
    by_file = collections.OrderedDict()
    kind_file = dict(zip(["GS", "A", "TM", "GD", "DD", "IM", "R", "NFR", "LC", "DC"], SRS_FILES))
    kind_file["UC"] = "changes.yaml"
    for it in items:
        came = ((evidence or {}).get(it["label"]) or {}).get("file")
        name = os.path.basename(came) if came else kind_file.get(it["kind"], "other.yaml")
        by_file.setdefault(name, []).append(
            {k: v for k, v in it.items()})
    os.makedirs(out_dir, exist_ok=True)
    for name, its in by_file.items():
        with open(os.path.join(out_dir, name), "w", encoding="utf-8") as fh:
            yaml.safe_dump(its, fh, sort_keys=False, allow_unicode=True, width=100)
    return list(by_file)


# --------------------------------------------------------------------------- command line
def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    e = sub.add_parser("export", help="write the report as ReqIF")
    e.add_argument("--report", default="reports/traceability.json")
    e.add_argument("--out", default=None, help=f"output file (default: {FILE_NAME} beside the report)")
    i = sub.add_parser("import", help="read a ReqIF file back into item records")
    i.add_argument("file")
    i.add_argument("--out", default=None, help="write srs/-style YAML files into this directory")
    i.add_argument("--json", default=None, help="write everything read as JSON")
    v = sub.add_parser("validate", help="validate against the ReqIF XML Schema (python3-xmlschema)")
    v.add_argument("file")
    v.add_argument("--schema", default=os.path.join(os.path.dirname(HERE), "..", "shared",
                                                    "standards", "reqif", "reqif.xsd"))
    args = p.parse_args(argv)
    if args.cmd == "export":
        with open(args.report, encoding="utf-8") as fh:
            report = json.load(fh)
        text, summary = export_text(report)
        out = args.out or os.path.join(os.path.dirname(os.path.abspath(args.report)), FILE_NAME)
        with open(out, "w", encoding="utf-8") as fh:
            fh.write(text)
        so = summary["spec_objects"]
        print(f"{out}: {so['items']} items, {so['tests']} tests and checks, {so['code_sites']} code "
              f"sites; relations " + ", ".join(f"{k} {n}" for k, n in summary["spec_relations"].items()))
        return 0
    if args.cmd == "validate":
        try:
            import xmlschema
        except ImportError:
            print("reqif: python3-xmlschema is not installed (scripts/setup.sh installs it)", file=sys.stderr)
            return 2
        if not os.path.exists(args.schema):
            print(f"reqif: no schema at {args.schema}", file=sys.stderr)
            return 2
        errors = list(xmlschema.XMLSchema(args.schema).iter_errors(args.file))
        for err in errors[:20]:
            print(f"{args.file}: {err.reason} at {err.path}", file=sys.stderr)
        print(f"{args.file}: {'valid' if not errors else f'{len(errors)} error(s)'} against {args.schema}")
        return 0 if not errors else 1
    try:
        data = read(args.file)
    except (OSError, ValueError) as exc:
        print(f"reqif: {exc}", file=sys.stderr)
        return 1
    s = data["summary"]
    print(f"{args.file}: {s['objects']} objects, {s['relations']} relations, {s['specifications']} "
          f"specifications ({s['tool']}); mapped {s['items']} SRS items, {s['tests']} tests, "
          f"{s['links']} verifies links, {s['code_sites']} code sites")
    print(f"not mapped ({len(data['unmapped'])}):" if data["unmapped"] else "not mapped: nothing")
    for u in data["unmapped"]:
        print(f"  - {u}")
    if args.out:
        names = write_srs(data["items"], args.out, data["evidence"])
        print(f"wrote {', '.join(names) or 'no files'} into {args.out}")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({k: v for k, v in data.items()}, fh, indent=1, ensure_ascii=False)
            fh.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
