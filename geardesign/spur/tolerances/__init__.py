"""Accuracy and backlash of a cylindrical gear pair: GOST 1643-81 (types of mating,
guaranteed backlash, centre-distance deviation) and ISO 1328-1, editions 2013 and 1995
(flank tolerances, also those of the ISO 6336 rating), and the backlash chain that turns tooth-thickness allowances, the centre-distance
tolerance and the operating temperatures into the backlash range.

Modules: :mod:`gost1643`, :mod:`iso1328`, :mod:`backlash`; the data tables are TOML files
beside them.
"""
