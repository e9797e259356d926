"""The connection computed from its typed inputs: one record per connection type, no report
rows (those are :mod:`geardesign.connection.calculator`'s).  Formulas in :mod:`.key`,
:mod:`.spline`, :mod:`.fit`; tables in :mod:`.tables`."""

from __future__ import annotations

import math

from geardesign.connection import fit as F
from geardesign.connection import key as K
from geardesign.connection import sources as S
from geardesign.connection import spline as SP
from geardesign.connection import tables
from geardesign.connection.inputs import FitInput, KeyInput, Load, SplineInput
from geardesign.core.records import dataclass


@dataclass(frozen=True)
class Flank:
    """One bearing-pressure check of a key: the side, its engaged height and pressures."""

    code: str
    side: str             # "hub", "shaft" or "key"
    k: float              # engaged height [mm]
    p: float              # [MPa]
    p_allow: float        # [MPa]


@dataclass(frozen=True)
class KeySolution:
    l_p: float
    n_eff: float
    flanks: tuple[Flank, ...]
    allow_source: str
    tau: float
    tau_allow: float
    tau_source: str
    l_p_min: float        # least bearing length that passes every check
    l_min: float          # least key length of the form
    l_std: float          # shortest standard length >= l_min (inf: none)


def key(k: KeyInput, ld: Load) -> KeySolution:
    """Bearing pressure and shear of a parallel key ([Ivanov] ch. 6; [DIN6892] method C)."""
    Td = ld.T_d
    l_p = K.bearing_length(k.l, k.b, k.form)
    n_eff = float(tables.toml()["key_share"][str(k.count)])
    k_hub = k.h - k.t1
    p_hub = K.pressure(Td, k.d, l_p, k_hub, n_eff)
    over = k.allowable_pressure
    if k.din:
        tb = tables.toml()["key_din"]
        fS = tb["support_factor"]
        k_shaft = k.t1
        p_shaft = K.pressure(Td, k.d, l_p, k_shaft, n_eff)
        allow = (lambda mat, R: over if over is not None else fS[mat] * k.f_H * R)
        flanks = (Flank("KEY_PRESSURE_HUB", "hub", k_hub, p_hub,
                        allow(k.hub_material, k.hub_strength)),
                  Flank("KEY_PRESSURE_SHAFT", "shaft", k_shaft, p_shaft,
                        allow("steel", k.shaft_strength)),
                  Flank("KEY_PRESSURE_KEY", "key", min(k_hub, k_shaft), max(p_hub, p_shaft),
                        allow("steel", k.key_strength)))
        allow_src = "spec" if over is not None else S.KEY_ALLOW_DIN
        tau_allow = (k.allowable_shear if k.allowable_shear is not None
                     else tb["shear_factor"] * k.key_strength)
        tau_src = "spec" if k.allowable_shear is not None else S.KEY_ALLOW_DIN
    else:
        tb = tables.toml()["key_gost"]
        flanks = (Flank("KEY_PRESSURE", "hub", k_hub, p_hub,
                        over if over is not None else tb["pressure"][k.hub_material]),)
        allow_src = "spec" if over is not None else S.KEY_ALLOW_GOST
        tau_allow = k.allowable_shear if k.allowable_shear is not None else tb["shear"]
        tau_src = "spec" if k.allowable_shear is not None else S.KEY_ALLOW_GOST
    tau = K.shear(Td, k.d, k.b, l_p, n_eff)
    lp_min = max([K.required_bearing_length(Td, k.d, f.k, f.p_allow, n_eff) for f in flanks]
                 + [2.0 * Td / (k.d * k.b * tau_allow * n_eff)])
    l_min = K.length_for(lp_min, k.b, k.form)
    return KeySolution(l_p, n_eff, flanks, allow_src, tau, tau_allow, tau_src, lp_min, l_min,
                       K.standard_length(l_min, tables.key_lengths()))


@dataclass(frozen=True)
class SplineSolution:
    g: SP.Geometry
    p: float
    p_allow: float
    allow_source: str
    l_min: float


def spline(s: SplineInput, ld: Load) -> SplineSolution:
    """Mean flank pressure of an involute spline ([DIN5466]; [Ivanov] ch. 6)."""
    g = SP.geometry(s.d_B, s.m, s.z, "GOST" if s.gost else "DIN")
    if s.allowable_pressure is not None:
        p_allow, src = s.allowable_pressure, "spec"
    else:
        p_allow = tables.toml()["spline_pressure"][s.use][s.hardness][s.conditions]
        src = S.SPLINE_ALLOW
    p = SP.pressure(ld.T_d, g.d_m, s.z, g.h_w, s.l, s.psi)
    return SplineSolution(g, p, p_allow, src,
                          SP.required_length(ld.T_d, g.d_m, s.z, g.h_w, s.psi, p_allow))


@dataclass(frozen=True)
class FitSolution:
    Q_A: float
    Q_I: float
    smoothing: float      # [µm]
    U_w_min: float
    U_w_max: float
    p_min: float          # [MPa]
    p_max: float
    T_slip: float         # [N·mm]
    F_slip: float         # [N]
    S_slip: float
    p_req: float
    U_req: float          # [µm]
    stress: F.Stresses    # at p_max
    p_perm_hub: float     # permissible joint pressures at S_P = 1 [MPa]
    p_perm_shaft: float
    S_P_hub: float
    S_P_shaft: float
    U_perm: float         # [µm]
    F_press: float        # [N]
    theta: float          # [°C]


def fit(f: FitInput, ld: Load) -> FitSolution:
    """Joint pressure, capacity, stresses and assembly of an interference fit
    ([DIN7190-1]; Lamé, [Roark]); the yield safeties by the model ``f.pressure_limit`` of
    the permissible pressure, the press-in force with the press-in coefficient μ_e."""
    loss = F.smoothing(f.rz_shaft, f.rz_hub)
    Uw_min, Uw_max = f.U_min - loss, f.U_max - loss
    C = F.compliance(f.d, f.D_a, f.D_i, f.E_A, f.nu_A, f.E_I, f.nu_I)
    p_min, p_max = F.pressure(Uw_min, f.d, C), F.pressure(Uw_max, f.d, C)
    F_slip = F.axial_force(p_min, f.d, f.l, f.mu)
    S_slip = F_slip / math.hypot(2.0 * ld.T_d / f.d, ld.F_ax * ld.K_A)
    p_req = F.required_pressure(ld.T_d, ld.F_ax * ld.K_A, f.d, f.l, f.mu, f.S_R)
    s = F.stresses(p_max, f.d, f.D_a, f.D_i)
    # the yield safeties are the ratios of the permissible pressures (S_P = 1) to p_max
    p_hub, p_shaft = F.pressure_limits(f.pressure_limit, f.R_eA, f.R_eI, f.d, f.D_a, f.D_i, 1.0)
    S_hub = p_hub / p_max if p_max > 0 else math.inf
    S_shaft = p_shaft / p_max if p_max > 0 else math.inf
    p_lim = min(p_hub, p_shaft) / f.S_P
    return FitSolution(
        f.d / f.D_a, f.D_i / f.d, loss, Uw_min, Uw_max, p_min, p_max,
        F.torque(p_min, f.d, f.l, f.mu), F_slip, S_slip, p_req,
        F.interference_for(p_req, f.d, C) + loss, s, p_hub, p_shaft, S_hub, S_shaft,
        F.interference_for(p_lim, f.d, C) + loss, F.axial_force(p_max, f.d, f.l, f.mu_e),
        F.shrink_temperature(f.U_max, f.d, f.alpha_A, f.clearance, f.room))
