"""Kinematics and assembly identities of planetary trains (properties, not published
values): the Willis speeds against the closed ratio forms, the mesh frequency seen from
both central gears, and the assembly numbers against a brute-force check of the tooth
phases of every planet."""

from __future__ import annotations

import math
from functools import reduce

from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.planetary.assembly import assembly_numbers, neighbour_clearance, phasing, spacing
from geardesign.planetary.kinematics import Train, frequencies, ratio, speeds


@settings(max_examples=60, deadline=None)
@given(za=st.integers(12, 60), zg=st.integers(12, 60), d=st.integers(-2, 2))
def test_2kh_ratios(za, zg, d):
    zb = za + 2 * zg + d
    t = Train("2K-H", za, zg, zb, 3)
    assert math.isclose(ratio(t, "ring", "sun", "carrier"), 1 + zb / za, rel_tol=1e-12)
    assert math.isclose(ratio(t, "carrier", "sun", "ring"), -zb / za, rel_tol=1e-12)
    assert math.isclose(ratio(t, "sun", "ring", "carrier"), 1 + za / zb, rel_tol=1e-12)
    s = speeds(t, {"ring": 0.0, "sun": 1000.0})
    f = frequencies(t, s)
    assert math.isclose(f.f_mesh, zb * f.f_rel["ring"], rel_tol=1e-12)
    assert math.isclose(f.f_mesh, zg * f.f_rel["planet"], rel_tol=1e-12)


@settings(max_examples=60, deadline=None)
@given(za=st.integers(12, 40), zg=st.integers(20, 60), zf=st.integers(15, 60),
       de=st.integers(1, 6))
def test_3k_ratio_formula(za, zg, zf, de):
    zb = za + 2 * zg
    ze = zb - zg + zf + de
    t = Train("3K", za, zg, zb, 3, zf, ze)
    if zb * zf == zg * ze:
        return
    expected = (1 + zb / za) / (1 - zb * zf / (zg * ze))
    assert math.isclose(ratio(t, "ring", "sun", "ring2"), expected, rel_tol=1e-9)


def _phases_fit(train: Train, theta: float) -> bool:
    """Can a planet sit at angle θ (turns) when the first one sits at 0?  Its orientation
    ψ must give every mesh the tooth phase of the first planet; ψ follows from the ring b
    up to a multiple of 1/z_cb, each other mesh is then checked (all in turns)."""
    zb, cb = train.ring, train.crown("ring")
    for n in range(cb):
        psi = ((cb - zb) * theta + n) / cb
        ok = True
        for x in train.central:
            zx, cx = train.teeth(x), train.crown(x)
            if x == "sun":
                ph = cx * (theta - psi) + zx * theta
            else:
                ph = cx * (theta - psi) - zx * theta
            if abs(ph - round(ph)) > 1e-9:
                ok = False
                break
        if ok:
            return True
    return False


@settings(max_examples=40, deadline=None)
@given(za=st.integers(10, 40), zg=st.integers(12, 40), zf=st.integers(12, 40),
       k=st.integers(2, 6), d=st.integers(1, 8), stepped=st.booleans())
def test_assembly_numbers_against_tooth_phases(za, zg, zf, k, d, stepped):
    if stepped:
        t = Train("2K-H-stepped", za, zg, za + zg + zf + d, k, zf)
    else:
        t = Train("3K", za, zg, za + 2 * zg, k, zf, za + zg + zf + d)
    N = assembly_numbers(t)
    n_eff = reduce(math.gcd, N.values())
    assert _phases_fit(t, 1.0 / n_eff)
    for m in range(2, 7):   # no finer admissible step exists
        if _phases_fit(t, 1.0 / (n_eff * m)):
            raise AssertionError((t, n_eff, m))
    assert spacing(t).equal_ok == (n_eff % k == 0)


def test_phasing_kinds():
    angles = [0.0, 120.0, 240.0]
    assert phasing(Train("2K-H", 18, 27, 72, 3), angles).kind == "in phase"
    assert phasing(Train("2K-H", 19, 17, 56, 3), angles).kind == "sequential"
    assert phasing(Train("2K-H", 20, 30, 80, 4), [0.0, 90.0, 180.0, 270.0]).kind == "in phase"
    assert phasing(Train("2K-H", 18, 28, 74, 4), [0.0, 90.0, 180.0, 270.0]).kind == "mixed"


def test_neighbour_clearance_geometry():
    assert math.isclose(neighbour_clearance(50.0, 40.0, math.pi / 3), 10.0, rel_tol=1e-12)
