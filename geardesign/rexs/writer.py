"""The drive spec as TOML text: tables and ``key = value`` lines, each with the source of
its value in a comment."""

from __future__ import annotations

from geardesign.core.text import escape_controls, toml_string


def fmt(x: float) -> str:
    """A number as TOML: integers without noise, others to 10 significant digits."""
    if float(x).is_integer() and abs(x) < 1e15:
        return f"{x:.1f}"
    return f"{x:.10g}"


def _q(s: str) -> str:
    """A TOML string (:func:`geardesign.core.text.toml_string`)."""
    return toml_string(str(s))


def _note(text: str) -> str:
    """A comment's text on one line: controls (a line break), bidi overrides and lone
    surrogates escaped (:func:`geardesign.core.text.escape_controls`), so that no text of
    a model or a file name ends the comment and writes TOML of its own."""
    return escape_controls(str(text))


class Writer:
    def __init__(self):
        self.lines: list[str] = []

    def table(self, name: str, array: bool = False, note: str | None = None) -> None:
        h = f"[[{name}]]" if array else f"[{name}]"
        self.lines.append(h + (f"  # {_note(note)}" if note else ""))

    def kv(self, key: str, value, source: str | None) -> None:
        if isinstance(value, bool):
            v = "true" if value else "false"
        elif isinstance(value, int):
            v = str(value)
        elif isinstance(value, float):
            v = fmt(value)
        elif isinstance(value, list):
            v = "[" + ", ".join(_q(x) if isinstance(x, str) else
                                "true" if x is True else "false" if x is False else
                                str(x) if isinstance(x, int) else fmt(x)
                                for x in value) + "]"
        else:
            v = _q(value)
        self.lines.append(f"{key} = {v}" + (f"  # {_note(source)}" if source else ""))

    def comment(self, text: str) -> None:
        self.lines.append(f"# {_note(text)}")

    def blank(self) -> None:
        self.lines.append("")
