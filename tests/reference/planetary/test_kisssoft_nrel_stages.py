"""Two spur planetary stages from printed KISSsoft reports: geometry of the external
sun–planet pair and of the internal planet–ring pair, kinematics, torques, forces, load
cycles and mesh losses.

Source: KISSsoft Release 03/2017 A, "CALCULATION OF A SPUR PLANETARY GEAR STAGE", NREL
5 MW drivetrain, GitHub ``gfsReboucas/Drivetrain``, files ``@NREL_5MW/stage_01.rtf`` and
``@NREL_5MW/stage_02.rtf``, commit 2a41bf1ce829b76800693e2b52c91e5f74d074d4 (the same
repository's ``stage_03.rtf`` is the spur reference ``tests/reference/spur/
test_kisssoft_nrel.py``).  Geometry to ISO 21771:2007; the ring is written with z < 0 and
the ISO sign of its shift, as KISSsoft prints it; sun and planet reference profile
1.25/0.38/1.0, ring 1.25/0.30/1.0, ring root form circle with a pinion-type cutter
(stage 1: z0 = 36, stage 2: z0 = 30, x0 = 0).  a and x_sun are given, x_planet and
x_ring follow (KISSsoft prints them to 4 decimals).

Tolerances: lengths printed to 0.001 mm ±0.0006 mm; those that depend on the tip
diameters or the printed 4-decimal shifts ±0.002 mm; angles printed to 0.001° ±0.0006°;
dimensionless values printed to 3 (4) decimals ±0.0006 (±0.00006).  The loss factors
H_V are printed with 3 decimals; the mesh losses use the mean coefficients of friction
KISSsoft prints to 3 decimals (0.041/0.045; 0.037/0.029), so the losses carry ±1.7 %.
"""

import math

import pytest

from geardesign.planetary import strength as PS
from tests.conftest import assert_ref
from tests.reference.planetary._util import planetary

STAGE1 = {
    "train": {"planets": 3, "module": 45.0, "face_width": 491.0, "center_distance": 863.0},
    "teeth": {"sun": 19, "planet": 17, "ring": -56},
    "shift": {"sun": 0.6170},
    "ring": {"root_radius_coef": 0.30},
    "cutter": {"teeth": 36},
    "operation": {"fixed": "ring", "input": "carrier", "output": "sun", "speed": 12.1,
                  "power": 5000.0},
}
STAGE2 = {
    "train": {"planets": 3, "module": 21.0, "face_width": 550.0, "center_distance": 584.0},
    "teeth": {"sun": 18, "planet": 36, "ring": -93},
    "shift": {"sun": 0.3890},
    "ring": {"root_radius_coef": 0.30},
    "cutter": {"teeth": 30},
    "operation": {"fixed": "ring", "input": "carrier", "output": "sun",
                  "speed": 12.1 * (1 + 56 / 19), "power": 5000.0},
}

# section, key: (printed, tolerance)
EXPECTED1 = {
    ("train", "i"): (0.253, 0.0006),                      # itot
    ("kinematics", "n_sun"): (47.8, 0.06),                # n, printed to 0.1
    ("kinematics", "n_planet_rel"): (-39.9, 0.06),        # n2, planet bearing speed
    ("power", "T_sun_ideal"): (-999650.9, 0.06),          # T (sun is the output here)
    ("power", "T_ring_ideal"): (-2946339.4, 0.06),
    # TSteg = 30000 P/(π n_h) = 3945990.3246 for P = 5000 kW, n_h = 12.1 min⁻¹: KISSsoft's
    # printed 3945990.316 differs by 2e-9 (its internal speed is rounded), tolerance 0.01
    ("power", "T_carrier_ideal"): (3945990.316, 0.01),
    ("sun_planet", "u"): (0.895, 0.0006),
    ("planet_ring", "u"): (3.294, 0.0006),                # printed -3.294 (ISO, z3 < 0)
    ("sun_planet", "alpha_tw"): (28.118, 0.0006),
    ("planet_ring", "alpha_tw"): (17.161, 0.0006),
    ("sun_planet", "a"): (810.000, 0.0006),
    ("planet_ring", "a"): (877.500, 0.0006),
    ("sun_planet", "x_sum"): (1.4191, 0.00006),
    ("gears", "x_planet"): (0.8021, 0.00006),
    ("gears", "x_ring_iso"): (-0.5013, 0.00006),
    ("gears", "d_b_sun"): (803.437, 0.0006),
    ("gears", "d_b_planet"): (718.865, 0.0006),
    ("gears", "d_b_ring"): (2368.025, 0.0006),
    ("gears", "d_a_sun"): (978.808, 0.002),
    ("gears", "d_a_planet"): (905.470, 0.002),
    ("gears", "d_a_ring"): (2475.118, 0.002),
    ("gears", "d_f_sun"): (798.030, 0.0006),
    ("gears", "d_f_planet"): (724.692, 0.002),
    ("gears", "d_f_ring"): (2677.618, 0.002),
    ("sun_planet", "d_w_sun"): (910.944, 0.0006),
    ("sun_planet", "d_w_planet"): (815.056, 0.0006),
    ("planet_ring", "d_w_planet"): (752.359, 0.0006),
    ("planet_ring", "d_w_ring"): (2478.359, 0.0006),
    ("sun_planet", "c_21"): (11.250, 0.002),             # c, planet tip to sun root
    ("sun_planet", "c_12"): (11.250, 0.002),
    ("planet_ring", "c_12"): (23.074, 0.002),            # planet tip to ring root
    ("planet_ring", "c_21"): (12.213, 0.002),            # ring tip to planet root
    ("sun_planet", "d_p_sun"): (845.350, 0.002),         # dNf
    ("sun_planet", "d_p_planet"): (762.541, 0.002),
    ("planet_ring", "d_p_planet"): (749.170, 0.002),
    ("planet_ring", "d_p_ring"): (2594.369, 0.002),
    ("gears", "d_l_sun"): (825.979, 0.002),              # dFf (rack)
    ("gears", "d_l_planet"): (748.795, 0.002),
    ("gears", "d_l_ring"): (2662.682, 0.002),            # dFf (pinion-type cutter)
    ("gears", "s_an_sun"): (32.599, 0.002),
    ("gears", "s_an_planet"): (26.588, 0.002),
    ("gears", "s_an_ring"): (38.407, 0.002),
    ("gears", "s_n_sun"): (90.897, 0.0006),              # sn (arc)
    ("gears", "s_n_planet"): (96.962, 0.002),
    ("gears", "s_n_ring"): (54.264, 0.002),
    ("gears", "k_sun"): (3, 0), ("gears", "k_planet"): (3, 0), ("gears", "k_ring"): (8, 0),
    ("gears", "W_sun"): (363.082, 0.0006),               # Wk (no backlash)
    ("gears", "W_planet"): (367.520, 0.002),
    ("gears", "W_ring"): (1047.070, 0.002),
    ("sun_planet", "theta_tip_p"): (0.491, 0.0006),      # zetaa, sun
    ("sun_planet", "theta_p"): (-1.341, 0.0006),         # zetaf, sun
    ("sun_planet", "theta_tip_q"): (0.573, 0.0006),      # zetaa, planet (sun mesh)
    ("sun_planet", "theta_q"): (-0.967, 0.0006),
    ("planet_ring", "theta_tip_p"): (0.416, 0.0006),     # zetaa, planet (ring mesh)
    ("planet_ring", "theta_p"): (-0.037, 0.0006),
    ("planet_ring", "theta_tip_q"): (0.035, 0.0006),     # ring
    ("planet_ring", "theta_q"): (-0.711, 0.0006),
    ("sun_planet", "p_bt"): (132.846, 0.0006),
    ("sun_planet", "g_alpha"): (148.093, 0.002),         # ga
    ("planet_ring", "g_alpha"): (169.815, 0.004),
    ("sun_planet", "eps_alpha"): (1.115, 0.0006),
    ("planet_ring", "eps_alpha"): (1.278, 0.0006),
    ("efficiency", "H_V_sun_planet"): (0.181, 0.0006),   # loss factor HV (4b)
    ("efficiency", "H_V_planet_ring"): (0.161, 0.0006),
    ("planet_bearing", "F_bearing_t"): (-(731585.690 + 792551.164), 0.2),   # Ftw1 + Ftw2
    ("planet_bearing", "F_bearing_r"): (390918.311 - 244739.454, 0.2),      # Fr1 − Fr2
}
EXPECTED2 = {
    ("train", "i"): (0.162, 0.0006),
    ("kinematics", "n_sun"): (294.5, 0.06),
    ("kinematics", "n_planet_rel"): (-123.4, 0.06),
    ("power", "T_sun_ideal"): (-162105.5, 0.06),
    ("power", "T_ring_ideal"): (-837545.3, 0.06),
    ("power", "T_carrier_ideal"): (999650.881, 0.002),
    ("sun_planet", "u"): (2.000, 0.0006),
    ("planet_ring", "u"): (2.583, 0.0006),
    ("sun_planet", "alpha_tw"): (24.169, 0.0006),
    ("planet_ring", "alpha_tw"): (15.630, 0.0006),
    ("sun_planet", "a"): (567.000, 0.0006),
    ("planet_ring", "a"): (598.500, 0.0006),
    ("sun_planet", "x_sum"): (0.8929, 0.00006),
    ("gears", "x_planet"): (0.5039, 0.00006),
    ("gears", "x_ring_iso"): (0.1171, 0.00006),
    ("gears", "d_b_sun"): (355.204, 0.0006),
    ("gears", "d_b_planet"): (710.408, 0.0006),
    ("gears", "d_b_ring"): (1835.220, 0.0006),
    ("gears", "d_a_sun"): (432.838, 0.002),
    ("gears", "d_a_planet"): (815.663, 0.002),
    ("gears", "d_a_ring"): (1906.081, 0.002),
    ("gears", "d_f_sun"): (341.838, 0.0006),
    ("gears", "d_f_planet"): (724.663, 0.002),
    ("gears", "d_f_ring"): (2000.581, 0.002),
    ("sun_planet", "d_w_sun"): (389.333, 0.0006),
    ("sun_planet", "d_w_planet"): (778.667, 0.0006),
    ("planet_ring", "d_w_planet"): (737.684, 0.0006),
    ("planet_ring", "d_w_ring"): (1905.684, 0.0006),
    ("sun_planet", "c_21"): (5.250, 0.002),
    ("planet_ring", "c_12"): (8.459, 0.002),
    ("planet_ring", "c_21"): (6.709, 0.002),
    ("sun_planet", "d_p_sun"): (363.547, 0.002),
    ("sun_planet", "d_p_planet"): (746.983, 0.002),
    ("planet_ring", "d_p_planet"): (738.082, 0.002),
    ("planet_ring", "d_p_ring"): (1969.750, 0.002),
    ("gears", "d_l_sun"): (359.324, 0.002),
    ("gears", "d_l_planet"): (737.389, 0.002),
    ("gears", "d_l_ring"): (1987.879, 0.002),
    ("gears", "s_an_sun"): (12.910, 0.002),
    ("gears", "s_an_planet"): (14.858, 0.002),
    ("gears", "s_an_ring"): (18.937, 0.002),
    ("sun_planet", "theta_tip_p"): (0.533, 0.0006),
    ("sun_planet", "theta_p"): (-1.588, 0.0006),
    ("sun_planet", "theta_tip_q"): (0.614, 0.0006),
    ("sun_planet", "theta_q"): (-1.143, 0.0006),
    ("planet_ring", "theta_tip_p"): (0.309, 0.0006),
    ("planet_ring", "theta_p"): (0.005, 0.0006),
    ("planet_ring", "theta_tip_q"): (-0.005, 0.0006),
    ("planet_ring", "theta_q"): (-0.447, 0.0006),
    ("sun_planet", "p_bt"): (61.995, 0.0006),
    ("sun_planet", "g_alpha"): (84.952, 0.002),
    ("planet_ring", "g_alpha"): (100.284, 0.004),
    ("sun_planet", "eps_alpha"): (1.370, 0.0006),
    ("planet_ring", "eps_alpha"): (1.618, 0.0006),
    ("planet_bearing", "F_bearing_t"): (-(277577.994 + 292998.993), 0.2),
    ("planet_bearing", "F_bearing_r"): (124570.684 - 81969.432, 0.2),
}


@pytest.mark.parametrize("data, expected, name", [(STAGE1, EXPECTED1, "stage_01"),
                                                   (STAGE2, EXPECTED2, "stage_02")])
def test_kisssoft_planetary_stage(data, expected, name):
    r = planetary(data)["results"]
    for (section, key), (value, tol) in expected.items():
        assert_ref(r[section][key], value, tol, f"KISSsoft NREL {name}: {section}.{key}")


@pytest.mark.parametrize("data, printed, name", [
    (STAGE1, {"tip_alteration": -10.861, "F_t": 779454.877, "N_sun": 1124.7e6,
              "N_planet": 419.0e6, "N_ring": 381.6e6, "mesh_power": 3733.333}, "stage_01"),
    (STAGE2, {"tip_alteration": -1.750, "F_t": 285900.438, "N_sun": 7782.3e6,
              "N_planet": 1297.1e6, "N_ring": 1506.3e6, "mesh_power": 4189.189}, "stage_02"),
])
def test_kisssoft_forces_cycles_and_mesh_power(data, printed, name):
    """Tip alteration k·m_n = −Δy·m_n; nominal force at the reference circle per planet
    (no K_γ): F_t = 2000 T_sun/(n_w d_sun); load cycles over 175200 h:
    N = 60·|n − n_h|·c·L_h (c = 3 for sun and ring, 1 for the planet); mesh power
    |T_sun (n_sun − n_h)| without losses."""
    r = planetary(data)["results"]
    m = data["train"]["module"]
    assert_ref(-r["sun_planet"]["delta_y"] * m, printed["tip_alteration"], 0.0006, name)
    F_t = PS._member_torque_force(r["power"]["T_sun_ideal"], r["gears"]["d_sun"], 3, 1.0)
    assert_ref(F_t, printed["F_t"], 0.002, f"{name} F_t")
    L = 175200.0
    k = r["kinematics"]
    for who, n, c in (("N_sun", k["n_sun_rel"], 3), ("N_planet", k["n_planet_rel"], 1),
                      ("N_ring", k["n_ring_rel"], 3)):
        assert_ref(60.0 * abs(n) * c * L / 1e6, printed[who] / 1e6, 0.06, f"{name} {who}")
    P = abs(r["power"]["T_sun_ideal"] * k["n_sun_rel"]) * math.pi / 30.0 / 1000.0
    assert_ref(P, printed["mesh_power"], 0.0006, f"{name} mesh power")


@pytest.mark.parametrize("data, mu, loss, total, eta, name", [
    (STAGE1, (0.041, 0.045), (9.272, 8.986), 54.775, 0.989, "stage_01"),
    (STAGE2, (0.037, 0.029), (7.667, 4.353), 36.060, 0.993, "stage_02"),
])
def test_kisssoft_mesh_losses(data, mu, loss, total, eta, name):
    """Gear power loss per mesh and planet P_V = μ_m H_V P_mesh/n_w (ISO/TR 14179-2),
    total = n_w Σ P_V, efficiency 1 − total/P with KISSsoft's printed μ_m (3 decimals:
    ±1.7 % on the losses)."""
    r = planetary(data)["results"]
    k = r["kinematics"]
    P_mesh = abs(r["power"]["T_sun_ideal"] * k["n_sun_rel"]) * math.pi / 30.0 / 1000.0
    losses = [mu_i * r["efficiency"][f"H_V_{mesh}"] * P_mesh / 3
              for mu_i, mesh in zip(mu, ("sun_planet", "planet_ring"))]
    for got, printed in zip(losses, loss):
        assert abs(got / printed - 1.0) < 0.017, (name, got, printed)
    assert abs(3 * sum(losses) / total - 1.0) < 0.017
    assert_ref(1.0 - 3 * sum(losses) / 5000.0, eta, 0.0006, f"{name} total efficiency")


# The ISO 6336 rating of both meshes of both stages through the planetary calculator with
# the reports' inputs (every printed factor of sections 2–4, m_red, n_E1, N, K_v, Z_W):
# tests/reference/planetary/test_kisssoft_nrel_iso6336.py.
