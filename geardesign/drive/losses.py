"""Power losses of a gear drive (pure functions).

One published method per source of loss:

* tooth mesh, load dependent: [ISOTR14179-2], P_VZP = P_A·μ_mz·H_V with the mean
  coefficient of friction μ_mz of Schlenk and the tooth loss factor H_V of Ohlendorf;
* dip-lubricated gears, no load: churning of [Changenet2007] (and [Changenet2008] for the
  high-speed regime);
* rolling bearings: Palmgren's friction torque M = M0 + M1 ([Palmgren1959]; factors f0, f1
  by bearing type as tabulated by [Harris2007], data in ``losses.toml``);
* radial lip seals: [ISOTR14179-2], P_VD = 7.69·10⁻⁶·d²·n.

Units: lengths mm, speeds min⁻¹, forces N, kinematic viscosity mm²/s, dynamic viscosity
mPa·s, density kg/m³, power W unless a docstring says otherwise.

>>> round(tooth_loss_factor(1.5, 16, 0.0, 1.4625, 0.7341), 4)
0.1986
"""

from __future__ import annotations

import math
from functools import lru_cache
from pathlib import Path

G = 9.81                    # m/s², gravitational acceleration


@lru_cache(maxsize=1)
def data() -> dict:
    """The tables of ``losses.toml``."""
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("losses.toml"))


# ----------------------------------------------------------------------------- tooth mesh


def partial_contact_ratios(d_a1: float, d_a2: float, d_b1: float, d_b2: float,
                           alpha_tw: float, p_bt: float) -> tuple[float, float]:
    """Addendum contact ratios ε_1, ε_2 of pinion and wheel (external pair): the path of
    contact on each gear's addendum over the transverse base pitch,
    ε_i = (½·√(d_ai² − d_bi²) − ½·d_bi·tan α_tw)/p_bt.  [ISO21771]; α_tw in degrees.

    >>> e1, e2 = partial_contact_ratios(82.636, 118.544, 67.658, 101.486, 22.439, 13.285)
    >>> round(e1, 3), round(e2, 3), round(e1 + e2, 2)
    (0.734, 0.728, 1.46)
    """
    t = math.tan(math.radians(alpha_tw))
    g1 = 0.5 * math.sqrt(max(d_a1 * d_a1 - d_b1 * d_b1, 0.0)) - 0.5 * d_b1 * t
    g2 = 0.5 * math.sqrt(max(d_a2 * d_a2 - d_b2 * d_b2, 0.0)) - 0.5 * d_b2 * t
    return g1 / p_bt, g2 / p_bt


def tooth_loss_factor(u: float, z1: int, beta_b: float, eps_alpha: float,
                      eps_1: float) -> float:
    """Tooth loss factor H_V of Ohlendorf, [ISOTR14179-2]:
    H_V = π·(u + 1)/(z1·u·cos β_b)·(1 − ε_α + ε_1² + ε_2²), ε_2 = ε_α − ε_1; β_b in
    degrees.  The planetary calculator's implementation (one formula for both).

    >>> round(tooth_loss_factor(24 / 16, 16, 0.0, 1.4625, 0.7341), 4)
    0.1986
    """
    from geardesign.gears.losses import loss_factor

    return loss_factor(eps_alpha, eps_1, z1, u, math.radians(beta_b))


def sum_velocity_pitch(n1: float, d_w1: float, alpha_tw: float) -> float:
    """Sum of the rolling velocities at the pitch point v_ΣC = 2·v_t·sin α_tw [m/s]
    (v_t = π·d_w1·n1/60000), by :func:`~geardesign.spur.strength.iso6336.part21.
    sum_velocity_pitch`.  [ISOTR14179-2]"""
    from geardesign.spur.strength.iso6336.part21 import sum_velocity_pitch

    return sum_velocity_pitch(math.pi * d_w1 * n1 / 60000.0, math.radians(alpha_tw))


def reduced_radius_pitch(d_w1: float, d_w2: float, alpha_tw: float, beta_b: float) -> float:
    """Reduced radius of curvature at the pitch point in the normal section [mm]:
    ρ_redC = ρ_C1·ρ_C2/(ρ_C1 + ρ_C2)/cos β_b, ρ_Ci = ½·d_wi·sin α_tw.  [ISOTR14179-2]"""
    s = math.sin(math.radians(alpha_tw))
    r1, r2 = 0.5 * d_w1 * s, 0.5 * d_w2 * s
    return r1 * r2 / (r1 + r2) / math.cos(math.radians(beta_b))


def mean_friction_coefficient(F_bt: float, b: float, v_sum: float, rho_red: float,
                              eta_oil: float, Ra: float, X_L: float) -> float:
    """Mean coefficient of friction of the tooth mesh (Schlenk), [ISOTR14179-2]:
    μ_mz = 0.048·(F_bt/b/(v_ΣC·ρ_redC))^0.2·η_oil^(−0.05)·Ra^0.25·X_L with F_bt the
    transverse tangential force on the base circle [N], b the face width [mm], v_ΣC [m/s],
    ρ_redC [mm], η_oil the dynamic viscosity at the oil temperature [mPa·s], Ra the mean
    arithmetic roughness of the flanks [µm] and X_L the lubricant factor.

    >>> round(mean_friction_coefficient(6370.7, 40.0, 5.267, 8.382, 49.85, 0.355, 0.65), 4)
    0.0256
    """
    return (0.048 * (F_bt / b / (v_sum * rho_red)) ** 0.2 * eta_oil ** -0.05 * Ra ** 0.25
            * X_L)


def mesh_power_loss(P_in: float, mu: float, H_V: float) -> float:
    """Load-dependent mesh loss P_VZP = P_A·μ_mz·H_V [W] of the power P_A [W] that the
    pair transmits.  [ISOTR14179-2]"""
    return P_in * mu * H_V


def lubricant_factor(base_oil: str) -> float:
    """X_L of ``losses.toml`` by base oil.  [ISOTR14179-2]"""
    return float(data()["lubricant_factor"][base_oil])


def lubricant_types() -> tuple[str, ...]:
    return tuple(k for k in data()["lubricant_factor"] if k != "source")


# ----------------------------------------------------------------------------- churning


def immersed_surface(R_p: float, b: float, h: float, z: int, m_n: float,
                     alpha_n: float) -> float:
    """Wetted surface S_m [mm²] of a gear of pitch radius R_p dipping h into the oil:
    both side faces, the periphery and the tooth flanks, [Changenet2007]:
    S_m = R_p²·(2θ − sin 2θ) + 2·R_p·b·θ + 2·z·h_t·b·θ/(π·cos α_n), θ = arccos(1 − h/R_p),
    h_t = 2.25·m_n the tooth depth."""
    if h <= 0.0:
        return 0.0
    theta = math.acos(max(-1.0, 1.0 - h / R_p))
    h_t = 2.25 * m_n
    return (R_p * R_p * (2 * theta - math.sin(2 * theta)) + 2 * R_p * b * theta
            + 2 * z * h_t * b * theta / (math.pi * math.cos(math.radians(alpha_n))))


def churning_coefficient(h: float, D_p: float, V0: float, b: float, Fr: float,
                         Re: float) -> float:
    """Dimensionless churning torque C_m: [Changenet2007] for Re < 6000,
    C_m = 1.366·(h/D_p)^0.45·(V0/D_p³)^0.1·Fr^(−0.6)·Re^(−0.21); [Changenet2008] for
    Re > 9000, C_m = 3.644·(h/D_p)^0.1·(V0/D_p³)^(−0.35)·Fr^(−0.88)·(b/D_p)^0.85; linear
    in Re between (the papers leave 6000…9000 open).  Lengths in one unit, V0 in its cube."""
    def low(r):
        return 1.366 * (h / D_p) ** 0.45 * (V0 / D_p ** 3) ** 0.1 * Fr ** -0.6 * r ** -0.21

    def high():
        return 3.644 * (h / D_p) ** 0.1 * (V0 / D_p ** 3) ** -0.35 * Fr ** -0.88 * (
            b / D_p) ** 0.85
    if Re <= 6000.0:
        return low(Re)
    if Re >= 9000.0:
        return high()
    w = (Re - 6000.0) / 3000.0
    return (1 - w) * low(6000.0) + w * high()


def churning_loss(rho: float, nu: float, n: float, R_p: float, b: float, h: float,
                  V0: float, z: int, m_n: float, alpha_n: float) -> float:
    """Churning loss of one dip-lubricated gear [W], [Changenet2007]:
    P = ½·ρ·ω³·S_m·R_p³·C_m with Fr = ω²·R_p/g and Re = ω·R_p·b/ν.  ρ [kg/m³], ν [mm²/s],
    n [min⁻¹], R_p, b, h, m_n [mm], V0 the oil volume [l], α_n [deg]."""
    if h <= 0.0 or n < 1e-3:        # below 0.001 min⁻¹ nothing churns
        return 0.0
    w = n * math.pi / 30.0
    Rm, bm, hm = R_p / 1000.0, b / 1000.0, h / 1000.0
    S = immersed_surface(R_p, b, h, z, m_n, alpha_n) * 1e-6
    Fr = w * w * Rm / G
    Re = w * Rm * bm / (nu * 1e-6)
    Cm = churning_coefficient(hm, 2 * Rm, V0 * 1e-3, bm, Fr, Re)
    return 0.5 * rho * w ** 3 * S * Rm ** 3 * Cm


# ----------------------------------------------------------------------------- bearings


def bearing_types() -> tuple[str, ...]:
    return tuple(k for k in data()["bearing_friction"] if k != "source")


def bearing_friction_moment(kind: str, d_m: float, n: float, nu: float, F_r: float,
                            F_a: float, P0: float, C0: float,
                            Y: float | None = None) -> tuple[float, float]:
    """Palmgren's friction torque of a rolling bearing [N·mm]: (M0, M1) with
    M0 = 10⁻⁷·f0·(ν·n)^(2/3)·d_m³ for ν·n >= 2000, else 160·10⁻⁷·f0·d_m³, and
    M1 = f1·P1·d_m.  [Palmgren1959]; f0, f1 and P1 by type from ``losses.toml``
    ([Harris2007]).  ν [mm²/s], n [min⁻¹], d_m the mean diameter [mm], loads [N].

    >>> m0, m1 = bearing_friction_moment("cylindrical_roller", 60.0, 1000.0, 20.0, 5000.0,
    ...                                  0.0, 5000.0, 50000.0)
    >>> round(m0, 1), round(m1, 1)
    (47.7, 90.0)
    """
    return (bearing_no_load_moment(kind, d_m, n, nu),
            bearing_load_moment(kind, d_m, F_r, F_a, P0, C0, Y))


def bearing_no_load_moment(kind: str, d_m: float, n: float, nu: float) -> float:
    """M0 of :func:`bearing_friction_moment` [N·mm], the part that depends on the oil's
    viscosity ν [mm²/s] and not on the load."""
    f0 = data()["bearing_friction"][kind]["f0"]
    vn = nu * n
    return (1e-7 * f0 * vn ** (2.0 / 3.0) * d_m ** 3 if vn >= 2000.0
            else 160e-7 * f0 * d_m ** 3)


def bearing_load_moment(kind: str, d_m: float, F_r: float, F_a: float, P0: float, C0: float,
                        Y: float | None = None) -> float:
    """M1 = f1·P1·d_m of :func:`bearing_friction_moment` [N·mm], the part that depends on
    the load and not on the oil."""
    t = data()["bearing_friction"][kind]
    scale = (Y if (t["p1_uses_Y"] and Y) else 1.0)
    P1 = max(t["p1_axial"] * scale * F_a - t["p1_radial"] * F_r, F_r)
    f1 = t["f1_coefficient"] * ((P0 / C0) ** t["f1_exponent"]
                                if t["f1_exponent"] and C0 > 0 else 1.0)
    return f1 * P1 * d_m


def moment_power(M: float, n: float) -> float:
    """Power [W] of a friction torque M [N·mm] at n [min⁻¹]: P = M·ω."""
    return M / 1000.0 * n * math.pi / 30.0


# ----------------------------------------------------------------------------- seals


def seal_power_loss(d: float, n: float) -> float:
    """Friction loss of a radial lip seal on a shaft of diameter d [mm] at n [min⁻¹] [W],
    [ISOTR14179-2]: P_VD = 7.69·10⁻⁶·d²·n.

    >>> round(seal_power_loss(40.0, 1500.0), 2)
    18.46
    """
    return 7.69e-6 * d * d * n


# ----------------------------------------------------------------------------- oil


def oil_density(rho15: float, t: float) -> float:
    """Density of a mineral oil at t [°C] from its density at 15 °C [kg/m³]:
    ρ = ρ15·(1 − 0.00065·(t − 15)).  [ISOTR14179-2]"""
    return rho15 * (1.0 - 0.00065 * (t - 15.0))
