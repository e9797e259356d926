"""Sliding along the line of action: the printed relations of the paper (V5).

Source: I. V. Dobrov, A. V. Semichev, A. V. Koptil'nyi, I. I. Get'man, "Mechanical model of
the sliding kinematics of reducer gear wheels", Bulletin of NTU "KhPI" 2017 No. 25 ([Dobrov2017]).
Its example pair is z = 18/34
(Fig. 4); the paper prints no numbers for it, only the relations tested here exactly:

* eq. (2): the normal velocity components of both flanks are equal at every contact point
  (v^n = ω1·r_b1 = ω2·r_b2);
* eq. (3) and (15): sliding v_s = v_t1 − v_t2 < 0 on the approach A–P, = 0 at the pitch
  point P, > 0 on the recess P–E;
* eqs. (10) and (20): the relative sliding σ12 lies in (−1, 0] on the approach and [0, 1)
  on the recess.

The numbers of V5 (ε_α = 1.6052, ϑ1(A) = −6.349, ...) are the synthetic
recomputation and are regression values (tests/regression/test_spur_method_note.py).
"""

import math

from geardesign.gears.geometry import BasicRack, PairInput, pair_geometry
from geardesign.spur.kinematics import relative_sliding

G = pair_geometry(PairInput(1.0, 18, 34, 0.0, 0.0, 0.0, 10.0, BasicRack(math.radians(20))))
OMEGA1 = 1.0
OMEGA2 = OMEGA1 / G.u
RHO_W1 = 0.5 * G.g1.d_w * math.sin(G.alpha_tw)


def points(n=41):
    lo, hi = G.g1.rho_p, G.g1.rho_a
    return [lo + (hi - lo) * i / (n - 1) for i in range(n)]


def test_equal_normal_velocities_eq2():
    assert math.isclose(OMEGA1 * G.g1.d_b / 2, OMEGA2 * G.g2.d_b / 2, rel_tol=1e-12)


def test_sliding_sign_eq3_eq15():
    for rho1 in points():
        rho2 = G.g_w - rho1
        v_s = OMEGA1 * rho1 - OMEGA2 * rho2
        if rho1 < RHO_W1 - 1e-9:
            assert v_s < 0
        elif rho1 > RHO_W1 + 1e-9:
            assert v_s > 0
    assert abs(OMEGA1 * RHO_W1 - OMEGA2 * (G.g_w - RHO_W1)) < 1e-12


def test_relative_sliding_bounds_eq10_eq20():
    for rho1 in points():
        s = relative_sliding(rho1, G.g_w - rho1, G.u)
        if rho1 < RHO_W1:
            assert -1.0 < s <= 0.0
        else:
            assert 0.0 <= s < 1.0
    assert abs(relative_sliding(RHO_W1, G.g_w - RHO_W1, G.u)) < 1e-12
