"""Basic racks of Novikov DLZ gears (data in ``racks.toml``) and the module series."""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

DATA = Path(__file__).with_name("racks.toml")
STANDARD = "GOST 15023-76"


@dataclass(frozen=True)
class NovikovRack:
    """Constants of a Novikov DLZ basic rack (module-independent, in units of m).

    Parameters
    ----------
    name : rack name (``"GOST 15023-76"`` or ``"custom"``).
    alpha_k : profile angle at the nominal contact point [rad].
    lk_star : l_k*, length of the active part of the addendum along its chord, / m.
    eps_q : ε_q = q/p_x, the axial offset of the two contact points of one tooth in axial
        pitches ("phase coefficient of axial overlap"); a rack constant ([Korotkin2017]).
    h_a, h_f : addendum and dedendum coefficients h_a*, h_f*.
    verified : whether the values were checked against the standard's text.
    """

    name: str
    alpha_k: float
    lk_star: float
    eps_q: float
    h_a: float
    h_f: float
    verified: bool = False

    @property
    def delta(self) -> float:
        """δ: distance of ε_q to the nearest integer (0 ≤ δ ≤ 0.5), the quantity that the
        minimum face width criteria of Cyclogram 2017 depend on."""
        frac = self.eps_q - math.floor(self.eps_q)
        return min(frac, 1.0 - frac)


@lru_cache(maxsize=1)
def library() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(DATA)


def standard_rack(name: str = STANDARD) -> NovikovRack:
    """The rack ``name`` from ``racks.toml``."""
    r = library()[name]
    return NovikovRack(name, math.radians(r["profile_angle"]), r["lk_star"], r["eps_q"],
                       r["addendum_coef"], r["dedendum_coef"], r["verified"])


def module_range(name: str = STANDARD) -> tuple[float, float]:
    """Module range [mm] of the standard rack (scope of GOST 15023-76, from memory)."""
    lo, hi = library()[name]["module_range"]
    return float(lo), float(hi)


def module_series() -> tuple[tuple[float, ...], tuple[float, ...]]:
    """First and second series of preferred modules (GOST 14186-69, from memory)."""
    s = library()["modules"]
    return tuple(s["series1"]), tuple(s["series2"])
