"""ISO 6336-1/-3 factors at stated inputs against python-gearbox 0.1.2a (GitHub
``efirvida/python-gearbox`` at commit 2a41b4d56720ffc33e272bc2c8a8c09bd97252fe,
``gearbox/standards/iso.py``), its functions named with each test and evaluated at the
inputs below in double precision (tolerance 1e-12 relative).

Only functions that transcribe the standard as geardesign does are used; where that
program is known to differ (its running-in y_α divides by f_pb, its Y_DT and ρ' of St are
misprinted, its Y_β is the 2006 form) the value is not taken from it.
"""

import math

import pytest

from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336 import part3 as P3


@pytest.mark.parametrize("material, Rz, expected", [
    ("V", 0.5, 1.12), ("St", 0.5, 1.07), ("NT", 0.5, 1.025), ("V", 10.0, 1.0016507255538354),
    ("Eh", 20.0, 0.956738365558955), ("St", 10.0, 1.0009984033988903),
    ("NT", 10.0, 0.9943578488876694), ("GG", 25.0, 0.9778292384865543)])
def test_relative_surface_factor(material, Rz, expected):
    """``__yrel``: Y_RrelT by material group, constants below R_z = 1 µm."""
    assert P3.y_r_rel(material, Rz) == pytest.approx(expected, rel=1e-12)


Y_NT = {  # ``__ynt``: (N_L, Y_NT)
    "V": [(1e3, 2.5), (1e4, 2.5), (1e5, 1.7270060230666913), (3e6, 1.0),
          (1e8, 0.9321569425523123), (1e10, 0.85), (1e12, 0.85)],
    "Eh": [(1e2, 2.5), (1e3, 2.5), (1e4, 1.9208557828782513), (1e5, 1.4758747754467278)],
    "NT": [(1e3, 1.6), (1e4, 1.3977073662068888), (1e5, 1.2209911759681238)],
    "NV_nitrocar": [(1e3, 1.1), (1e4, 1.0702577660403354), (1e5, 1.0413197143360449),
                    (1e8, 0.9321569425523123)],
}


@pytest.mark.parametrize("material, N_L, expected",
                         [(m, n, y) for m, pts in Y_NT.items() for n, y in pts])
def test_bending_life_factor(material, N_L, expected):
    assert float(P3.y_nt(material, N_L)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("q_s, rho_p, expected", [
    (3.3238, 0.003, 1.0073008589920192), (1.8, 0.0281, 0.9806996357034901),
    (3.0, 0.1005, 1.0206527081515993)])
def test_relative_notch_sensitivity(q_s, rho_p, expected):
    """``__ydelta``: (1 + √(ρ'χ*))/(1 + √(ρ'χ*_T)), χ* = (1 + 2q_s)/5, q_sT = 2.5."""
    assert float(P3.y_delta_rel(q_s, rho_p)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("s_R_over_h, expected", [(1.3, 1.0), (1.2, 1.0),
                                                  (0.9, 1.4603661444924712),
                                                  (0.6, 2.109110317465534)])
def test_rim_factor_external(s_R_over_h, expected):
    """``__yb``: 1 for s_R/h_t ≥ 1.2, else 1.6 ln(2.242 h_t/s_R)."""
    h_t = 9.0
    assert float(P3.y_b(s_R_over_h * h_t, h_t, 4.0)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("eps_beta, beta_deg, expected", [
    (0.6, 12.0, 0.94), (1.4, 20.0, 0.8333333333333334), (1.4, 35.0, 0.75)])
def test_helix_factor_2006(eps_beta, beta_deg, expected):
    """``__ybeta`` (the 2006 form, ε_β ≤ 1 and β ≤ 30° in the bracket); the 2019 factor
    divides it by cos³β."""
    b = math.radians(beta_deg)
    assert P3.y_beta_2006(eps_beta, b) == pytest.approx(expected, rel=1e-12)
    assert float(P3.y_beta(eps_beta, b)) == pytest.approx(expected / math.cos(b) ** 3, rel=1e-12)


@pytest.mark.parametrize("material, m_n, expected", [
    ("St", 4.0, 1.0), ("St", 15.0, 0.94), ("St", 40.0, 0.85), ("GG", 10.0, 0.925),
    ("GG", 30.0, 0.7), ("Eh", 12.0, 0.93), ("Eh", 30.0, 0.8), ("Eh", 5.0, 1.0)])
def test_size_factor_for_bending(material, m_n, expected):
    """``__yx`` (the standard's table, linear between its points)."""
    assert float(P3.y_x(material, m_n)) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("material, sigma_Hlim, v, F_beta_x, expected", [
    ("St", 600.0, 3.0, 40.0, 21.333333333333332), ("St", 600.0, 8.0, 100.0, 42.666666666666664),
    ("St", 600.0, 12.0, 100.0, 21.333333333333332), ("St", 600.0, 8.0, 20.0, 10.666666666666666),
    ("GG", 300.0, 3.0, 40.0, 22.0), ("GG", 300.0, 8.0, 100.0, 45.0),
    ("GG", 300.0, 12.0, 100.0, 22.0), ("Eh", 1500.0, 8.0, 30.0, 4.5)])
def test_running_in_allowance_of_the_helix(material, sigma_Hlim, v, F_beta_x, expected):
    """``__yb__``: y_β of one gear by material group and velocity band."""
    assert float(P1.running_in_beta(F_beta_x, material, sigma_Hlim, v)) == pytest.approx(
        expected, rel=1e-12)
