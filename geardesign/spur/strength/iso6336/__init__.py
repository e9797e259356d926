"""ISO 6336:2019, method B: load capacity of spur and helical gears.

One module per part of the standard — :mod:`.part1` (load factors), :mod:`.part2`
(pitting), :mod:`.part3` (tooth bending), :mod:`.part5` (materials), :mod:`.part6` (load
spectra) — with the standard's tables as data in :mod:`.tables`, the ISO 1328-1 tolerances
from :mod:`geardesign.spur.tolerances.iso1328` (the drawing's), and :mod:`.rating` putting
them together for a gear pair.
"""
