"""Formulas of an internal spur or helical pair (GOST 19274-73 sign, see
:mod:`geardesign.gears.internal`): the working pressure angle from x2 − x1, the tip
interference of two internal-mesh tip circles and the tip thickness of an internal tooth.

Pure functions on plain numbers.  Lengths in mm, angles in radians.
"""

from __future__ import annotations

import math

from geardesign.gears.geometry import GeometryError
from geardesign.involute import inv, inv_inverse


def working_pressure_angle(x_diff: float, z1: int, z2: int, alpha_n: float,
                           alpha_t: float) -> float:
    """Working transverse pressure angle of an internal pair from x2 − x1.

    .. math:: \\operatorname{inv} α_{tw} = \\frac{2 (x_2 - x_1) \\tan α}{z_2 - z_1}
              + \\operatorname{inv} α_t

    (ISO 21771 writes the same with z2 < 0 and x2_ISO = −x2.)

    Raises
    ------
    GeometryError ``INV_ALPHA_TW`` if inv α_tw <= 0 (x2 − x1 too negative); its ``limit``
    is the least x2 − x1.

    References: GOST 19274-73 (x_d given); [GOST19274]; paper (b) eq. (21).

    Example: with x2 − x1 = 0 the pair works at the rack's angle, α_tw = α_t (identity):

    >>> import math
    >>> a = math.radians(20.0)
    >>> abs(working_pressure_angle(0.0, 20, 60, a, a) - a) < 1e-12
    True
    """
    if z2 <= z1:
        raise GeometryError("TEETH_DIFFERENCE", f"z2 = {z2} <= z1 = {z1}: no internal pair",
                            z2, z1)
    value = 2.0 * x_diff * math.tan(alpha_n) / (z2 - z1) + inv(alpha_t)
    if value <= 0.0:
        limit = -inv(alpha_t) * (z2 - z1) / (2.0 * math.tan(alpha_n))
        raise GeometryError("INV_ALPHA_TW", f"inv α_tw = {value:.6g} <= 0", x_diff, limit)
    return inv_inverse(value)


def tip_interference(z1: int, z2: int, r_a1: float, r_a2: float, r_b1: float, r_b2: float,
                     a_w: float, alpha_tw: float) -> float | None:
    """Interference of the tooth tips of an internal pair outside the line of action
    (the trochoid of the pinion tip crossing the internal tooth's tip corner).

    .. math::
        δ = z_1(\\operatorname{inv} α_{a1} + ν_1) + (z_2 - z_1)\\operatorname{inv} α_{tw}
            - z_2(\\operatorname{inv} α_{a2} + ν_2) \\ge 0,

        \\cos ν_1 = \\frac{r_{a2}^2 - r_{a1}^2 - a_w^2}{2 r_{a1} a_w}, \\quad
        \\cos ν_2 = \\frac{r_{a2}^2 - r_{a1}^2 + a_w^2}{2 r_{a2} a_w}

    ν1, ν2 are the angles at the two centres of the point where the tip circles cross.
    Used both for the working pair and for the cutter–ring pair (cutting of the ring tips).

    Returns δ [rad·teeth]; ``None`` when the tip circles do not cross (no interference
    possible).  The form is the handbook one (Kudryavtsev; GOST 19274-73 quoted from
    memory in [Kudryavtsev], not verified against the standard's text); a
    brute-force simulation of the tip paths agrees in sign on every case tried
    (``tests/test_planetary_internal.py``).
    """
    c1 = (r_a2 * r_a2 - r_a1 * r_a1 - a_w * a_w) / (2.0 * r_a1 * a_w)
    c2 = (r_a2 * r_a2 - r_a1 * r_a1 + a_w * a_w) / (2.0 * r_a2 * a_w)
    if not (-1.0 <= c1 <= 1.0 and -1.0 <= c2 <= 1.0):
        return None
    nu1, nu2 = math.acos(c1), math.acos(c2)
    alpha_a1 = math.acos(min(r_b1 / r_a1, 1.0))
    alpha_a2 = math.acos(min(r_b2 / r_a2, 1.0))
    return (z1 * (inv(alpha_a1) + nu1) + (z2 - z1) * inv(alpha_tw)
            - z2 * (inv(alpha_a2) + nu2))


def internal_tip_thickness(d_a: float, z: int, x: float, alpha_n: float, alpha_t: float,
                           beta: float, d: float, d_b: float) -> float:
    """Normal tooth thickness at the tip circle of an internal gear (GOST 19274-73 sign).

    .. math:: s_{an} = d_a\\Big[\\frac{π/2 - 2x\\tan α}{z} - \\operatorname{inv} α_t
              + \\operatorname{inv} α_a\\Big]\\cos β_a,\\quad \\cos α_a = d_b/d_a,\\quad
              \\tan β_a = \\tan β\\, d_a/d

    The internal tooth widens outwards, hence the signs opposite to the external form.
    References: paper (b) eq. (36) ([Matusevich2017]); GOST 19274-73.  KISSsoft
    prints 38.407 mm for the NREL stage-1 ring (z = 56, x = 0.5013).
    """
    alpha_a = math.acos(min(d_b / d_a, 1.0))
    beta_a = math.atan(math.tan(beta) * d_a / d)
    return d_a * ((0.5 * math.pi - 2.0 * x * math.tan(alpha_n)) / z - inv(alpha_t)
                  + inv(alpha_a)) * math.cos(beta_a)
