"""Power flow and efficiency of planetary trains: the general torque solver against the
closed forms of Kudryavtsev and of Malashchenko et al. 2017, and the self-locking
criterion of the 3K train."""

from __future__ import annotations

import math

import pytest

from geardesign.planetary.efficiency import efficiency, efficiency_2kh_braked_carrier, flow
from geardesign.planetary.kinematics import Train, speeds


def test_2kh_ring_fixed_closed_form():
    """η^b_ah = 1 − (1 − η^h) z_b/(z_a + z_b) (Kudryavtsev)."""
    t = Train("2K-H", 12, 45, 102, 3)
    s = speeds(t, {"ring": 0.0, "sun": 1000.0})
    eta = {"sun": 0.985, "ring": 0.97 / 0.985}
    f = flow(t, s, eta, "sun", 100.0, ("ring", "carrier"), driven="carrier")
    assert efficiency(f, ("sun",), "carrier") == pytest.approx(1 - 0.03 * 102 / 114, rel=1e-12)
    assert sum(f.T.values()) == pytest.approx(0.0, abs=1e-9)
    ideal = flow(t, s, {"sun": 1.0, "ring": 1.0}, "sun", 100.0, ("ring", "carrier"))
    assert ideal.T["ring"] == pytest.approx(100.0 * 102 / 12, rel=1e-12)   # −T_a u^h_ab


@pytest.mark.parametrize("i", [1.5, 2.0, 3.0, 4.0, 8.0])
@pytest.mark.parametrize("w4", [0.0, 5.0, 10.0])
def test_braked_carrier_sun_drives_eq_14(i, w4):
    """Malashchenko et al. 2017 eq. (14): η_13 = −T_3ω_3/(T_1ω_1 + T_4ω_4)."""
    zs = 20
    zr = round(i * zs)
    t = Train("2K-H", zs, (zr - zs) // 2, zr, 3)
    s = speeds(t, {"sun": 100.0, "carrier": w4})
    if s.n["ring"] >= 0.0:            # ring stopped or reversed: outside the formula
        return
    eta = {"sun": 0.97, "ring": 1.0}
    f = flow(t, s, eta, "sun", 1.0, ("ring", "carrier"), driven="ring")
    got = efficiency(f, ("sun", "carrier"), "ring")
    assert got == pytest.approx(efficiency_2kh_braked_carrier(zr / zs, 0.97, 100.0, w4),
                                rel=1e-12)


@pytest.mark.parametrize("i", [2.0, 4.0, 8.0])
@pytest.mark.parametrize("w4", [0.0, 5.0, 10.0])
def test_braked_carrier_ring_drives_eq_17(i, w4):
    """Eq. (17): ring 3 drives at ω_3 = 100 rad/s, the sun is driven."""
    zs = 20
    zr = round(i * zs)
    t = Train("2K-H", zs, (zr - zs) // 2, zr, 3)
    s = speeds(t, {"ring": 100.0, "carrier": w4})
    eta = {"sun": 0.97, "ring": 1.0}
    f = flow(t, s, eta, "ring", 1.0, ("sun", "carrier"), driven="sun")
    got = efficiency(f, ("ring", "carrier"), "sun")
    assert got == pytest.approx(efficiency_2kh_braked_carrier(zr / zs, 0.97, 100.0, w4, "ring"),
                                rel=1e-12)


def test_braked_carrier_zero_crossing():
    """The ring stops at i = ω_1/ω_4 − 1 (Malashchenko et al., conclusions): η_13 = 0."""
    assert efficiency_2kh_braked_carrier(19.0, 0.97, 100.0, 5.0) == pytest.approx(0.0, abs=1e-15)


def test_3k_self_locking_criterion():
    """The reverse drive ring e → sun of a 3K train (ring b fixed) locks when the
    fixed-carrier efficiency of the chain e → b is at most u = z_b z_f/(z_g z_e)
    ([Kudryavtsev]): here η_b η_e = η² against u = 0.971429."""
    t = Train("3K", 12, 46, 102, 3, None, 105)
    s = speeds(t, {"ring": 0.0, "sun": 1000.0})
    u = 102 / 105
    for factor, locked in ((1.000001, False), (0.999999, True)):
        e = math.sqrt(u * factor)
        eta = {"sun": 0.99, "ring": e, "ring2": e}
        fwd = flow(t, s, eta, "sun", 1.0, ("ring", "ring2"), driven="ring2")
        assert fwd.consistent and efficiency(fwd, ("sun",), "ring2") > 0.0
        rev = flow(t, s, eta, "ring2", -fwd.T["ring2"], ("sun", "ring"), driven="sun")
        eta_r = efficiency(rev, ("ring2",), "sun")
        assert (not rev.consistent or eta_r <= 0.0) is locked, (factor, eta_r)


def test_energy_balance_of_the_3k_train():
    t = Train("3K", 12, 46, 102, 3, None, 105)
    s = speeds(t, {"ring": 0.0, "sun": 3000.0})
    eta = {"sun": 0.985, "ring": 0.996, "ring2": 0.998}
    f = flow(t, s, eta, "sun", 0.05, ("ring", "ring2"), driven="ring2")
    losses = 0.0
    for x in t.central:
        P = f.P_mesh[x]
        losses += P * (1 - eta[x]) if f.k[x] > 0 else -P * (1 - eta[x]) / eta[x]
    assert sum(f.P.values()) == pytest.approx(losses, rel=1e-9)


def test_the_loss_factor_holds_for_one_or_two_pairs_in_contact():
    """Ohlendorf's H_V (ISO/TR 14179-2) is derived for 1 <= ε_α <= 2; the calculators refuse
    a computed mesh efficiency outside (the drive: tests/test_drive_losses.py)."""
    from geardesign.planetary.efficiency import EPS_ALPHA_RANGE, loss_factor_applies

    assert EPS_ALPHA_RANGE == (1.0, 2.0)
    assert [loss_factor_applies(e) for e in (0.99, 1.0, 1.6, 2.0, 2.01)] == [
        False, True, True, True, False]


def test_a_mesh_outside_the_loss_factor_is_refused_or_given(monkeypatch):
    """The wiring of the refusal (a standard-rack train hardly leaves 1 <= ε_α <= 2, so the
    range is narrowed here): model "niemann" is refused naming efficiency.model; with
    model "given" the train computes and reports no H_V for that mesh."""
    from geardesign.core.errors import InputError
    from geardesign.core.registry import run_data
    from geardesign.core.spec import load_toml
    from geardesign.gears import losses as EFF
    from tests.conftest import SPECS

    monkeypatch.setattr(EFF, "EPS_ALPHA_RANGE", (1.0, 1.5))
    data = load_toml(SPECS / "planetary_2kh_reducer.toml")
    with pytest.raises(InputError) as info:
        run_data(data, "p.toml")
    line = info.value.problems[0].line("p.toml")
    assert line.startswith('p.toml: efficiency.model = "niemann": the default (not in the '
                           "spec): the loss factor H_V (Ohlendorf, ISO/TR 14179-2) holds for 1 "
                           "<= ε_α <= 1.5")
    assert 'give model = "given"' in line
    data["efficiency"] = {"model": "given", "external": 0.99, "internal": 0.995}
    eff = run_data(data, "p.toml").document()["results"]["efficiency"]
    assert not any(k.startswith("H_V_") for k in eff) and eff["eta"] > 0
