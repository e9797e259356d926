"""Typesetting of symbols, units and numbers for the HTML report.

Symbols are written in ASCII in the result (``K_Hbeta``, ``S_H,st1``, ``sigma_Hlim``):
the part after the first underscore is a subscript and Greek names become letters.
Units are written as the JSON document has them (``mm^2/s``, ``min^-1``, ``kg*m^2``)
and printed as an engineer writes them (mm²/s, min⁻¹, kg·m²).  Numbers are rounded to
the precision of their unit (:data:`DECIMALS`) and keep at least :data:`SIGNIFICANT`
significant digits.  The printing rules are those of [ISO80000-1] clause 7 (subscripts of
quantity symbols, the half-high dot of a product of units, powers as superscripts); the
gear symbols themselves are those of the standards cited in each row ([ISO21771]).
"""

from __future__ import annotations

import math
import re
from html import escape
from typing import Any

from geardesign.core.text import escape_controls

GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "eps": "ε",
    "zeta": "ζ", "theta": "θ", "eta": "η", "lambda": "λ", "kappa": "κ", "mu": "μ",
    "nu": "ν", "xi": "ξ", "pi": "π", "rho": "ρ", "sigma": "σ", "tau": "τ", "phi": "φ",
    "chi": "χ", "psi": "ψ", "omega": "ω", "Delta": "Δ", "Sigma": "Σ", "Omega": "Ω",
    "Phi": "Φ", "Psi": "Ψ", "Theta": "Θ", "Gamma": "Γ", "Lambda": "Λ",
}
"""ASCII names of Greek letters as they appear in result keys and symbols."""

_NAMES = "|".join(sorted(GREEK, key=len, reverse=True))
_GREEK_IN_SUB = re.compile(rf"(?:(?<=^)|(?<=[A-Z0-9,]))({_NAMES})(?![a-z])")

SUPERSCRIPT = str.maketrans("0123456789-+", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺")


def e(x: Any) -> str:
    """Any text for HTML: control characters shown (never obeyed), markup escaped."""
    return escape(escape_controls(str(x)))


def symbol_html(sym: str) -> str:
    """``K_Hbeta`` → K<sub>Hβ</sub>; ``sigma_Hlim`` → σ<sub>Hlim</sub>; a symbol that is
    already typeset (``σ_H``) gets its subscript the same way, and each term of a ratio or
    product (``b_w/d_w1``) its own.  Escaped."""
    terms = _OPERATORS.split(escape_controls(str(sym)))
    return "".join(escape(t) if i % 2 else _term_html(t) for i, t in enumerate(terms))


_OPERATORS = re.compile(r"([/·*() ]+)")


_GREEK_BASE = re.compile(rf"^({_NAMES})(\d*)$")
_WORD = re.compile(r"^[a-z]{4,}\d*$")


def _term_html(sym: str) -> str:
    base, sep, sub = sym.partition("_")
    m = _GREEK_BASE.match(base)
    if m:
        base = GREEK[m.group(1)] + m.group(2)
    elif _WORD.match(base):          # a key used as its own symbol ("rotation_ring")
        return escape(sym)
    if not sep or not sub:
        return escape(base + sep)
    sub = _GREEK_IN_SUB.sub(lambda m: GREEK[m.group(1)], sub)
    return f"{escape(base)}<sub>{escape(sub)}</sub>"


UNIT_WORDS = {"-": "", "deg": "°", "MPa^0.5": "√MPa", "N·m*s/rad": "N·m·s/rad"}
"""Units printed otherwise than by the general rules of :func:`unit_text`."""


def unit_text(unit: str | None) -> str:
    """A unit as printed: ``mm^2/s`` → mm²/s, ``min^-1`` → min⁻¹, ``kg*m^2`` → kg·m²,
    ``deg`` → °, the dimensionless ``-`` → nothing (plain text, not escaped)."""
    if unit is None:
        return ""
    unit = str(unit)
    if unit in UNIT_WORDS:
        return UNIT_WORDS[unit]
    unit = unit.replace("*", "·")
    return re.sub(r"\^([-+]?\d+)(?![\d.])", lambda m: m.group(1).translate(SUPERSCRIPT), unit)


def unit_html(unit: str | None) -> str:
    """:func:`unit_text`, escaped; a fractional power (``s^0.5``) as <sup>."""
    text = escape(escape_controls(unit_text(unit)))
    return re.sub(r"\^([-+]?[\d.]+)", r"<sup>\1</sup>", text)


DECIMALS = {
    "mm": 3, "µm": 1, "MPa": 1, "N": 1, "N·m": 2, "deg": 3, "arcmin": 2, "min^-1": 2,
    "Hz": 2, "m/s": 3, "h": 0, "kW": 3, "W": 1, "rad/s": 3, "N/mm": 1, "°C": 1, "%": 2,
    "mm^2/s": 1, "s": 4, "kg": 3, "HB": 0, "HV": 0, "HRC": 1, "-": 3, "N·m/rad": 0,
    "kg*m^2": 5, "mPa·s": 2, "K": 1, "l": 3, "m^2": 3, "m²": 3, "mm^4": 0, "mm^3": 0,
}
"""Decimals shown per unit (a unit not listed: :data:`SIGNIFICANT` digits)."""

SIGNIFICANT = 4
"""Significant digits kept at least: a small value is never shown as 0.000."""


def number_parts(value: float | int, unit: str | None) -> tuple[str, str]:
    """``value`` rounded for its unit, split at the decimal point: ``("147", ".500")``.
    Very large or small magnitudes in scientific notation (``("1.234", "e-09")``)."""
    if isinstance(value, bool):
        return ("yes" if value else "no", "")
    if isinstance(value, int):
        return (str(value), "")
    if not math.isfinite(value):
        return ("—", "")
    if value == 0:
        return ("0", "")
    mag = math.floor(math.log10(abs(value)))
    if mag >= 12 or mag < -6:
        text = f"{value:.{SIGNIFICANT - 1}e}"
        mant, _, exp = text.partition("e")
        i, _, f = mant.partition(".")
        return (i, "." + f + "e" + exp) if f else (i, "e" + exp)
    dec = DECIMALS.get(unit or "-", None)
    need = max(0, SIGNIFICANT - 1 - mag)
    dec = need if dec is None else max(dec, min(need, 8))
    text = f"{value:.{dec}f}"
    i, _, f = text.partition(".")
    return (i, "." + f if f else "")


def number_text(value: float | int, unit: str | None = None) -> str:
    i, f = number_parts(value, unit)
    return i + f
