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
* a bevel stage ahead of cylindrical ones (bevel-helical reducer): the cylindrical stages
  together take ``CYLINDRICAL_AFTER_BEVEL``·u^((n−1)/n), shared equally, the bevel stage
  the rest — for one cylindrical stage u_T = 1.1·sqrt(u), the handbook rule for a
  bevel-cylindrical reducer that keeps the bevel wheel small ([Dunaev], verify); for more
  cylindrical stages the same factor on their equal share (our extension).
"""

from __future__ import annotations

import math

DEVELOPED_FACTOR = 1.25
CYLINDRICAL_WITH_WORM = 2.5
CYLINDRICAL_AFTER_BEVEL = 1.1


def split_ratio(u: float, kinds: list[str], rule: str = "equal") -> list[float]:
    """Stage ratios whose product is ``u`` for stages of the given kinds, in order from the
    input.  ``kinds`` are calculator kinds ("spur", "novikov", "worm", "bevel").

    >>> [round(r, 6) for r in split_ratio(16.0, ["bevel", "spur"])]
    [3.636364, 4.4]
    """
    n = len(kinds)
    worms = [i for i, k in enumerate(kinds) if k == "worm"]
    if worms:
        if len(worms) > 1:
            raise ValueError("more than one worm stage")
        cyl = n - 1
        out = [CYLINDRICAL_WITH_WORM] * n
        out[worms[0]] = u / CYLINDRICAL_WITH_WORM ** cyl
        return out
    bevels = [i for i, k in enumerate(kinds) if k == "bevel"]
    if bevels and n > 1:
        if len(bevels) > 1:
            raise ValueError("more than one bevel stage")
        u_c = CYLINDRICAL_AFTER_BEVEL * u ** ((n - 1) / n)
        out = [u_c ** (1.0 / (n - 1))] * n
        out[bevels[0]] = u / u_c
        return out
    if rule == "developed" and n == 2:
        u1 = DEVELOPED_FACTOR * math.sqrt(u)
        return [u1, u / u1]
    return [u ** (1.0 / n)] * n
