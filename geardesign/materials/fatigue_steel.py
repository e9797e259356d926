"""Structural steels with fatigue data (σ_u, σ_y, σ_-1) for endurance calculations of
parts by GOST 25.504-82, read from ``fatigue_steel.toml`` beside this module.

Each grade carries the source of its values; only printed values are listed (the 30KhGSA
entry is the ring-gear steel of Gutyria et al. 2017).  Explicit values in a spec override
the table.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path


@lru_cache(maxsize=None)
def grades() -> dict[str, dict]:
    """All grades: ``{name: {"sigma_u", "sigma_y", "sigma_m1", "hardness", "treatment",
    "source"}}`` (stresses in MPa)."""
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("fatigue_steel.toml"))


def grade(name: str) -> dict:
    """One grade by name (KeyError if unknown)."""
    return grades()[name]
