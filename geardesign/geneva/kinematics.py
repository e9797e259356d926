"""Kinematics and geometry of the external and the internal Geneva mechanism.

Notation (lengths in mm, angles in rad, the crank turning at a constant ω1):

* ``z`` slots, ``k`` pins (rollers) equally spaced on the crank, centre distance ``a``;
* λ = R1/a = sin(π/z), R1 = a·sin(π/z) the crank radius, R2 = a·cos(π/z) the radius of the
  roller centre on the cross at entry;
* φ the crank angle measured from the line of centres, φ = 0 in the middle of the motion;
  the roller is in a slot for |φ| <= φ0; the crank turns from −φ0 to +φ0, so that the cross
  accelerates for φ < 0 and decelerates for φ > 0.

The relations follow from the slider-crank geometry of a roller in a radial slot (the cross
angle ψ is the direction of the roller centre seen from the cross axis); they are the
textbook formulas (Artobolevsky; Kozhevnikov; Sclater & Chironis, "Kinematics of
intermittent mechanisms"), derived again in each docstring so that they can be checked
without the books.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass


def crank_ratio(z: int) -> float:
    """λ = R1/a = sin(π/z).

    The roller enters the slot tangentially: at entry the crank O1P is perpendicular to the
    slot O2P, and the cross turns by 2π/z per index, so the triangle O1 P O2 has the right
    angle at P and the angle π/z at O2: R1 = a·sin(π/z), R2 = a·cos(π/z).

    Parameters: z number of slots (>= 3).  Reference: Geneva geometry, [Artobolevsky].

    Example: four slots give λ = sin 45° = 0.7071:

    >>> round(crank_ratio(4), 4)
    0.7071
    """
    return math.sin(math.pi / z)


def half_motion_angle(z: int, internal: bool) -> float:
    """φ0, half the crank angle during which the roller drives the cross [rad].

    External: φ0 = π/2 − π/z (total 2φ0 = π(z − 2)/z);  internal: φ0 = π/2 + π/z
    (total π(z + 2)/z).  At φ = ±φ0 the crank is perpendicular to the slot.

    Reference: [Artobolevsky] (Geneva mechanism).
    """
    return 0.5 * math.pi + (math.pi / z if internal else -math.pi / z)


def motion_share(z: int, pins: int, internal: bool) -> float:
    """Share of a crank revolution during which the cross moves, k·2φ0/(2π).

    External: k(z − 2)/(2z); internal: k(z + 2)/(2z).  It must stay below 1, or the cross
    never dwells (two rollers in slots at the same time).

    Reference: [Artobolevsky] (motion share, "with k pins: k(z − 2)/(2z) < 1").

    Example: an external four-slot wheel with one pin moves a quarter of the crank's turn
    (2·45° of 360°):

    >>> motion_share(4, 1, False)
    0.25
    """
    return pins * 2.0 * half_motion_angle(z, internal) / (2.0 * math.pi)


def _den(phi: float, lam: float, internal: bool) -> float:
    s = 1.0 if internal else -1.0
    return 1.0 + 2.0 * s * lam * math.cos(phi) + lam * lam


def cross_angle(phi: float, lam: float, internal: bool) -> float:
    """Cross (Geneva wheel) angle ψ(φ) from its middle position [rad].

    External: tan ψ = λ sin φ/(1 − λ cos φ);  internal: tan ψ = λ sin φ/(1 + λ cos φ)
    (roller centre at (a ∓ R1 cos φ, R1 sin φ) seen from the cross axis).  ψ runs from
    −π/z to +π/z while φ runs from −φ0 to +φ0.

    Reference: Geneva kinematics, [Artobolevsky].
    """
    s = 1.0 if internal else -1.0
    return math.atan2(lam * math.sin(phi), 1.0 + s * lam * math.cos(phi))


def omega_ratio(phi: float, lam: float, internal: bool) -> float:
    """ω2/ω1, the cross speed per unit crank speed (dψ/dφ).

    External: λ(cos φ − λ)/(1 − 2λ cos φ + λ²);  internal: λ(λ + cos φ)/(1 + 2λ cos φ + λ²).
    Zero at entry and exit (tangential entry), largest at φ = 0.

    Reference: Geneva kinematics (Artobolevsky), [Artobolevsky].
    """
    if internal:
        return lam * (lam + math.cos(phi)) / _den(phi, lam, True)
    return lam * (math.cos(phi) - lam) / _den(phi, lam, False)


def eps_ratio(phi: float, lam: float, internal: bool) -> float:
    """ε2/ω1², the cross acceleration per unit crank speed squared (d²ψ/dφ², ω1 constant).

    Both kinds: −λ(1 − λ²) sin φ/(1 ∓ 2λ cos φ + λ²)² (− external, + internal).  Positive
    (speeding up) for φ < 0.  At entry |ε2|/ω1² = tan(π/z) for both kinds: the acceleration
    jumps from zero (soft impact).

    Reference: Geneva kinematics (Artobolevsky), [Artobolevsky].
    """
    return -lam * (1.0 - lam * lam) * math.sin(phi) / _den(phi, lam, internal) ** 2


def peak_omega_ratio(lam: float, internal: bool) -> float:
    """Largest ω2/ω1, at φ = 0: λ/(1 − λ) external, λ/(1 + λ) internal.

    Reference: [Artobolevsky].
    """
    return lam / (1.0 + lam) if internal else lam / (1.0 - lam)


def peak_acceleration(z: int, internal: bool) -> tuple[float, float]:
    """Largest |ε2|/ω1² and the crank angle φ where it occurs (φ < 0, speeding up).

    External: d/dφ of the acceleration vanishes at cos φ = −b + sqrt(b² + 2),
    b = (1 + λ²)/(4λ) (from d/dφ [sin φ/(1 − 2λ cos φ + λ²)²] = 0, a quadratic in cos φ).
    Internal: the same substitution with φ → π − φ puts that extremum outside the motion
    range, |ε2| grows monotonically towards entry, and the largest value is the entry jump
    tan(π/z) at φ = −φ0.

    Reference: [Artobolevsky] (closed form of the extreme).
    """
    lam = crank_ratio(z)
    if internal:
        phi = -half_motion_angle(z, True)
        return abs(eps_ratio(phi, lam, True)), phi
    b = (1.0 + lam * lam) / (4.0 * lam)
    phi = -math.acos(-b + math.sqrt(b * b + 2.0))
    return abs(eps_ratio(phi, lam, False)), phi


def entry_jump(z: int) -> float:
    """|ε2|/ω1² at entry and exit, tan(π/z), for both kinds.

    At φ = ±φ0 the centripetal acceleration ω1²R1 of the roller centre is perpendicular
    to the slot and is carried by the cross alone: |ε2| = ω1²R1/R2 = ω1² tan(π/z).

    Reference: [Artobolevsky] ("soft impact").
    """
    return math.tan(math.pi / z)


def maximise(f, lo: float, hi: float, steps: int = 720) -> tuple[float, float]:
    """Maximum of a smooth function on [lo, hi]: a scan, then golden-section refinement
    (to 1e-12 rad) around the best sample."""
    best_i, best = 0, -math.inf
    for i in range(steps + 1):
        v = f(lo + (hi - lo) * i / steps)
        if v > best:
            best_i, best = i, v
    h = (hi - lo) / steps
    a, b = max(lo, lo + (best_i - 1) * h), min(hi, lo + (best_i + 1) * h)
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = f(c), f(d)
    while b - a > 1e-12:
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = f(d)
    x = 0.5 * (a + b)
    fx = f(x)
    for edge in (lo, hi):
        if f(edge) > fx:
            x, fx = edge, f(edge)
    return fx, x


def peak_power_factor(z: int, internal: bool) -> tuple[float, float]:
    """Largest |ω2·ε2|/ω1³ (the dynamic power of a rigid load J on the cross per J·ω1³) and
    its crank angle φ < 0.

    N = J·ω2·ε2 ([RotaryDevices], Fig. 2 curve 3); the maximum of the product has no simple closed
    form and is found numerically (scan and golden section) on the speeding-up half.

    Reference: [Artobolevsky] (table "|omega2·eps2|max/omega1³").
    """
    lam = crank_ratio(z)
    phi0 = half_motion_angle(z, internal)
    value, phi = maximise(
        lambda p: omega_ratio(p, lam, internal) * eps_ratio(p, lam, internal), -phi0, 0.0)
    return value, phi


@dataclass(frozen=True)
class MotionLaw:
    """The motion law sampled at ``n`` equally spaced crank angles from −φ0 to +φ0."""

    phi: list       # crank angle [rad]
    psi: list       # cross angle [rad]
    omega: list     # ω2/ω1 [-]
    eps: list       # ε2/ω1² [-]


def motion_law(z: int, internal: bool, n: int) -> MotionLaw:
    """ψ, ω2/ω1 and ε2/ω1² at ``n`` crank angles spanning the motion (both ends included)."""
    lam = crank_ratio(z)
    phi0 = half_motion_angle(z, internal)
    phi = [-phi0 + 2.0 * phi0 * i / (n - 1) for i in range(n)]
    return MotionLaw(
        phi=phi,
        psi=[cross_angle(p, lam, internal) for p in phi],
        omega=[omega_ratio(p, lam, internal) for p in phi],
        eps=[eps_ratio(p, lam, internal) for p in phi],
    )


@dataclass(frozen=True)
class GenevaGeometry:
    """Main dimensions [mm] of the mechanism (see :func:`geometry`)."""

    lam: float
    R1: float               # crank radius (roller centre)
    R2: float               # roller-centre radius on the cross at entry
    mouth_radius: float     # radius of the slot-mouth corners (cross outer radius / ring bore)
    slot_travel: float      # travel of the roller centre along the slot
    slot_end_radius: float  # slot bottom (external) / slot end (internal), roller + clearance
    slot_depth: float       # slot length from the mouth to its end
    web: float              # material between two adjacent slots at its narrowest
    locking_radius: float   # largest locking-disc radius on the crank
    max_roller: float       # largest roller diameter that fits (web >= 0, locking disc > 0)


def geometry(z: int, internal: bool, a: float, d_roller: float, clearance: float,
             shaft_diameter: float = 0.0) -> GenevaGeometry:
    """Main dimensions of a Geneva mechanism.

    * R1 = a sin(π/z), R2 = a cos(π/z) (:func:`crank_ratio`).
    * Slot mouth: the slot flanks lie d/2 either side of the slot centre line and start where
      the roller centre enters, at R2, so the mouth corners lie on the circle
      sqrt(R2² + (d/2)²) (the outer radius of an external cross, the bore of an internal
      ring; Sclater & Chironis give D = 2·sqrt((d/2)² + R1² cot²(π/z)), the same value).
    * Roller-centre travel along the slot: from R2 to a − R1 (external, closest at φ = 0) or
      to a + R1 (internal): R1 + R2 − a, resp. a + R1 − R2.
    * Slot end radius (roller surface plus ``clearance``): a − R1 − d/2 − c (external),
      a + R1 + d/2 + c (internal); slot depth = distance from the mouth circle to it.
    * Web: two adjacent slot centre lines are 2π/z apart, so at a distance x from the cross
      axis their flanks are 2x·sin(π/z) − d apart; the narrowest place is the slot bottom
      (external, x = slot end radius) or the mouth (internal, x = R2).
    * Locking disc: its arc may reach the slot flank at the mouth, R_l = R1 − d/2 − c (at
      entry the flank nearest the crank axis is at R1 − d/2 from it).
    * ``max_roller``: the largest roller diameter with web >= 0, a locking disc > 0 and,
      external, a slot bottom outside the cross shaft (``shaft_diameter``).

    Parameters: z slots, ``internal`` kind, a centre distance [mm], d_roller roller
    diameter [mm], clearance [mm], shaft_diameter of the cross [mm] (0: not checked).
    Reference: Geneva geometry, [Artobolevsky] ("R1 = a sin(π/z), R2 = a cos(π/z), slot
    depth R1 + R2 − a + clearance, locking-arc radius").
    """
    lam = crank_ratio(z)
    R1, R2 = a * lam, a * math.cos(math.pi / z)
    d, c = d_roller, clearance
    s = math.sin(math.pi / z)
    mouth = math.hypot(R2, 0.5 * d)
    if internal:
        travel = a + R1 - R2
        end = a + R1 + 0.5 * d + c
        depth = end - mouth
        web = 2.0 * R2 * s - d
        d_web = 2.0 * R2 * s
        d_max = min(d_web, 2.0 * (R1 - c))
    else:
        travel = R1 + R2 - a
        end = a - R1 - 0.5 * d - c
        depth = mouth - end
        web = 2.0 * end * s - d
        # 2 s (a − R1 − d/2 − c) − d >= 0  <=>  d <= 2 s (a − R1 − c)/(1 + s)
        d_web = 2.0 * s * (a - R1 - c) / (1.0 + s)
        d_shaft = 2.0 * (a - R1 - c - 0.5 * shaft_diameter)
        d_max = min(d_web, d_shaft, 2.0 * (R1 - c))
    return GenevaGeometry(lam=lam, R1=R1, R2=R2, mouth_radius=mouth, slot_travel=travel,
                          slot_end_radius=end, slot_depth=depth, web=web,
                          locking_radius=R1 - 0.5 * d - c, max_roller=d_max)


def roller_radius_on_cross(phi: float, z: int, a: float, internal: bool) -> float:
    """Distance ρ(φ) of the roller centre from the cross axis [mm]:
    ρ² = a² ∓ 2aR1 cos φ + R1² (− external, + internal); the slot force is M2/ρ.

    Reference: Geneva geometry (law of cosines in O1 P O2).
    """
    R1 = a * crank_ratio(z)
    s = 1.0 if internal else -1.0
    return math.sqrt(a * a + 2.0 * s * a * R1 * math.cos(phi) + R1 * R1)
