"""Unit slips on the small side (a load typed in a unit a thousand times too small) and the
report of why GOST 21354-87 and ISO 6336:2019 disagree, as a user meets them: the command
line, the printed report.

The slips are the ones a designer makes: torque in kN·m written as N·m, power in MW-ish
fractions of kW, force in kN written as N. Each run must still compute (exit 0) and say in
a ``UNITS_LOAD`` warning which input is probably in the wrong unit and the value it would
have in the larger unit; no example value of any spec or template may raise such a warning.
"""

from __future__ import annotations

import json
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.units_guard import LIGHT_LOAD_FRACTION, light_load, slip_hint
from tests.conftest import SPECS
from tests.helpers_cli import cli, write_spec


def template(kind: str) -> str:
    code, out, err = cli("template", kind)
    assert code == 0, err
    return out


def with_value(text: str, key: str, value: str) -> str:
    """The template with the first uncommented ``key = ...`` line set to ``value``."""
    new, n = re.subn(rf"(?m)^{re.escape(key)} = [^#\n]*", f"{key} = {value} ", text, count=1)
    assert n == 1, key
    return new


def run_table(tmp_path, text: str) -> tuple[int, str]:
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "table")
    assert "Traceback" not in err
    return code, " ".join(out.split())     # the table wraps messages: compare words


def units_warnings(doc) -> list[dict]:
    """Every failing ``UNITS_*`` check of a result document, nested reports included."""
    found = []
    if isinstance(doc, dict):
        for c in doc.get("checks", []) if isinstance(doc.get("checks"), list) else []:
            if isinstance(c, dict) and str(c.get("code", "")).startswith("UNITS_") \
                    and not c.get("passed", True):
                found.append(c)
        for v in doc.values():
            if isinstance(v, (dict, list)):
                found += units_warnings(v)
    elif isinstance(doc, list):
        for v in doc:
            found += units_warnings(v)
    return found


# --------------------------------------------------------------------- the slips, by CLI

SLIPS = [
    # kind, key, slipped value, hint printed
    ("spur", "torque1", "0.25", "load.torque1 = 0.25 N·m: if kN·m was meant, give 250"),
    ("drive", "power", "0.0075", "motor.power = 0.0075 kW: if MW was meant, give 7.5"),
    ("worm", "torque2", "0.5", "load.torque2 = 0.5 N·m: if kN·m was meant, give 500"),
    ("planetary", "torque", "0.04", "operation.torque = 0.04 N·m: if kN·m was meant, give 40"),
    ("novikov", "torque2", "30.0", "load.torque2 = 30 N·m: if kN·m was meant, give 30000"),
    ("connection", "torque", "0.25", "load.torque = 0.25 N·m: if kN·m was meant, give 250"),
    ("bevel", "torque", "0.15", "load.torque = 0.15 N·m: if kN·m was meant, give 150"),
    ("ball_clutch", "torque", "0.015",
     "operation.torque = 0.015 N·m: if kN·m was meant, give 15"),
]

SLIP_TESTED_APART = {
    "bearing": "test_bearing_slip_names_the_minimum_load_and_the_force",
    "shaft": "test_shaft_slip_names_the_largest_loads",
    "pzdn": "test_pzdn_coupling_gear_slip_names_the_coupling_torque",
}
"""Calculators whose slip needs a spec of its own (not one key of the template)."""

NO_LOAD_SLIP = {
    "epicycle_rim": "the rim's stresses are inputs (measured or from a model, MPa, checked "
                    "against the material's own range); ring_torque only scales the rough "
                    "thin-ring hoop estimate",
    "geneva": "the load is the spindle block's inertia and friction; the drive's dynamic "
              "power is the result, with no capacity to compare it with",
    "wave_gear": "the flexible rim's endurance comes from its forced deflection, not from "
                 "output_torque, which enters only the shell shear and the axial fixation",
}
"""Calculators whose load no capacity fraction can judge, and why."""


def test_every_calculator_is_guarded_against_a_slip_or_says_why_not():
    """A new calculator must join :data:`SLIPS` (or a test of its own), or say why it has no
    load to guard: the class of the bevel pair, which once shipped without the guard."""
    from geardesign.core.kinds import KINDS as ALL

    covered = {s[0] for s in SLIPS} | set(SLIP_TESTED_APART) | set(NO_LOAD_SLIP) | {"drive"}
    assert covered == set(ALL)
    for name in SLIP_TESTED_APART.values():
        assert name in globals(), name


@pytest.mark.parametrize("kind,key,value,hint", SLIPS, ids=[s[0] for s in SLIPS])
def test_small_side_slip_is_named_with_the_value_in_the_larger_unit(tmp_path, kind, key,
                                                                     value, hint):
    code, out = run_table(tmp_path, with_value(template(kind), key, value))
    assert code in (0, 1)
    assert "UNITS_LOAD" in out and hint in out, out[-3000:]


def test_spur_slip_names_the_absurd_dynamic_factor(tmp_path):
    """torque1 = 0.25 (kN·m meant): PASS with K_Hv = 184 before; now the warning says the
    dynamic factor comes from the light load."""
    code, out = run_table(tmp_path, with_value(template("spur"), "torque1", "0.25"))
    assert code == 0
    assert "K_Hv = 184.3 comes from this light load" in out
    assert re.search(r"carries 0\.05\d? % of its contact capacity", out)


def test_drive_slip_is_raised_to_the_drive_and_names_the_motor(tmp_path):
    code, out = run_table(tmp_path, with_value(template("drive"), "power", "0.0075"))
    head = out.split("Stage 1:")[0]          # the drive's own first screen
    assert "stage 1 carries" in head and "motor.power = 0.0075 kW" in head
    # the stage's own warning names the absurd dynamic factor this light load gives
    k_hv = [float(x) for x in re.findall(r"the dynamic factor K_Hv = ([0-9.]+) comes from this "
                                         r"light load", out)]
    assert k_hv and min(k_hv) > 10.0


BEARING_SLIP = """kind = "bearing"
method = "iso281_2007"
[bearing]
designation = "6208"
[load]
F_r = 4.0
speed = 1000.0
[requirements]
life = 20000.0
"""


def test_bearing_slip_names_the_minimum_load_and_the_force(tmp_path):
    """F_r = 4 (kN meant): life 8.9·10¹² h; ISO 281 life does not hold below the SKF minimum
    load 0.01·C_r of a ball bearing ([SKFMinLoad])."""
    code, out = run_table(tmp_path, BEARING_SLIP)
    assert code == 0
    assert "UNITS_LOAD" in out
    assert "below the minimum load 0.01·C_r = 325 N of a ball bearing" in out
    assert "load.F_r = 4 N: if kN was meant, give 4000" in out


def test_bearing_light_but_real_load_is_no_slip(tmp_path):
    """A life beyond 10⁷ h at a load above the minimum load (a slow bearing) is not a slip."""
    code, out = run_table(tmp_path, BEARING_SLIP.replace("F_r = 4.0", "F_r = 400.0")
                          .replace("speed = 1000.0", "speed = 0.5"))
    assert "UNITS_LOAD" not in out


def test_shaft_slip_names_the_largest_loads(tmp_path):
    text = template("shaft")
    for key, value in (("Fy", "-2.6"), ("Fz", "7.0"), ("torque", "0.56"),
                       ("moment_y", "-0.15")):
        text = with_value(text, key, value)
    text = re.sub(r"(?m)^Fz = -1500\.0", "Fz = -1.5", text)
    text = re.sub(r"(?m)^torque = -560\.0", "torque = -0.56", text)
    code, out = run_table(tmp_path, text)
    assert code == 0
    assert "UNITS_LOAD" in out and "load[0].Fz = 7 N: if kN was meant, give 7000" in out


def test_pint_value_out_of_range_says_what_it_became(tmp_path):
    pytest.importorskip("pint")
    path = write_spec(tmp_path, with_value(template("spur"), "module", '"4 in"'))
    code, out, err = cli("run", path)
    assert code == 2 and out == ""
    assert 'gear.module = "4 in": 4 in = 101.6 mm: must be a number >= 0.05 and <= 100 (mm)' \
        in err


# ------------------------------------------------------------ no false alarms anywhere

def _all_kinds() -> list[str]:
    from geardesign.core.kinds import KINDS as ALL

    return sorted(ALL)


KINDS = _all_kinds()


@pytest.mark.parametrize("kind", KINDS)
def test_template_example_values_raise_no_units_warning(tmp_path, kind):
    code, out, err = cli("run", write_spec(tmp_path, template(kind)), "--format", "json")
    assert code in (0, 1), err
    assert units_warnings(json.loads(out)) == []


@pytest.mark.parametrize("expected", sorted(SPECS.glob("*.expected.json")),
                         ids=lambda p: p.name.split(".")[0])
def test_spec_example_values_raise_no_units_warning(expected):
    """The golden documents are the specs' real output (tests/test_golden.py)."""
    assert units_warnings(json.loads(expected.read_text(encoding="utf-8"))) == []


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-9, 1e9), st.floats(0.0, 1.0))
def test_light_load_fires_exactly_below_the_fraction(value, fraction):
    found = light_load("UNITS_LOAD", fraction, "x", [("load.F_r", value, "N")])
    assert bool(found) == (fraction < LIGHT_LOAD_FRACTION)
    if found:
        assert found[0].severity == "warning" and not found[0].passed
        assert slip_hint("load.F_r", value, "N") in found[0].message


@settings(max_examples=100, deadline=None)
@given(st.floats(1e-6, 1e6))
def test_slip_hint_gives_the_value_in_the_larger_unit(value):
    hint = slip_hint("load.torque1", value, "N·m")
    shown = float(hint.rsplit("give ", 1)[1])
    assert shown == pytest.approx(value * 1e3, rel=1e-5)


# ------------------------------------------------------------------- methods differ

BOTH = '["GOST 21354-87", "ISO 6336:2019"]'


def test_template_rated_by_both_methods_says_why_they_disagree(tmp_path):
    """The spur template passes by GOST 21354-87 (K_Hβ 1.04) and fails by ISO 6336
    (K_Hβ 2.21: f_ma = f_Hβ of grade 8 without adjustment, at 79 N/mm)."""
    text = template("spur").replace("# methods = ", f"methods = {BOTH} # ", 1)
    code, out = run_table(tmp_path, text)
    assert code == 1
    m = re.search(r"METHODS_DIFFER (.*?) Decide which assumption is yours", out)
    assert m, out[-3000:]
    msg = m.group(1)
    assert "GOST 21354-87 passes and ISO 6336:2019 fails the pair" in msg
    assert msg.index("K_Hβ 1.04 by GOST against 2.21 by ISO") < msg.index("K_Fα")
    for words in ("f_ma = f_Hβ = 22 µm of grade 8 for gears without adjustment at assembly",
                  "at 79 N/mm", "gear.bearing_scheme = 5", "iso.f_ma",
                  "iso.helix_modification", "gear.accuracy_grade = 8"):
        assert words in msg, words


def test_methods_differ_follows_the_designers_assumption(tmp_path):
    """Gears adjusted at assembly (iso.f_ma given, 0.5·f_Hβ per ISO 6336-1 7.6.2.4): the
    message names the given f_ma instead of the grade's f_Hβ, and K_Hβ differs less."""
    text = (SPECS / "spur_gost_vs_iso.toml").read_text(encoding="utf-8")
    code, out = run_table(tmp_path, text)
    before = re.search(r"K_Hβ [\d.]+ by GOST against [\d.]+ by ISO \(×([\d.]+)\)", out)
    assert before and "f_ma = f_Hβ = 14 µm of grade 7" in out
    code, out = run_table(tmp_path, text + "\n[iso]\nf_ma = 7.0\n")
    assert "f_ma = 7 µm (iso.f_ma)" in out or "K_Hβ" not in out.split("METHODS_DIFFER")[1]
    after = re.search(r"K_Hβ [\d.]+ by GOST against [\d.]+ by ISO \(×([\d.]+)\)", out)
    assert after is None or float(after.group(1)) < float(before.group(1))


def test_pzdn_coupling_gear_slip_names_the_coupling_torque(tmp_path):
    text = (SPECS / "pzdn_ko2_coupling_gear.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^torque = 22\.1", "torque = 0.0221", text)
    text = re.sub(r"(?m)^peak_torque = 48\.6", "peak_torque = 0.0486", text)
    code, out = run_table(tmp_path, text)
    head = out.split("Coupling gear: the spur calculator's report")[0]
    assert "UNITS_LOAD" in head
    assert "coupling_gear.torque = 0.0221 N·m: if kN·m was meant, give 22.1" in head
