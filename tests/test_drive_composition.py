"""The drive composes its spur stages through the typed interface: each spur stage is
solved once per pass (:func:`geardesign.spur.solve.solve`), its values read from the
record, and its report (with the advice of its failed checks) written once, from the last
pass; no whole spur calculation and no JSON document inside the passes."""

import pytest

import geardesign.core.advice as ADVICE
import geardesign.drive.calculator as DC
import geardesign.spur.report as SPUR_REPORT
import geardesign.spur.solve as SPUR_SOLVE
from geardesign.core.registry import run
from geardesign.core.result import Result
from tests.conftest import SPECS


@pytest.fixture
def counted(monkeypatch):
    """Counts of spur solves, spur reports, passes of the stage chain and whole
    documents written while a drive computes."""
    n = dict(solve=0, report=0, passes=0, spur_stages=0, documents=0)
    solve, report, chain = SPUR_SOLVE.solve, SPUR_REPORT.report, DC._run_chain
    document = Result.document

    def solve_(inputs):
        n["solve"] += 1
        return solve(inputs)

    def report_(record):
        n["report"] += 1
        return report(record)

    def chain_(stages, *args):
        n["passes"] += 1
        n["spur_stages"] = sum(1 for st in stages if st[2].get("kind") == "spur")
        return chain(stages, *args)

    def document_(self):
        n["documents"] += 1
        return document(self)

    monkeypatch.setattr(SPUR_SOLVE, "solve", solve_)
    monkeypatch.setattr(SPUR_REPORT, "report", report_)
    monkeypatch.setattr(DC, "_run_chain", chain_)
    monkeypatch.setattr(Result, "document", document_)
    return n


def test_each_spur_stage_is_solved_once_per_pass(counted):
    """Two spur stages, the losses and the heat balance (several passes): spur solves per
    stage per pass = 1, one report per stage, no JSON document written by the drive."""
    res = run(SPECS / "drive_thermal_two_stage.toml")
    n = counted
    assert n["passes"] >= 3 and n["spur_stages"] == 2
    assert n["solve"] == n["spur_stages"] * n["passes"]
    assert n["report"] == n["spur_stages"]
    assert n["documents"] == 0
    assert res.verdict == "pass"


def test_shafts_re_rate_the_iso_stage_once(counted):
    """With the shafts analysed, the ISO 6336 stage is rated once more with the
    misalignment f_sh the shafts give (its report replaces the first, which is never
    written); everything else as above."""
    run(SPECS / "drive_reducer_shafts_keys_thermal.toml")
    n = counted
    assert n["spur_stages"] == 2
    assert n["solve"] == n["spur_stages"] * n["passes"] + 1
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
