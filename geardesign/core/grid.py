"""The columns of a terminal table: widths that fit the terminal, groups of columns when
they do not, and the borderless rich tables of the ``table`` report
(:func:`geardesign.core.render.to_table`) and of ``geardesign materials``/``bearings``.
rich is imported only when a table is drawn."""

from __future__ import annotations

import io
import os
import textwrap

from geardesign.core.text import escape_controls


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
