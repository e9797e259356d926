"""Parallel keys: bearing pressure on the flanks and shear of the key.

* effective (bearing) length l_p: form A (both ends round) l − b, form B (square ends) l,
  form C (one round end) l − b/2 ([GOST23360]; [DIN6892] supporting length l_tr);
* bearing pressure p = 2·T/(d·l_p·k·n_eff) with the engaged height k of the flank:
  GOST practice k = h − t1 for the hub side (the smaller flank) ([Ivanov] ch. 6,
  [Dunaev] ch. 6); DIN 6892 method C: hub side h − t1, shaft side t1 ([DIN6892]);
* shear of the key τ = 2·T/(d·b·l_p·n_eff) ([Ivanov] ch. 6);
* n_eff: 1 for one key, 1.5 for two keys ([DIN6892] φ = 0.75; ``tables.toml``).

Units: T in N·mm, lengths in mm, stresses in MPa.
"""

from __future__ import annotations

import math

FORMS = ("A", "B", "C")


def bearing_length(l: float, b: float, form: str) -> float:
    """Effective length l_p [mm] of a key of length ``l`` and width ``b``.

    >>> bearing_length(56.0, 12.0, "A"), bearing_length(56.0, 12.0, "B"), bearing_length(56.0, 12.0, "C")
    (44.0, 56.0, 50.0)
    """
    return {"A": l - b, "B": l, "C": l - 0.5 * b}[form]


def pressure(T: float, d: float, l_p: float, k: float, n_eff: float = 1.0) -> float:
    """Bearing pressure p = 2·T/(d·l_p·k·n_eff) [MPa]; T [N·mm], d, l_p, k [mm].

    >>> round(pressure(200e3, 40.0, 44.0, 3.0), 2)
    75.76
    """
    return 2.0 * T / (d * l_p * k * n_eff)


def shear(T: float, d: float, b: float, l_p: float, n_eff: float = 1.0) -> float:
    """Shear stress of the key τ = 2·T/(d·b·l_p·n_eff) [MPa]."""
    return 2.0 * T / (d * b * l_p * n_eff)


def required_bearing_length(T: float, d: float, k: float, p_allow: float,
                            n_eff: float = 1.0) -> float:
    """The least l_p [mm] at which p = p_allow (the pressure formula solved for l_p)."""
    return 2.0 * T / (d * k * p_allow * n_eff)


def length_for(l_p: float, b: float, form: str) -> float:
    """The key length l [mm] that gives the bearing length ``l_p`` (inverse of
    :func:`bearing_length`)."""
    return {"A": l_p + b, "B": l_p, "C": l_p + 0.5 * b}[form]


def standard_length(l_min: float, lengths: tuple[float, ...]) -> float:
    """The shortest standard length >= ``l_min`` (``math.inf`` when none is long enough)."""
    for v in lengths:
        if v >= l_min - 1e-9:
            return v
    return math.inf
