"""Scuffing (ISO/TS 6336-21 integral temperature) in the spur calculator: input errors of
every key (one line, exit 2), a failing design with advice that leads to a passing one, and
properties that hold for every input."""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.errors import format_value
from geardesign.core.registry import run_data
from geardesign.spur.strength.iso6336 import part21 as P21
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.strength.iso6336.spec import SCUFFING
from tests.conftest import SPECS
from tests.helpers_cli import cli, run_bad, write_spec
from tests.test_iso6336_inputs import DATA, GOOD

OIL = "[iso.scuffing]\nfzg_load_stage = 12\noil_temperature = 70.0\n"


def _bad(field):
    if field.type == "string":
        return '"nonsense"', "nonsense"
    if field.type == "integer":
        return str(int(field.maximum) + 1), int(field.maximum) + 1
    return repr(float(field.maximum) * 2 + 1), float(field.maximum) * 2 + 1


@pytest.mark.parametrize("field", SCUFFING.fields, ids=[f.key for f in SCUFFING.fields])
def test_every_scuffing_key_has_its_domain(tmp_path, field):
    text, value = _bad(field)
    body = "".join(line + "\n" for line in OIL.splitlines()[1:]
                   if not line.startswith(field.key + " "))
    lines = run_bad(tmp_path, GOOD + "[iso.scuffing]\n" + body + f"{field.key} = {text}\n")
    assert len(lines) == 1
    assert lines[0].startswith(f"s.toml: iso.scuffing.{field.key} = {format_value(value)}: "
                               f"must be {field.rule()}")


def test_required_keys(tmp_path):
    lines = run_bad(tmp_path, GOOD + "[iso.scuffing]\noil_temperature = 70.0\n")
    assert len(lines) == 1 and lines[0].startswith("s.toml: iso.scuffing.fzg_load_stage")


def test_viscosity_at_100_below_40(tmp_path):
    lines = run_bad(tmp_path, GOOD + OIL + "oil_viscosity_100 = 300.0\n")
    assert lines == ["s.toml: iso.scuffing.oil_viscosity_100 = 300.0: must be smaller than the "
                     "viscosity at 40 °C (iso.lubricant_viscosity = 220 mm²/s)"]


def _data(**scuffing) -> dict:
    d = json.loads(json.dumps(DATA))
    d["load"]["speed1"] = 6000.0
    d["load"]["torque1"] = 120.0
    d["iso"] = {"scuffing": {"fzg_load_stage": 12, "oil_temperature": 70.0, **scuffing}}
    return d


def _scuffing(d: dict) -> tuple[dict, dict]:
    res = run_data(d)
    doc = res.document()
    checks = {c["code"]: c for c in doc["checks"]}
    return doc["results"]["iso6336_scuffing"], checks


def test_failing_design_gets_advice_that_passes():
    """A hot, fast pair on a weak oil fails with exit 1; the FZG stage the advice names
    passes."""
    r, checks = _scuffing(_data(fzg_load_stage=4, oil_temperature=110.0))
    c = checks["ISO_SCUFFING"]
    assert not c["passed"] and c["severity"] == "error"
    assert "use an oil of FZG load stage" in c["message"]
    stage = int(c["message"].split("FZG load stage ")[1].split()[0])
    r2, checks2 = _scuffing(_data(fzg_load_stage=stage, oil_temperature=110.0))
    assert checks2["ISO_SCUFFING"]["passed"]
    r3, checks3 = _scuffing(_data(fzg_load_stage=stage - 1, oil_temperature=110.0))
    assert not checks3["ISO_SCUFFING"]["passed"]


def test_failing_design_exit_code(tmp_path):
    text = GOOD.replace("speed1 = 1450.0", "speed1 = 6000.0").replace("torque1 = 70.0",
                                                                      "torque1 = 120.0")
    path = write_spec(tmp_path, text + "[iso.scuffing]\nfzg_load_stage = 4\n"
                      "oil_temperature = 110.0\n")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1 and "Traceback" not in err
    doc = json.loads(out)
    assert any(c["code"] == "ISO_SCUFFING" and not c["passed"] for c in doc["checks"])


def test_welding_factor_from_the_material_types():
    d = _data()
    for w in ("pinion", "wheel"):
        d["material"][w] = {"grade": "38Kh2MYuA", "treatment": "nitrided", "hardness_HV": 700.0,
                          "core_HRC": 30.0}
    r, _ = _scuffing(d)
    assert r["X_WrelT"] == T.SCUFFING_X_WRELT["nitrided"] == 1.5
    r, _ = _scuffing(_data(structure="carburized_high_austenite"))
    assert r["X_WrelT"] == 0.85


def test_no_scuffing_without_the_table():
    doc = run_data(json.loads(json.dumps(DATA))).document()
    assert "iso6336_scuffing" not in doc["results"]
    assert not any(c["code"].startswith("ISO_SCUFFING") for c in doc["checks"])


# ----------------------------------------------------------------------------- properties


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(20.0, 120.0), stage=st.integers(1, 14), speed=st.floats(200.0, 6000.0),
       torque=st.floats(10.0, 150.0))
def test_temperatures_and_safety_are_physical(theta, stage, speed, torque):
    """Θ_int lies above the oil temperature and Θ_M between them; S_intS and S_SL are finite
    and positive; the safety factor is the ratio it claims."""
    d = _data(fzg_load_stage=stage, oil_temperature=theta)
    d["load"]["speed1"], d["load"]["torque1"] = speed, torque
    r, _ = _scuffing(d)
    assert theta < r["theta_M"] < r["theta_int"]
    for k in ("S_intS", "mu_mC", "theta_flaint", "X_eps", "X_BE"):
        assert math.isfinite(r[k]) and r[k] > 0, k
    assert math.isfinite(r["S_SL"]) and r["S_SL"] >= 0.0
    if r["theta_intS"] <= theta:       # the oil alone reaches the scuffing temperature
        assert r["S_SL"] == 0.0
    assert r["S_intS"] == pytest.approx(r["theta_intS"] / r["theta_int"], rel=1e-12)
    assert 1.0 <= r["K_Bgamma"] <= 1.3 and 0.6 <= r["X_Q"] <= 1.0 and r["X_Ca"] >= 1.0


@settings(max_examples=30, deadline=None)
@given(theta=st.floats(20.0, 110.0))
def test_hotter_oil_is_less_safe(theta):
    a, _ = _scuffing(_data(oil_temperature=theta))
    b, _ = _scuffing(_data(oil_temperature=theta + 10.0))
    assert b["S_intS"] < a["S_intS"]


def test_stronger_oil_scuffs_later():
    temps = [P21.integral_scuffing_temperature(k, 220.0, 1.0, 1.0)[0] for k in range(1, 15)]
    assert temps == sorted(temps) and len(set(temps)) == 14


@settings(max_examples=200, deadline=None)
@given(e=st.floats(0.05, 0.999))
def test_contact_ratio_factor_is_continuous_at_its_branches(e):
    """The branches of X_ε join: at ε_α = 1 (ε_2 = 1 − ε_1), at ε_1 = 1 and at ε_2 = 1."""
    f = P21.contact_ratio_factor
    tiny = 1e-9
    assert f(e, 1 - e - tiny)[0] == pytest.approx(f(e, 1 - e + tiny)[0], rel=1e-6)
    assert f(1 - tiny, e)[0] == pytest.approx(f(1 + tiny, e)[0], rel=1e-6)
    assert f(e, 1 - tiny)[0] == pytest.approx(f(e, 1 + tiny)[0], rel=1e-6)


def test_contact_ratio_factor_outside_the_table_is_flagged():
    value, branch = P21.contact_ratio_factor(1.6, 0.6)
    assert branch.endswith("(nearest)") and value > 0


def test_helical_load_factor_range():
    assert P21.helical_load_factor(1.5) == 1.0
    assert P21.helical_load_factor(2.0) == 1.0
    assert P21.helical_load_factor(3.5) == pytest.approx(1.3)
    assert P21.helical_load_factor(4.2) == 1.3


# ----------------------------------------------------------------------------- planetary

PLANETARY = SPECS / "planetary_nrel_stage1_iso.toml"


def test_planetary_meshes_are_rated_for_scuffing():
    """Each mesh of the NREL stage 1 (three planets) gets its scuffing rating; gear 1 of both
    meshes is the planet (17 teeth, fewer than the sun's 19), in mesh with the sun and the
    ring: X_mp = (1 + 2)/2."""
    from geardesign.core.registry import run

    doc = run(PLANETARY).document()
    for mesh in ("sun_planet", "planet_ring"):
        r = doc["results"][f"strength_{mesh}"]
        assert r["gear1"] == "planet" and r["X_mp"] == 1.5
        assert r["theta_oil"] < r["theta_M"] < r["theta_int"] < r["theta_intS"]
        assert r["S_intS"] == pytest.approx(r["theta_intS"] / r["theta_int"], rel=1e-12)
    codes = {c["code"]: c["passed"] for c in doc["checks"]}
    assert codes["SUN_PLANET_ISO_SCUFFING"] and codes["PLANET_RING_ISO_SCUFFING"]


def test_planetary_scuffing_needs_the_iso_method(tmp_path):
    """Under GOST 21354-87 the scuffing table is not rated, and a warning says so."""
    import re

    text = PLANETARY.read_text(encoding="utf-8").replace('method = "ISO 6336:2019"',
                                                         'method = "GOST 21354-87"')
    # the [iso...] tables are read only by the ISO rating (an input error under GOST)
    text = re.sub(r"^\[iso[^\n]*\n(?:(?!\[)[^\n]*\n)*", "", text, flags=re.M)
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert "Traceback" not in err
    doc = json.loads(out)
    c = next(c for c in doc["checks"] if c["code"] == "SCUFFING_NOT_RATED")
    assert not c["passed"] and c["severity"] == "warning" and "strength.method" in c["message"]
    assert not any("ISO_SCUFFING" in c["code"] for c in doc["checks"])


def test_planetary_scuffing_key_domain(tmp_path):
    text = PLANETARY.read_text(encoding="utf-8").replace("fzg_load_stage = 14",
                                                         "fzg_load_stage = 15")
    lines = run_bad(tmp_path, text)
    assert len(lines) == 1 and lines[0].startswith("s.toml: strength.scuffing.fzg_load_stage = 15")


def test_oil_temperature_advice_leads_to_a_pass():
    """The oil temperature the advice names passes (a cooler oil is also more viscous, so
    the friction falls: the advice is on the safe side); no temperature below 40 °C is
    proposed."""
    import re

    r, checks = _scuffing(_data(fzg_load_stage=9, oil_temperature=110.0))
    msg = checks["ISO_SCUFFING"]["message"]
    t = float(re.search(r"to ([\d.]+) °C \(cooling\)", msg).group(1))
    assert t >= 40.0
    r2, checks2 = _scuffing(_data(fzg_load_stage=9, oil_temperature=t))
    assert checks2["ISO_SCUFFING"]["passed"]
    r3, checks3 = _scuffing(_data(fzg_load_stage=4, oil_temperature=110.0))
    assert "(cooling)" not in checks3["ISO_SCUFFING"]["message"]
