"""The import path of the GOST 21354-87 tables for the calculators that read the series
(modules, centre distances, regimes, velocity limits): the data live in
:mod:`geardesign.spur.strength.gost21354.tables`."""

from geardesign.spur.strength.gost21354.tables import *  # noqa: F401,F403
