"""Geometry of a Novikov DLZ pair on a circular-arc basic rack, the axial overlap, the
theoretical contact points of both lines of action along the face (Korotkin's Table 1)
phase by phase, and the minimum face width criteria of the cyclogram paper.

Pure functions on plain data; lengths in mm, angles in radians.  Index 1 is the driving
pinion, 2 the driven wheel.  j = 1 marks a contact point on the pinion addendum (line of
action 1: pinion addendum on wheel dedendum), j = 2 a point on the wheel addendum.

References: Korotkin 2017 (Table 1, phase stepping; [Korotkin2017] table 1); Cyclogram 2017
(criteria 1 and 2, [Matyushenko2017], with the sign of criterion 2
corrected); GOST 15023-76 (rack, unverified values, [GOST15023]).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.novikov.rack import NovikovRack

B_TOL = 1e-9
"""A point with −B_TOL ≤ b ≤ 1 + B_TOL is inside the face (Korotkin counts 0 ≤ b ≤ 1)."""


class GeometryError(ValueError):
    """The input admits no pair; ``code`` names the rule, ``limit`` the bound."""

    def __init__(self, code: str, message: str, limits: tuple = ()):
        super().__init__(message)
        self.code = code
        self.limits = limits


def helix_for_center_distance(a_w: float, m: float, z1: int, z2: int) -> float:
    """Helix angle for a given centre distance (x1 + x2 = 0):

    .. math:: \\cos β = \\frac{m (z_1 + z_2)}{2 a_w}

    Raises :class:`GeometryError` when a_w ≤ m(z1+z2)/2 (no helix angle exists).
    Reference: theory of gearing; Korotkin 2017 chooses β so that a_w = 450 mm.

    Example: a_w = a_0/cos 10° gives β = 10° (identity, a_0 = 5·(20 + 30)/2 = 125 mm):

    >>> import math
    >>> round(math.degrees(helix_for_center_distance(125.0 / math.cos(math.radians(10.0)),
    ...                                               5.0, 20, 30)), 9)
    10.0
    """
    a0 = 0.5 * m * (z1 + z2)
    if a_w <= a0:
        raise GeometryError("A_W_SMALL", f"a_w = {a_w} mm <= m(z1 + z2)/2 = {a0} mm", (a0,))
    return math.acos(a0 / a_w)


@dataclass(frozen=True)
class NovikovPair:
    """Input of a pair.  ``beta`` [rad], ``b_w`` [mm], shifts x1 = −x2 (checked upstream)."""

    m: float
    z1: int
    z2: int
    beta: float
    b_w: float
    x1: float
    x2: float
    rack: NovikovRack


@dataclass(frozen=True)
class PairGeometry:
    inp: NovikovPair
    u: float
    d1: float
    d2: float
    a_w: float
    d_a1: float
    d_a2: float
    d_f1: float
    d_f2: float
    p_t: float
    p_x: float
    eps_beta: float
    z_v1: float
    z_v2: float
    l_k: float
    rho_p: float


def pair_geometry(p: NovikovPair) -> PairGeometry:
    """Diameters, pitches and the axial overlap of a Novikov DLZ pair.

    .. math::
        d_i = \\frac{m z_i}{\\cos β}, \\quad a_w = \\frac{d_1 + d_2}{2}, \\quad
        p_x = \\frac{π m}{\\sin β}, \\quad ε_β = \\frac{b_w}{p_x}, \\quad
        z_{vi} = \\frac{z_i}{\\cos^3 β}, \\quad l_k = l_k^* m

        d_{ai} = d_i + 2(h_a^* + x_i)m, \\quad d_{fi} = d_i − 2(h_f^* − x_i)m

    ρ_p, the reduced lengthwise radius of curvature of the contacting surfaces, is the
    reconstruction of [Korotkin2017] eq. (4) (Meusnier's theorem at R_K ≈ r):

    .. math:: ρ_p = \\frac{a_w u}{(u + 1)^2 \\sin^2 β \\sin α_k}

    Reference: Korotkin 2017 (G1–G7 of [Korotkin2017]: ε_β = 2.33849 of the printed
    example is reproduced); h_a*, h_f*: GOST 15023-76 (from memory, unverified).
    """
    m, beta, r = p.m, p.beta, p.rack
    cb = math.cos(beta)
    d1 = m * p.z1 / cb
    d2 = m * p.z2 / cb
    a_w = 0.5 * (d1 + d2)
    u = p.z2 / p.z1
    p_x = math.pi * m / math.sin(beta)
    rho_p = a_w * u / ((u + 1.0) ** 2 * math.sin(beta) ** 2 * math.sin(r.alpha_k))
    return PairGeometry(
        inp=p, u=u, d1=d1, d2=d2, a_w=a_w,
        d_a1=d1 + 2.0 * (r.h_a + p.x1) * m, d_a2=d2 + 2.0 * (r.h_a + p.x2) * m,
        d_f1=d1 - 2.0 * (r.h_f - p.x1) * m, d_f2=d2 - 2.0 * (r.h_f - p.x2) * m,
        p_t=math.pi * m / cb, p_x=p_x, eps_beta=p.b_w / p_x,
        z_v1=p.z1 / cb ** 3, z_v2=p.z2 / cb ** 3, l_k=r.lk_star * m, rho_p=rho_p)


# ----------------------------------------------------------------------------- Table 1


@dataclass(frozen=True)
class TheoreticalPoint:
    """A theoretical contact point of Korotkin's Table 1: serial number ``i``, tooth
    (pair) number ``zub``, line ``j`` and its position ``b1`` in phase 1 (fraction of
    b_w from the reference face end, where the points enter)."""

    i: int
    zub: int
    j: int
    b1: float


def table1_points(eps_beta: float, eps_q: float) -> list[TheoreticalPoint]:
    """The theoretical contact points in phase 1 (Korotkin 2017, Table 1):

    i = 0: zub 1, j = 2, b = −(1 − ε_q)/ε_β;  i = 1 (base point): zub 2, j = 1, b = 0;
    then for zub ≥ 2: j = 1 at b = (zub − 2)/ε_β and j = 2 at b = (zub − 2 + ε_q)/ε_β,
    i = 2(zub − 2) + j.

    The paper lists zub 1…7 (ε_β up to about 5); here as many teeth are generated as can
    reach the face: zub ≤ ⌈ε_β⌉ + 2 (paper B eq. (1): z = b_w/p_x + 1 teeth share the load).
    """
    out = [TheoreticalPoint(0, 1, 2, -(1.0 - eps_q) / eps_beta)]
    for zub in range(2, math.ceil(eps_beta) + 3):
        out.append(TheoreticalPoint(2 * (zub - 2) + 1, zub, 1, (zub - 2) / eps_beta))
        out.append(TheoreticalPoint(2 * (zub - 2) + 2, zub, 2, (zub - 2 + eps_q) / eps_beta))
    return out


def phase_step(eps_beta: float, phases: int) -> float:
    """Δb = p_x/(b_w f_z) = 1/(ε_β f_z): shift of every point from one phase to the next
    (Korotkin 2017; the printed example gives db = 0.020363)."""
    return 1.0 / (eps_beta * phases)


@dataclass(frozen=True)
class PhasePoint:
    """A theoretical point inside the face in phase ``k`` (1-based): ``b`` fraction of b_w,
    ``t = |0.5 − b|`` distance from mid-face."""

    k: int
    i: int
    zub: int
    j: int
    b: float

    @property
    def t(self) -> float:
        return min(abs(0.5 - self.b), 0.5)


def phase_points(points: list[TheoreticalPoint], eps_beta: float, phases: int
                 ) -> list[list[PhasePoint]]:
    """The points inside the face (0 ≤ b ≤ 1) in each phase k = 1 … f_z, with
    b_i(k) = b_i(1) + (k − 1)·Δb (Korotkin 2017)."""
    db = phase_step(eps_beta, phases)
    out = []
    for k in range(1, phases + 1):
        row = []
        for p in points:
            b = p.b1 + (k - 1) * db
            if -B_TOL <= b <= 1.0 + B_TOL:
                row.append(PhasePoint(k, p.i, p.zub, p.j, min(max(b, 0.0), 1.0)))
        out.append(row)
    return out


def engaged_teeth(rows: list[list[PhasePoint]]) -> list[int]:
    """Tooth (pair) numbers that come into contact during one axial pitch."""
    return sorted({p.zub for row in rows for p in row})


# ----------------------------------------------------------------------------- cyclogram


def min_face_width(n_points: int, p_x: float, delta: float) -> float:
    """Least face width b_w for at least ``n_points`` simultaneous contact points at every
    instant (Cyclogram 2017, criteria 1 and 2; [Matyushenko2017]):

    * n = 2k (criterion 1):    b_w ≥ k·p_x
    * n = 2k + 1 (criterion 2): b_w ≥ (1 + k)·p_x − |q_21 − n'·p_x| = (k + 1 − δ)·p_x

    with δ = |q_21/p_x − n'| ≤ 0.5 the distance of ε_q = q_21/p_x to its nearest integer
    n'.  The printed criterion 2 reads "+|q_21 − n'p_x|", a misprint: the paper's own
    Table 1 (row "3" = 2 − δ in all five columns) and the coverage argument need "−".
    n = 1 (k = 0) is the continuity condition b_w ≥ (1 − δ)·p_x (the paper's base case).
    """
    if n_points < 1:
        raise ValueError("n_points must be >= 1")
    k, odd = divmod(n_points, 2)
    if odd:
        return (k + 1 - delta) * p_x
    return k * p_x


@dataclass(frozen=True)
class Coverage:
    """Closed-form counts of simultaneous contact points over one axial pitch
    ([Matyushenko2017], independent derivation): K = ⌊ε_β⌋, r = {ε_β}."""

    n_min: int
    n_max: int
    fraction_max: float


def coverage(eps_beta: float, delta: float) -> Coverage:
    """Least and greatest number of points in contact and the fraction of the cycle with
    the greatest number.

    Each line of action has K + 1 points during a fraction r of the cycle and K otherwise;
    the second line is phase-shifted by ε_q.  Hence n_min = 2K + 1 if r ≥ 1 − δ else 2K;
    n_max = 2K + 2 if r > δ, 2K + 1 if 0 < r ≤ δ, 2K if r = 0; the fraction with n_max
    points is max(0, r − δ) + max(0, r − (1 − δ)) when n_max = 2K + 2, else 2r (r > 0) or 1.
    Consistent with criteria 1–2 of Cyclogram 2017 (:func:`min_face_width`).
    """
    K = math.floor(eps_beta + 1e-12)
    r = eps_beta - K
    if r < 1e-12:
        r = 0.0
    n_min = 2 * K + 1 if r >= 1.0 - delta - 1e-12 else 2 * K
    if r > delta + 1e-12:
        n_max = 2 * K + 2
        frac = max(0.0, r - delta) + max(0.0, r - (1.0 - delta))
    elif r > 0.0:
        n_max, frac = 2 * K + 1, 2.0 * r
    else:
        n_max, frac = 2 * K, 1.0
    if n_min == n_max:
        frac = 1.0
    return Coverage(n_min, n_max, min(frac, 1.0))
