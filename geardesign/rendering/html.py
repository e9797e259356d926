"""The HTML report: one self-contained document (no script, no request outside it).

Order, as ``DESIGN.md`` ("Report") asks:

1. the first screen (:mod:`geardesign.rendering.first_screen`): the title (the spec's
   ``title``), the spec, kind and methods; the verdict; the governing margins as bars
   (:mod:`geardesign.rendering.margins`, worst first); every failed check with its advice;
   the warnings;
2. the table of contents;
3. the pictures of the whole (:mod:`geardesign.rendering.figures`), the sections with their
   pictures and the tables, then the parts grouped with their real hierarchy (a drive:
   stages, bearings, shafts, connections; each with its own sections);
4. all margins, the checks, and the inputs with their source (given / assumed default).

Symbols, units and numbers are typeset by :mod:`geardesign.rendering.typeset`; numbers of a
column are aligned at the decimal point.  Every text that comes from a spec is escaped.
The print style sheet makes the PDF (:mod:`geardesign.rendering.pdf`): A4, headings kept with
what follows, table heads repeated on each page, rows and figures never split.
"""

from __future__ import annotations

from typing import Any

from geardesign import __version__
from geardesign.core.result import Check, Result, Row
from geardesign.rendering.figures import Figure, figures
from geardesign.rendering.first_screen import Page
from geardesign.rendering.first_screen import advice_html as _advice
from geardesign.rendering.margins import Margin, margins
from geardesign.rendering.typeset import e, number_parts, symbol_html, unit_html

PART_GROUPS = {"stage_reports": "Stage calculations", "bearing_reports": "Bearing calculations",
               "shaft_reports": "Shaft calculations",
               "connection_reports": "Shaft–hub connection calculations"}
"""Headings of the groups of nested results (a drive's parts), by their key."""

CSS = """
:root{--ok:#1b7a3a;--bad:#b3261e;--warn:#8a5a00;--ink:#1d1d1f;--mute:#5f6368;--line:#d9dce1}
*{box-sizing:border-box}
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,"Noto Sans",sans-serif;color:var(--ink);
margin:0;line-height:1.4;font-size:15px}
main{max-width:1200px;margin:0 auto;padding:20px 28px 60px}
h1{font-size:1.7em;margin:0 0 4px}h2{font-size:1.3em;margin:1.6em 0 .4em;border-bottom:2px solid var(--line)}
h3{font-size:1.12em;margin:1.3em 0 .3em}h4{font-size:1em;margin:1.1em 0 .3em}
h5,h6{font-size:.95em;margin:1em 0 .3em}
.meta{color:var(--mute);margin:0 0 12px;font-size:.92em}
.verdict{border-radius:8px;padding:10px 16px;margin:8px 0 14px;display:flex;gap:16px;align-items:center}
.verdict b{font-size:1.6em;letter-spacing:.05em}
.verdict.pass{background:#e7f4ea;border:1px solid #9fd1ab;color:var(--ok)}
.verdict.fail{background:#fbe9e7;border:1px solid #f0a59d;color:var(--bad)}
.verdict span{color:var(--ink)}
.summary{display:grid;grid-template-columns:minmax(0,1.15fr) minmax(0,1fr);gap:28px}
.summary h2{margin-top:.2em;font-size:1.1em}
.bar-row{display:grid;grid-template-columns:minmax(0,13em) minmax(0,1fr) 9.5em;gap:8px;align-items:center;
margin:3px 0;font-size:.9em}
.bar-row .lbl{overflow:hidden;text-overflow:ellipsis;white-space:nowrap}
.bar-row .lbl small{color:var(--mute)}.code{font-family:ui-monospace,monospace;font-size:.88em}
.bar{position:relative;height:14px;background:#f1f3f4;border-radius:3px}
.bar .fill{position:absolute;left:0;top:0;bottom:0;border-radius:3px;background:var(--ok)}
.bar .fill.low{background:#c98a00}.bar .fill.bad{background:var(--bad)}
.bar.failed{background:var(--bad);color:#fff;font-size:.75em;line-height:14px;padding-left:6px;
font-weight:600}
.bar .one{position:absolute;top:-3px;bottom:-3px;width:2px;background:var(--ink)}
.bar-row .num{font-variant-numeric:tabular-nums;text-align:right;white-space:nowrap}
.findings ul{margin:.2em 0 .8em;padding-left:1.1em}.findings li{margin:.25em 0}
.findings .code{font-family:ui-monospace,monospace;font-size:.88em}
.findings .fix{color:var(--mute)}
.none{color:var(--mute)}
nav.toc{border-top:1px solid var(--line);margin-top:16px;padding-top:4px}
nav.toc ol{columns:3 16em;margin:.3em 0;padding-left:2.2em}nav.toc ol ol{columns:1;padding-left:1.6em}
nav.toc li{break-inside:avoid}
a{color:#1a57b5;text-decoration:none}a:hover{text-decoration:underline}
.scroll{overflow-x:auto;max-width:100%}
table{border-collapse:collapse;margin:.3em 0 1em;font-size:.9em}
table.rows{width:100%}
th,td{border-bottom:1px solid var(--line);padding:3px 8px;vertical-align:top;text-align:left}
th{background:#f5f6f8;font-weight:600}
td.num{text-align:right;white-space:nowrap;font-variant-numeric:tabular-nums}
td.num .f{display:inline-block;min-width:var(--fw,4ch);text-align:left}
td.sym{white-space:nowrap}td.unit{white-space:nowrap}
td.src{color:var(--mute);font-size:.92em}
tr.assumed td{background:#fff8e1}
td.st-fail{color:var(--bad);font-weight:600;white-space:nowrap}
td.st-warn{color:var(--warn);white-space:nowrap}td.st-ok{color:var(--ok);white-space:nowrap}
td.st-info{color:var(--mute);white-space:nowrap}
figure{margin:.6em 0 1.2em}figure svg{width:100%;height:auto;display:block}
figure svg.chart{max-width:820px}figure svg.diagram{max-width:980px}
figure svg.figure-profile{max-width:640px;max-height:460px;border:1px solid var(--line)}
figcaption{color:var(--mute);font-size:.88em}
.part-head{color:var(--mute);font-size:.92em}
article+article{border-top:3px solid var(--line);margin-top:2em}
@media print{
@page{size:A4;margin:16mm 12mm 14mm 12mm}
body{font-size:10.5pt}main{max-width:none;padding:0}
.summary{grid-template-columns:1fr 1fr;gap:14px}
.scroll{overflow:visible}table{font-size:8.5pt}
thead{display:table-header-group}tr,figure,.bar-row{break-inside:avoid}
h1,h2,h3,h4,h5,h6{break-after:avoid}
nav.toc ol{columns:2}
a{color:inherit}
}
"""


def _num_cell(value: Any, unit: str | None) -> tuple[str, int]:
    """A value cell: (html, length of the fraction part) for decimal alignment."""
    if isinstance(value, (int, float)) and not isinstance(value, bool) or value is None:
        if value is None:
            return '<td class="num">—</td>', 0
        i, f = number_parts(value, unit)
        return f'<td class="num">{e(i)}<span class="f">{e(f)}</span></td>', len(f)
    from geardesign.core.text import fmt

    return f"<td>{e(fmt(value))}</td>", 0


def _fw(n: int) -> str:
    return f' style="--fw:{max(n, 1)}ch"'


def _status(c: Check) -> tuple[str, str]:
    if c.passed:
        return ("st-info", "ℹ info") if c.severity == "info" else ("st-ok", "✔ ok")
    return {"error": ("st-fail", "✘ FAIL"), "warning": ("st-warn", "⚠ warn")}.get(
        c.severity, ("st-info", "ℹ info"))


class _Doc(Page):
    """The report document: the first screen (:class:`Page`), the tables and sections."""

    # ------------------------------------------------------------------ tables

    def rows_table(self, rows: list[Row], with_source: bool, inputs: bool = False) -> None:
        cells, fw = [], 0
        for row in rows:
            cell, n = _num_cell(row.value, row.unit)
            fw = max(fw, n)
            cells.append(cell)
        head = ("<th>symbol</th><th>name</th><th>value</th><th>unit</th>"
                + ("<th>source</th>" if with_source or inputs else ""))
        self.add(f'<div class="scroll"><table class="rows"{_fw(fw)}><thead><tr>{head}</tr>'
                 "</thead><tbody>")
        for row, cell in zip(rows, cells):
            src = (("assumed default" if row.assumed else "given") if inputs else row.source)
            self.add(f'<tr{" class=assumed" if inputs and row.assumed else ""}>'
                     f'<td class="sym" title="{e(row.key)}">{symbol_html(row.symbol or row.key)}'
                     f'</td><td>{e(row.name)}</td>{cell}<td class="unit">{unit_html(row.unit)}'
                     "</td>" + (f'<td class="src">{e(src)}</td>' if with_source or inputs else "")
                     + "</tr>")
        self.add("</tbody></table></div>")

    def data_table(self, t) -> None:
        heads = "".join(f"<th>{symbol_html(h)}"
                        + (f" [{unit_html(u)}]" if u not in (None, "-") else "") + "</th>"
                        for _, h, u in t.columns)
        body, fws = [], [0] * len(t.columns)
        for row in t.rows:
            tds = []
            for j, (k, _, u) in enumerate(t.columns):
                cell, n = _num_cell(row.get(k), u)
                fws[j] = max(fws[j], n)
                tds.append(cell)
            body.append(tds)
        fw = max(fws, default=0)
        self.add(f'<div class="scroll"><table{_fw(fw)}><thead><tr>{heads}</tr></thead><tbody>')
        for tds in body:
            self.add("<tr>" + "".join(tds) + "</tr>")
        self.add("</tbody></table></div>")

    def figure(self, f: Figure) -> None:
        self.add(f"<figure>{f.svg}<figcaption>{e(f.caption)}</figcaption></figure>")

    def checks_table(self, r: Result, cid: str) -> None:
        self.add('<div class="scroll"><table class="rows"><thead><tr><th>status</th>'
                 "<th>code</th><th>message</th><th>value</th><th>limit</th></tr></thead><tbody>")
        for c in r.checks:
            cls, word = _status(c)
            value, _ = _num_cell(c.value, None)
            limit, _ = _num_cell(c.limit, None)
            advice = _advice(c) if not c.passed else ""
            self.add(f'<tr id="{cid}-{e(c.code.lower())}"><td class="{cls}">{word}</td>'
                     f"<td>{e(c.code)}</td><td>{e(c.message)}"
                     + (f"<br><small>Advice: {advice}</small>" if advice else "")
                     + f"</td>{value}{limit}</tr>")
        self.add("</tbody></table></div>")

    def margins_table(self, ms: list[Margin]) -> None:
        if not ms:
            self.add('<p class="none">None.</p>')
            return
        self.add('<div class="scroll"><table class="rows" style="--fw:4ch"><thead><tr>'
                 "<th>quantity</th><th>where</th><th>value</th><th></th><th>limit</th>"
                 "<th>margin</th><th>check</th></tr></thead><tbody>")
        for m in ms:
            v, _ = _num_cell(m.value, None)
            lim, _ = _num_cell(m.limit, None)
            ratio, _ = _num_cell(m.ratio, "-")
            where = m.name if m.section == "checks" else f"{m.section}: {m.name}"
            label = (f'<span class="code">{e(m.label)}</span>' if m.section == "checks"
                     else symbol_html(m.label))
            self.add(f"<tr><td class=sym>{label}</td><td>{e(where)}</td>{v}"
                     f"<td>{'≥' if m.at_least else '≤'}</td>{lim}{ratio}<td>{e(m.code)}</td>"
                     "</tr>")
        self.add("</tbody></table></div>")

    # ------------------------------------------------------------------ results

    def result(self, r: Result) -> None:
        """One top-level result: first screen, contents, body."""
        ids = self.ids
        key = ids(r.source.rsplit("/", 1)[-1].rsplit(".", 1)[0] if r.source else r.kind)
        all_id, checks_id = ids(key, "margins"), ids(key, "checks")
        title = r.title or f"{r.kind} design"
        self.add(f'<article id="{key}"><header class="first-screen">',
                 f"<h1>{e(title)}</h1>",
                 f'<p class="meta">{e(r.source) + " · " if r.source else ""}'
                 f"kind {e(r.kind)} · {e(', '.join(r.methods))} · geardesign {e(__version__)}"
                 "</p>")
        from geardesign.core.text import verdict_line

        word = "FAIL" if r.failed else "PASS"
        self.add(f'<div class="verdict {word.lower()}" id="{ids(key, "verdict")}" '
                 f'data-verdict="{word.lower()}"><b>{word}</b>'
                 f"<span>{e(verdict_line(r).split(':', 1)[-1].strip())}</span></div>")
        ms = margins(r)
        self.add('<div class="summary">')
        self.margin_bars(ms, all_id, r.failed)
        self.findings(r, checks_id)
        self.add("</div></header>")
        figs = figures(r)
        body = _Doc()
        body.ids = ids
        for f in figs.get("", []):      # the picture of the whole, before the contents
            self.figure(f)
        toc = body.body(r, {k: v for k, v in figs.items() if k}, 2, key)
        toc += [(2, all_id, "All margins"), (2, checks_id, "Checks"),
                (2, ids(key, "inputs"), "Inputs")]
        self.add(_toc(toc))
        self.out.extend(body.out)
        self.add(f'<h2 id="{all_id}">All margins</h2>')
        self.margins_table(ms)
        self.add(f'<h2 id="{checks_id}">Checks</h2>')
        self.checks_table(r, checks_id)
        self.add(f'<h2 id="{toc[-1][1]}">Inputs</h2><p class="none">Every input the '
                 "calculation used; highlighted rows are defaults the calculator assumed.</p>")
        self.rows_table(r.input_rows, False, inputs=True)
        self.add("</article>")

    def body(self, r: Result, figs: dict, level: int, key: str) -> list:
        """Sections, tables and parts of ``r`` at heading ``level``; the contents entries
        ``(level, id, title)``."""
        h = min(level, 6)
        toc = []
        for f in figs.get("", []):
            self.figure(f)
        blocks = ([(sec.key, sec.title, lambda sec=sec: self.rows_table(sec.rows, True))
                   for sec in r.sections]
                  + [(t.key, t.title, lambda t=t: self.data_table(t)) for t in r.tables])
        for bkey, title, table in blocks:
            bid = self.ids(key, bkey)
            toc.append((level, bid, title))
            self.add(f'<h{h} id="{bid}">{e(title)}</h{h}>')
            for f in figs.get(bkey, []):
                self.figure(f)
            table()
        groups: dict[str, list] = {}
        for pkey, title, part in r.parts:
            groups.setdefault(pkey, []).append((title, part))
        for pkey, items in groups.items():
            gid = self.ids(key, pkey)
            gtitle = PART_GROUPS.get(pkey, pkey.replace("_reports", "").replace("_", " ")
                                     .capitalize())
            toc.append((level, gid, gtitle))
            self.add(f'<h{h} id="{gid}">{e(gtitle)}</h{h}>')
            for title, part in items:
                pid = self.ids(key, pkey, title)
                toc.append((level + 1, pid, title))
                sub = min(level + 1, 6)
                from geardesign.core.text import verdict_line

                self.add(f'<section><h{sub} id="{pid}">{e(title)}</h{sub}>'
                         f'<p class="part-head">{e(part.kind)} · {e(", ".join(part.methods))}'
                         f" · {e(verdict_line(part))}</p>")
                self.body(part, figures(part), level + 2, pid)
                inner = min(level + 2, 6)
                self.add(f"<h{inner}>Checks</h{inner}>")
                self.checks_table(part, self.ids(pid, "checks"))
                self.add(f"<h{inner}>Inputs</h{inner}>")
                self.rows_table(part.input_rows, False, inputs=True)
                self.add("</section>")
        return toc


def _toc(entries: list) -> str:
    """Nested ordered lists from ``(level, id, title)`` entries."""
    out = ['<nav class="toc" aria-label="contents"><h2>Contents</h2><ol>']
    base = min((lv for lv, _, _ in entries), default=2)
    depth = base
    first = True
    for lv, i, title in entries:
        if lv > depth:
            out.append("<ol>" * (lv - depth))
        elif lv < depth:
            out.append("</li></ol>" * (depth - lv) + "</li>")
        elif not first:
            out.append("</li>")
        depth, first = lv, False
        out.append(f'<li><a href="#{i}">{e(title)}</a>')
    if not first:
        out.append("</li></ol>" * (depth - base) + "</li>")
    out.append("</ol></nav>")
    return "".join(out)


def document_title(results: list[Result]) -> str:
    if len(results) == 1:
        r = results[0]
        return f"{r.title or r.kind + ' design'} — geardesign report"
    return f"geardesign report: {len(results)} specs"


def to_html(results: list[Result]) -> str:
    """The self-contained HTML report of ``results`` (cleaned: no NaN or infinity)."""
    doc = _Doc()
    for r in results:
        doc.result(r)
    head = ('<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            '<meta name="viewport" content="width=device-width, initial-scale=1">'
            f'<meta name="generator" content="geardesign {e(__version__)}">'
            f"<title>{e(document_title(results))}</title><style>{CSS}</style></head>"
            "<body><main>")
    return head + "\n".join(doc.out) + "\n</main></body></html>\n"
