"""The vectorised spur kernel gives the numbers of the scalar calculator: geometry and the
GOST 21354-87 rating on 10 000 random valid pairs to 1e-9 relative, and the pass/fail of
every error check on a few hundred pairs run through the whole calculator."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data, run_data
from geardesign.core.spec import load_toml
from geardesign.spur.geometry import GeometryError, PairInput, pair_geometry
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


@pytest.mark.parametrize("spec, seed", [("spur_reducer_through_hardened.toml", 1),
                                        ("spur_helical_carburized_spectrum.toml", 2)])
def test_kernel_equals_scalar_on_random_pairs(spec, seed):
    """10 000 random pairs per spec (two materials/duty sets: a regime and a spectrum):
    every geometry value and factor of the kernel equals the scalar one to 1e-9."""
    f = _fixed(spec)
    c = _candidates(N, seed)
    out = evaluate(c, f)
    compared = 0
    for i in range(N):
        row = {k: float(c[k][i]) for k in c}
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


def test_kernel_checks_equal_the_calculator():
    """The pass/fail of each error check of the kernel is the calculator's, pair by pair."""
    base = load_toml(SPECS / "spur_reducer_through_hardened.toml")
    base["load"].pop("peak_torque1", None)
    _, spec = load_data(base, "x")
    f = fixed_from_spec(spec)
    c = _candidates(300, 4)
    out = evaluate(c, f)
    seen = 0
    for i in range(300):
        d = {k: (dict(v) if isinstance(v, dict) else v) for k, v in base.items()}
        d["gear"] = {k: v for k, v in base["gear"].items()
                     if k not in ("center_distance", "x1", "x2", "x_sum", "shift_split")}
        d["gear"].update(module=float(c["m_n"][i]), z1=int(c["z1"][i]), z2=int(c["z2"][i]),
                         x1=float(c["x1"][i]), x2=float(c["x2"][i]),
                         helix_angle=math.degrees(float(c["beta"][i])),
                         face_width=float(c["b_w"][i]))
        try:
            doc = run_data(d).document()
        except InputError:
            assert not out["valid"][i]
            continue
        checks = {ch["code"]: ch["passed"] for ch in doc["checks"]}
        for code in ERROR_CODES:
            if code in checks:
                assert bool(out["ok_" + code][i]) == checks[code], (i, code)
        seen += 1
    assert seen > 200
