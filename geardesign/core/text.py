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
from functools import lru_cache
from typing import Any

_CONTROLS = re.compile(
    "[\x00-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029"
    "\ud800-\udfff]")

FORMATS = ("table", "json", "jsonl", "markdown", "csv", "html", "pdf")
"""The report formats (``--format``; :func:`geardesign.core.render.render`)."""


def _escape(m: re.Match) -> str:
    c = m.group(0)
    return f"\\x{ord(c):02x}" if ord(c) < 0x100 else f"\\u{ord(c):04x}"


def escape_matching(s: str, pattern: re.Pattern) -> str:
    """``s`` with each character ``pattern`` matches written as ``\\xNN`` / ``\\uNNNN``
    (the escape of :func:`escape_controls`, for another set of characters)."""
    return pattern.sub(_escape, s)


def escape_controls(s: str) -> str:
    """``s`` with C0/C1 controls, DEL, bidi marks/overrides, line/paragraph separators and
    lone surrogates (the bytes of a file name that is not UTF-8, as Python decodes it: no
    encoder writes them) written as ``\\xNN`` / ``\\uNNNN``.

    >>> escape_controls("a\\nb\\x1b[31m")
    'a\\\\x0ab\\\\x1b[31m'
    """
    return _CONTROLS.sub(_escape, s)


_TOML_RAW = re.compile('["\\\\\x00-\x1f\x7f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029'
                       '\ud800-\udfff]')


def _toml_escape(m: re.Match) -> str:
    c = m.group(0)
    if c in '"\\':
        return "\\" + c
    if "\ud800" <= c <= "\udfff":          # no TOML string holds it: its escape as text
        return "\\" + _escape(m)
    return f"\\u{ord(c):04x}"


def toml_string(s: str) -> str:
    """``s`` as a TOML basic string [TOML] ("String"): ``"`` and ``\\`` escaped; control
    characters, DEL, bidi marks and overrides and line/paragraph separators as
    ``\\uXXXX`` (the same string to a TOML reader, inert in an editor and never a line
    break of the file); a lone surrogate (a file name that is not UTF-8), which no TOML
    string can hold, as the text ``\\udcXX``.  The one writer of TOML strings (the sweep's
    ``--emit-spec``, the REXS import).

    >>> print(toml_string('a "b"\\nc\\\\d'))
    "a \\"b\\"\\u000ac\\\\d"
    """
    return '"' + _TOML_RAW.sub(_toml_escape, s) + '"'


def json_text(obj, indent: int | None = None) -> str:
    """``obj`` as JSON (UTF-8 kept, no NaN allowed) with the characters of
    :func:`escape_controls` that JSON itself leaves raw (DEL, C1 controls, bidi marks and
    overrides, line/paragraph separators) written as ``\\uNNNN``: the same string to a
    JSON reader, inert on a terminal.

    The text is that of ``json.dumps(obj, indent=indent, ensure_ascii=False,
    allow_nan=False)``; with an ``indent``, plain JSON data (dicts with string keys, lists,
    tuples, strings, numbers, booleans, ``None``) is written by :func:`_indented`, which
    the standard library does in pure Python (its C encoder only writes without indent);
    anything else, and every error, is the standard library's own.

    >>> print(json_text({"a": [1, 2.5], "b": {}, "c": {"d": None}}, indent=1))
    {
     "a": [
      1,
      2.5
     ],
     "b": {},
     "c": {
      "d": null
     }
    }
    """
    if indent is not None and type(indent) is int:
        try:
            return _indented(obj, indent)
        except (_NotPlain, ValueError, RecursionError):
            pass        # the standard library writes it or says what is wrong
    import json

    return _raw_escaped(json.dumps(obj, indent=indent, ensure_ascii=False, allow_nan=False))


_RAW_IN_JSON = re.compile("[\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069\u2028\u2029"
                          "\ud800-\udfff]")


def _raw_escaped(text: str) -> str:
    """``text`` with the characters of :data:`_RAW_IN_JSON` written as ``\\uNNNN``."""
    if text.isascii() and "\x7f" not in text:    # a flag of the string, a memchr: no regex
        return text
    return _RAW_IN_JSON.sub(lambda m: f"\\u{ord(m.group(0)):04x}", text)


class _NotPlain(Exception):
    """Not plain JSON data: :func:`json_text` leaves it to the standard library."""


def _refuse(obj):
    raise _NotPlain


_LEAF = frozenset((str, int, float, bool, type(None)))


@lru_cache(maxsize=None)
def _flat(pad: str):
    """The C encoder of the standard library writing a dict or list of leaves one item a
    line, each line beginning with ``pad`` (a newline and the indent)."""
    from json.encoder import c_make_encoder, encode_basestring

    if c_make_encoder is None:
        raise _NotPlain
    return c_make_encoder(None, _refuse, encode_basestring, None, ": ", "," + pad, False,
                          False, False)


def _indented(obj, indent: int) -> str:
    """``json.dumps(obj, indent=indent, ensure_ascii=False, allow_nan=False)`` with the raw
    characters escaped (:func:`json_text`), for plain JSON data.  A dict or list whose
    values are all leaves, most of a report, is written by the C encoder (:func:`_flat`),
    the nesting around them here; raises :class:`_NotPlain` for anything else, and
    ``ValueError`` for a non-finite number."""
    from json.encoder import encode_basestring

    out: list[str] = []
    add = out.append
    step = " " * indent

    def leaves(text: str) -> None:
        add(_raw_escaped(text))

    def flat(o, values, pad: str, inner: str) -> bool:
        """Write ``o`` by the C encoder if its ``values`` are all leaves."""
        for v in values:
            if type(v) not in _LEAF:
                return False
        text = "".join(_flat(inner)(o, 0))
        leaves(text[0] + inner + text[1:-1] + pad + text[-1])
        return True

    def walk(o, pad: str) -> None:
        inner = pad + step
        if isinstance(o, dict):
            if not o:
                add("{}")
            elif not flat(o, o.values(), pad, inner):
                sep = "{" + inner
                for k, v in o.items():
                    if type(k) is not str:
                        raise _NotPlain
                    leaves(sep + encode_basestring(k) + ": ")
                    sep = "," + inner
                    walk(v, inner)
                add(pad + "}")
        elif isinstance(o, (list, tuple)):
            if not o:
                add("[]")
            elif not flat(o, o, pad, inner):
                sep = "[" + inner
                for v in o:
                    add(sep)
                    sep = "," + inner
                    walk(v, inner)
                add(pad + "]")
        elif type(o) in _LEAF:
            leaves("".join(_flat(inner)(o, 0)))
        else:
            raise _NotPlain

    walk(obj, "\n")
    return "".join(out)


_MD_ACTIVE = str.maketrans({c: "\\" + c for c in "\\<>[]|"})
"""What Markdown would read as markup in a text of the report: a backslash, raw HTML and
autolinks (``<``, ``>``), links and images (``[``, ``]``), a table cell's end (``|``);
each is written with a backslash escape (CommonMark §2.4), which shows the character
itself.  Emphasis (``*``, ``_``) and code spans only change how a text looks."""


def md_escape(text) -> str:
    """``text`` for a Markdown report: controls and bidirectional overrides escaped
    (:func:`geardesign.core.text.escape_controls`), markup characters backslash-escaped
    (:data:`_MD_ACTIVE`), so that a title, a name or a message from a spec or a model shows
    as written and never runs as HTML, a link or an image."""
    return escape_controls(str(text)).translate(_MD_ACTIVE)


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
