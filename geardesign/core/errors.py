"""Input problems: what makes a spec unusable (exit code 2).

Every problem is reported on one line, ``FILE: key.path = value: what is allowed``.  The
calculators raise :class:`InputError` for rules that involve several keys (for example a
centre distance smaller than the gears allow); the schema layer collects single-key
problems itself.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from geardesign.core.text import escape_controls

_MISSING = object()


def format_value(value: Any) -> str:
    """Show a value the way it would be written in TOML."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        if len(value) > 60:
            value = value[:57] + "..."
        return '"' + escape_controls(value.replace("\\", "\\\\").replace('"', '\\"')) + '"'
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, dict):
        return "{...}"
    if isinstance(value, list):
        if len(value) <= 6 and not any(isinstance(v, (dict, list)) for v in value):
            return "[" + ", ".join(format_value(v) for v in value) + "]"
        return f"[... {len(value)} items]"
    return str(value)


@dataclass(frozen=True)
class Problem:
    """One reason why an input cannot be used.

    ``key`` is the dotted key path (``gear.z1``); ``value`` the offending value, or
    ``Problem.NO_VALUE`` when the key is missing or the problem concerns the whole file.
    """

    key: str
    message: str
    value: Any = _MISSING

    NO_VALUE = _MISSING

    def line(self, source: str) -> str:
        """The problem as one line: control characters of the file name, key, value and
        message are escaped (:func:`geardesign.core.text.escape_controls`)."""
        where = f"{escape_controls(source)}: " if source else ""
        key, message = escape_controls(self.key), escape_controls(self.message)
        if not self.key:
            return f"{where}{message}"
        if self.value is _MISSING:
            return f"{where}{key}: {message}"
        return f"{where}{key} = {format_value(self.value)}: {message}"


class InputError(Exception):
    """The input cannot be used; carries one or more :class:`Problem` lines."""

    def __init__(self, problems: list[Problem] | Problem):
        self.problems = [problems] if isinstance(problems, Problem) else list(problems)
        super().__init__("; ".join(p.line("") for p in self.problems))

    @classmethod
    def at(cls, key: str, value: Any, message: str) -> "InputError":
        return cls(Problem(key, message, value))
