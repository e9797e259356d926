"""A whole drive: motor, stages (each computed by its own calculator), shafts on two
bearings and their bearings' lives.  Modules: :mod:`.stages` (stage adapters),
:mod:`.shafts` (statics), :mod:`.split` (ratio split), :mod:`.spec`, :mod:`.calculator`."""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules does not
# import the calculation
__getattr__ = lazy_calculator(
    "drive",
    summary="a whole drive: motor to output, every stage, shaft reactions, bearing lives; "
    "with steps and keys the shafts and hubs, with [lubrication] the losses and heat balance",
    methods=("stage calculators", "statics of two-bearing shafts", "bearing calculator"),
)
