"""Properties of the ISO 6336 factors that a wrong formula breaks: the work hardening
factor Z_W, the reduced mass of K_v (a sun shared by the planets, a rigid ring), the sum
of velocities at the pitch point of the scuffing rating, and the flag of a transverse load
factor's cap (GOST 21354 and ISO 6336 alike).  The published values are in
``tests/reference/planetary/test_kisssoft_nrel_iso6336.py`` and
``tests/reference/spur/test_iso6336_kisssoft.py``."""

from __future__ import annotations

import math

from hypothesis import assume, given, settings
from hypothesis import strategies as st

from geardesign.gears.geometry import BasicRack, PairInput, pair_geometry
from geardesign.spur.strength import gost21354 as G
from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336 import part2 as P2
from geardesign.spur.strength.iso6336 import part21 as P21
from geardesign.core.registry import run_data
from tests.conftest import flat

HB = st.floats(100.0, 500.0)
RZ = st.floats(0.5, 30.0)
RHO = st.floats(0.5, 500.0)
V = st.floats(0.1, 60.0)
NU = st.floats(10.0, 1500.0)


@settings(max_examples=300, deadline=None)
@given(HB, RZ, RZ, RZ, RHO, V, NU)
def test_z_w_does_not_grow_when_the_pinion_gets_rougher(hb, rz1, rz1b, rz2, rho, v, nu):
    """R_zH grows with the hardened gear's roughness (R_z1^1.66): Z_W does not grow."""
    lo, hi = sorted((rz1, rz1b))
    assert P2.z_w(hb, hi, rz2, rho, v, nu) <= P2.z_w(hb, lo, rz2, rho, v, nu) + 1e-15


@settings(max_examples=300, deadline=None)
@given(HB, RZ, RZ, RHO, RHO, V, NU)
def test_z_w_bounds_and_curvature(hb, rz1, rz2, rho_a, rho_b, v, nu):
    """1.2 − (HB − 130)/1700 times (3/R_zH)^0.15 with 3 ≤ R_zH ≤ 16 µm: between (3/16)^0.15
    of the 2006 value and the 2006 value; a more sharply curved contact (smaller ρ_red,
    a small gear) has the larger equivalent roughness, so Z_W does not grow as ρ_red falls."""
    base = P2.z_w(hb)
    z = P2.z_w(hb, rz1, rz2, rho_a, v, nu)
    assert base * (3.0 / 16.0) ** 0.15 - 1e-12 <= z <= base + 1e-12
    small, large = sorted((rho_a, rho_b))
    assert P2.z_w(hb, rz1, rz2, small, v, nu) <= P2.z_w(hb, rz1, rz2, large, v, nu) + 1e-15


MASS = st.floats(1e-4, 50.0)


@given(MASS, MASS, st.integers(1, 12))
def test_reduced_mass_of_a_shared_sun(m_s, m_p, n_p):
    """Pair formula for n = 1; m_P m_S/(n_P m_P + m_S) for a sun with n_P planets (in
    either rating order), never above the pair value; a rigid ring leaves the planet."""
    pair = P1.reduced_mass(m_s, m_p)
    assert math.isclose(pair, m_s * m_p / (m_s + m_p), rel_tol=1e-12)
    shared = m_p * m_s / (n_p * m_p + m_s)
    assert math.isclose(P1.reduced_mass(m_s, m_p, n_p, 1), shared, rel_tol=1e-12)
    assert math.isclose(P1.reduced_mass(m_p, m_s, 1, n_p), shared, rel_tol=1e-12)
    assert shared <= pair * (1 + 1e-12)
    assert P1.reduced_mass(m_p, None) == m_p


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 120), st.floats(-0.4, 0.8), st.floats(-0.4, 0.8),
       st.floats(0.0, 25.0), st.floats(10.0, 3000.0))
def test_sum_of_velocities_is_the_kinematic_sum_at_the_pitch_point(z1, z2, x1, x2, beta, n1):
    """v_ΣC = ω1 ρ_C1 + ω2 ρ_C2 with ρ_Ci = ½ d_bi tan α_wt, from the base circles (not
    from the operating pitch circle the function uses) on shifted pairs."""
    from geardesign.gears.geometry import GeometryError

    try:    # a pair that cannot mesh (inv α_tw <= 0) is refused by the geometry
        g = pair_geometry(PairInput(3.0, z1, z2, x1, x2, math.radians(beta), 30.0,
                                    BasicRack(math.radians(20.0))))
    except GeometryError:
        assume(False)
    w1 = math.pi * n1 / 30.0
    w2 = w1 * z1 / z2
    t = math.tan(g.alpha_tw)
    kinematic = (w1 * 0.5 * g.g1.d_b * t + w2 * 0.5 * g.g2.d_b * t) / 1000.0
    v_w = math.pi * g.g1.d_w * n1 / 60000.0
    assert math.isclose(P21.sum_velocity_pitch(v_w, g.alpha_tw), kinematic, rel_tol=1e-9)


K = st.floats(0.5, 3.0)


@given(K, K)
def test_cap_flag_only_when_the_cap_lowers_the_factor(k, k_max):
    """The flag says whether the cap set the factor (K = K_max < k); with K_max < 1 the floor
    sets K = 1, and the flag is off."""
    for limited in (G.limited, P1.limited):
        value, capped = limited(k, k_max)
        assert value == max(1.0, min(k, k_max))
        assert bool(capped) == (value == k_max < k)


def test_gost_report_wide_helical_pair_not_capped_at_the_floor():
    """A wide helical pair (ε_β > 0.95 ε_α²: K_Hα,max < 1): K_Hα = 1 is the floor's, and the
    report does not say the cap set it."""
    mat = {"grade": "40Kh", "treatment": "improved", "hardness_HB": 280.0}
    v = flat(run_data({"kind": "spur", "gear": {"module": 2.0, "z1": 30, "z2": 60,
                                                "helix_angle": 20.0, "face_width": 80.0,
                                                "x1": 0.0, "x2": 0.0, "bearing_scheme": 5},
                       "load": {"speed1": 1000.0, "torque1": 400.0, "life_hours": 10000.0},
                       "material": {"pinion": mat, "wheel": mat}}).document())
    assert v["eps_beta"] > 0.95 * v["eps_alpha"] ** 2 and v["K_Halpha_max"] < 1.0
    assert v["K_Halpha"] == 1.0
    assert v["K_Halpha_capped"] == "no"
