"""ISO 6336-6:2019 — service life under variable load: Palmgren–Miner damage sum of a load
spectrum on the S-N curves of ISO 6336-2 (contact) and ISO 6336-3 (bending).

Pure functions.  The S-N curve is given as a callable σ_G(N_L) [MPa] (the limit stress with
its life and influence factors at N_L cycles, falling with N_L); a block stress above it at
N_L ≤ the static point has no life.
"""

from __future__ import annotations

import math
from typing import Callable, Sequence
from geardesign.core.roots import bracket_root

N_MIN = 1.0
N_MAX = 1e10
"""Beyond 10¹⁰ cycles the curves of ISO 6336-2/-3 are flat: a stress below σ_G(10¹⁰) does no
damage."""


def cycles_to_failure(sigma: float, sigma_G: Callable[[float], float]) -> float:
    """Cycles N at which σ_G(N) = σ (bisection on log N); ``math.inf`` when σ ≤ σ_G(10¹⁰),
    0 when σ exceeds the static limit σ_G(1).  [ISO6336-6] (S-N curve, Miner's rule).

    Example: on the curve σ_G(N) = 1000·(N/10⁶)^−0.1 MPa the stress σ_G(10⁵) fails at
    N = 10⁵ (identity):

    >>> curve = lambda N: 1000.0 * (N / 1e6) ** -0.1
    >>> round(cycles_to_failure(curve(1e5), curve))
    100000
    """
    if sigma <= sigma_G(N_MAX):
        return math.inf
    if sigma > sigma_G(N_MIN):
        return 0.0
    # σ_G(10^x) − σ falls with x, >= 0 at x = 0 and < 0 at log10 N_MAX: log10 N to 1e-13
    # (N to 2.3e-13 relative), the last x with σ_G(10^x) >= σ
    return 10.0 ** bracket_root(lambda x: float(sigma_G(10.0 ** x)) - sigma, 0.0,
                            math.log10(N_MAX), 1e-13, closed=True)


def damage(stresses: Sequence[float], cycles: Sequence[float],
           sigma_G: Callable[[float], float]) -> float:
    """Damage sum D = Σ n_i/N_i of the blocks (stress σ_i [MPa], n_i cycles).
    [ISO6336-6] (Palmgren–Miner rule).

    Example: half the cycles to failure of one block is half the damage (identity):

    >>> curve = lambda N: 1000.0 * (N / 1e6) ** -0.1
    >>> round(damage([curve(1e5)], [5e4], curve), 9)
    0.5
    """
    D = 0.0
    for s, n in zip(stresses, cycles):
        N = cycles_to_failure(s, sigma_G)
        if n <= 0.0:
            continue
        D += math.inf if N == 0.0 else (0.0 if math.isinf(N) else n / N)
    return D


def spectrum_safety(stresses: Sequence[float], cycles: Sequence[float],
                    sigma_G: Callable[[float], float]) -> float:
    """Safety factor of a spectrum: the factor S by which every block stress may grow until
    the damage sum reaches 1 (D(S·σ_i) = 1).  [ISO6336-6] (safety factor from a load
    spectrum)."""
    peak = max(stresses)
    if peak <= 0.0:
        return math.inf
    lo, hi = 1e-3, sigma_G(N_MIN) / peak * 1.000001
    if damage([hi * s for s in stresses], cycles, sigma_G) < 1.0:
        return hi
    if damage([lo * s for s in stresses], cycles, sigma_G) >= 1.0:
        return lo

    def margin(log_S: float) -> float:
        # 1 − D, bounded (a block above the static limit has D = ∞), falling with S
        S = math.exp(log_S)
        return 1.0 - min(damage([S * s for s in stresses], cycles, sigma_G), 1e6)

    # ln S to 1e-13 (S to 1e-13 relative), the last S with D < 1
    return math.exp(bracket_root(margin, math.log(lo), math.log(hi), 1e-13, closed=False))
