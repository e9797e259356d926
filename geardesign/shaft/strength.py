"""Static strength and fatigue of a shaft section (pure functions; stresses MPa, lengths mm).

Fatigue: the method of the Russian machine-design textbooks ([Dunaev] ch. 10; [Ivanov]),
based on GOST 25.504-82 ([GOST25504]):

.. math::
    S_σ = \\frac{σ_{-1}}{K_{σD} σ_a + ψ_σ σ_m},\\quad
    S_τ = \\frac{τ_{-1}}{K_{τD} τ_a + ψ_τ τ_m},\\quad
    S = \\frac{S_σ S_τ}{\\sqrt{S_σ^2 + S_τ^2}},\\quad
    K_{σD} = \\Big(\\frac{K_σ}{K_{dσ}} + \\frac{1}{K_{Fσ}} - 1\\Big)\\frac{1}{K_V}

The formulas of [GOST25504] (K_σD, the roughness factors, ψ_σ and ψ_τ, the safety
factors) are those of :mod:`geardesign.fatigue.gost25504`; the tables of K_σ, K_τ, K_σ/K_d
and K_d are data (``tables.toml``).
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass
from geardesign.fatigue import gost25504 as g25


@lru_cache(maxsize=1)
def tables() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("tables.toml"))


TABLE_D_MAX = 100.0
"""Largest diameter of the size-factor and press-fit tables [mm]."""


def _interp(x: float, xs: list[float], ys: list[float]) -> float:
    """Linear interpolation, the end values outside the range."""
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    for i in range(len(xs) - 1):
        if x <= xs[i + 1]:
            t = (x - xs[i]) / (xs[i + 1] - xs[i])
            return ys[i] + t * (ys[i + 1] - ys[i])
    return ys[-1]  # pragma: no cover


# ----------------------------------------------------------------------------- section


def section_moduli(d: float, bore: float = 0.0) -> tuple[float, float, float]:
    """Area A [mm²], bending and polar section moduli W, W_p [mm³] of a (hollow) round
    section ([Timoshenko]): W = π d³/32 · (1 − (d_0/d)⁴), W_p = 2W."""
    a = 1.0 - (bore / d) ** 4
    W = math.pi * d ** 3 / 32.0 * a
    return math.pi / 4.0 * (d * d - bore * bore), W, 2.0 * W


def von_mises(sigma: float, tau: float) -> float:
    """Equivalent stress σ_v = √(σ² + 3τ²) [MPa] (distortion energy; [Shigley] ch. 7)."""
    return math.sqrt(sigma * sigma + 3.0 * tau * tau)


# ----------------------------------------------------------------------------- factors


def fillet_factors(t: float, r: float, d: float, sigma_B: float) -> tuple[float, float, bool]:
    """K_σ, K_τ of a shoulder fillet by t/r and r/d ([Dunaev], table "stepped transition
    with a fillet", ``tables.toml`` [fillet]); bilinear in t/r, r/d, linear in σ_B.  The
    third value is True when the nearest row used may understate the factor: t/r above the
    largest row or r/d below the smallest (t/r below 2 and r/d above the rows take the
    nearest row, which overstates it)."""
    tab = tables()["fillet"]
    sb = tab["sigma_B"]
    tr, rd = t / r, r / d
    rows = tab["rows"]
    trs = sorted({row["t_r"] for row in rows})
    outside = tr > trs[-1]

    def at_tr(tr_row: float) -> tuple[float, float, bool]:
        sub = [row for row in rows if row["t_r"] == tr_row]
        rds = [row["r_d"] for row in sub]
        ks = [_interp(sigma_B, sb, row["K_sigma"]) for row in sub]
        kt = [_interp(sigma_B, sb, row["K_tau"]) for row in sub]
        return _interp(rd, rds, ks), _interp(rd, rds, kt), rd < rds[0]

    trc = min(max(tr, trs[0]), trs[-1])
    for i in range(len(trs) - 1):
        if trc <= trs[i + 1]:
            lo, hi = trs[i], trs[i + 1]
            break
    a, b = at_tr(lo), at_tr(hi)
    w = (trc - lo) / (hi - lo)
    return (a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]),
            outside or a[2] or b[2])


def keyway_factors(sigma_B: float, cutter: str = "end_mill") -> tuple[float, float]:
    """K_σ, K_τ of a keyway cut by an end mill or a disc cutter ([Dunaev], table of
    keyway factors, ``tables.toml`` [keyway]), linear in σ_B."""
    tab = tables()["keyway"]
    row = tab[cutter]
    return (_interp(sigma_B, tab["sigma_B"], row["K_sigma"]),
            _interp(sigma_B, tab["sigma_B"], row["K_tau"]))


def press_fit_ratios(d: float, sigma_B: float) -> tuple[float, float]:
    """K_σ/K_d and K_τ/K_d at the edge of a press-fitted hub ([Dunaev], ``tables.toml``
    [press_fit]): bilinear in d and σ_B; K_τ/K_d = 0.6·K_σ/K_d + 0.4."""
    tab = tables()["press_fit"]
    col = [_interp(sigma_B, tab["sigma_B"], row) for row in tab["K_sigma_Kd"]]
    ks = _interp(d, tab["d"], col)
    return ks, tab["tau_a"] * ks + tab["tau_b"]


def size_factors(d: float, alloy: bool) -> tuple[float, float]:
    """Size factors K_dσ (bending) and K_dτ (torsion) by diameter ([Dunaev], table of K_d,
    ``tables.toml`` [size]); bending of carbon steel has its own column."""
    tab = tables()["size"]
    k_alloy = _interp(d, tab["d"], tab["alloy_or_torsion"])
    k_bend = k_alloy if alloy else _interp(d, tab["d"], tab["carbon_bending"])
    return k_bend, k_alloy


def surface_factors(Rz: float, sigma_B: float) -> tuple[float, float]:
    """Surface roughness factors K_Fσ, K_Fτ of a shaft section [-]: K_Fσ of [GOST25504]
    (:func:`geardesign.fatigue.gost25504.roughness_factor`) at R_z >= 1 µm and at most 1
    (a polished surface does not raise the limit), K_Fτ = 0.575·K_Fσ + 0.425
    (:func:`geardesign.fatigue.gost25504.torsion_roughness_factor`).

    >>> [round(k, 4) for k in surface_factors(10.0, 1000.0)]
    [0.8462, 0.9116]
    """
    k = min(1.0, g25.roughness_factor(max(Rz, 1.0), sigma_B))
    return k, g25.torsion_roughness_factor(k)


mean_stress_sensitivity = g25.mean_stress_sensitivity
"""ψ_σ = 0.02 + 2·10⁻⁴·σ_B and ψ_τ = 0.5·ψ_σ of the shaft's steel: the function of
[GOST25504] in :mod:`geardesign.fatigue.gost25504` (one formula for the shaft and the rim)."""


def endurance_estimates(sigma_B: float) -> tuple[float, float]:
    """σ_-1 ≈ 0.43·σ_B and τ_-1 ≈ 0.58·σ_-1 of carbon and alloy steels ([Ivanov];
    [Dunaev])."""
    s = 0.43 * sigma_B
    return s, 0.58 * s


# ----------------------------------------------------------------------------- safety


@dataclass(frozen=True)
class Fatigue:
    K_sigma_D: float
    K_tau_D: float
    S_sigma: float
    S_tau: float
    S: float


def fatigue_safety(sigma_a: float, sigma_m: float, tau_a: float, tau_m: float,
                   ratio_sigma: float, ratio_tau: float, K_F_sigma: float, K_F_tau: float,
                   K_V: float, sigma_m1: float, tau_m1: float, psi_sigma: float,
                   psi_tau: float) -> Fatigue:
    """Fatigue safety factors of a section (module docstring).  ``ratio_*`` are the largest
    K/K_d of the section's concentrators; stresses nominal, MPa.  A safety with no stress is
    infinite."""
    K_sD = g25.reduction_factor(ratio_sigma, K_F_sigma, K_V)
    K_tD = g25.reduction_factor(ratio_tau, K_F_tau, K_V)
    S_s = g25.safety_factor(sigma_m1, K_sD, psi_sigma, sigma_a, sigma_m)
    S_t = g25.safety_factor(tau_m1, K_tD, psi_tau, tau_a, tau_m)
    return Fatigue(K_sD, K_tD, S_s, S_t, g25.combined_safety(S_s, S_t))
