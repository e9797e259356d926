"""Shared test helpers."""

from __future__ import annotations

import math
import os
import time
from contextlib import contextmanager

# as the command line does (geardesign/cli.py): the beam problems are small, and OpenBLAS's
# threads make them slow on a busy machine; read when numpy is first imported
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
from pathlib import Path

import pytest
from hypothesis import settings

from geardesign.core.registry import run_data

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"

# Hypothesis: in CI (the environment variable CI set, as .ci/run and the usual CI services
# do) every property test draws the same examples on every run, so a red run is reproduced
# by running it again; locally the examples are random (and failures are kept in the
# .hypothesis database). HYPOTHESIS_PROFILE=ci selects the CI profile by hand.
settings.register_profile("ci", derandomize=True, database=None, print_blob=True)
settings.register_profile("dev", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if os.environ.get("CI")
                                                               else "dev"))

GUARD_FACTOR = 20.0
"""A time bound that guards against unbounded work is this many times the figure measured
on the development machine: it fails on a runaway loop or a quadratic cost, never on a busy
or slow machine.  Speed goals are in ``benchmarks/`` (their figures in the docs)."""

GUARD_FLOOR = 2.0
"""No guard is tighter than this many seconds of CPU time (a figure of a few hundredths of a
second is within the start-up noise of an interpreter on a slow machine)."""


@contextmanager
def bounded_work(measured_s: float, what: str = "the block"):
    """Fail when the block takes more than :data:`GUARD_FACTOR` × ``measured_s`` seconds (at
    least :data:`GUARD_FLOOR`) of this process's CPU time (``measured_s``: the figure of the
    development machine).  CPU time, not the wall clock: another process keeping the core
    busy does not count, a runaway loop does.  The only clock a test may read
    (``tests/test_suite_conventions.py``)."""
    t0 = time.process_time()
    yield
    elapsed = time.process_time() - t0
    bound = max(GUARD_FACTOR * measured_s, GUARD_FLOOR)
    assert elapsed < bound, (
        f"{what} took {elapsed:.2f} s of CPU time, more than {bound:g} s ({GUARD_FACTOR:g} × "
        f"the {measured_s} s measured): unbounded work?")


def pytest_addoption(parser):
    parser.addoption("--update-golden", action="store_true", default=False,
                     help="rewrite specs/*.expected.json from the current code (review the diff!)")
    parser.addoption("--update-readme", action="store_true", default=False,
                     help="rewrite the README tour's outputs from real runs (review the diff!)")


@pytest.fixture
def update_golden(request) -> bool:
    return request.config.getoption("--update-golden")


@pytest.fixture
def update_readme(request) -> bool:
    return request.config.getoption("--update-readme")


def spur(gear: dict, rack: dict | None = None, load: dict | None = None) -> dict:
    """The JSON document of a spur spec given as tables."""
    data = {"kind": "spur", "gear": dict(gear)}
    if rack:
        data["rack"] = rack
    if load:
        data["load"] = load
    return run_data(data).document()


def flat(doc: dict) -> dict:
    """All result values of a document by their key (keys are unique across sections)."""
    out = {}
    for section in doc["results"].values():
        out.update(section)
    return out


def dms(deg: float, minutes: float = 0.0, seconds: float = 0.0) -> float:
    """Degrees from degrees, minutes and seconds."""
    return deg + minutes / 60.0 + seconds / 3600.0


def assert_ref(actual: float, expected: float, tol: float, what: str) -> None:
    assert math.isfinite(actual), f"{what}: not finite"
    assert abs(actual - expected) <= tol, (
        f"{what}: computed {actual!r}, published {expected!r}, tolerance ±{tol}")
