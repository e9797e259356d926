"""The largest eigenvalue of a symmetric tridiagonal matrix (pure Python): the step of the
Lanczos process of the shaft's critical speed (:func:`geardesign.shaft.beam._largest_mu`)."""

from __future__ import annotations


def largest_eigenvalue(alpha: list[float], beta: list[float], below: float) -> float:
    """Largest eigenvalue of the symmetric tridiagonal matrix of diagonal ``alpha`` and
    off-diagonal ``beta``, at least ``below`` (the largest of its leading block, by
    interlacing).  Newton's method on its characteristic polynomial p(θ) from above its
    largest root, where it descends monotonically ([GolubVanLoan] §8.4.1: p_r(θ) =
    (α_r − θ)·p_{r−1}(θ) − β_{r−1}²·p_{r−2}(θ), here as the pivots d_r = p_r/p_{r−1}, all
    negative above the spectrum, and p'/p = Σ d_r'/d_r).  The start: the largest
    eigenvalue of the leading block and α_k, raised by β_{k−1} (Weyl's bound).

    Example: [[2, 1], [1, 2]] has the eigenvalues 1 and 3; [[2, 1, 0], [1, 2, 1], [0, 1, 2]]
    has 2 − √2, 2 and 2 + √2:

    >>> largest_eigenvalue([2.0, 2.0], [1.0], 2.0)
    3.0
    >>> round(largest_eigenvalue([2.0, 2.0, 2.0], [1.0, 1.0], 3.0), 12) == round(2 + 2 ** 0.5, 12)
    True
    """
    k = len(alpha)
    if k == 1:
        return alpha[0]
    theta = max(below, alpha[-1]) + beta[-1]
    for _ in range(100):
        d, dd = alpha[0] - theta, -1.0         # pivot and its derivative in θ
        ratio = 0.0
        for r in range(k):
            if r:
                bb = beta[r - 1] * beta[r - 1]
                d, dd = alpha[r] - theta - bb / d, -1.0 + bb * dd / (d * d)
            if not d < 0.0:                    # not above the spectrum: at its top
                return theta                   # to rounding
            ratio += dd / d
        if not ratio > 0.0:                    # at the root to rounding
            return theta
        step = 1.0 / ratio                     # p/p' (> 0 above the largest root)
        if not step > 0.0:
            return theta
        theta -= step
        if step <= 1e-15 * abs(theta):         # quadratic convergence: settled
            return theta
    return theta
