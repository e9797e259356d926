"""Geometry of an external spur or helical involute gear pair (GOST 16532-70).

Pure functions on plain data.  Lengths in mm, angles in radians.  Index 1 is the pinion,
2 the wheel.  The spur, planetary, PZDN, worm, bevel and drive calculators call these
functions for every external mesh; nothing here knows about spec files.  The span (base
tangent length) is :mod:`geardesign.gears.span`, the internal pair
:mod:`geardesign.gears.internal`.

References
----------
GOST 16532-70 "Cylindrical involute external gear pairs. Calculation of geometry";
GOST 13755-81 basic rack; ISO 21771:2007 (same quantities, ISO notation);
[GOST16532] table 1; [ZPCIL] GEOM.h.
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core import xp
from geardesign.core.records import dataclass
from geardesign.gears.span import choose_span_teeth
from geardesign.involute import inv, inv_inverse, inv_inverse_array


class GeometryError(ValueError):
    """The input admits no gear pair (e.g. inv α_tw <= 0, tip inside the base circle).

    ``code`` names the rule; the calculator turns it into an input error naming the keys.
    """

    def __init__(self, code: str, message: str, value: float | None = None,
                 limit: float | None = None):
        super().__init__(message)
        self.code = code
        self.value = value
        self.limit = limit


STEEL_DENSITY = 7850.0
"""Density of steel [kg/m³] for the estimated masses of gear bodies (the shaft calculator's
default too)."""


def disc_volume(d, b):
    """Volume [mm³] of a solid disc of diameter d and width b [mm], π/4·d²·b (a gear body
    estimated at its reference or pitch diameter); numbers or arrays."""
    return math.pi / 4.0 * d * d * b


def disc_mass(d, b, density: float = STEEL_DENSITY):
    """Mass [kg] of that disc: ``density`` [kg/m³]·:func:`disc_volume`·10⁻⁹."""
    return density * disc_volume(d, b) * 1e-9


@dataclass(frozen=True)
class BasicRack:
    """Basic rack profile (GOST 13755-81: α = 20°, h_a* = 1, c* = 0.25, ρ_f* = 0.38).

    Parameters
    ----------
    alpha_n : profile (normal pressure) angle α [rad].
    h_a : addendum coefficient h_a*.
    c : bottom clearance coefficient c*.
    rho_f : fillet radius coefficient ρ_f* of the rack (the tip radius of the generating
        rack that cuts the gear's root).
    """

    alpha_n: float
    h_a: float = 1.0
    c: float = 0.25
    rho_f: float = 0.38

    @property
    def h_straight(self) -> float:
        """Height above the datum line, in modules, of the end of the straight flank of the
        generating rack: ``h_l* − h_a* = (h_a* + c*) − ρ_f*(1 − sin α)``.

        For GOST 13755-81 this is 1.25 − 0.38·(1 − sin 20°) = 1.000 = h_a*, the "boundary
        height" used by GOST 16532-70 in x_min and in the form-point radius.
        ([GOST16532] table 1; [ZPCIL] GEOM.h.)
        """
        return self.h_a + self.c - self.rho_f * (1.0 - math.sin(self.alpha_n))


@dataclass(frozen=True)
class PairInput:
    """Data of an external pair.  ``beta`` is the reference helix angle [rad] (0 = spur);
    ``b_w`` the working face width [mm]; ``tip_shortening`` false keeps the nominal tips
    d_a = d + 2(h_a* + x)m_n instead of shortening them by Δy·m_n."""

    m_n: float
    z1: int
    z2: int
    x1: float
    x2: float
    beta: float
    b_w: float
    rack: BasicRack
    tip_shortening: bool = field(default=True, kw_only=True)


@dataclass(frozen=True)
class GearGeometry:
    """Per-gear results (mm and rad)."""

    z: int
    x: float
    d: float          # reference diameter
    d_b: float        # base diameter
    d_w: float        # working (pitch) diameter
    d_a: float        # tip diameter
    d_f: float        # root diameter
    h: float          # tooth depth
    alpha_a: float    # transverse pressure angle at the tip
    rho_a: float      # radius of curvature of the profile at the tip
    rho_p: float      # radius of curvature at the lower point of active profile
    rho_l: float      # radius of curvature at the form (limit) point of the involute
    d_l: float        # form circle diameter (start of the involute made by the rack)
    d_p: float        # diameter of the lower point of active profile
    x_min: float      # least shift without undercut
    s_n: float        # normal tooth thickness on the reference circle (arc)
    s_an: float       # normal tooth thickness at the tip (arc)
    k: int            # number of teeth spanned for W
    W: float          # base tangent length over k teeth (normal section)
    d_W: float        # diameter at which the calliper touches the flanks


@dataclass(frozen=True)
class PairGeometry:
    """Pair results (mm and rad); ``g1``/``g2`` the pinion and the wheel."""

    inp: PairInput
    u: float
    m_t: float
    alpha_t: float
    beta_b: float
    alpha_tw: float
    a: float
    a_w: float
    x_sum: float
    y: float
    dy: float
    g_w: float        # length N1N2 of the line of action between tangency points
    g_alpha: float    # length of the active line of action
    p_bt: float       # transverse base pitch
    p_bn: float       # normal base pitch
    eps_alpha: float
    eps_alpha_z: float  # ε_α from the tooth-number form, equal to eps_alpha
    eps_beta: float
    eps_gamma: float
    c_12: float       # radial clearance, pinion tip to wheel root
    c_21: float       # radial clearance, wheel tip to pinion root
    g1: GearGeometry
    g2: GearGeometry

    @property
    def gears(self) -> tuple[GearGeometry, GearGeometry]:
        return self.g1, self.g2


# ----------------------------------------------------------------------------- pieces


def transverse_angles(alpha_n: float, beta: float) -> tuple[float, float]:
    """Transverse pressure angle and base helix angle.

    .. math:: \\tan α_t = \\tan α / \\cos β, \\qquad \\sin β_b = \\sin β \\cos α

    GOST 16532-70, table 1; ISO 21771:2007.

    Example: a spur gear (β = 0) has α_t = α and β_b = 0 (identity):

    >>> transverse_angles(0.35, 0.0)
    (0.35, 0.0)
    """
    alpha_t = xp.atan(xp.tan(alpha_n) / xp.cos(beta))
    beta_b = xp.asin(xp.sin(beta) * math.cos(alpha_n))
    return alpha_t, beta_b


def undercut_shift_limit(z: int, alpha_t: float, beta: float, rack: BasicRack) -> float:
    """Least profile shift without undercut when cut by the rack (or a rack-like tool).

    .. math:: x_{min} = (h_l^* - h_a^*) - \\frac{z \\sin^2 α_t}{2 \\cos β}

    h_l* − h_a* = :attr:`BasicRack.h_straight` (1 for GOST 13755-81).
    References: GOST 16532-70 (quality checks); ZPCIL ``GEOM.h`` ([ZPCIL] GEOM.h).  The worm
    calculator uses it for the wheel's mid-plane (β = 0, α_t = α_x).

    Example: the GOST 13755-81 rack (h_l* − h_a* = 1.000) undercuts no spur gear of
    z ≥ 2/sin²20° = 17.1 teeth, so x_min ≈ 0 at z = 17:

    >>> import math
    >>> a = math.radians(20.0)
    >>> round(undercut_shift_limit(17, a, 0.0, BasicRack(a)), 3)
    0.006
    """
    return rack.h_straight - z * xp.sin(alpha_t) ** 2 / (2.0 * xp.cos(beta))


def working_pressure_angle(x_sum: float, z1: int, z2: int, alpha_n: float, alpha_t: float) -> float:
    """Working transverse pressure angle α_tw from the sum of shifts.

    .. math:: \\operatorname{inv} α_{tw} = \\frac{2 x_Σ \\tan α}{z_1 + z_2} + \\operatorname{inv} α_t

    Solved to 1e-12 rad by :func:`geardesign.involute.inv_inverse`.

    Raises
    ------
    GeometryError ``INV_ALPHA_TW`` if inv α_tw <= 0 (the shifts are too negative).

    References: GOST 16532-70, table 1 (x_Σ given).

    Example: with x_Σ = 0 the pair works at the rack's angle, α_tw = α_t (identity):

    >>> abs(working_pressure_angle(0.0, 20, 40, 0.35, 0.35) - 0.35) < 1e-12
    True
    """
    value = 2.0 * x_sum * math.tan(alpha_n) / (z1 + z2) + inv(alpha_t)
    if value <= 0.0:
        # least x_Σ with inv α_tw > 0
        limit = -inv(alpha_t) * (z1 + z2) / (2.0 * math.tan(alpha_n))
        raise GeometryError("INV_ALPHA_TW", f"inv α_tw = {value:.6g} <= 0", x_sum, limit)
    return inv_inverse(value)


def shift_sum_for_center_distance(a_w: float, m_n: float, z1: int, z2: int, alpha_n: float,
                                  beta: float) -> tuple[float, float]:
    """Sum of shifts x_Σ and α_tw for a given centre distance (reverse task).

    .. math:: \\cos α_{tw} = \\frac{a \\cos α_t}{a_w}, \\qquad
              x_Σ = \\frac{(z_1+z_2)(\\operatorname{inv} α_{tw} - \\operatorname{inv} α_t)}{2 \\tan α}

    Raises
    ------
    GeometryError ``CENTER_DISTANCE_TOO_SMALL`` if a_w <= a·cos α_t = (d_b1 + d_b2)/2:
    the base circles would overlap.

    References: GOST 16532-70, table 1 (a_w given); [GOST16532] table 1.
    """
    alpha_t, _ = transverse_angles(alpha_n, beta)
    a = 0.5 * m_n * (z1 + z2) / math.cos(beta)
    a_min = a * math.cos(alpha_t)
    if a_w <= a_min * (1.0 + 1e-9):
        raise GeometryError("CENTER_DISTANCE_TOO_SMALL",
                            f"a_w must exceed (d_b1 + d_b2)/2 = {a_min:.4f} mm", a_w, a_min)
    alpha_tw = math.acos(a * math.cos(alpha_t) / a_w)
    x_sum = (z1 + z2) * (inv(alpha_tw) - inv(alpha_t)) / (2.0 * math.tan(alpha_n))
    return x_sum, alpha_tw


# ----------------------------------------------------------------------------- the pair


def tip_thickness(z: int, x: float, d: float, d_a: float, alpha_t: float, alpha_n: float,
                  beta: float) -> float:
    """Normal tooth thickness at the tip [mm] (arc), GOST 16532-70 table 4:

    .. math:: s_{an} = d_a\\left[\\frac{π/2 + 2x\\tan α}{z} + \\mathrm{inv}\\,α_t
              - \\mathrm{inv}\\,α_a\\right]\\cos β_a, \\qquad \\tan β_a = \\tan β\\,d_a/d

    z teeth, x normal shift coefficient, d and d_a reference and tip diameters [mm],
    α_t, α_n transverse and normal pressure angles, β helix angle [rad]; a value <= 0 is a
    pointed tooth.  [GOST16532]
    """
    d_b = d * xp.cos(alpha_t)
    alpha_a = xp.acos(xp.minimum(d_b / d_a, 1.0))
    beta_a = xp.atan(xp.tan(beta) * d_a / d)
    return d_a * ((0.5 * math.pi + 2.0 * x * math.tan(alpha_n)) / z + inv(alpha_t)
                  - inv(alpha_a)) * xp.cos(beta_a)


GEAR_FIELDS = ("z", "x", "d", "d_b", "d_w", "d_a", "d_f", "h", "alpha_a", "rho_a", "rho_l",
               "x_min", "s_n", "s_an", "rho_p", "d_l", "d_p")
GEAR_KEYS = tuple(tuple(f + str(i) for f in GEAR_FIELDS) for i in (1, 2))
"""The per-gear keys of :func:`pair_core` (``d_a1``, ``d_a2``, …)."""


def pair_core(m_n, z1, z2, x1, x2, beta, b_w, rack: BasicRack, tip_shortening: bool = True
              ) -> dict:
    """The formulas of :func:`pair_geometry` (see there) for Python numbers or numpy arrays of
    candidates: a dict of the pair values and the per-gear values with suffix 1/2.

    For numbers it raises :class:`GeometryError` as :func:`pair_geometry` does; for arrays
    it marks the candidates that admit no pair in ``valid`` (inv α_tw <= 0, a tip inside
    its base circle) and computes the others (the invalid ones carry meaningless numbers).
    """
    scalar = xp.scalar(m_n, z1, z2, x1, x2, beta, b_w)
    alpha_n = rack.alpha_n
    alpha_t, beta_b = transverse_angles(alpha_n, beta)
    m_t = m_n / xp.cos(beta)
    u = z2 / z1
    x_sum = x1 + x2
    c: dict = {}
    if scalar:
        alpha_tw = working_pressure_angle(x_sum, z1, z2, alpha_n, alpha_t)
        valid = True
    else:
        import numpy as np

        value = 2.0 * x_sum * math.tan(alpha_n) / (z1 + z2) + inv(alpha_t)
        valid = value > 0.0
        alpha_tw = inv_inverse_array(np.where(valid, value, 1e-3))
    d1, d2 = z1 * m_t, z2 * m_t
    a = 0.5 * (d1 + d2)
    cos_at = xp.cos(alpha_t)
    a_w = a * cos_at / xp.cos(alpha_tw)
    y = (a_w - a) / m_n
    dy = x_sum - y
    g_w = a_w * xp.sin(alpha_tw)
    p_bt = math.pi * m_t * cos_at
    p_bn = math.pi * m_n * math.cos(alpha_n)
    d_w = (2.0 * a_w / (u + 1.0), 2.0 * a_w * u / (u + 1.0))
    hl = rack.h_straight  # h_l* − h_a* in GOST 16532 notation (1.0 for the GOST 13755 rack)
    sin_at = xp.sin(alpha_t)
    for i, (z, x, d) in enumerate(((z1, x1, d1), (z2, x2, d2))):
        k = str(i + 1)
        d_b = d * cos_at
        d_a = d + 2.0 * (rack.h_a + x - (dy if tip_shortening else 0.0)) * m_n
        d_f = d - 2.0 * (rack.h_a + rack.c - x) * m_n
        if scalar and d_a <= d_b:
            raise GeometryError(f"TIP_INSIDE_BASE_{k}",
                                f"tip circle d_a{k} = {d_a:.4f} mm lies inside the base circle "
                                f"d_b{k} = {d_b:.4f} mm", d_a, d_b)
        if not scalar:
            valid = valid & (d_a > d_b)
        alpha_a = xp.acos(xp.minimum(d_b / d_a, 1.0))
        c.update({"z" + k: z, "x" + k: x, "d" + k: d, "d_b" + k: d_b, "d_w" + k: d_w[i],
                  "d_a" + k: d_a, "d_f" + k: d_f, "h" + k: 0.5 * (d_a - d_f),
                  "alpha_a" + k: alpha_a, "rho_a" + k: 0.5 * d_b * xp.tan(alpha_a),
                  "rho_l" + k: 0.5 * d * sin_at - (hl - x) * m_n / sin_at,
                  "x_min" + k: undercut_shift_limit(z, alpha_t, beta, rack),
                  "s_n" + k: m_n * (0.5 * math.pi + 2.0 * x * math.tan(alpha_n)),
                  "s_an" + k: tip_thickness(z, x, d, d_a, alpha_t, alpha_n, beta)})
    c["rho_p1"] = g_w - c["rho_a2"]
    c["rho_p2"] = g_w - c["rho_a1"]
    for k in "12":
        c["d_l" + k] = 2.0 * xp.hypot(0.5 * c["d_b" + k], xp.maximum(c["rho_l" + k], 0.0))
        c["d_p" + k] = 2.0 * xp.hypot(0.5 * c["d_b" + k], c["rho_p" + k])
    g_alpha = c["rho_a1"] + c["rho_a2"] - g_w
    eps_alpha = g_alpha / p_bt
    tan_atw = xp.tan(alpha_tw)
    eps_alpha_z = (z1 * (xp.tan(c["alpha_a1"]) - tan_atw)
                   + z2 * (xp.tan(c["alpha_a2"]) - tan_atw)) / (2.0 * math.pi)
    eps_beta = b_w * xp.sin(beta) / (math.pi * m_n)
    c.update(u=u, m_t=m_t, alpha_t=alpha_t, beta_b=beta_b, alpha_tw=alpha_tw, a=a, a_w=a_w,
             x_sum=x_sum, y=y, dy=dy, g_w=g_w, g_alpha=g_alpha, p_bt=p_bt, p_bn=p_bn,
             eps_alpha=eps_alpha, eps_alpha_z=eps_alpha_z, eps_beta=eps_beta,
             eps_gamma=eps_alpha + eps_beta,
             c_12=a_w - 0.5 * (c["d_a1"] + c["d_f2"]), c_21=a_w - 0.5 * (c["d_a2"] + c["d_f1"]),
             valid=valid)
    return c


def pair_geometry(p: PairInput) -> PairGeometry:
    """Complete geometry of an external pair from module, tooth numbers and shifts.

    Formulas (GOST 16532-70, table 1; [GOST16532] table 1):

    * m_t = m_n/cos β; d = z·m_t; d_b = d·cos α_t; a = (d1 + d2)/2; u = z2/z1
    * inv α_tw = 2x_Σ tan α/(z1 + z2) + inv α_t;  a_w = a·cos α_t / cos α_tw
    * y = (a_w − a)/m_n; Δy = x_Σ − y (tip shortening, ≥ 0)
    * d_w1 = 2a_w/(u + 1); d_w2 = 2a_w·u/(u + 1)
    * d_a = d + 2(h_a* + x − Δy)m_n (Δy = 0 without tip shortening);
      d_f = d − 2(h_a* + c* − x)m_n
    * ρ_a = ½ d_b tan α_a, cos α_a = d_b/d_a; g_w = a_w sin α_tw = ρ_1 + ρ_2
    * lower active points ρ_p1 = g_w − ρ_a2, ρ_p2 = g_w − ρ_a1
    * form points ρ_l = ½ d sin α_t − (h_l* − h_a* − x)m_n / sin α_t
    * x_min = h_l* − h_a* − z sin²α_t/(2 cos β)
    * ε_α = (ρ_a1 + ρ_a2 − g_w)/p_bt, p_bt = π m_t cos α_t;
      equally [z1(tan α_a1 − tan α_tw) + z2(tan α_a2 − tan α_tw)]/(2π)
    * ε_β = b_w sin β/(π m_n); ε_γ = ε_α + ε_β
    * s_n = m_n(π/2 + 2x tan α); s_an = d_a[(π/2 + 2x tan α)/z + inv α_t − inv α_a]·cos β_a,
      tan β_a = tan β·d_a/d (GOST 16532-70 table 2/5; ZPCIL ``GEOM.h``)

    Raises
    ------
    GeometryError if inv α_tw <= 0 or a tip circle lies inside its base circle.
    """
    c = pair_core(p.m_n, p.z1, p.z2, p.x1, p.x2, p.beta, p.b_w, p.rack, p.tip_shortening)
    alpha_n, alpha_t, beta_b = p.rack.alpha_n, c["alpha_t"], c["beta_b"]
    partial = [{k[:-1]: c[k] for k in GEAR_KEYS[i]} for i in range(2)]
    for r in partial:
        r["k"], r["W"], r["d_W"] = choose_span_teeth(
            r["z"], r["x"], p.m_n, alpha_n, alpha_t, beta_b, r["d"], r["d_b"],
            max(r["d_p"], r["d_l"]), r["d_a"], p.b_w)
    r1, r2 = partial
    g1, g2 = GearGeometry(**r1), GearGeometry(**r2)

    return PairGeometry(
        inp=p, u=c["u"], m_t=c["m_t"], alpha_t=alpha_t, beta_b=beta_b, alpha_tw=c["alpha_tw"],
        a=c["a"], a_w=c["a_w"], x_sum=c["x_sum"], y=c["y"], dy=c["dy"], g_w=c["g_w"],
        g_alpha=c["g_alpha"], p_bt=c["p_bt"], p_bn=c["p_bn"], eps_alpha=c["eps_alpha"],
        eps_alpha_z=c["eps_alpha_z"], eps_beta=c["eps_beta"], eps_gamma=c["eps_gamma"],
        c_12=c["c_12"], c_21=c["c_21"],
        g1=g1, g2=g2,
    )
