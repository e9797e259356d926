"""Vectorised evaluation of many external spur/helical pairs at once: the pair geometry,
the geometric checks and the GOST 21354-87 or ISO 6336:2019 fatigue rating, for numpy
arrays of candidates (one call per chunk).

No formula is written here: the geometry is :func:`geardesign.gears.geometry.pair_core` and
the GOST 21354-87 rating is :func:`geardesign.spur.strength.gost21354.rating.rate` itself,
called on a view of the candidates' arrays (:func:`pair_view`): its formulas are written
with :mod:`geardesign.core.xp`, so one function rates one pair or a chunk.  This module
keeps only what is array-specific: the view, the check flags and the chunk's columns;
``tests/test_sweep_kernel.py`` guards kernel == calculator on 10 000 random pairs
(1e-9 relative).

ISO 6336:2019 (:func:`evaluate` of a :class:`Fixed` with ``method = ISO_NAME``) is
:func:`geardesign.spur.strength.iso6336.rating.rate` itself on the same view, with the
``[iso]`` and ``[iso_factors]`` inputs of the spec; pairs that the calculator does not rate by ISO
(:func:`geardesign.spur.calculator.ratable`: ε_α < 1, an active limit beyond the tangency
point, a pointed tooth) fail ``STRENGTH_NOT_RATED``.  No load spectrum, no scuffing (a sweep
refuses those with ISO).

Scope: external pairs, the fatigue rating (contact and bending, life by GOST regime or by a
load spectrum) with the ``[factors]`` overrides of the spec, and the error checks of
:func:`geardesign.spur.checks.geometry_checks` (contact ratio, undercut, pointed tip,
interference, root diameter, radial clearance).  Not here: the peak-torque (static)
checks (the kernel rates without the peak torque), the span: a sweep re-rates the variants
it reports with the scalar calculator (``geardesign sweep --emit-spec``).
"""

from __future__ import annotations

from dataclasses import replace
from types import SimpleNamespace

import numpy as np

from geardesign.core.records import dataclass
from geardesign.gears.geometry import BasicRack, pair_core
from geardesign.spur.strength.common import values
from geardesign.spur.strength.gost21354.rating import rate as gost_rate
from geardesign.spur.strength.verdict import verdict

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
    method: str = "GOST 21354-87"
    iso: object = None          # IsoSetting of an ISO 6336 sweep


def fixed_from_spec(spec) -> Fixed:
    """The :class:`Fixed` data of a validated spur spec (materials, load, setting)."""
    from geardesign.spur.calculator import _strength_inputs, pair_input_from_spec

    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen, iso_setting

    p, _ = pair_input_from_spec(spec)
    mats, duty, setting = _strength_inputs(spec, spec.data["gear"])
    tip = spec.data["gear"].get("tip_shortening", True)
    if chosen(spec.data["options"]) == [ISO_NAME]:
        return Fixed(p.rack, mats, duty, setting, tip, ISO_NAME, iso_setting(spec))
    return Fixed(p.rack, mats, duty, setting, tip)


def evaluate(c: dict, f: Fixed) -> dict:
    """Geometry, checks and GOST 21354-87 fatigue rating of the candidates ``c`` (arrays of
    equal length, keys :data:`INPUTS`).  Returns a dict of arrays: the geometry of
    :func:`pair_core`, the factors and stresses under the keys of the scalar rating
    (``K_Hv``, ``sigma_H``, ``S_H1``, ``sigma_F2``, ...), the check flags ``ok_<CODE>``,
    ``valid`` (a pair exists) and ``passed`` (valid and every error check passed)."""
    arrays = {k: np.asarray(c[k], dtype=float) for k in INPUTS}
    n = len(arrays["m_n"])
    with np.errstate(all="ignore"):
        out = _evaluate(arrays, f) if f.iso is None else _evaluate_iso(arrays, f)
    return {k: (np.broadcast_to(v, (n,)) if np.ndim(v) == 0 else v) for k, v in out.items()}


GOST_COLUMNS = ("F_tH", "v_H", "w_Hv", "w_Fv", "K_Hv", "K_Fv", "psi_bd", "K0_Hbeta", "K_Hbeta",
                "K_Fbeta", "K_Halpha", "K_Falpha", "K_H", "K_F", "Z_eps", "Y_eps", "Z_E", "Z_H",
                "sigma_H", "sigma_HP1", "sigma_HP2", "S_H1", "S_H2", "Z_N1", "Z_N2", "Z_v1",
                "Z_v2", "Z_X1", "Z_X2", "Y_beta", "Y_delta", "Y_FS1", "Y_FS2", "sigma_F1",
                "sigma_F2", "sigma_FP1", "sigma_FP2", "S_F1", "S_F2", "sigma_HP")
"""The rating's values a chunk returns as columns (the sweep copies each column of each
chunk: the rating's other values stay in the record)."""


def pair_view(g: dict, rack=None):
    """The pair geometry of :func:`pair_core`'s arrays as the rating reads it
    (``inp``, ``g1``, ``g2`` and the pair values, as :class:`~geardesign.gears.geometry.PairGeometry`)."""
    inp = SimpleNamespace(m_n=g["m_n"], b_w=g["b_w"], beta=g["beta"], x1=g["x1"], x2=g["x2"],
                          z1=g["z1"], z2=g["z2"], rack=rack)
    gears = [SimpleNamespace(**{k: g[k + i] for k in ("z", "x", "d", "d_b", "d_w", "d_a", "d_f",
                                                       "h", "rho_p", "s_an")})
             for i in "12"]
    return SimpleNamespace(inp=inp, g1=gears[0], g2=gears[1], **{
        k: g[k] for k in ("u", "a_w", "alpha_t", "beta_b", "alpha_tw", "eps_alpha", "eps_beta",
                          "eps_gamma")})


def _evaluate(c: dict, f: Fixed) -> dict:
    m_n, z1, z2, x1, x2, beta, b_w = (c[k] for k in INPUTS)
    g = pair_core(m_n, z1, z2, x1, x2, beta, b_w, f.rack, f.tip_shortening)
    out = dict(g)
    g.update(m_n=m_n, b_w=b_w, beta=beta)
    # the static (peak-torque) checks are the re-check's (module docstring)
    rating = gost_rate(pair_view(g), f.mats, replace(f.duty, T_peak=None), f.setting)
    v = values(rating)
    out.update((k, v[k]) for k in GOST_COLUMNS)
    judged = verdict(rating)
    ok = {"CONTACT_FATIGUE": judged.contact_passes}
    ok["BENDING_FATIGUE_PINION"], ok["BENDING_FATIGUE_WHEEL"] = judged.bending_ok
    out["margin"] = judged.margin
    del rating, v, judged      # the chunk's peak memory: the record's other values go now

    # ------------------------------------------------------------------ checks
    ok = {**_geometry_ok(g, beta > 0.0), **ok}
    valid = np.asarray(g["valid"], dtype=bool) & np.isfinite(out["sigma_H"])
    return _flags(out, ok, valid)


def _geometry_ok(g: dict, helical) -> dict:
    """The error checks of :func:`geardesign.spur.checks.geometry_checks` as flags."""
    ok = {}
    eps_cont = np.where(helical, g["eps_gamma"], g["eps_alpha"])
    ok["CONTACT_RATIO"] = eps_cont >= 1.0
    for k in "12":
        who = "PINION" if k == "1" else "WHEEL"
        ok["UNDERCUT_" + who] = g["x" + k] >= g["x_min" + k] - 1e-9
        ok["POINTED_TIP_" + who] = g["s_an" + k] > 0.0
        ok["INTERFERENCE_" + who] = \
            (g["rho_p" + k] > 0.0) & (g["rho_p" + k] >= g["rho_l" + k] - 1e-9)
        ok["ROOT_DIAMETER_" + who] = g["d_f" + k] > 0.0
    ok["ROOT_CLEARANCE"] = np.minimum(g["c_12"], g["c_21"]) >= -1e-9
    # a pair whose teeth interfere has no contact ratio to rely on (checks.py)
    ok["CONTACT_RATIO"] &= ok["INTERFERENCE_PINION"] & ok["INTERFERENCE_WHEEL"]
    return ok


def _flags(out: dict, ok: dict, valid) -> dict:
    """``ok_<CODE>`` (the check passed on a valid candidate), ``valid`` and ``passed``."""
    passed = valid.copy()
    for code, flag in ok.items():
        out["ok_" + code] = flag & valid
        passed &= flag
    out["valid"] = valid
    out["passed"] = passed
    return out


# ----------------------------------------------------------------------------- ISO 6336


ISO_COLUMNS = ("F_t", "v", "w", "N_L1", "N_L2", "K_A", "grade", "C_M", "sigma_Hlim1",
               "sigma_Flim1", "sigma_Hlim2", "sigma_Flim2", "f_pb", "f_falpha", "F_beta",
               "f_Hbeta", "c_th", "C_B", "C_R", "c_prime", "c_gamma_alpha", "c_gamma_beta",
               "y_alpha", "y_f", "C_a", "m_red", "n_E1", "N", "N_S", "K_v", "f_sh", "f_ma",
               "F_betax", "y_beta", "F_betay", "K_Hbeta", "N_F", "K_Fbeta", "K_Halpha_max",
               "K_Falpha_max", "K_Halpha", "K_Falpha", "Z_eps", "Z_H", "Z_E", "Z_beta", "M1",
               "M2", "Z_B", "Z_D", "sigma_H0", "sigma_H1", "sigma_H2", "Z_L", "Z_v", "rho_red",
               "Z_R", "S_Hmin", "Z_NT1", "Z_W1", "Z_X1", "sigma_HG1", "sigma_HP1", "S_H1",
               "Z_NT2", "Z_W2", "Z_X2", "sigma_HG2", "sigma_HP2", "S_H2", "Y_beta", "Y_DT",
               "S_Fmin", "s_Fn1", "h_Fe1", "rho_F1", "alpha_Fen1", "q_s1", "Y_F1", "Y_S1",
               "Y_B1", "sigma_F01", "sigma_F1", "Y_NT1", "Y_deltarelT1", "Y_RrelT1", "Y_X1",
               "Y_M1", "sigma_FG1", "sigma_FP1", "S_F1", "s_Fn2", "h_Fe2", "rho_F2",
               "alpha_Fen2", "q_s2", "Y_F2", "Y_S2", "Y_B2", "sigma_F02", "sigma_F2", "Y_NT2",
               "Y_deltarelT2", "Y_RrelT2", "Y_X2", "Y_M2", "sigma_FG2", "sigma_FP2", "S_F2")
"""The ISO 6336 rating's values a chunk returns as columns."""


def _evaluate_iso(c: dict, f: Fixed) -> dict:
    """ISO 6336:2019 rating of the candidates: :func:`iso6336.rating.rate` itself on the
    view of the candidates' arrays (method B; K_Hβ by method C), external pairs, no
    spectrum, no scuffing, no peak torque (the re-check's)."""
    from geardesign.spur.strength.iso6336.rating import rate as iso_rate

    m_n, z1, z2, x1, x2, beta, b_w = (c[k] for k in INPUTS)
    g = pair_core(m_n, z1, z2, x1, x2, beta, b_w, f.rack, f.tip_shortening)
    out = dict(g)
    g.update(m_n=m_n, b_w=b_w, beta=beta)
    rating = iso_rate(pair_view(g, f.rack), f.mats, replace(f.duty, T_peak=None), f.setting,
                      f.iso)
    v = values(rating)
    out.update((k, v[k]) for k in ISO_COLUMNS)
    judged = verdict(v)
    del rating, v

    # ------------------------------------------------------------------ checks
    ok = _geometry_ok(g, beta > 0.0)
    # the calculator rates by ISO only a pair that can mesh as computed (calculator.ratable)
    eps_a = g["eps_alpha"]
    ratable = ((eps_a >= 1.0) & (g["rho_p1"] > 0.0) & (g["rho_p2"] > 0.0)
               & (g["s_an1"] > 0.0) & (g["s_an2"] > 0.0))
    ok["STRENGTH_NOT_RATED"] = ratable
    for i, who in enumerate(("PINION", "WHEEL")):
        ok["ISO_PITTING_" + who] = ratable & judged.contact_ok[i]
        ok["ISO_BENDING_" + who] = ratable & judged.bending_ok[i]
    # the sweep's columns: the larger contact stress and the smaller permissible one
    out["sigma_H"] = np.maximum(out["sigma_H1"], out["sigma_H2"])
    out["sigma_HP"] = np.minimum(out["sigma_HP1"], out["sigma_HP2"])
    out["margin"] = judged.margin
    valid = np.asarray(g["valid"], dtype=bool) & _iso_inputs_fit(g, f.iso)
    return _flags(out, ok, valid)


def _iso_inputs_fit(g: dict, iso) -> np.ndarray:
    """Candidates whose gears take the ``[iso.pinion]``/``[iso.wheel]`` body data (bore
    inside the root circle, rim within the domain of Y_B and the body): the conditions of
    :func:`geardesign.spur.strength.iso6336.spec.gear_checks`, which the calculator refuses
    as input errors."""
    from geardesign.spur.strength.iso6336.part3 import y_b_domain

    ok = np.ones(np.shape(g["d_f1"]), dtype=bool)
    for i, ig in enumerate(iso.gears):
        k = str(i + 1)
        ok &= ig.inner_diameter < g["d_f" + k]
        if ig.rim_thickness is not None:
            ok &= ig.rim_thickness > y_b_domain(ig.rim_thickness, g["h" + k], None)
            ok &= 2.0 * ig.rim_thickness <= g["d_f" + k] - ig.inner_diameter
    return ok
