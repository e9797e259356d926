"""Thermal balance of a worm gear unit: steady oil temperature ([Chernavsky], thermal balance;
Dunaev & Lelikov;
Chernavsky)."""

from __future__ import annotations

from geardesign.core.records import dataclass


def housing_area(a_w: float) -> float:
    """Default cooling surface of the housing A ≈ 20·a_w^1.7 [m²], a_w in m ([Chernavsky]; Dunaev &
    Lelikov).

    Example: a_w = 1000 mm (1 m) gives A = 20 m²:

    >>> housing_area(1000.0)
    20.0
    """
    return 20.0 * (a_w / 1000.0) ** 1.7


@dataclass(frozen=True)
class Thermal:
    heat: float        # heat generated Φ [W]
    area: float        # cooling surface A [m²]
    K_T_fan: float | None
    t_oil: float       # steady oil temperature [°C]


def oil_temperature(P1: float, eta: float, t0: float, K_T: float, area: float, psi: float,
                    K_T_fan: float | None = None, fan_share: float = 0.35) -> Thermal:
    """Steady oil temperature [°C].

    .. math:: Φ = 1000\\,(1 - η) P_1, \\qquad
              t_{oil} = t_0 + \\frac{Φ}{K_T A (1 + ψ)}

    With a fan on the worm shaft, the share s of the surface blown by it cools with
    K_T,fan (:func:`geardesign.worm.tables.fan_heat_transfer`):

    .. math:: t_{oil} = t_0 + \\frac{Φ}{A\\,[(1 - s)(1 + ψ) K_T + s K_{T,fan}]}

    P1 in kW, K_T in W/(m² K), A in m², ψ the share of heat taken by the base.  [Chernavsky]; the
    fan form with s = 0.35 (0.65/0.35 split) is from memory of Dunaev & Lelikov,
    textbooks give s = 0.3 ... 0.5.
    """
    heat = 1000.0 * (1.0 - eta) * P1
    if K_T_fan is None:
        t = t0 + heat / (K_T * area * (1.0 + psi))
    else:
        t = t0 + heat / (area * ((1.0 - fan_share) * (1.0 + psi) * K_T + fan_share * K_T_fan))
    return Thermal(heat, area, K_T_fan, t)
