"""The axial load capacity of the ribs of a cylindrical roller bearing (rib and roller
ends, flange strength)."""

from __future__ import annotations

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class RibCapacity:
    F_ap: float          # permissible continuous axial load (rib and roller ends), N
    F_a_max: float       # flange strength limit for a continuous axial load, N
    k1: float
    k2: float

    @property
    def limit(self) -> float:
        return min(self.F_ap, self.F_a_max)


def rib_capacity(C_0r: float, F_r: float, n: float, d: float, D: float, series: str,
                 lubricant: str = "oil") -> RibCapacity:
    """Axial load a single-row cylindrical roller bearing with ribs on both rings (NJ, NUP)
    carries continuously ([SKF6000] p. 518):

    F_ap = k1·C0·10⁴/(n·(d + D)) − k2·F_r   [kN, kN, min⁻¹, mm]; k1 = 1.5, k2 = 0.15 with
    oil, 1 and 0.1 with grease (the base oil's κ >= 2, 60 K above ambient); and never more
    than F_a,max = 0.0045·D^1.5 (diameter series 2) or 0.0023·D^1.7 (other series) [kN, mm].
    Forces in N here; short axial loads may be twice, shocks three times F_ap (not used).

    >>> round(rib_capacity(53000.0, 5000.0, 1500.0, 40.0, 80.0, "2").F_ap)
    3667
    """
    k1, k2 = (1.5, 0.15) if lubricant == "oil" else (1.0, 0.1)
    F_ap = (k1 * (C_0r / 1000.0) * 1.0e4 / (n * (d + D)) - k2 * F_r / 1000.0) * 1000.0
    diameter_series_2 = series in ("2", "22")
    F_a_max = (0.0045 * D ** 1.5 if diameter_series_2 else 0.0023 * D ** 1.7) * 1000.0
    return RibCapacity(max(F_ap, 0.0), F_a_max, k1, k2)
