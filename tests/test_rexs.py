"""REXS import and export (docs/rexs.md): public models (tests/data/rexs/README.md) import
and run, their stated geometry is reproduced; exported files conform to the REXS 1.5
attribute database; export → import → run gives the original results; bad files are one
line, exit 2, bounded work."""

from __future__ import annotations

import io
import json
import math
import re
import tomllib
import zipfile
from pathlib import Path

import pytest

from geardesign.core import registry
from geardesign.rexs.exporter import export_spec
from geardesign.rexs.importer import import_model
from geardesign.rexs.model import parse, read_model
from geardesign.testing import RTOL
from tests.conftest import bounded_work
from tests.helpers_cli import cli

DATA = Path(__file__).parent / "data" / "rexs"
SPECS = Path(__file__).parent.parent / "specs"

PUBLIC = {
    # file: (program, stated centre distances [mm] in stage order)
    "FVA-Industriegetriebe_2stufig_1-4.rexs": ("Bearinx", [190.0, 190.0]),
    "FVA-Industriegetriebe_2stufig_1-4.rexsj": ("Bearinx", [190.0, 190.0]),
    "FVA-Industriegetriebe_2_stufig_1-6.rexs": ("Bearinx", [190.0, 190.0]),
    "SEW_3-stage_cylindrical_gearbox_1.0.rexs": ("FVA Workbench", [53.0, 57.0, 77.0]),
}


def _run(text: str):
    return registry.run_data(tomllib.loads(text), "imported.toml")


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_public_model_imports_runs_and_reproduces_stated_geometry(name):
    model = read_model(DATA / name)
    imp = import_model(model, name)
    res = _run(imp.text)
    assert res.exit_code in (0, 1)
    doc = res.document()
    stages = doc["results"]["stage_reports"]
    assert [s["component"] for s in imp.stages]
    # every centre distance the file states, at its printed precision (one decimal)
    stated = PUBLIC[name][1]
    assert len(stages) == len(stated)
    for st, a in zip(stages, stated):
        assert round(st["results"]["geometry"]["a_w"], 1) == pytest.approx(a)
    # every component type of the file is read or listed as not imported
    types = {c.type for c in model.components.values()}
    assert types == imp.read_types | set(imp.not_imported), (
        types ^ (imp.read_types | set(imp.not_imported)))
    assert "# Not imported" in imp.text


def test_xml_and_json_of_one_model_give_one_spec():
    a = import_model(read_model(DATA / "FVA-Industriegetriebe_2stufig_1-4.rexs"), "m")
    b = import_model(read_model(DATA / "FVA-Industriegetriebe_2stufig_1-4.rexsj"), "m")
    strip = lambda t: [ln for ln in t.splitlines() if not ln.startswith("# Imported")]
    assert strip(a.text) == strip(b.text)


def test_every_value_names_its_source():
    text = import_model(read_model(DATA / "SEW_3-stage_cylindrical_gearbox_1.0.rexs"),
                        "m").text
    for line in text.splitlines():
        if "=" in line and not line.startswith(("#", "[", "kind", "title")):
            assert "#" in line, line


@pytest.mark.parametrize("name", ["FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz",
                                  "FVA_worm_stage_1-4.rexs"])
def test_planetary_and_worm_models_are_one_line(name):
    code, out, err = cli("import", DATA / name)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "not imported" in err


# ----------------------------------------------------------------------- export

def _database():
    from importlib.resources import files

    return json.loads(files("geardesign.rexs").joinpath("rexs_database_1.5.json").read_text())


def check_against_database(text: str) -> list[str]:
    """Problems of a REXS 1.5 model against the attribute database: unknown attribute ids,
    attributes not of the component type, wrong units, wrong value types, unknown relation
    types, references to missing components.  ``custom_`` attributes are the program's own."""
    db = _database()
    model = parse(text.encode())
    problems = []
    py_types = {"floating_point": (float, int), "integer": (int,), "boolean": (bool,),
                "string": (str,), "enum": (str,), "floating_point_array": (list,),
                "string_array": (list,)}
    for c in model.components.values():
        allowed = set(db["components"].get(c.type, ()))
        if c.type not in db["components"]:
            problems.append(f"component type {c.type}")
        for a in c.attributes.values():
            if a.id.startswith("custom_"):
                continue
            spec = db["attributes"].get(a.id)
            if spec is None or a.id not in allowed:
                problems.append(f"{c.type}.{a.id}: not an attribute of {c.type}")
                continue
            if (a.unit or "none") != spec["unit"]:
                problems.append(f"{c.type}.{a.id}: unit {a.unit!r}, database {spec['unit']!r}")
            v = a.value
            if model.fmt == "xml":   # XML text: check it parses as the type
                try:
                    if spec["type"] == "integer":
                        int(v)
                    elif spec["type"] == "floating_point":
                        assert math.isfinite(float(v))
                    elif spec["type"] == "boolean":
                        assert v in ("true", "false")
                    elif spec["type"] == "enum":
                        assert v in spec["enum"]
                except (ValueError, AssertionError, TypeError):
                    problems.append(f"{c.type}.{a.id}: {v!r} is no {spec['type']}")
            elif not isinstance(v, py_types.get(spec["type"], (object,))) or (
                    spec["type"] != "boolean" and isinstance(v, bool)):
                problems.append(f"{c.type}.{a.id}: {v!r} is no {spec['type']}")
    for r in model.relations:
        if r.type not in db["relation_types"]:
            problems.append(f"relation type {r.type}")
        for ref in r.refs:
            if ref.id not in model.components:
                problems.append(f"relation {r.id} refers to missing {ref.id}")
    return problems


EXPORTED = ["spur_reducer_through_hardened.toml", "spur_helical_carburized_spectrum.toml",
            "spur_en_case_hardened.toml", "spur_plain.toml", "drive_two_stage_reducer.toml"]


@pytest.mark.parametrize("fmt", ["xml", "json"])
@pytest.mark.parametrize("name", EXPORTED)
def test_exported_model_conforms_to_the_rexs_database(name, fmt):
    text = export_spec(SPECS / name, fmt)
    assert check_against_database(text) == []
    assert parse(text.encode()).version == "1.5"


def test_export_writes_computed_geometry():
    text = export_spec(SPECS / "drive_two_stage_reducer.toml", "json")
    m = parse(text.encode())
    stage = m.of_type("cylindrical_stage")[0]
    assert float(stage.attributes["center_distance"].value) == pytest.approx(180.0)
    gear = m.of_type("cylindrical_gear")[0]
    # d = z·m_n/cos β = 24·2/cos 12° (ISO 21771 eq. (1))
    assert float(gear.attributes["reference_circle_diameter"].value) == pytest.approx(
        24 * 2.0 / math.cos(math.radians(12.0)), rel=1e-12)


def test_export_of_another_kind_is_one_line():
    code, out, err = cli("export", SPECS / "worm_design.toml")
    assert code == 2 and "export writes spur and drive specs" in err


# ----------------------------------------------------------------------- round trip

def _numbers(x, path=""):
    """The numbers of a result document by path (text such as shift_source left out, and
    the inputs: the imported spec gives x2 where the original gave the centre distance)."""
    if isinstance(x, dict):
        for k, v in x.items():
            if k in ("inputs", "units"):
                continue
            yield from _numbers(v, f"{path}.{k}")
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from _numbers(v, f"{path}[{i}]")
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        yield path, x


def _close(a: dict, b: dict) -> list[str]:
    na, nb = dict(_numbers(a)), dict(_numbers(b))
    bad = [p for p in na if p not in nb]
    bad += [f"{p}: {na[p]} vs {nb[p]}" for p in na if p in nb
            and not math.isclose(na[p], nb[p], rel_tol=RTOL, abs_tol=1e-9)]
    return bad


@pytest.mark.parametrize("fmt", ["xml", "json"])
@pytest.mark.parametrize("name", ["spur_reducer_through_hardened.toml",
                                  "spur_helical_carburized_spectrum.toml",
                                  "drive_two_stage_reducer.toml"])
def test_round_trip_gives_the_original_results(name, fmt):
    original = registry.run(SPECS / name).document()
    model = parse(export_spec(SPECS / name, fmt).encode())
    back = _run(import_model(model, name).text).document()
    if original["kind"] == "spur":
        stage = back["results"]["stage_reports"][0]
        assert _close(original["results"], stage["results"]) == []
        # the drive adds SET_BY_DRIVE (it names the torque and speed it filled in)
        assert ([(c["code"], c["passed"]) for c in original["checks"]]
                == [(c["code"], c["passed"]) for c in stage["checks"]
                    if c["code"] != "SET_BY_DRIVE"])
    else:
        assert _close(original["results"], back["results"]) == []
        assert original["verdict"] == back["verdict"]


# ----------------------------------------------------------------------- bad files

GOOD = (DATA / "FVA-Industriegetriebe_2stufig_1-4.rexs").read_bytes()


def _bad(tmp_path, name: str, raw: bytes, needle: str):
    path = tmp_path / name
    path.write_bytes(raw)
    with bounded_work(0.2, f"importing {name}"):
        code, out, err = cli("import", path)
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1, err
    assert needle in err, err
    assert out == ""


def test_truncated_xml(tmp_path):
    _bad(tmp_path, "t.rexs", GOOD[: len(GOOD) // 2], "not well-formed XML")


def test_not_rexs(tmp_path):
    _bad(tmp_path, "n.rexs", b"<html><body>hello</body></html>", "not a REXS model")
    _bad(tmp_path, "n2.rexs", b"hello", "not a REXS model")
    _bad(tmp_path, "n3.rexsj", b'{"something": 1}', "not a REXS model")


def test_unknown_version(tmp_path):
    _bad(tmp_path, "v.rexs", GOOD.replace(b'version="1.4"', b'version="2.1"', 1),
         "REXS version 2.1 is not one this tool reads")


def test_entity_declarations_refused(tmp_path):
    bomb = (b'<?xml version="1.0"?><!DOCTYPE model [<!ENTITY a "aaaaaaaaaa">'
            + b"".join(b'<!ENTITY a%d "&a%s;&a%s;&a%s;&a%s;&a%s;&a%s;&a%s;&a%s;&a%s;&a%s;">'
                       % ((i,) + (b"" if i == 1 else str(i - 1).encode(),) * 10)
                       for i in range(1, 10))
            + b']><model version="1.4">&a9;</model>')
    _bad(tmp_path, "b.rexs", bomb, "document type declaration")


def test_zip_bomb(tmp_path):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as zf:
        zf.writestr("rexs-model.rexs", b"<" + b" " * (70 * 1024 * 1024))   # > 64 MiB
    _bad(tmp_path, "bomb.rexsz", buf.getvalue(), "zip bomb")


def test_zip_of_many_members(tmp_path):
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w") as zf:
        for i in range(100):
            zf.writestr(f"f{i}.txt", b"x")
    _bad(tmp_path, "many.rexsz", buf.getvalue(), "members")


def test_huge_file(tmp_path):
    path = tmp_path / "huge.rexs"
    with open(path, "wb") as fh:       # 1 GB, sparse: refused by its size, not read
        fh.truncate(1 << 30)
    with bounded_work(0.2, "a 1 GB file"):
        code, out, err = cli("import", path)
    assert code == 2 and "larger than 64 MiB" in err and len(err.strip().splitlines()) == 1


def test_missing_relation_target(tmp_path):
    raw = GOOD.replace(b'<ref hint="cylindrical_gear" id="17" role="gear_2"/>',
                       b'<ref hint="cylindrical_gear" id="999" role="gear_2"/>')
    _bad(tmp_path, "m.rexs", raw, "refers to component 999")


def test_stage_gear_on_no_shaft(tmp_path):
    raw = GOOD.replace(b'<ref hint="cylindrical_gear" id="17" role="part"/>',
                       b'<ref hint="external_load" id="41" role="part"/>')
    _bad(tmp_path, "s.rexs", raw, "is on no shaft")


def test_cyclic_relations(tmp_path):
    # stage 20 made to lead from shaft 13 back to shaft 12
    raw = re.sub(rb'<ref hint="shaft" id="14" role="assembly"/>(\s*)'
                 rb'<ref hint="cylindrical_gear" id="18" role="part"/>',
                 rb'<ref hint="shaft" id="12" role="assembly"/>\1'
                 rb'<ref hint="cylindrical_gear" id="18" role="part"/>', GOOD)
    assert raw != GOOD
    path = tmp_path / "c.rexs"
    path.write_bytes(raw)
    with bounded_work(0.2, "a cyclic model"):
        code, out, err = cli("import", path)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "cycle" in err or "drives 2 stages" in err, err


def test_import_writes_the_output_file(tmp_path):
    out = tmp_path / "drive.toml"
    code, _, err = cli("import", DATA / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz", "-o", out)
    assert code == 2 and not out.exists()
    code, _, err = cli("import", DATA / "SEW_3-stage_cylindrical_gearbox_1.0.rexs", "-o", out)
    assert code == 0, err
    code, _, err = cli("run", out, "--format", "json", "-o", tmp_path / "r.json")
    assert code in (0, 1), err


def test_cli_start_up_does_not_import_the_exchange_code():
    import subprocess
    import sys

    code = ("import sys, geardesign.cli_app; "
            "print(sorted(m for m in sys.modules if m.startswith('geardesign.rexs.')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=Path(__file__).parent.parent, check=True).stdout
    assert out.strip() == "['geardesign.rexs.cli']"
