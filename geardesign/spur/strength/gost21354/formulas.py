"""Strength of cylindrical involute gears to GOST 21354-87: contact and bending fatigue,
peak (static) loads.  The formulas by part of the standard — :mod:`.contact`,
:mod:`.bending`, :mod:`.load_factors` — gathered here under one name (``G.z_e``,
``G.k_v``, …) for the rating.

Pure functions written with :mod:`geardesign.core.xp` (numbers or arrays of candidates);
stresses MPa, forces N, lengths mm, angles rad.  The standard's text could not be
consulted: every formula was checked against the public implementations named in its
docstring — ZPCIL (GitHub ``s-berlin/ZPCIL_test``, a port of the Fortran GOST 21354-87
program, file names given per function) and MATLAB DANNYE — and [GOST21354] with the
corrections of [ZPCIL]; where those sources disagree, the docstring says which was chosen.
"""

from geardesign.spur.strength.gost21354.bending import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.bending import N_FG  # noqa: F401
from geardesign.spur.strength.gost21354.contact import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.load_factors import *  # noqa: F401,F403
from geardesign.spur.strength.gost21354.load_factors import S_FST  # noqa: F401
