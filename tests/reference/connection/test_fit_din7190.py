"""Interference fits by DIN 7190-1 against an independent implementation and the published
equations (values this code did not produce).

* [WHZPressfit] (a university formula sheet of DIN 7190): permissible joint pressures
  eq. (8) hub p_zul,A = (1 − Q_A²)·R_eA/(√3·S_F), eq. (9) solid shaft 2·R_eI/(√3·S_F),
  eq. (10) hollow shaft (1 − Q_I²)·R_eI/(√3·S_F); eq. (15) the press-in force
  F_e = π·D_F·l_F·μ_ll·p_max with the release coefficient of longitudinal press fits.
* [DTProfiPassung] ``pressverband.js`` (GitHub ``DieterTepe/dt-profipassung-web``, commit
  7248026485312d08c244a476442bac014873cefe), an independent DIN 7190-1 elastic calculator,
  run with node on its own two presets (60 H7/s6 gear shrunk on a solid steel shaft, dry,
  μ = 0.14, l = 50, hub 120 mm; 45 H7/s6 hollow shaft 25 mm pressed in oiled, μ = 0.08,
  l = 40, hub 90 mm; Rz 4/1.6 µm, R_e = 355 MPa, α = 11.5e-6/K).  Its printed results:
  preset 1 p_min = 24.3075, p_max = 88.62, p_zul,A = 153.7195 MPa, S_F = 1.73459,
  F_ax = 32 072.99 N, M_t = 962.190 N·m, S_H = 3.84876, F_e = 116 931.3 N, ϑ_A = 211.304 °C;
  preset 2 p_min = 17.72522, p_max = 71.47773, p_zul,I = 141.7003 MPa, S_F = 1.98244,
  F_ax = 8 018.70 N, M_t = 180.4207 N·m, S_H = 1.50351, F_e = 32 335.76 N,
  ϑ_A = 220.966 °C.  Tolerance 1e-6 relative (both are closed forms).  One difference above
  0.5 %: for the solid shaft of preset 1 the program gives p_zul,I = R_eI/√3 = 204.96 MPa
  (its hollow-shaft formula at Q_I = 0), where DIN 7190-1 ([WHZPressfit] eq. (9)) gives
  2·R_eI/√3 = 409.92 MPa; the hub governs, so S_F agrees.  The program presses in with the
  slip coefficient; the test gives both coefficients equal to compare F_e.
"""

import math

import pytest

from geardesign.core.registry import run_data
from tests.helpers_cli import run_bad


def _fit(d, l, D_a, D_i, mu, T, **extra):
    fit = {"diameter": d, "hub_outer_diameter": D_a, "shaft_bore": D_i, "length": l,
           "fit": "H7/s6", "rz_hub": 4.0, "rz_shaft": 1.6, "friction": mu,
           "friction_press_in": mu, "shaft_yield": 355.0, "hub_yield": 355.0,
           "hub_expansion": 11.5e-6, **extra}
    doc = run_data({"kind": "connection", "load": {"torque": T}, "fit": fit}).document()
    return {k: v for section in doc["results"].values() for k, v in section.items()}, doc


PRESET_1 = {"p_min": 24.3075, "p_max": 88.62, "p_perm_hub": 153.71950917173785,
            "S_P_hub": 1.7345916178259746, "F_slip": 32072.990639396234,
            "T_slip": 962.189719181887, "S_slip": 3.8487588767275476,
            "F_press": 116931.33520367355, "theta_hub": 211.30434782608697}
PRESET_2 = {"p_min": 17.725217391304344, "p_max": 71.47772575250835,
            "p_perm_shaft": 141.70028828999702, "S_P_shaft": 1.9824397992268854,
            "F_slip": 8018.699434531743, "T_slip": 180.42073727696422,
            "S_slip": 1.5035061439747017, "F_press": 32335.76132919161,
            "theta_hub": 220.96618357487924}


@pytest.mark.parametrize("case, want", [((60.0, 50.0, 120.0, 0.0, 0.14, 250.0), PRESET_1),
                                        ((45.0, 40.0, 90.0, 25.0, 0.08, 120.0), PRESET_2)])
def test_independent_din7190_calculator(case, want):
    r, _ = _fit(*case)
    for key, value in want.items():
        assert r[key] == pytest.approx(value, rel=1e-6), f"[DTProfiPassung] {key}"


def test_permissible_pressures_of_the_published_equations():
    """[WHZPressfit] eqs. (8)-(10) at R_e = 355 MPa: hub Q_A = 0.5, 0.75·355/√3; solid shaft
    2·355/√3 (the program above: 355/√3, see the module note); hollow Q_I = 5/9."""
    r, _ = _fit(60.0, 50.0, 120.0, 0.0, 0.14, 250.0)
    assert r["p_perm_hub"] == pytest.approx(0.75 * 355.0 / math.sqrt(3.0), rel=1e-12)
    assert r["p_perm_shaft"] == pytest.approx(2.0 * 355.0 / math.sqrt(3.0), rel=1e-12)
    assert r["p_perm_shaft"] / 204.95934556231717 == pytest.approx(2.0, rel=1e-9)
    r, _ = _fit(45.0, 40.0, 90.0, 25.0, 0.08, 120.0)
    assert r["p_perm_shaft"] == pytest.approx((1 - (25 / 45) ** 2) * 355.0 / math.sqrt(3.0))


def test_the_von_mises_option_is_the_exact_plane_stress_limit():
    """pressure_limit = "von Mises": the safety is R_e over the Lamé von Mises stress at the
    bore (plane stress), √3/√(3 + Q_A⁴) of DIN's at the hub and √3/2 of it in the shaft;
    the report names the model."""
    din, _ = _fit(60.0, 50.0, 120.0, 0.0, 0.14, 250.0)
    vm, doc = _fit(60.0, 50.0, 120.0, 0.0, 0.14, 250.0, pressure_limit="von Mises")
    assert vm["S_P_hub"] == pytest.approx(355.0 / vm["sigma_v_hub"], rel=1e-12)
    assert vm["S_P_shaft"] == pytest.approx(355.0 / vm["sigma_v_shaft"], rel=1e-12)
    assert vm["S_P_hub"] / din["S_P_hub"] == pytest.approx(math.sqrt(3 / (3 + 0.5 ** 4)))
    assert vm["S_P_shaft"] / din["S_P_shaft"] == pytest.approx(math.sqrt(3) / 2)
    assert vm["U_perm"] < din["U_perm"]
    assert vm["pressure_limit"] == "von Mises" and din["pressure_limit"] == "DIN 7190-1"
    assert "permissible joint pressure: von Mises" in doc["methods"]
    hub = next(c for c in doc["checks"] if c["code"] == "FIT_HUB_YIELD")
    assert hub["message"].endswith("(von Mises)")


def test_the_press_in_force_has_its_own_coefficient():
    """By default the press-in force takes the coefficient of longitudinal press fits of the
    joint's surface (DIN 7190-1, [WHZPressfit] eq. (15)), whatever the joining; the slip
    check keeps the joining's coefficient; friction_press_in overrides it."""
    base = dict(diameter=50.0, hub_outer_diameter=90.0, length=50.0, fit="H7/u6",
                shaft_yield=430.0, hub_yield=650.0, joining="shrink", surface="dry")
    for fit, mu, mu_e in ((base, 0.20, 0.10), (dict(base, surface="oiled"), 0.14, 0.08),
                          (dict(base, joining="press"), 0.10, 0.10),
                          (dict(base, friction_press_in=0.3), 0.20, 0.3)):
        r = run_data({"kind": "connection", "load": {"torque": 100.0}, "fit": fit}
                     ).document()["results"]
        assert (r["capacity"]["mu"], r["assembly"]["mu_press_in"]) == (mu, mu_e)
        assert r["assembly"]["F_press"] == pytest.approx(
            math.pi * 50.0 * 50.0 * mu_e * r["capacity"]["p_max"], rel=1e-12)


def test_an_unknown_pressure_limit_is_refused(tmp_path):
    lines = run_bad(tmp_path, 'kind = "connection"\n[load]\ntorque = 100.0\n[fit]\n'
                    'diameter = 50.0\nhub_outer_diameter = 90.0\nlength = 50.0\n'
                    'fit = "H7/u6"\nshaft_yield = 430.0\nhub_yield = 650.0\n'
                    'pressure_limit = "Tresca"\n')
    assert len(lines) == 1 and lines[0].startswith('s.toml: fit.pressure_limit = "Tresca": ')
    assert '"DIN 7190-1"' in lines[0] and '"von Mises"' in lines[0]
