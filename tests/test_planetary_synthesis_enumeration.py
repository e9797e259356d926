"""The vectorised tooth-number enumeration of the planetary synthesis gives the candidates
of a plain loop over every tooth set (the procedure of the module notes written out), in
the same order, and stays bounded and small for the widest allowed search."""

from __future__ import annotations

import math
import tracemalloc

import pytest

from geardesign.planetary import synthesis as S
from tests.conftest import bounded_work


def _loop(scheme, k, fixed, driving, driven, target, tol, sun_min, planet_min, ring_max, dev):
    lo, hi = target * (1 - tol / 100), target * (1 + tol / 100)

    def r(member, z):
        if member == "carrier":
            return 0.0
        if member == "sun":
            return -z["g"] / z["a"]
        return z["g"] / z["b" if member == "ring" else "e"]

    def ratio(z):
        rf = r(fixed, z)
        den = r(driven, z) - rf
        return math.inf if den == 0.0 else (r(driving, z) - rf) / den

    out = []
    if scheme == "2K-H":
        for za in range(sun_min, ring_max):
            for zb in range(za + 2 * planet_min - dev, ring_max + 1):
                if (za + zb) % k:
                    continue
                i = ratio({"a": za, "b": zb, "g": 1.0})
                if not lo <= abs(i) <= hi:
                    continue
                for db in range(-dev, dev + 1):
                    if (zb - za - db) % 2:
                        continue
                    zg = (zb - za - db) // 2
                    if zg < planet_min or zb - zg < 4:
                        continue
                    out.append((za, zg, zb, None, i, abs(db)))
    else:
        for za in range(sun_min, ring_max):
            for zg in range(planet_min, ring_max):
                if za + 2 * zg - dev > ring_max:
                    break
                for db in range(-dev, dev + 1):
                    zb = za + 2 * zg + db
                    if zb > ring_max or zb - zg < 4 or (za + zb) % k:
                        continue
                    for de in range(db + k, dev + 1, k):
                        ze = za + 2 * zg + de
                        i = ratio({"a": za, "b": zb, "e": ze, "g": zg})
                        if math.isfinite(i) and lo <= abs(i) <= hi:
                            out.append((za, zg, zb, ze, i, abs(db) + abs(de)))
    out.sort(key=lambda c: (round(abs((abs(c[4]) - target) / target * 100), 6),
                            max(c[2], c[3] or 0), c[5], c[0]))
    return out


CASES = [("2K-H", 3, "ring", "sun", "carrier", 5.0, 3.0, 13, 13, 120, 2),
         ("2K-H", 4, "carrier", "sun", "ring", 3.2, 5.0, 12, 12, 100, 3),
         ("3K", 3, "ring", "sun", "ring2", 300.0, 5.0, 12, 13, 150, 2),
         ("3K", 3, "ring", "sun", "ring2", 80.0, 10.0, 8, 8, 120, 4)]


@pytest.mark.parametrize("case", CASES, ids=[f"{c[0]}-{c[5]}" for c in CASES])
def test_enumeration_equals_the_loop(case):
    want = _loop(*case)
    for keep in (None, 7):
        got, total = S.candidates(*case, keep=keep)
        assert total == len(want)
        ref = want if keep is None else want[:keep]
        assert len(got) == len(ref)
        for c, w in zip(got, ref):
            t = c.train
            assert (t.sun, t.planet, t.ring, t.ring2 if case[0] == "3K" else None) == w[:4]
            assert c.ratio == w[4] and c.deviation == w[5]


def test_widest_3k_search_is_bounded_and_small():
    """ring_max = 1000, sum_deviation = 6, 20 % tolerance, sun and planet from 6 teeth: the
    work is bounded by the candidates counted and the memory by the peak (the speed goal is
    benchmarks/time_cases.py's)."""
    args = ("3K", 3, "ring", "sun", "ring2", 300.0, 20.0, 6, 6, 1000, 6)
    with bounded_work(0.2, "the widest 3K search"):
        got, total = S.candidates(*args, keep=S.MAX_EVALUATED)
    tracemalloc.start()
    S.candidates(*args, keep=S.MAX_EVALUATED)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert total > 300_000 and len(got) == S.MAX_EVALUATED
    assert peak < 20e6        # about 8 MB
