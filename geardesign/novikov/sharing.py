"""Load sharing among the simultaneous contact points: Korotkin 2017, system (2).

.. math::
    W_1 + δu_1 + Δ_1 = W_2 + δu_2 + Δ_2 = … = W_n + δu_n + Δ_n, \\qquad
    \\sum_{i=1}^{n} F_{ji} = F_Σ

W_i is the bending-plus-contact displacement of point i, W_i = K_W(t_i, ψ_i)·W_base(F_i);
δu_i + Δ_i is the gap of point i (manufacturing deviations and end relief, µm).  Forces
cannot be negative, so a point whose gap exceeds the common approach δ leaves the
contact and the actual number of points p may be smaller than the theoretical n
([Korotkin2017] system (2)).

W_base is not given by Korotkin (his ref. [3]).  Here it is linear,
W_base = F/c_p with c_p = c'·2a_ref (c' ≈ 14 N/(mm·µm) per unit length
of the contact patch, a_ref the patch semi-axis at the mean load per point), an
assumption flagged in the reports.  With it the solution is exact for a given set of K_W:

.. math:: F_i = \\frac{c_p\\,(δ − g_i)}{K_{W,i}}, \\quad
          δ = \\frac{F_Σ/c_p + \\sum_{act} g_i/K_{W,i}}{\\sum_{act} 1/K_{W,i}}

over the active points (g_i < δ), found by adding points in order of increasing gap.
ψ_i = a(F_i)/b_w and K_W(t_i, ψ_i) are then updated until the forces settle.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.novikov.factors import k_w
from geardesign.novikov.stress import psi_of_force

MAX_ITER = 200
REL_TOL = 1e-10


@dataclass(frozen=True)
class Sharing:
    """Solution of system (2) for one phase and one set of gaps."""

    F: tuple[float, ...]        # N, per point, in input order
    psi: tuple[float, ...]      # ψ = a/b_w per point (unclamped; 0 for unloaded points)
    K_W: tuple[float, ...]      # compliance ratios used
    delta: float                # common approach δ [µm]
    active: int                 # number p of loaded points
    iterations: int


def _solve_linear(F_sum: float, c_p: float, gaps: list[float], kw: list[float]
                  ) -> tuple[list[float], float, int]:
    order = sorted(range(len(gaps)), key=lambda i: gaps[i])
    s1 = s2 = 0.0
    delta = 0.0
    p = 0
    for n, i in enumerate(order):
        s1 += 1.0 / kw[i]
        s2 += gaps[i] / kw[i]
        delta = (F_sum / c_p + s2) / s1
        p = n + 1
        if n + 1 == len(order) or delta <= gaps[order[n + 1]]:
            break
    F = [c_p * max(0.0, delta - g) / k for g, k in zip(gaps, kw)]
    return F, delta, p


def share_load(F_sum: float, t: list[float], gaps: list[float], c_p: float, k_a: float,
               b_w: float) -> Sharing:
    """Solve system (2) for the points at distances ``t`` from mid-face with ``gaps`` [µm].

    Parameters
    ----------
    F_sum : total force F_Σ [N] (> 0).
    t : |0.5 − b_i| of each point.
    gaps : δu_i + Δ_i [µm]; only differences matter.
    c_p : base stiffness of one contact point [N/µm].
    k_a : ellipse coefficient, a = k_a·√F [mm/√N] (:func:`stress.ellipse_coefficient`).
    b_w : face width [mm].
    """
    n = len(t)
    if n == 0:
        raise ValueError("no contact point")
    kw = [k_w(ti, 0.0) for ti in t]
    F, delta, p = _solve_linear(F_sum, c_p, gaps, kw)
    it = 0
    for it in range(1, MAX_ITER + 1):
        psi = [psi_of_force(f, k_a, b_w) for f in F]
        kw = [k_w(ti, ps) for ti, ps in zip(t, psi)]
        F_new, delta, p = _solve_linear(F_sum, c_p, gaps, kw)
        change = max(abs(a - b) for a, b in zip(F_new, F))
        F = F_new
        if change <= REL_TOL * F_sum:
            break
    psi = [psi_of_force(f, k_a, b_w) for f in F]
    return Sharing(tuple(F), tuple(psi), tuple(kw), delta, p, it)
