"""Renderers: one for all calculators.  ``json`` (the result document), ``markdown`` and
``table`` (rich, coloured on a terminal).  Rounding happens here and only here."""

from __future__ import annotations

import io
import json
import math
from typing import Any

from geardesign import __version__
from geardesign.core.result import Check, Result, Row, cleaned
from geardesign.core.text import (FORMATS, escape_controls, fmt, json_text, md_escape,  # noqa: F401
                                  verdict_line)


_STATUS = {  # (failed?, severity) -> (mark, word, rich style)
    (False, "error"): ("✔", "ok", "green"),
    (False, "warning"): ("✔", "ok", "green"),
    (False, "info"): ("ℹ", "info", "cyan"),
    (True, "error"): ("✘", "FAIL", "bold red"),
    (True, "warning"): ("⚠", "warn", "yellow"),
    (True, "info"): ("ℹ", "info", "cyan"),
}


def _status(c: Check) -> tuple[str, str, str]:
    return _STATUS[(not c.passed, c.severity)]


def _header(r: Result) -> str:
    """The report's first line: version, kind, title and spec, controls escaped."""
    return escape_controls(_header_text(r))


def _header_text(r: Result) -> str:
    """The report's first line as it is (each renderer escapes it for its format)."""
    title = f" — {r.title}" if r.title else ""
    src = f" [{r.source}]" if r.source else ""
    return f"geardesign {__version__} · {r.kind}{title}{src}"


# --------------------------------------------------------------------------- json


def to_json(results: list[Result]) -> str:
    docs = [r.document() for r in results]
    payload = docs[0] if len(docs) == 1 else docs
    return json_text(payload, indent=2) + "\n"


# --------------------------------------------------------------------------- markdown


def _md_rows(rows: list[Row], with_source: bool) -> list[str]:
    head = "| symbol | name | value | unit |" + (" source |" if with_source else "")
    sep = "|---|---|---:|---|" + ("---|" if with_source else "")
    out = [head, sep]
    for row in rows:
        value = fmt(row.value) + (" *(assumed)*" if row.assumed else "")
        line = (f"| {md_escape(row.symbol)} | {md_escape(row.name)} | {md_escape(value)} | "
                f"{md_escape(row.unit or '')} |")
        if with_source:
            line += f" {md_escape(row.source)} |"
        out.append(line)
    return out


def _md_table(t) -> list[str]:
    heads = [h + (f" [{u}]" if u not in (None, "-") else "") for _, h, u in t.columns]
    out = ["| " + " | ".join(md_escape(h) for h in heads) + " |",
           "|" + "---|" * len(t.columns)]
    for row in t.rows:
        out.append("| " + " | ".join(md_escape(fmt(row.get(k))) for k, _, _ in t.columns) + " |")
    return out


def to_markdown(results: list[Result], level: int = 1) -> str:
    lines: list[str] = []
    h = "#" * level
    for r in results:
        lines.append(f"{h} {md_escape(_header_text(r))}")
        lines.append("")
        lines.append("Methods: " + ", ".join(r.methods))
        lines.append("")
        for t in r.tables:
            lines += ["", f"{h}# {t.title}", ""]
            lines += _md_table(t)
        for sec in r.sections:
            lines += ["", f"{h}# {sec.title}", ""]
            lines += _md_rows(sec.rows, with_source=True)
        lines += ["", f"{h}# Inputs", ""]
        lines += _md_rows(r.input_rows, with_source=False)
        lines += ["", f"{h}# Checks", "", "| status | code | message |", "|---|---|---|"]
        for c in r.checks:
            mark, word, _ = _status(c)
            lines.append(f"| {mark} {word} | {c.code} | {md_escape(c.message)} |")
        lines += ["", f"**{verdict_line(r)}**", ""]
        for _, title, part in r.parts:
            lines += [f"{h}# {md_escape(title)}", ""]
            lines.append(to_markdown([part], level + 1))
    return "\n".join(lines)


# --------------------------------------------------------------------------- table
# the layout of the columns: geardesign.core.grid


def to_table(results: list[Result], color: bool, width: int | None = None) -> str:
    """Rich tables; ``color`` only on a terminal."""
    from rich.console import Console
    from rich.table import Table
    from rich.text import Text

    from geardesign.core.grid import default_width, grid

    if width is None:
        width = default_width()

    def _t(text: Any, style: str = "") -> Text:
        """Text as it is (no markup), control characters escaped."""
        return Text(escape_controls(str(text)), style=style)

    buf = io.StringIO()
    console = Console(file=buf, force_terminal=color, no_color=not color, width=width,
                      highlight=False, emoji=False, soft_wrap=False)

    def rows_table(title: str, rows: list[Row], with_source: bool) -> list[Table]:
        body = []
        for row in rows:
            note = row.source if with_source else ("assumed" if row.assumed else "")
            value = fmt(row.value) + ("*" if row.assumed else "")
            body.append([_t(row.symbol), _t(row.name), _t(value), _t(row.unit or ""),
                         _t(note, "dim")])
        heads = ["symbol", "name", "value", "unit", "source" if with_source else ""]
        return grid(_t(title), heads, body, width, right={2}, whole={0, 3})

    def data_table(t) -> list[Table]:
        heads = [head + (f" [{unit}]" if unit not in (None, "-") else "")
                 for _, head, unit in t.columns]
        body = [[_t(fmt(row.get(k))) for k, _, _ in t.columns] for row in t.rows]
        return grid(_t(t.title), heads, body, width)

    def one(r: Result) -> None:
        console.print(Text(_header(r), style="bold"))
        console.print(_t("Methods: " + ", ".join(r.methods)))
        console.print()
        def show(tables: list[Table]) -> None:
            for tab in tables:
                console.print(tab)
                console.print()

        for t in r.tables:
            show(data_table(t))
        for sec in r.sections:
            show(rows_table(sec.title, sec.rows, with_source=True))
        show(rows_table("Inputs  (* assumed default)", r.input_rows, with_source=False))
        body = []
        for c in r.checks:
            mark, word, style = _status(c)
            body.append([Text(f"{mark} {word}", style=style), _t(c.code, style),
                         _t(c.message)])
        for tab in grid(Text("Checks"), ["", "code", "message"], body, width, whole={0, 1}):
            console.print(tab)
        style = "bold red" if r.failed else "bold green"
        console.print(Text(verdict_line(r), style=style))
        for _, title, part in r.parts:
            console.print()
            console.rule(_t(title))
            one(part)

    for i, r in enumerate(results):
        if i:
            console.print()
        one(r)
    text = buf.getvalue()
    if not color:   # no trailing blanks in a file or a pipe
        text = "\n".join(line.rstrip() for line in text.split("\n"))
    return text


def to_jsonl(results: list[Result]) -> str:
    """One JSON document a line (``jq .verdict`` works for one spec and for many)."""
    return "".join(json_text(r.document()) + "\n" for r in results)


CSV_COLUMNS = ("spec", "key", "symbol", "name", "value", "unit", "source", "status",
               "severity", "limit", "message")
"""Columns of the CSV report: a quantity fills the first seven, a check all of them."""

BOM = "\ufeff"
"""The UTF-8 byte order mark that CSV files begin with, so that spreadsheet programs read
them as UTF-8 (σ_H, min⁻¹, ψ_bd) instead of a local code page."""


def _csv_value(value: Any) -> Any:
    if isinstance(value, dict):
        return json.dumps(value, allow_nan=False, default=str, ensure_ascii=False)
    if isinstance(value, (list, tuple)):
        return json.dumps(value, allow_nan=False, default=str) if all(
            v is None or isinstance(v, (int, float)) for v in value) else fmt(value)
    return "" if value is None else value


def _csv_rows(r: Result):
    """The rows of one result: its inputs (``inputs.KEY``; source "assumed" for a default
    the calculator took), its quantities (``results.SECTION.KEY``), then its checks
    (``checks.CODE``) with value, limit, status, severity and message in their columns."""
    doc_units = r.document()["units"]
    for row in r.input_rows:
        yield (r.source, f"inputs.{row.key}", row.symbol, row.name, _csv_value(row.value),
               row.unit or "", "assumed" if row.assumed else "given")
    for sec in r.sections:
        for row in sec.rows:
            key = f"results.{sec.key}.{row.key}"
            yield (r.source, key, row.symbol, row.name, _csv_value(row.value),
                   doc_units.get(key, ""), row.source)
    for c in r.checks:
        yield (r.source, f"checks.{c.code}", c.code, "", _csv_value(c.value), "", c.source,
               "pass" if c.passed else "fail", c.severity, _csv_value(c.limit), c.message)


_FORMULA = ("=", "+", "-", "@", "\t", "\r")
"""First characters that make a spreadsheet read a cell as a formula."""


def csv_cell(x: Any) -> Any:
    """A CSV cell: numbers as they are; text with its control characters escaped
    (:func:`escape_controls`) and, when it begins like a formula (``=``, ``+``, ``-``,
    ``@``, tab, CR) and is not a plain number (or the unit ``-``), preceded by ``'`` so
    that a spreadsheet shows it as text instead of evaluating it ("CSV injection")."""
    if not isinstance(x, str):
        return x
    if x.startswith(_FORMULA) and x != "-":
        try:
            number = math.isfinite(float(x))
        except ValueError:
            number = False
        if not number:
            x = "'" + x
    return escape_controls(x)


def to_csv(results: list[Result]) -> str:
    """The results flattened for a spreadsheet (:data:`CSV_COLUMNS`): one row per input,
    per quantity and per check (:func:`_csv_rows`), the results of a drive's stages after
    it; numbers at full precision, text cells through :func:`csv_cell`; UTF-8 with a byte
    order mark (:data:`BOM`)."""
    import csv

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS)

    def write(r: Result) -> None:
        for row in _csv_rows(r):
            w.writerow([csv_cell(x) for x in row])
        for _, _, part in r.parts:
            write(part)

    for r in results:
        write(r)
    return BOM + buf.getvalue()


def to_html(results: list[Result]) -> str:
    """The self-contained HTML report (:mod:`geardesign.rendering.html`)."""
    from geardesign.rendering.html import to_html as html

    return html(results)


def render_pdf(results: list[Result]) -> bytes:
    """The HTML report printed to PDF by Chromium (:mod:`geardesign.rendering.pdf`);
    :class:`geardesign.rendering.browser.BrowserMissing` when no browser is installed."""
    from geardesign.rendering.html import document_title
    from geardesign.rendering.pdf import html_to_pdf

    results = [cleaned(r) for r in results]
    return html_to_pdf(to_html(results), document_title(results))


def render(results: list[Result], fmt_name: str, color: bool = False, width: int | None = None) -> str:
    """The report of ``results`` in format ``fmt_name``.  Every format receives the same
    cleaned results (:func:`geardesign.core.result.cleaned`: no NaN or infinity anywhere),
    and every text reaching the output has its control characters escaped."""
    results = [cleaned(r) for r in results]
    if fmt_name == "json":
        return to_json(results)
    if fmt_name == "jsonl":
        return to_jsonl(results)
    if fmt_name == "csv":
        return to_csv(results)
    if fmt_name == "html":
        return to_html(results)
    if fmt_name == "markdown":
        return to_markdown(results)
    return to_table(results, color=color, width=width)


_GRID = {"GAP", "fit_widths", "column_groups", "grid", "default_width", "terminal_width",
         "grid_text"}


def __getattr__(name: str):
    # the columns of a terminal table (geardesign.core.grid), imported when asked for
    if name in _GRID:
        from geardesign.core import grid

        return getattr(grid, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
