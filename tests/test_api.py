"""The Python API (docs/api.md): the document's examples run, the typed path gives the
command line's documents, and ``import geardesign`` stays cheap."""

import doctest
import json
import subprocess
import sys
from pathlib import Path

import pytest

import geardesign
from geardesign.core.registry import run
from tests.conftest import SPECS

ROOT = Path(__file__).resolve().parent.parent


def test_the_api_document_runs(monkeypatch):
    monkeypatch.chdir(ROOT)
    out = doctest.testfile(str(ROOT / "docs" / "api.md"), module_relative=False,
                           optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert out.attempted > 20 and out.failed == 0


@pytest.mark.parametrize("path", sorted(SPECS.glob("spur_*.toml")), ids=lambda p: p.stem)
def test_load_solve_report_gives_the_command_lines_document(path):
    """report(solve(load(spec))) is the document of `geardesign run spec`."""
    doc = geardesign.report(geardesign.solve(geardesign.load(path))).document()
    assert json.dumps(doc, sort_keys=True) == json.dumps(run(path).document(), sort_keys=True)


def test_records_convert_to_json_safe_data_and_flat_rows():
    from geardesign import spur

    r = spur.solve(geardesign.load(SPECS / "spur_gost_vs_iso.toml"))
    json.dumps(r.asdict(), allow_nan=False)
    flat = r.flat()
    assert all(not isinstance(v, (dict, list)) for v in flat.values())
    assert flat["GOST.S_H1"] == r.ratings["GOST 21354-87"].v["S_H1"]
    assert flat["ISO.S_F2"] == r.ratings["ISO 6336:2019"].v["S_F2"]
    assert flat["d_a1"] == r.geometry.g1.d_a
    rows = r.rows()
    assert {"section", "key", "value", "unit", "symbol", "name", "source"} == set(rows[0])
    json.dumps(rows, allow_nan=False)
    assert geardesign.rows([r]) == [flat]


def test_replace_changes_pair_and_duty_fields():
    inp = geardesign.load(SPECS / "spur_reducer_through_hardened.toml")
    b = inp.replace(b_w=40.0, T1=100.0)
    assert b.pair.b_w == 40.0 and b.strength.duty.T1 == 100.0 and b.spec is None
    assert inp.pair.b_w == 63.0
    fast = inp.replace(n1=1460.0)
    assert fast.speed1 == fast.strength.duty.n1 == 1460.0
    assert geardesign.solve(fast).velocities.n2 == pytest.approx(1460.0 * 22 / 87)
    with pytest.raises(ValueError, match="spec"):
        geardesign.report(geardesign.solve(b))


def test_import_geardesign_imports_no_calculator():
    code = ("import sys, geardesign; "
            "print(sorted(m for m in sys.modules if m.startswith('geardesign')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout
    assert out.strip() == "['geardesign']"


def test_no_module_of_the_package_shadows_an_api_function():
    """Importing a subpackage sets it as an attribute of ``geardesign``: a module named as
    an API function (``geardesign/report/``) would replace the function for every caller
    after its first import.  No module or package may take an API name, and after every
    subpackage is imported the API functions are still the functions."""
    import importlib
    import pkgutil

    names = {m.name for m in pkgutil.iter_modules(geardesign.__path__)}
    assert not names & set(geardesign._API), names & set(geardesign._API)
    for name in sorted(names - {"__main__"}):
        importlib.import_module(f"geardesign.{name}")
    for name in geardesign._API:
        assert callable(getattr(geardesign, name)) and not isinstance(
            getattr(geardesign, name), type(geardesign)), name


@pytest.mark.parametrize("change, key", [
    ({"b_w": float("nan")}, "gear.face_width (b_w)"), ({"b_w": -5.0}, "gear.face_width (b_w)"),
    ({"m_n": 0.0}, "gear.module (m_n)"), ({"z1": 3}, "gear.z1 (z1)"),
    ({"x1": 5.0}, "gear.x1 (x1)"), ({"beta": 1.0}, "gear.helix_angle (beta)"),
    ({"T1": 1e30}, "load.torque1 (T1)"), ({"n1": -1.0}, "load.speed1 (n1)"),
    ({"K_A": 0.1}, "load.application_factor (K_A)"),
    ({"reverse_ratio": 2.0}, "load.reverse_torque_ratio (reverse_ratio)"),
])
def test_replace_keeps_every_value_in_its_spec_keys_domain(change, key):
    """A study changes inputs in Python: each value is held to the domain of the spec key
    that holds it, as reading a spec holds it (no NaN face width, no K_A of 0.1 solved)."""
    from geardesign.core.errors import InputError

    inputs = geardesign.load(SPECS / "spur_reducer_through_hardened.toml")
    with pytest.raises(InputError) as caught:
        inputs.replace(**change)
    line = caught.value.problems[0].line("<python>")
    assert line.startswith(f"<python>: {key} = ") and "must be" in line


def test_a_study_never_sees_a_negative_margin():
    """A variant whose formulas leave their domain (z1 = 5 with x1 = 2: a negative S_F1)
    raises the command line's refusal, naming the quantity, instead of giving a record
    with a negative margin; every domain-valid variant of a sweep over x1 either solves
    with margins >= 0 or is refused so."""
    from geardesign import spur
    from geardesign.core.errors import InputError
    from geardesign.gears.geometry import GeometryError

    inputs = geardesign.load(SPECS / "spur_reducer_through_hardened.toml")
    with pytest.raises(InputError) as caught:
        spur.solve(inputs.replace(z1=5, x1=2.0))
    assert caught.value.problems[0].message.startswith(
        "the inputs give a negative S_F1 (results.bending.S_F1), which the method cannot "
        "compute")
    for z1 in (5, 9, 17):
        for x1 in (-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0):
            try:
                record = spur.solve(inputs.replace(z1=z1, x1=x1))
            except (InputError, GeometryError):
                continue
            assert all(m >= 0 for m in record.margins().values()), (z1, x1)


def test_inputs_built_in_python_meet_the_spec_keys_domains():
    """Typed inputs written directly (no spec read them) are held to the same domains
    when solved."""
    import math

    from geardesign import spur
    from geardesign.core.errors import InputError

    rack = spur.BasicRack(math.radians(20.0), 1.0, 0.25, 0.38)
    for args, key in (((3.0, 20, 40, 0.2, 0.0, 0.0, math.nan, rack), "gear.face_width (b_w)"),
                      ((-3.0, 20, 40, 0.2, 0.0, 0.0, 30.0, rack), "gear.module (m_n)"),
                      ((3.0, 2, 40, 0.2, 0.0, 0.0, 30.0, rack), "gear.z1 (z1)")):
        with pytest.raises(InputError) as caught:
            spur.solve(spur.Inputs(spur.PairInput(*args)))
        assert caught.value.problems[0].key == key
