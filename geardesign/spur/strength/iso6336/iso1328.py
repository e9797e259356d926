"""Flank tolerances of ISO 1328-1:2013 that ISO 6336-1:2019 uses for its load factors.

Each tolerance of flank tolerance class A is the class-5 value times √2^(A − 5), computed
from the actual reference diameter d, normal module m_n and face width b [mm] and rounded
as the standard rounds (≥ 10 µm to 1 µm, 5…10 µm to 0.5 µm, below 5 µm to 0.1 µm).
Results in µm.  ISO 1328-1:2013 clause 5.3 (Table 1 formulas).

Written with :mod:`geardesign.core.xp`: d, m_n, b, α_t may be numbers or numpy arrays (the
sweep kernel); the class A is one integer.
"""

from __future__ import annotations

import math

from geardesign.core import xp


def _step(A: int) -> float:
    return math.sqrt(2.0) ** (A - 5)


def rounded(value: float) -> float:
    """The ISO 1328-1:2013 rounding of a tolerance [µm] (clause 5.2)."""
    return xp.where(value >= 10.0, xp.rnd(value),
                    xp.where(value >= 5.0, xp.rnd(value * 2.0) / 2.0, xp.rnd(value, 1)))


def single_pitch(d: float, m_n: float, A: int) -> float:
    """Single pitch tolerance f_pT = (0.001d + 0.4m_n + 5)·√2^(A−5) [µm].

    >>> single_pitch(341.183, 14.0, 6)
    15.0
    """
    return rounded((0.001 * d + 0.4 * m_n + 5.0) * _step(A))


def profile_form(d: float, m_n: float, A: int) -> float:
    """Profile form tolerance f_fαT = (2.5√m_n + 0.17√d + 0.5)·√2^(A−5) [µm]."""
    return rounded((2.5 * xp.sqrt(m_n) + 0.17 * xp.sqrt(d) + 0.5) * _step(A))


def helix_total(d: float, b: float, A: int) -> float:
    """Total helix tolerance F_βT = (0.1√d + 0.63√b + 4.2)·√2^(A−5) [µm]."""
    return rounded((0.1 * xp.sqrt(d) + 0.63 * xp.sqrt(b) + 4.2) * _step(A))


def helix_slope(d: float, b: float, A: int) -> float:
    """Helix slope tolerance f_HβT = (0.07√d + 0.45√b + 3)·√2^(A−5) [µm]."""
    return rounded((0.07 * xp.sqrt(d) + 0.45 * xp.sqrt(b) + 3.0) * _step(A))


def base_pitch(d: float, m_n: float, alpha_t: float, A: int) -> float:
    """Transverse base pitch deviation f_pb [µm] used by ISO 6336-1:2019 for K_v and K_Hα:
    the single pitch tolerance projected on the line of action, f_pT·cos α_t (α_t [rad])."""
    return single_pitch(d, m_n, A) * xp.cos(alpha_t)
