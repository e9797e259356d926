"""Losses and heat balance of a drive: properties of the loss functions and the solver,
the drive with [lubrication]/[thermal], and its input rules (one line, exit 2)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from geardesign.core.spec import load_toml
from geardesign.drive import losses as L
from geardesign.drive import thermal as TH
from geardesign.planetary import efficiency as EFF
from geardesign.gears import geometry as G
from tests.helpers_cli import cli, run_bad, write_spec

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT / "specs" / "drive_thermal_two_stage.toml"
PLAIN = ROOT / "specs" / "drive_two_stage_reducer.toml"


def _data(path=SPEC):
    d = load_toml(path)
    return d


def _run(data):
    return run_data(data, "test").document()


# ----------------------------------------------------------------------------- functions


@settings(max_examples=200, deadline=None)
@given(F=st.floats(1.0, 1e6), b=st.floats(1.0, 500.0), v=st.floats(0.01, 100.0),
       rho=st.floats(0.5, 200.0), eta=st.floats(1.0, 5000.0), Ra=st.floats(0.05, 5.0),
       XL=st.sampled_from(L.lubricant_types()))
def test_friction_coefficient_positive_and_finite(F, b, v, rho, eta, Ra, XL):
    mu = L.mean_friction_coefficient(F, b, v, rho, eta, Ra, L.lubricant_factor(XL))
    assert math.isfinite(mu) and mu > 0


def _pair(z1, z2, x1, x2, beta):
    """The spur calculator's geometry of a pair (m = 3, α = 20°), None when it refuses it."""
    try:
        return G.pair_geometry(G.PairInput(3.0, z1, z2, x1, x2, math.radians(beta), 30.0,
                                           G.BasicRack(math.radians(20.0))))
    except G.GeometryError:
        return None


@settings(max_examples=300, deadline=None)
@given(z1=st.integers(12, 60), u=st.floats(1.0, 8.0), beta=st.floats(0.0, 35.0),
       x1=st.floats(-0.3, 0.8), x2=st.floats(-0.3, 0.8))
def test_tooth_loss_factor_within_its_model(z1, u, beta, x1, x2):
    """H_V of every pair the geometry accepts: within the model (1 <= ε_α <= 2) the bracket
    1 − ε_α + ε_1² + ε_2² lies in [½, 1 − ε_α + ε_α²], and in [½, 1] while the pitch point
    is in single contact (0 <= ε_1, ε_2 <= 1), so H_V < 1 for z1 >= 12 there; the addendum
    contact ratios of the loss functions are the geometry's."""
    g = _pair(z1, max(z1, round(u * z1)), x1, x2, beta)
    if g is None:
        return
    e1, e2 = L.partial_contact_ratios(g.g1.d_a, g.g2.d_a, g.g1.d_b, g.g2.d_b,
                                      math.degrees(g.alpha_tw), g.p_bt)
    assert e1 + e2 == pytest.approx(g.eps_alpha, rel=1e-9)
    assert e1 > 0 and e2 > 0
    if not EFF.loss_factor_applies(g.eps_alpha):
        return
    hv = L.tooth_loss_factor(g.u, z1, math.degrees(g.beta_b), g.eps_alpha, e1)
    assert hv == pytest.approx(EFF.mesh_loss_factor(g), rel=1e-12)
    k = math.pi * (g.u + 1) / (z1 * g.u * math.cos(g.beta_b))
    assert 0.5 * k * (1 - 1e-12) <= hv <= k * (1 - g.eps_alpha + g.eps_alpha ** 2)
    if e1 <= 1 and e2 <= 1:
        assert hv <= k * (1 + 1e-12) and hv < 1


def test_a_pair_that_cannot_mesh_gets_no_loss_factor(tmp_path):
    """The draw that once failed the property above (z = 12/12, x = −0.25/−0.25, whose
    tip-circle contact ratios give H_V = 1.174): inv α_tw < 0, no working pressure angle,
    so the geometry refuses it before any loss is computed."""
    with pytest.raises(G.GeometryError) as info:
        G.pair_geometry(G.PairInput(3.0, 12, 12, -0.25, -0.25, 0.0, 30.0,
                                    G.BasicRack(math.radians(20.0))))
    assert info.value.code == "INV_ALPHA_TW"
    lines = run_bad(tmp_path, 'kind = "spur"\n[gear]\nmodule = 3.0\nz1 = 12\nz2 = 12\n'
                    'x1 = -0.25\nx2 = -0.25\nface_width = 30.0\nallow_undercut = true\n')
    assert len(lines) == 1 and "no working pressure angle exists" in lines[0]


def test_a_high_contact_ratio_stage_needs_its_efficiency_with_lubrication():
    """ε_α = 2.57 (α = 15°, h_a* = 1.3): three pairs share the load, outside Ohlendorf's
    H_V; the drive asks for the stage's efficiency instead, in one line (exit 2), and
    computes with it."""
    d = _data()
    d["stage"][1]["gear"]["pressure_angle"] = 15.0
    d["stage"][1]["rack"] = {"addendum_coef": 1.3}
    with pytest.raises(InputError) as info:
        _run(d)
    assert [p.line("s.toml") for p in info.value.problems] == [
        "s.toml: stage[1].efficiency: missing; [lubrication] computes the mesh loss of "
        "stage 2 with Ohlendorf's H_V (ISO/TR 14179-2), which holds for 1 <= ε_α <= 2, and "
        "the stage has ε_α = 2.57: give the stage's efficiency, or change its geometry"]
    d["stage"][1]["efficiency"] = 0.98
    assert _run(d)["results"]["losses"]


@settings(max_examples=200, deadline=None)
@given(kind=st.sampled_from(L.bearing_types()), dm=st.floats(5.0, 1000.0),
       n=st.floats(0.0, 2e4), nu=st.floats(2.0, 2000.0), Fr=st.floats(0.0, 1e6),
       Fa=st.floats(0.0, 1e6), C0=st.floats(1e3, 1e7), Y=st.floats(0.5, 3.0))
def test_bearing_moments_nonnegative(kind, dm, n, nu, Fr, Fa, C0, Y):
    M0, M1 = L.bearing_friction_moment(kind, dm, n, nu, Fr, Fa, max(Fr, Fa), C0, Y)
    assert M0 >= 0 and M1 >= 0 and math.isfinite(M0 + M1)


@settings(max_examples=200, deadline=None)
@given(n=st.floats(0.0, 1e4), R=st.floats(10.0, 1000.0), b=st.floats(5.0, 500.0),
       h_share=st.floats(0.0, 1.0), V0=st.floats(0.1, 1000.0), nu=st.floats(2.0, 3000.0))
def test_churning_nonnegative(n, R, b, h_share, V0, nu):
    P = L.churning_loss(880.0, nu, n, R, b, h_share * R, V0, 40, R / 20, 20.0)
    assert P >= 0 and math.isfinite(P)


def test_churning_grows_with_speed_and_immersion():
    p = [L.churning_loss(880.0, 100.0, n, 150.0, 60.0, 20.0, 10.0, 75, 4.0, 20.0)
         for n in (100.0, 300.0, 1000.0, 3000.0)]
    assert p == sorted(p) and p[0] > 0
    q = [L.churning_loss(880.0, 100.0, 500.0, 150.0, 60.0, h, 10.0, 75, 4.0, 20.0)
         for h in (5.0, 20.0, 60.0, 150.0)]
    assert q == sorted(q)


def test_churning_regimes_join_continuously():
    # the linear blend between Re = 6000 and 9000 meets both formulas at the ends
    args = (0.02, 0.3, 5e-3, 0.06, 2.0)
    lo = L.churning_coefficient(*args, 6000.0)
    hi = L.churning_coefficient(*args, 9000.0)
    assert L.churning_coefficient(*args, 6000.0 - 1e-9) == pytest.approx(lo)
    assert L.churning_coefficient(*args, 9000.0 + 1e-9) == pytest.approx(hi)


def test_heat_transfer_coefficients_plausible():
    # free convection on a 0.4 m wall at ΔT = 50 K: a few W/(m²·K) ([Incropera2007]
    # example values for air lie between 2 and 25); radiation of a painted wall ≈ 6–7
    hf = TH.h_free(75.0, 25.0, 400.0)
    assert 2.0 < hf < 10.0
    assert 5.0 < TH.h_radiation(75.0, 25.0, 0.9) < 8.0
    assert TH.h_forced(10.0, 500.0, 75.0, 25.0) > 3 * hf


def test_solver_bounded_iterations():
    r = TH.solve_bounded(lambda x: x ** 3 - 5.0, 0.0, 250.0, max_iterations=200)
    assert r.bracketed and r.iterations <= 200 and r.x == pytest.approx(5 ** (1 / 3), rel=1e-6)
    r = TH.solve_bounded(lambda x: -1.0, 0.0, 250.0)
    assert not r.bracketed and r.x == 250.0
    r = TH.solve_increasing(lambda x: x - 1e6, 0.0, 1.0)
    assert r.bracketed and r.x == pytest.approx(1e6, rel=1e-6) and r.iterations <= 200


def _plain_bisection(f, lo: float, hi: float, tol: float = 1e-7, steps: int = 200):
    """The bisection as :func:`geardesign.drive.thermal.solve_bounded` defines it, every
    midpoint evaluated."""
    if f(lo) >= 0.0:
        return lo, 1
    if f(hi) < 0.0:
        return hi, 2
    it = 0
    while hi - lo > tol * max(1.0, abs(hi)) and it < steps:
        it += 1
        mid = 0.5 * (lo + hi)
        if f(mid) >= 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi), it


@settings(max_examples=300, deadline=None)
@given(root=st.floats(-50.0, 300.0), slope=st.floats(1e-3, 1e4), curve=st.floats(0.0, 5.0),
       power=st.sampled_from([1.0, 0.5, 2.0, 3.0]), step=st.floats(0.0, 100.0))
def test_the_narrowed_bisection_is_the_bisection(root, slope, curve, power, step):
    """The heat balance's bisection reads the sign at a midpoint outside a bracket narrowed
    by the Illinois method: for an increasing function (the balance's premise; here
    smooth, steep, flat, with a jump) it returns the plain bisection's root and step count
    to the last digit, with at most the narrowing's steps more evaluations (a root where f
    is flat), mostly far fewer."""
    def f(t):
        u = t - root
        return slope * (math.copysign(abs(u) ** power, u) + curve * u ** 3) \
            + (step if t >= root else 0.0)

    calls = []

    def counted(t):
        calls.append(t)
        return f(t)

    r = TH.solve_bounded(counted, 25.0, 250.0)
    x, it = _plain_bisection(f, 25.0, 250.0)
    assert (r.x, r.iterations) == (x, it)
    assert len(calls) <= it + 2 + TH.NARROWING_STEPS


def test_the_narrowed_bisection_evaluates_a_dozen_times():
    """A housing's heat flow against a loss (the balance's shape, convex): the root of
    plain bisection with less than half of its evaluations."""
    housing = TH.Housing(0.5, 400.0, 480.0, 0.9, 0.0, 0.0, 0.0)
    for P_V in (30.0, 300.0, 1000.0):
        calls = []

        def f(t):
            return TH.dissipation(housing, t, 25.0).P_Q - P_V

        def counted(t):
            calls.append(t)
            return f(t)

        r = TH.solve_bounded(counted, 25.0, 250.0)
        assert (r.x, r.iterations) == _plain_bisection(f, 25.0, 250.0)
        assert len(calls) <= 12 < r.iterations


# ----------------------------------------------------------------------------- the drive


def test_golden_spec_efficiencies_and_balance():
    doc = _run(_data())
    r = doc["results"]
    assert doc["verdict"] == "pass"
    for row in r["losses"]:
        for k in ("mesh", "churning", "bearings", "seals", "other", "total"):
            assert row[k] >= 0
        assert 0 < row["eta"] <= 1
        assert row["total"] == pytest.approx(row["mesh"] + row["churning"] + row["bearings"]
                                             + row["seals"] + row["other"])
    for row, st_ in zip(r["losses"], r["stages"]):
        assert st_["efficiency"] == pytest.approx(row["eta"], abs=2e-6)
    th = r["thermal"]
    assert th["P_V"] == pytest.approx(th["P_Q"], rel=1e-5)
    assert th["t_oil"] > doc["inputs"]["thermal"]["ambient"]
    assert th["iterations"] <= TH.MAX_ITERATIONS
    # power balance: P_out = P_in − losses
    P_in = r["drive"]["T_in"] * doc["inputs"]["motor"]["speed"] * math.pi / 30000.0
    assert r["drive"]["P_out"] == pytest.approx(P_in - th["P_V"] / 1000.0, rel=1e-4)


def test_sump_temperature_feeds_the_bearings_kappa():
    doc = _run(_data())
    t = doc["results"]["thermal"]["t_oil"]
    out = [b for b in doc["results"]["bearing_reports"]
           if b["inputs"]["method"] == "iso281_2007"]
    assert out
    for b in out:
        assert b["inputs"]["lubrication"]["temperature"] == pytest.approx(t)
        assert b["inputs"]["lubrication"]["oil"] == "VG 220"
        assert b["results"]["life"]["kappa"] > 0


def test_temperature_rises_with_power():
    temps = []
    for P in (3.0, 7.5, 15.0):
        d = _data()
        d["motor"]["power"] = P
        del d["load"]["torque"]
        temps.append(_run(d)["results"]["thermal"]["t_oil"])
    assert temps == sorted(temps) and temps[0] < temps[-1]


def test_thermal_power_limit_reaches_the_permissible_temperature():
    d = _data()
    del d["load"]["torque"]
    doc = _run(d)
    P_T = doc["results"]["thermal"]["P_thermal"]
    d["motor"]["power"] = P_T
    t = _run(d)["results"]["thermal"]["t_oil"]
    # the limit is computed with the bearing loads and stage runs at the nominal power;
    # rerun at P_T the sump lands near the permissible temperature
    assert t == pytest.approx(d["thermal"]["max_oil_temperature"], abs=3.0)


def test_small_housing_fails_with_advice():
    d = _data()
    d["thermal"].update(length=200.0, width=100.0, height=150.0)
    d["lubrication"]["oil_volume"] = 2.0
    doc = _run(d)
    c = next(c for c in doc["checks"] if c["code"] == "THERMAL")
    assert not c["passed"] and doc["verdict"] == "fail"
    assert "oil cooler of" in c["message"] and "housing area of" in c["message"]
    assert "fan" in c["message"] and "thermal power limit" in c["message"]
    # with the cooler it asks for, the sump is within the limit
    kw = float(c["message"].split("oil cooler of ")[1].split(" kW")[0])
    d["thermal"]["cooler"] = kw + 0.01
    c2 = next(c for c in _run(d)["checks"] if c["code"] == "THERMAL")
    assert c2["passed"]


def test_fan_cools():
    d = _data()
    t0 = _run(d)["results"]["thermal"]["t_oil"]
    d["thermal"]["fan_velocity"] = 8.0
    t1 = _run(d)["results"]["thermal"]["t_oil"]
    assert t1 < t0


def test_thicker_oil_more_churning_and_mesh_loss_at_same_temperature():
    lo = L.churning_loss(880.0, 50.0, 300.0, 150.0, 60.0, 20.0, 10.0, 75, 4.0, 20.0)
    hi = L.churning_loss(880.0, 500.0, 300.0, 150.0, 60.0, 20.0, 10.0, 75, 4.0, 20.0)
    assert hi > lo


def test_estimated_housing_without_shafts(tmp_path):
    d = _data()
    del d["thermal"]
    del d["shaft"]
    doc = _run(d)
    th = doc["results"]["thermal"]
    assert th["housing_L"] > 0 and th["A"] > 0
    assert "thermal.ambient" in doc["assumed"]
    assert any(c["code"] == "BEARING_LOSSES" for c in doc["checks"])


def test_without_lubrication_numbers_unchanged():
    # the fixed 0.98 of a cylindrical stage stays without [lubrication]
    doc = _run(_data(PLAIN))
    assert doc["results"]["drive"]["eta"] == pytest.approx(0.98 ** 2)
    assert "thermal" not in doc["results"] and "losses" not in doc["results"]


def test_given_stage_efficiency_is_kept():
    d = _data()
    d["stage"][0]["efficiency"] = 0.97
    doc = _run(d)
    assert doc["results"]["stages"][0]["efficiency"] == 0.97
    row = doc["results"]["losses"][0]
    assert row["mesh"] == 0 and row["other"] == pytest.approx(0.03 * row["P_in"] * 1000)


# ----------------------------------------------------------------------------- input rules


def _toml_with(**tables) -> str:
    text = SPEC.read_text(encoding="utf-8")
    for old, new in tables.items():
        assert old in text
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize("old,new,message", [
    ('oil = "VG 220"', 'oil = "VG 225"', 'lubrication.oil = "VG 225": not an ISO VG grade'),
    ('immersion = 12.0', 'immersion = 500.0', "lubrication.immersion = 500.0: deeper than"),
    ('ambient = 25.0\nmax_oil_temperature = 90.0', 'ambient = 50.0\nmax_oil_temperature = 40.0',
     "thermal.max_oil_temperature = 40.0: must be above the ambient temperature 50"),
    ('base_oil = "mineral"', 'base_oil = "castor"', "lubrication.base_oil"),
    ('ambient = 25.0', 'ambient = 25.0\nfan_share = 2.0', "thermal.fan_share = 2"),
    ('width = 200.0', 'width = -1.0', "thermal.width = -1"),
])
def test_bad_input_one_line_exit_2(tmp_path, old, new, message):
    path = write_spec(tmp_path, _toml_with(**{old: new}))
    code, out, err = cli("run", path, "--format", "json")
    assert code == 2, err
    lines = [x for x in err.strip().splitlines() if x]
    assert len(lines) == 1 and message in lines[0], err


def test_thermal_without_lubrication_is_one_line(tmp_path):
    text = SPEC.read_text(encoding="utf-8")
    start = text.index("[lubrication]")
    end = text.index("[thermal]")
    path = write_spec(tmp_path, text[:start] + text[end:])
    code, out, err = cli("run", path)
    assert code == 2 and "lubrication: missing" in err and len(err.strip().splitlines()) == 1


def test_cli_json_has_loss_table(tmp_path):
    code, out, err = cli("run", SPEC, "--format", "json")
    assert code == 0
    doc = json.loads(out)
    assert [r["stage"] for r in doc["results"]["losses"]] == [1, 2]
    assert doc["units"]["results.thermal.t_oil"] == "°C"


def test_losses_above_the_input_power_is_one_line(tmp_path):
    text = SPEC.read_text(encoding="utf-8").replace("power = 7.5", "power = 0.05").replace(
        "torque = 1100.0\n", "")
    path = write_spec(tmp_path, text)
    code, out, err = cli("run", path)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "motor.power" in err and "the drive would not turn" in err and "bearings" in err


# ------------------------------------------------------------------ scuffing at the sump

SHAFTS = ROOT / "specs" / "drive_reducer_shafts_keys_thermal.toml"


def _scuffing_stage(doc):
    st = doc["results"]["stage_reports"][0]
    return st["inputs"]["iso"], st["results"]["iso6336_scuffing"]


def test_scuffing_is_rated_at_the_sump_temperature_with_the_drives_oil():
    doc = _run(_data(SHAFTS))
    iso, sc = _scuffing_stage(doc)
    th = doc["results"]["thermal"]
    assert iso["scuffing"]["oil_temperature"] == pytest.approx(th["t_oil"], rel=1e-12)
    assert iso["lubricant_viscosity"] == th["nu40"]
    assert iso["scuffing"]["oil_viscosity_100"] == pytest.approx(
        _nu100(th["nu40"], th["VI"]), rel=1e-12)
    assert iso["scuffing"]["oil_density"] == doc["inputs"]["lubrication"]["density"]
    msg = next(c for c in doc["checks"] if c["code"] == "SCUFFING_OIL_1")
    assert msg["passed"] and "sump temperature" in msg["message"]


def _nu100(nu40, VI):
    from geardesign.materials import lubricants as OIL
    return OIL.nu100_from_vi(nu40, VI)


def test_scuffing_equals_the_spur_calculator_at_that_temperature():
    """The stage's scuffing rating is the spur calculator's for the stage as the drive
    loads it, with Θ_oil = the sump temperature: one formula, no copy."""
    doc = _run(_data(SHAFTS))
    st = doc["results"]["stage_reports"][0]
    data = {"kind": "spur", **{k: v for k, v in st["inputs"].items()
                               if k not in ("kind", "title")}}
    alone = run_data(data).document()["results"]["iso6336_scuffing"]
    assert alone["S_intS"] == pytest.approx(_scuffing_stage(doc)[1]["S_intS"], rel=1e-12)


def test_a_given_oil_temperature_below_the_sump_warns():
    d = _data(SHAFTS)
    d["stage"][0]["iso"]["scuffing"]["oil_temperature"] = 30.0
    doc = _run(d)
    iso, _ = _scuffing_stage(doc)
    assert iso["scuffing"]["oil_temperature"] == 30.0
    c = next(c for c in doc["checks"] if c["code"] == "SCUFFING_OIL_1")
    assert not c["passed"] and c["severity"] == "warning"
    assert "leave oil_temperature out" in c["message"]


def test_scuffing_without_lubrication_needs_its_oil_temperature():
    d = _data(SHAFTS)
    d.pop("lubrication")
    d.pop("thermal")
    with pytest.raises(Exception) as e:
        _run(d)
    assert "oil_temperature" in str(e.value)


def test_planetary_stage_scuffing_at_the_sump_temperature():
    """A planetary stage's [strength.scuffing] takes the sump temperature and the drive's
    oil as a cylindrical stage's [iso.scuffing] does."""
    d = load_toml(ROOT / "specs" / "drive_planetary_spur_iso.toml")
    pl = load_toml(ROOT / "specs" / "planetary_2kh_reducer.toml")
    pl.pop("title", None)
    pl.setdefault("strength", {})["scuffing"] = {"fzg_load_stage": 12}
    d["stage"][0] = {"name": "planetary reducer", **pl}
    d["lubrication"] = {"oil": "VG 320"}
    d["thermal"] = {"length": 700.0, "width": 400.0, "height": 500.0}
    doc = _run(d)
    st = doc["results"]["stage_reports"][0]
    sc = st["inputs"]["strength"]["scuffing"]
    t = doc["results"]["thermal"]["t_oil"]
    assert sc["oil_temperature"] == pytest.approx(min(t, 150.0), rel=1e-12)
    assert st["inputs"]["strength"]["lubricant_viscosity"] == 320.0
    assert any(c["code"] == "SCUFFING_OIL_1" for c in doc["checks"])
