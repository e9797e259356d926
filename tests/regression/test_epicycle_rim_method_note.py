"""Regression values: our recomputations of [Gutyria2017] and [Yaglinskyi2017], not published
numbers. They guard against
unintended changes; the published values are in ``tests/reference/epicycle_rim``."""

import math

import pytest

from geardesign.epicycle_rim import endurance as E
from geardesign.epicycle_rim import mathieu as M
from geardesign.epicycle_rim import stress as ST
from geardesign.fatigue import gost25504 as g25
from geardesign.fatigue import probability as FP


def test_alternative_mean_stress_models_on_the_printed_pair():
    """[Gutyria2017]: on (σ_a, σ_m) = (80.28, 26.78): Goodman 83.39, Gerber 80.39,
    Serensen-Kinasoshvili 81.64 (ψ_σD = ψ_σ/3.228 = 0.0506), cubic 81.33 MPa."""
    psi_D = g25.mean_stress_sensitivity(717.0)[0] / 3.228
    assert psi_D == pytest.approx(0.0506, abs=5e-5)
    got = {m: ST.equivalent_amplitude(80.28, 26.78, 717.0, m, psi_D)
           for m in ST.MEAN_STRESS_MODELS}
    assert got == pytest.approx({"cubic": 81.33, "goodman": 83.39, "gerber": 80.39,
                                 "kinasoshvili": 81.64}, abs=0.006)


def test_outside_the_diagram_is_nan():
    assert math.isnan(ST.equivalent_amplitude(400.0, 400.0, 717.0))


def test_improved_fillet_intermediates():
    """[Gutyria2017]: G = 5.996 mm⁻¹ (t = 0.635 mm held), θ = 0.2265, K_σ/K_dσ = 2.299, K = 2.846."""
    pe = E.part_endurance(sigma_u=717.0, sigma_m1=314.0, d0=7.5, blank_size=34.0,
                          root_chord=9.0, fillet_radius=0.46, radius_tol=0.06,
                          rim_thickness=8.0, perimeter=120.0, Rz=25.0, K_V=1.0,
                          v_material=0.06, alpha=2.5, depth=0.635)
    assert pe.gradient == pytest.approx(5.996, abs=5e-4)
    assert pe.theta == pytest.approx(0.2265, abs=5e-5)
    assert pe.k_ratio == pytest.approx(2.299, abs=5e-4)
    assert pe.K == pytest.approx(2.846, abs=0.002)


def test_life_of_the_consistent_governing_case():
    """Appendix R output: σ_-1eq = 87.31 MPa → n = 0.969, P = 37.5 %, lg N_P = 6.242 /
    6.165 / 6.053 / 5.999 at P = 50 / 70 / 90 / 95 %."""
    s1D, v, K = 84.6042, 0.10, 3.2242
    m = FP.sn_slope(717.0, K)
    assert m == pytest.approx(4.3306, abs=1e-4)
    lg = [FP.lg_life(87.31, s1D, v, P, m, 2e6, -0.8, -2.3) for P in (0.5, 0.7, 0.9, 0.95)]
    assert lg == pytest.approx([6.242, 6.165, 6.053, 5.999], abs=6e-4)
    assert 100 * FP.probability_of_non_failure(87.31, s1D, v) == pytest.approx(37.5, abs=0.05)
    assert 100 * FP.probability_of_non_failure(79.0, 84.5, v) == pytest.approx(74.2, abs=0.05)


def test_mathieu_bands_of_the_note():
    """[Yaglinskyi2017]: along b = μa/2, μ = 1/3: region 1 a = 0.855 … 1.194 (Ω/k0 = 1.830 … 2.163),
    region 2 a = 3.964 … 4.190 (series); μ = 1/9: 0.947 … 1.058 and 3.996 … 4.021; the
    linear boundaries 1/(1 ± μ/2).  The exact characteristic values and the series agree to
    1e-6 in region 1 (the hand calculation's RK4 check, 0.857 … 1.193, was 0.002 off)."""
    b3 = M.band_series(1, 1 / 3)
    assert [b3.a_lo, b3.a_hi] == pytest.approx([0.8550, 1.1939], abs=5e-5)
    assert [b3.ratio_lo, b3.ratio_hi] == pytest.approx([1.8304, 2.1629], abs=5e-5)
    e3 = M.band_exact(1, 1 / 3)
    assert [e3.a_lo, e3.a_hi] == pytest.approx([b3.a_lo, b3.a_hi], abs=1e-6)
    assert [M.band_series(2, 1 / 3).a_lo, M.band_series(2, 1 / 3).a_hi] == pytest.approx(
        [3.9637, 4.1901], abs=5e-5)
    b9 = M.band_series(1, 1 / 9)
    assert [b9.a_lo, b9.a_hi] == pytest.approx([0.9470, 1.0584], abs=5e-5)
    assert [M.band_series(2, 1 / 9).a_lo, M.band_series(2, 1 / 9).a_hi] == pytest.approx(
        [3.9959, 4.0207], abs=5e-5)
    lin = M.band_linear(1 / 3)
    assert [lin.a_lo, lin.a_hi] == pytest.approx([0.857, 1.2], abs=5e-4)


def test_meissner_rectangular_wave():
    """[Yaglinskyi2017], rectangular wave with equal halves k0²(1 ± μ): Ω/k0 ∈ 1.78 … 2.21 (μ = 1/3)
    and 1.93 … 2.07 (μ = 1/9)."""
    for mu, expected in ((1 / 3, (1.78, 2.21)), (1 / 9, (1.93, 2.07))):
        lo, hi = M.stepwise_band([(0.5, 1 + mu), (0.5, 1 - mu)], 2.0, 0.3)
        assert (lo, hi) == pytest.approx(expected, abs=0.006)


def test_thin_ring_bending_parts_of_the_note():
    """[Roark]: about −155 / +82 MPa for the Raba ring: these are the bending terms 6M/(bδ²);
    the hoop forces add +2.8 / +5.6 MPa (−152.3 / +87.7 MPa in all)."""
    h = ST.thin_ring_hoop_stress(4023.0, 3.25, 64, 3, 60.0, 8.0, math.radians(20.0))
    W = 60.0 * 64.0 / 6.0
    assert h.F_r == pytest.approx(4693, abs=1)
    assert h.R_m == pytest.approx(112.06, abs=0.01)
    assert -h.M_load / W == pytest.approx(-155.1, abs=0.1)
    assert h.M_between / W == pytest.approx(82.1, abs=0.1)
    assert (h.hoop_loaded, h.hoop_between) == pytest.approx((-152.32, 87.73), abs=0.01)


def test_stepwise_stiffness_through_the_calculator():
    """resonance.stiffness_model = "stepwise": the Floquet transfer matrix of the exact pair
    count of the Raba train (sequential phasing, h = 3) gives the principal band close to
    the sinusoidal Mathieu band with μ_3 (f_m/k0 = 0.6483 … 0.6849 against 0.6484 … 0.6847);
    near f_m/k0 = 1/3 the 6th harmonic (μ_6 = 0.075) widens the band of order 2."""
    from geardesign.core.registry import run_data

    spec = {"kind": "epicycle_rim",
            "ring": {"module": 3.25, "z": 64, "face_width": 60.0, "rim_thickness": 8.0},
            "planets": {"count": 3, "contact_ratio": 1.42},
            "resonance": {"natural_frequencies": [2233.0], "orders": [1, 2],
                          "stiffness_model": "stepwise"}}
    r = run_data(spec).document()["results"]["resonance"]
    assert r["mesh_ratio_stepwise_n1"] == pytest.approx([0.64828, 0.68495], abs=5e-5)
    sinus = [x / 3 for x in r["Omega_ratio_n1"]]
    assert sinus == pytest.approx([0.64839, 0.68470], abs=5e-5)
    lo, hi = r["mesh_ratio_stepwise_n2"]
    assert lo < 1 / 3 < hi and hi - lo > 0.01
