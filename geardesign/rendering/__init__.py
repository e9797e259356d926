"""The engineer's report: HTML (and PDF printed from it) with the verdict first.

* :mod:`.typeset`: symbols with subscripts, units as printed (mm²/s, min⁻¹, N·m) and
  numbers at the precision of their unit, split at the decimal point for alignment;
* :mod:`.margins`: the governing margins of a result (each safety factor against its
  minimum, every error check against its limit);
* :mod:`.svg`: a few self-contained SVG charts (no matplotlib, no network);
* :mod:`.figures`: the pictures of each kind (tooth profiles, shaft diagrams, a drive's
  power flow and heat balance, a sweep's front);
* :mod:`.html`: the HTML document; :mod:`.pdf`: the same document printed by Chromium.

The report is a renderer: it reads the :class:`~geardesign.core.result.Result` and never
changes the JSON document.
"""
