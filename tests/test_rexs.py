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
from geardesign.core.errors import InputError
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


def _imported_and_run(name: str):
    """Import a public model and run the spec (exit 0 or 1); every component type of the
    file is read or listed as not imported.  Returns the import and the results."""
    model = read_model(DATA / name)
    imp = import_model(model, name)
    res = _run(imp.text)
    assert res.exit_code in (0, 1)
    types = {c.type for c in model.components.values()}
    assert types == imp.read_types | set(imp.not_imported), (
        types ^ (imp.read_types | set(imp.not_imported)))
    assert "# Not imported" in imp.text
    return imp, res.document()["results"]


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_public_model_imports_runs_and_reproduces_stated_geometry(name):
    imp, results = _imported_and_run(name)
    stages = results["stage_reports"]
    assert [s["component"] for s in imp.stages]
    # every centre distance the file states, at its printed precision (one decimal)
    stated = PUBLIC[name][1]
    assert len(stages) == len(stated)
    for st, a in zip(stages, stated):
        assert round(st["results"]["geometry"]["a_w"], 1) == pytest.approx(a)


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


STAGE_MODELS = {
    # file: (program, stated value → our result's (section, key))
    "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz": ("FVA Workbench", {
        "a_w": ("sun_planet", "a_w"), "a_w_ring": ("planet_ring", "a_w")}),
    "FVA_worm_stage_1-4.rexs": ("FVA Workbench", {
        "a_w": ("geometry", "a_w"), "d1": ("geometry", "d1"), "d_a1": ("geometry", "d_a1"),
        "d_f1": ("geometry", "d_f1"), "gamma": ("geometry", "gamma"),
        "d2": ("geometry", "d2"), "d_a2": ("geometry", "d_a2"), "d_f2": ("geometry", "d_f2")}),
}


def _decimals(x: float) -> int:
    """Decimals of a number as the file prints it (36.0: 1, 12.5288: 4)."""
    text = repr(float(x))
    return len(text.split(".")[1]) if "." in text and "e" not in text else 0


@pytest.mark.parametrize("name", sorted(STAGE_MODELS))
def test_planetary_and_worm_models_import_run_and_reproduce_stated_geometry(name):
    imp, results = _imported_and_run(name)
    where = STAGE_MODELS[name][1]
    stated = imp.stages[0]["stated"]
    assert set(stated) == set(where)          # every value the file states is compared
    for key, (value, source) in stated.items():
        sec, k = where[key]
        assert round(results[sec][k], _decimals(value)) == pytest.approx(value), (key, source)


def test_worm_model_is_the_worm_spec_it_states():
    text = import_model(read_model(DATA / "FVA_worm_stage_1-4.rexs"), "m").text
    spec = tomllib.loads(text)
    # FVA_worm_stage_1-4.rexs: m_x = 4, d1 = 36 (q = 9), z = 2/41, a = 100, ZI, T2 = 300 N·m
    # on the wheel shaft, n1 = 1000 min^-1, 100 000 h
    assert spec["gear"] == {"module": 4.0, "diameter_factor": 9.0, "z1": 2, "z2": 41,
                            "center_distance": 100.0, "worm_type": "ZI", "hand": "left",
                            "face_width": 30.0, "worm_length": 160.0}
    assert spec["load"] == {"torque2": 300.0, "speed1": 1000.0, "life": 100000.0}
    assert "16MnCr5" in text          # the wheel's steel, listed as not imported


def test_planetary_model_is_the_2kh_train_it_states():
    spec = tomllib.loads(import_model(read_model(
        DATA / "FVA_Planetary_stage_-_Minus_gearing_1.1.rexsz"), "m").text)
    # sun 17, planets 3 × 22, ring 61, m = 4, b = 50, a = 78; sun in (1591.55 N·m,
    # 1500 min^-1), carrier out (its shafts carry the other load), ring held
    assert spec["teeth"] == {"sun": 17, "planet": 22, "ring": 61}
    assert spec["train"] == {"planets": 3, "module": 4.0, "face_width": 50.0,
                             "center_distance": 78.0}
    assert (spec["operation"]["fixed"], spec["operation"]["input"],
            spec["operation"]["output"]) == ("ring", "sun", "carrier")
    assert spec["operation"]["torque"] == pytest.approx(1591.5494309189535, rel=1e-9)


def test_a_chain_with_planetary_stages_of_another_program_is_a_drive(tmp_path):
    """Without the stage order geardesign writes, the chain is ordered along the power flow
    (the planetary stage first: the input torque is on its sun's shaft)."""
    text = export_spec(SPECS / "drive_planetary_spur.toml", "xml")
    foreign = re.sub(r'\s*<attribute id="custom_geardesign__drive__order"[^<]*</attribute>', "",
                     text)
    path, out = tmp_path / "chain.rexs", tmp_path / "chain.toml"
    path.write_text(foreign, encoding="utf-8")
    code, _, err = cli("import", path, "-o", out)
    assert code == 0, err
    spec = tomllib.loads(out.read_text(encoding="utf-8"))
    assert [s["kind"] for s in spec["stage"]] == ["planetary", "spur"]
    assert spec["stage"][0]["operation"]["input"] == "sun"
    assert spec["stage"][0]["operation"]["output"] == "carrier"
    code, _, err = cli("run", out, "--format", "json", "-o", tmp_path / "r.json")
    assert code in (0, 1), err


def test_bearings_the_drive_cannot_express_are_said():
    # Bearinx: the input shaft 12 rests in the output shaft 14 (bearing 36)
    text = import_model(read_model(DATA / "FVA-Industriegetriebe_2stufig_1-4.rexs"), "m").text
    assert re.search(r"bearing 36 .*between shaft 12 and shaft 14", text)
    # SEW: a third bearing (NUP 204) on the second intermediate shaft
    text = import_model(read_model(DATA / "SEW_3-stage_cylindrical_gearbox_1.0.rexs"), "m").text
    assert "a third bearing on shaft" in text and "two supports" in text


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
    code, out, err = cli("export", SPECS / "connection_key.toml")
    assert code == 2 and "export writes spur, planetary, worm, bevel, drive specs" in err
    assert len(err.strip().splitlines()) == 1


def test_shaft_loads_and_keys_are_exported_and_read_back(tmp_path):
    spec = (SPECS / "drive_two_stage_reducer.toml").read_text(encoding="utf-8")
    spec += ("[[shaft.load]]\nname = \"chain sprocket\"\nposition = 260.0\n"
             "force = 4000.0\nangle = 30.0\naxial = 150.0\n")
    path = tmp_path / "drive.toml"
    path.write_text(spec, encoding="utf-8")
    model = parse(export_spec(path, "json").encode())
    assert check_against_database(export_spec(path, "xml")) == []
    load = next(c for c in model.of_type("external_load") if c.name == "chain sprocket")
    # F_v = F cos 30°, F_w = F sin 30° (the drive's x-y plane is REXS's v-w plane)
    assert float(load.attributes["force_v_direction"].value) == pytest.approx(
        4000.0 * math.cos(math.radians(30.0)), rel=1e-12)
    assert float(load.attributes["force_u_direction"].value) == 150.0
    back = tomllib.loads(import_model(model, "m").text)
    shaft = back["shaft"][2]
    assert shaft["load"][0]["position"] == 260.0
    assert shaft["load"][0]["force"] == pytest.approx(4000.0, rel=1e-9)
    assert shaft["load"][0]["angle"] == pytest.approx(30.0, abs=1e-9)
    assert back["shaft"][2]["load"][0]["name"] == "chain sprocket"
    # keys: REXS 1.5 has no shaft-hub connection; the spec's tables come back as written
    name = "drive_reducer_shafts_keys_thermal.toml"
    original = tomllib.loads((SPECS / name).read_text(encoding="utf-8"))
    back = tomllib.loads(import_model(parse(export_spec(SPECS / name).encode()), name).text)
    assert [s.get("key") for s in back["shaft"]] == [s.get("key") for s in original["shaft"]]


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


def _kind(path: Path) -> str | None:
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    return None if "sweep" in data else data.get("kind")


ROUND_TRIP = sorted(p.name for p in SPECS.glob("*.toml")
                    if _kind(p) in ("spur", "planetary", "worm", "bevel", "drive"))
"""Every example spec of the kinds export writes (a spur spec with [sweep] is a sweep)."""


JSON_TOO = ("spur_helical_carburized_spectrum.toml", "drive_planetary_spur.toml",
            "worm_selflocking_hoist.toml", "planetary_3k_high_ratio.toml",
            "bevel_spiral_iso.toml", "drive_bevel_helical.toml")
"""One spec of each kind goes through JSON as well."""


@pytest.mark.parametrize("name, fmt", [(n, "xml") for n in ROUND_TRIP]
                         + [(n, "json") for n in JSON_TOO])
def test_round_trip_gives_the_original_results(name, fmt):
    original = registry.run(SPECS / name).document()
    text = export_spec(SPECS / name, fmt)
    assert check_against_database(text) == []
    assert parse(text.encode()).version == "1.5"
    back = _run(import_model(parse(text.encode()), name).text).document()
    assert back["kind"] == original["kind"]
    assert _close(original["results"], back["results"]) == []
    assert original["verdict"] == back["verdict"]
    assert ([(c["code"], c["passed"]) for c in original["checks"]]
            == [(c["code"], c["passed"]) for c in back["checks"]])


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
    bad = tmp_path / "bad.rexs"
    bad.write_bytes(b"<html></html>")
    code, _, err = cli("import", bad, "-o", out)
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


# ----------------------------------------------------------------------- damaged models

_STAGE_MODELS_JSON = {name: json.loads(export_spec(SPECS / name, "json"))
                      for name in ("planetary_2kh_reducer.toml", "worm_single_start_reducer.toml",
                                   "drive_worm_spur.toml", "bevel_spiral_iso.toml",
                                   "drive_bevel_helical.toml")}


@pytest.mark.parametrize("name", sorted(_STAGE_MODELS_JSON))
def test_a_damaged_stage_model_is_one_line_or_a_spec(name):
    """An exported planetary, worm or bevel model with one attribute or one relation dropped, or one
    value replaced by text: the import writes a spec or refuses in one line (InputError),
    never an exception of another kind; the spec runs or is refused the same way."""
    from hypothesis import given, settings, strategies as st

    from geardesign.core.errors import InputError

    base = _STAGE_MODELS_JSON[name]["model"]
    n_attr = sum(len(c["attributes"]) for c in base["components"])

    @settings(max_examples=40, deadline=None, derandomize=True)
    @given(st.sampled_from(["attribute", "relation", "text"]),
           st.integers(0, max(n_attr, len(base["relations"])) - 1))
    def check(what, k):
        doc = json.loads(json.dumps({"model": base}))
        m = doc["model"]
        attrs = [(c, a) for c in m["components"] for a in c["attributes"]]
        if what == "relation":
            del m["relations"][k % len(m["relations"])]
        else:
            c, a = attrs[k % len(attrs)]
            if what == "attribute":
                c["attributes"].remove(a)
            else:
                key = next(x for x in a if x not in ("id", "unit"))
                a[key] = "not a value"
        try:
            imp = import_model(parse(json.dumps(doc).encode()), name)
        except InputError:
            return
        try:
            _run(imp.text)
        except InputError:
            pass

    check()


# ----------------------------------------------------------------------- bevel stages

def _without_custom(text: str) -> bytes:
    """A model as another program would write it: the custom attributes dropped."""
    doc = json.loads(text)
    for c in doc["model"]["components"]:
        c["attributes"] = [a for a in c["attributes"] if not a["id"].startswith("custom_")]
    return json.dumps(doc).encode()


@pytest.mark.parametrize("name", sorted(p.name for p in SPECS.glob("bevel_*.toml")))
def test_a_bevel_stage_of_another_program_imports_from_standard_attributes(name):
    """The bevel model without geardesign's custom attributes is read from the standard
    bevel_stage/bevel_gear attributes alone: it runs, every cone dimension it states is
    reproduced at the precision written, and its component types are read or listed."""
    model = parse(_without_custom(export_spec(SPECS / name, "json")))
    imp = import_model(model, name)
    assert 'kind = "bevel"' in imp.text
    doc = _run(imp.text).document()
    stated = imp.stages[0]["stated"]
    assert {"d_e1", "d_e2", "d_m1", "delta1", "delta_a2", "R_e", "R_m"} <= set(stated)
    for key, (value, source) in stated.items():
        assert doc["results"]["geometry"][key] == pytest.approx(value, rel=1e-9), (key, source)
    types = {c.type for c in model.components.values()}
    assert types == set(imp.read_types) | set(imp.not_imported)


def test_a_bevel_model_whose_gears_are_on_no_shaft_is_one_line():
    doc = json.loads(export_spec(SPECS / "bevel_spiral_iso.toml", "json"))
    m = doc["model"]
    gears = {c["id"] for c in m["components"] if c["type"] == "bevel_gear"}
    m["relations"] = [r for r in m["relations"] if not (
        r["type"] == "assembly" and any(ref["id"] in gears for ref in r["refs"]))]
    with pytest.raises(InputError) as err:
        import_model(parse(_without_custom(json.dumps(doc))), "m")
    assert "on no shaft" in str(err.value) and "\n" not in str(err.value)


# ------------------------------------------------- chains with planetary, worm, bevel stages

CHAINS = ("drive_planetary_spur.toml", "drive_worm_spur.toml", "drive_bevel_helical.toml")
"""Drives whose chain holds a planetary, worm or bevel stage."""


@pytest.mark.parametrize("name", CHAINS)
def test_a_chain_of_another_program_imports_as_drive_stages(name):
    """The drive's model without geardesign's custom attributes (as another program writes
    it: no stage order, no spec keys) is ordered along the power flow from the input shaft
    and imported as a drive of the same stage kinds; it runs, and every geometric value
    the model states of the planetary, worm and bevel stages is reproduced."""
    model = parse(_without_custom(export_spec(SPECS / name, "json")))
    imp = import_model(model, name)
    data = tomllib.loads(imp.text)
    original = registry.run(SPECS / name).document()
    kinds = [s["kind"] for s in original["results"]["stage_reports"]]
    assert data["kind"] == "drive" and [s["kind"] for s in data["stage"]] == kinds
    doc = _run(imp.text).document()
    reports = doc["results"]["stage_reports"]
    sections = {"planetary": {"a_w": ("sun_planet", "a_w"), "a_w_ring": ("planet_ring", "a_w")},
                "worm": dict((k, ("geometry", k)) for k in
                             ("a_w", "d1", "d_a1", "d_f1", "gamma", "d2", "d_a2", "d_f2", "u"))}
    for s in imp.stages:
        rep = reports[s["stage"] - 1]
        for key, (value, source) in s["stated"].items():
            if rep["kind"] == "spur" or key == "d_a_ring":
                # spur: compared by the chain import's own tests; the ring's tip diameter
                # follows from the spec's tip_shortening and [cutter], which REXS 1.5 has
                # no attribute for (docs/rexs.md)
                continue
            default = ("gears" if rep["kind"] == "planetary" else "geometry", key)
            sec, k = sections.get(rep["kind"], {}).get(key, default)
            assert abs(rep["results"][sec][k]) == pytest.approx(abs(value), rel=1e-6), (
                rep["kind"], key, source)
    types = {c.type for c in model.components.values()}
    assert types == set(imp.read_types) | set(imp.not_imported)
