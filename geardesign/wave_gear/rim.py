"""Bending stiffness of the toothed rim of a flexible wheel: the factor K_zh of Tkachenko,
Ustinenko and Borisenko ([Tkachenko2017]).

The rim under the teeth has the thickness H0; over one pitch p = π·m the teeth add the
height h(x) (the tooth-space profile cut by the hob).  Bending a slice of thickness H0 + h
needs (H0 + h)³/H0³ times the moment of the smooth rim, so the toothed rim is stiffer, and
under the same imposed deflection its stress in the tooth spaces is K_zh times that of a
smooth rim of thickness H0:

    K_zh = 1/a0,   a0 = (1/p)·∫ over one pitch of (H0/(H0 + h(x)))³ dx      (eqs. (4), (5))

with the tooth height limited to an effective h = 0.45·m (the tooth tips do not bend with
the rim; calibrated by the authors' cantilever tests of five steel racks).  Lengths in
module units (m = 1) unless stated.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class RackSpace:
    """The tooth-space profile of a gear cut by a hob with the basic rack (module 1).

    x runs from the middle of the tooth space (x = 0) to the middle of the tooth
    (x = π/2); y is the height above the root line.
    """

    alpha: float    # pressure angle [rad]
    depth: float    # root line to pitch line, h_a* + c*
    height: float   # whole tooth height, 2·h_a* + c*
    rho: float      # root fillet radius ρ_f*
    x_c: float      # half-width of the flat bottom (fillet centre abscissa)
    x_t: float      # fillet/flank tangency abscissa
    y_t: float      # its height
    w0: float       # where the straight flank meets the root line


def rack_space(alpha: float, h_a: float = 1.0, c: float = 0.25, rho_f: float = 0.38) -> RackSpace:
    """Tooth-space profile of the basic rack (GOST 13755-81: α = 20°, h_a* = 1, c* = 0.25,
    ρ_f* = 0.38): a flat bottom, a fillet of radius ρ_f tangent to it and to the straight
    flank inclined at α, the flank up to the tip at 2h_a* + c*.

    The straight flank meets the root line at w0 = π/4 − (h_a* + c*)·tan α (half the space
    width, the space being π/2 wide on the pitch line); the fillet touches the bottom at
    x_c = w0 − ρ_f·tan(45° − α/2) and the flank at (x_c + ρ_f·cos α, ρ_f·(1 − sin α)).
    Standard values: x_c = 0.0644, tangency height 0.25 ([Tkachenko2017] eqs. (4), (5)).

    Raises ValueError when the fillet does not fit (x_c < 0).
    Reference: GOST 13755-81 basic rack; [Tkachenko2017] eqs. (4), (5).

    Example: the GOST 13755-81 rack gives the standard values above, x_c = 0.0644 and a
    tangency height of 0.25 ([Tkachenko2017]):

    >>> import math
    >>> s = rack_space(math.radians(20.0))
    >>> round(s.x_c, 4), round(s.y_t, 2)
    (0.0644, 0.25)
    """
    depth = h_a + c
    w0 = math.pi / 4.0 - depth * math.tan(alpha)
    x_c = w0 - rho_f * math.tan(math.pi / 4.0 - alpha / 2.0)
    if x_c < 0.0:
        raise ValueError(f"root fillet ρ_f* = {rho_f} does not fit the tooth space "
                         f"(flat bottom half-width {x_c:.4f} < 0)")
    return RackSpace(alpha=alpha, depth=depth, height=2.0 * h_a + c, rho=rho_f, x_c=x_c,
                     x_t=x_c + rho_f * math.cos(alpha), y_t=rho_f * (1.0 - math.sin(alpha)),
                     w0=w0)


def _simpson(f, a: float, b: float, n: int = 256) -> float:
    if b <= a:
        return 0.0
    h = (b - a) / n
    s = f(a) + f(b)
    for i in range(1, n):
        s += (4.0 if i % 2 else 2.0) * f(a + i * h)
    return s * h / 3.0


def mean_cube(H0: float, rack: RackSpace, h_cap: float) -> float:
    """a0 = (2/p)·∫_0^{p/2} (H0/(H0 + min(h(x), h_cap)))³ dx over half a pitch (module 1).

    Pieces: flat bottom (integrand 1); fillet, y = ρ(1 − cos θ), x = x_c + ρ sin θ, by
    Simpson's rule in θ; straight flank in closed form, dx = tan α·dy:
    ∫(H0/(H0 + y))³ dx = tan α·H0³/2·[1/(H0 + y1)² − 1/(H0 + y2)²]; the rest of the half
    pitch at the capped height (or the tip).

    Parameters: H0 rim thickness under the teeth and h_cap the effective tooth height, both
    in module units.  Reference: Tkachenko et al. 2017, eq. (5) (reconstructed).
    """
    H = H0
    cap = min(h_cap, rack.height)
    half = math.pi / 2.0

    def g(y: float) -> float:
        return (H / (H + y)) ** 3

    total = rack.x_c                                   # flat bottom
    rho = rack.rho
    y_end = min(cap, rack.y_t)                         # fillet up to the cap or the flank
    th_end = math.acos(1.0 - y_end / rho) if rho > 0 else 0.0
    total += _simpson(lambda t: g(rho * (1.0 - math.cos(t))) * rho * math.cos(t), 0.0, th_end)
    x = rack.x_c + rho * math.sin(th_end)
    if cap > rack.y_t:                                 # straight flank up to the cap
        ta = math.tan(rack.alpha)
        total += ta * H ** 3 / 2.0 * (1.0 / (H + rack.y_t) ** 2 - 1.0 / (H + cap) ** 2)
        x = rack.w0 + cap * ta
    total += (half - x) * g(cap)                      # capped (or tip) plateau
    return total / half


def stiffness_factor(H0: float, rack: RackSpace, h_eff: float) -> float:
    """K_zh = 1/a0 with the tooth height limited to h_eff (module units), eq. (4)."""
    return 1.0 / mean_cube(H0, rack, h_eff)


def shift_rule(z: int, rule: str) -> float:
    """Recommended profile shift of the flexible wheel teeth quoted by the paper:
    eq. (7) x = 2.15 + 0.009·z_g, eq. (8) x = 0.022·z_g."""
    return 2.15 + 0.009 * z if rule == "eq7" else 0.022 * z
