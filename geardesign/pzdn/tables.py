"""Data of the pzdn calculator, read once from ``tables.toml`` (sources are named there)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

DATA = Path(__file__).with_name("tables.toml")


@lru_cache(maxsize=1)
def data() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(DATA)


def wire_series() -> tuple[float, ...]:
    """Nominal spring-wire diameters [mm] (GOST 9389-75 table 1)."""
    return tuple(data()["wire"]["diameters"])


def limits() -> dict:
    """Limits and defaults of the spring checks (``[spring_limits]``)."""
    return data()["spring_limits"]


def regression(machine: str = "ko2") -> dict:
    """Coefficients and zero levels of a machine's regression (``[regression.<machine>]``)."""
    return data()["regression"][machine]
