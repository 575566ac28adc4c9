"""index.html: one self-contained page (inline CSS and a few lines of JS for sorting; the graphs
are inline SVG; plots are SVG files under reports/plots/)."""
from __future__ import annotations

import html
import json
import os
import re

from . import module_reach_reference, mutation_reference, render_audit
from .graphs import KIND_HEX, STATUS_BORDER
from .srsdata import KIND_NAMES

E = html.escape

STATUS_CLASS = {"verified": "st-ok", "goal met": "st-ok", "goal missed": "st-warn",
                "goal-missed": "st-warn", "failing": "st-fail", "untested": "st-warn",
                "model only": "st-ok", "assumed": "st-none", "not testable": "st-none", "not implemented": "st-none", "passed": "st-ok", "known-failure": "st-warn",
                "target-missed": "st-warn", "failed": "st-fail",
                "error": "st-fail", "skipped": "st-none", "notrun": "st-none"}
STATUS_HELP = {
    "verified": "at least one passing test or check labelled with the item, and none failing",
    "goal met": "a \"should\" requirement (a goal, srs/ obligation) whose labelled checks pass",
    "failing": "at least one labelled test or check fails",
    "goal missed": "a \"should\" requirement (a goal) whose measured figure misses its limit; shown with the figure, never gating",
    "model only": "a model item whose formula the engine does not evaluate (srs/ engine: model-only, the reason is on the item): its module's labelled tests pass, and tests beyond the module do not count for it",
    "untested": "code carries the item's \\srs tag (or labelled tests exist but did not run), but nothing passing verifies it",
    "assumed": "no test can verify it: an assumption the code is built on (the reason is on the item); no labelled test exists",
    "not testable": "no test can verify it (the reason is on the item): a statement about the project, not the code; no labelled test exists",
    "not implemented": "neither a code tag nor a labelled test",
    "known-failure": "a test declared with Boost's expected_failures(N): exactly N known, documented findings fail (docs/verification.md); any other failure fails the test",
    "target-missed": "a verification check stating a goal beyond the SRS (e.g. one of the project's speed floors) that this run did not reach; reported, not gating",
}

CSS = """
:root{--ok:#2e7d32;--fail:#c62828;--warn:#ef6c00;--none:#757575;--ink:#1d2330;--mute:#5b6474;
--line:#dde2ea;--bg:#f6f8fb;--card:#fff;--accent:#2f5d9e}
*{box-sizing:border-box}
body{margin:0;font:14px/1.5 -apple-system,"Segoe UI",Roboto,"Helvetica Neue",Arial,sans-serif;color:var(--ink);background:var(--bg)}
header.top{background:#1f2a3c;color:#fff;padding:18px 28px 14px}
header.top h1{margin:0 0 4px;font-size:22px;font-weight:600}
header.top .meta{color:#c5cede;font-size:12.5px}
header.top .meta code{color:#fff;background:rgba(255,255,255,.1)}
nav.toc{position:sticky;top:0;z-index:5;background:#fff;border-bottom:1px solid var(--line);padding:6px 28px;font-size:13px}
nav.toc a{margin-right:14px;color:var(--accent);text-decoration:none;white-space:nowrap}
nav.toc a:hover{text-decoration:underline}
main{max-width:1320px;margin:0 auto;padding:8px 28px 60px}
section{background:var(--card);border:1px solid var(--line);border-radius:8px;padding:6px 22px 18px;margin:18px 0}
h2{font-size:19px;margin:16px 0 8px;padding-bottom:4px;border-bottom:2px solid var(--line)}
h3{font-size:15.5px;margin:18px 0 6px}
h4{font-size:14px;margin:12px 0 4px}
a{color:var(--accent)}
code,pre{font-family:"SFMono-Regular",Consolas,"Liberation Mono",monospace;font-size:12.5px;background:#f0f2f6;border-radius:3px;padding:0 3px}
pre{padding:8px;overflow:auto;white-space:pre-wrap}
.gate{border-radius:8px;padding:12px 18px;margin:18px 0;border:2px solid}
.gate.pass{background:#e8f5e9;border-color:var(--ok)}
.gate.fail{background:#fdecea;border-color:var(--fail)}
.gate.warn{background:#fff4e5;border-color:var(--warn)}
.gate h2{border:none;margin:0 0 4px;padding:0}
.gate ul{margin:4px 0 0 0;padding-left:20px}
.cards{display:flex;flex-wrap:wrap;gap:12px;margin:10px 0}
.card{flex:1 1 150px;border:1px solid var(--line);border-left:6px solid;border-radius:6px;padding:8px 12px;background:#fff}
.card .n{font-size:26px;font-weight:600;line-height:1.1}
.card .l{color:var(--mute);font-size:12.5px}
.card.st-ok{border-left-color:var(--ok)}.card.st-fail{border-left-color:var(--fail)}
.card.st-warn{border-left-color:var(--warn)}.card.st-none{border-left-color:var(--none)}
.card.info{border-left-color:var(--accent)}
table{border-collapse:collapse;margin:6px 0 10px;font-size:13px}
table.data{width:100%}
table.data th,table.data td{border-bottom:1px solid var(--line);padding:4px 8px;text-align:left;vertical-align:top}
table.data th{background:#eef1f6;position:sticky;top:31px;font-weight:600}
table.data td code,table.data td.tid{overflow-wrap:anywhere}
table.data td.src{min-width:200px}
table.data td.tid{min-width:300px}
.scroll{overflow-x:auto;max-width:100%}
.scroll table.data th{position:static}
table.data tbody tr:nth-child(even){background:#fafbfd}
table.data tbody tr:hover{background:#f1f6ff}
table.sortable th{cursor:pointer}
table.sortable th::after{content:" \\2195";color:#9aa3b2;font-size:11px}
table.data td.num,table.data th.num,td.num,th.num{text-align:right;font-variant-numeric:tabular-nums}
.badge{display:inline-block;padding:0 7px;border-radius:10px;font-size:12px;font-weight:600;color:#fff;white-space:nowrap}
.badge.st-ok{background:var(--ok)}.badge.st-fail{background:var(--fail)}
.badge.st-warn{background:var(--warn)}.badge.st-none{background:var(--none)}
.kind{display:inline-block;padding:0 6px;border-radius:4px;border:1px solid #c9ced8;font-size:12px;color:#333}
.bar{display:inline-block;width:90px;height:9px;background:#e7eaf0;border-radius:5px;vertical-align:middle;margin-right:6px;overflow:hidden}
.bar span{display:block;height:100%;background:var(--ok)}
.mute{color:var(--mute)}
.small{font-size:12.5px}
.item{border:1px solid var(--line);border-radius:7px;padding:4px 14px 8px;margin:12px 0;border-left:6px solid}
.item.st-ok{border-left-color:var(--ok)}.item.st-fail{border-left-color:var(--fail)}
.item.st-warn{border-left-color:var(--warn)}.item.st-none{border-left-color:var(--none)}
.item h4{font-size:15px;margin:8px 0 6px}
.item dl{display:grid;grid-template-columns:150px 1fr;gap:2px 12px;margin:4px 0}
.item dt{color:var(--mute)}
.item dd{margin:0}
.matrix{overflow:auto;max-width:100%}
.matrix table{font-size:12px}
.matrix th,.matrix td{border:1px solid var(--line);padding:2px 5px;text-align:center;min-width:22px}
.matrix thead th{writing-mode:vertical-rl;transform:rotate(180deg);white-space:nowrap;padding:5px 2px;background:#eef1f6}
.matrix tbody th{text-align:left;white-space:nowrap;background:#eef1f6}
.matrix td.x{background:#dbe7f7;font-weight:600}
.matrix td.both{background:#dbe7f7;font-weight:600}
.matrix td.seed{background:#fde2e1;color:var(--fail);font-weight:600}
.matrix td.data{background:#fff1d6;color:#a35a00;font-weight:600}
.matrix tr.empty th{color:var(--mute);font-style:italic}
.legend span{display:inline-block;margin-right:12px;font-size:12.5px}
.swatch{display:inline-block;width:14px;height:14px;border:2px solid #999;border-radius:3px;vertical-align:middle;margin-right:4px}
.graph{overflow:auto;border:1px solid var(--line);border-radius:6px;padding:6px;background:#fff;max-height:900px}
.graph svg{max-width:100%;height:auto}
.graph.tall{max-height:none}
.note{background:#fff8e1;border:1px solid #f3d98b;border-radius:6px;padding:6px 12px;margin:8px 0}
.ok-note{background:#e8f5e9;border:1px solid #a5d6a7;border-radius:6px;padding:6px 12px;margin:8px 0}
details summary{cursor:pointer;color:var(--accent)}
ul.compact{margin:4px 0;padding-left:20px}
.plots{display:flex;flex-wrap:wrap;gap:14px}
.plots figure{margin:0;border:1px solid var(--line);border-radius:6px;padding:6px;background:#fff}
.plots img{width:560px;max-width:100%}
.plots img.wide{width:1280px}
.orphan{color:var(--fail);font-weight:600}
.player-frame{width:100%;height:640px;border:1px solid var(--line);border-radius:6px;background:#fff}
table.data td img.thumb{width:210px;border:1px solid var(--line);border-radius:4px;display:block}
table.data td code.nowrap{white-space:nowrap}
"""

JS = """
document.querySelectorAll('table.sortable').forEach(function(t){
  t.querySelectorAll('th').forEach(function(th,i){
    th.addEventListener('click',function(){
      var tb=t.tBodies[0],rows=Array.prototype.slice.call(tb.rows),asc=th.dataset.asc!=='1';
      th.dataset.asc=asc?'1':'0';
      function key(r){var c=r.cells[i];if(!c)return '';var v=c.dataset.sort!==undefined?c.dataset.sort:c.textContent.trim();
        var n=parseFloat(v);return (v!==''&&!isNaN(n)&&/^[-+0-9.eE%]+$/.test(v))?n:v.toLowerCase();}
      rows.sort(function(a,b){var x=key(a),y=key(b);if(typeof x!==typeof y){x=String(x);y=String(y);}
        return (x<y?-1:x>y?1:0)*(asc?1:-1);});
      rows.forEach(function(r){tb.appendChild(r);});
    });
  });
});
var pick=document.getElementById('player-pick');
if(pick)pick.addEventListener('change',function(){document.getElementById('player-frame').src=pick.value;});
"""


def badge(status):
    return f'<span class="badge {STATUS_CLASS.get(status, "st-none")}" title="{E(STATUS_HELP.get(status, status))}">{E(status)}</span>'


def natural_sort_value(label):
    return "".join(f"{int(t):06d}" if t.isdigit() else t for t in re.split(r"(\d+)", str(label)))


class Html:
    def __init__(self, report):
        self.r = report
        self.items = {i["label"]: i for i in report["items"]}
        self.tests = {t["id"]: t for t in report["tests"]}
        self.test_anchor = {t["id"]: f"test-{n}" for n, t in enumerate(report["tests"], 1)}
        self.categories = {c["label"] for c in report.get("category_labels", [])}
        # The report's paths are relative to the source root; files beside it are found here.
        self.out_dir = report.get("_out_path") or report["inputs"]["out_dir"]
        self.parts = []

    # helpers
    def w(self, s):
        self.parts.append(s)

    def link(self, label):
        if label in self.categories:
            return f'<code class="mute" title="category label (traceability/config.yaml), not an SRS item">{E(label)}</code>'
        if label in self.items:
            it = self.items[label]
            return (f'<a href="#item-{E(label)}" title="{E((it.get("title") or "") + " [" + it["status"] + "]")}">'
                    f'{E(label)}</a>')
        return f'<span class="orphan" title="not an SRS item">{E(label)}</span>'

    def links(self, labels):
        return ", ".join(self.link(x) for x in labels) if labels else '<span class="mute">none</span>'

    def kind(self, k):
        return (f'<span class="kind" style="background:{KIND_HEX.get(k, "#fff")}" '
                f'title="{E(KIND_NAMES.get(k, k))}">{E(k)}</span>')

    def tlink(self, tid):
        return f'<a href="#{self.test_anchor[tid]}">{E(tid)}</a>' if tid in self.test_anchor else E(tid)

    def site(self, s):
        return f'<code>{E(s["file"])}:{s["line"]}</code>'

    # sections
    def header(self):
        r = self.r
        src = r["source"]
        commit = src.get("git_commit") or "unknown"
        dirty = " (working tree has uncommitted changes)" if src.get("git_dirty") else ""
        ran = "tests run by this invocation" if r["inputs"]["ran_tests"] else \
            "pre-recorded test results (tests not re-run)"
        self.w(f"""<header class="top"><h1>Tamias2D: SRS traceability and V&amp;V evidence</h1>
<div class="meta">Generated {E(r['generated'])} by <code>traceability/build_report.py</code> ·
commit <code>{E(commit[:12])}</code>{E(dirty)} · {E(ran)} · report schema {E(r['schema_version'])}</div></header>""")
        self.w("""<nav class="toc"><a href="#summary">Summary</a><a href="#items">Items</a>
<a href="#gaps">Gaps &amp; orphans</a><a href="#matrices">Matrices</a><a href="#graphs">Graphs</a>
<a href="#errata">Errata</a><a href="#vv">V&amp;V evidence</a><a href="#coverage">Coverage</a>
<a href="#tests">All tests</a><a href="#method">Method &amp; warnings</a>
<a href="#reviews">Link reviews</a><a href="#reqif">ReqIF</a>""")
        if os.path.exists(os.path.join(self.out_dir, "api", "index.html")):
            self.w('<a href="api/index.html">API reference</a>')
        if self._players():
            self.w('<a href="#players">Recorded runs</a>')
        self.w("</nav><main>")

    def gate(self):
        g = self.r["gate"]
        if g["passed"]:
            self.w(f"""<div class="gate pass" id="gate"><h2>Gate: PASS (exit status 0)</h2>
Every {E('/'.join(g['gated_kinds']))} item has a passing test and no test or check fails.</div>""")
        else:
            lis = "".join(f"<li>{self._linkify_tests(self._linkify(E(x)), g.get('failing_tests', []))}</li>"
                          for x in g["reasons"])
            self.w(f"""<div class="gate fail" id="gate"><h2>Gate: FAIL (exit status {g['exit_code']})</h2>
The harness exits non-zero when any {E('/'.join(g['gated_kinds']))} item lacks a passing test or
any test or check fails. This report is complete nonetheless; the reasons are:<ul>{lis}</ul></div>""")
        self._test_list_box("known-failures", "Known failures (documented findings)",
                            """These tests pass only because they declare their failing cases as expected (Boost
<code>expected_failures</code>); each failing case is a finding described in
docs/verification.md, printed with its seed so it can be replayed:""", g.get("known_failures"))
        self.goals()
        self.w(render_audit.html_gate_box(self))
        self._test_list_box("targets-missed", "Targets not met (goals beyond the SRS)",
                            """These verification checks state project goals beyond the SRS (the project's speed
floors); this run did not reach them. They do not gate the exit status, and the SRS items they
are labelled with are judged by their other checks:""", g.get("targets_missed"))

    def goals(self):
        """The SRS's own goals ("should" requirements): each with its figures, met or missed."""
        goals = self.r["gate"].get("goals") or []
        if not goals:
            return
        tests = {t["id"]: t for t in self.r["tests"]}
        rows = []
        for g in goals:
            checks = [tests[c] for c in g["checks"] if c in tests]
            figs = "".join(
                f'<li>{badge(t["status"])} {self.tlink(t["id"])}'
                f'{": <b>" + E(t["figure"]) + "</b>" if t.get("figure") else ""}</li>'
                for t in checks) or "<li>no measurement in this run</li>"
            rows.append(f'<li>{self.link(g["label"])} {badge(g["status"])}<ul>{figs}</ul></li>')
        missed = any(g["status"] == "goal missed" for g in goals)
        cls = "warn" if missed else "pass"
        self.w(f"""<div class="gate {cls}" id="goals"><h2>Goals of the SRS ("should" requirements)</h2>
The SRS states these with "should": goals, measured and shown with their figures in every run,
never a reason for a non-zero exit status ("shall" requirements gate). Each check's details
say how the figure is measured:<ul>{"".join(rows)}</ul></div>""")

    def _test_list_box(self, anchor, title, intro, ids):
        """A box under the gate listing tests (linked) with a heading and an explanation: an
        outcome shown but not gating, so in the warning colour."""
        if not ids:
            return
        lis = "".join(f"<li>{self._linkify_tests(E(x), ids)}</li>" for x in ids)
        self.w(f"""<div class="gate warn" id="{anchor}"><h2>{E(title)}</h2>
{intro}<ul>{lis}</ul></div>""")

    def _linkify_tests(self, text, ids):
        for tid in ids:
            text = text.replace(E(tid), self.tlink(tid), 1)
        return text

    def _linkify(self, text):
        # Turn bare SRS labels in a reason line (already HTML-escaped) into links.
        if not self.items:
            return text
        labels = sorted(self.items, key=len, reverse=True)
        pat = re.compile(r"(?<![\w:/.@-])(" + "|".join(re.escape(x) for x in labels) + r")(?![\w@])")
        return pat.sub(lambda m: f'<a href="#item-{E(m.group(1))}">{E(m.group(1))}</a>', text)

    def summary(self):
        r = self.r
        s = r["summary"]
        self.w('<section id="summary"><h2>1. Summary</h2>')
        n_items = len(r["items"])
        self.w('<div class="cards">')
        self.w(f'<div class="card info"><div class="n">{n_items}</div><div class="l">SRS items in srs/</div></div>')
        for st in ("verified", "goal met", "failing", "goal missed", "model only", "untested",
                   "assumed", "not testable", "not implemented"):
            self.w(f'<div class="card {STATUS_CLASS[st]}"><div class="n">{s["by_status"].get(st, 0)}</div>'
                   f'<div class="l">{E(st)}</div></div>')
        self.w('</div>')
        self.w('<p class="small mute">' + " · ".join(f"<b>{E(k)}</b>: {E(v)}" for k, v in STATUS_HELP.items()) +
               '. An item\'s status comes only from tests and checks labelled with it; it is never '
               'inferred from the items it uses.</p>')
        self.w('<h3>Coverage of the SRS per kind</h3><table class="data sortable"><thead><tr>'
               '<th>Kind</th><th>Name</th><th class="num">Items</th><th class="num">Verified</th>'
               '<th class="num">Goal met</th><th class="num">Failing</th><th class="num">Goal missed</th><th class="num">Model only</th><th class="num">Untested</th><th class="num">Assumed</th>'
               '<th class="num">Not testable</th><th class="num">Not impl.</th>'
               '<th class="num">With code tag</th><th class="num">With tests</th><th>Verified share</th>'
               '<th>Gate</th></tr></thead><tbody>')
        for row in s["by_kind"]:
            pct = row["verified_percent"]
            gated = "yes" if row["kind"] in r["gate"]["gated_kinds"] else '<span class="mute">no</span>'
            self.w(f'<tr><td data-sort="{E(row["kind"])}">{self.kind(row["kind"])}</td><td>{E(row["name"])}</td>'
                   f'<td class="num">{row["total"]}</td><td class="num">{row["verified"]}</td>'
                   f'<td class="num">{row["goal met"]}</td><td class="num">{row["failing"]}</td>'
                   f'<td class="num">{row["goal missed"]}</td><td class="num">{row["model only"]}</td>'
                   f'<td class="num">{row["untested"]}</td>'
                   f'<td class="num">{row["assumed"]}</td><td class="num">{row["not testable"]}</td>'
                   f'<td class="num">{row["not implemented"]}</td><td class="num">{row["with_code"]}</td>'
                   f'<td class="num">{row["with_tests"]}</td>'
                   f'<td data-sort="{pct}"><span class="bar"><span style="width:{pct}%"></span></span>{pct}%</td>'
                   f'<td>{gated}</td></tr>')
        self.w('</tbody></table>')
        self.w('<h3>Tests and checks</h3><table class="data"><thead><tr><th>Origin</th>'
               '<th class="num">Total</th><th class="num">Passed</th><th class="num">Failed</th>'
               '<th class="num">Error</th><th class="num">Skipped</th><th class="num">Not run</th>'
               '<th class="num">Known failure</th><th class="num">Target missed</th>'
               '<th class="num">Goal missed</th></tr></thead><tbody>')
        names = {"boost": "Boost.Test cases (per test case, from JUnit)",
                 "ctest": "Other CTest entries (compile-fail, checker, CLI, examples)",
                 "verification": "Verification-program checks (reports/data/*.json)"}
        for origin in ("boost", "ctest", "verification"):
            t = s["tests"].get(origin, {})
            self.w(f'<tr><td>{E(names[origin])}</td><td class="num">{t.get("total", 0)}</td>'
                   f'<td class="num">{t.get("passed", 0)}</td><td class="num">{t.get("failed", 0)}</td>'
                   f'<td class="num">{t.get("error", 0)}</td><td class="num">{t.get("skipped", 0)}</td>'
                   f'<td class="num">{t.get("notrun", 0)}</td><td class="num">{t.get("known-failure", 0)}</td>'
                   f'<td class="num">{t.get("target-missed", 0)}</td>'
                   f'<td class="num">{t.get("goal-missed", 0)}</td></tr>')
        self.w('</tbody></table>')
        c = s["counts"]
        self.w('<ul class="compact">'
               f'<li><a href="#gaps">Items without a code tag</a>: {len(r["gaps"]["no_code"])}; '
               f'without any labelled test: {len(r["gaps"]["no_test"])}</li>'
               f'<li><a href="#orphan-tags">Orphan code tags</a> (name no SRS item): {c["orphan_code_tags"]}; '
               f'<a href="#orphan-labels">orphan test labels</a>: {c["orphan_test_labels"]}</li>'
               f'<li><a href="#errata">SRS errata</a> recorded in srs/errata.yaml: {c["errata"]}; '
               f'<a href="#refby">Ref.By disagreements</a> between the seed and the data: {c["refby_disagreements"]}</li>'
               f'<li><a href="#missing-oracle">Tests without an oracle statement</a>: {len(r["missing_oracle"])} '
               f'({len(r.get("missing_oracle_srs", []))} of them SRS-labelled: weak evidence for their items); '
               f'<a href="#gaps">items whose only evidence is weak</a> (no strong passing link): '
               f'{len(r["gaps"]["weak_evidence"])}; <a href="#links">trace links</a>: '
               f'{(r.get("link_summary") or {}).get("strong", 0)} strong, '
               f'{(r.get("link_summary") or {}).get("weak", 0)} weak, '
               f'<a href="#reviews">{(r.get("reviews") or {}).get("suspect", 0)} suspect</a></li>'
               f'<li><a href="#warnings">Harness warnings</a>: {c["warnings"]}</li></ul>')
        self.w('</section>')

    def items_section(self):
        r = self.r
        self.w('<section id="items"><h2>2. SRS items</h2>')
        self.w('<p class="small">One row per item of srs/*.yaml; click a label for its evidence. Columns sort on click.</p>')
        self.w('<table class="data sortable"><thead><tr><th>Label</th><th>Kind</th><th>Drasil alias</th>'
               '<th>Title</th><th>Status</th><th class="num">Code sites</th><th class="num">Tests pass</th>'
               '<th class="num">fail</th><th class="num">other</th><th>Oracle kinds</th><th>Errata</th>'
               '</tr></thead><tbody>')
        for it in r["items"]:
            self.w(f'<tr><td data-sort="{E(natural_sort_value(it["label"]))}"><a href="#item-{E(it["label"])}">{E(it["label"])}</a></td>'
                   f'<td>{self.kind(it["kind"])}</td><td>{E(it.get("alias") or "")}</td>'
                   f'<td>{E(it.get("title") or "")}</td><td data-sort="{E(it["status"])}">{badge(it["status"])}</td>'
                   f'<td class="num">{len(it["code_sites"])}</td><td class="num">{it["tests_passed"]}</td>'
                   f'<td class="num">{it["tests_failing"]}</td><td class="num">{it["tests_other"]}</td>'
                   f'<td>{self._oracle_kinds(it)}</td>'
                   f'<td>{self._errata_links(it["errata"])}</td></tr>')
        self.w('</tbody></table>')
        current = None
        for it in r["items"]:
            if it["kind"] != current:
                current = it["kind"]
                self.w(f'<h3 id="kind-{E(current)}">{self.kind(current)} {E(KIND_NAMES.get(current, current))}</h3>')
            self.item_card(it)
        self.w('</section>')

    def _oracle_kinds(self, it):
        kinds = E(", ".join(it.get("oracle_kinds") or []))
        if it.get("weak_evidence"):
            return f'<span class="orphan" title="every passing test rests on these only">{kinds} (weak)</span>'
        if it.get("tests_without_oracle"):
            n = len(it["tests_without_oracle"])
            return (f'{kinds} <span class="orphan" title="labelled tests that state no oracle">'
                    f'(weak: {n} without oracle)</span>')
        return kinds

    def _errata_links(self, ids):
        return ", ".join(f'<a href="#erratum-{E(e)}">{E(e)}</a>' for e in ids)

    def _reason(self, it):
        if not it.get("status_reason"):
            return ""
        return f' <span class="small mute">{E(it["status"])}: {E(it["status_reason"])}</span>'

    def item_card(self, it):
        cls = STATUS_CLASS[it["status"]]
        alias = f' · Drasil: <code>{E(it["alias"])}</code>' if it.get("alias") else ""
        self.w(f'<div class="item {cls}" id="item-{E(it["label"])}"><h4>{E(it["label"])} · {E(it.get("title") or "")} '
               f'{badge(it["status"])}{self._reason(it)}</h4><div class="small mute">{E(KIND_NAMES.get(it["kind"], it["kind"]))}{alias}'
               f' · {E(it.get("file") or "")}</div><dl>')
        src = it.get("source") or {}
        if src:
            self.w(f'<dt>Seed source</dt><dd>{E(str(src.get("seed", "")))} §{E(str(src.get("section", "")))}</dd>')
        if it.get("equation"):
            self.w(f'<dt>Equation</dt><dd><code>{E(str(it["equation"]))}</code></dd>')
        if it.get("seed_equation"):
            self.w(f'<dt>Seed equation</dt><dd><code>{E(str(it["seed_equation"]))}</code></dd>')
        if it.get("oracle_kinds"):
            self.w(f'<dt>Oracle kinds of the passing evidence</dt><dd>{self._oracle_kinds(it)}</dd>')
        self.w(f'<dt>Uses</dt><dd>{self.links(it["uses"])}</dd>')
        self.w(f'<dt>Ref. by (computed)</dt><dd>{self.links(it["ref_by"])}</dd>')
        if it.get("seed_ref_by") is not None:
            diff = set(it["seed_ref_by"]) != set(it["ref_by"])
            mark = ' <a href="#refby" class="orphan">differs</a>' if diff else ""
            self.w(f'<dt>Ref. by (seed)</dt><dd>{self.links(it["seed_ref_by"])}{mark}</dd>')
        if it["errata"]:
            self.w(f'<dt>Errata</dt><dd>{self._errata_links(it["errata"])}</dd>')
        notes = list(it["notes"])
        if it.get("srs_notes"):
            sn = it["srs_notes"]
            notes.append("SRS note: " + (" ".join(map(str, sn)) if isinstance(sn, list) else str(sn)))
        if notes:
            self.w('<dt>Notes</dt><dd>' + "<br>".join(E(n) for n in notes) + '</dd>')
        if it["code_sites"]:
            lis = "".join(f'<li>{self.site(s)} <span class="mute">[{E(s["area"])}]</span> {E(s["text"])}</li>'
                          for s in it["code_sites"])
            self.w(f'<dt>Code sites</dt><dd><ul class="compact">{lis}</ul></dd>')
        else:
            self.w('<dt>Code sites</dt><dd><span class="mute">none: no <code>\\srs{' + E(it["label"]) +
                   '}</code> tag in src/, apps/ or verification/</span></dd>')
        self.w('</dl>')
        if it["tests"]:
            self.w('<table class="data"><thead><tr><th>Test / check</th><th>Status</th><th>Link</th>'
                   '<th>Oracle kind</th><th>Oracle</th></tr></thead><tbody>')
            for tid in it["tests"]:
                t = self.tests[tid]
                oracle = E(t["oracle"]) if t.get("oracle") else '<span class="mute">no oracle stated</span>'
                extra = f'<div class="small mute">{E(t["samples"])}</div>' if t.get("samples") else ""
                self.w(f'<tr><td>{self.tlink(tid)}{extra}</td><td>{badge(t["status"])}</td>'
                       f'<td class="small">{self._link_grade((it.get("links") or {}).get(tid))}</td>'
                       f'<td class="small">{E(", ".join(t.get("oracle_kinds") or []))}</td><td>{oracle}</td></tr>')
            self.w('</tbody></table>')
        else:
            self.w('<p class="small mute">No test or verification check carries this label.</p>')
        self.w('</div>')

    def _link_grade(self, g):
        if not g:
            return ""
        cls = "st-ok" if g["grade"] == "strong" else "st-warn"
        why = "; ".join(g.get("reasons") or [])
        return (f'<span class="badge {cls}" title="{E(why)}">{E(g["grade"])}</span>'
                f'{render_audit.review_badge(g.get("review"), g.get("changed"))} '
                f'<span class="mute">{E(g["level"])}</span>' + (f'<br>{E(why)}' if why else ""))

    def link_review(self):
        """Every link's grade, counted, and a seeded sample of links with their facts."""
        r = self.r
        s = r.get("link_summary") or {}
        smp = r.get("link_sample") or {}
        self.w(f'<h3 id="links">Trace links graded ({s.get("total", 0)}: {s.get("strong", 0)} strong, '
               f'{s.get("weak", 0)} weak)</h3>')
        self.w('<p class="small">Each (item, test) link is graded from facts the harness has '
               '(<code>traceability/links.py</code>): <b>strong</b> when the test states an oracle '
               'independent of the code (closed form, stated rule, GSL reference, conservation law, '
               'property; a peer only where the item is itself a comparison with it) and drives '
               'the item\'s implementation at a level that can show it right (a requirement on the '
               'software: the world, the command or a program, not a model function alone); '
               '<b>weak</b> otherwise, with the reasons. An item whose passing links are all weak is '
               'listed under "Verified only by weak evidence".</p>')
        rows = smp.get("links") or []
        if rows:
            self.w(f'<h4 id="link-sample">A sample for review: {len(rows)} links drawn with seed '
                   f'<code>{E(str(smp.get("seed")))}</code></h4><p class="small">Drawn afresh for '
                   'every commit (the seed is its first digits), the same in every report of it. A '
                   'reviewer judges each link against its test\'s code and the item\'s text; the '
                   'grade is the harness\'s.</p>')
            self.w('<table class="data small"><thead><tr><th>Item</th><th>Test / check</th>'
                   '<th>Grade</th><th>Oracle kinds</th><th>Tolerance stated</th><th>Oracle</th>'
                   '</tr></thead><tbody>')
            for g in rows:
                t = self.tests.get(g["test"], {})
                self.w(f'<tr><td>{self.link(g["item"])}</td><td>{self.tlink(g["test"])}</td>'
                       f'<td>{self._link_grade(g)}</td><td>{E(", ".join(g["oracle_kinds"]))}</td>'
                       f'<td>{"yes" if g["tolerance_stated"] else "no"}</td>'
                       f'<td>{E(str(t.get("oracle") or ""))}</td></tr>')
            self.w('</tbody></table>')

    def gaps(self):
        r = self.r
        g, o = r["gaps"], r["orphans"]
        self.w('<section id="gaps"><h2>3. Gaps and orphans (both directions)</h2>')
        self.w('<h3>SRS → evidence</h3><table class="data"><thead><tr><th>Gap</th><th class="num">Count</th>'
               '<th>Items</th></tr></thead><tbody>')
        for key, title in (("no_code", "No code tag"), ("no_test", "No labelled test or check"),
                           ("no_passing_test", "No passing test or check"),
                           ("weak_evidence", "Verified only by weak evidence (no passing link "
                                             "is strong)"),
                           ("unstated_oracle", "Weak evidence: a labelled test states no oracle")):
            self.w(f'<tr><td>{E(title)}</td><td class="num">{len(g.get(key, []))}</td><td>{self.links(g.get(key, []))}</td></tr>')
        self.w('</tbody></table>')
        self.link_review()
        self.w(render_audit.html_reviews(self))
        self.w('<h3 id="orphan-tags">Evidence → SRS: orphan code tags</h3>')
        if o["code_tags"]:
            self.w('<table class="data sortable"><thead><tr><th>Tag</th><th>Site</th><th>Text</th><th>Hint</th></tr></thead><tbody>')
            for s in o["code_tags"]:
                hint = f'alias of {self.link(s["alias_of"])}: tag the label instead' if s.get("alias_of") else ""
                self.w(f'<tr><td class="orphan">\\srs{{{E(s["label"])}}}</td><td>{self.site(s)}</td>'
                       f'<td>{E(s["text"])}</td><td>{hint}</td></tr>')
            self.w('</tbody></table>')
        else:
            self.w('<p class="ok-note">Every <code>\\srs{}</code> tag names an SRS item.</p>')
        self.w('<h3 id="orphan-labels">Evidence → SRS: orphan test labels</h3>')
        if o["test_labels"]:
            self.w('<table class="data sortable"><thead><tr><th>Label</th><th>Tests / checks carrying it</th><th>Hint</th></tr></thead><tbody>')
            for x in o["test_labels"]:
                hint = f'alias of {self.link(x["alias_of"])}' if x.get("alias_of") else ""
                self.w(f'<tr><td class="orphan">{E(x["label"])}</td><td>{", ".join(self.tlink(t) for t in x["tests"])}</td><td>{hint}</td></tr>')
            self.w('</tbody></table>')
        else:
            self.w('<p class="ok-note">Every test label names an SRS item or a declared category label.</p>')
        if r["category_labels"]:
            cats = ", ".join(f'<code>{E(c["label"])}</code> ({len(c["tests"])})' for c in r["category_labels"])
            self.w(f'<p class="small">Category labels (not SRS items; declared in <code>traceability/config.yaml</code>): {cats}.</p>')
        if o["unlabelled_tests"]:
            self.w(f'<h4>Tests and checks with no SRS label ({len(o["unlabelled_tests"])})</h4><p class="small">'
                   + ", ".join(self.tlink(t) for t in o["unlabelled_tests"]) + '</p>')
        self.w(f'<h3 id="missing-oracle">Tests without an oracle statement ({len(r["missing_oracle"])})</h3>')
        if r["missing_oracle"]:
            self.w('<p class="small">Boost.Test cases need a <code>// Oracle: ...</code> line in the comment block '
                   'directly above the test-case macro; other CTest entries a <code># Oracle: ...</code> line above '
                   'their <code>add_test()</code> or the helper call that registers them; checks an <code>oracle</code> field.</p>' +
                   (f'<p class="small"><strong>SRS-labelled ({len(r.get("missing_oracle_srs", []))})</strong>, '
                    'weak evidence for their items: ' +
                    (", ".join(self.tlink(t) for t in r.get("missing_oracle_srs", [])) or "none") +
                    '</p>') +
                   '<p class="small">All: ' +
                   ", ".join(self.tlink(t) for t in r["missing_oracle"]) + '</p>')
        else:
            self.w('<p class="ok-note">Every test states its oracle.</p>')
        if r["registration"]:
            self.w('<h3>CTest registration mismatches</h3><ul class="compact">' +
                   "".join(f"<li>{E(x)}</li>" for x in r["registration"]) + '</ul>')
        self.w('</section>')

    def matrix_table(self, rows, cols, cellfn, empty_rows=()):
        out = ['<div class="matrix"><table><thead><tr><th></th>']
        out += [f'<th>{self.link(c) if c in self.items else E(c)}</th>' for c in cols]
        out.append('</tr></thead><tbody>')
        for r in rows:
            cls = ' class="empty"' if r in empty_rows else ""
            out.append(f'<tr{cls}><th>{self.link(r) if r in self.items else E(r)}</th>')
            for c in cols:
                v = cellfn(r, c)
                if v:
                    klass, txt, tip = v
                    out.append(f'<td class="{klass}" title="{E(tip)}">{txt}</td>')
                else:
                    out.append('<td></td>')
            out.append('</tr>')
        out.append('</tbody></table></div>')
        self.w("".join(out))

    def matrices(self):
        r = self.r
        self.w('<section id="matrices"><h2>4. Traceability matrices (SRS §9, Tables 3–5)</h2>')
        self.w('<p class="small">Regenerated from the <code>uses</code> lists in srs/: a mark in row <i>r</i>, column '
               '<i>c</i> means <i>r</i> uses <i>c</i>, so a change to <i>c</i> calls for a review of <i>r</i>. '
               'Rows and columns with no mark are kept (italic row headers) because an unused item is itself a finding.</p>')
        seed = {t["id"]: t for t in r["seed_tables"]}
        for m in r["matrices"]:
            self.w(f'<h3 id="{E(m["id"])}">Table {m["number"]} (regenerated): {E(m["caption"])}</h3>')
            if not m["row_labels"] or not m["col_labels"]:
                self.w('<p class="note">No items of these kinds in srs/ yet.</p>')
            else:
                cells = {r_: set(v) for r_, v in m["cells"].items()}
                self.matrix_table(m["row_labels"], m["col_labels"],
                                  lambda a, b: ("x", "X", f"{a} uses {b}") if b in cells.get(a, ()) else None,
                                  m["empty_rows"])
                if m["empty_cols"]:
                    self.w(f'<p class="small mute">Columns used by no row: {self.links(m["empty_cols"])}</p>')
            st = seed.get(m["id"])
            if not st:
                continue
            if st["missing"]:
                self.w('<div class="note"><b>Seed Table %d is missing from the seed text.</b> ' % m["number"] +
                       " ".join(E(n) for n in st["notes"]) + '</div>')
                continue
            self.w(f'<h4>Seed Table {m["number"]} as printed (transcribed in <code>traceability/seed_tables.yaml</code>, '
                   f'seed lines {E("–".join(map(str, st.get("seed_lines") or [])))})</h4>')
            srows = [x["label"] for x in st["seed_rows"]]
            smarks = [set(x.get("marks") or []) for x in st["seed_rows"]]
            out = ['<div class="matrix"><table><thead><tr><th></th>'] + \
                  [f'<th>{E(c)}</th>' for c in st["seed_columns"]] + ['</tr></thead><tbody>']
            for lab, marks, row in zip(srows, smarks, st["seed_rows"]):
                name = E(row.get("printed_as") or lab)
                out.append(f'<tr><th>{name}</th>' + "".join(
                    '<td class="x">X</td>' if c in marks else '<td></td>' for c in st["seed_columns"]) + '</tr>')
            out.append('</tbody></table></div>')
            self.w("".join(out))
            cmp_ = st.get("comparison")
            if cmp_:
                self.w(f'<h4>Seed vs regenerated Table {m["number"]}</h4><p class="legend small">'
                       '<span><span class="swatch" style="background:#dbe7f7"></span>in both</span>'
                       '<span><span class="swatch" style="background:#fde2e1"></span>S: only in the seed</span>'
                       '<span><span class="swatch" style="background:#fff1d6"></span>D: only in srs/ data</span></p>')
                cc = cmp_["cells"]
                self.matrix_table(cmp_["rows"], cmp_["cols"],
                                  lambda a, b: {"both": ("both", "X", "in both"),
                                                "seed": ("seed", "S", "only in the seed"),
                                                "data": ("data", "D", "only in srs/ data")}.get(cc.get(f"{a}|{b}")))
            if st["differences"]:
                self.w(f'<details open><summary>{len(st["differences"])} difference(s)</summary>'
                       '<table class="data sortable"><thead><tr><th>Row</th><th>Column</th><th>Type</th><th>Detail</th></tr></thead><tbody>')
                for d in st["differences"]:
                    self.w(f'<tr><td>{self.link(d["row"]) if d["row"] in self.items else E(d["row"])}</td>'
                           f'<td>{self.link(d["column"]) if d["column"] in self.items else E(d["column"] or "")}</td>'
                           f'<td>{E(d["type"])}</td><td>{E(d["detail"])}</td></tr>')
                self.w('</tbody></table></details>')
            if st["notes"]:
                self.w('<ul class="compact small">' + "".join(f"<li>{E(n)}</li>" for n in st["notes"]) + '</ul>')
        self.w('</section>')

    def graphs(self):
        r = self.r
        self.w('<section id="graphs"><h2>5. Traceability graphs</h2>')
        kinds = [row["kind"] for row in r["summary"]["by_kind"]]
        self.w('<p class="legend small">Fill: kind (Drasil\'s colours) · ' + "".join(
            f'<span><span class="swatch" style="background:{KIND_HEX.get(k, "#fff")}"></span>{E(k)}</span>' for k in kinds) +
            '<br>Border: status · ' + "".join(
            f'<span><span class="swatch" style="border-color:{c}"></span>{E(s)}</span>' for s, c in STATUS_BORDER.items()) +
            '<br>An arrow goes from the used item to the item that uses it (if the tail changes, revisit the head). '
            'Nodes link to the item\'s evidence.</p>')
        for g in r["graphs"]:
            self.w(f'<h3 id="{E(g["id"])}">{E(g["title"])}</h3><p class="small mute">{g["nodes"]} nodes, {g["edges"]} edges · '
                   f'<a href="{E(g["dot"])}">DOT</a>' + (f' · <a href="{E(g["svg"])}">SVG</a>' if g.get("svg") else "") + '</p>')
            if g.get("inline"):
                wide = " tall" if g["id"] == "graph_all" else ""
                self.w(f'<div class="graph{wide}">{g["inline"]}</div>')
            else:
                self.w('<p class="note">No SVG (Graphviz unavailable or no linked items).</p>')
            if g.get("isolated"):
                self.w(f'<p class="small">Not drawn: items of this view with no edge in it ({len(g["isolated"])}): '
                       f'{self.links(g["isolated"])}</p>')
        self.w('</section>')

    def errata(self):
        r = self.r
        self.w('<section id="errata"><h2>6. SRS errata</h2>')
        if r["errata"]:
            self.w('<p class="small">From <code>srs/errata.yaml</code>: defects found in the seed text. The project '
                   'implements the correct reading and records the seed text.</p>')
            self.w('<table class="data sortable"><thead><tr><th>Id</th><th>Items</th><th>Kind</th><th>Seed text</th>'
                   '<th>Problem</th><th>Correct reading</th><th>Compile-fail test</th></tr></thead><tbody>')
            for e in r["errata"]:
                cf = e.get("compile_fail")
                cf_s = E(str(cf)) if cf not in (None, False, "") else '<span class="mute">—</span>'
                self.w(f'<tr id="erratum-{E(e["id"])}"><td data-sort="{E(natural_sort_value(e["id"]))}"><b>{E(e["id"])}</b></td>'
                       f'<td>{self.links(e.get("items", []))}</td>'
                       f'<td>{E(str(e.get("kind") or ""))}</td><td class="small">{E(str(e.get("seed_text") or ""))}</td>'
                       f'<td class="small">{E(str(e.get("problem") or ""))}</td>'
                       f'<td class="small">{E(str(e.get("correct_reading") or ""))}</td><td class="small">{cf_s}</td></tr>')
            self.w('</tbody></table>')
        else:
            self.w('<p class="note">No errata loaded (srs/errata.yaml missing or empty).</p>')
        d = r["refby_disagreements"]
        self.w(f'<h3 id="refby">Ref. By disagreements: seed text vs computed from <code>uses</code> ({len(d)})</h3>')
        if d:
            self.w('<table class="data sortable"><thead><tr><th>Item</th><th>Seed Ref. By</th><th>Computed Ref. By</th>'
                   '<th>Only in seed</th><th>Only computed</th></tr></thead><tbody>')
            for x in d:
                self.w(f'<tr><td data-sort="{E(natural_sort_value(x["label"]))}">{self.link(x["label"])}</td><td>{self.links(x["seed_ref_by"])}</td>'
                       f'<td>{self.links(x["computed_ref_by"])}</td><td>{self.links(x["only_in_seed"])}</td>'
                       f'<td>{self.links(x["only_in_data"])}</td></tr>')
            self.w('</tbody></table>')
        else:
            self.w('<p class="ok-note">No disagreements (or no <code>seed_ref_by</code> data).</p>')
        ch = r["checker"]
        self.w(f'<p class="small">Cross-check with <code>srs/check_srs.py --json</code>: {E(ch["message"])}')
        if ch.get("disagreements") is not None:
            n = len(ch["disagreements"]) if hasattr(ch["disagreements"], "__len__") else "?"
            ag = ch.get("agreement")
            verdict = ""
            if ag:
                verdict = (f' <span class="badge st-ok">agrees</span> {E(ag["summary"])}' if ag["agrees"] else
                           f' <span class="badge st-fail">differs</span> {E(ag["summary"])}')
            self.w(f' — it reports {n} disagreement(s).{verdict}</p><details><summary>checker output</summary><pre>'
                   f'{E(_short_json(ch["disagreements"]))}</pre></details>')
        else:
            self.w('</p>')
        self.w('</section>')

    def vv(self):
        r = self.r
        self.w('<section id="vv"><h2>7. Verification and validation evidence</h2>')
        progs = r["verification"]
        prov = r.get("provenance") or {}
        b = prov.get("build") or {}
        self.w('<p class="small">Results are accepted only from the checkout\'s commit '
               f'(<code>{E(str(prov.get("source_commit") or "unknown")[:12])}</code>) and, for built '
               f'programs, the build directory\'s build id (<code>{E(str(b.get("build_id") or "unknown"))}</code>); '
               f'expected programs: {E(", ".join(prov.get("expected_programs") or []) or "none")}'
               + (f'; <b>missing: {E(", ".join(prov["missing_programs"]))}</b>' if prov.get("missing_programs") else "")
               + (f'; <b>refused: {E(", ".join(x["program"] for x in prov["refused"]))}</b>' if prov.get("refused") else "")
               + (f'; not run: {E("; ".join(x["program"] + " (" + x["how"] + ")" for x in prov["not_run_programs"]))}'
                  if prov.get("not_run_programs") else "")
               + '.</p>')
        if not progs:
            self.w('<p class="note">No verification results in <code>reports/data/*.json</code>.</p>')
        else:
            self.w('<ul class="compact">' + "".join(
                f'<li><a href="#vv-{n}">{E(p["program"])}</a> — {sum(c["status"] == "passed" for c in p["checks"])}/'
                f'{len(p["checks"])} checks pass</li>' for n, p in enumerate(progs, 1)) + '</ul>')
        for n, p in enumerate(progs, 1):
            self.w(f'<h3 id="vv-{n}">{E(p["program"])}</h3><p>{E(p.get("description") or "")} '
                   f'<span class="small mute">(data/{E(p["file"])})</span></p>')
            if p["invalid"]:
                self.w('<p class="note">Schema problems: ' + E("; ".join(p["invalid"])) + '</p>')
            if p.get("refused"):
                self.w('<p class="note">Refused as evidence: ' + E(p["refused"]) + '</p>')
            pv = p.get("provenance") or {}
            if pv:
                self.w(f'<p class="small mute">Commit {E(str(pv.get("commit"))[:12])}'
                       f'{" (dirty)" if pv.get("dirty") else ""}, build {E(str(pv.get("build_id")))}, '
                       f'run {E(str(pv.get("generated")))}</p>')
            if p["checks"]:
                self.w('<table class="data sortable"><thead><tr><th>Check</th><th>Labels</th><th>Status</th>'
                       '<th>Oracle</th><th>Details</th></tr></thead><tbody>')
                for c in p["checks"]:
                    tid = f'{p["program"]}:{c.get("name")}'
                    anchor = self.test_anchor.get(tid, "")
                    self.w(f'<tr id="{anchor}"><td>{E(str(c.get("name")))}</td><td>{self.links(c.get("labels") or [])}</td>'
                           f'<td>{badge(c["status"])}</td><td class="small">{E(str(c.get("oracle") or ""))}</td>'
                           f'<td class="small">{E(str(c.get("details") or ""))}</td></tr>')
                self.w('</tbody></table>')
            for t in p["tables"]:
                self.w(f'<h4>{E(str(t.get("name", "")))}</h4><div class="scroll"><table class="data sortable"><thead><tr>' +
                       "".join(f'<th>{E(str(c))}</th>' for c in t.get("columns", [])) + '</tr></thead><tbody>')
                for row in t.get("rows", []):
                    cells = row if isinstance(row, list) else [row]
                    self.w('<tr>' + "".join(
                        f'<td class="num">{E(_fmt(v))}</td>' if isinstance(v, (int, float)) and not isinstance(v, bool)
                        else f'<td>{E(_fmt(v))}</td>' for v in cells) + '</tr>')
                self.w('</tbody></table></div>')
            figs = [s for s in p["series"] if s.get("svg")]
            if figs:
                self.w('<div class="plots">' + "".join(
                    f'<figure><img src="{E(s["svg"])}" alt="{E(str(s.get("name")))}"><figcaption class="small">'
                    f'{E(str(s.get("name")))}</figcaption></figure>' for s in figs) + '</div>')
            if p["program"] == "benchmark":
                self.bench_records()
            if p["program"] == "mutation":
                self.mutation_reference()
            if p["program"] == "module_reach":
                self.module_reach_reference()
        if not any(p["program"] == "benchmark" for p in progs):
            self.bench_records()
        if not any(p["program"] == "mutation" for p in progs):
            self.mutation_reference()
        if not any(p["program"] == "module_reach" for p in progs):
            self.module_reach_reference()
        self.players()
        self.w('</section>')

    def module_reach_reference(self):
        """Every module's perturbations on a named commit (traceability/module_reach_reference.py)."""
        ref = self.r.get("module_reach_reference")
        self.w('<h3 id="module-reach-reference">Module reach: the reference run</h3>')
        if not ref:
            self.w(f'<p class="note">No reference run is kept (<code>{E(module_reach_reference.REFERENCE)}</code>).</p>')
            return
        self.w(f'<p>{E(module_reach_reference.summary(ref))} <span class="small mute">({E(ref["file"])})</span></p>')
        self.w('<div class="scroll"><table class="data sortable"><thead><tr><th>Item</th><th>Module</th>'
               '<th>srs/ expects</th><th>Perturbations</th><th>Result</th></tr></thead><tbody>')
        for s in ref["items"]:
            self.w(f'<tr><td>{self.links([s["label"]])}</td><td>{E(", ".join(s["modules"]))}</td>'
                   f'<td>{E(s["expected"])}</td><td class="num">{s["perturbations"]}</td>'
                   f'<td>{E(", ".join(s["results"]))}{"" if s["as_expected"] else " (not as srs/ states)"}</td></tr>')
        self.w('</tbody></table></div>')

    def mutation_reference(self):
        """The whole mutation analysis of a named commit (traceability/mutation_reference.py)."""
        ref = self.r.get("mutation_reference")
        self.w('<h3 id="mutation-reference">Mutation: the reference analysis</h3>')
        if not ref:
            self.w(f'<p class="note">No reference analysis is kept (<code>{E(mutation_reference.REFERENCE)}</code>).</p>')
            return
        self.w(f'<p>{E(mutation_reference.summary(ref))} <span class="small mute">({E(ref["file"])}; '
               f'selection {E(json.dumps(ref.get("selection")))}; '
               f'{E(str(ref.get("seconds_per_mutant")))} s per built mutant)</span></p>')
        if ref["survivors"]:
            self.w('<div class="scroll"><table class="data sortable"><thead><tr><th>File:line</th><th>Operator</th>'
                   '<th>Line</th><th>Judgement</th><th>Reason</th></tr></thead><tbody>')
            for s in ref["survivors"]:
                self.w(f'<tr><td>{E(s["file"])}:{s["line"]}</td><td>{E(s["op"])}'
                       f'{" (" + str(s["occurrence"]) + ")" if s["occurrence"] > 1 else ""}</td>'
                       f'<td><code>{E(s["before"])}</code></td><td>{E(mutation_reference.judgement_text(s))}</td>'
                       f'<td class="small">{E(s["reason"])}</td></tr>')
            self.w('</tbody></table></div>')

    def bench_records(self):
        """The dated records of verification/bench/results/ (traceability/bench_records.py)."""
        br = self.r.get("bench_records") or {}
        pts = br.get("points") or []
        self.w('<h3 id="bench-records">Dated benchmark records</h3>')
        self.w('<p class="small">Step times of <code>tamias_bench</code> runs kept in '
               '<code>verification/bench/results/&lt;machine&gt;/</code> (thread CPU time, one thread, '
               'each engine\'s defaults): each point is true of its commit, machine and date only, '
               'and two machines, or one shared machine hours apart, do not compare one to one. '
               'A point of several runs is their median, its bar their range. '
               f'{len(pts)} points from {br.get("records", 0)} record file(s)'
               + (f'; {br["left_out"]} cell(s) that are not one number left out' if br.get("left_out") else "")
               + (f'; data: <a href="{E(br["csv"])}"><code>{E(br["csv"])}</code></a>' if br.get("csv") else "")
               + '.</p>')
        if br.get("svg"):
            self.w(f'<div class="plots"><figure><img class="wide" src="{E(br["svg"])}" '
                   'alt="ms/step by date per scene and engine"><figcaption class="small">ms/step by '
                   'date and commit, per scene and engine</figcaption></figure></div>')
        elif not pts:
            self.w('<p class="note">No dated benchmark record with step times.</p>')

    # Scenes whose motion the V&V evidence refers to, shown first in the player (IM3's
    # collision, the elastic pair, the pyramid, the rain).
    FEATURED_PLAYERS = ("collision_im3", "elastic2", "pyramid20", "rain")

    def _players(self):
        """reports/players/index.json, written by the main job (tests/viewer/check_player.py):
        one entry per page of `tamias2d view`; [] when absent or unreadable."""
        path = os.path.join(self.out_dir, "players", "index.json")
        try:
            with open(path, encoding="utf-8") as fh:
                entries = json.load(fh)
        except (OSError, ValueError):
            return []
        return [e for e in entries if isinstance(e, dict) and e.get("name") and e.get("page")]

    def players(self):
        entries = self._players()
        if not entries:
            return
        featured = sorted(entries, key=lambda e: (e["name"] not in self.FEATURED_PLAYERS,
                                                  self.FEATURED_PLAYERS.index(e["name"])
                                                  if e["name"] in self.FEATURED_PLAYERS else 0, e["name"]))
        first = f'players/{featured[0]["page"]}'
        self.w('<h3 id="players">Recorded runs (tamias2d view)</h3>')
        self.w('<p class="small">The example scenes run by <code>tamias2d view</code>, each into one '
               'self-contained page (docs/viewer.md) that plays the recorded states: play, step, '
               'scrub, zoom (wheel), pan (drag), contacts, AABBs, velocities, trails, joints, the '
               'state of the body under the cursor and the energy (DD15, DD16). Headless Chromium '
               'checked each page (tests/viewer/check_player.py): its states equal '
               '<code>tamias2d run</code>\'s CSV to half a quantisation step, and its screenshots '
               'show the bodies.</p>')
        options = "".join(f'<option value="players/{E(e["page"])}">{E(e["name"])}</option>' for e in featured)
        self.w(f'<p><label>Scene: <select id="player-pick">{options}</select></label> '
               f'<span class="small mute">(or open a page from the table)</span></p>'
               f'<iframe id="player-frame" class="player-frame" src="{E(first)}" loading="lazy" '
               f'title="Recorded run"></iframe>')
        self.w('<table class="data sortable"><thead><tr><th>Scene</th><th>Recorded</th>'
               '<th class="num">Page size</th><th>Browser check</th><th>Middle frame</th></tr></thead><tbody>')
        for e in sorted(entries, key=lambda e: e["name"]):
            page = f'players/{e["page"]}'
            result = str(e.get("result") or "")
            status = "passed" if result.startswith("OK") else "failed" if result.startswith("failed") else "skipped"
            size = e.get("bytes")
            size_text = (f"{size / 1e6:.2f} MB" if size >= 1e5 else f"{size / 1e3:.0f} kB") \
                if isinstance(size, (int, float)) else ""
            recorded = ", ".join(x for x in (
                f'{e["frames"]} frames' if e.get("frames") is not None else "",
                f'{e["bodies"]} bodies' if e.get("bodies") is not None else "",
                f'<code class="nowrap">{E(e["options"])}</code>' if e.get("options") else "") if x)
            shot = (f'<a href="{E(page)}"><img class="thumb" loading="lazy" src="players/{E(e["screenshot"])}" '
                    f'alt="{E(e["name"])}"></a>') if e.get("screenshot") else '<span class="mute">none</span>'
            desc = f'<div class="small mute">{E(str(e["description"]))}</div>' if e.get("description") else ""
            self.w(f'<tr><td><a href="{E(page)}">{E(e["name"])}</a>{desc}</td><td>{recorded}</td>'
                   f'<td class="num" data-sort="{E(str(size or 0))}">{E(size_text)}</td>'
                   f'<td>{badge(status)} <span class="small">{E(result)}</span></td><td>{shot}</td></tr>')
        self.w('</tbody></table>')

    def coverage(self):
        cov = self.r["coverage"]
        self.w('<section id="coverage"><h2>8. Code coverage</h2>')
        if not cov:
            self.w('<p class="note">No <code>reports/data/coverage.json</code> (gcovr <code>--json-summary</code>); '
                   'the coverage build did not run.</p></section>')
            return
        t = cov["totals"]
        self.w('<div class="cards">')
        for k, name in (("line", "lines"), ("function", "functions"), ("branch", "branches")):
            pct = t.get(f"{k}_percent")
            self.w(f'<div class="card info"><div class="n">{E(_fmt(pct))}%</div><div class="l">{name}: '
                   f'{E(_fmt(t.get(k + "_covered")))}/{E(_fmt(t.get(k + "_total")))}</div></div>')
        self.w('</div><table class="data sortable"><thead><tr><th>File</th><th class="num">Lines %</th>'
               '<th class="num">Lines</th><th class="num">Functions %</th><th class="num">Branches %</th></tr></thead><tbody>')
        for f in cov["files"]:
            self.w(f'<tr><td><code>{E(str(f.get("filename")))}</code></td><td class="num">{E(_fmt(f.get("line_percent")))}</td>'
                   f'<td class="num">{E(_fmt(f.get("line_covered")))}/{E(_fmt(f.get("line_total")))}</td>'
                   f'<td class="num">{E(_fmt(f.get("function_percent")))}</td><td class="num">{E(_fmt(f.get("branch_percent")))}</td></tr>')
        self.w('</tbody></table>')
        if os.path.exists(os.path.join(self.out_dir, "coverage.html")):
            self.w('<p><a href="coverage.html">Line-by-line coverage (gcovr HTML)</a></p>')
        self.w('</section>')

    def tests_section(self):
        r = self.r
        self.w(f'<section id="tests"><h2>9. All tests and checks ({len(r["tests"])})</h2>')
        if not r["tests"]:
            self.w('<p class="note">No test results: see <a href="#warnings">warnings</a>.</p></section>')
            return
        self.w('<table class="data sortable"><thead><tr><th>Test / check</th><th>Origin</th><th>Status</th>'
               '<th>Labels</th><th>Oracle</th><th>Source</th></tr></thead><tbody>')
        for t in r["tests"]:
            src = f'<code>{E(t["file"])}:{t["line"]}</code>' if t.get("file") and t.get("line") else \
                (f'<code>{E(t["file"])}</code>' if t.get("file") else "")
            det = ""
            if t.get("details") and t["status"] in ("failed", "error", "notrun"):
                det = f'<details><summary>details</summary><pre>{E(t["details"][:1500])}</pre></details>'
            samples = f'<div class="small mute">{E(t["samples"])}</div>' if t.get("samples") else ""
            oracle = E(t["oracle"]) if t.get("oracle") else '<span class="mute">—</span>'
            self.w(f'<tr id="{self.test_anchor[t["id"]]}"><td class="tid">{E(t["id"])}{samples}{det}</td><td>{E(t["origin"])}</td>'
                   f'<td data-sort="{E(t["status"])}">{badge(t["status"])}</td><td>{self.links(t["labels"])}</td>'
                   f'<td class="small">{oracle}</td><td class="small src">{src}</td></tr>')
        self.w('</tbody></table></section>')

    def method(self):
        r = self.r
        i = r["inputs"]
        self.w('<section id="method"><h2>10. Method, inputs and warnings</h2><ul class="compact small">')
        self.w(f'<li>SRS: <code>{E(i["srs_dir"])}</code> ({E(", ".join(i["srs_files"]) or "no files")})</li>')
        self.w('<li>Code sites: comments containing <code>\\srs{LABEL}</code> in src/, include/, apps/, verification/</li>')
        self.w(f'<li>Build directory: <code>{E(i["build_dir"])}</code>; raw results: <code>{E(i["results_dir"])}</code>; '
               f'verification data: <code>{E(i["data_dir"])}</code></li>')
        self.w('<li>Boost.Test: each binary is listed once with <code>--list_content=DOT</code> (test cases, '
               'file:line, labels, inherited from suites) and run once with a JUnit logger (<code>--logger=JUNIT,…</code>); '
               'data-driven cases are one test with their samples aggregated. Other CTest entries run through '
               '<code>ctest --output-junit</code>; their SRS items come from their LABELS.</li>')
        self.w('<li>Status of an item: ' + "; ".join(f"<b>{E(k)}</b> = {E(v)}" for k, v in STATUS_HELP.items()) + '.</li>')
        self.w(f'<li>Gate: exit status 1 when any of {E(", ".join(r["gate"]["gated_kinds"]))} lacks a passing test or any test/check fails; '
               'a failed check of a "should" requirement alone is a missed goal, shown and not gating.</li>')
        run = r.get("run") or {}
        if run.get("started") and run.get("finished"):
            self.w(f'<li>This report\'s test run: started {E(run["started"])}, finished '
                   f'{E(run["finished"])} (the main job\'s earlier phases: program '
                   '<code>main_job</code> in the V&amp;V evidence)</li>')
        self.w('</ul>')
        self.builds()
        self.w(render_audit.html_reqif(self))
        cmds = run.get("commands") or []
        if cmds:
            self.w('<details><summary>Commands run</summary><pre>' + E("\n".join(
                f'[exit {c["exit"]}, {c["seconds"]} s] ' + " ".join(c["cmd"]) for c in cmds)) + '</pre></details>')
        self.w(f'<h3 id="warnings">Warnings ({len(r["warnings"])})</h3>')
        if r["warnings"]:
            self.w('<ul class="compact small">' + "".join(f"<li>{E(w)}</li>" for w in r["warnings"]) + '</ul>')
        else:
            self.w('<p class="ok-note">None.</p>')
        self.w('</section>')

    def builds(self):
        """The builds whose results this report joins, each with what it was made of."""
        bs = self.r.get("builds") or []
        prov = self.r.get("provenance") or {}
        self.w('<h3 id="builds">Builds joined</h3>')
        tree = prov.get("source_tree")
        self.w('<p class="small">The report describes commit <code>'
               f'{E(str(prov.get("source_commit") or "unknown")[:12])}</code>'
               + (f', tree <code>{E(tree[:12])}</code> (the commit and its uncommitted changes, '
                  'hashed)' if tree else '') +
               '. A build whose tree is another, or that <code>ninja -n</code> finds out of date, '
               'is refused: its results fail the gate.</p>')
        for p in prov.get("build_problems") or []:
            self.w(f'<p class="small">{badge("error")} {E(p)}</p>')
        if not bs:
            self.w('<p class="small mute">No build recorded its provenance.</p>')
            return
        self.w('<table class="data small"><thead><tr><th>Build</th><th>Tree</th><th>Build id</th>'
               '<th>Built</th><th>Compiler</th><th>Flags and options</th></tr></thead><tbody>')
        for b in bs:
            ok = tree is None or b.get("tree") == tree
            self.w(f'<tr><td>{E(str(b.get("name")))}<br><code class="small">{E(str(b.get("where") or ""))}</code></td>'
                   f'<td><code>{E(str(b.get("tree") or "")[:12])}</code>'
                   f'{"" if ok else " " + badge("error")}</td>'
                   f'<td><code>{E(str(b.get("build_id") or ""))}</code></td><td>{E(str(b.get("built") or ""))}</td>'
                   f'<td>{E(str(b.get("compiler") or ""))}</td>'
                   f'<td><code class="small">{E(str(b.get("flags") or ""))}</code> '
                   f'<span class="small">{E(str(b.get("options") or ""))}</span></td></tr>')
        self.w('</tbody></table>')
        pk = (bs[0].get("packages") or {}) if bs else {}
        if pk:
            self.w('<details><summary>Debian packages of the build directory\'s build</summary>'
                   '<p class="small">' + ", ".join(f"<code>{E(k)}</code> {E(str(v))}"
                                                   for k, v in sorted(pk.items())) + '</p></details>')

    def render(self):
        self.w('<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
               '<meta name="viewport" content="width=device-width, initial-scale=1">'
               '<title>Tamias2D traceability report</title><style>' + CSS + '</style></head><body>')
        self.header()
        self.gate()
        self.summary()
        self.items_section()
        self.gaps()
        self.matrices()
        self.graphs()
        self.errata()
        self.vv()
        self.coverage()
        self.tests_section()
        self.method()
        self.w('</main><script>' + JS + '</script></body></html>\n')
        return "".join(self.parts)


def _fmt(v):
    if v is None:
        return ""
    if isinstance(v, float):
        if v == 0:
            return "0"
        if abs(v) >= 1e5 or abs(v) < 1e-3:
            return f"{v:.4g}"
        return f"{v:.6g}"
    return str(v)


def _short_json(obj):
    import json
    s = json.dumps(obj, indent=1, default=str)
    return s if len(s) < 20000 else s[:20000] + "\n..."


def render(report):
    return Html(report).render()
