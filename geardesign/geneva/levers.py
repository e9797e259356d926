"""Levers of the Geneva advice (:mod:`geardesign.core.advice`): a roller that does not fit
is reduced to the largest that fits (``geneva.roller_diameter``, the check's limit rounded
down to 0.1 mm), and a motor below the indexing peak is replaced by one rated for it
(``drive.rated_power``, the peak rounded up to 0.01 kW); each re-rated."""

from __future__ import annotations

from geardesign.core.advice import Lever, to_limit

LEVERS = (
    Lever(("ROLLER_FIT",), to_limit("ROLLER_FIT", "geneva.roller_diameter", up=False),
          "the largest roller that fits"),
    Lever(("MOTOR_POWER",), to_limit("MOTOR_POWER", "drive.rated_power", up=True, digits=2,
                                     of="value"), "a motor rated for the indexing peak"),
)
