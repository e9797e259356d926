"""Conventions of the suite itself: no test reads a clock except through the guard against
unbounded work (``tests/conftest.py``, ``bounded_work``), and the README's test count stays
within 10 % of the tests collected."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.conftest import ROOT

TESTS = Path(__file__).resolve().parent
CLOCKS = re.compile(r"\b(perf_counter|process_time|monotonic|time\.time|timeit)\b")


def test_no_test_reads_a_clock():
    """A wall-clock assertion fails on a busy machine: speed goals live in benchmarks/."""
    readers = [f"{p.relative_to(ROOT)}:{n}" for p in sorted(TESTS.rglob("*.py"))
               if p.name not in ("conftest.py", Path(__file__).name)
               for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
               if CLOCKS.search(line.split("#")[0])]
    assert not readers, "use tests.conftest.bounded_work: " + ", ".join(readers)


def _whole_suite(config) -> bool:
    o = config.option
    if o.keyword or o.markexpr or getattr(o, "deselect", None) or getattr(o, "lf", False) \
            or getattr(o, "last_failed", False):
        return False
    targets = {(Path(config.invocation_params.dir) / a.split("::")[0]).resolve()
               for a in config.args}
    return targets <= {ROOT, TESTS}


def test_readme_states_the_number_of_tests(request):
    """The README's "about N tests" within 10 % of the tests collected (checked when the
    whole suite runs, as in CI; a selection cannot count them)."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    m = re.search(r"runs everything \(about ([\d ]+) tests", text)
    assert m, 'README.md: "runs everything (about N tests" not found'
    stated = int(m.group(1).replace(" ", ""))
    if not _whole_suite(request.config):
        pytest.skip("counted only when the whole suite runs")
    collected = request.session.testscollected
    assert abs(collected - stated) <= 0.1 * collected, (
        f"README.md says about {stated} tests, {collected} are collected: update the README")
