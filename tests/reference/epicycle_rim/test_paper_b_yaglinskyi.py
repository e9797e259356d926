"""Paper B: V. P. Yaglinskyi, S. S. Gutyria, A. M. Chanchin, V. M. Zheglova, "Influence of
parametric oscillations on the fatigue strength of a wheel-gearbox epicycle", Visnyk NTU
"KhPI", series "Problems of mechanical drive", 2017 ([Yaglinskyi2017]).

Raba 118.77: n_p = 3, z = 26/19/64, m = 3.25 mm, ε_α = 1.42, wheel radius R = 0.5 m, natural
frequencies of the ring k0 = 2233 … 3770 Hz.

Checked against the printed values:

* Table 1, excitation frequencies Ω = 2k0/√a for a = 1, 4, 16: exact to the printed unit.
* Eq. (8), the boundary series: the printed coefficients agree with the exact characteristic
  values to the order of the series.
* Eq. (3)-(4): Δφ = 2°15′ and 1°7′ for k = 0.4 and 0.2.

Misprints, with the value the tool gives:

* Table 1, a = 9 column: 1496, 1636, 1778, 2200, 2242, 2526 Hz are 0.5 % above 2k0/3
  (1488.7 … 2513.3 Hz), i.e. a ≈ 8.91 instead of 9.
* Table 1, k0 = 2442 Hz, a = 1: the source text reads "4844"; 2·2442 = 4884.
* Table 1, speeds V_T (26 … 43 km/h for a = 1): 30.6 times below the kinematics of the fixed
  ring, V = 3.6·2πR·Ω/(h·z_r); the formula (1) behind them is garbled in the source.  The
  tool gives 789 km/h for Ω = 4466 Hz with the paper's in-phase model (h = 1) and 263 km/h
  with the real sequential phasing (h = 3).
* Δφ3 printed −3°38′; k = −0.6 (Σk = 0) gives −3°22.5′.
* μ = 1/3 for equally spaced planets "in phase": the exact pair count gives 0.352, and the
  real phases of 64/3 (not an integer) make equally spaced planets sequentially phased,
  μ = 0.117 (the paper's "improved" value).  μ = 1/9 for the shifted planets: 0.117 by the
  paper's model, but 0.235 with the real phases of those angles, which also violate the
  assembly condition (multiples of 4°).
"""


import pytest

from geardesign.core.registry import run_data
from geardesign.epicycle_rim import mathieu as M
from geardesign.epicycle_rim import mesh
from geardesign.epicycle_rim import resonance as R
from tests.conftest import assert_ref, dms

K0 = [2233.0, 2442.0, 2654.0, 3284.0, 3346.0, 3770.0]
# Table 1 (L16779-16791): Ω for a = 1; 4; 9; 16 [Hz]
TABLE1 = {2233: (4466, 2233, 1496, 1116), 2442: (4884, 2442, 1636, 1221),
          2654: (5308, 2654, 1778, 1327), 3284: (6568, 3284, 2200, 1642),
          3346: (6692, 3346, 2242, 1673), 3770: (7540, 3770, 2526, 1885)}
SPEEDS_A1 = {2233: 26, 2442: 28, 2654: 31, 3284: 38, 3346: 38.5, 3770: 43}  # km/h, a = 1

SPEC = {
    "kind": "epicycle_rim",
    "ring": {"module": 3.25, "z": 64, "face_width": 60.0, "rim_thickness": 8.0,
             "tooth_height": 7.3},
    "planets": {"count": 3, "z_sun": 26, "z_planet": 19, "contact_ratio": 1.42},
    "vehicle": {"wheel_radius": 500.0, "speed_range": [5.0, 55.0]},
    "resonance": {"natural_frequencies": K0, "orders": [1, 2, 3, 4]},
}


def resonance(**over):
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in SPEC.items()}
    for table, values in over.items():
        data[table].update(values)
    return run_data(data).document()["results"]


@pytest.fixture(scope="module")
def res():
    return resonance()["resonance"]


@pytest.mark.parametrize("order, column", [(1, 0), (2, 1), (4, 3)], ids=["a=1", "a=4", "a=16"])
def test_table1_excitation_frequencies(res, order, column):
    # printed to 1 Hz (1116 for 1116.5): tolerance 0.5 Hz
    for k0, omega in zip(K0, res[f"Omega_n{order}"]):
        assert_ref(omega, TABLE1[int(k0)][column], 0.5, f"Ω, k0 = {k0}, a = {order ** 2}")
        assert omega == R.resonance_frequency(k0, order)


def test_table1_a9_column_misprint(res):
    """Printed 2k0/3 is 0.5 % high in every row (a ≈ 8.91); the tool gives 2k0/3."""
    for k0, omega in zip(K0, res["Omega_n3"]):
        printed = TABLE1[int(k0)][2]
        assert omega == pytest.approx(2 * k0 / 3, rel=1e-12)
        assert 0.004 < printed / omega - 1 < 0.0065
        assert 4 * k0 ** 2 / printed ** 2 == pytest.approx(8.91, abs=0.02)


def test_table1_4844_misprint():
    """The source reads 4844 Hz for k0 = 2442, a = 1: the tool gives 2·2442 = 4884."""
    assert R.resonance_frequency(2442.0, 1) == 4884.0


def test_table1_speed_misprint():
    """Printed V_T are 30.6x below the fixed-ring kinematics ([Yaglinskyi2017])."""
    for k0, v_printed in SPEEDS_A1.items():
        v_kin = R.speed_from_mesh_frequency(2 * k0, 64, 500.0)  # the paper's h = 1
        assert 30.0 < v_kin / v_printed < 31.3
    assert_ref(R.speed_from_mesh_frequency(4466.0, 64, 500.0), 789.2, 0.05, "V at 4466 Hz")
    # real phasing: the stiffness pulses at 3·f_m, so the principal resonance is at f_m = Ω/3
    r = resonance()["resonance"]
    assert r["h"] == 3
    assert_ref(r["V_n1"][0], 263.07, 0.01, "V, principal resonance, k0 = 2233 Hz")


def test_series_8_coefficients():
    """Eq. (8) against the exact characteristic values: the differences are O(b⁵)."""
    for b in (0.01, 0.02, 0.05):
        for n in (1, 2, 3):
            lo_s, hi_s = M.series_boundaries(n, b)
            lo_e, hi_e = M.boundaries(n, b)
            assert abs(lo_s - lo_e) < 2 * b ** 5 and abs(hi_s - hi_e) < 2 * b ** 5, (n, b)
        a0_s, _ = M.series_boundaries(0, b)
        assert abs(a0_s - M.characteristic_value("a", 0, b)) < 2 * b ** 5


def test_harmonic_balance_7():
    """a^П = 1 + b, a^Л = 1 − b (eq. (7)): the first-order terms of the exact boundaries."""
    b = 1e-4
    lo, hi = M.boundaries(1, b)
    assert lo == pytest.approx(1 - b, abs=2 * b * b) and hi == pytest.approx(1 + b, abs=2 * b * b)


def test_planet_shifts_eq3_eq4():
    """k = (0.4, 0.2, −0.6): Δφ = 2°15′, 1°7′ (printed) and −3°22.5′ (printed −3°38′)."""
    pitch = 360.0 / 64
    assert_ref(0.4 * pitch, dms(2, 15), 1e-9, "Δφ12")
    assert_ref(0.2 * pitch, dms(1, 7), 1 / 120, "Δφ23 (printed to 1′)")
    assert_ref(-0.6 * pitch, -dms(3, 22.5), 1e-9, "Δφ31")
    assert abs(-0.6 * pitch + dms(3, 38)) > 0.25  # the printed −3°38′ is a misprint
    angles = mesh.angles_from_shifts(3, [0.4, 0.2, -0.6], 64)
    assert angles == pytest.approx([0.0, 122.25, 243.375])


def test_pulsation_claims():
    """μ = c_a/c_m: printed 1/3 (uniform, in phase) and 1/9 (shifted); c_m = 4.5 c1 printed,
    exact mean n_p·ε_α = 4.26 c1."""
    uniform = [0.0, 120.0, 240.0]
    shifted = mesh.angles_from_shifts(3, [0.4, 0.2, -0.6], 64)
    p_in = mesh.pulsation(mesh.mesh_phases(uniform, 64, "paper"), 1.42)
    p_sh = mesh.pulsation(mesh.mesh_phases(shifted, 64, "paper"), 1.42)
    assert p_in.mean == pytest.approx(4.26) and p_sh.mean == pytest.approx(4.26)
    assert_ref(p_in.mu, 1 / 3, 0.02, "μ uniform (paper model): 0.352, printed 1/3")
    assert_ref(p_sh.mu, 1 / 9, 0.007, "μ shifted (paper model): 0.117, printed 1/9")
    # the real phases of the tooth count
    p_real_uniform = mesh.pulsation(mesh.mesh_phases(uniform, 64, "actual"), 1.42)
    p_real_shifted = mesh.pulsation(mesh.mesh_phases(shifted, 64, "actual"), 1.42)
    assert p_real_uniform.mu == pytest.approx(p_sh.mu)  # equal spacing is already as good
    assert p_real_uniform.h_dominant == 3
    assert_ref(p_real_shifted.mu, 0.2347, 0.0001, "μ of the paper's angles, real phases")
    assert [mesh.assembly_index(a, 26, 64) for a in shifted] == pytest.approx(
        [0.0, 30.5625, 60.84375])


def test_paper_model_reproduced_by_the_calculator():
    r = resonance(planets={"shifts": [0.4, 0.2, -0.6]},
                  resonance={"phase_model": "paper", "depth": "half_range"})
    assert_ref(r["resonance"]["mu_used"], 1 / 9, 0.007, "μ, paper's spacing and model")
    assert r["resonance"]["phases"] == pytest.approx([0.0, 0.4, 0.6])
