"""GOST 21354-87, strength of cylindrical involute gears: :mod:`.formulas` (the pure
functions, written with :mod:`geardesign.core.xp` for numbers and arrays), :mod:`.tables`
(the standard's tables as data) and :mod:`.rating` (``rate()`` → :class:`.rating.GostRating`).

The formulas are re-exported here, so that ``from geardesign.spur.strength import
gost21354 as G; G.z_e(...)`` reads as the standard.
"""

from geardesign.spur.strength.gost21354.formulas import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.formulas import N_FG, S_FST  # noqa: F401
