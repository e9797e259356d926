"""Input problems: what makes a spec unusable (exit code 2).

Every problem is reported on one line, ``FILE: key.path = value: what is allowed``.  The
calculators raise :class:`InputError` for rules that involve several keys (for example a
centre distance smaller than the gears allow); the schema layer collects single-key
problems itself.
"""

from __future__ import annotations

from typing import Any

from geardesign.core.records import dataclass
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


class Unusable(Exception):
    """A stage of input checks read a value that is already reported as a problem: its own
    checks depend on that value and are left out of the report (they would follow from the
    first mistake, not from another one)."""


class _Reported:
    """Stands, in a partially validated spec, for a value that is missing or wrong and is
    already reported: any use of it (a comparison, arithmetic, formatting, a key of it)
    raises :class:`Unusable`; ``value is None`` is false (it was given, or is required)."""

    __slots__ = ()

    def _unusable(self, *args, **kwargs):
        raise Unusable()

    __bool__ = __float__ = __int__ = __index__ = __len__ = __iter__ = _unusable
    __eq__ = __ne__ = __lt__ = __le__ = __gt__ = __ge__ = _unusable
    __add__ = __radd__ = __sub__ = __rsub__ = __mul__ = __rmul__ = _unusable
    __truediv__ = __rtruediv__ = __floordiv__ = __rfloordiv__ = __mod__ = __rmod__ = _unusable
    __pow__ = __rpow__ = __neg__ = __pos__ = __abs__ = __round__ = _unusable
    __getitem__ = __contains__ = __format__ = __str__ = _unusable
    get = items = keys = values = _unusable
    __hash__ = _unusable

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        raise Unusable()

    def __repr__(self) -> str:  # pragma: no cover - debugging aid
        return "REPORTED"


REPORTED: Any = _Reported()
"""The value of a key that failed validation, in a partially validated spec."""


class Problems:
    """Input problems of independent stages, collected so that one run reports them all.

    ``stage(fn, *args)`` runs one stage of checks: its :class:`InputError` lines are kept and
    :data:`FAILED` is returned (stages that need its result are then skipped by the caller);
    a stage that reads a value already reported (:class:`Unusable`) is skipped silently.
    ``at(key, value, message)`` adds one problem of a rule checked in place (the rule's
    stage goes on with the next rule).  ``raise_all()`` raises one :class:`InputError` with
    every line, in order, once each; with none, but a stage skipped for a reported value, it
    raises :class:`Unusable` (what follows would need that stage's result).
    """

    FAILED: Any = object()

    def __init__(self, problems: list[Problem] | None = None):
        self.found: list[Problem] = list(problems or ())
        self.skipped = False

    def add(self, problem: Problem) -> None:
        self.found.append(problem)

    def at(self, key: str, value: Any, message: str) -> None:
        self.found.append(Problem(key, message, value))

    def stage(self, fn, *args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except InputError as exc:
            self.found.extend(exc.problems)
        except Unusable:
            self.skipped = True
        return self.FAILED

    def raise_all(self) -> None:
        if self.found:
            lines = {p.line(""): p for p in self.found}
            raise InputError(list(lines.values()))
        if self.skipped:
            raise Unusable()
