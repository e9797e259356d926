"""Helpers of the bearing reference tests."""

from __future__ import annotations

from geardesign.core.registry import run_data
from tests.conftest import flat


def bearing(method: str, bearing: dict, load: dict, **tables) -> dict:
    """Flat result values of a bearing spec given as tables."""
    data = {"kind": "bearing", "method": method, "bearing": dict(bearing), "load": dict(load)}
    data.update(tables)
    return flat(run_data(data).document())


def document(method: str, bearing: dict, load: dict, **tables) -> dict:
    data = {"kind": "bearing", "method": method, "bearing": dict(bearing), "load": dict(load)}
    data.update(tables)
    return run_data(data).document()
