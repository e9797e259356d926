"""Levers of the rim advice (:mod:`geardesign.core.advice`): a rim short of its required
probability of non-failure, or whose equivalent amplitude exceeds its endurance limit, gets
hardened fillets (``fillet.hardening_factor``, from the present value, 1 without
hardening, in steps of 0.05 up to 2.5, the top of the range that induction hardening,
nitriding or roller burnishing give ([GOST25504] via [Gutyria2017], as the spec key
states)); each re-rated.

Planets that cannot be assembled (``ASSEMBLY``: identical planets mesh with sun and ring
only at multiples of 360°/(z_s + z_r)) are moved to the nearest such positions, then to
the sets with one planet a step the other way (at most :data:`ASSEMBLY_TRIES`); planets
whose tip circles overlap (``PLANET_SPACING``) are spread as evenly as assembly allows
(one change for both checks when both fail).
The positions are advised as the spec gives them: ``planets.shifts`` (paper B's relative
shifts, k = (θ − 360°/n)·z_r/360°) or ``planets.angles``.  When even spacing does not clear
the tips, fewer or smaller planets change the loads the rim is rated for (the stresses are
given for the present train): no fix; the message names them."""

from __future__ import annotations

import math

from geardesign.core.advice import Lever

K_V_MAX = 2.5
"""The largest hardening factor advised."""


def _harder(data: dict, _res):
    fillet = data.get("fillet")
    if not isinstance(fillet, dict):
        return
    k = fillet.get("hardening_factor", 1.0)
    if not isinstance(k, (int, float)) or isinstance(k, bool):
        return
    n = math.floor(k * 20.0 + 1e-9) + 1
    while n / 20.0 <= K_V_MAX + 1e-9:
        yield (("fillet.hardening_factor", n / 20.0),)
        n += 1


LEVERS = (Lever(("PROBABILITY", "ENDURANCE_LIMIT"), _harder,
                "hardened fillets, the least hardening factor that passes"),)


# ------------------------------------------------------------------ planet positions

ASSEMBLY_TRIES = 4
"""Sets of planet positions re-rated at most (a rim with Floquet bands rates in ~1 s)."""

DIGITS = 8
"""Decimals of an advised angle or shift: the assembly index (z_s + z_r)·θ/360° must be an
integer within 1e-6, which four decimals of a degree do not give."""


def _positions(data: dict, res):
    """Planet positions at multiples of 360°/(z_s + z_r) (see :func:`_assemblable`)."""
    from geardesign.epicycle_rim import mesh

    pl, ring = data.get("planets"), data.get("ring")
    if not isinstance(pl, dict) or not isinstance(ring, dict):
        return None
    zs, zr, n = pl.get("z_sun"), ring.get("z"), pl.get("count")
    if not all(isinstance(x, int) and not isinstance(x, bool) for x in (zs, zr, n)):
        return None
    sec = next((s for s in res.sections if s.key == "geometry"), None)
    angles = None if sec is None else next((r.value for r in sec.rows if r.key == "angles"),
                                           None)
    if not isinstance(angles, list) or len(angles) != n:
        return None
    N = zs + zr
    step = mesh.assembly_step(zs, zr)
    rel = [a - angles[0] for a in angles]
    return pl, zr, n, N, step, angles[0], [x * N / 360.0 for x in rel]


def _as_fix(pl: dict, zr: int, n: int, a0: float, step: float, idx: list[int]) -> tuple:
    """Planet indices as the spec gives the planets: shifts k (paper B) if it gives shifts,
    else angles."""
    angles = [a0 + i * step for i in idx]
    if pl.get("shifts") is not None:
        pitch = 360.0 / zr
        gaps = [b - a for a, b in zip(angles, angles[1:])]
        k = [round((g - 360.0 / n) / pitch, DIGITS) for g in gaps]
        return (("planets.shifts", k + [round(-sum(k), DIGITS) + 0.0]),)
    return (("planets.angles", [round(a, DIGITS) + 0.0 for a in angles]),)


def _assemblable(data: dict, res):
    """The planets moved to the nearest assemblable positions (each index rounded), then
    the sets with one planet a step the other way, the least moved first; positions in
    order around the carrier, none shared."""
    got = _positions(data, res)
    if got is None:
        return
    pl, zr, n, N, step, a0, x = got
    base = [round(v) for v in x]
    sets = [base]
    for i in range(1, n):
        alt = list(base)
        alt[i] += 1 if x[i] > base[i] else -1
        sets.append(alt)
    sets.sort(key=lambda s: sum(abs(a - b) for a, b in zip(s, x)))
    tried = 0
    for idx in sets:
        if idx[0] != 0 or any(b <= a for a, b in zip(idx, idx[1:])) or idx[-1] >= N:
            continue
        tried += 1
        if tried > ASSEMBLY_TRIES:
            return
        yield _as_fix(pl, zr, n, a0, step, idx)


def _spread(data: dict, res):
    """Planets as evenly spread as assembly allows: planet i at the multiple of
    360°/(z_s + z_r) nearest to i·360°/n (the largest smallest gap those positions give);
    advised only when they differ from the present ones."""
    got = _positions(data, res)
    if got is None or not any(c.code == "PLANET_SPACING" and not c.passed for c in res.checks):
        return
    pl, zr, n, N, step, a0, x = got
    idx = [round(i * N / n) for i in range(n)]
    if any(abs(a - b) > 1e-6 for a, b in zip(idx, x)) and len(set(idx)) == n:
        yield _as_fix(pl, zr, n, a0, step, idx)


LEVERS = LEVERS + (
    Lever(("PLANET_SPACING", "ASSEMBLY"), _spread, "the planets spread as evenly as assembly "
          "allows"),
    Lever(("ASSEMBLY",), _assemblable, "the nearest planet positions at multiples of "
          "360°/(z_s + z_r), where identical planets assemble"),
)
