"""The auditor's parts of index.html and traceability.md: the review state of the trace links
(suspect links first) and the ReqIF export. render_html.py and render_md.py call these."""
from __future__ import annotations

import html

E = html.escape
STATE_CLASS = {"reviewed": "st-ok", "suspect": "st-fail", "unreviewed": "st-none"}
STATE_HELP = {
    "reviewed": "a person reviewed this link and neither end has changed since (traceability/reviews.yaml)",
    "suspect": "reviewed, but the item's normative text or the test's source changed since: review it again",
    "unreviewed": "no review recorded",
}


def review_badge(review, changed=None):
    """The review state beside a link's grade ('' for an unreviewed link)."""
    status = review.get("status") if isinstance(review, dict) else review
    if isinstance(review, dict):
        changed = review.get("changed")
    if not status:
        return ""
    if status == "unreviewed":
        return ' <span class="mute small" title="' + E(STATE_HELP[status]) + '">unreviewed</span>'
    what = f" ({', '.join(changed)} changed)" if status == "suspect" and changed else ""
    return (f' <span class="badge {STATE_CLASS[status]}" title="{E(STATE_HELP[status])}">'
            f'{E(status + what)}</span>')


def _counts(rv):
    return f'{rv.get("reviewed", 0)} reviewed, {rv.get("suspect", 0)} suspect, {rv.get("unreviewed", 0)} unreviewed'


def html_gate_box(page):
    """A box under the gate listing the suspect links (never hidden)."""
    rv = page.r.get("reviews") or {}
    sus = rv.get("suspect_links") or []
    if not sus:
        return ""
    gates = "they fail the gate (--suspect-gates)" if rv.get("gates") else \
        "they do not gate (build_report.py --suspect-gates makes them)"
    lis = "".join(f'<li>{page.link(s["item"])} ← {page.tlink(s["test"])}: {E(", ".join(s["changed"]))} '
                  f'changed since {E(s["reviewer"])} reviewed it ({E(s["date"])})</li>' for s in sus)
    return (f'<div class="gate fail" id="suspect-links"><h2>Suspect trace links ({len(sus)})</h2>'
            f'An end of each of these links changed since its review; {E(gates)}. '
            f'<a href="#reviews">Reviews</a>:<ul>{lis}</ul></div>')


def html_reviews(page):
    r = page.r
    rv = r.get("reviews") or {}
    out = [f'<h3 id="reviews">Reviews of the trace links ({E(_counts(rv))})</h3>',
           '<p class="small">Each link carries a fingerprint of both ends '
           '(<code>traceability/fingerprints.py</code>): of the item\'s statement, equation, '
           'symbols, uses and obligation, and of the test\'s source text (the test case from its '
           'oracle comment to the next test case, the CTest entry\'s <code>add_test</code> block, '
           'or the verification program\'s source and the check\'s declaration). '
           f'<code>{E(str(rv.get("file") or "traceability/reviews.yaml"))}</code> records who reviewed '
           'which link against which fingerprints (<code>traceability/review.py mark ITEM TEST '
           '--reviewer NAME</code>, after looking; <code>mark-all</code> for several). A link whose '
           'end changed since is <b>suspect</b>: listed here and under the gate, '
           + ('failing the gate (<code>--suspect-gates</code>).' if rv.get("gates") else
              'not gating (<code>build_report.py --suspect-gates</code> makes it gate).') + '</p>']
    sus = rv.get("suspect_links") or []
    if sus:
        out.append('<table class="data"><thead><tr><th>Item</th><th>Test / check</th><th>Changed</th>'
                   '<th>Reviewed by</th><th>On</th></tr></thead><tbody>')
        out += [f'<tr><td>{page.link(s["item"])}</td><td>{page.tlink(s["test"])}</td>'
                f'<td>{E(", ".join(s["changed"]))}</td><td>{E(s["reviewer"])}</td><td>{E(s["date"])}</td></tr>'
                for s in sus]
        out.append('</tbody></table>')
    else:
        out.append('<p class="ok-note">No suspect link.</p>')
    orphans = rv.get("orphan_records") or []
    if orphans:
        out.append(f'<p class="note">{len(orphans)} review record(s) name a link the report no longer '
                   'has (the test or the label is gone; <code>review.py prune</code> drops them): '
                   + ", ".join(f'{E(o["item"])} ← {E(o["test"])}' for o in orphans) + '</p>')
    rows = r.get("links") or []
    if rows:
        tests = {t["id"]: t for t in r.get("tests") or []}
        out.append(f'<details><summary>Every link with its grade, review state and fingerprints '
                   f'({len(rows)})</summary><table class="data sortable small"><thead><tr><th>Item</th>'
                   '<th>Test / check</th><th>Grade</th><th>Review</th><th>Item fingerprint</th>'
                   '<th>Test fingerprint</th><th>Test text hashed</th></tr></thead><tbody>')
        for ln in rows:
            st = (ln.get("review") or {}).get("status", "")
            out.append(f'<tr><td>{page.link(ln["item"])}</td><td>{page.tlink(ln["test"])}</td>'
                       f'<td>{E(ln["grade"])}</td><td data-sort="{E(st)}">{review_badge(ln.get("review")) or E(st)}</td>'
                       f'<td><code>{E(str(ln.get("item_fingerprint")))}</code></td>'
                       f'<td><code>{E(str(ln.get("test_fingerprint")))}</code></td>'
                       f'<td>{E(str((tests.get(ln["test"]) or {}).get("fingerprint_source") or ""))}</td></tr>')
        out.append('</tbody></table></details>')
    return "".join(out)


def html_reqif(page):
    x = page.r.get("reqif")
    if not x:
        return ""
    so, rel = x["spec_objects"], x["spec_relations"]
    return (f'<h3 id="reqif">ReqIF export</h3><p class="small"><a href="{E(x["file"])}">{E(x["file"])}</a>: '
            f'this report as ReqIF 1.2 for a requirements tool (DOORS, Polarion, Codebeamer, Jama, '
            f'StrictDoc...): {so["items"]} SRS items, {so["tests"]} tests and checks, '
            f'{so["code_sites"]} code sites as SPEC-OBJECTs; SPEC-RELATIONs verifies {rel["verifies"]} '
            f'(test → item, with grade and review state), refines {rel["refines"]} and uses '
            f'{rel["uses"]} (item → item, from <code>uses</code>), implements {rel["implements"]} '
            f'(code site → item); specifications: {E("; ".join(x["specifications"]))}. Its '
            f'CREATION-TIME is the report\'s <code>generated</code> time; every LAST-CHANGE is '
            f'{E(x["last_change"])}, the reported commit\'s date. <code>traceability/reqif.py import '
            f'FILE</code> reads such a file back and lists what it cannot map.</p>')


def md(r):
    """The reviews and the ReqIF export as Markdown lines."""
    rv = r.get("reviews") or {}
    L = [f"### Reviews of the trace links ({_counts(rv)})\n",
         f"Review records: `{rv.get('file') or 'traceability/reviews.yaml'}`; suspect links "
         + ("fail the gate (--suspect-gates)." if rv.get("gates") else "do not gate (--suspect-gates makes them).") + "\n"]
    sus = rv.get("suspect_links") or []
    if sus:
        L.append("| Item | Test / check | Changed | Reviewed by | On |\n|---|---|---|---|---|")
        L += [f"| {s['item']} | {s['test']} | {', '.join(s['changed'])} | {s['reviewer']} | {s['date']} |"
              for s in sus]
        L.append("")
    else:
        L.append("No suspect link.\n")
    for o in rv.get("orphan_records") or []:
        L.append(f"- Review record of a link the report no longer has: {o['item']} <- {o['test']}")
    x = r.get("reqif")
    if x:
        so, rel = x["spec_objects"], x["spec_relations"]
        L.append(f"\n### ReqIF export\n\n[{x['file']}]({x['file']}): {so['items']} SRS items, "
                 f"{so['tests']} tests and checks, {so['code_sites']} code sites; relations "
                 + ", ".join(f"{k} {n}" for k, n in rel.items()) +
                 f"; CREATION-TIME is the report's generated time, every LAST-CHANGE {x['last_change']}.\n")
    return "\n".join(L) + "\n"


def md_gate(r):
    sus = (r.get("reviews") or {}).get("suspect_links") or []
    if not sus:
        return ""
    return ("**Suspect trace links (an end changed since its review):**\n\n" +
            "\n".join(f"- {s['item']} <- {s['test']}: {', '.join(s['changed'])} changed" for s in sus) + "\n")
