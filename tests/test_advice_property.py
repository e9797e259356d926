"""Every advice of every calculator that carries a fix converges in one step: the template
(``geardesign template KIND``, and for the drive also the reducer with shafts, keys and a
heat balance) perturbed into random failing variants; each failed check's printed fix is
written into the spec as printed and the spec run again, and the check passes and no error
check that passed (or that the spec did not have) fails.  A failed
check without a fix says what to change instead (the next lever).  The advised run stays
bounded in CPU time (``bounded_work``)."""

from __future__ import annotations

import copy
import re
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geardesign.core.advice import apply_fix
from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from geardesign.core.result import fix_text
from tests.conftest import bounded_work
from tests.helpers_cli import cli

SPECS = Path(__file__).parent.parent / "specs"

WORST = (1.0, 1.5, 2.0, 3.0)
THINNER = (0.35, 0.5, 0.7, 0.85, 1.0)

# knobs: ("scale", (keys...), factors): the same factor on every key; ("set", key, values);
# ("pick", None, settings): one of the settings ({key: value, ...})
KNOBS: dict[str, list] = {
    "spur": [("scale", ("load.torque1", "load.peak_torque1"), WORST),
             ("scale", ("gear.face_width",), THINNER)],
    "worm": [("scale", ("load.torque2",), (1.0, 2.0, 3.0, 5.0))],
    "planetary": [("scale", ("operation.torque",), (1.0, 3.0, 6.0, 10.0)),
                  ("scale", ("train.face_width",), THINNER)],
    "novikov": [("scale", ("load.torque2",), WORST), ("scale", ("gear.face_width",), THINNER)],
    "bearing": [("scale", ("requirements.life",), (1.0, 3.0, 10.0)),
                ("scale", ("load.spectrum[0].F_r", "load.spectrum[1].F_r"), WORST)],
    "shaft": [("scale", tuple(f"step[{i}].diameter" for i in range(5)), (0.5, 0.6, 0.75, 1.0)),
              ("scale", ("shaft.speed",), (1.0, 5.0, 20.0))],
    "connection": [("scale", ("load.torque",), (1.0, 2.0, 4.0, 8.0)),
                   ("scale", ("key.length",), (0.3, 0.6, 1.0))],
    "geneva": [("scale", ("geneva.roller_diameter",), (1.0, 3.0, 6.0, 12.0)),
               ("set", "drive.rated_power", (None, 0.05, 0.5))],
    "bevel": [("scale", ("load.torque",), WORST), ("scale", ("pair.face_width",), THINNER),
              ("set", "pair.x1", (None, -0.4))],
    "wave_gear": [("scale", ("gear.rim_thickness",), (0.3, 0.5, 1.0)),
                  ("scale", ("load.output_torque",), WORST)],
    "ball_clutch": [("scale", ("operation.torque",), WORST),
                    ("scale", ("spring.preload",), (0.3, 0.6, 1.0, 2.0, 3.0)),
                    ("scale", ("spring.wire_diameter",), (0.7, 0.85, 1.0)),
                    ("scale", ("operation.speed",), (1.0, 4.0, 8.0)),
                    ("set", "safety.socket_angle", (45.0, 70.0, 80.0))],
    "pzdn": [("scale", ("spring[0].torque",), (1.0, 1.3, 2.0)),
             ("scale", ("spring[0].wire_diameter",), (0.75, 0.9, 1.0)),
             ("set", "spring[1].stop_angle", (None, 20.0, 60.0, 200.0)),
             ("set", "spring[1].arbor_diameter", (None, 30.0, 44.0)),
             ("set", "spring[0].ends_fixed_axially", (None, True)),
             ("set", "spring[1].pitch", (None, 4.6, 5.0)),
             ("scale", ("spring[1].coil_diameter",), (0.4, 1.0, 1.3)),
             ("scale", ("coupling_gear.face_width",), (0.3, 0.6, 1.0)),
             ("scale", ("coupling_gear.torque", "coupling_gear.peak_torque"), (1.0, 3.0, 9.0))],
    "epicycle_rim": [("pick", None, ({}, {"planets.count": 4}, {"planets.count": 5},
                                     {"planets.angles": [0.0, 40.0, 201.0]},
                                     {"planets.angles": [0.0, 40.0, 200.0]},
                                     {"planets.angles": [0.0, 100.0, 230.0]},
                                     {"planets.count": 4,
                                      "planets.angles": [0.0, 80.0, 170.0, 275.0]})),
                     ("scale", ("load.bending_stress",), (1.0, 1.3, 1.8))],
    "drive": [("scale", ("stage[1].gear.face_width",), THINNER),
              ("scale", ("load.life_hours",), (1.0, 2.0))],
    "drive_shafts": [
        ("scale", ("load.life_hours",), (1.0, 2.0, 4.0)),
        ("scale", ("shaft[2].step[1].diameter", "shaft[2].step[2].diameter",
                   "shaft[2].step[4].diameter", "shaft[2].step[5].diameter"),
         (0.7, 0.8, 1.0)),
        ("scale", ("shaft[1].step[2].diameter", "shaft[1].step[3].diameter",
                   "shaft[1].step[4].diameter"), (0.7, 0.85, 1.0)),
        ("scale", ("shaft[0].key[0].length",), (0.3, 0.5, 1.0)),
        ("scale", ("shaft[1].key[0].length",), (0.5, 1.0)),
        ("set", "load.torque", (None, 1400.0)),
        ("pick", None, ({}, {"thermal.ambient": 45.0, "thermal.max_oil_temperature": 55.0},
                        {"thermal.ambient": 50.0, "thermal.max_oil_temperature": 60.0}))],
}

CPU = {"drive": 0.2, "drive_shafts": 0.3, "epicycle_rim": 0.1}
"""CPU seconds of an advised run measured on the development machine (bounded_work: 20
times, at least 2 s); 0.05 s for the others."""

NEXT_LEVER = re.compile(
    r"\b(use|increase|reduce|raise|lower|choose|give|set|larger|thicker|smaller|stiffen|"
    r"spread|fewer|more|longer|shorter|move|add|take|change|harden|see its report|"
    r"scale|select|thin|widen|replace)\b", re.I)
"""A message that says what to change."""


def _base(kind: str) -> dict:
    if kind == "drive_shafts":
        return tomllib.loads((SPECS / "drive_reducer_shafts_keys_thermal.toml").read_text(
            encoding="utf-8"))
    code, out, err = cli("template", kind)
    assert code == 0, err
    data = tomllib.loads(out)
    if kind == "pzdn":       # the start-up simulation (half a second a run) is not the springs'
        data.pop("startup", None)
    return data


_BASES: dict[str, dict] = {}


def _get(data: dict, key: str):
    node = data
    for part in re.finditer(r"([^.\[\]]+)(?:\[(\d+)\])?", key):
        name, index = part.groups()
        if not isinstance(node, dict) or name not in node:
            return None
        node = node[name] if index is None else node[name][int(index)]
    return node


def _variant(kind: str, draw) -> dict:
    if kind not in _BASES:
        _BASES[kind] = _base(kind)
    data = copy.deepcopy(_BASES[kind])
    fix = []
    for how, keys, values in KNOBS[kind]:
        v = draw(st.sampled_from(values))
        if how == "pick":
            fix += list(v.items())
            continue
        if how == "set":
            if v is not None:
                fix.append((keys, v))
            continue
        for key in keys:
            x = _get(data, key)
            if isinstance(x, (int, float)) and not isinstance(x, bool) and v != 1.0:
                fix.append((key, max(1, round(x * v)) if isinstance(x, int) else
                            round(x * v, 2)))
    return apply_fix(data, fix)


SLOW = ("drive_shafts", "epicycle_rim")
"""Kinds whose rating takes a tenth of a second or more (a drive with its shafts and heat
balance, a rim with Floquet bands): fewer examples."""


def _follow_every_fix(kind: str, draw) -> None:
    spec = _variant(kind, draw)
    try:
        with bounded_work(CPU.get(kind, 0.05), f"{kind}: rating with the advice search"):
            doc = run_data(spec).document()
    except InputError:           # refused input: nothing to advise
        return
    before = {c["code"]: c["passed"] for c in doc["checks"] if c["severity"] == "error"}
    for c in doc["checks"]:
        if c["passed"] or c["severity"] != "error":
            continue
        if "fix" not in c:
            assert NEXT_LEVER.search(c["message"]), (kind, c["code"], c["message"])
            continue
        # the message prints the fix: "set KEY = VALUE", or its values in the advice's words
        # ("increase the face width to at least 52.4 mm")
        assert fix_text(list(c["fix"].items())) in c["message"] or all(
            fix_text([("", v)])[3:] in c["message"] for v in c["fix"].values()), c["message"]
        again = {x["code"]: x for x in run_data(apply_fix(spec, c["fix"])).document()["checks"]}
        assert c["code"] in again and again[c["code"]]["passed"], (
            kind, c["code"], c["fix"], again.get(c["code"], {}).get("message"))
        # and no error check that passed (or that the spec did not have) fails now
        broken = [k for k, x in again.items() if x["severity"] == "error" and not x["passed"]
                  and before.get(k, True)]
        assert not broken, (kind, c["code"], c["fix"], broken)


@pytest.mark.parametrize("kind", sorted(set(KNOBS) - set(SLOW)))
@settings(max_examples=6, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(st.data())
def test_every_printed_fix_passes_when_followed(kind, data):
    _follow_every_fix(kind, data.draw)


@pytest.mark.parametrize("kind", SLOW)
@settings(max_examples=3, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(st.data())
def test_every_printed_fix_passes_when_followed_slow_kinds(kind, data):
    _follow_every_fix(kind, data.draw)
