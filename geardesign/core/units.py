"""Quantities with units in a spec (``module = "4 mm"``, ``torque1 = "520 kN*mm"``).

Each numeric key has one fixed unit (DESIGN.md); a string with a unit is converted to it
at the input boundary, through pint (the optional ``units`` extra), and everything after
that — the calculation, the JSON document — sees the fixed unit only.
"""

from __future__ import annotations

from functools import lru_cache

PINT_NAMES = {
    "mm": "mm", "µm": "micrometer", "um": "micrometer", "deg": "degree", "N": "newton",
    "N·m": "newton * meter", "N*m": "newton * meter", "N·m/rad": "newton * meter / radian",
    "N*m/rad": "newton * meter / radian", "N/mm": "newton / mm", "MPa": "megapascal",
    "min^-1": "1 / minute", "kW": "kilowatt", "h": "hour", "s": "second", "kg": "kilogram",
    "kg*m^2": "kilogram * meter ** 2", "m/s": "meter / second", "mm^2/s": "mm ** 2 / second",
    "°C": "degC", "m^2": "meter ** 2", "l": "liter", "kg/m^3": "kilogram / meter ** 3",
    "W": "watt",
}
"""The fixed units of the spec fields in pint's spelling."""


@lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def convert(text: str, unit: str) -> tuple[float | None, str | None]:
    """``(value in unit, None)`` or ``(None, why not)`` for a quantity written as text."""
    if unit not in PINT_NAMES:
        return None, "a plain number (this quantity takes no unit)"
    try:
        ureg = _registry()
    except ImportError:
        return None, ("a number; quantities with units need the units extra: "
                      "pip install \"geardesign[units]\"")
    try:
        q = ureg.Quantity(text)
        if not hasattr(q, "to"):
            return None, f"a quantity in {unit} like \"4 {unit}\""
        value = float(q.to(PINT_NAMES[unit]).magnitude)
    except Exception as exc:  # pint raises several unrelated types for bad text
        name = type(exc).__name__
        if name == "DimensionalityError":
            return None, f"a quantity convertible to {unit} (\"{text}\" has another dimension)"
        return None, f"a quantity in {unit} like \"4 {unit}\" (\"{text}\" is not understood)"
    return value, None
