"""Helpers of the planetary reference tests."""

from __future__ import annotations

from geardesign.core.registry import run_data


def planetary(data: dict) -> dict:
    """The JSON document of a planetary spec given as a dict (without ``kind``)."""
    return run_data({"kind": "planetary", **data}).document()
