"""Published shaft cases (values that this code did not produce).

1. [ShigleySM] problem 7-8: a uniform steel shaft, d = 1.875 in, bearings 11 in apart, a
   gear force of 1449 lbf 9 in from the left bearing, E = 30 Mpsi.  The published solution
   prints the slopes 0.0002823 rad at the left bearing, 0.0004342 rad at the right bearing
   and 0.000304 rad at the gear (four and three significant digits: tolerance half a unit
   of the last printed digit).

   Problem 4-27 of the same manual: a uniform shaft d = 1.375 in on bearings 16 in apart
   (E = 30 Mpsi) with 100 lbf in the x–y plane 4 in from the left bearing and 300 lbf in
   the x–z plane 10 in from it; at mid-span the printed deflections are 1.115·10⁻³ in (y),
   4.445·10⁻³ in (z) and |δ| = 4.583·10⁻³ in (tolerance half a unit of the fourth digit).

2. [Ugural] example 9.6: a stepped shaft on two bearings, the middle half of twice the
   second moment of area of the end quarters (2I, I), a flywheel of weight W at mid-span.
   The moment-area solution prints the static deflection δ_C = 3WL³/(256EI) and the
   critical speed from Rayleigh's formula n = (1/2π)·√(g/δ) for W = 400 N, L = 1 m,
   I = 0.3·10⁻⁶ m⁴, E = 200 GPa, the shaft weight ignored.  The printed δ_C is a closed
   form: reproduced to 1e-9; the critical speed follows from it (the shaft here is given a
   mass 10⁻⁴ of the flywheel's, so the eigenvalue agrees with Rayleigh's formula to 1e-4).

3. [Faires] problem 471 (a): a stub shaft of SAE 1035 as rolled (s_u = 85, s_y = 55,
   s_n = 0.5·s_u = 42.5 ksi) transmits 30 hp at 300 rpm (T = 6300 in·lb) through a 12-in
   gear midway between bearings 16 in apart (M = 4200 in·lb, the radial component
   neglected), profile keyway K_f = 2.0, K_fs = 1.6, size factor 0.85; octahedral-shear
   combination of a Soderberg line in bending and in torsion, N = 1.5.  The published
   solution finds d = 1.569 in.  The combination is the one of [GOST25504] and [Dunaev]
   (S = S_σ·S_τ/√(S_σ² + S_τ²)) with σ_-1 = s_n, K_σD = K_f/0.85, ψ_σ = s_n/s_y,
   τ_-1 = 0.577·s_n, ψ_τ = s_n/s_y; at the printed d it gives N = 1.5 (tolerance 0.003:
   d is printed to four digits, N ∝ d³).
"""

import math

from geardesign.shaft import strength as ST
from geardesign.shaft.solve import Load, Material, Step, Support, analyse
from tests.conftest import assert_ref

IN = 25.4               # mm
LBF = 4.4482216152605   # N
PSI = 6.894757293168e-3  # MPa


def _material(E, density=7850.0):
    return Material(600.0, 350.0, 250.0, 150.0, 0.1, 0.05, E=E, density=density)


def test_shigley_sm_7_8_slopes():
    d, l, a, F = 1.875 * IN, 11.0 * IN, 9.0 * IN, 1449.0 * LBF
    r = analyse([Step(l, d)], [Load(a, Fy=F, name="gear")], [Support(0.0), Support(l)],
                _material(30e6 * PSI))
    assert_ref(r.supports[0].slope, 0.0002823, 0.5e-7, "[ShigleySM] 7-8 left bearing")
    assert_ref(r.supports[1].slope, 0.0004342, 0.5e-7, "[ShigleySM] 7-8 right bearing")
    assert_ref(r.loads[0].slope, 0.000304, 0.5e-6, "[ShigleySM] 7-8 gear")


def test_shigley_sm_4_27_two_planes():
    d, l = 1.375 * IN, 16.0 * IN
    loads = [Load(4.0 * IN, Fy=-100.0 * LBF), Load(10.0 * IN, Fz=-300.0 * LBF),
             Load(8.0 * IN, name="mid-span")]
    r = analyse([Step(l, d)], loads, [Support(0.0), Support(l)], _material(30e6 * PSI))
    mid = r.loads[2]
    assert_ref(-mid.w_y / IN, 1.115e-3, 0.5e-6, "[ShigleySM] 4-27 y")
    assert_ref(-mid.w_z / IN, 4.445e-3, 0.5e-6, "[ShigleySM] 4-27 z")
    assert_ref(mid.w / IN, 4.583e-3, 0.5e-6, "[ShigleySM] 4-27 |δ|")


def test_ugural_9_6_stepped_shaft():
    W, L, I, E = 400.0, 1000.0, 0.3e-6 * 1e12, 200e3          # N, mm, mm⁴, MPa
    d1 = (64 * I / math.pi) ** 0.25
    d2 = (64 * 2 * I / math.pi) ** 0.25
    g = 9.80665
    m = W / g
    steps = [Step(L / 4, d1), Step(L / 2, d2), Step(L / 4, d1)]
    # shaft mass 1e-4 of the flywheel's ("shaft weight ignored")
    vol = sum(math.pi * s.diameter ** 2 / 4 * s.length for s in steps) * 1e-9  # m³
    mat = _material(E, density=max(1e-4 * m / vol, 1e-6))
    r = analyse(steps, [Load(L / 2, Fy=W, mass=m)], [Support(0.0), Support(L)], mat)
    delta = 3 * W * L ** 3 / (256 * E * I)                     # printed closed form, mm
    assert abs(r.loads[0].w_y - delta) <= 1e-9 * delta, "[Ugural] ex. 9.6 δ_C"
    n_rayleigh = 30 / math.pi * math.sqrt(g * 1000 / delta)    # δ in mm, g in mm/s²
    assert abs(r.n_cr / n_rayleigh - 1) <= 1e-4, "[Ugural] ex. 9.6 n_cr"


def test_faires_471_combined_safety():
    d = 1.569                                       # in, printed
    s_u, s_y = 85.0, 55.0                          # ksi
    s_n = 0.5 * s_u
    M, T = 4200.0, 6300.0                          # in·lb
    sigma_a = 32 * M / (math.pi * d ** 3) / 1000   # ksi
    tau_m = 16 * T / (math.pi * d ** 3) / 1000
    f = ST.fatigue_safety(sigma_a, 0.0, 0.0, tau_m, 2.0 / 0.85, 1.0, 1.0, 1.0, 1.0,
                          s_n, 0.577 * s_n, s_n / s_y, s_n / s_y)
    assert_ref(f.S, 1.5, 0.003, "[Faires] 471 (a) N at d = 1.569 in")

