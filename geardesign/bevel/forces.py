"""Forces on the shafts of a bevel pair at the mean cone, per member, by the hand of the
spiral, the sense of rotation and the driving member, as frozen records.  Forces [N],
lengths [mm], torque [N·mm].
"""

from __future__ import annotations

import math

from geardesign.bevel.geometry import Geometry
from geardesign.bevel.inputs import Inputs
from geardesign.core.records import dataclass


@dataclass(frozen=True)
class MemberForces:
    """Forces on one member at the mean cone [N]: F_a > 0 points from the apex to the
    back of the member, F_r > 0 toward its axis (separating)."""

    F_t: float
    F_a: float
    F_r: float


@dataclass(frozen=True)
class Forces:
    F_mt: float           # tangential force at the mean cone
    T2: float             # wheel torque [N·mm] (no losses)
    v_mt: float           # pitch line speed at the mean cone [m/s]
    v_et: float           # pitch line speed at the outer cone [m/s] (AGMA, [Shigley] §15-1)
    pinion: MemberForces
    wheel: MemberForces


def thrust_sign(hand: str, rotation: str, driving: bool) -> int:
    """+1 when the member's axial force points away from the apex (out of mesh): a driving
    member with a right hand spiral turning counter-clockwise, or a left hand spiral turning
    clockwise, seen from its back (the large end); a driven member the other way.

    From the definitions alone: the hand of spiral as [ISO23509] defines it (right hand: the
    outer half of a tooth inclined clockwise from the axial plane through its midpoint, seen
    by an observer looking at the face of the gear, i.e. from the apex side), the rotation
    seen from the back, the normal force on the flank at the mean point perpendicular to the
    tooth line and inclined by α_n, opposing the motion of a driving member: a left hand
    pinion driving clockwise is pushed out of mesh, the hand chosen for that in practice.
    Checked against that vector construction in all eight cases of hand, rotation and driver
    (tests/test_bevel_published_forces.py); no printed force figure with its signs was found
    (docs/bevel.md, published cases).

    >>> thrust_sign("left", "cw", True), thrust_sign("right", "cw", True)
    (1, -1)
    """
    same = (hand == "right") == (rotation == "ccw")
    return 1 if same == driving else -1


def member_forces(F_mt: float, alpha_n: float, beta_m: float, delta: float, s: int
                  ) -> MemberForces:
    """Axial and radial forces of a member with pitch cone angle δ and sign s
    (:func:`thrust_sign`).

    .. math::
        F_a = \\frac{F_{mt}}{\\cos β_m}(\\tan α_n \\sin δ + s \\sin β_m \\cos δ),\\quad
        F_r = \\frac{F_{mt}}{\\cos β_m}(\\tan α_n \\cos δ - s \\sin β_m \\sin δ)

    the components of the normal force F_n = F_mt/(cos α_n cos β_m) on the flank at the mean
    point (the vector construction of :func:`thrust_sign`).  At Σ = 90° the wheel (sign −s)
    carries F_a2 = F_r1 and F_r2 = F_a1.  [ISO10300-1] §5 (F_mt, F_n at the mean cone);
    [Dunaev] §2.6 (straight teeth: F_a1 = F_t tan α sin δ1, F_r1 = F_t tan α cos δ1).

    >>> f = member_forces(1000.0, math.radians(20), 0.0, math.radians(45), 1)
    >>> round(f.F_a, 3), round(f.F_r, 3)
    (257.366, 257.366)
    """
    k = F_mt / math.cos(beta_m)
    ta, sb = math.tan(alpha_n), math.sin(beta_m)
    return MemberForces(F_mt, k * (ta * math.sin(delta) + s * sb * math.cos(delta)),
                        k * (ta * math.cos(delta) - s * sb * math.sin(delta)))


def forces(inp: Inputs, g: Geometry) -> Forces:
    """F_mt = 2 T1/d_m1 and the members' forces (the pinion's hand, rotation, driver); the
    pitch line speeds v = π d n1/60 000 at the mean and the outer cone.  [ISO10300-1] §5
    (F_mt, checked by [ISOTR10300-30] sample 1); [Shigley] §15-1 (v_et, AGMA)."""
    p, ld = inp.pair, inp.load
    F_mt = 2.0 * ld.T1 / g.pinion.d_m
    s1 = thrust_sign(p.hand, ld.rotation, ld.driver == "pinion")
    return Forces(F_mt, ld.T1 * g.u, math.pi * g.pinion.d_m * ld.n1 / 60000.0,
                  math.pi * g.pinion.d_e * ld.n1 / 60000.0,
                  member_forces(F_mt, g.alpha_n, g.beta_m, g.pinion.delta, s1),
                  member_forces(F_mt, g.alpha_n, g.beta_m, g.wheel.delta, -s1))
