"""Renderers: one for all calculators.  ``json`` (the result document), ``markdown`` and
``table`` (rich, coloured on a terminal).  Rounding happens here and only here."""

from __future__ import annotations

import io
import json
import math
import os
import textwrap
from typing import Any

from geardesign import __version__
from geardesign.core.result import Check, Result, Row, cleaned
from geardesign.core.text import escape_controls, fmt, json_text, verdict_line  # noqa: F401

FORMATS = ("table", "json", "jsonl", "markdown", "csv", "html", "pdf")

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
    title = f" — {escape_controls(r.title)}" if r.title else ""
    src = f" [{escape_controls(r.source)}]" if r.source else ""
    return f"geardesign {__version__} · {r.kind}{title}{src}"


# --------------------------------------------------------------------------- json


def to_json(results: list[Result]) -> str:
    docs = [r.document() for r in results]
    payload = docs[0] if len(docs) == 1 else docs
    return json_text(payload, indent=2) + "\n"


# --------------------------------------------------------------------------- markdown


def _md_escape(text: str) -> str:
    return escape_controls(str(text)).replace("|", "\\|")


def _md_rows(rows: list[Row], with_source: bool) -> list[str]:
    head = "| symbol | name | value | unit |" + (" source |" if with_source else "")
    sep = "|---|---|---:|---|" + ("---|" if with_source else "")
    out = [head, sep]
    for row in rows:
        value = fmt(row.value) + (" *(assumed)*" if row.assumed else "")
        line = (f"| {_md_escape(row.symbol)} | {_md_escape(row.name)} | {_md_escape(value)} | "
                f"{_md_escape(row.unit or '')} |")
        if with_source:
            line += f" {_md_escape(row.source)} |"
        out.append(line)
    return out


def _md_table(t) -> list[str]:
    heads = [h + (f" [{u}]" if u not in (None, "-") else "") for _, h, u in t.columns]
    out = ["| " + " | ".join(_md_escape(h) for h in heads) + " |",
           "|" + "---|" * len(t.columns)]
    for row in t.rows:
        out.append("| " + " | ".join(_md_escape(fmt(row.get(k))) for k, _, _ in t.columns) + " |")
    return out


def to_markdown(results: list[Result], level: int = 1) -> str:
    lines: list[str] = []
    h = "#" * level
    for r in results:
        lines.append(f"{h} {_header(r)}")
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
            lines.append(f"| {mark} {word} | {c.code} | {_md_escape(c.message)} |")
        lines += ["", f"**{verdict_line(r)}**", ""]
        for _, title, part in r.parts:
            lines += [f"{h}# {escape_controls(title)}", ""]
            lines.append(to_markdown([part], level + 1))
    return "\n".join(lines)


# --------------------------------------------------------------------------- table


GAP = 3
"""Characters between two columns of a rich table without edges (padding and divider)."""


def _longest_word(text: str) -> int:
    from rich.cells import cell_len

    return max((cell_len(w) for w in text.split()), default=0)


def fit_widths(mins: list[int], maxs: list[int], room: int) -> list[int]:
    """Widths of columns that together take at most ``room`` characters: each column its
    natural width ``maxs[i]`` when that fits, else the widest columns narrowed first, never
    below ``mins[i]`` (the longest word of the column: a number is never cut or folded)."""
    widths = list(maxs)
    while sum(widths) > room:
        wide = [i for i, w in enumerate(widths) if w > mins[i]]
        if not wide:
            break
        top = max(widths[i] for i in wide)
        tops = [i for i in wide if widths[i] == top]
        rest = [widths[i] for i in wide if widths[i] < top]
        floor = max([max(mins[i] for i in tops), *rest, 1])
        over = sum(widths) - room
        cut = min(top - floor, -(-over // len(tops)))
        for i in tops:
            widths[i] = max(mins[i], widths[i] - max(cut, 1))
    return widths


def column_groups(mins: list[int], width: int, keep: int = 1) -> list[list[int]]:
    """The columns split into groups that each fit ``width`` characters at their least
    widths ``mins`` (wrapping text, never cutting a word or a number); the first ``keep``
    columns (the row's name, e.g. the rank) repeat in every group."""
    n = len(mins)
    keep = min(keep, n)
    head = list(range(keep))
    groups: list[list[int]] = []
    cur = list(head)
    used = sum(mins[i] for i in head) + GAP * max(0, keep - 1)
    for i in range(keep, n):
        need = mins[i] + (GAP if cur else 0)
        if len(cur) > keep and used + need > width:
            groups.append(cur)
            cur = list(head)
            used = sum(mins[j] for j in head) + GAP * max(0, keep - 1)
            need = mins[i] + (GAP if cur else 0)
        cur.append(i)
        used += need
    groups.append(cur)
    return groups


def grid(title, heads: list[str], body: list[list], width: int, right: set = frozenset(),
         whole: set = frozenset(), keep: int = 1) -> list:
    """A table as one or more rich tables of at most ``width`` characters.  Every column
    gets a fixed width (:func:`fit_widths`): text wraps at spaces, a word or a number is
    never cut (no ellipsis, no fold); when even the least widths do not fit, the columns
    are split into groups (:func:`column_groups`) that repeat the first column.  Columns
    in ``whole`` are never wrapped; ``right`` are right-aligned.  Cells are rich ``Text``."""
    from rich import box
    from rich.table import Table
    from rich.text import Text

    n = len(heads)
    mins, maxs = [], []
    for i in range(n):
        cells = [row[i] for row in body]
        longest = max((c.cell_len for c in cells), default=0)
        word = max((_longest_word(c.plain) for c in cells), default=0)
        least = longest if i in whole else word
        mins.append(max(least, _longest_word(heads[i]), 1))
        maxs.append(max(longest, len(heads[i]), mins[-1]))
    tables = []
    groups = column_groups(mins, width, keep)
    for g, cols in enumerate(groups):
        room = width - GAP * (len(cols) - 1)
        widths = fit_widths([mins[i] for i in cols], [maxs[i] for i in cols], room)
        name = title.copy() if isinstance(title, Text) else Text(str(title))
        if g:
            name.append(f"{' ' if name.plain else ''}(continued, {g + 1} of {len(groups)})")
        tab = Table(title=name, title_justify="left", title_style="bold", box=box.SIMPLE_HEAD,
                    show_edge=False, pad_edge=False)
        for i, w in zip(cols, widths):
            head = "\n".join(textwrap.wrap(heads[i], w, break_long_words=False)) or heads[i]
            tab.add_column(Text(head), width=w, no_wrap=i in whole,
                           justify="right" if i in right else "left", overflow="fold")
        for row in body:
            tab.add_row(*(row[i] for i in cols))
        tables.append(tab)
    return tables


def default_width() -> int:
    """The width of a table written to a pipe or a file: the ``COLUMNS`` of the
    environment (60 to 1000), else 120."""
    try:
        return max(60, min(int(os.environ.get("COLUMNS", "120")), 1000))
    except ValueError:
        return 120


def terminal_width() -> int:
    """The width of a table printed to standard output: the terminal's when it is one (or
    ``COLUMNS``), else :func:`default_width`."""
    import shutil
    import sys

    if sys.stdout.isatty():
        return max(20, shutil.get_terminal_size((120, 40)).columns)
    return default_width()


def grid_text(heads: list[str], body: list[list[str]], width: int | None = None,
              right: set = frozenset(), whole: set = frozenset()) -> str:
    """Plain cells as :func:`grid` tables, as text without colour or trailing blanks."""
    from rich.console import Console
    from rich.text import Text

    width = terminal_width() if width is None else width
    buf = io.StringIO()
    console = Console(file=buf, force_terminal=False, no_color=True, width=width,
                      highlight=False, emoji=False, soft_wrap=False)
    cells = [[Text(escape_controls(c)) for c in row] for row in body]
    for i, tab in enumerate(grid(Text(""), heads, cells, width, right=right, whole=whole)):
        if i:
            console.print()
        console.print(tab)
    return "\n".join(line.rstrip() for line in buf.getvalue().split("\n"))


def to_table(results: list[Result], color: bool, width: int | None = None) -> str:
    """Rich tables; ``color`` only on a terminal."""
    from rich.console import Console
    from rich.table import Table
    from rich.text import Text

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
