"""Shared test helpers."""

from __future__ import annotations

import math
import os

# as the command line does (geardesign/cli.py): the beam problems are small, and OpenBLAS's
# threads make them slow on a busy machine; read when numpy is first imported
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
from pathlib import Path

import pytest

from geardesign.core.registry import run_data

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"


def pytest_addoption(parser):
    parser.addoption("--update-golden", action="store_true", default=False,
                     help="rewrite specs/*.expected.json from the current code (review the diff!)")


@pytest.fixture
def update_golden(request) -> bool:
    return request.config.getoption("--update-golden")


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
