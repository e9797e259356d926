"""Text that reaches a person: control characters are shown, never obeyed.

Spec files are written by people and by programs; a key, a value or a title may carry a
newline, an ESC sequence or a bidirectional override.  Every human-facing output (input
error lines, the table, Markdown, HTML and CSV reports) passes such text through
:func:`escape_controls`, so that one problem stays one line and no spec can move the
cursor, recolour the terminal or reorder what is shown.
"""

from __future__ import annotations

import math
import re
from typing import Any

_CONTROLS = re.compile(
    "[\x00-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029]")

FORMATS = ("table", "json", "jsonl", "markdown", "csv", "html", "pdf")
"""The report formats (``--format``; :func:`geardesign.core.render.render`)."""


def _escape(m: re.Match) -> str:
    c = m.group(0)
    return f"\\x{ord(c):02x}" if ord(c) < 0x100 else f"\\u{ord(c):04x}"


def escape_controls(s: str) -> str:
    """``s`` with C0/C1 controls, DEL, bidi marks/overrides and line/paragraph separators
    written as ``\\xNN`` / ``\\uNNNN``.

    >>> escape_controls("a\\nb\\x1b[31m")
    'a\\\\x0ab\\\\x1b[31m'
    """
    return _CONTROLS.sub(_escape, s)


def json_text(obj, indent: int | None = None) -> str:
    """``obj`` as JSON (UTF-8 kept, no NaN allowed) with the characters of
    :func:`escape_controls` that JSON itself leaves raw (DEL, C1 controls, bidi marks and
    overrides, line/paragraph separators) written as ``\\uNNNN``: the same string to a
    JSON reader, inert on a terminal."""
    import json

    text = json.dumps(obj, indent=indent, ensure_ascii=False, allow_nan=False)
    return _RAW_IN_JSON.sub(lambda m: f"\\u{ord(m.group(0)):04x}", text)


_RAW_IN_JSON = re.compile("[\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029]")


def fmt(value: Any) -> str:
    """Round a value for display (6 significant digits)."""
    if value is None:
        return "—"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        if value == 0:
            return "0"
        return f"{value:.6g}"
    if isinstance(value, (list, tuple)):
        if len(value) > 8 or any(isinstance(v, (list, tuple)) for v in value):
            return f"[{len(value)} values, see JSON]"
        return ", ".join(fmt(v) for v in value)
    return escape_controls(str(value))


def verdict_line(r) -> str:
    """The one-line verdict of a :class:`~geardesign.core.result.Result`."""
    if r.failed:
        codes = ", ".join(c.code for c in r.failed)
        return f"✘ FAIL: {len(r.failed)} check(s) failed: {codes}"
    extra = f" ({len(r.warnings)} warning(s))" if r.warnings else ""
    return f"✔ PASS: every check passed{extra}"
