"""Hertz contact of a ball in its socket (point contact of two bodies of revolution)."""

from __future__ import annotations

import math


def effective_modulus(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """E* with 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2 [MPa].

    Reference: K. L. Johnson, "Contact Mechanics" (1985), eq. (4.22).

    Example: steel on steel, E = 2.1·10⁵ MPa, ν = 0.3: E* = E/(2(1 − ν²)) = 115 385 MPa:

    >>> round(effective_modulus(2.1e5, 0.3, 2.1e5, 0.3))
    115385
    """
    return 1.0 / ((1.0 - nu1 ** 2) / E1 + (1.0 - nu2 ** 2) / E2)


def ball_contact(F: float, d_ball: float, socket_radius: float | None, E_star: float) -> tuple:
    """Peak contact pressure and contact radius of a ball pressed into a socket.

    .. math:: \\frac1R = \\frac{2}{d_b} - \\frac1{R_s},\\quad
              a = \\left(\\frac{3FR}{4E^*}\\right)^{1/3},\\quad
              p_0 = \\frac{3F}{2πa^2} = \\left(\\frac{6FE^{*2}}{π^3R^2}\\right)^{1/3}

    A conical socket (or a flat flank) touches the ball like a plane, R_s = ∞; a spherical
    socket of radius R_s > d_b/2 is concave (conformity lowers p0).

    Parameters: F normal force [N], d_ball [mm], socket_radius [mm] or None (plane),
    E_star [MPa].  Returns (p0 [MPa], a [mm]).
    Reference: K. L. Johnson, "Contact Mechanics" (1985), §4.2, eqs. (4.22)-(4.23).
    """
    inv_R = 2.0 / d_ball - (0.0 if socket_radius is None else 1.0 / socket_radius)
    R = 1.0 / inv_R
    a = (3.0 * F * R / (4.0 * E_star)) ** (1.0 / 3.0)
    p0 = 3.0 * F / (2.0 * math.pi * a * a)
    return p0, a
