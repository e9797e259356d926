"""Vectorised evaluation of many external spur/helical pairs at once: the pair geometry,
the geometric checks and the GOST 21354-87 fatigue rating, for numpy arrays of candidates
(one call per chunk).

No formula is written here: the geometry is :func:`geardesign.spur.geometry.pair_core` and
every factor a function of :mod:`geardesign.spur.strength.gost21354`, the same functions
the scalar calculator calls, written with :mod:`geardesign.core.xp` so that they take
numbers and arrays alike.  This module only strings them together in the order of
:func:`geardesign.spur.strength.rating.rate`; ``tests/test_sweep_kernel.py`` keeps the two
equal on 10 000 random pairs (1e-9 relative).

Scope: external pairs, the fatigue rating (contact and bending, life by GOST regime or by a
load spectrum) with the ``[factors]`` overrides of the spec, and the error checks of
:func:`geardesign.spur.checks.geometry_checks` (contact ratio, undercut, pointed tip,
interference, root diameter, radial clearance).  Not here: the peak-torque (static)
checks, the span, the informative contact models: a sweep re-rates the variants it
reports with the scalar calculator (``geardesign sweep --emit-spec``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from geardesign.spur.geometry import BasicRack, pair_core
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength import tables as T
from geardesign.spur.strength.rating import life_cycles

INPUTS = ("m_n", "z1", "z2", "x1", "x2", "beta", "b_w")
"""The candidate arrays :func:`evaluate` takes (beta in rad)."""


@dataclass(frozen=True)
class Fixed:
    """What all candidates of a chunk share: the rack, the tip rule, the materials, the duty
    and the GOST setting (as the scalar calculator builds them from the spec)."""

    rack: BasicRack
    mats: tuple
    duty: object
    setting: object
    tip_shortening: bool = True


def fixed_from_spec(spec) -> Fixed:
    """The :class:`Fixed` data of a validated spur spec (materials, load, setting)."""
    from geardesign.spur.calculator import _strength_inputs, pair_input_from_spec

    p, _ = pair_input_from_spec(spec)
    mats, duty, setting = _strength_inputs(spec, spec.data["gear"])
    return Fixed(p.rack, mats, duty, setting, spec.data["gear"].get("tip_shortening", True))


def _given(s, key: str, computed):
    """The spec's ``[factors]`` value of ``key`` where given (as the scalar rating's
    ``_factor``), else the computed one."""
    v = s.overrides.get(key)
    if v is None:
        return computed
    return np.full(np.shape(computed), float(v)) if np.ndim(computed) else float(v)


def evaluate(c: dict, f: Fixed) -> dict:
    """Geometry, checks and GOST 21354-87 fatigue rating of the candidates ``c`` (arrays of
    equal length, keys :data:`INPUTS`).  Returns a dict of arrays: the geometry of
    :func:`pair_core`, the factors and stresses under the keys of the scalar rating
    (``K_Hv``, ``sigma_H``, ``S_H1``, ``sigma_F2``, ...), the check flags ``ok_<CODE>``,
    ``valid`` (a pair exists) and ``passed`` (valid and every error check passed)."""
    arrays = {k: np.asarray(c[k], dtype=float) for k in INPUTS}
    n = len(arrays["m_n"])
    with np.errstate(all="ignore"):
        out = _evaluate(arrays, f)
    return {k: (np.full(n, v) if np.ndim(v) == 0 else v) for k, v in out.items()}


def _evaluate(c: dict, f: Fixed) -> dict:
    m_n, z1, z2, x1, x2, beta, b_w = (c[k] for k in INPUTS)
    g = pair_core(m_n, z1, z2, x1, x2, beta, b_w, f.rack, f.tip_shortening)
    out = dict(g)
    s, duty, (m1, m2) = f.setting, f.duty, f.mats
    mats = (m1, m2)
    helical = beta > 0.0
    u = g["u"]
    d1 = g["d1"]
    eps_a, eps_b = g["eps_alpha"], g["eps_beta"]
    eps_b_h = np.where(helical, eps_b, 0.0)

    # ------------------------------------------------------------------ forces, life
    F_tH = 2000.0 * duty.T1 / d1
    v = math.pi * d1 * duty.n1 / 60000.0
    _, N_HE, N_FE = life_cycles(duty, mats, u)

    # ------------------------------------------------------------------ load factors
    K_A = duty.K_A
    soft_pair = min(m1.HB, m2.HB) <= 350.0
    dH = np.where(helical, T.DELTA_H[("soft" if soft_pair else "hard", "helical")],
                  T.DELTA_H[("soft" if soft_pair else "hard",
                             "spur_relieved" if s.tip_relief else "spur")])
    dF = np.where(helical, T.DELTA_F["helical"],
                  T.DELTA_F["spur_relieved" if s.tip_relief else "spur"])
    w_Hv = G.dynamic_load(dH, s.grade, m_n, v, g["a_w"], u)
    w_Fv = G.dynamic_load(dF, s.grade, m_n, v, g["a_w"], u)
    K_Hv = _given(s, "K_Hv", G.k_v(w_Hv, b_w, F_tH, K_A))
    K_Fv = _given(s, "K_Fv", G.k_v(w_Fv, b_w, F_tH, K_A))
    psi_bd = b_w / d1
    K0_Hb = G.k_h_beta(s.scheme, psi_bd, False)
    K_Hb = _given(s, "K_Hbeta", G.k_h_beta(s.scheme, psi_bd, soft_pair))
    h_eff = np.where(helical, 2.0 * m_n, 2.0 * m_n / eps_a)
    K_Fb = _given(s, "K_Fbeta", K0_Hb ** G.n_f(b_w, h_eff))
    Z_eps = _given(s, "Z_eps", G.z_eps(eps_a, eps_b_h))
    Y_eps = _given(s, "Y_eps", G.y_eps(eps_a, eps_b_h))
    zv1 = z1 / np.cos(beta) ** 3
    zv2 = z2 / np.cos(beta) ** 3
    c_gamma = G.mesh_stiffness(zv1, zv2, x1, x2) * (0.75 * eps_a + 0.25)
    f_pb = np.hypot(G.base_pitch_deviation(m_n, d1, s.grade),
                    G.base_pitch_deviation(m_n, g["d2"], s.grade))
    a_alpha = 0.2 if soft_pair else 0.3
    K_Ha_max = G.k_h_alpha_max(eps_a, eps_b, Z_eps)
    K_Fa_max = 1.0 / Y_eps
    kha = G.limited(G.k_alpha(eps_a, eps_b, c_gamma, b_w, f_pb, a_alpha, F_tH, K_A, K_Hv, K_Hb),
                    K_Ha_max)[0]
    kfa = G.limited(G.k_alpha(eps_a, eps_b, c_gamma, b_w, f_pb, 0.4, F_tH, K_A, K_Fv, K_Fb),
                    K_Fa_max)[0]
    K_Ha = _given(s, "K_Halpha", np.where(helical, kha, 1.0))
    K_Fa = _given(s, "K_Falpha", np.where(helical, kfa, 1.0))
    K_H = K_A * K_Hv * K_Hb * K_Ha
    K_F = K_A * K_Fv * K_Fb * K_Fa
    out.update(F_tH=F_tH, v_H=v, w_Hv=w_Hv, w_Fv=w_Fv, K_Hv=K_Hv, K_Fv=K_Fv, psi_bd=psi_bd,
               K0_Hbeta=K0_Hb, K_Hbeta=K_Hb, K_Fbeta=K_Fb, K_Halpha=K_Ha, K_Falpha=K_Fa,
               K_H=K_H, K_F=K_F, Z_eps=Z_eps, Y_eps=Y_eps)

    # ------------------------------------------------------------------ contact
    Z_E = _given(s, "Z_E", G.z_e(m1.E, m1.nu, m2.E, m2.nu))
    Z_H = _given(s, "Z_H", G.z_h(g["beta_b"], g["alpha_t"], g["alpha_tw"]))
    sigma_H = G.sigma_h(Z_E, Z_H, Z_eps, F_tH, K_H, u, b_w, d1)
    out.update(Z_E=Z_E, Z_H=Z_H, sigma_H=sigma_H)
    for i, mat in enumerate(mats):
        k = str(i + 1)
        NHG = _given(s, "N_HG" + k, G.n_hg(mat.HB))
        ZNmax = _given(s, "Z_Nmax" + k, mat.Z_N_max)
        ZN = _given(s, "Z_N" + k, G.z_n(NHG, N_HE[i], ZNmax))
        ZR = _given(s, "Z_R" + k, G.z_r(s.Ra[i]))
        ZV = _given(s, "Z_v" + k, G.z_v(v, mat.soft))
        ZX = _given(s, "Z_X" + k, G.z_x(g["d" + k]))
        limit = mat.sigma_Hlim * ZN * ZR * ZV * ZX
        out["sigma_HP" + k] = limit / mat.S_H
        out["S_H" + k] = limit / sigma_H
        out["Z_N" + k], out["Z_v" + k], out["Z_X" + k] = ZN, ZV, ZX

    # ------------------------------------------------------------------ bending
    Y_beta = _given(s, "Y_beta", np.where(helical, G.y_beta(eps_b, beta), 1.0))
    Y_delta = _given(s, "Y_delta", G.y_delta(m_n))
    N_FG = _given(s, "N_FG", G.N_FG)
    Y_R = _given(s, "Y_R", 1.0)
    out.update(Y_beta=Y_beta, Y_delta=Y_delta)
    for i, mat in enumerate(mats):
        k = str(i + 1)
        zv = zv1 if i == 0 else zv2
        YFS = _given(s, "Y_FS" + k, G.y_fs(zv, (x1, x2)[i]))
        sF = G.sigma_f(F_tH, K_F, b_w, m_n, YFS, Y_beta, Y_eps)
        YN = _given(s, "Y_N" + k, G.y_n(N_FE[i], mat.q_F, N_FG))
        YX = _given(s, "Y_X" + k, G.y_x(g["d" + k]))
        rev = duty.reverse_ratio if duty.reverse_ratios is None else duty.reverse_ratios[i]
        YA = _given(s, "Y_A" + k, G.y_a(mat.gamma_A, rev))
        limit = mat.sigma_Flim * YN * Y_delta * Y_R * YX * YA
        out["Y_FS" + k], out["sigma_F" + k] = YFS, sF
        out["sigma_FP" + k] = limit / mat.S_F
        out["S_F" + k] = limit / sF

    # ------------------------------------------------------------------ checks
    ok = {}
    eps_cont = np.where(helical, g["eps_gamma"], eps_a)
    ok["CONTACT_RATIO"] = eps_cont >= 1.0
    for k in "12":
        ok["UNDERCUT_" + ("PINION" if k == "1" else "WHEEL")] = g["x" + k] >= g["x_min" + k] - 1e-9
        ok["POINTED_TIP_" + ("PINION" if k == "1" else "WHEEL")] = g["s_an" + k] > 0.0
        ok["INTERFERENCE_" + ("PINION" if k == "1" else "WHEEL")] = \
            (g["rho_p" + k] > 0.0) & (g["rho_p" + k] >= g["rho_l" + k] - 1e-9)
        ok["ROOT_DIAMETER_" + ("PINION" if k == "1" else "WHEEL")] = g["d_f" + k] > 0.0
    ok["ROOT_CLEARANCE"] = np.minimum(g["c_12"], g["c_21"]) >= -1e-9
    # a pair whose teeth interfere has no contact ratio to rely on (checks.py)
    ok["CONTACT_RATIO"] &= ok["INTERFERENCE_PINION"] & ok["INTERFERENCE_WHEEL"]
    out["sigma_HP"] = G.sigma_hp_pair(out["sigma_HP1"], out["sigma_HP2"],
                                      helical & (eps_b >= 1.0))
    ok["CONTACT_FATIGUE"] = sigma_H <= out["sigma_HP"] * (1 + 1e-12)
    for k, who in (("1", "PINION"), ("2", "WHEEL")):
        ok["BENDING_FATIGUE_" + who] = out["S_F" + k] >= mats[int(k) - 1].S_F * (1 - 1e-12)
    valid = np.asarray(g["valid"], dtype=bool) & np.isfinite(sigma_H)
    passed = valid.copy()
    for code, flag in ok.items():
        out["ok_" + code] = flag & valid
        passed &= flag
    out["valid"] = valid
    out["passed"] = passed
    out["margin"] = np.minimum.reduce([out["sigma_HP"] / sigma_H,
                                       out["S_F1"] / m1.S_F, out["S_F2"] / m2.S_F])
    return out
