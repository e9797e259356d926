"""Splitting an overall ratio between the stages of a drive (pure functions).

Rules (handbook practice; they are recommendations, the stage calculators decide):

* ``equal``: every cylindrical stage gets u^(1/n) — equal ratios, the simplest split for
  equal-strength stages of equal materials.
* ``developed`` (two cylindrical stages, developed layout): the high-speed stage takes
  u1 = 1.25·sqrt(u), the low-speed stage u/u1 — the middle of the 1.2…1.3·sqrt(u) rule
  that gives wheels of similar immersion and the smallest housing
  ([Dunaev]).
* a worm stage takes what the cylindrical stages leave when each of them has
  ``CYLINDRICAL_WITH_WORM`` (2.5; handbook range 2…3.15 for a cylindrical stage behind a
  worm, verify).
"""

from __future__ import annotations

import math

DEVELOPED_FACTOR = 1.25
CYLINDRICAL_WITH_WORM = 2.5


def split_ratio(u: float, kinds: list[str], rule: str = "equal") -> list[float]:
    """Stage ratios whose product is ``u`` for stages of the given kinds, in order from the
    input.  ``kinds`` are calculator kinds ("spur", "novikov", "worm")."""
    n = len(kinds)
    worms = [i for i, k in enumerate(kinds) if k == "worm"]
    if worms:
        if len(worms) > 1:
            raise ValueError("more than one worm stage")
        cyl = n - 1
        out = [CYLINDRICAL_WITH_WORM] * n
        out[worms[0]] = u / CYLINDRICAL_WITH_WORM ** cyl
        return out
    if rule == "developed" and n == 2:
        u1 = DEVELOPED_FACTOR * math.sqrt(u)
        return [u1, u / u1]
    return [u ** (1.0 / n)] * n
