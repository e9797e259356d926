"""Involute splines with 30° pressure angle ([DIN5480], [GOST6033]): geometry from the
designation and the mean flank pressure.

Geometry ([DIN5480]): reference diameter d = m·z, profile shift from
d_B = m·z + 2·x·m + 1.1·m, tip diameter of the shaft d_a1 = d_B − 0.2·m, tip diameter of the
hub d_a2 = d_B − 2·m; bearing height h_w = (d_a1 − d_a2)/2 = 0.9·m and mean diameter
d_m = (d_a1 + d_a2)/2 = d_B − 1.1·m ([DIN5466]).  The GOST practice takes h_w = 0.8·m and
d_m = m·z ([Ivanov] ch. 6).

Flank pressure p = 2·T·K_A/(d_m·z·h_w·l·ψ) with the load-distribution factor ψ ≈ 0.75
([DIN5466]; [Ivanov] ch. 6, ψ = 0.7...0.8).
"""

from __future__ import annotations

from geardesign.core.records import dataclass

X_RANGE = (-0.05, 0.45)
"""Profile shift coefficients of the [DIN5480] series."""


@dataclass(frozen=True)
class Geometry:
    d_B: float
    m: float
    z: int
    d: float
    x: float
    d_a1: float
    d_a2: float
    h_w: float
    d_m: float


def geometry(d_B: float, m: float, z: int, method: str = "DIN") -> Geometry:
    """Spline geometry [mm] by [DIN5480]; ``method="GOST"`` takes h_w and d_m of [Ivanov].

    >>> g = geometry(40.0, 2.0, 18)
    >>> (g.d, round(g.x, 3), g.d_a1, g.d_a2, round(g.h_w, 3), round(g.d_m, 3))
    (36.0, 0.45, 39.6, 36.0, 1.8, 37.8)
    """
    d = m * z
    x = (d_B - d - 1.1 * m) / (2.0 * m)
    d_a1 = d_B - 0.2 * m
    d_a2 = d_B - 2.0 * m
    if method == "GOST":
        h_w, d_m = 0.8 * m, d
    else:
        h_w, d_m = 0.5 * (d_a1 - d_a2), 0.5 * (d_a1 + d_a2)
    return Geometry(d_B, m, z, d, x, d_a1, d_a2, h_w, d_m)


def pressure(T: float, d_m: float, z: int, h_w: float, l: float, psi: float) -> float:
    """Mean flank pressure p = 2·T/(d_m·z·h_w·l·ψ) [MPa]; T [N·mm] (with K_A), lengths [mm].

    >>> round(pressure(500e3, 37.8, 18, 1.8, 30.0, 0.75), 2)
    36.29
    """
    return 2.0 * T / (d_m * z * h_w * l * psi)


def required_length(T: float, d_m: float, z: int, h_w: float, psi: float,
                    p_allow: float) -> float:
    """The least engaged length l [mm] at which p = p_allow."""
    return 2.0 * T / (d_m * z * h_w * psi * p_allow)
