"""The vectorised spur kernel gives the numbers of the scalar calculator: geometry, the
GOST 21354-87 and the ISO 6336:2019 rating on 10 000 random pairs per spec to 1e-9
relative, and the pass/fail of every error check on a few hundred pairs run through the
whole calculator."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data, run_data
from geardesign.core.spec import load_toml
from geardesign.gears.geometry import GeometryError, PairInput, pair_geometry
from geardesign.spur.kernel import evaluate, fixed_from_spec
from geardesign.spur.strength.rating import rate
from tests.conftest import SPECS

N = 10_000
GEOMETRY = ("a_w", "alpha_tw", "d_a1", "d_a2", "d_f1", "d_f2", "eps_alpha", "eps_beta",
            "rho_p1", "rho_p2", "rho_l1", "rho_l2", "s_an1", "s_an2", "x_min1", "x_min2",
            "c_12", "c_21")
RATING = ("K_Hv", "K_Fv", "K_Hbeta", "K_Fbeta", "K_Halpha", "K_Falpha", "Z_E", "Z_H", "Z_eps",
          "sigma_H", "sigma_HP1", "sigma_HP2", "sigma_HP", "S_H1", "S_H2", "Y_FS1", "Y_FS2",
          "Y_beta", "Y_eps", "sigma_F1", "sigma_F2", "sigma_FP1", "sigma_FP2", "S_F1", "S_F2")


def _candidates(n: int, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    return dict(m_n=rng.choice([1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0], n),
                z1=rng.integers(12, 45, n).astype(float),
                z2=rng.integers(20, 180, n).astype(float),
                x1=rng.uniform(-0.4, 1.0, n), x2=rng.uniform(-0.4, 1.0, n),
                beta=np.radians(np.where(rng.random(n) < 0.3, 0.0, rng.uniform(5, 35, n))),
                b_w=rng.uniform(8.0, 250.0, n))


def _fixed(name: str):
    _, spec = load_data(load_toml(SPECS / name), name)
    return fixed_from_spec(spec)


def _scalar(f, row: dict):
    p = PairInput(row["m_n"], int(row["z1"]), int(row["z2"]), row["x1"], row["x2"],
                  row["beta"], row["b_w"], f.rack, tip_shortening=f.tip_shortening)
    try:
        g = pair_geometry(p)
    except GeometryError:
        return None, None
    return g, rate(g, f.mats, f.duty, f.setting).v


def _close(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9)


def _rows(c: dict) -> list[dict]:
    """The candidates as one dict of Python floats each."""
    cols = {k: v.tolist() for k, v in c.items()}
    return [{k: float(cols[k][i]) for k in cols} for i in range(len(next(iter(cols.values()))))]


def _lists(out: dict) -> dict:
    """The kernel's arrays as lists of Python numbers (the same values, read faster)."""
    return {k: v.tolist() for k, v in out.items()}


@pytest.mark.parametrize("spec, seed", [("spur_reducer_through_hardened.toml", 1),
                                        ("spur_helical_carburized_spectrum.toml", 2)])
def test_kernel_equals_scalar_on_random_pairs(spec, seed):
    """10 000 random pairs per spec (two materials/duty sets: a regime and a spectrum):
    every geometry value and factor of the kernel equals the scalar one to 1e-9."""
    f = _fixed(spec)
    c = _candidates(N, seed)
    out = _lists(evaluate(c, f))
    compared = 0
    for i, row in enumerate(_rows(c)):
        g, v = _scalar(f, row)
        if g is None:
            assert not out["valid"][i]
            continue
        assert out["valid"][i]
        for key in GEOMETRY:
            want = getattr(g, key) if hasattr(g, key) else getattr(g.gears[int(key[-1]) - 1],
                                                                    key[:-1])
            assert _close(float(out[key][i]), want), (i, key, out[key][i], want)
        for key in RATING:
            assert _close(float(out[key][i]), v[key]), (i, key, out[key][i], v[key])
        compared += 1
    assert compared >= N * 0.9


def test_kernel_honours_given_factors():
    f = _fixed("spur_reducer_through_hardened.toml")
    f = replace(f, setting=replace(f.setting, overrides={"K_Hbeta": 1.3, "Y_FS1": 4.0}))
    c = _candidates(200, 3)
    out = evaluate(c, f)
    assert np.all(out["K_Hbeta"] == 1.3) and np.all(out["Y_FS1"] == 4.0)
    for i in range(200):
        g, v = _scalar(f, {k: float(c[k][i]) for k in c})
        if g is not None:
            assert _close(float(out["S_H1"][i]), v["S_H1"])
            assert _close(float(out["S_F1"][i]), v["S_F1"])


ERROR_CODES = ("CONTACT_RATIO", "UNDERCUT_PINION", "UNDERCUT_WHEEL", "POINTED_TIP_PINION",
               "POINTED_TIP_WHEEL", "INTERFERENCE_PINION", "INTERFERENCE_WHEEL",
               "ROOT_DIAMETER_PINION", "ROOT_DIAMETER_WHEEL", "ROOT_CLEARANCE",
               "CONTACT_FATIGUE", "BENDING_FATIGUE_PINION", "BENDING_FATIGUE_WHEEL")


def _spec_of(base: dict, c: dict, i: int) -> dict:
    """The spur spec of candidate ``i``: the base spec with the candidate's gear data."""
    d = {k: (dict(v) if isinstance(v, dict) else v) for k, v in base.items()}
    d["gear"] = {k: v for k, v in base["gear"].items()
                 if k not in ("center_distance", "x1", "x2", "x_sum", "shift_split")}
    d["gear"].update(module=float(c["m_n"][i]), z1=int(c["z1"][i]), z2=int(c["z2"][i]),
                     x1=float(c["x1"][i]), x2=float(c["x2"][i]),
                     helix_angle=math.degrees(float(c["beta"][i])),
                     face_width=float(c["b_w"][i]))
    return d


def _calculator_checks(base: dict, c: dict, out: dict, n: int):
    """``(i, document, {code: passed})`` of the calculator for each of the first ``n``
    candidates it accepts; a candidate it refuses must be invalid in the kernel too."""
    for i in range(n):
        try:
            doc = run_data(_spec_of(base, c, i)).document()
        except InputError:
            assert not out["valid"][i]
            continue
        yield i, doc, {ch["code"]: ch["passed"] for ch in doc["checks"]}


def test_kernel_checks_equal_the_calculator():
    """The pass/fail of each error check of the kernel is the calculator's, pair by pair."""
    base = load_toml(SPECS / "spur_reducer_through_hardened.toml")
    base["load"].pop("peak_torque1", None)
    _, spec = load_data(base, "x")
    f = fixed_from_spec(spec)
    c = _candidates(300, 4)
    out = evaluate(c, f)
    seen = 0
    for i, _, checks in _calculator_checks(base, c, out, 300):
        for code in ERROR_CODES:
            if code in checks:
                assert bool(out["ok_" + code][i]) == checks[code], (i, code)
        seen += 1
    assert seen > 200


# ----------------------------------------------------------------------------- ISO 6336

ISO_N = 10_000
ISO_RATING = ("F_t", "v", "w", "N_L2", "f_pb", "f_falpha", "F_beta", "c_th", "C_R",
              "c_prime", "c_gamma_alpha", "c_gamma_beta", "y_alpha", "y_f", "C_a", "m_red",
              "n_E1", "N", "N_S", "K_v", "f_sh", "f_ma", "F_betax", "y_beta", "F_betay",
              "K_Hbeta", "N_F", "K_Fbeta", "Z_eps", "K_Halpha_max", "K_Falpha_max", "K_Halpha",
              "K_Falpha", "Z_H", "Z_E", "Z_beta", "M1", "M2", "Z_B", "Z_D", "sigma_H0",
              "sigma_H1", "sigma_H2", "Z_L", "Z_v", "rho_red", "Z_R", "Z_NT1", "Z_NT2", "Z_W1",
              "Z_W2", "Z_X1", "Z_X2", "sigma_HG1", "sigma_HG2", "sigma_HP1", "sigma_HP2",
              "S_H1", "S_H2", "Y_beta", "Y_DT", "s_Fn1", "s_Fn2", "h_Fe1", "h_Fe2", "rho_F1",
              "rho_F2", "alpha_Fen1", "alpha_Fen2", "q_s1", "q_s2", "Y_F1", "Y_F2", "Y_S1",
              "Y_S2", "Y_B1", "Y_B2", "sigma_F01", "sigma_F02", "sigma_F1", "sigma_F2",
              "Y_NT1", "Y_NT2", "Y_deltarelT1", "Y_deltarelT2", "Y_RrelT1", "Y_RrelT2", "Y_X1",
              "Y_X2", "Y_M1", "Y_M2", "sigma_FG1", "sigma_FG2", "sigma_FP1", "sigma_FP2",
              "S_F1", "S_F2")


def _iso_only(d: dict) -> None:
    d.setdefault("options", {}).pop("methods", None)
    d["options"]["method"] = "ISO 6336:2019"
    d["load"].pop("spectrum", None)
    d["load"].pop("regime", None)      # the GOST regime: not read by ISO 6336


def _iso_mixed(d: dict) -> None:
    """A carburized pinion against a through-hardened wheel (Z_W of the wheel), a web wheel
    with a rim (C_R, Y_B), another oil and class."""
    _iso_only(d)
    d["material"]["pinion"] = {"grade": "20KhN3A", "treatment": "carburized",
                               "hardness_HRC": 60.0, "roughness_Ra": 0.8}
    d["iso"] = {"lubricant_viscosity": 150.0, "accuracy_grade": 6,
                "pinion": {"Rz_root": 6.0},
                "wheel": {"web_ratio": 0.5, "rim_thickness": 12.0, "inner_diameter": 40.0}}


def _iso_fixed(name: str, mod):
    d = load_toml(SPECS / name)
    mod(d)
    _, spec = load_data(d, name)
    f = fixed_from_spec(spec)
    assert f.iso is not None
    return f


@pytest.mark.parametrize("spec, mod, seed", [
    ("spur_reducer_through_hardened.toml", _iso_only, 11),
    ("spur_gost_vs_iso.toml", _iso_only, 12),
    ("spur_reducer_through_hardened.toml", _iso_mixed, 13)])
def test_iso_kernel_equals_scalar_on_random_pairs(spec, mod, seed):
    """10 000 random pairs per spec (through-hardened, case-hardened and a mixed pair with a
    web wheel): every ISO 6336 factor, stress and safety factor of the kernel equals
    iso6336.rating.rate on the scalar geometry to 1e-9 (30 000 pairs, ~12 s in all)."""
    from geardesign.spur.calculator import ratable
    from geardesign.spur.strength.iso6336.rating import rate as iso_rate

    f = _iso_fixed(spec, mod)
    c = _candidates(ISO_N, seed)
    out = _lists(evaluate(c, f))
    compared = 0
    for i, row in enumerate(_rows(c)):
        p = PairInput(row["m_n"], int(row["z1"]), int(row["z2"]), row["x1"], row["x2"],
                      row["beta"], row["b_w"], f.rack, tip_shortening=f.tip_shortening)
        try:
            g = pair_geometry(p)
        except GeometryError:
            assert not out["valid"][i]
            continue
        rated = bool(out["ok_STRENGTH_NOT_RATED"][i])
        if not out["valid"][i] or not rated:
            assert not (out["valid"][i] and ratable(g))
            continue
        assert ratable(g)
        v = iso_rate(g, f.mats, f.duty, f.setting, f.iso).v
        for key in ISO_RATING:
            assert _close(float(out[key][i]), v[key]), (i, key, out[key][i], v[key])
        compared += 1
    assert compared >= ISO_N * 0.75


def test_iso_kernel_honours_given_factors():
    f = _iso_fixed("spur_gost_vs_iso.toml", _iso_only)
    f = replace(f, iso=replace(f.iso, overrides={"K_v": 1.1, "Y_F2": 2.5, "Z_NT1": 1.0}))
    c = _candidates(200, 14)
    out = evaluate(c, f)
    assert np.all(out["K_v"] == 1.1) and np.all(out["Y_F2"] == 2.5)
    from geardesign.spur.strength.iso6336.rating import rate as iso_rate

    for i in range(200):
        if out["valid"][i] and out["ok_STRENGTH_NOT_RATED"][i]:
            g, _ = _scalar(f, {k: float(c[k][i]) for k in c})
            v = iso_rate(g, f.mats, f.duty, f.setting, f.iso).v
            for key in ("S_H1", "S_H2", "S_F1", "S_F2"):
                assert _close(float(out[key][i]), v[key])


ISO_CODES = ERROR_CODES[:10] + ("STRENGTH_NOT_RATED", "ISO_PITTING_PINION", "ISO_PITTING_WHEEL",
                                "ISO_BENDING_PINION", "ISO_BENDING_WHEEL")


def test_iso_kernel_checks_equal_the_calculator():
    """The pass/fail of each error check (geometry, STRENGTH_NOT_RATED, ISO pitting and
    bending) of the ISO kernel is the calculator's, pair by pair, on ~250 pairs."""
    base = load_toml(SPECS / "spur_gost_vs_iso.toml")
    _iso_only(base)
    base["load"].pop("peak_torque1", None)
    base["load"]["torque1"] = 150.0          # about half of the pairs pass
    _, spec = load_data(base, "x")
    f = fixed_from_spec(spec)
    c = _candidates(300, 15)
    out = evaluate(c, f)
    seen = passed = 0
    for i, doc, checks in _calculator_checks(base, c, out, 300):
        checks.setdefault("STRENGTH_NOT_RATED", True)
        for code in ISO_CODES:
            if code in checks:
                assert bool(out["ok_" + code][i]) == checks[code], (i, code)
        errors = all(ch["passed"] for ch in doc["checks"] if ch["severity"] == "error")
        assert bool(out["passed"][i]) == errors, i
        passed += errors
        seen += 1
    assert seen > 200 and 20 < passed < seen - 20


def test_xp_round_is_pythons_round_on_arrays():
    """xp.rnd (the ISO 1328-1 rounding of the tolerances, Y_X) rounds an array element by
    element as Python's round does, halves included."""
    from geardesign.core import xp

    rng = np.random.default_rng(16)
    x = np.concatenate([rng.uniform(0.0, 20.0, 20_000), np.arange(0, 200) * 0.05,
                        np.arange(0, 40) * 0.5 + 0.25])
    for nd in (0, 1, 12):
        got = xp.rnd(x, nd)
        assert all(got[i] == round(float(x[i]), nd) for i in range(len(x))), nd


@pytest.mark.parametrize("standard", ["ISO 1328-1:2013", "ISO 1328-1:1995"])
def test_iso1328_tolerances_on_arrays_are_the_scalar_ones(standard):
    """The tolerances the kernel computes for arrays of candidates equal the calculator's
    for each candidate, both editions, the bounds of the 1995 size ranges included."""
    from geardesign.spur.tolerances import iso1328

    rng = np.random.default_rng(1328)
    bounds = [20.0, 50.0, 125.0, 280.0, 560.0, 1000.0]
    d = np.concatenate([rng.uniform(5.0, 3000.0, 300), bounds, np.nextafter(bounds, 1e9)])
    m = np.concatenate([rng.uniform(0.5, 40.0, 300), [2.0, 3.5, 6.0, 10.0, 16.0, 25.0],
                        np.nextafter([2.0, 3.5, 6.0, 10.0, 16.0, 25.0], 1e9)])
    b = rng.uniform(4.0, 1000.0, len(d))
    for A in (2, 6, 10):
        arrays = iso1328.tolerances(d, m, b, A, standard)
        for i in range(len(d)):
            one = iso1328.tolerances(float(d[i]), float(m[i]), float(b[i]), A, standard)
            assert all(arrays[k][i] == one[k] for k in one), (i, A)
