"""The epicycle_rim calculator through the command line: design failures exit 1 with the
failed check and its advice, the template and schema, list-valued results, and the cold
path without numpy/scipy."""

import json
import re
import subprocess
import sys
import tomllib

import pytest

from geardesign.core.registry import get
from geardesign.core.spec import json_schema, template, validate
from tests.conftest import SPECS
from tests.helpers_cli import cli
from tests.test_epicycle_rim_inputs import GOOD, rep

SPACING = rep("contact_ratio = 1.42", "contact_ratio = 1.42\nangles = [0.0, 40.0, 200.0]")

DESIGN_FAILURES = {
    # Raba 118/77 with the consistent governing amplitude: σ_-1eq > σ_-1D, P ≈ 35 %
    "probability": (GOOD, ["ENDURANCE_LIMIT", "PROBABILITY"],
                    "increase the fillet radius to ρ >= 0.514 mm (e.g. cut the ring with a "
                    "shaper cutter of more teeth), harden the fillets to K_V >= 1.16"),
    # paper B's non-uniform spacing: not assemblable with identical planets
    "assembly": (rep("contact_ratio = 1.42", "contact_ratio = 1.42\nshifts = [0.4, 0.2, -0.6]",
                     rep("natural_frequencies = [2233.0, 3770.0]", "natural_frequencies = [2233.0]")
                     ).split("[fillet]")[0] + GOOD.split("[vehicle]")[1].join(["[vehicle]", ""]),
                 ["ASSEMBLY"], "use multiples of 4.0000°, e.g. 0.0000°, 124.0000°, 244.0000°"),
    # a low natural frequency puts the principal resonance at 35 km/h
    "resonance speed": (GOOD.split("[fillet]")[0] + "[vehicle]" + GOOD.split("[vehicle]")[1]
                        .replace("[2233.0, 3770.0]", "[300.0]"),
                        ["RESONANCE_SPEED"], "n = 1, k0 = 300 Hz at 34.4…36.3 km/h"),
    # planets 40° apart: the tip circles (55.6° needed) overlap
    "planet spacing": (SPACING.split("[fillet]")[0] + "[vehicle]" + SPACING.split("[vehicle]")[1],
                       ["PLANET_SPACING"], "smallest spacing 40.000° <= 55.636°"),
    # a bending stress far beyond the steel: yielding and outside the Haigh diagram
    "static yield": (rep("bending_stress = 259.3", "bending_stress = 3000.0"),
                     ["MEAN_STRESS_DOMAIN", "STATIC_YIELD", "ENDURANCE_LIMIT", "PROBABILITY"],
                     "the fillet yields"),
}


@pytest.mark.parametrize("name", DESIGN_FAILURES)
def test_design_failure_exit_1(tmp_path, name):
    text, codes, advice = DESIGN_FAILURES[name]
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1, err
    doc = json.loads(out)
    failed = [c for c in doc["checks"] if not c["passed"] and c["severity"] == "error"]
    assert [c["code"] for c in failed] == codes
    assert any(advice in c["message"] for c in failed), [c["message"] for c in failed]
    if name == "probability":
        code, out, _ = cli("run", path, "--format", "table")
        assert code == 1 and re.search(rf"✘ FAIL\s+{codes[0]}\s", out)


def test_advice_reaches_the_required_probability(tmp_path):
    """The K_V and ρ named by the PROBABILITY advice do give P >= 90 %."""
    for change in ("radius = 0.514\n", "radius = 0.2\nhardening_factor = 1.16\n"):
        path = tmp_path / "s.toml"
        path.write_text(rep("radius = 0.2\n", change), encoding="utf-8")
        code, out, _ = cli("run", path, "--format", "json")
        doc = json.loads(out)
        assert doc["results"]["life"]["P"] >= 90.0 and code == 0


def test_json_units_and_lists():
    doc = get("epicycle_rim").compute(validate(get("epicycle_rim").schema,
                                               tomllib.loads(GOOD))).document()
    res = doc["results"]
    assert doc["units"]["results.endurance.sigma_m1D"] == "MPa"
    assert doc["units"]["results.resonance.V_n1"] == "km/h"
    assert doc["units"]["results.resonance.chart_a1"] == "-"
    assert len(res["resonance"]["chart_b"]) == 21
    assert res["life"]["lg_N_P"][0] is not None  # 87.3 > 84.6: finite median life
    for section, values in res.items():
        for key, value in values.items():
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                assert f"results.{section}.{key}" in doc["units"], key
    json.dumps(doc, allow_nan=False)


def test_infinite_life_is_null_and_dash(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(rep("radius = 0.2", "radius = 0.46\nhardening_factor = 2.0"), "utf-8")
    code, out, _ = cli("run", path, "--format", "json")
    assert code == 0 and json.loads(out)["results"]["life"]["lg_N_P"] == [None] * 4
    code, out, _ = cli("run", path, "--format", "markdown")
    assert "| lg N_P | life of the governing case at P (∞ shown as —) | —, —, —, — |" in out


def test_template_validates_and_matches_schema():
    calc = get("epicycle_rim")
    data = tomllib.loads(template(calc.schema))
    spec = validate(calc.schema, data)
    assert calc.compute(spec).verdict in ("pass", "fail")
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.validate(data, json_schema(calc.schema))
    code, out, _ = cli("schema", "epicycle_rim")
    assert code == 0 and json.loads(out)["properties"]["ring"]["properties"]["module"][
        "x-unit"] == "mm"


@pytest.mark.parametrize("spec", ["epicycle_rim_raba", "epicycle_rim_resonance"])
def test_cold_run_imports_no_numpy_or_scipy(spec):
    code = ("import sys, runpy; sys.argv = ['geardesign', 'run', %r, '--format', 'json'];\n"
            "try:\n    runpy.run_module('geardesign', run_name='__main__')\n"
            "except SystemExit as e:\n"
            "    heavy = [m for m in ('scipy', 'numpy') if m in sys.modules]\n"
            "    sys.stderr.write('HEAVY=' + ','.join(heavy))\n") % str(SPECS / f"{spec}.toml")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    json.loads(proc.stdout)
    assert proc.stderr.strip().endswith("HEAVY=")
