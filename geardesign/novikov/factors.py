"""Phase factors of Korotkin's method: compliance ratio K_W, bending and contact ratios
K_F, K_H, shear correction K_ψ, 3-D tooth form factor Y_v.

All fitted factors are evaluated inside their validity range only: ψ is clamped to
[0.05, 0.25] and t to [0, 0.5] (:func:`clamp_psi`); the caller reports when clamping
happened.  t is the distance of the contact point from mid-face as a fraction of b_w,
ψ = a/b_w the semi-major axis of the contact ellipse over the face width.

Reference: Korotkin 2017, eq. (1), (5), (6), Tables 2–4 and the Y_v formulas
([Korotkin2017] eq. (3), eq. (1), tables 2-4).
"""

from __future__ import annotations

from geardesign.novikov.tables import (
    KF_COEFFS,
    KH_PSI,
    KH_ROWS,
    KPSI_COEFFS,
    KW_COEFFS,
    PSI_RANGE,
    T_RANGE,
    YV_BRANCHES,
    YV_SPLIT_ZV,
)


def clamp_psi(psi: float) -> float:
    """ψ clamped to the validity range [0.05, 0.25] of the fitted tables."""
    lo, hi = PSI_RANGE
    return min(max(psi, lo), hi)


def clamp_t(t: float) -> float:
    """t clamped to [0, 0.5]."""
    lo, hi = T_RANGE
    return min(max(t, lo), hi)


def psi_in_range(psi: float) -> bool:
    lo, hi = PSI_RANGE
    return lo - 1e-12 <= psi <= hi + 1e-12


def _horner(c: tuple[float, ...], x: float) -> float:
    s = 0.0
    for ci in reversed(c):
        s = s * x + ci
    return s


def _poly4(coeffs: tuple[tuple[float, ...], ...], t: float, psi: float) -> float:
    """Σ_p (ψ+0.1)^(−p)·Σ_q C_pq·(t − 0.05)^q, with t and ψ clamped."""
    u = clamp_t(t) - 0.05
    s = 1.0 / (clamp_psi(psi) + 0.1)
    total, w = 0.0, 1.0
    for row in coeffs:
        total += w * _horner(row, u)
        w *= s
    return total


def k_w(t: float, psi: float) -> float:
    """Compliance ratio K_W: the bending-plus-contact displacement of a contact point at t
    over the displacement at mid-face under the same force, Korotkin 2017 eq. (1):

    .. math:: K_W = \\sum_{q=0}^{6} B_{0q}u^q + (ψ+0.1)^{-1}\\sum_{q=0}^{3} B_{1q}u^q
              + (ψ+0.1)^{-2}\\sum_{q=0}^{4} B_{2q}u^q + (ψ+0.1)^{-3}\\sum_{q=0}^{6} B_{3q}u^q,
              \\quad u = t − 0.05

    Parameters: t, ψ (fractions of b_w; clamped to [0, 0.5] and [0.05, 0.25]).
    Returns K_W ≈ 1 at mid-face, 1.6–2.0 at the face end.  Coefficients: Table 2.
    """
    return _poly4(KW_COEFFS, t, psi)


def k_f(t: float, psi: float) -> float:
    """Bending-stress ratio K_F (phase over base bending stress), Korotkin 2017 eq. (6)
    with Table 3 (same form as :func:`k_w`, with 9/4/9/5 coefficients)."""
    return _poly4(KF_COEFFS, t, psi)


def k_psi(psi: float) -> float:
    """Shear-deformation correction of the contact stress, Korotkin 2017 eq. (5):

    .. math:: K_ψ = −1333.333333ψ^4 + 923.9999998ψ^3 − 238.8666667ψ^2 + 26.4ψ − 0.106

    ψ is clamped to [0.05, 0.25], the range of the five nodes the quartic interpolates.

    Example: outside [0.05, 0.25] ψ is clamped, so K_ψ(0.5) = K_ψ(0.25) (identity):

    >>> k_psi(0.5) == k_psi(0.25)
    True
    """
    return _horner(KPSI_COEFFS, clamp_psi(psi))


def k_h(t: float, psi: float) -> float:
    """Contact-stress ratio K_H (phase over base contact stress): bilinear interpolation in
    Table 4 of Korotkin 2017 (rows t, columns ψ; t and ψ clamped to the table)."""
    t = clamp_t(t)
    psi = clamp_psi(psi)
    rows = KH_ROWS
    k = 0
    while k < len(rows) - 2 and t > rows[k + 1][0]:
        k += 1
    (t0, r0), (t1, r1) = rows[k], rows[k + 1]
    c = 0
    while c < len(KH_PSI) - 2 and psi > KH_PSI[c + 1]:
        c += 1
    p0, p1 = KH_PSI[c], KH_PSI[c + 1]
    ft = (t - t0) / (t1 - t0)
    fp = (psi - p0) / (p1 - p0)
    low = r0[c] + (r0[c + 1] - r0[c]) * fp
    high = r1[c] + (r1[c + 1] - r1[c]) * fp
    return low + (high - low) * ft


def y_v(z_v: float, x: float) -> float:
    """3-D ("volumetric") tooth form factor Y_v of the tooth whose addendum carries the
    load, [Korotkin2017] eq. (3):

    −0.5 ≤ x < 0:  z_v ≤ 18: Y_v = 1.18·z_v^−0.285 + 2.08·|x|^1.15·z_v^−1.32;
                   z_v > 18: Y_v = 0.52 + 1.17·|x|^1.33·z_v^−1.058
    0 ≤ x ≤ 0.3:   z_v ≤ 18: Y_v = 1.18·z_v^−0.285 − 3.59·x·z_v^−1.17;
                   z_v > 18: Y_v = 0.52 − 3.50·x·z_v^−1.16

    Parameters: z_v = z/cos³β (virtual number of teeth), x (rack shift coefficient).
    The exponents 1.17 and 1.16 of the x > 0 branch are unreadable in the source and are
    placeholders (the two z_v branches then meet at z_v = 18): a result with x > 0 is
    unverified.  The coefficient 1.18 reproduces the printed Y_ve1 = 0.542 (z_v = 15.30).
    """
    sign = "neg" if x < 0.0 else "pos"
    size = "small" if z_v <= YV_SPLIT_ZV else "large"
    a, b, p, e, q = YV_BRANCHES[(sign, size)]
    ax = abs(x)
    extra = b * (ax ** e) * z_v ** q if ax > 0.0 else 0.0
    return a * z_v ** p + extra


Y_A = 1.0
"""Y_a, the factor for the load distribution over the contact patch (Korotkin 2017).  Its
exponent is unreadable in the source ([Korotkin2017] eq. (3)); 1 is conservative (the printed
example suggests about 0.95)."""
