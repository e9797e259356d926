"""A whole drive: motor, stages (each computed by its own calculator), shafts on two
bearings and their bearings' lives.  Modules: :mod:`.stages` (stage adapters),
:mod:`.shafts` (statics), :mod:`.split` (ratio split), :mod:`.spec`, :mod:`.calculator`."""

from __future__ import annotations

from functools import lru_cache


@lru_cache(maxsize=1)
def _calculator():
    from geardesign.core.registry import Calculator
    from geardesign.drive.calculator import compute
    from geardesign.drive.spec import SCHEMA

    return Calculator(
        kind="drive",
        summary="a whole drive: motor to output, every stage, shaft reactions, bearing lives",
        methods=("stage calculators", "statics of two-bearing shafts", "bearing calculator"),
        schema=SCHEMA,
        compute=compute,
    )


def __getattr__(name: str):
    if name == "CALCULATOR":
        return _calculator()
    raise AttributeError(name)
