"""Bevel load factors by ISO 10300-1 method B and the static checks at a peak torque.

Published: [ISOTR10300-30] sample 1 prints K_v = 1.020 and K_Hα = 1.161 as its method B
results for the single pitch deviations f_pt1 = 12 µm, f_pt2 = 26 µm, case-hardened steel,
ρ = 7.86·10⁻⁶ kg/mm³ (the inputs as transcribed in the self-test of [ISO10300Calc]);
half a unit of the last printed digit.  The peak-load checks have no published case: their
tests are properties (scaling with the torque, the one source of the static limits) and the
input rules.
"""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.bevel import factors, solve
from geardesign.bevel.inputs import Accuracy, Inputs, Load, Material, Pair, Rating
from geardesign.spur.strength.iso6336 import part3 as P3

M_MN = 3.2133
SAMPLE1_PAIR = Pair(True, 176.893 / 39, "outer", 14, 39, math.pi / 2, 25.4, math.radians(35.0),
                    "left", math.radians(20.0), 1.0, 0.25, 0.8 / M_MN, 0.505, 2.0 * 0.036,
                    "constant_clearance", xt2=2.0 * -0.055, rho_a02=1.2 / M_MN)


def _sample1(K_v=None, K_alpha=None, T_peak=None, method="iso10300", **material):
    mat = dict(sigma_HPmax=(2640.0, 2640.0), sigma_FSt=(2000.0, 2000.0)) | material
    return Inputs(SAMPLE1_PAIR,
                  Load(300e3, 1200.0, "cw", "pinion", 1.1, K_v, "one_straddle", K_alpha,
                       T_peak),
                  Material((1500.0, 1500.0), (480.0, 480.0), "both_hard", 210000.0, 0.3,
                           **mat),
                  Rating(method, 1.0, 1.3), Accuracy((12.0, 26.0), 7.86e-6))


# (value, tolerance): [ISOTR10300-30] sample 1, method B, half a unit of the last digit
SAMPLE1_FACTORS = {"K_v": (1.020, 0.0005), "K_Halpha": (1.161, 0.0005)}
# the stresses of the sample with the factors computed here (printed with K_v, K_Hα of
# its own method B; tolerances as in tests/test_bevel_published.py)
SAMPLE1_STRESSES = {"sigma_H": (1712.8, 1.5), "sigma_F1": (680.1, 0.9),
                    "sigma_F2": (700.1, 0.9)}


@pytest.mark.parametrize("key", sorted(SAMPLE1_FACTORS))
def test_sample1_method_b_factors(key):
    sol = solve.solve(_sample1())
    value, tol = SAMPLE1_FACTORS[key]
    assert getattr(sol.factors, key) == pytest.approx(value, abs=tol)
    assert sol.factors.K_v_src == sol.factors.K_Halpha_src == "method B"
    assert sol.factors.method_b.range == "subcritical"


@pytest.mark.parametrize("key", sorted(SAMPLE1_STRESSES))
def test_sample1_stresses_with_method_b_factors(key):
    r = solve.solve(_sample1()).iso
    ours = {"sigma_H": r.sigma_H, "sigma_F1": r.pinion.sigma_F, "sigma_F2": r.wheel.sigma_F}
    value, tol = SAMPLE1_STRESSES[key]
    assert ours[key] == pytest.approx(value, abs=tol)


def test_given_factors_override_method_b():
    sol = solve.solve(_sample1(K_v=1.3, K_alpha=1.05))
    lf = sol.factors
    assert (lf.K_v, lf.K_v_src, lf.K_Halpha, lf.K_Halpha_src) == (1.3, "given", 1.05, "given")
    auto = solve.solve(_sample1())
    assert sol.iso.sigma_H == pytest.approx(
        auto.iso.sigma_H * math.sqrt(1.3 * 1.05 / (auto.factors.K_v * auto.factors.K_Halpha)))


def test_without_accuracy_the_factors_are_assumed():
    inp = dataclasses.replace(_sample1(), accuracy=None)
    lf = solve.solve(inp).factors
    assert (lf.K_v, lf.K_v_src, lf.K_Halpha, lf.K_Halpha_src) == (
        factors.K_V_ASSUMED, "assumed", factors.K_HALPHA_ASSUMED, "assumed")
    assert lf.method_b is None


@given(st.floats(0.0, 3.0), st.floats(0.5, 40.0), st.floats(1.0, 3.2))
@settings(max_examples=60, deadline=None)
def test_dynamic_factor_continuous_over_the_ranges(N, f_eff, eps):
    """K_v is continuous at the range limits 0.75 (not: the main resonance jumps, as in
    ISO 6336-1), 1.25 and 1.5, and never below 1 in the subcritical range."""
    K = lambda n: factors.dynamic_factor(n, 14.0, f_eff, 300.0, eps)[0]  # noqa: E731
    for edge in (factors.N_MAIN, 1.5):
        assert K(edge - 1e-9) == pytest.approx(K(edge + 1e-9), abs=1e-6)
    if N <= factors.N_SUB:
        assert K(N) >= 1.0


def test_transverse_factor_within_its_limits():
    k, k_max = factors.transverse_factor(1.3, 1.3, 1.0, 20.0, 200.0, 50.0)
    assert k == pytest.approx(k_max)
    assert factors.transverse_factor(2.5, 1.2, 0.95, 20.0, 0.0, 800.0)[0] == 1.0


# --------------------------------------------------------------------------- peak load


def test_no_peak_torque_no_peak_checks():
    sol = solve.solve(_sample1(method="both"))
    assert sol.iso_peak is None and sol.gost_peak is None


@given(st.floats(1.0, 4.0), st.sampled_from(["iso10300", "both"]))
@settings(max_examples=25, deadline=None)
def test_peak_stresses_scale_with_the_torque(ratio, method):
    """ISO: σ_H,st = σ_H √(T_max/(T K_A)), σ_F,st = σ_F T_max/(T K_A); GOST: σ_Hmax and
    σ_Fmax by the spur formulas with the load factors at the peak (K_A = K_v = 1)."""
    sol = solve.solve(_sample1(T_peak=300e3 * ratio, method=method))
    p, r, K_A = sol.iso_peak, sol.iso, 1.1
    assert p.sigma_H == pytest.approx(r.sigma_H * math.sqrt(ratio / K_A))
    for pm, m in zip((p.pinion, p.wheel), (r.pinion, r.wheel)):
        assert pm.sigma_F == pytest.approx(m.sigma_F * ratio / K_A)
        assert pm.S_F == pytest.approx(pm.sigma_FG / pm.sigma_F)
    if method == "both":
        q, gr = sol.gost_peak, sol.gost
        K_Hb = 1.5 * 1.10
        K_max = ((K_Hb - 1) / ratio + 1) * ((sol.factors.K_Halpha - 1) / ratio + 1)
        assert q.K_Hmax == pytest.approx(K_max)
        assert q.sigma_Hmax == pytest.approx(gr.sigma_H * math.sqrt(ratio * K_max / gr.K_H))
        for qm, m in zip((q.pinion, q.wheel), (gr.pinion, gr.wheel)):
            assert qm.sigma_Fmax == pytest.approx(m.sigma_F * ratio * K_max / gr.K_F)


@pytest.mark.parametrize("material, Z_NT, Y_NT", [("Eh", 1.6, 2.5), ("V", 1.6, 2.5),
                                                  ("NT", 1.3, 1.6)])
def test_static_limits_are_the_iso6336_ones(material, Z_NT, Y_NT):
    """The life factors at the static point of ISO 6336-2/-3 (the spur function, called)."""
    p = solve.solve(_sample1(T_peak=600e3, type=material, sigma_02=800.0)).iso_peak
    assert (p.Z_NT, p.Y_NT) == (Z_NT, Y_NT)
    for i, m in enumerate((p.pinion, p.wheel)):
        Y_S = (solve.solve(_sample1()).iso.pinion, solve.solve(_sample1()).iso.wheel)[i].Y_Sa
        limits = P3.static_limits(material, 1500.0, 480.0, Y_S, 800.0)
        assert m.sigma_HG == pytest.approx(limits[1] * 1.2)      # with Z_K
        assert m.sigma_FG == pytest.approx(limits[4])


def _spec(tmp_path, extra_load="", extra_material="", extra=""):
    path = tmp_path / "b.toml"
    path.write_text(f"""kind = "bevel"
[pair]
teeth = "spiral"
module = 3.5
module_at = "mean"
z1 = 17
z2 = 43
face_width = 32.0
spiral_angle = 35.0
clearance = 0.25
x1 = 0.3
[load]
torque = 220.0
speed = 1450.0
{extra_load}
[material]
sigma_Hlim1 = 1500.0
sigma_Hlim2 = 1500.0
sigma_Flim1 = 500.0
sigma_Flim2 = 500.0
{extra_material}
{extra}
""")
    return path


def _run(path):
    from geardesign.bevel.calculator import compute
    from geardesign.core.registry import load

    return compute(load(path)[1])


def _codes(res):
    return [c.code for c in res.checks]


def test_peak_checks_in_the_report(tmp_path):
    res = _run(_spec(tmp_path, "peak_torque = 500.0",
                     "sigma_HPmax1 = 2640.0\nsigma_HPmax2 = 2640.0\nsigma_FSt1 = 2000.0\n"
                     "sigma_FSt2 = 2000.0"))
    codes = _codes(res)
    for code in ("ISO_STATIC_PITTING", "ISO_STATIC_BENDING", "GOST_STATIC_CONTACT",
                 "GOST_STATIC_BENDING"):
        assert codes.count(code) == 2
    assert "GOST_STATIC_NOT_RATED" not in codes


def test_gost_peak_without_limits_is_said(tmp_path):
    res = _run(_spec(tmp_path, "peak_torque = 500.0"))
    c = next(c for c in res.checks if c.code == "GOST_STATIC_NOT_RATED")
    assert c.severity == "warning" and "sigma_HPmax1" in c.message
    assert _codes(res).count("ISO_STATIC_PITTING") == 2


def test_failed_peak_check_carries_a_fix(tmp_path):
    """A failed static check is advised by re-rating, like the fatigue checks."""
    from geardesign.core.registry import get, load

    path = _spec(tmp_path, "peak_torque = 700.0",
                 "sigma_HPmax1 = 2640.0\nsigma_HPmax2 = 2640.0\nsigma_FSt1 = 1200.0\n"
                 "sigma_FSt2 = 1200.0")
    res = get("bevel").compute(load(path)[1])
    failed = [c for c in res.checks if c.code == "GOST_STATIC_BENDING" and not c.passed]
    assert failed and all(c.fix for c in failed)
    assert failed[0].fix[0][0] in ("pair.face_width", "pair.module")


def test_given_factor_marked_in_the_report(tmp_path):
    res = _run(_spec(tmp_path, "dynamic_factor = 1.2", extra="[accuracy]\nf_pt1 = 12.0\n"
                     "f_pt2 = 16.0"))
    rows = {r.key: r for r in res.section("load_factors", "").rows}
    assert "(given)" in rows["K_v"].name and "(method B)" in rows["K_Halpha"].name


@pytest.mark.parametrize("extra_load, extra_material, key", [
    ("peak_torque = 100.0", "", "load.peak_torque"),
    ("", "sigma_HPmax1 = 2640.0", "material.sigma_HPmax1"),
])
def test_bad_peak_input_is_one_line(tmp_path, extra_load, extra_material, key):
    from geardesign.core.errors import InputError

    with pytest.raises(InputError) as exc:
        _run(_spec(tmp_path, extra_load, extra_material))
    assert [p.key for p in exc.value.problems] == [key]


def test_drive_passes_its_peak_ratio_to_a_bevel_stage():
    from geardesign.core.registry import load
    from geardesign.drive.bevel_stage import bevel_data
    from geardesign.drive.stages import Duty

    data = load("specs/drive_bevel_helical.toml")[1].data["stage"][0]
    fields = {f.name: None for f in dataclasses.fields(Duty)}
    duty = Duty(**(fields | {"K_A": 1.25, "peak_ratio": 2.0}))
    d = bevel_data(data, 40.0, 1455.0, duty, "stage[0]")
    assert d["load"]["peak_torque"] == pytest.approx(80.0)
    no_peak = bevel_data(data, 40.0, 1455.0, dataclasses.replace(duty, peak_ratio=None), "s")
    assert no_peak["load"].get("peak_torque") is None
