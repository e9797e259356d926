"""Involute functions shared by every involute-gear calculator (spur, planetary, PZDN...).

Angles are in radians throughout.
"""

from __future__ import annotations

import math


def inv(alpha: float) -> float:
    """Involute function.

    .. math:: \\operatorname{inv}\\alpha = \\tan\\alpha - \\alpha

    Parameters
    ----------
    alpha : pressure angle [rad], 0 <= alpha < pi/2.

    References
    ----------
    GOST 16532-70 (notation inv α); ISO 21771:2007 (involute function).
    """
    return math.tan(alpha) - alpha


def inv_inverse(value: float, tol: float = 1e-12) -> float:
    """Inverse of the involute function: the angle θ with ``inv θ = value``.

    Newton's iteration on f(θ) = tan θ − θ − v, f'(θ) = tan²θ:

    .. math:: θ_{k+1} = θ_k - \\frac{\\tan θ_k - θ_k - v}{\\tan^2 θ_k},
              \\qquad θ_0 = (3v)^{1/3}

    The start value is the first term of the series inv θ = θ³/3 + 2θ⁵/15 + …, from which
    the iteration converges monotonically (f is convex on (0, π/2)); a few steps reach
    |Δθ| < ``tol``.

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
    ``shared/methods/spur_helical.md`` §8.2 item 3 (Newton start value); the function
    itself: GOST 16532-70, table 1, item "inv α_tw".
    """
    if not value > 0.0 or not math.isfinite(value):
        raise ValueError(f"inv θ = {value!r}: the inverse involute needs a value > 0")
    theta = (3.0 * value) ** (1.0 / 3.0)
    theta = min(theta, 1.5)
    for _ in range(100):
        t = math.tan(theta)
        step = (t - theta - value) / (t * t)
        theta_new = theta - step
        if theta_new <= 0.0:
            theta_new = theta / 2.0
        if abs(theta_new - theta) < tol:
            return theta_new
        theta = theta_new
    raise ValueError(f"inverse involute of {value!r} did not converge")
