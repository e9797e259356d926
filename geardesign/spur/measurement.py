"""Test dimensions of a cylindrical involute gear: span (base tangent length) W over k
teeth, dimension over two balls or pins M_d (external and internal gears, even and odd
tooth numbers, spur and helical), chordal tooth thickness and height, constant chord.

Pure functions; lengths in mm, angles in radians.  Each takes the tooth thickness (external)
or space width (internal) on the reference circle in the normal section, so that the same
function gives the nominal dimension and its limits: the thickness with its upper or lower
allowance gives the upper or lower limit of the dimension.

References: [GOST16532] (span, chordal and constant chord, dimension over balls);
[ISO21771] 6 (test dimensions for tooth thickness); [KHK] (over-pin and chordal formulas).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.involute import inv, inv_inverse
from geardesign.gears.span import base_tangent_length, span_measurable


class MeasurementError(ValueError):
    """A test dimension that cannot be measured (ball not touching the flanks, impossible
    k); ``key`` names the spec key and ``value`` its value."""

    def __init__(self, key: str, value, message: str):
        super().__init__(message)
        self.key = key
        self.value = value


@dataclass(frozen=True)
class Tooth:
    """The data of one gear the test dimensions need.  ``s_n`` is the normal tooth thickness
    (external) or space width (internal) on the reference circle; ``d_form`` the diameter
    where the involute starts (external: the form circle; internal: the involute's outer end),
    ``d_a`` the tip diameter (internal: the smaller, inner one)."""

    z: int
    m_n: float
    alpha_n: float
    beta: float
    s_n: float
    d_a: float
    d_form: float
    internal: bool = False

    @property
    def alpha_t(self) -> float:
        return math.atan(math.tan(self.alpha_n) / math.cos(self.beta))

    @property
    def beta_b(self) -> float:
        return math.asin(math.sin(self.beta) * math.cos(self.alpha_n))

    @property
    def d(self) -> float:
        return self.z * self.m_n / math.cos(self.beta)

    @property
    def d_b(self) -> float:
        return self.d * math.cos(self.alpha_t)


# ----------------------------------------------------------------------------- balls


@dataclass(frozen=True)
class OverBalls:
    """Dimension over (external) or between (internal) two balls or pins."""

    D: float          # ball or pin diameter
    M: float          # dimension over/between the balls
    d_M: float        # diameter of the circle of the ball centres
    alpha_Mt: float   # transverse pressure angle at the ball centre
    d_c: float        # diameter at which the ball touches the flanks
    internal: bool = False

    @property
    def M_r(self) -> float:
        """Radial single-ball dimension: from the gear axis to the far point of one ball,
        external ½(d_M + D), internal ½(d_M − D) (the near point, toward the axis), for even
        and odd z alike ([ISO21771] 6.4; KISSsoft's M_rK, [KISSsoft2017]: the NREL stage-1
        ring z = 56, D = 80 mm gives 1222.689 mm)."""
        return 0.5 * (self.d_M - self.D) if self.internal else 0.5 * (self.d_M + self.D)


def _K(t: Tooth, s_n: float) -> float:
    """inv α_Mt − (±D/(d_b cos β_b)): the part of the ball-centre equation without D."""
    if t.internal:
        return inv(t.alpha_t) + s_n / (t.m_n * t.z)
    return inv(t.alpha_t) + s_n / (t.m_n * t.z) - math.pi / t.z


def over_balls(t: Tooth, D: float, s_n: float | None = None) -> OverBalls:
    """Dimension over two balls (or pins, spur only) of diameter ``D`` [mm].

    External gear, ball centres on the circle d_M = d_b / cos α_Mt with

    .. math:: \\operatorname{inv} α_{Mt} = \\operatorname{inv} α_t + \\frac{s_n}{m_n z}
              - \\frac{π}{z} + \\frac{D}{m_n z \\cos α_n}

    (m_n z cos α_n = d_b cos β_b: the ball centre lies on the helicoid offset by D/2, exact
    for balls); internal gear with the space width e_n for s_n,

    .. math:: \\operatorname{inv} α_{Mt} = \\operatorname{inv} α_t - \\frac{e_n}{m_n z}
              + \\frac{π}{z} - \\frac{D}{m_n z \\cos α_n}

    Even z: M = d_M ± D; odd z: M = d_M cos(90°/z) ± D (+ external, − internal).  The ball
    touches the flank where tan α_ct = tan α_Mt ∓ D cos β_b / d_b.  [GOST16532]; [ISO21771]
    6.4; [KHK] over-pin formulas.

    >>> t = Tooth(20, 1.0, math.radians(20), 0.0, math.pi / 2, 22.0, 17.8)
    >>> round(over_balls(t, 1.7).M, 4)
    22.2941
    """
    s = t.s_n if s_n is None else s_n
    sign = -1.0 if t.internal else 1.0
    value = _K(t, s) + sign * D / (t.d_b * math.cos(t.beta_b))
    if value <= 0.0:
        raise MeasurementError("D", D, "the ball centre would lie inside the base circle")
    alpha_M = inv_inverse(value)
    d_M = t.d_b / math.cos(alpha_M)
    tan_c = math.tan(alpha_M) - sign * D * math.cos(t.beta_b) / t.d_b
    d_c = t.d_b * math.sqrt(1.0 + tan_c * tan_c) if tan_c > 0.0 else t.d_b * (1.0 - 1e-9)
    chord = 1.0 if t.z % 2 == 0 else math.cos(0.5 * math.pi / t.z)
    return OverBalls(D, d_M * chord + sign * D, d_M, alpha_M, d_c, t.internal)


def ball_touches(t: Tooth, res: OverBalls) -> str | None:
    """``None`` if the ball touches both flanks on the involute and stands out of the tooth
    space (external: over the tip circle; internal: inside the tip circle), else the reason."""
    lo, hi = (t.d_a, t.d_form) if t.internal else (t.d_form, t.d_a)
    lo = max(lo, t.d_b)
    # a larger ball touches higher on an external gear's flanks, but nearer the axis (lower
    # d) between an internal gear's teeth, whose spaces narrow outward
    bigger, smaller = ("a smaller", "a larger") if t.internal else ("a larger", "a smaller")
    if res.d_c < lo - 1e-9:
        return (f"it would touch the flanks at d = {res.d_c:.4f} mm, below the involute, which "
                f"starts at d = {lo:.4f} mm: choose {bigger} ball")
    if res.d_c > hi + 1e-9:
        return (f"it would touch the flanks at d = {res.d_c:.4f} mm, beyond the involute, which "
                f"ends at d = {hi:.4f} mm: choose {smaller} ball")
    edge = res.d_M - res.D if t.internal else res.d_M + res.D
    if (edge >= t.d_a) if t.internal else (edge <= t.d_a):
        return ("it would not stand out of the tooth space, so the measuring faces would touch "
                "the teeth: choose a larger ball")
    return None


def ideal_ball(t: Tooth, d_contact: float | None = None, step: float = 0.01) -> float:
    """Ball diameter that touches the flanks on the circle ``d_contact`` (default d + 2x·m_n,
    the shifted reference circle near mid-height), rounded to ``step`` mm.

    From tan α_ct = tan α_Mt − cos²β_b·(inv α_Mt − K) (the contact and the ball-centre
    relations of :func:`over_balls` with D eliminated; increasing in α_Mt), solved for α_Mt
    by bisection; then D = ±d_b cos β_b (inv α_Mt − K).
    """
    if d_contact is None:
        d_contact = t.d + 2.0 * _shift(t) * t.m_n
    tan_c = math.sqrt(max((d_contact / t.d_b) ** 2 - 1.0, 1e-12))
    K = _K(t, t.s_n)
    c2 = math.cos(t.beta_b) ** 2
    sign = -1.0 if t.internal else 1.0
    lo, hi = 1e-6, 0.5 * math.pi - 1e-6
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if math.tan(mid) - c2 * (inv(mid) - K) - tan_c > 0.0:
            hi = mid
        else:
            lo = mid
    D = sign * t.d_b * math.cos(t.beta_b) * (inv(0.5 * (lo + hi)) - K)
    return max(round(D / step) * step, step)


def _shift(t: Tooth) -> float:
    """Profile shift coefficient implied by the thickness: s_n = m_n(π/2 + 2x tan α) of an
    external gear; an internal gear's space width e_n = m_n(π/2 + 2x tan α) gives its shift
    in the GOST 19274-73 sign, whose shifted reference circle d + 2x·m_n lies at mid-height
    of the internal teeth as well (the ideal balls KISSsoft prints for the NREL rings touch
    there, [KISSsoft2017])."""
    return (t.s_n / t.m_n - 0.5 * math.pi) / (2.0 * math.tan(t.alpha_n))


# ----------------------------------------------------------------------------- chords


@dataclass(frozen=True)
class Chordal:
    s_c: float   # chordal tooth thickness (normal section, reference circle)
    h_c: float   # chordal height from the tip circle


def chordal(t: Tooth, s_n: float | None = None) -> Chordal:
    """Chordal tooth thickness and height at the reference circle, in the normal section of
    a helical gear on the virtual spur gear d_n = d / cos²β_b ([ISO21771] 6.2; [GOST16532]):

    .. math:: ψ = \\frac{s_n}{d_n}, \\quad \\bar s = d_n \\sin ψ, \\quad
              \\bar h = h_a + \\tfrac12 d_n (1 - \\cos ψ), \\quad h_a = \\tfrac12 (d_a - d)

    An internal gear (``t.internal``; ``s_n`` is then its space width e_n) has the tooth
    thickness π m_n − e_n; its tip points to the axis, so the chord lies between the tip and
    the arc: h_a = ½(d − d_a), h̄ = h_a − ½ d_n (1 − cos ψ) (the geometry of the circle; the
    KISSsoft reports of the NREL rings agree to 0.0005 mm, [KISSsoft2017]).

    >>> s_n = 10 * (math.pi / 2 + 0.6 * math.tan(math.radians(20)))     # m = 10, x = 0.3
    >>> c = chordal(Tooth(12, 10.0, math.radians(20), 0.0, s_n, 146.0, 110.0))
    >>> round(c.s_c, 4), round(c.h_c, 4)
    (17.8256, 13.6657)
    """
    s = t.s_n if s_n is None else s_n
    d_n = t.d / math.cos(t.beta_b) ** 2
    if t.internal:
        s = math.pi * t.m_n - s
    psi = s / d_n
    rise = 0.5 * d_n * (1.0 - math.cos(psi))
    if t.internal:
        return Chordal(d_n * math.sin(psi), 0.5 * (t.d - t.d_a) - rise)
    return Chordal(d_n * math.sin(psi), 0.5 * (t.d_a - t.d) + rise)


def constant_chord(t: Tooth, s_n: float | None = None) -> Chordal:
    """Constant chord (the chord between the points where the basic rack touches the flanks)
    and its height from the tip circle ([GOST16532]; [KHK]):

    .. math:: \\bar s_c = s_n \\cos^2 α_n, \\qquad \\bar h_c = h_a - \\tfrac12 \\bar s_c \\tan α_n

    An internal gear (``t.internal``, ``s_n`` its space width e_n) has the tooth thickness
    π m_n − e_n; its tooth widens away from the axis, so the rack's contact points lie
    between the reference circle and its (inner) tip, ½ s̄_c tan α_n from the reference
    line: the same height formula with h_a = ½(d − d_a) (the rack geometry mirrored).
    """
    s = t.s_n if s_n is None else s_n
    if t.internal:
        s = math.pi * t.m_n - s
    s_c = s * math.cos(t.alpha_n) ** 2
    h_a = 0.5 * (t.d - t.d_a) if t.internal else 0.5 * (t.d_a - t.d)
    return Chordal(s_c, h_a - 0.5 * s_c * math.tan(t.alpha_n))


# ----------------------------------------------------------------------------- span


def span(z: int, x: float, m_n: float, alpha_n: float, beta: float, k: int,
         d_low: float, d_a: float, b: float, key: str) -> tuple[float, float]:
    """Span W over ``k`` teeth and the diameter d_W where the calliper touches (external
    gear; :func:`geardesign.gears.span.base_tangent_length`).  A k for which the calliper
    would not touch the flanks between ``d_low`` and the tip (or, helical, the face is
    narrower than W·sin β_b) raises :class:`MeasurementError` naming ``key``."""
    alpha_t = math.atan(math.tan(alpha_n) / math.cos(beta))
    beta_b = math.asin(math.sin(beta) * math.cos(alpha_n))
    d = z * m_n / math.cos(beta)
    d_b = d * math.cos(alpha_t)
    if not 1 <= k < z:
        raise MeasurementError(key, k, f"must be 1…{z - 1} (fewer than the {z} teeth)")
    _, W, d_W = base_tangent_length(z, x, m_n, alpha_n, alpha_t, beta_b, d, d_b, k)
    if not span_measurable(W, d_W, d_low, d_a, beta_b, b):
        ok = [j for j in range(1, z) if span_measurable(
            *base_tangent_length(z, x, m_n, alpha_n, alpha_t, beta_b, d, d_b, j)[1:],
            d_low, d_a, beta_b, b)]
        where = ("the face is narrower than W·sin β_b" if d_low - 1e-9 <= d_W <= d_a + 1e-9
                 else f"the calliper would touch at d = {d_W:.4f} mm, outside the involute "
                      f"{d_low:.4f}…{d_a:.4f} mm")
        advice = (f"use k = {ok[0]}…{ok[-1]}" if len(ok) > 1 else f"use k = {ok[0]}") if ok \
            else "no k is measurable on this gear; use balls or the chordal thickness"
        raise MeasurementError(key, k, f"impossible span: {where}; {advice}")
    return W, d_W
