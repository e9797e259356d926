"""The import path of the GOST 21354-87 rating's inputs for the calculators that build
them (spur, planetary): the rating is :mod:`geardesign.spur.strength.gost21354.rating`, the
duty :mod:`geardesign.spur.strength.common`."""

from geardesign.spur.strength.common import Duty, Life, Value  # noqa: F401
from geardesign.spur.strength.gost21354.rating import (  # noqa: F401
    GostRating, Setting, forces, life_cycles, rate)
