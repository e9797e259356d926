"""Materials of Novikov (DLZ) gear pairs: steel constants and hardness rules
(``novikov.toml``).  The Novikov method (Korotkin 2017) is empirical for steel pairs of at
most 350 HB after run-in; only the surface hardness is an input."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

DATA = Path(__file__).with_name("novikov.toml")


@dataclass(frozen=True)
class NovikovSteel:
    E: float                    # MPa
    nu: float
    hardness_max_HB: float      # scope of the method
    hardness_diff_min_HB: float  # recommended HB1 − HB2 for run-in


@lru_cache(maxsize=1)
def steel() -> NovikovSteel:
    """The steel constants of ``novikov.toml``."""
    from geardesign.core.data import toml_table

    s = toml_table(DATA)["steel"]
    return NovikovSteel(float(s["E"]), float(s["nu"]), float(s["hardness_max_HB"]),
                        float(s["hardness_diff_min_HB"]))
