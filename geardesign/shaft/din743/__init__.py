"""DIN 743 (2012): load capacity of shafts and axles, as the second strength method of the
shaft calculator (``[shaft] method = "DIN743"``).

One module per part of the standard: :mod:`.part1` (component fatigue limits, mean-stress
influence, safety against fatigue and against yielding; [DIN743-1]), :mod:`.part2` (stress
concentration factors, support number, notch factors, size and roughness factors;
[DIN743-2]), :mod:`.part3` (steels and the technological size factor; [DIN743-3]);
:mod:`.rating` rates one section with them.  The tables are data (``tables.toml``).

No printed copy of the standard was at hand: the formulas and tables are those transcribed
in the independent implementation [din743py] and, where noted, in public course scripts of
the method that agree with it; docs/shaft.md lists which.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path


@lru_cache(maxsize=1)
def tables() -> dict:
    """The DIN 743 tables (``tables.toml``)."""
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("tables.toml"))
