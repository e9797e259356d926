"""Kinematics and sliding along the line of action of an external involute pair.

Points on the transverse line of action are given by the distance ρ1 = N1K of the contact
point K from the pinion's tangency point N1; then ρ2 = g_w − ρ1 (g_w = N1N2 = a_w sin α_tw).
A = start of the active line of action (pinion root, wheel tip), E = end (pinion tip,
wheel root), P = pitch point.  The pinion drives.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.gears.geometry import GeometryError, PairGeometry, PairInput, pair_core


def specific_sliding(rho1: float, rho2: float, u: float) -> tuple[float, float]:
    """Specific sliding of the pinion and the wheel flank at a contact point.

    .. math:: ϑ_1 = 1 - \\frac{ρ_2}{u ρ_1}, \\qquad ϑ_2 = 1 - \\frac{u ρ_1}{ρ_2}

    (ϑ_i = (v_ti − v_tj)/v_ti with rolling velocities v_t1 = ω1 ρ1, v_t2 = ω2 ρ2 = ω1 ρ2/u.)

    Parameters
    ----------
    rho1, rho2 : radii of curvature of the pinion and wheel profiles at the point [mm], > 0.
    u : gear ratio z2/z1.

    References: [ISO21771]; Dobrov et al. 2017, eqs. (3) ([Dobrov2017]).

    Example: at the pitch point ρ2 = u·ρ1 and both flanks roll without sliding (identity):

    >>> specific_sliding(10.0, 30.0, 3.0)
    (0.0, 0.0)
    """
    return 1.0 - rho2 / (u * rho1), 1.0 - u * rho1 / rho2


def relative_sliding(rho1: float, rho2: float, u: float) -> float:
    """Dobrov's relative sliding σ12: the sliding velocity over the larger rolling velocity,
    bounded in (−1, 1); negative on the approach (A–P), positive on the recess (P–E).

    .. math:: σ_{12} = \\frac{v_{t1} - v_{t2}}{\\max(v_{t1}, v_{t2})}

    References: Dobrov et al. 2017, eqs. (10) and (20) ([Dobrov2017] eqs. (10), (20)), with the
    denominators read as in [Dobrov2017].

    Examples: zero at the pitch point (ρ2 = u·ρ1); v_t1 = 10, v_t2 = 20/3 gives 1/3:

    >>> relative_sliding(10.0, 30.0, 3.0)
    0.0
    >>> round(relative_sliding(10.0, 20.0, 3.0), 12)
    0.333333333333
    """
    v1, v2 = rho1, rho2 / u
    return (v1 - v2) / max(v1, v2)


@dataclass(frozen=True)
class Sliding:
    """Specific and relative sliding at A and E."""

    theta1_A: float
    theta2_A: float
    theta1_E: float
    theta2_E: float
    sigma12_A: float
    sigma12_E: float


def sliding_at_ends(g: PairGeometry) -> Sliding:
    """Sliding at the ends of the active line of action.

    A: ρ1 = ρ_p1, ρ2 = ρ_a2;  E: ρ1 = ρ_a1, ρ2 = ρ_p2 ([ISO21771]).
    At a point beyond a tangency point (ρ <= 0) the sliding is undefined: the
    interference check fails first and the value is reported as ±inf -> null.
    """
    return sliding_from_radii(g.g1.rho_p, g.g1.rho_a, g.g2.rho_p, g.g2.rho_a, g.u)


def sliding_from_radii(rho_p1: float, rho_a1: float, rho_p2: float, rho_a2: float,
                       u: float) -> Sliding:
    """:func:`sliding_at_ends` from the radii of curvature at the ends of the active line
    of action and u (what the shift balancing needs, without the rest of the geometry)."""
    rA = (rho_p1, rho_a2)
    rE = (rho_a1, rho_p2)

    def at(r1: float, r2: float) -> tuple[float, float, float]:
        if r1 <= 0 or r2 <= 0:
            return math.nan, math.nan, math.nan
        t1, t2 = specific_sliding(r1, r2, u)
        return t1, t2, relative_sliding(r1, r2, u)

    a1, a2, sa = at(*rA)
    e1, e2, se = at(*rE)
    return Sliding(a1, a2, e1, e2, sa, se)


@dataclass(frozen=True)
class Velocities:
    n1: float        # min^-1
    n2: float
    omega1: float    # rad/s
    omega2: float
    v: float         # pitch-line velocity, m/s
    v_s_A: float     # sliding velocity at A, m/s (negative: approach)
    v_s_E: float     # sliding velocity at E, m/s


def velocities(g: PairGeometry, n1: float) -> Velocities:
    """Angular, pitch-line and sliding velocities.

    .. math::
        ω_1 = π n_1/30,\\quad ω_2 = ω_1/u,\\quad v = ω_1 d_{w1}/2000,\\quad
        v_s = (ω_1 \\pm ω_2)(ρ_1 - ρ_{w1})/1000, \\; ρ_{w1} = \\tfrac12 d_{w1} \\sin α_{tw}

    "+" for an external pair (the gears turn in opposite senses), "−" for an internal pair
    (``g.internal``: both turn the same way, ω2 has the sign of ω1).

    (v in m/s with d in mm.)  The sliding velocity is the same in the transverse and the
    normal section: the contact line lies in the plane of action, whose distance from the
    pitch line is measured along the transverse line of action.

    References: [ISO21771]; Dobrov et al. 2017, eq. (3) (v_s = 0 at P, eq. (15)).
    """
    omega1 = math.pi * n1 / 30.0
    omega2 = omega1 / g.u
    relative = omega1 - omega2 if getattr(g, "internal", False) else omega1 + omega2
    rho_w1 = 0.5 * g.g1.d_w * math.sin(g.alpha_tw)
    return Velocities(
        n1=n1, n2=n1 / g.u, omega1=omega1, omega2=omega2,
        v=omega1 * g.g1.d_w / 2000.0,
        v_s_A=relative * (g.g1.rho_p - rho_w1) / 1000.0,
        v_s_E=relative * (g.g1.rho_a - rho_w1) / 1000.0,
    )


def balanced_shift_split(base: PairInput, x_sum: float, steps: int = 120) -> float:
    """Pinion shift x1 (with x2 = x_Σ − x1) that equalises the specific sliding at the two
    roots, ϑ1(A) = ϑ2(E).

    f(x1) = ϑ1(A) − ϑ2(E) increases monotonically with x1 (a larger x1 lengthens the pinion
    addendum and shortens the wheel's), so the root is bracketed on a grid over
    x1 ∈ [x_Σ/2 − 2, x_Σ/2 + 2] and refined by bisection to 1e-10.  (Bisection is written
    out here rather than taken from scipy.optimize, whose import alone costs about 1 s
    on the development machine.)

    Raises
    ------
    GeometryError ``NO_BALANCED_SPLIT`` when no x1 in that interval balances the sliding
    with a valid geometry.

    References: [ISO21771] ("design goal |ϑ1(A)| ≈ |ϑ2(E)|, equalised by x1, x2");
    GOST 16532-70 appendix (choice of shifts by equal specific sliding).
    """

    def f(x1: float) -> float | None:
        try:
            c = pair_core(base.m_n, base.z1, base.z2, x1, x_sum - x1, base.beta, base.b_w,
                          base.rack)
        except GeometryError:
            return None
        s = sliding_from_radii(c["rho_p1"], c["rho_a1"], c["rho_p2"], c["rho_a2"], c["u"])
        val = s.theta1_A - s.theta2_E
        return None if math.isnan(val) else val

    lo_x, hi_x = 0.5 * x_sum - 2.0, 0.5 * x_sum + 2.0
    grid = [lo_x + (hi_x - lo_x) * i / steps for i in range(steps + 1)]
    prev_x, prev_f = None, None
    for x in grid:
        fx = f(x)
        if fx is None:
            prev_x, prev_f = None, None
            continue
        if fx == 0.0:
            return x
        if prev_f is not None and (prev_f < 0.0) != (fx < 0.0):
            a, fa, b = prev_x, prev_f, x
            for _ in range(200):
                mid = 0.5 * (a + b)
                fm = f(mid)
                if fm is None:
                    break
                if (fm < 0.0) == (fa < 0.0):
                    a, fa = mid, fm
                else:
                    b = mid
                if b - a < 1e-10:
                    break
            return 0.5 * (a + b)
        prev_x, prev_f = x, fx
    raise GeometryError("NO_BALANCED_SPLIT",
                        "no split of x1 + x2 equalises the specific sliding with a valid geometry")
