"""The shared spec machinery: arrays, arrays of tables, defaults, template, schema."""

import json
import tomllib

import pytest

from geardesign.core.errors import InputError
from geardesign.core.spec import (
    Field, SpecSchema, Table, TableList, iter_fields, json_schema, template, validate)

SCHEMA = SpecSchema("x", "test", (
    Table("rim", "rim", (
        Field("angles", "array", "planet angles", "deg", items="number", minimum=0, lt=360,
              min_items=1, max_items=12, example=[0.0, 120.0, 240.0]),
        Field("mode", "string", "mode", default="a", choices=("a", "b")),
    )),
    TableList("blocks", "load blocks", Table("blocks", "block", (
        Field("torque", "number", "torque", "N·m", gt=0, example=100.0),
        Field("share", "number", "time share", gt=0, maximum=1, example=1.0),
    )), required=False, examples=({"torque": 100.0, "share": 0.6},
                                  {"torque": 50.0, "share": 0.4})),
))


def problems(data):
    with pytest.raises(InputError) as exc:
        validate(SCHEMA, data)
    return [p.line("f.toml") for p in exc.value.problems]


def test_array_and_table_list_rules():
    assert problems({"kind": "x", "rim": {"angles": [0, 120, 400]},
                     "blocks": [{"torque": -1, "share": 1}]}) == [
        "f.toml: rim.angles = [0, 120, 400]: must be a list of 1 to 12 numbers >= 0 and < 360 "
        "(deg)",
        "f.toml: blocks[0].torque = -1: must be a number >= 1e-06 and <= 1000000000 (N·m)"]
    assert problems({"kind": "x", "rim": {"angles": []}, "blocks": 5}) == [
        "f.toml: rim.angles = []: must be a list of 1 to 12 numbers >= 0 and < 360 (deg)",
        "f.toml: blocks = 5: must be 1 to 1000 [[blocks]] tables (load blocks)"]


def test_defaults_and_echo():
    v = validate(SCHEMA, {"kind": "x", "rim": {"angles": [0, 90]},
                          "blocks": [{"torque": 1, "share": 1}]})
    assert v.data["rim"] == {"angles": [0.0, 90.0], "mode": "a"}
    assert v.assumed == ["rim.mode"]
    assert [k for k, _, _ in iter_fields(SCHEMA.root, v.data)][-2:] == [
        "blocks[0].torque", "blocks[0].share"]


def test_template_parses_validates_and_matches_schema():
    text = template(SCHEMA)
    data = tomllib.loads(text)
    assert data["blocks"] == [{"torque": 100.0, "share": 0.6}, {"torque": 50.0, "share": 0.4}]
    validate(SCHEMA, data)
    js = json_schema(SCHEMA)
    assert js["properties"]["rim"]["properties"]["angles"]["x-unit"] == "deg"
    assert js["properties"]["blocks"]["type"] == "array"
    jsonschema = pytest.importorskip("jsonschema")
    jsonschema.validate(data, js)
    json.dumps(js)
