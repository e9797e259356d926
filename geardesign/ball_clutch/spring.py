"""Helical compression spring of round wire: rate, stress, solid length.

Lengths mm, forces N, stresses and moduli MPa.  The formulas are the textbook ones (Wahl's
curvature factor; GOST 13765-86 uses the same rate and stress relations; Budynas & Nisbett,
"Shigley's Mechanical Engineering Design", §10-2..10-4 and Table 10-1 for the end types).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

END_TYPES = ("closed_ground", "closed", "plain_ground", "plain")
"""End types of Shigley Table 10-1: squared (closed) and ground, squared, plain and ground,
plain."""

# (inactive coils added to n_a, solid length = (n_t + extra)·d): Shigley Table 10-1
_ENDS = {
    "closed_ground": (2.0, 0.0),
    "closed": (2.0, 1.0),
    "plain_ground": (1.0, 0.0),
    "plain": (0.0, 1.0),
}


def wahl_factor(C: float) -> float:
    """Wahl curvature factor K_W = (4C − 1)/(4C − 4) + 0.615/C, C = D/d (spring index).

    Reference: A. M. Wahl, "Mechanical Springs"; [Wahl]; the factor used by
    the textbook examples in ``tests/reference/ball_clutch``.

    Example: C = 6 gives 23/20 + 0.615/6 = 1.2525:

    >>> round(wahl_factor(6.0), 4)
    1.2525
    """
    return (4.0 * C - 1.0) / (4.0 * C - 4.0) + 0.615 / C


def rate(G: float, d: float, D: float, n_a: float) -> float:
    """Spring rate c = G·d⁴/(8·D³·n_a) [N/mm].

    Parameters: G shear modulus [MPa], d wire diameter [mm], D mean coil diameter [mm],
    n_a active coils.  Reference: Shigley eq. (10-9); GOST 13765-86.
    """
    return G * d ** 4 / (8.0 * D ** 3 * n_a)


def active_coils(G: float, d: float, D: float, c: float) -> float:
    """Active coils for a rate c [N/mm]: n_a = G·d⁴/(8·D³·c) (:func:`rate` solved).

    Example: the inverse of :func:`rate` (identity):

    >>> active_coils(80000.0, 2.0, 12.0, rate(80000.0, 2.0, 12.0, 8.0))
    8.0
    """
    return G * d ** 4 / (8.0 * D ** 3 * c)


def shear_stress(F: float, d: float, D: float) -> float:
    """Corrected shear stress τ = K_W·8·F·D/(π·d³) [MPa].

    Parameters: F axial force [N], d wire diameter [mm], D mean coil diameter [mm].
    Reference: Wahl; Shigley eq. (10-2) with K_W; [Wahl].
    """
    return wahl_factor(D / d) * 8.0 * F * D / (math.pi * d ** 3)


def total_coils(n_a: float, ends: str) -> float:
    """Total coils n_t = n_a + inactive coils of the end type (Shigley Table 10-1)."""
    return n_a + _ENDS[ends][0]


def solid_length(n_a: float, d: float, ends: str) -> float:
    """Solid length L_s [mm]: n_t·d (ground ends), (n_t + 1)·d (unground); Shigley Table
    10-1."""
    extra = _ENDS[ends][1]
    return (total_coils(n_a, ends) + extra) * d


@dataclass(frozen=True)
class SpringState:
    """Lengths and forces of the clutch spring [mm, N]."""

    F_pre: float        # force at the preload (clutch engaged)
    F_max: float        # force with the ball lifted out of its socket
    L_installed: float | None  # length with the preload (free length − y0)
    L_released: float | None   # length with the ball lifted
    L_solid: float | None
    L_free_min: float | None   # least free length that keeps the lifted spring off solid


def spring_state(c: float, y0: float, lift: float, L0: float | None,
                 L_s: float | None) -> SpringState:
    """Spring forces F = c·y ([Malashchenko2025] eq. (7): F_pr = c(y0 + r − r0), r − r0 = lift) and
    the lengths in the clutch."""
    F_pre, F_max = c * y0, c * (y0 + lift)
    L1 = None if L0 is None else L0 - y0
    L2 = None if L0 is None else L0 - y0 - lift
    L_min = None if L_s is None else L_s + y0 + lift
    return SpringState(F_pre, F_max, L1, L2, L_s, L_min)
