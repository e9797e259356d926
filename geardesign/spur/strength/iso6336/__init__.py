"""ISO 6336:2019, method B: load capacity of spur and helical gears.

One module per part of the standard — :mod:`.part1` (load factors), :mod:`.part2`
(pitting), :mod:`.part3` (tooth bending, with the tooth form of :mod:`.tooth_form`),
:mod:`.part5` (materials), :mod:`.part6` (load spectra), :mod:`.part21` (scuffing) — with
the standard's tables as data in :mod:`.tables`, the ISO 1328-1 tolerances from
:mod:`geardesign.spur.tolerances.iso1328` (the drawing's); :mod:`.setting` the ISO inputs,
:mod:`.record` the declared rating record (:mod:`.scuffing`, :mod:`.spectrum` its optional
sections), :mod:`.rating` putting the parts together for a gear pair (``rate()``) and
:mod:`.checks` judging the record.
"""
