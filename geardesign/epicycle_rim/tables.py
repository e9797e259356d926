"""The data tables of the calculator (``tables.toml`` beside this module), read once."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path


@lru_cache(maxsize=None)
def _data() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("tables.toml"))


def loading_modes() -> dict[str, dict]:
    """GOST 21354-87 typical loading modes: ``{key: {"K_FE_6", "K_FE_9", "name"}}``."""
    return _data()["loading_modes"]


def mode_K_FE(mode: str, q_F: int) -> float:
    """Equivalence factor K_FE of a typical loading mode for the exponent q_F (6 or 9)."""
    return loading_modes()[mode][f"K_FE_{q_F}"]
