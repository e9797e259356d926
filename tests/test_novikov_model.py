"""Properties of the Novikov model: the cyclogram closed forms against Korotkin's phase
counting, the load-sharing solution of system (2), and the error model."""

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.novikov.geometry import (
    coverage,
    min_face_width,
    phase_points,
    table1_points,
)
from geardesign.novikov.sharing import share_load
from geardesign.novikov.factors import k_w
from tests.conftest import flat

EXAMPLE = {
    "kind": "novikov",
    "gear": {"module": 10.0, "z1": 12, "z2": 71, "helix_angle": 22.747, "face_width": 190.0},
    "material": {"pinion": {"hardness": 302.0}, "wheel": {"hardness": 269.0}},
    "accuracy": {"grade_smoothness": 10, "grade_contact": 9, "risk": 2.17,
                 "misalignment": 0.003},
    "load": {"torque2": 69500.0},
}


def novikov(**tables) -> dict:
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in EXAMPLE.items()}
    for key, value in tables.items():
        data[key] = {**data.get(key, {}), **value}
    return flat(run_data(data).document())


@settings(max_examples=30, deadline=None)
@given(st.floats(0.3, 5.5), st.floats(0.02, 0.98))
def test_closed_form_counts_match_phase_counting(eps_beta, eps_q):
    frac = eps_beta - math.floor(eps_beta)
    delta = min(eps_q, 1 - eps_q)
    for edge in (0.0, 1.0, delta, 1.0 - delta):    # avoid boundaries the sampling misses
        assume(abs(frac - edge) > 5e-3)
    cov = coverage(eps_beta, delta)
    counts = [len(r) for r in phase_points(table1_points(eps_beta, eps_q), eps_beta, 600)]
    assert (min(counts), max(counts)) == (cov.n_min, cov.n_max)
    share = sum(c == cov.n_max for c in counts) / len(counts)
    assert abs(share - cov.fraction_max) < 5e-3


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 8), st.floats(0.02, 0.98))
def test_least_face_width_gives_the_number_of_points(n, eps_q):
    delta = min(eps_q, 1 - eps_q)
    w = min_face_width(n, 1.0, delta)
    assert coverage(w + 1e-6, delta).n_min >= n
    assert coverage(w - 1e-3, delta).n_min < n


def test_sharing_balances_the_load_and_is_inverse_to_the_compliance():
    t = [0.5, 0.3, 0.05, 0.2, 0.45]
    sh = share_load(180000.0, t, [0.0] * 5, 700.0, 0.034, 190.0)
    assert abs(sum(sh.F) - 180000.0) < 1e-6 * 180000
    assert sh.active == 5
    # no gaps: F_i·K_W,i is the same for every point (system (2) with linear W_base)
    prod = [f * k_w(ti, ps) for f, ti, ps in zip(sh.F, t, sh.psi)]
    assert max(prod) - min(prod) < 1e-6 * max(prod)


def test_a_large_gap_lifts_a_point_off():
    sh = share_load(10000.0, [0.1, 0.2, 0.3], [0.0, 0.0, 500.0], 700.0, 0.034, 190.0)
    assert sh.F[2] == 0.0 and sh.active == 2
    assert abs(sum(sh.F) - 10000.0) < 1e-6


def test_a_leading_tooth_takes_more_load():
    base = share_load(1e5, [0.1, 0.2, 0.3], [0.0, 0.0, 0.0], 700.0, 0.034, 190.0)
    lead = share_load(1e5, [0.1, 0.2, 0.3], [-30.0, 0.0, 0.0], 700.0, 0.034, 190.0)
    assert lead.F[0] > base.F[0] and lead.F[1] < base.F[1]


def test_explicit_zero_deviations_equal_model_none():
    a = novikov(accuracy={"error_model": "explicit", "pitch_errors": [0.0] * 4,
                          "lead_error": 0.0})
    b = novikov(accuracy={"error_model": "none"})
    for key in ("sigma_F_max", "sigma_H_max", "sigma_F_phase", "sigma_H_phase"):
        assert a[key] == b[key]


def test_no_errors_no_misalignment_is_the_ideal_pair():
    v = novikov(accuracy={"error_model": "none", "misalignment": 0.0})
    assert v["sigma_F_max"] == pytest.approx(v["sigma_F_max_ideal"], rel=1e-12)
    assert v["share_H_deviations"] == pytest.approx(0.0, abs=1e-12)


def test_finer_grades_lower_the_stresses():
    coarse = novikov(accuracy={"grade_smoothness": 10, "grade_contact": 9})
    fine = novikov(accuracy={"grade_smoothness": 6, "grade_contact": 6})
    assert fine["sigma_H_max"] < coarse["sigma_H_max"]
    assert fine["sigma_F_max"] < coarse["sigma_F_max"]
    assert fine["sigma_F_max"] > fine["sigma_F_max_ideal"]


@pytest.mark.parametrize("c_p", [500.0, 1000.0, 2000.0])
def test_printed_critical_positions_are_robust_to_the_stiffness(c_p):
    """The printed critical points (phase 10 / 9, tooth 1, j = 2) come out for any point
    stiffness from 500 to 2000 N/µm; the default (735 N/µm) lies inside."""
    v = novikov(analysis={"point_stiffness": c_p})
    assert (v["sigma_F_phase"], v["sigma_F_zub"], v["sigma_F_j"]) == (10, 1, 2)
    assert (v["sigma_H_phase"], v["sigma_H_zub"], v["sigma_H_j"]) == (9, 1, 2)


def test_stiffer_teeth_feel_the_deviations_more():
    soft = novikov(analysis={"point_stiffness": 300.0})
    stiff = novikov(analysis={"point_stiffness": 1500.0})
    assert stiff["sigma_H_max"] > soft["sigma_H_max"]
    assert soft["sigma_H_max_ideal"] == stiff["sigma_H_max_ideal"]


def test_end_relief_unloads_the_face_ends():
    plain = novikov(accuracy={"error_model": "none", "misalignment": 0.0})
    crowned = novikov(accuracy={"error_model": "none", "misalignment": 0.0,
                                "end_relief": 0.05})
    assert crowned["sigma_H_max"] < plain["sigma_H_max"]


def test_application_factor_scales_the_load():
    v = novikov(load={"application_factor": 1.5})
    assert v["F_t_design"] == pytest.approx(1.5 * v["F_t"])


def test_life_factors():
    v = novikov(load={"speed1": 100.0, "life": 1000.0})
    assert v["N_K1"] == pytest.approx(6.0e6)
    assert v["N_K2"] == pytest.approx(6.0e6 * 12 / 71)
    assert v["Z_N2"] == pytest.approx((v["N_HG2"] / v["N_K2"]) ** (1 / 6))
    assert v["Y_N1"] == 1.0                      # N_K1 > N_FG = 4·10⁶
    assert v["Y_N2"] == pytest.approx((4e6 / v["N_K2"]) ** (1 / 6))


def test_reversing_load():
    v = novikov(load={"reversing": True})
    assert v["Y_A"] == pytest.approx(0.65)
    assert v["sigma_FP1"] == pytest.approx(1.75 * 302 * 0.65 / 1.7)


def test_custom_rack_equal_to_the_standard_gives_the_same_result():
    rack = {"name": "custom", "profile_angle": 27.0, "lk_star": 0.859, "eps_q": 0.64372,
            "addendum_coef": 0.9, "dedendum_coef": 1.05}
    a, b = novikov(rack=rack), novikov()
    assert a["sigma_H_max"] == b["sigma_H_max"]


def test_explicit_model_assumes_no_lead_error():
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in EXAMPLE.items()}
    data["accuracy"] = {"error_model": "explicit", "pitch_errors": [0.0, 0.0, 20.0, 0.0]}
    doc = run_data(data).document()
    assert "accuracy.lead_error" in doc["assumed"]
    assert doc["results"]["deviations"]["lead_error"] == 0.0
