"""ISO 6336 parts 2, 3, 5, 6 and 21: the remaining factors at stated inputs, each against the
equation of the clause named (and where available a printed value).

* Y_DT: [ISO6336-3] — 1 up to ε_αn = 2.05, 2.366 − 0.666ε_αn to 2.5, 0.7 beyond
  (grade ≤ 4); transcribed alike in [PythonGearbox2020] ``__ydt`` (which misprints 0.9
  for the last range) and in the public JavaScript ``toothRootStressCalc2``.
* Y_B of an internal gear: 1.15 ln(8.324 m_n/s_R) for 1.75 < s_R/m_n < 3.5.
* ρ' (Y_δrelT): the table of [ISO6336-3], interpolated; Y_δrelT static by material group.
* σ_Hlim, σ_Flim: the lines A·x + B of [ISO6336-5] Table 2 (St MQ: 1.000x + 190,
  0.455x + 69 over 110…210 HBW).
* Miner's rule ([ISO6336-6]) on a single-slope S-N curve σ_G = 1000 N^(−1/10), where the
  damage sum and the spectrum safety have closed forms: N = (1000/σ)^10,
  S = (Σ n_i (σ_i/1000)^10)^(−1/10).
* Scuffing ([ISO6336-21]): X_Q, X_ε branches, X_mp, Θ_M, X_BE, μ_mC, Θ_flaE as printed
  there; the KISSsoft NREL stage 3 chain is in ``test_iso6336_scuffing``.
"""

import math

import pytest

from geardesign.spur.strength.iso6336 import part2 as P2
from geardesign.spur.strength.iso6336 import part3 as P3
from geardesign.spur.strength.iso6336 import part5 as P5
from geardesign.spur.strength.iso6336 import part6 as P6
from geardesign.spur.strength.iso6336 import part21 as P21


@pytest.mark.parametrize("eps_an, grade, expected", [
    (2.3, 5, 1.0), (1.9, 4, 1.0), (2.0, 4, 1.0), (2.05, 4, 1.0), (2.2, 4, 2.366 - 0.666 * 2.2),
    (2.5, 4, 2.366 - 0.666 * 2.5), (2.6, 4, 0.7)])
def test_deep_tooth_factor(eps_an, grade, expected):
    assert float(P3.y_dt(eps_an, grade)) == pytest.approx(expected, rel=1e-12)


def test_rim_factor_internal():
    m = 10.0
    assert float(P3.y_b(40.0, 22.5, m, internal=True)) == 1.0
    assert float(P3.y_b(35.0, 22.5, m, internal=True)) == 1.0
    assert float(P3.y_b(25.0, 22.5, m, internal=True)) == pytest.approx(1.15 * math.log(8.324 / 2.5))
    assert P3.y_b(None, 22.5, m) == 1.0
    assert P3.y_b_domain(25.0, 22.5, m, internal=True) == 17.5
    assert P3.y_b_domain(25.0, 22.5, m) == 11.25


@pytest.mark.parametrize("material, sigma_B, sigma_02, expected", [
    ("Eh", None, None, 0.003), ("NT", None, None, 0.1005), ("GG", None, None, 0.3124),
    ("St", 250.0, None, 0.4445), ("St", 350.0, None, 0.5 * (0.4445 + 0.3070)),
    ("St", 450.0, None, 0.3070), ("St", None, None, 0.4445),
    ("V", None, 450.0, 0.0281), ("V", None, 550.0, 0.5 * (0.0281 + 0.0194)),
    ("V", None, 700.0, 0.5 * (0.0194 + 0.0064)), ("V", None, 900.0, 0.5 * (0.0064 + 0.0014)),
    ("V", None, 1200.0, 0.0014)])
def test_slip_layer_thickness(material, sigma_B, sigma_02, expected):
    assert P3.rho_prime(material, sigma_B, sigma_02) == pytest.approx(expected, rel=1e-12)


def test_static_notch_sensitivity():
    k = 0.82 * (300.0 / 800.0) ** 0.25
    assert P3.y_delta_rel_static("V", 2.1, 800.0) == pytest.approx((1 + k * 1.1) / (1 + k))
    k6 = 0.82 * 0.5 ** 0.25
    assert P3.y_delta_rel_static("St", 2.1, None) == pytest.approx((1 + k6 * 1.1) / (1 + k6))
    assert P3.y_delta_rel_static("Eh", 2.1, None) == pytest.approx(0.44 * 2.1 + 0.12)
    assert P3.y_delta_rel_static("NT", 2.1, None) == pytest.approx(1.22 / 1.2)
    assert P3.y_delta_rel_static("GG", 2.1, None) == 1.0


def test_mean_stress_factor_and_root_stresses():
    assert P3.y_m(0.0) == 1.0 and P3.y_m(1.0) == pytest.approx(0.7)
    assert P3.y_m(0.5) == pytest.approx(0.85) and P3.y_m(2.0) == pytest.approx(0.7)
    assert P3.y_m(-1.0) == 1.0
    s0 = P3.nominal_root_stress(10000.0, 50.0, 4.0, 1.5, 2.1, 0.9, 1.1, 0.95)
    assert s0 == pytest.approx(10000.0 / 200.0 * 1.5 * 2.1 * 0.9 * 1.1 * 0.95)
    assert P3.root_stress(s0, 1.25, 1.1, 1.05, 1.2, 1.1) == pytest.approx(
        s0 * 1.25 * 1.1 * 1.05 * 1.2 * 1.1)
    assert P3.reference_cycles_bending("Eh") == (1e3, 3e6)
    assert P3.reference_cycles_bending("V") == (1e4, 3e6)


def test_contact_stresses_of_tr30():
    """σ_H0 = Z_H Z_E Z_ε Z_β √(F_t/(d1 b)·(u + 1)/u) with the printed factors of ISO/TR
    6336-30 ex. 1 (Z_H 2.39533, Z_E 189.8117, Z_β 1.01944, F_t 127352 N, d1 = 141.33 mm,
    b = 100, u = 103/17); Z_ε from ε_α = 1.5491, ε_β = 1.0825: σ_H0 = 1206.58 printed."""
    d1 = 17 * 8.0 / math.cos(math.radians(15.8))
    s0 = float(P2.nominal_contact_stress(2.39533, 189.8117, math.sqrt(1 / 1.5491), 1.01944,
                                         127352.0, d1, 100.0, 103 / 17))
    assert s0 == pytest.approx(1206.58207, rel=1e-3)
    s_int = float(P2.nominal_contact_stress(2.39533, 189.8117, 0.8, 1.0, 127352.0, d1, 100.0,
                                            103 / 17, internal=True))
    s_ext = float(P2.nominal_contact_stress(2.39533, 189.8117, 0.8, 1.0, 127352.0, d1, 100.0,
                                            103 / 17))
    assert s_int == pytest.approx(s_ext * math.sqrt((103 / 17 - 1) / (103 / 17 + 1)), rel=1e-12)
    sH = float(P2.contact_stress(1.0, s0, 1.0, 1.0, 1.003, 1.16, 1.0))
    assert sH == pytest.approx(s0 * math.sqrt(1.003 * 1.16), rel=1e-12)
    assert P2.safety(1338.4805, 1301.35343) == pytest.approx(1.02853, abs=6e-6)


def test_influence_factors_in_the_limited_life_range():
    """Z_L·Z_v·Z_R (and Y_δ, Y_R, Y_X) are 1 at the static point, their value from the
    reference point on, log–log between ([ISO6336-2], [ISO6336-3])."""
    assert float(P2.interpolated(0.9, 1e5, 1e5, 5e7)) == 1.0
    assert float(P2.interpolated(0.9, 1e4, 1e5, 5e7)) == 1.0
    assert float(P2.interpolated(0.9, 5e7, 1e5, 5e7)) == 0.9
    assert float(P2.interpolated(0.9, 1e9, 1e5, 5e7)) == 0.9
    k = math.log(1e6 / 1e5) / math.log(5e7 / 1e5)
    assert float(P2.interpolated(0.9, 1e6, 1e5, 5e7)) == pytest.approx(0.9 ** k, rel=1e-12)
    assert float(P2.interpolated(0.9, 1e6, 1e5, 5e7, 1.1)) == pytest.approx(
        1.1 * (0.9 / 1.1) ** k, rel=1e-12)
    assert P2.reference_cycles_contact("Eh") == (1e5, 5e7)
    assert P2.reference_cycles_contact("Eh", limited_pitting=True) == (6e5, 1e9)
    assert P2.reference_cycles_contact("NT") == (1e5, 2e6)
    assert float(P2.z_nt("Eh", 1e10, optimum=True)) == 1.0
    assert float(P2.z_nt("Eh", 5e8, optimum=True)) == 1.0


def test_work_hardening_factor():
    """[ISO6336-2] Z_W: (1.2 − (HB − 130)/1700)(3/R_zH)^0.15, HB within 130…470,
    3 ≤ R_zH ≤ 16 µm."""
    assert P2.z_w(240.0) == pytest.approx(1.2 - 110.0 / 1700.0, rel=1e-12)
    assert P2.z_w(100.0) == pytest.approx(1.2, rel=1e-12)
    assert P2.z_w(500.0) == pytest.approx(1.2 - 340.0 / 1700.0, rel=1e-12)
    rzh = 4.0 * (10.0 / 8.0) ** 0.33 * (4.0 / 5.0) ** 0.66 / (150.0 * 5.0 / 1500.0) ** 0.33
    assert 3.0 < rzh < 16.0
    assert float(P2.z_w(300.0, 4.0, 5.0, 8.0, 5.0, 150.0)) == pytest.approx(
        (1.2 - 170.0 / 1700.0) * (3.0 / rzh) ** 0.15, rel=1e-12)
    assert float(P2.z_w(300.0, 20.0, 3.0, 2.0, 0.5, 100.0)) == pytest.approx(
        (1.2 - 170.0 / 1700.0) * (3.0 / 16.0) ** 0.15, rel=1e-12)
    assert P2.z_x("Eh", 20.0) == 1.0


@pytest.mark.parametrize("material, quality, hardness, sH, sF, x, clamped", [
    ("St", "MQ", 150.0, 340.0, 0.455 * 150 + 69.0, 150.0, False),
    ("St", "ME", 150.0, 1.52 * 150 + 250.0, 0.386 * 150 + 147.0, 150.0, False),
    ("St", "MQ", 250.0, 400.0, 0.455 * 210 + 69.0, 210.0, True),
    ("St", "MQ", 100.0, 300.0, 0.455 * 110 + 69.0, 110.0, True)])
def test_material_limits(material, quality, hardness, sH, sF, x, clamped):
    L = P5.limits(material, quality, hardness)
    assert L.sigma_Hlim == pytest.approx(sH) and L.sigma_Flim == pytest.approx(sF)
    assert L.hardness == x and L.scale == "HBW" and L.clamped is clamped


def test_hardness_scales():
    assert P5.hardness_on_scale("HV", None, 600.0) == 600.0
    assert P5.hardness_on_scale("HV", 570.0, None) == pytest.approx(600.0)
    assert P5.hardness_on_scale("HBW", 300.0, 700.0) == 300.0
    assert P5.hardness_on_scale("HBW", None, 300.0) == pytest.approx(285.0)
    assert P5.hardness_on_scale("HV", 500.0, 620.0) == 620.0


def _sigma_G(N):
    return 1000.0 * N ** -0.1


def test_miner_rule_closed_form():
    assert P6.cycles_to_failure(500.0, _sigma_G) == pytest.approx(2.0 ** 10, rel=1e-9)
    assert P6.cycles_to_failure(1001.0, _sigma_G) == 0.0
    assert P6.cycles_to_failure(_sigma_G(1e10), _sigma_G) == math.inf
    assert P6.cycles_to_failure(_sigma_G(1e10) * 0.9, _sigma_G) == math.inf
    blocks, cycles = [500.0, 400.0], [100.0, 1000.0]
    D = 100.0 / 2.0 ** 10 + 1000.0 / 2.5 ** 10
    assert P6.damage(blocks, cycles, _sigma_G) == pytest.approx(D, rel=1e-9)
    assert P6.damage([500.0, 50.0], [100.0, 1e12], _sigma_G) == pytest.approx(100.0 / 2.0 ** 10,
                                                                           rel=1e-9)
    assert P6.damage([500.0, 2000.0], [100.0, 0.0], _sigma_G) == pytest.approx(100.0 / 2.0 ** 10,
                                                                            rel=1e-9)
    assert P6.damage([2000.0], [1.0], _sigma_G) == math.inf
    S = sum(n * (s / 1000.0) ** 10 for s, n in zip(blocks, cycles)) ** -0.1
    assert P6.spectrum_safety(blocks, cycles, _sigma_G) == pytest.approx(S, rel=1e-9)
    assert P6.spectrum_safety([0.0], [1.0], _sigma_G) == math.inf
    # a spectrum too short to reach D = 1 below the static limit: the static limit sets S
    assert P6.spectrum_safety([500.0], [1e-6], _sigma_G) == pytest.approx(2.0, rel=1e-6)


@pytest.mark.parametrize("ratio, expected", [(1.0, 1.0), (1.5, 1.0), (2.0, 1.4 - 8 / 15),
                                             (3.0, 0.6), (4.0, 0.6)])
def test_approach_factor(ratio, expected):
    assert P21.approach_factor(ratio, 1.0) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("e1, e2, numerator, branch", [
    (0.5, 0.4, 0.25 + 0.16, "ε_α < 1"),
    (0.8, 0.7, 0.70 * (0.64 + 0.49) - 0.22 * 1.5 + 0.52 - 0.60 * 0.56, "1 ≤ ε_α < 2, ε_1 < 1, ε_2 < 1"),
    (1.2, 0.5, 0.18 * 1.44 + 0.70 * 0.25 + 0.82 * 1.2 - 0.52 * 0.5 - 0.30 * 0.6, "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1"),
    (0.5, 1.2, 0.70 * 0.25 + 0.18 * 1.44 - 0.52 * 0.5 + 0.82 * 1.2 - 0.30 * 0.6, "1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1"),
    (1.2, 1.1, 0.44 * 1.44 + 0.59 * 1.21 + 0.30 * 1.2 - 0.30 * 1.1 - 0.15 * 1.32, "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1"),
    (1.8, 1.4, 0.44 * 3.24 + 0.59 * 1.96 + 0.30 * 1.8 - 0.30 * 1.4 - 0.15 * 2.52, "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1 (nearest)"),
    (1.5, 0.7, 0.18 * 2.25 + 0.70 * 0.49 + 0.82 * 1.5 - 0.52 * 0.7 - 0.30 * 1.05, "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1 (nearest)"),
    (0.7, 1.5, 0.70 * 0.49 + 0.18 * 2.25 - 0.52 * 0.7 + 0.82 * 1.5 - 0.30 * 1.05, "1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1 (nearest)")])
def test_contact_ratio_factor_for_scuffing(e1, e2, numerator, branch):
    X, name = P21.contact_ratio_factor(e1, e2)
    assert X == pytest.approx(numerator / (2.0 * (e1 + e2) * e1), rel=1e-12)
    assert name == branch


def test_scuffing_temperature_terms():
    assert P21.multiple_mesh_factor(1) == 1.0 and P21.multiple_mesh_factor(2) == 1.5
    assert P21.bulk_temperature(80.0, 100.0, 1.2, 1.5) == pytest.approx(80.0 + 0.7 * 1.5 * 1.2 * 100.0)
    assert P21.helical_load_factor(1.9) == 1.0 and P21.helical_load_factor(3.6) == 1.3
    assert P21.helical_load_factor(3.0) == pytest.approx(1.0 + 0.2 * math.sqrt(2.0))
    rho1, rho2, u = 10.0, 40.0, 3.0
    xbe = 0.51 * math.sqrt(4.0) * abs(math.sqrt(10.0) - math.sqrt(40.0 / 3.0)) / 400.0 ** 0.25
    assert P21.geometry_factor_tip(rho1, rho2, u) == pytest.approx(xbe, rel=1e-12)
    xbe_i = 0.51 * math.sqrt(2.0) * abs(math.sqrt(10.0) - math.sqrt(40.0 / 3.0)) / 400.0 ** 0.25
    assert P21.geometry_factor_tip(rho1, rho2, u, internal=True) == pytest.approx(xbe_i, rel=1e-12)
    mu = 0.045 * (500.0 / (10.0 * 20.0)) ** 0.2 * 50.0 ** -0.05 * 0.8 * 1.0
    assert P21.mean_friction(500.0, 10.0, 20.0, 50.0, 0.8, 1.0) == pytest.approx(mu, rel=1e-12)
    fla = 0.05 * 50.0 * 0.2 * 0.98 * 500.0 ** 0.75 * math.sqrt(10.0) / 200.0 ** 0.25 * 1.1 / (0.9 * 1.2)
    assert P21.flash_temperature_tip(0.05, 50.0, 0.2, 0.98, 500.0, 10.0, -200.0, 1.1, 0.9,
                                     1.2) == pytest.approx(fla, rel=1e-12)
    assert P21.tip_relief_factor(50.0, 40.0, 0.8) == pytest.approx(
        1.0 + 0.24 * 0.8 + 0.71 * 0.64, rel=1e-12)
    assert P21.oil_density(880.0, 15.0) == 880.0
    assert P21.oil_density(880.0, 115.0) == pytest.approx(880.0 * (1.0 - 0.07), rel=1e-12)
    th, thM, thf = P21.integral_scuffing_temperature(10, 100.0, 1.1, 1.0)
    T1 = P21.fzg_torque(10)
    assert thM == pytest.approx(80.0 + 0.23 * T1 * 1.1) and thf == pytest.approx(0.2 * T1 * 1.1)
    assert th == pytest.approx(thM + 1.5 * thf)


@pytest.mark.parametrize("material, sigma_Hlim, v, f_pb, expected", [
    ("St", 600.0, 3.0, 20.0, 160.0 / 600.0 * 20.0), ("St", 600.0, 8.0, 100.0, 12800.0 / 600.0),
    ("St", 600.0, 8.0, 20.0, 160.0 / 600.0 * 20.0), ("St", 600.0, 12.0, 100.0, 6400.0 / 600.0),
    ("GG", 300.0, 3.0, 100.0, 27.5), ("GG", 300.0, 8.0, 100.0, 22.0),
    ("GG", 300.0, 12.0, 100.0, 11.0), ("GG", 300.0, 12.0, 20.0, 5.5),
    ("Eh", 1500.0, 3.0, 20.0, 1.5), ("Eh", 1500.0, 3.0, 60.0, 3.0)])
def test_running_in_allowance_of_the_pitch(material, sigma_Hlim, v, f_pb, expected):
    """[ISO6336-1] eqs. (75)–(77): y_α = 160/σ_Hlim·f_pb (≤ 12800/σ_Hlim for 5 < v ≤ 10,
    ≤ 6400/σ_Hlim above), 0.275f_pb (≤ 22, ≤ 11 µm), 0.075f_pb ≤ 3 µm; KISSsoft's helical
    pair prints y_α = 1.2 µm (``test_iso6336_kisssoft``)."""
    from geardesign.spur.strength.iso6336 import part1 as P1

    assert float(P1.running_in_alpha(f_pb, material, sigma_Hlim, v)) == pytest.approx(
        expected, rel=1e-12)
    assert P1.pair_mean(2.0, 3.0) == 2.5
    assert float(P1.running_in_beta(100.0, "Eh", 1500.0, 3.0)) == 6.0


def test_size_factor_for_bending_of_cast_iron_beyond_its_table():
    assert float(P3.y_x("GG", 40.0)) == 0.7
    assert float(P3.y_x("V", 60.0)) == 0.85


@pytest.mark.parametrize("material, sigma_Hlim, v, f, y_alpha, y_beta", [
    ("St", 600.0, 3.0, 100.0, 160.0 / 6.0, 320.0 / 6.0), ("St", 600.0, 5.0, 100.0, 160.0 / 6.0, 320.0 / 6.0),
    ("St", 600.0, 5.5, 100.0, 12800.0 / 600.0, 25600.0 / 600.0),
    ("St", 600.0, 10.0, 100.0, 12800.0 / 600.0, 25600.0 / 600.0),
    ("St", 600.0, 10.5, 100.0, 6400.0 / 600.0, 12800.0 / 600.0),
    ("GG", 300.0, 3.0, 100.0, 27.5, 55.0), ("GG", 300.0, 5.0, 100.0, 27.5, 55.0),
    ("GG", 300.0, 5.5, 100.0, 22.0, 45.0), ("GG", 300.0, 10.0, 100.0, 22.0, 45.0),
    ("GG", 300.0, 10.5, 100.0, 11.0, 22.0)])
def test_running_in_velocity_bands(material, sigma_Hlim, v, f, y_alpha, y_beta):
    """[ISO6336-1] eqs. (61)–(63), (75)–(77): no limit up to 5 m/s, the middle limit up to
    10 m/s inclusive, the low one above."""
    from geardesign.spur.strength.iso6336 import part1 as P1

    assert float(P1.running_in_alpha(f, material, sigma_Hlim, v)) == pytest.approx(y_alpha)
    assert float(P1.running_in_beta(f, material, sigma_Hlim, v)) == pytest.approx(y_beta)


def test_shaft_deflection_with_the_pinion_offset():
    """[ISO6336-1] eq. (57): f_sh = F_m/b·0.023·[|1 + K' l s/d1²·(d1/d_sh)⁴ − 0.3| + 0.3]
    (b/d1)²; K' = 0.48 and −0.48 (the two arrangements of the table), l = 300, s = 30,
    d1 = 100, d_sh = 80 mm; without s (or l, d_sh) the pinion sits midway."""
    from geardesign.spur.strength.iso6336 import part1 as P1

    term = 0.48 * 300.0 * 30.0 / 100.0 ** 2 * (100.0 / 80.0) ** 4
    base = 1500.0 * 0.023 * (80.0 / 100.0) ** 2
    f = P1.shaft_deflection(1500.0, 80.0, 100.0, 0.48, 300.0, 30.0, 80.0)
    assert f == pytest.approx(base * (abs(1.0 + term - 0.3) + 0.3), rel=1e-12)
    f_neg = P1.shaft_deflection(1500.0, 80.0, 100.0, -0.48, 300.0, 30.0, 80.0)
    assert f_neg == pytest.approx(base * (abs(1.0 - term - 0.3) + 0.3), rel=1e-12)
    assert P1.shaft_deflection(1500.0, 80.0, 100.0, 0.48, 300.0, d_shaft=80.0) == \
        pytest.approx(base, rel=1e-12)
    assert P1.shaft_deflection(1500.0, 80.0, 100.0, span=300.0, offset=30.0, d_shaft=80.0) == \
        pytest.approx(base, rel=1e-12)
    assert P1.shaft_deflection(1500.0, 80.0, 100.0, 0.48, offset=30.0) == pytest.approx(base)
    assert P1.shaft_deflection(1500.0, 80.0, 100.0, 0.48, d_shaft=80.0) == pytest.approx(base)
    # helix correction: B1 = 0.1 on the deflection part ([ISO6336-1] Table 9)
    assert float(P1.initial_misalignment(20.0, 10.0, "helix_correction", 100.0, 0.0)) == \
        pytest.approx(1.33 * 0.1 * 20.0 + 10.0)


def test_stiffness_and_mass_edges():
    from geardesign.spur.strength.iso6336 import part1 as P1

    assert float(P1.single_stiffness(17.0, 1.0, 1.0, 0.0, 300.0, E_ratio=0.5)) == pytest.approx(
        17.0 * 0.8 * 0.5)
    assert P1.reduced_mass(0.06, None, 3) == pytest.approx(0.02)
    # effective deviations below zero count as zero ([ISO6336-1] 6.5.9, 8.3.2)
    K, _ = P1.dynamic_factor(1.0, 0.85, 14.0, 0.5, 0.5, 10.0, 320.0, 2.3)
    assert float(K) == pytest.approx(1.3108361191860465, rel=1e-12)   # [Drivetrain]
    t = P1.transverse_load_factor(2.6, 18.0, 0.5, 400.0)
    assert float(t) == pytest.approx(0.9 + 0.4 * math.sqrt(3.2 / 2.6) * 18.0 * 0.5 / 400.0)
    assert [float(x) for x in P1.limited(1.2, 1.0)] == [1.0, 1.0]


@pytest.mark.parametrize("material, Rz, expected", [
    ("V", 1.0, 1.674 - 0.529 * 2.0 ** 0.1), ("V", 1.5, 1.674 - 0.529 * 2.5 ** 0.1),
    ("V", 50.0, 1.674 - 0.529 * 41.0 ** 0.1), ("St_cast", 1.0, 5.306 - 4.203 * 2.0 ** 0.01),
    ("St", 1.5, 5.306 - 4.203 * 2.5 ** 0.01), ("St", 50.0, 5.306 - 4.203 * 41.0 ** 0.01),
    ("NV", 1.0, 4.299 - 3.259 * 2.0 ** 0.0058), ("NT", 1.5, 4.299 - 3.259 * 2.5 ** 0.0058),
    ("GG", 50.0, 4.299 - 3.259 * 41.0 ** 0.0058), ("IF", 0.5, 1.12)])
def test_relative_surface_factor_edges(material, Rz, expected):
    """[ISO6336-3] Y_RrelT: the formula from R_z = 1 µm, R_z above 40 µm taken at 40."""
    assert P3.y_r_rel(material, Rz) == pytest.approx(expected, rel=1e-12)


def test_static_notch_sensitivity_groups_and_life_edges():
    assert P3.y_delta_rel_static("IF", 2.2, None) == pytest.approx(0.44 * 2.2 + 0.12)
    for m in ("NV", "NV_nitrocar"):
        assert P3.y_delta_rel_static(m, 2.2, None) == pytest.approx(1.24 / 1.2)
    assert float(P3.y_nt("Eh", 1e10, optimum=True)) == 1.0
    assert float(P3.y_x("St", 5.5)) == pytest.approx(0.997)


def test_type_from_treatment():
    """The ISO 6336-5 type of a GOST row: 38Kh2MYuA nitrided NT, steel 45 through-hardened
    V, otherwise by the treatment (carburized Eh, induction IF, normalized St, nitrided NV)."""
    cases = [("nitrided", "38Kh2MYuA, nitrided", "NT"), ("improved", "45, improved", "V"),
             ("through_hardened", "45, through", "V"), ("carburized", "45, x", "Eh"),
             ("nitrided", "40Kh, x", "NV"), ("induction", "45, x", "IF"),
             ("normalized", "45, x", "St"), ("carburized", "38Kh2MYuA, x", "Eh")]
    for treatment, label, expected in cases:
        assert P5.type_from_treatment(treatment, label) == expected
    assert P5.limits("St", "MQ", 110.0).clamped is False
    assert P5.limits("St", "MQ", 210.0).clamped is False


def test_miner_rule_edges():
    assert P6.cycles_to_failure(1000.0, _sigma_G) == pytest.approx(1.0, rel=1e-9)
    assert P6.cycles_to_failure(_sigma_G(2.0), _sigma_G) == pytest.approx(2.0, rel=1e-9)
    assert P6.damage([500.0, 400.0], [0.0, 1000.0], _sigma_G) == pytest.approx(1000.0 / 2.5 ** 10)
    S = P6.spectrum_safety([900.0], [1e6], _sigma_G)
    assert S == pytest.approx((1e6 * 0.9 ** 10) ** -0.1, rel=1e-9)
    assert P6.spectrum_safety([0.5], [1.0], _sigma_G) == pytest.approx(2000.0, rel=1e-6)
    assert P6.spectrum_safety([500.0], [1e-6], _sigma_G) == pytest.approx(2.0, rel=1e-9)
    S2 = P6.spectrum_safety([500.0, 100.0], [0.0, 1.5e7], _sigma_G)
    assert S2 == pytest.approx(10.0 * 1.5e7 ** -0.1, rel=1e-9)
    assert P6.spectrum_safety([500.0, 100.0], [0.0, 1.0], _sigma_G) == pytest.approx(
        2.0 * 1.000001, rel=1e-12)


def test_scuffing_factor_edges():
    a = [math.radians(x) for x in (21.0, 20.0, 20.6, 15.0)]
    expected = 1.22 * (math.sin(a[0]) * math.cos(a[1]) * math.cos(a[3])) ** 0.25 / \
        math.sqrt(math.cos(a[2]) * math.cos(a[0]))
    assert P21.angle_factor(*a) == pytest.approx(expected, rel=1e-12)
    assert P21.mean_friction(500.0, 10.0, 20.0, 50.0, 0.8, 1.2) == pytest.approx(
        0.045 * 2.5 ** 0.2 * 50.0 ** -0.05 * 0.96, rel=1e-12)
    th = P21.integral_scuffing_temperature(10, 100.0, 1.0, 0.8)
    assert th[0] == pytest.approx(th[1] + 1.5 * 0.8 * th[2])
    assert P21.approach_factor(3.0, 1.5) == pytest.approx(1.4 - 8 / 15)
    assert P21.approach_factor(3.5, 1.0) == 0.6
    names = {(0.5, 0.5): "1 ≤ ε_α < 2, ε_1 < 1, ε_2 < 1", (1.0, 0.5): "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1",
             (0.5, 1.0): "1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1", (1.0, 1.0): "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1",
             (1.5, 1.5): "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1 (nearest)",
             (1.5, 0.5): "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1 (nearest)",
             (0.5, 1.5): "1 ≤ ε_α < 2, ε_1 < 1, ε_2 ≥ 1 (nearest)",
             (1.2, 0.9): "1 ≤ ε_α < 2, ε_1 ≥ 1, ε_2 < 1 (nearest)",
             (1.0, 1.2): "2 ≤ ε_α < 3, ε_1 ≥ 1, ε_2 ≥ 1"}
    for (e1, e2), name in names.items():
        assert P21.contact_ratio_factor(e1, e2)[1] == name, (e1, e2)


def test_single_pair_factor_of_an_internal_pair():
    """[ISO6336-2] (Z_B, Z_D): for an internal pair z2, d_a2, d_b2 enter M1 with a negative
    sign; Z_D = 1 (the internal gear's contact is not at its inner point of single
    contact).  Pinion z1 = 17, d_a1 = 95, d_b1 = 79.9; ring z2 = 56, d_a2 = 268,
    d_b2 = 263.2; α_wt = 20°, ε_α = 1.6."""
    a = math.radians(20.0)
    s1 = math.sqrt((95.0 / 79.9) ** 2 - 1.0) - 2.0 * math.pi / 17
    s2 = math.sqrt((268.0 / 263.2) ** 2 - 1.0) - 0.6 * 2.0 * math.pi / -56
    M1 = math.tan(a) / math.sqrt(s1 * s2)
    Z_B, Z_D, m1, m2 = P2.single_pair_factors(a, (95.0, 268.0), (79.9, 263.2), (17, 56), 1.6,
                                              0.0, False, internal=True)
    assert float(m1) == pytest.approx(M1, rel=1e-12)
    assert float(Z_B) == pytest.approx(max(M1, 1.0), rel=1e-12)
    assert m2 == 1.0 and Z_D == 1.0
