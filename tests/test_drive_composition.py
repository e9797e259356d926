"""The drive composes its stages through the typed interface: each stage (spur, worm,
Novikov, planetary) is solved once per pass by its calculator's ``solve()``, its values
read from the record, and its report (with the advice of its failed checks) written once,
from the last pass; no whole calculation and no JSON document inside the passes."""

import pytest

import geardesign.core.advice as ADVICE
import geardesign.drive.calculator as DC
import geardesign.spur.calculator as SPUR_CALCULATOR
import geardesign.spur.solve as SPUR_SOLVE
from geardesign.core.registry import run
from geardesign.core.result import Result
from tests.conftest import SPECS


@pytest.fixture
def counted(monkeypatch):
    """Counts of spur solves, spur reports, passes of the stage chain (``probes``: the
    probe passes among them, which take a spur stage's ratio from its geometry, unrated)
    and whole documents written while a drive computes."""
    n = dict(solve=0, report=0, passes=0, probes=0, spur_stages=0, documents=0)
    solve, report, chain = SPUR_SOLVE.solve, SPUR_CALCULATOR.report, DC._run_chain
    document = Result.document

    def solve_(inputs):
        n["solve"] += 1
        return solve(inputs)

    def report_(record):
        n["report"] += 1
        return report(record)

    def chain_(stages, *args):
        n["passes"] += 1
        n["probes"] += bool(args[3:4] and args[3])
        n["spur_stages"] = sum(1 for st in stages if st[2].get("kind") == "spur")
        return chain(stages, *args)

    def document_(self):
        n["documents"] += 1
        return document(self)

    monkeypatch.setattr(SPUR_SOLVE, "solve", solve_)
    monkeypatch.setattr(SPUR_CALCULATOR, "report", report_)
    monkeypatch.setattr(DC, "_run_chain", chain_)
    monkeypatch.setattr(Result, "document", document_)
    return n


def test_each_spur_stage_is_solved_once_per_pass(counted):
    """Two spur stages, the losses and the heat balance (several passes): spur solves per
    stage per rated pass = 1, none in the probe pass and the passes of the heat balance
    (a spur stage's ratio and mesh forces from its geometry), so each stage is rated once;
    one report per stage, no JSON document written by the drive."""
    res = run(SPECS / "drive_thermal_two_stage.toml")
    n = counted
    assert n["passes"] >= 3 and n["spur_stages"] == 2
    assert n["passes"] - n["probes"] == 1
    assert n["solve"] == n["spur_stages"] * (n["passes"] - n["probes"])
    assert n["report"] == n["spur_stages"]
    assert n["documents"] == 0
    assert res.verdict == "pass"


def test_shafts_re_rate_the_iso_stage_once(counted):
    """With the shafts analysed, the ISO 6336 stage is rated once more with the
    misalignment f_sh the shafts give (its report replaces the first, which is never
    written); the stages are rated once, after the passes of the heat balance (stage 1's
    scuffing at the last sump temperature); everything else as above."""
    run(SPECS / "drive_reducer_shafts_keys_thermal.toml")
    n = counted
    assert n["spur_stages"] == 2
    assert n["passes"] - n["probes"] == 1
    assert n["solve"] == n["spur_stages"] * (n["passes"] - n["probes"]) + 1
    assert n["report"] == n["spur_stages"]


def test_the_advice_is_not_searched_inside_the_passes(counted, monkeypatch):
    """A failing stage gets the advice of its failed checks once, in its final report;
    the re-ratings of that search and of the drive's own advice write no advice."""
    calls = {"top": 0, "nested": 0}
    advise = ADVICE.advise

    def advise_(calc, spec, res, levers):
        calls["nested" if ADVICE.rerating() else "top"] += 1
        return advise(calc, spec, res, levers)

    monkeypatch.setattr(ADVICE, "advise", advise_)
    res = run(SPECS / "drive_two_stage_reducer.toml")
    assert calls["nested"] == 0
    assert calls["top"] <= counted["spur_stages"] + 1     # the stages', the drive's
    assert res.kind == "drive"


STAGE_KINDS = {"worm": ("worm_single_start_reducer.toml", "geardesign.worm.solve"),
               "novikov": ("novikov_high_speed.toml", "geardesign.novikov.solve"),
               "planetary": ("planetary_2kh_reducer.toml", "geardesign.planetary.solve"),
               "spur": (None, "geardesign.spur.solve")}
"""Each stage kind of a drive: a stage spec of it and the module of its typed ``solve``."""

SPUR_STAGE = """
[[stage]]
name = "spur stage"
kind = "spur"
[stage.gear]
module = 5.0
z1 = 25
z2 = 80
face_width = 90.0
accuracy_grade = 7
bearing_scheme = 5
[stage.material.pinion]
grade = "40KhN"
treatment = "improved"
hardness_HB = 300.0
[stage.material.wheel]
grade = "40Kh"
treatment = "improved"
hardness_HB = 270.0
"""


@pytest.mark.parametrize("kind", ["worm", "novikov", "planetary"])
def test_every_stage_kind_is_solved_once_per_pass(kind, tmp_path, monkeypatch, counted):
    """A stage of each kind and a spur stage, rated for the machine's torque (two passes:
    the ratios, then the torque carried back): each stage's calculator ``solve()`` runs
    once per pass, from typed inputs, but the spur stage's in the probe pass (its ratio
    and efficiency need no rating); the stage's report is written once, and no JSON
    document inside the drive."""
    import importlib
    import shutil

    solves = {k: 0 for k in STAGE_KINDS}
    for k, (_, module) in STAGE_KINDS.items():
        mod = importlib.import_module(module)
        original = mod.solve if k != "spur" else SPUR_SOLVE.solve

        def solve_(inputs, k=k, original=original):
            solves[k] += 1
            return original(inputs)

        if k != "spur":
            monkeypatch.setattr(mod, "solve", solve_)
    name = STAGE_KINDS[kind][0]
    shutil.copy(SPECS / name, tmp_path / name)
    spec = tmp_path / "drive.toml"
    spec.write_text(f"""kind = "drive"
[motor]
power = 15.0
speed = 1450.0
[load]
torque = 300.0
life_hours = 10000.0
[[stage]]
name = "{kind} stage"
file = "{name}"
""" + SPUR_STAGE, encoding="utf-8")
    res = run(spec)
    n = counted
    assert n["passes"] == 2 and n["probes"] == 1 and n["spur_stages"] == 1
    assert solves[kind] == n["passes"]             # this kind: once per pass
    assert n["solve"] == n["passes"] - n["probes"]  # the spur stage: once per rated pass
    assert n["report"] == 1 and n["documents"] == 0
    assert [p[2].kind for p in res.parts if p[0] == "stage_reports"] == [kind, "spur"]


def test_specs_are_validated_once_per_run(monkeypatch):
    """The bearings of the heat balance's passes are rated through ``bearing.solve`` from
    typed inputs, their specs validated once per run (and once more with the drive's oil
    for their reports); a spur stage's spec once (its loads, the shafts' f_sh and the oil
    temperature of its scuffing rating change between passes), not once per pass."""
    import geardesign.core.registry as REG

    kinds: dict = {}
    validate = REG.validate_partial

    def validate_(schema, data, *args, **kwargs):
        kinds[schema.kind] = kinds.get(schema.kind, 0) + 1
        return validate(schema, data, *args, **kwargs)

    monkeypatch.setattr(REG, "validate_partial", validate_)
    res = run(SPECS / "drive_reducer_shafts_keys_thermal.toml")
    bearings = sum(1 for p in res.parts if p[0] == "bearing_reports")
    assert bearings == 6
    assert kinds["bearing"] == 2 * bearings
    assert kinds["spur"] == 2 + 1       # each stage once; the GOST stage's ISO K_Hβ with f_sh


@pytest.mark.parametrize("name", ["drive_reducer_shafts_keys_thermal.toml",
                                  "drive_worm_spur.toml", "drive_planetary_spur.toml"])
def test_reusing_a_validated_spec_changes_nothing(name, monkeypatch):
    """A stage or bearing spec reused across passes (:mod:`geardesign.drive.reuse`) gives
    the document that validating it again in every pass gives."""
    import geardesign.drive.reuse as REUSE

    reused = run(SPECS / name).document()
    monkeypatch.setattr(REUSE, "reloaded", lambda *args, **kwargs: None)
    assert run(SPECS / name).document() == reused


@pytest.mark.parametrize("name", ["drive_reducer_shafts_keys_thermal.toml",
                                  "drive_thermal_two_stage.toml"])
def test_unrated_passes_of_the_heat_balance_change_nothing(name, monkeypatch):
    """The passes of the heat balance take a spur stage's ratio and mesh forces from its
    geometry, unrated, and rate the stages once after them: the document is the one that
    rating every stage in every pass gives, to the last digit."""
    light = run(SPECS / name).document()
    monkeypatch.setitem(DC.PASSES, "light", {})
    assert run(SPECS / name).document() == light


def test_each_shaft_is_analysed_once_after_the_passes(counted, monkeypatch):
    """The shafts' results do not feed back into the passes (their f_sh re-rates the ISO
    stage once, after them): each shaft with steps is analysed once per run, after the
    last pass of the chain; each pass of the heat balance rates every bearing once
    through its typed interface; the chain runs once per pass of the heat balance
    (unrated) after the first, once more for the ratios (the machine's torque is given)
    and once, rated, at the efficiencies of the last pass (stage 1's scuffing at the sump
    temperature of the last balance)."""
    import geardesign.drive.shaft_analysis as SA
    import geardesign.drive.shaft_loads as SL

    at_pass: list = []
    rated = {"bearings": 0}
    solve, rate = SA.solve, SL.rate_bearing

    def solve_(inputs):
        at_pass.append(counted["passes"])
        return solve(inputs)

    def rate_(case, memo):
        rated["bearings"] += 1
        return rate(case, memo)

    monkeypatch.setattr(SA, "solve", solve_)
    monkeypatch.setattr(SL, "rate_bearing", rate_)
    res = run(SPECS / "drive_reducer_shafts_keys_thermal.toml")
    shafts = sum(1 for p in res.parts if p[0] == "shaft_reports")
    bearings = sum(1 for p in res.parts if p[0] == "bearing_reports")
    passes = next(r.value for r in res.section("thermal", "").rows if r.key == "passes")
    assert shafts == 3 and len(at_pass) == shafts
    assert set(at_pass) == {counted["passes"]}          # after the last pass
    assert rated["bearings"] == bearings * passes
    assert any(c.code == "SCUFFING_OIL_1" for c in res.checks)
    assert counted["passes"] == passes + 2
