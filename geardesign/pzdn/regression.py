"""Regression of the maximum dynamic moments of the KO-2 drive lines on the link
stiffness (KO-2 thesis §2.3, [Lopukhov] §2.3).  Pure functions; coefficients
in ``tables.toml`` ``[regression.ko2]``.

The thesis quotes one-factor slices in C12 of a second-order regression fitted by its
ref. [23] to a chain three-mass model with the first mass driving, at the zero levels
T1 = 48.6 N·m, J1 = 0.023 kg·m², C12 = 1940 N·m/rad:

    T12max = a0 + a1·C12 + a2·C12²,    T23max = b0 + b1·C12 + b2·C12²   [N·m]

and uses them at the series stiffness of the PZDN spring and the V-belt drive,
1/C = 1/C_M + 1/C_belt = 1/25 + 1/1940 → C = 24.68 N·m/rad, which lies far from the
design centre (an extrapolation the thesis does not mention).  It prints
T12max(24.7) = 77.906 N·m: the equation gives 79.906 N·m.
"""

from __future__ import annotations

from geardesign.core.records import dataclass


def poly(coef, C: float) -> float:
    """c0 + c1·C + c2·C² ..."""
    return sum(c * C ** j for j, c in enumerate(coef))


@dataclass(frozen=True)
class RegressionPoint:
    C: float
    T12max: float
    T23max: float
    k12: float
    k23: float


def evaluate(C: float, reg: dict, T_ref_12: float, T_ref_23: float) -> RegressionPoint:
    """Moments and dynamic factors k12 = T12max/T_ref12, k23 = T23max/T_ref23 at C [N·m/rad]
    (thesis eqs. (1), (2) and l. 1765-1769; T_ref12 = 26.5, T_ref23 = 17.7 N·m there)."""
    T12, T23 = poly(reg["T12"], C), poly(reg["T23"], C)
    return RegressionPoint(C, T12, T23, T12 / T_ref_12, T23 / T_ref_23)


def fitted_range(reg: dict) -> tuple[float, float]:
    """Range of C12 treated as fitted: C0·(1 ± share) (an assumption; the thesis gives
    only the centre C0 of its rotatable design)."""
    c0, s = reg["C_zero"], reg["range_share"]
    return c0 * (1.0 - s), c0 * (1.0 + s)
