"""Involute functions shared by every involute-gear calculator (spur, planetary, PZDN...).

Angles are in radians throughout.
"""

from __future__ import annotations

import math

from geardesign.core import xp


def inv(alpha: float) -> float:
    """Involute function.

    .. math:: \\operatorname{inv}\\alpha = \\tan\\alpha - \\alpha

    Parameters
    ----------
    alpha : pressure angle [rad], 0 <= alpha < pi/2.

    References
    ----------
    GOST 16532-70 (notation inv α); ISO 21771:2007 (involute function).

    Examples: inv 0 = 0, and inv 20° = tan 20° − π/9 = 0.363970 − 0.349066 = 0.014904 (the
    value of the involute tables of GOST 16532-70):

    >>> import math
    >>> inv(0.0)
    0.0
    >>> round(inv(math.radians(20.0)), 6)
    0.014904
    """
    return xp.tan(alpha) - alpha


def inv_inverse(value: float, tol: float = 1e-12) -> float:
    """Inverse of the involute function: the angle θ with ``inv θ = value``.

    Newton's iteration on f(θ) = tan θ − θ − v, f'(θ) = tan²θ:

    .. math:: θ_{k+1} = θ_k - \\frac{\\tan θ_k - θ_k - v}{\\tan^2 θ_k},
              \\qquad θ_0 = (3v)^{1/3}

    The start value is the first term of the series inv θ = θ³/3 + 2θ⁵/15 + …; a few
    steps reach |Δθ| < ``tol``.  Each step is kept inside the bracket of the root (a step
    that leaves it is replaced by bisection), so values near π/2 converge too.

    Parameters
    ----------
    value : inv θ, must be > 0.
    tol : absolute tolerance on θ [rad].

    Returns
    -------
    θ [rad], 0 < θ < π/2.

    Raises
    ------
    ValueError if ``value <= 0`` or the iteration does not converge.

    References
    ----------
    [GOST16532] table 1 (Newton start value); the function
    itself: GOST 16532-70, table 1, item "inv α_tw".

    Example: the inverse of :func:`inv` (identity):

    >>> round(inv_inverse(inv(0.35)), 12)
    0.35
    """
    if not value > 0.0 or not math.isfinite(value):
        raise ValueError(f"inv θ = {value!r}: the inverse involute needs a value > 0")
    # Newton safeguarded by the bracket [lo, hi]: a step that leaves it is replaced by
    # bisection, so the iteration cannot jump past π/2 (large values) or below 0.
    lo, hi = 0.0, 0.5 * math.pi
    theta = min((3.0 * value) ** (1.0 / 3.0), 1.5)
    for _ in range(200):
        t = math.tan(theta)
        f = t - theta - value
        if f > 0.0:
            hi = theta
        else:
            lo = theta
        step = f / (t * t)
        if abs(step) < tol:
            return theta - step
        theta_new = theta - step
        if not lo < theta_new < hi:
            theta_new = 0.5 * (lo + hi)
        theta = theta_new
    raise ValueError(f"inverse involute of {value!r} did not converge")


def inv_inverse_array(value, tol: float = 1e-12):
    """:func:`inv_inverse` of a numpy array of values > 0, element by element the same
    safeguarded Newton iteration (each element stops at its own step below ``tol``)."""
    import numpy as np

    v = np.asarray(value, dtype=float)
    if not np.all(v > 0.0) or not np.all(np.isfinite(v)):
        raise ValueError("the inverse involute needs values > 0")
    # every element iterates on the whole array (no gathers of the unfinished ones, which
    # cost more than the arithmetic); an element's result is fixed at its own last step
    lo = np.zeros_like(v)
    hi = np.full_like(v, 0.5 * math.pi)
    theta = np.minimum(np.cbrt(3.0 * v), 1.5)
    out = np.full_like(v, np.nan)
    todo = np.ones(v.shape, dtype=bool)
    with np.errstate(all="ignore"):     # finished elements keep iterating, unread
        for _ in range(200):
            t = np.tan(theta)
            f = t - theta - v
            up = f > 0.0
            np.copyto(hi, theta, where=up)
            np.copyto(lo, theta, where=~up)
            step = f / (t * t)
            fin = np.abs(step) < tol
            fin &= todo
            np.copyto(out, theta - step, where=fin)
            todo &= ~fin
            if not todo.any():
                return out
            theta -= step
            bad = lo < theta
            bad &= theta < hi
            np.logical_not(bad, out=bad)
            np.copyto(theta, 0.5 * (lo + hi), where=bad)
    raise ValueError("inverse involute did not converge")
