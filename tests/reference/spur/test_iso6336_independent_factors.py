"""ISO 6336 factors at stated inputs against two independent public implementations.

* [Drivetrain]: G. F. de Souza Rebouças, GitHub ``gfsReboucas/Drivetrain`` at commit
  4a88df348fc70d04254c84bd375bb2bab0d15d0d, file ``MATISO_6336.m``: the getters
  ``Z_L``, ``Z_v``, ``Z_R``, ``Z_NT``, ``K_Falpha``, ``K_Hbeta``, ``K_Fbeta``, ``Z_BD``,
  ``Z_H``, evaluated at the inputs below in double precision.
* [DIN3990py]: GitHub ``hanslhansl/din3990`` at commit
  22b8478bae2b660e418d6891ecb5d466d77de63a, ``tests/test_1.py``: its printed output for
  the pair z = 19/104, m_n = 4, x = 0.5/0.15, α_wt = 21.5319°, d_a = 88/425.2 mm:
  M_1 = 1.00554704549864, M_2 = 0.8835590102280203, Z_B = 1.00554704549864, Z_D = 1.0,
  Z_H = 2.3959406670899934 (DIN 3990-2 = ISO 6336-2 method B for these factors).

Tolerance 1e-12 relative unless stated; the branches of every factor are covered (C_ZL,
C_ZR below 850, between, above 1200 MPa; the four Z_NT curves before the static point,
between the points, beyond 10¹⁰; ε_γ ≤ 2 and > 2; K_Hβ ≤ 2 and > 2; b/h below 3).
"""

import math

import pytest

from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336 import part2 as P2

Z_L = [(700.0, 100.0, 0.9354002108004216), (700.0, 320.0, 1.0895071629820665),
       (850.0, 100.0, 0.9353947822467074), (1000.0, 100.0, 0.9484233111609081),
       (1000.0, 320.0, 1.0714628197892953), (1200.0, 100.0, 0.9658001116002232),
       (1500.0, 320.0, 1.0473861451081528)]
Z_V = [(700.0, 2.0, 0.92319250547114), (700.0, 25.0, 1.058012573584461),
       (1000.0, 2.0, 0.9407411892211148), (1000.0, 25.0, 1.0447580817721636),
       (1500.0, 2.0, 0.9641565025531986), (1500.0, 25.0, 1.0270725343394151)]


@pytest.mark.parametrize("sigma_Hlim, nu40, expected", Z_L)
def test_lubricant_factor(sigma_Hlim, nu40, expected):
    # Drivetrain writes C_ZL = σ/4375 + 0.6357, the same line as 0.08(σ − 850)/350 + 0.83
    # to 5·10⁻⁵
    assert P2.z_l(sigma_Hlim, nu40) == pytest.approx(expected, abs=6e-5)


@pytest.mark.parametrize("sigma_Hlim, v, expected", Z_V)
def test_velocity_factor(sigma_Hlim, v, expected):
    assert float(P2.z_v(sigma_Hlim, v)) == pytest.approx(expected, abs=6e-5)


GEAR = {"d_b": (71.41663917972905, 390.9121302469379), "d_a": (88.0, 425.2), "z": (19, 104),
        "alpha_wt": math.radians(21.531902292465457), "eps_alpha": 1.5363235945832296}


@pytest.mark.parametrize("sigma_Hlim, expected", [(700.0, 0.9661829821815024),
                                                  (1000.0, 0.9728536374316795),
                                                  (1500.0, 0.981819540573381)])
def test_roughness_factor(sigma_Hlim, expected):
    """R_z = 4 µm on both gears of the [DIN3990py] pair; ρ_red = 11.9125 mm."""
    rho = P2.rho_red(*GEAR["d_b"], GEAR["alpha_wt"])
    assert float(rho) == pytest.approx(11.912526662298541, rel=1e-12)
    assert float(P2.z_r(sigma_Hlim, 4.0, 4.0, rho)) == pytest.approx(expected, rel=1e-12)


def test_relative_curvature_of_an_internal_pair():
    """ρ_red = ρ1ρ2/(ρ2 − ρ1) for an internal pair ([ISO6336-2], Z_R)."""
    r1, r2 = (0.5 * d * math.tan(0.4) for d in (60.0, 180.0))
    assert float(P2.rho_red(60.0, 180.0, 0.4, internal=True)) == pytest.approx(
        r1 * r2 / (r2 - r1), rel=1e-12)


Z_NT = {  # material: [(N_L, Z_NT)], Drivetrain rows 2 (St…IF), 3 (nitrided), 4 (NV nitrocar.)
    "St": [(1e4, 1.6), (1e5, 1.6), (6e5, 1.3972345072002734), (1e7, 1.1294377353395042),
           (2e8, 0.958368653207998), (3e9, 0.8819775786580923), (1e10, 0.85), (1e11, 0.85)],
    "NT": [(1e4, 1.3), (6e5, 1.1112029277861797), (1e7, 0.9697566338180248),
           (3e9, 0.8697533703004233), (1e11, 0.85)],
    "NV_nitrocar": [(1e4, 1.1), (6e5, 1.039047865210566), (3e6, 0.9922930595699065),
                    (1e11, 0.85)],
}


@pytest.mark.parametrize("material, N_L, expected",
                         [(m, n, z) for m, pts in Z_NT.items() for n, z in pts])
def test_contact_life_factor(material, N_L, expected):
    assert float(P2.z_nt(material, N_L)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("N_L, expected", [
    (1e5, 1.6), (3e6, 1.4208021247500424), (1e7, 1.3), (2e8, 1.0960276053110507),
    (1e9, 1.0), (3e9, 0.9253888646839725), (1e11, 0.85)])
def test_contact_life_factor_with_limited_pitting(N_L, expected):
    """Drivetrain row 1 (limited pitting permitted: 6·10⁵, 10⁷, 10⁹)."""
    assert float(P2.z_nt("Eh", N_L, limited_pitting=True)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("eps_gamma, expected", [(1.6, 0.8496000000000001), (2.0, 1.062),
                                                 (2.6, 1.0797228635769742)])
def test_transverse_load_factor(eps_gamma, expected):
    """``K_Falpha`` before its limits: c_γα = 18, f_pb − y_α = 9 µm, F_tH/b = 400 N/mm."""
    assert float(P1.transverse_load_factor(eps_gamma, 18.0, 9.0, 400.0)) == pytest.approx(
        expected, rel=1e-12)


def test_transverse_load_factor_limits():
    """``K_Halpha``/``K_Falpha``: capped at ε_γ/(ε_α Z_ε²) and ε_γ/(0.25ε_α + 0.75),
    floored at 1."""
    assert float(P1.transverse_limit_contact(2.6, 1.5, 0.8)) == pytest.approx(2.6 / (1.5 * 0.64))
    assert float(P1.transverse_limit_bending(2.6, 1.5)) == pytest.approx(2.6 / 1.125)
    assert [float(v) for v in P1.limited(1.3, 1.2)] == [1.2, 1.0]
    assert [float(v) for v in P1.limited(0.85, 1.2)] == [1.0, 0.0]
    assert [float(v) for v in P1.limited(1.3, 0.9)] == [1.0, 0.0]


@pytest.mark.parametrize("F_beta_y, c_gamma_beta, F_m_b, expected", [
    (20.0, 15.0, 500.0, 1.3), (40.0, 15.0, 200.0, 2.449489742783178), (30.0, 15.0, 225.0, 2.0)])
def test_face_load_factor(F_beta_y, c_gamma_beta, F_m_b, expected):
    assert float(P1.face_load_factor(F_beta_y, c_gamma_beta, F_m_b)) == pytest.approx(
        expected, rel=1e-12)


@pytest.mark.parametrize("K_Hbeta, b_h, expected", [
    (1.3, 10.0, 1.266635537650243), (1.3, 2.0, 1.1991785712924135),
    (1.8, 6.0, 1.6357484441919237)])
def test_face_load_factor_for_bending(K_Hbeta, b_h, expected):
    assert float(P1.face_load_factor_bending(K_Hbeta, b_h)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("eps_beta, helical, expected", [
    (0.0, False, 1.00554704549864), (0.4, True, 1.003328227299184), (1.2, True, 1.0)])
def test_single_pair_contact_factors(eps_beta, helical, expected):
    """M_1, M_2, Z_B, Z_D of the [DIN3990py] pair (printed for the spur case) and
    ``Z_BD`` of [Drivetrain] for a helical ε_β = 0.4 and 1.2."""
    Z_B, Z_D, M1, M2 = P2.single_pair_factors(GEAR["alpha_wt"], GEAR["d_a"], GEAR["d_b"],
                                              GEAR["z"], GEAR["eps_alpha"], eps_beta, helical)
    assert float(M1) == pytest.approx(1.00554704549864, rel=1e-12)
    assert float(M2) == pytest.approx(0.8835590102280203, rel=1e-12)
    assert float(Z_B) == pytest.approx(expected, rel=1e-12)
    assert float(Z_D) == 1.0


def test_zone_factor():
    """Z_H = 2.3959406670899934 printed by [DIN3990py] (β = 0, α_t = 20°)."""
    assert float(P2.z_h(0.0, math.radians(20.0), GEAR["alpha_wt"])) == pytest.approx(
        2.3959406670899934, rel=1e-12)


# --------------------------------------------------------------------------------------
# ISO 6336-3 method B root geometry of the [DIN3990py] pair (h_fP = 1.25m, ρ_fP = 0.25m,
# s_pr = 0): printed s_Fn, ρ_F, ϑ [°] and q_s; the program stops its ϑ iteration earlier
# (relative tolerance 10⁻⁴)

ROOT = [  # z, x, d, d_a, s_Fn, ρ_F, ϑ°, q_s
    (19, 0.5, 76.0, 88.0, 8.748743355951145, 1.3161477577049423, 48.10260415904784,
     3.32361746799878),
    (104, 0.15, 416.0, 425.2, 9.239504610725831, 1.325999192893118, 56.99835389167487,
     3.48397821817927),
]


@pytest.mark.parametrize("z, x, d, d_a, s_Fn, rho_F, theta, q_s", ROOT)
def test_root_chord_and_fillet_of_din3990(z, x, d, d_a, s_Fn, rho_F, theta, q_s):
    from geardesign.spur.strength.iso6336 import part3 as P3

    t = P3.tooth_form(z, x, 4.0, math.radians(20.0), 0.0, 0.0, d, d_a, GEAR["eps_alpha"],
                      5.0, 1.0)
    assert float(t.s_Fn) == pytest.approx(s_Fn, rel=1e-4)
    assert float(t.rho_F) == pytest.approx(rho_F, rel=1e-4)
    assert math.degrees(float(t.theta)) == pytest.approx(theta, rel=1e-4)
    assert float(t.q_s) == pytest.approx(q_s, rel=1e-4)
    assert float(t.z_n) == z


# --------------------------------------------------------------------------------------
# ISO 6336-1 stiffness, masses and misalignment: [Drivetrain] ``ISO_6336.m``
# (``dynamic_factor``: m_red, n_E1) and ``MATISO_6336.m`` (``C_ay``, ``K_Hbeta``: f_sh,
# F_βx, y_β); ISO/TR 6336-30 example 1 as transcribed there (c'_th 17.85584, c' 12.37047,
# c_γα 17.46485, c_γβ 14.84512 at ε_α = 1.5491); KISSsoft NREL stage 1 (C_R = 0.862 at
# b_s/b = 0.25 and s_R/m_n = 3.4875, C_B = 0.975 for h_fP = 1.25m_n)

def test_stiffness_chain_of_tr30():
    c_th = P1.theoretical_single_stiffness(18.905, 114.543, 0.145, 0.0)
    assert c_th == pytest.approx(17.85584, abs=6e-4)
    C_B = P1.basic_rack_factor(1.4, 1.4, math.radians(20.0))
    assert C_B == pytest.approx(0.9, rel=1e-12)
    c = float(P1.single_stiffness(17.85584, 1.0, C_B, math.radians(15.8), 1273.5))
    assert c == pytest.approx(12.37047, abs=6e-5)
    c_ga = P1.mesh_stiffness_alpha(12.37047, 1.5491)
    assert c_ga == pytest.approx(17.46485, abs=5e-4)   # ε_α printed to 4 decimals
    assert P1.mesh_stiffness_beta(17.46485) == pytest.approx(14.84512, abs=6e-6)
    # below 100 N/mm the single stiffness falls with (K_A F_t/b / 100)^0.25
    assert float(P1.single_stiffness(17.85584, 1.0, C_B, math.radians(15.8), 50.0)) == \
        pytest.approx(c * 0.5 ** 0.25, rel=1e-12)
    # an internal gear (z_n2 = ∞) loses the C_3/z_n2 and C_7 x2/z_n2 terms
    q = (0.04723 + 0.15551 / 19.0 - 0.00635 * 0.2 - 0.11654 * 0.2 / 19.0 - 0.00193 * -0.3
         + 0.00529 * 0.04 + 0.00182 * 0.09)
    assert P1.theoretical_single_stiffness(19.0, None, 0.2, -0.3) == pytest.approx(1.0 / q,
                                                                                  rel=1e-12)


def test_basic_rack_and_blank_factors():
    assert P1.basic_rack_factor(1.25, 1.25, math.radians(20.0)) == pytest.approx(0.975, rel=1e-12)
    assert P1.basic_rack_factor(1.25, 1.4, math.radians(25.0)) == pytest.approx(
        0.5 * (0.975 + 0.9) * 1.1, rel=1e-12)
    assert abs(float(P1.blank_factor(0.25, 3.4875)) - 0.862) <= 5e-4
    assert P1.blank_factor(None, None) == 1.0
    assert float(P1.blank_factor(0.1, 5.0)) == pytest.approx(float(P1.blank_factor(0.2, 5.0)))
    assert float(P1.blank_factor(1.5, 5.0)) == pytest.approx(1.0 + math.log(1.2) / (5.0 * math.e))
    assert float(P1.blank_factor(0.5, 0.5)) == pytest.approx(1.0 + math.log(0.5) / (5.0 * math.exp(0.2)))
    assert float(P1.blank_factor(0.5, None)) == pytest.approx(float(P1.blank_factor(0.5, 1.0)))


def test_masses_and_resonance_speed():
    m_S = P1.gear_mass(105.0, 95.0, 94.0, 0.0)
    assert m_S == pytest.approx(0.03479893401653474, rel=1e-12)
    m_P = P1.gear_mass(85.0, 75.0, 75.0, 0.0)
    assert P1.reduced_mass(m_P, m_S, 1, 3) == pytest.approx(0.0076410642745451, rel=1e-12)
    # a pair scaled by u (d_m2 = u d_m1, d_b2 = u d_b1): π ρ u² d_m1⁴/(8(u² + 1) d_b1²)
    m_W = P1.gear_mass(2.5 * 105.0, 2.5 * 95.0, 2.5 * 94.0, 0.0)
    assert P1.reduced_mass(m_S, m_W) == pytest.approx(0.029999081048736848, rel=1e-12)
    assert P1.reduced_mass(m_P, None, 1) == m_P
    # a bore d_i takes (1 − (d_i/d_m)⁴) of the solid mass
    assert P1.gear_mass(105.0, 95.0, 94.0, 50.0) == pytest.approx(m_S * (1.0 - 0.5 ** 4))
    assert float(P1.resonance_speed(17, 17.46485, 0.0348)) == pytest.approx(12583.9002962239,
                                                                            rel=1e-12)


@pytest.mark.parametrize("sigma_Hlim, expected", [(1000.0, 5.181741609688122),
                                                  (1500.0, 1.9953715857158036)])
def test_tip_relief_from_running_in(sigma_Hlim, expected):
    assert P1.tip_relief_running_in(sigma_Hlim) == pytest.approx(expected, rel=1e-12)


def test_misalignment_chain():
    """F_m = 150 kN, b = 100, d1 = 140 mm, f_ma = 10 µm, no helix modification."""
    f_sh = P1.shaft_deflection(1500.0, 100.0, 140.0)
    assert f_sh == pytest.approx(17.602040816326532, rel=1e-12)
    F_bx = float(P1.initial_misalignment(f_sh, 10.0, "none", 1500.0, 0.0))
    assert F_bx == pytest.approx(33.41071428571429, rel=1e-12)
    y_b = float(P1.running_in_beta(F_bx, "Eh", 1500.0, 3.0))
    assert F_bx - y_b == pytest.approx(28.399107142857147, rel=1e-12)
    # the minimum F_βx = max(0.005 F_m/b, 0.5 f_Hβ)
    assert float(P1.initial_misalignment(0.0, 0.0, "none", 1500.0, 4.0)) == 7.5
    assert float(P1.initial_misalignment(0.0, 0.0, "none", 100.0, 4.0)) == 2.0


def test_elasticity_and_helix_factors_of_tr30():
    """Z_E = 189.81170, Z_β = 1.01944 printed (ISO/TR 6336-30 ex. 1, as transcribed)."""
    assert float(P2.z_e(206000.0, 0.3, 206000.0, 0.3)) == pytest.approx(189.81170, abs=6e-6)
    assert float(P2.z_e(206000.0, 0.3, 170000.0, 0.3)) == pytest.approx(180.49638818673876,
                                                                        rel=1e-12)
    assert float(P2.z_beta(math.radians(15.8))) == pytest.approx(1.01944, abs=6e-6)
