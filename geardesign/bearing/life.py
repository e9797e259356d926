"""Rolling-bearing life to GOST 18855-94 / ISO 281:2007 (= GOST 18855-2013): pure functions.

Units: forces N, lengths mm, speed min⁻¹, life in 10⁶ revolutions or hours, viscosity
mm²/s, angles in degrees at the interface.  Table data live in :mod:`.tables`; the load
factors in :mod:`.load_factors`, the factor a_ISO in :mod:`.a_iso`, the rib capacity of
roller bearings in :mod:`.rib`.
"""

from __future__ import annotations

import math

from geardesign.bearing import tables as T
from geardesign.core.records import dataclass


class BearingError(ValueError):
    """A calculation cannot be done with these inputs; ``key`` names the input to change."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key


# ----------------------------------------------------------------------------- helpers


def interp(x: float, xs, ys) -> float:
    """Linear interpolation in a table, clamped at both ends (ISO 281 Table 3 permits linear
    interpolation between printed points)."""
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]  # pragma: no cover


def is_ball(kind: str) -> bool:
    return kind in T.BALL_TYPES


def life_exponent(kind: str) -> float:
    """p = 3 for ball bearings, 10/3 for roller bearings (GOST 18855-94 / ISO 281 L10 formula;
    [Haidamaka2017] eq. (2))."""
    return 3.0 if is_ball(kind) else 10.0 / 3.0


# ----------------------------------------------------------------------------- C_r from geometry


def f_c(kind: str, gamma: float, rows: int = 1) -> float:
    """Geometry factor f_c(γ) of ISO 281:2007 Tables 2/(roller), linear interpolation.

    γ = D_w·cos α/D_pw (ball) or D_we·cos α/D_pw (roller), dimensionless.  Ball column: deep
    groove single row and angular contact; double-row deep groove; self-aligning.
    """
    if is_ball(kind):
        xs = [r[0] for r in T.F_C_BALL]
        if not xs[0] <= gamma <= xs[-1]:
            raise BearingError("bearing.D_w", f"γ = D_w·cos α/D_pw = {gamma:.4f} is outside the "
                                              f"ISO 281 f_c table ({xs[0]} … {xs[-1]})")
        col = 3 if kind == "self_aligning_ball" else (2 if kind == "deep_groove_ball" and rows == 2
                                                      else 1)
        return interp(gamma, xs, [r[col] for r in T.F_C_BALL])
    xs = [r[0] for r in T.F_C_ROLLER]
    if not xs[0] <= gamma <= xs[-1]:
        raise BearingError("bearing.D_w", f"γ = D_we·cos α/D_pw = {gamma:.4f} is outside the "
                                          f"ISO 281 f_c table ({xs[0]} … {xs[-1]})")
    return interp(gamma, xs, [r[1] for r in T.F_C_ROLLER])


@dataclass(frozen=True)
class RatingFromGeometry:
    gamma: float
    f_c: float
    b_m: float
    C_r: float


def dynamic_rating(kind: str, Z: int, D_w: float, D_pw: float, alpha_deg: float = 0.0,
                   rows: int = 1, L_we: float | None = None) -> RatingFromGeometry:
    """Basic dynamic radial load rating C_r [N] from the internal geometry.

    Ball bearings (ISO 281:2007 / GOST 18855-94; [Haidamaka2017] eqs. (3), (4)):
    D_w <= 25.4 mm: C_r = b_m·f_c·(i·cos α)^0.7·Z^(2/3)·D_w^1.8;
    D_w > 25.4 mm:  C_r = 3.647·b_m·f_c·(i·cos α)^0.7·Z^(2/3)·D_w^1.4 (3.647 = 25.4^0.4).
    Roller bearings ([Haidamaka2017] eq. (5)): C_r = b_m·f_c·(i·L_we·cos α)^(7/9)·Z^(3/4)·D_we^(29/27).
    Z rolling elements per row, D_w/D_we element diameter [mm], D_pw pitch diameter [mm],
    α contact angle, i = rows, L_we effective roller length [mm].
    """
    cos_a = math.cos(math.radians(alpha_deg))
    gamma = D_w * cos_a / D_pw
    fc = f_c(kind, gamma, rows)
    bm = T.B_M[kind]
    if is_ball(kind):
        if D_w <= T.D_W_SPLIT:
            c = bm * fc * (rows * cos_a) ** 0.7 * Z ** (2.0 / 3.0) * D_w ** 1.8
        else:
            c = 3.647 * bm * fc * (rows * cos_a) ** 0.7 * Z ** (2.0 / 3.0) * D_w ** 1.4
    else:
        if L_we is None:
            raise BearingError("bearing.L_we", "missing; required for the rating of a roller "
                                               "bearing from its geometry (effective roller length, mm)")
        c = bm * fc * (rows * L_we * cos_a) ** (7.0 / 9.0) * Z ** 0.75 * D_w ** (29.0 / 27.0)
    return RatingFromGeometry(gamma, fc, bm, c)


# ----------------------------------------------------------------------------- life


def basic_life(C: float, P: float, p: float) -> float:
    """Basic rating life L10 = (C/P)^p [10⁶ rev] (GOST 18855-94 / ISO 281; [GOST18855]);
    infinite when it exceeds the float range (the caller refuses it).

    Example: C/P = 2 for a ball bearing (p = 3) gives L10 = 8·10⁶ rev:

    >>> basic_life(20.0, 10.0, 3.0)
    8.0
    """
    try:
        return (C / P) ** p
    except OverflowError:
        return math.inf


def hours(L_mrev: float, n: float) -> float:
    """Life in hours at constant speed n [min⁻¹]: L_h = 10⁶·L/(60·n) ([Haidamaka2017] eq. (2)).

    Example: 10⁶ rev at 1000 min⁻¹ last 10⁶/60 000 = 16.667 h:

    >>> round(hours(1.0, 1000.0), 3)
    16.667
    """
    return 1.0e6 * L_mrev / (60.0 * n)


def a1_factor(reliability: float, method: str) -> float:
    """Life adjustment factor for reliability a1 of the edition (tables in :mod:`.tables`;
    linear interpolation between printed reliabilities).  GOST 18855-94: 90 … 99 %;
    ISO 281:2007 / GOST 18855-2013: 90 … 99.95 %."""
    table = T.A1_GOST94 if method == "gost18855_94" else T.A1_ISO2007
    rs = [r[0] for r in table]
    if not rs[0] <= reliability <= rs[-1]:
        raise BearingError("requirements.reliability",
                           f"outside the a1 table of this edition ({rs[0]:g} … {rs[-1]:g} %)")
    return interp(reliability, rs, [r[1] for r in table])


def required_rating(P: float, life_h: float, n: float, p: float, a: float = 1.0) -> float:
    """Dynamic rating needed for a target life: C_req = P·(60·n·L_h/(10⁶·a))^(1/p) [N], with
    a = a1·a23 (GOST) or a1·a_ISO (ISO 281) ([Haidamaka2017]; [GOST18855])."""
    return P * (60.0 * n * life_h / (1.0e6 * a)) ** (1.0 / p)


def system_life(lives, slope: float) -> float:
    """Life of several bearings that all must survive: L = (Σ L_i^−e)^(−1/e) (Weibull slope
    e = 10/9 ball, 9/8 roller; NTN CAT. No. 2202/E formula (3.6)).

    Example: a system of one bearing lives as long as that bearing (identity):

    >>> round(system_life([5000.0], 9.0 / 8.0), 6)
    5000.0
    """
    return sum(L ** -slope for L in lives) ** (-1.0 / slope)


@dataclass(frozen=True)
class SpectrumResult:
    P_m: float                   # equivalent (mean) load [N]
    n_m: float                   # mean speed [min⁻¹]
    revolutions_share: list      # share of revolutions of each block
    damage_share: list           # share of fatigue damage of each block


def spectrum_mean(P: list, n: list, t: list, p: float) -> SpectrumResult:
    """Mean load of a stepped spectrum: P_m = [Σ P_j^p·n_j·t_j / Σ n_j·t_j]^(1/p),
    n_m = Σ n_j·t_j / Σ t_j (GOST 18855-94 / ISO 281; NTN CAT. No. 2202/E formula (4.12)).
    t_j are time shares; the damage share of block j is P_j^p·n_j·t_j / Σ."""
    rev = [nj * tj for nj, tj in zip(n, t)]
    dmg = [Pj ** p * r for Pj, r in zip(P, rev)]
    total_rev = sum(rev)
    total_t = sum(t)
    total_dmg = sum(dmg)
    P_m = (total_dmg / total_rev) ** (1.0 / p)
    return SpectrumResult(P_m, total_rev / total_t, [r / total_rev for r in rev],
                          [d / total_dmg if total_dmg > 0.0 else 0.0 for d in dmg])


def miner_hours(block_hours: list, t: list) -> float:
    """Palmgren–Miner over time shares: 1/L = Σ t_j/L_j (L_j the life [h] at block j)."""
    return 1.0 / sum(tj / Lj for tj, Lj in zip(t, block_hours))
