"""Traceability graphs (Graphviz), Drasil style: one fill colour per kind, edges from the used
item to the item that uses it (change the tail, revisit the head)."""
from __future__ import annotations

import os
import re
import shutil
import subprocess

# Drasil's TraceyGraph colours for the kinds it has (A, DD, GD, TM, IM, R, GS, changes); the
# kinds Drasil lumps together (FR/NFR, LC/UC) and DC get their own colour here.
KIND_COLOURS = {
    "A": "mistyrose", "DD": "paleturquoise1", "GD": "palegreen", "TM": "pink", "IM": "khaki1",
    "R": "ivory", "GS": "darkgoldenrod1", "LC": "lavender", "UC": "thistle", "NFR": "wheat",
    "DC": "lightcyan",
}
KIND_HEX = {  # the same colours as hex, for the HTML legend
    "A": "#ffe4e1", "DD": "#bbffff", "GD": "#98fb98", "TM": "#ffc0cb", "IM": "#fff68f",
    "R": "#fffff0", "GS": "#ffb90f", "LC": "#e6e6fa", "UC": "#d8bfd8", "NFR": "#f5deb3",
    "DC": "#e0ffff",
}
STATUS_BORDER = {"verified": "#2e7d32", "goal met": "#2e7d32", "failing": "#c62828",
                 "goal missed": "#ef6c00", "model only": "#2e7d32", "untested": "#ef6c00",
                 "assumed": "#5b6474", "not testable": "#5b6474", "not implemented": "#757575"}

VIEWS = [
    {"id": "graph_table3", "title": "Goals and requirements vs instance models, requirements and data constraints (Table 3 view)",
     "users": ["GS", "R"], "used": ["IM", "R", "DC"], "rankdir": "TB"},
    {"id": "graph_table4", "title": "Assumptions and the items that use them (Table 4 view)",
     "users": ["TM", "GD", "DD", "IM", "LC"], "used": ["A"], "rankdir": "TB"},
    {"id": "graph_table5", "title": "Theoretical models, general/data definitions and instance models among themselves (Table 5 view)",
     "users": ["TM", "GD", "DD", "IM"], "used": ["TM", "GD", "DD", "IM"], "rankdir": "TB"},
    {"id": "graph_all", "title": "All items", "users": None, "used": None, "rankdir": "LR"},
]


def _q(s):
    return '"' + str(s).replace("\\", "\\\\").replace('"', '\\"') + '"'


def view_dot(srs, status_of, view):
    users, used = view["users"], view["used"]
    if users is None:
        nodes = list(srs.order)
    else:
        kinds = set(users) | set(used)
        nodes = [lab for lab in srs.order if srs.items[lab]["kind"] in kinds]
    nodeset = set(nodes)
    edges = []
    for lab in nodes:
        it = srs.items[lab]
        if users is not None and it["kind"] not in users:
            continue
        for u in it["uses"]:
            if u not in nodeset:
                continue
            if used is not None and srs.items[u]["kind"] not in used:
                continue
            edges.append((u, lab))
    # Items with no edge in this view are listed beside the graph, not drawn: a column of
    # unconnected boxes says nothing a list does not, and it swamps the layout.
    linked = {a for a, _ in edges} | {b for _, b in edges}
    isolated = [lab for lab in nodes if lab not in linked]
    nodes = [lab for lab in nodes if lab in linked]
    lines = [f"digraph {_q(view['id'])} {{",
             f"  rankdir={view['rankdir']}; bgcolor=transparent; nodesep=0.25; ranksep=0.6;",
             '  node [shape=box, style="rounded,filled", fontname="Helvetica", fontsize=11, penwidth=2];',
             '  edge [color="#555555", arrowsize=0.7];']
    by_kind = {}
    for lab in nodes:
        by_kind.setdefault(srs.items[lab]["kind"], []).append(lab)
    for kind, labs in by_kind.items():
        lines.append(f"  subgraph {_q('k_' + kind)} {{")
        for lab in labs:
            it = srs.items[lab]
            st = status_of.get(lab, "not implemented")
            tip = f"{lab}: {it.get('title') or ''} [{st}]"
            style = '"rounded,filled,dashed"' if st == "not implemented" else '"rounded,filled"'
            lines.append(f"    {_q(lab)} [fillcolor={_q(KIND_COLOURS.get(kind, 'white'))}, "
                         f"color={_q(STATUS_BORDER[st])}, style={style}, "
                         f"URL={_q('#item-' + lab)}, target=\"_top\", tooltip={_q(tip)}];")
        lines.append("  }")
    for a, b in edges:
        lines.append(f"  {_q(a)} -> {_q(b)};")
    lines.append("}")
    return "\n".join(lines) + "\n", len(nodes), len(edges), isolated


def render_graphs(srs, status_of, out_dir, warnings):
    """Write graphs/<id>.dot and .svg; return [{id, title, dot, svg, inline, nodes, edges}]."""
    gdir = os.path.join(out_dir, "graphs")
    os.makedirs(gdir, exist_ok=True)
    dot_bin = shutil.which("dot")
    if not dot_bin:
        warnings.append("Graphviz `dot` not found: graphs written as .dot only")
    out = []
    for view in VIEWS:
        text, n, e, isolated = view_dot(srs, status_of, view)
        dpath = os.path.join(gdir, view["id"] + ".dot")
        with open(dpath, "w", encoding="utf-8") as fh:
            fh.write(text)
        rec = {"id": view["id"], "title": view["title"], "dot": f"graphs/{view['id']}.dot",
               "svg": None, "inline": None, "nodes": n, "edges": e, "isolated": isolated}
        if dot_bin and n:
            try:
                proc = subprocess.run([dot_bin, "-Tsvg"], input=text, capture_output=True,
                                      text=True, timeout=120)
                if proc.returncode == 0:
                    svg = proc.stdout
                    with open(os.path.join(gdir, view["id"] + ".svg"), "w", encoding="utf-8") as fh:
                        fh.write(svg)
                    rec["svg"] = f"graphs/{view['id']}.svg"
                    rec["inline"] = inline_svg(svg)
                else:
                    warnings.append(f"dot failed on {view['id']}: {proc.stderr.strip()[:300]}")
            except (OSError, subprocess.TimeoutExpired) as exc:
                warnings.append(f"dot failed on {view['id']}: {exc}")
        out.append(rec)
    return out


def inline_svg(svg):
    """Strip the XML prolog, doctype and comments so the SVG can sit inside HTML."""
    svg = re.sub(r"<\?xml[^>]*\?>", "", svg)
    svg = re.sub(r"<!DOCTYPE[^>]*>", "", svg, flags=re.S)
    svg = re.sub(r"<!--.*?-->", "", svg, flags=re.S)
    return svg.strip()
