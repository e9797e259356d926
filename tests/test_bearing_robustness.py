"""Bearing calculator robustness (issue 15): the "larger bearing" suggestion without a
catalogue C_u, linear cost of load spectra, no check on a non-finite life."""

import pytest

from geardesign.bearing import life as L
from geardesign.bearing.assess import Bearing, Block, Conditions, assess
from geardesign.core.registry import run_data
from tests.conftest import bounded_work
from tests.helpers_cli import run_bad

ISO_CASE = {"kind": "bearing", "method": "iso281_2007",
            "load": {"F_r": 6000.0, "speed": 1000.0},
            "lubrication": {"viscosity": 32.0, "contamination": "normal"},
            "requirements": {"life": 20000.0}}


@pytest.mark.parametrize("bearing", [
    {"designation": "6208"},                                        # catalogue C_u
    {"type": "deep_groove_ball", "C_r": 32500.0, "C_0r": 19000.0,   # C_u estimated
     "d": 40.0, "D": 80.0},
])
def test_suggestion_of_a_larger_bearing_with_and_without_c_u(bearing):
    doc = run_data(dict(ISO_CASE, bearing=bearing)).document()
    life = next(c for c in doc["checks"] if c["code"] == "LIFE")
    assert doc["verdict"] == "fail" and not life["passed"]
    assert "the catalogue SKF 6308 (GOST 308) would give 20 581 h" in life["message"]


def _blocks(n):
    return [Block(1000.0 + (i % 7), 100.0 * (i % 3), 500.0 + i % 11, 1.0 / n) for i in range(n)]


def test_spectrum_of_100000_blocks_is_linear():
    """Guards against a quadratic cost only (100 000 blocks squared would take hours);
    the speed is measured by benchmarks/time_specs.py."""
    b = Bearing("deep_groove_ball", C_r=32500.0, C_0r=19000.0, f0=14.0, D_pw=60.0)
    cond = Conditions("gost18855_94", a23=1.0)
    with bounded_work(1.2, "assessing 100 000 blocks"):
        a = assess(b, _blocks(100000), cond)
    s = a.spectrum
    assert abs(sum(s.damage_share) - 1.0) < 1e-9 and a.life_h > 0
    with bounded_work(0.05, "the mean load of 100 000 blocks"):
        L.spectrum_mean([1000.0 + i % 7 for i in range(100000)], [1000.0] * 100000,
                        [1e-5] * 100000, 3.0)


def test_spectrum_of_1000_blocks_through_a_spec_is_linear():
    blocks = [{"F_r": 1000.0 + i, "speed": 1000.0, "time_share": 0.001} for i in range(1000)]
    with bounded_work(0.1, "a spec of 1000 blocks"):
        doc = run_data({"kind": "bearing", "method": "gost18855_94",
                        "bearing": {"designation": "6208"},
                        "load": {"spectrum": blocks}}).document()
    assert doc["verdict"] == "pass"


def test_a_non_finite_life_is_refused_not_passed():
    b = Bearing("deep_groove_ball", C_r=1e8, C_0r=1e8, D_pw=60.0)
    with pytest.raises(L.BearingError, match="not a finite positive number"):
        assess(b, [Block(1e-300, 0.0, 0.01)], Conditions("gost18855_94", a23=1.0,
                                                         life_required=1000.0))


def test_tiny_loads_are_input_errors(tmp_path):
    text = ('kind = "bearing"\nmethod = "gost18855_94"\n[bearing]\ndesignation = "6208"\n'
            '[load]\nF_r = 0.0\nF_a = 1e-300\nspeed = 1000.0\n[requirements]\nlife = 1000.0\n')
    assert run_bad(tmp_path, text) == [
        "s.toml: load.F_a = 1e-300: must be a number >= 0 and <= 100000000 (N), and 0 or at "
        "least 1e-06 in magnitude"]
