"""Strength of cylindrical involute gears to GOST 21354-87: contact and bending fatigue,
peak (static) loads.  The formulas by part of the standard — :mod:`.contact`,
:mod:`.bending`, :mod:`.load_factors` — gathered here under one name (``G.z_e``,
``G.k_v``, …) for the rating.
"""

from geardesign.spur.strength.gost21354.bending import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.bending import N_FG  # noqa: F401
from geardesign.spur.strength.gost21354.contact import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.load_factors import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.load_factors import S_FST  # noqa: F401
