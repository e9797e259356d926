"""Unit slips: inputs that are plausible numbers in the wrong unit.

Each numeric key has one fixed unit (DESIGN.md). A value typed in a unit a thousand times
larger (torque in kN·m, power in MW, force in kN, given as N·m, kW, N) is still a valid
number, and the calculation runs: the part is then loaded with a thousandth of the load it
was meant for, and the methods answer with factors and lives far outside their range
(a dynamic factor of 184, a bearing life of 8·10¹⁴ h). The large side (σ_H above three times
σ_Hlim) is guarded by each calculator's stress checks; this module holds the small side,
one rule for every calculator:

* a calculator states the fraction of its capacity the load uses (stress ratio to the
  power that makes it a load ratio, load over load rating), and
* :func:`light_load` turns a fraction below :data:`LIGHT_LOAD_FRACTION` into a ``UNITS_*``
  warning that names the input that probably is in the wrong unit and the value it would
  have in the larger unit (:func:`slip_hint`).

The threshold: a unit slip by 10³ puts the load at about 0.1 % of what the part carries,
two orders of magnitude below any sized design; a design sized for its load uses tens of
per cent of it. A load below 1 % of the capacity is below what the methods are made for:
ISO 6336-1 treats line loads K_A·F_t/b below 100 N/mm as a low-load range of its load
factors ([ISO6336-1] 6.5.3, 9.3.1 eq. (84)), and a rolling bearing loaded below 0.01·C
(ball) or 0.02·C (roller) no longer follows the life equation ([SKFMinLoad]).
"""

from __future__ import annotations

from geardesign.core.result import Check, check

LIGHT_LOAD_FRACTION = 0.01
"""Fraction of the capacity below which a load is taken for a unit slip (see the module
docstring)."""

LARGER_UNIT = {
    "N·m": ("kN·m", 1e3), "N": ("kN", 1e3), "kW": ("MW", 1e3), "W": ("kW", 1e3),
    "mm": ("m", 1e3), "MPa": ("GPa", 1e3),
}
"""Fixed unit → the unit a thousand times larger that a slip on the small side uses, and
the factor between them."""


def slip_hint(key: str, value: float, unit: str) -> str:
    """``"load.torque1 = 0.25 N·m: if kN·m was meant, give 250"``: the input as given and
    the value it would have had in the next larger unit."""
    big, factor = LARGER_UNIT[unit]
    return f"{key} = {value:g} {unit}: if {big} was meant, give {value * factor:g}"


def light_load(code: str, fraction: float, what: str, inputs: list[tuple[str, float, str]],
               source: str = "[SKFMinLoad]; [ISO6336-1] 6.5.3") -> list[Check]:
    """A ``code`` warning (``UNITS_*``) when the load uses less than
    :data:`LIGHT_LOAD_FRACTION` of the capacity, else nothing (no row in a sound report).

    ``fraction``: load over what the part could carry (-); ``what``: the sentence that says
    so, with the numbers (e.g. "the pair carries 0.052 % of its contact capacity (σ_H0 =
    13 MPa against σ_Hlim = 570 MPa)"); ``inputs``: the load inputs
    the user gave as ``(key, value, fixed unit)``, each named with :func:`slip_hint`."""
    if not fraction < LIGHT_LOAD_FRACTION or not inputs:
        return []
    hints = "; ".join(slip_hint(*i) for i in inputs)
    return [check(
        code, False, "warning",
        f"{what}; a design sized for its load uses tens of per cent of its capacity, a load "
        f"typed in a unit a thousand times too small lands here: {hints}",
        "", fraction, LIGHT_LOAD_FRACTION, source)]


def lifted(res, code: str, inputs: list[tuple[str, float, str]], where: str) -> list[Check]:
    """A part's (a drive stage's, a planetary mesh's) ``UNITS_*`` warnings restated for the
    inputs of the whole (``inputs`` as for :func:`light_load`): the part's load is derived
    from them, so they are what the user typed. ``where`` names the part."""
    out = []
    for c in res.checks:
        if c.code.startswith("UNITS_") and not c.passed and isinstance(c.value, float) \
                and c.value < LIGHT_LOAD_FRACTION:
            out += light_load(code, c.value, f"{where} carries {100 * c.value:.2g} % of its "
                              f"capacity (see its {c.code})", inputs, c.source)
    return out[:1]


def given(table: dict | None, keys: dict[str, str], prefix: str) -> list[tuple[str, float, str]]:
    """The load inputs of ``table`` that the user gave, as ``(prefix.key, value, unit)``
    for :func:`light_load`; ``keys`` maps a key to its fixed unit."""
    if not table:
        return []
    return [(f"{prefix}.{k}", float(table[k]), u) for k, u in keys.items()
            if isinstance(table.get(k), (int, float)) and not isinstance(table.get(k), bool)
            and table.get(k) != 0]
