"""Input domains: inputs a user can type that once ended in an internal error (exit 3) end
in one line naming the key (exit 2) or a failed check (exit 1), and every numeric field of
every schema has a finite physical range and a resolution.

Each case is an example spec with one value changed, run through the command line
in-process; the reported line must name the user's key.
"""

from __future__ import annotations

import json
import math
import tomllib

import pytest

from geardesign.core import registry
from tests.fuzz import SPECS, schema_fields, set_path, toml_text
from tests.helpers_cli import cli, write_spec


def _run(tmp_path, spec: str, path: tuple, value):
    data = tomllib.loads((SPECS / spec).read_text(encoding="utf-8"))
    set_path(data, path, value)
    code, out, err = cli("run", write_spec(tmp_path, toml_text(data)), "--format", "json")
    assert "Traceback" not in err and "internal error" not in err, err
    return code, out, err


CASES = [
    # (spec, path, value, exit code, key the line must name)
    ("ball_clutch_design.toml", ("safety", "socket_angle"), 80.0, 2, "safety.socket_angle"),
    ("ball_clutch_design.toml", ("safety", "socket_angle"), 85.0, 2, "safety.socket_angle"),
    ("ball_clutch_design.toml", ("safety", "socket_angle"), 89.0, 2, "safety.socket_angle"),
    ("epicycle_rim_raba.toml", ("fatigue", "slgn_alpha"), 2.82, 2, "fatigue.slgn_alpha"),
    ("worm_single_start_reducer.toml", ("thermal", "heat_transfer"), 5e-324, 2,
     "thermal.heat_transfer"),
    ("drive_two_stage_reducer.toml", ("stage", 0, "rack", "addendum_coef"), 0.005, 2,
     "rack.addendum_coef"),
    ("drive_reducer_shafts_keys_thermal.toml", ("stage", 0, "gear", "x1"), 2.0, 2,
     "stage[0].gear"),
    ("pzdn_ko2_startup_closed_form.toml", ("startup", "sweep"), [1e-300], 2, "startup.sweep"),
    ("drive_reducer_shafts_keys_thermal.toml", ("lubrication", "oil_volume"), 5e-324, 2,
     "lubrication.oil_volume"),
    ("spur_iso_scuffing_nrel_stage3.toml", ("iso", "scuffing", "oil_viscosity_100"), 1.5, 2,
     "iso.scuffing.oil_viscosity_100"),
]


@pytest.mark.parametrize("spec, path, value, code, key", CASES,
                         ids=[f"{c[0]}:{'.'.join(map(str, c[1]))}={c[2]}" for c in CASES])
def test_input_outside_its_domain_is_one_line_naming_the_key(tmp_path, spec, path, value,
                                                              code, key):
    got, out, err = _run(tmp_path, spec, path, value)
    assert got == code, err
    lines = err.splitlines()
    assert len(lines) == 1 and key in lines[0], lines
    assert out == ""


def test_ball_clutch_beyond_self_locking_in_check_mode_fails_the_check(tmp_path):
    """With a given spring preload the socket angle beyond self-locking is a failed check."""
    code, out, err = _run(tmp_path, "ball_clutch_check.toml", ("safety", "socket_angle"), 85.0)
    assert code == 1, err
    doc = json.loads(out)
    failed = [c for c in doc["checks"] if not c["passed"]]
    assert "SELF_LOCKING" in [c["code"] for c in failed]
    assert "safety.socket_angle" in next(c["message"] for c in failed
                                         if c["code"] == "SELF_LOCKING")


def test_scuffing_oil_outside_astm_d341_at_the_oil_temperature(tmp_path):
    """A thin oil (ν40 = 2.5, ν100 = 2 mm²/s) at 150 °C lies below the 2 mm²/s of ASTM D341."""
    data = tomllib.loads((SPECS / "spur_iso_scuffing_nrel_stage3.toml").read_text("utf-8"))
    data["iso"]["lubricant_viscosity"] = 2.5
    data["iso"]["scuffing"].update(oil_viscosity_100=2.0, oil_temperature=150.0)
    code, out, err = cli("run", write_spec(tmp_path, toml_text(data)), "--format", "json")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "iso.scuffing.oil_temperature = 150.0" in err, err


def _numeric_fields():
    for kind in registry.known_kinds():
        for path, f in schema_fields(registry.get(kind).schema.root):
            if f.numeric and not f.choices:
                yield kind, ".".join(map(str, path)), f


FIELDS = list(_numeric_fields())


def test_every_numeric_field_has_a_finite_range_and_a_resolution():
    """No numeric input is bounded by "> 0" alone: each has finite lower and upper bounds and
    refuses denormals, 1e-300, ±1e300, NaN and infinity."""
    for kind, key, f in FIELDS:
        lo = f.minimum if f.minimum is not None else f.gt
        hi = f.maximum if f.maximum is not None else f.lt
        assert lo is not None and hi is not None and math.isfinite(lo) and math.isfinite(hi), \
            (kind, key)
        element = f.element if f.type == "array" else f
        for v in (5e-324, -5e-324, 1e-300, 1e300, -1e300, math.nan, math.inf, -math.inf):
            assert element.check(v)[1] is not None, (kind, key, v)


def test_epicycle_scatter_model_below_one_cycle_fails_a_check_naming_the_keys(tmp_path):
    """S_lgN = 10^(α + β·lg σ̄) with α = 0, β = −10 at σ̄ ≈ 0.86 is about 5 decades: the
    quantile life drops below one cycle; a failed check names the coefficients, the lives
    stay finite."""
    data = tomllib.loads((SPECS / "epicycle_rim_raba.toml").read_text(encoding="utf-8"))
    data["load"]["bending_stress"] *= 0.5
    data["fatigue"].update(slgn_alpha=0.0, slgn_beta=-10.0)
    code, out, err = cli("run", write_spec(tmp_path, toml_text(data)), "--format", "json")
    assert code == 1, err
    doc = json.loads(out, parse_constant=lambda c: pytest.fail(c))
    check = next(c for c in doc["checks"] if c["code"] == "SN_SCATTER_DOMAIN")
    assert not check["passed"]
    assert "fatigue.slgn_alpha" in check["message"] and "fatigue.slgn_beta" in check["message"]
    assert all(x is None or x >= 0 for x in doc["results"]["life"]["N_P"])
