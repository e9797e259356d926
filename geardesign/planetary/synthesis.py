"""Synthesis: tooth numbers (and shifts) of a 2K-H or single-crown 3K train for a target
ratio and number of planets that meet every assembly condition.

Procedure (Kudryavtsev's selection of tooth numbers, with shifts for non-standard sums):

1. For each sun z_a and planet z_g (z_a ≥ sun_min, z_g ≥ planet_min), each ring
   z_b = z_a + 2z_g + δ with |δ| ≤ sum_deviation (and for 3K each second ring
   z_e = z_a + 2z_g + δ_e, z_e > z_b), the ratio i = (ρ_in − ρ_F)/(ρ_out − ρ_F) of the
   chosen members (ρ of :mod:`.kinematics`, ρ = 0 for the carrier) is compared with the
   target; candidates within the tolerance that satisfy the equal-spacing condition
   (:func:`.assembly.assembly_numbers`) are kept.
2. They are ranked by the ratio error, then by size (ring teeth), then by |δ|.
3. In that order each candidate gets the common centre distance a_w = the largest
   reference centre distance of its meshes (so that no mesh needs a negative shift sum),
   raised in steps of 0.1·m (up to 0.8·m) while a mesh interferes, the sun–planet shifts
   of equal specific sliding, the ring shifts by coaxiality, and the full geometry; the
   first ``candidates`` that pass every geometric and assembly error check are reported,
   and the best is analysed.  (Matusevich et al. sweep the sun–planet working angle in the
   same way.)
"""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.core.records import dataclass
from geardesign.planetary import assembly as A
from geardesign.planetary import geometry as PG
from geardesign.planetary.checks import gear_checks, mesh_checks
from geardesign.planetary.kinematics import Train
from geardesign.gears.geometry import GeometryError, PairInput
from geardesign.spur.kinematics import balanced_shift_split

MAX_EVALUATED = 200  # geometries computed before the search gives up (keeps it fast)
A_W_STEP = 0.1       # × m: a_w is raised in these steps when a candidate interferes
A_W_STEPS = 8        # steps tried per candidate


@dataclass(frozen=True)
class Candidate:
    train: Train
    ratio: float
    error: float          # ratio error, %
    deviation: int        # Σ |δ| of the meshes
    a_w: float = math.nan
    shifts: dict | None = None
    d_ring: float = math.nan   # ring root diameter (size), mm


def _rho(train: Train, member: str) -> float:
    return 0.0 if member == "carrier" else train.rho(member)


def ratio_of(train: Train, fixed: str, driving: str, driven: str) -> float:
    """i = n_driving/n_driven = (ρ_in − ρ_F)/(ρ_out − ρ_F) (Willis, ρ_carrier = 0)."""
    rf = _rho(train, fixed)
    den = _rho(train, driven) - rf
    return math.inf if den == 0.0 else (_rho(train, driving) - rf) / den


def candidates(scheme: str, planets: int, fixed: str, driving: str, driven: str,
               target: float, tol_pct: float, sun_min: int, planet_min: int, ring_max: int,
               dev_max: int, keep: int | None = None) -> tuple[list[Candidate], int]:
    """Step 1 and 2 of the procedure: tooth-number candidates, ranked, and how many there
    are.

    The tooth sets are enumerated as numpy arrays, one (δ_b, δ_e) combination at a time over
    the grid of suns and planets, and only the ``keep`` best are turned into
    :class:`Candidate` objects (the search never looks further than ``MAX_EVALUATED``):
    time and memory stay small for the widest ranges.  The ratio is plain arithmetic on ρ
    (:func:`ratio_of` for a :class:`Train` gives the same numbers); for a 2K-H train z_g
    cancels from it.  The order is that of the ranking key — ratio error (to 1e-6 %), the
    larger ring, Σ|δ|, the sun — then the enumeration order (sun, planet or ring, δ_b, δ_e)."""
    import numpy as np

    k = planets
    lo, hi = target * (1.0 - tol_pct / 100.0), target * (1.0 + tol_pct / 100.0)

    def r(member: str, z: dict):   # ρ_X with the planet crown z["g"]
        if member == "carrier":
            return 0.0
        if member == "sun":
            return -z["g"] / z["a"]
        return z["g"] / z["b" if member == "ring" else "e"]

    def ratio(z: dict):
        rf = r(fixed, z)
        den = r(driven, z) - rf
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(den == 0.0, np.inf, (r(driving, z) - rf) / np.where(den == 0.0, 1.0,
                                                                                 den))

    kept = None
    total = 0

    def prune(parts):
        """Concatenate the arrays found so far and keep the ``keep`` best (with a margin for
        the rounding of the first key; the exact Python order is applied at the end)."""
        cat = [np.concatenate([f[j] for f in parts]) for j in range(10)]
        a_, g_, b_, e_, i_, dev = cat[:6]
        err = (np.abs(i_) - target) / target * 100.0
        approx = np.round(np.abs(err), 6)
        idx = np.lexsort((cat[9], cat[8], cat[7], cat[6], a_, dev, np.maximum(b_, e_), approx))
        if keep is not None and len(idx) > keep:
            cut = approx[idx[keep - 1]] + 2e-6
            idx = idx[approx[idx] <= cut]
        return [c[idx] for c in cat]

    block = 16   # suns per block: memory stays at a few MB whatever ring_max
    for a0 in range(sun_min, ring_max, block):
        found = []
        za_block = np.arange(a0, min(a0 + block, ring_max), dtype=np.int64)
        if scheme == "2K-H":
            za, zb = np.meshgrid(za_block, np.arange(0, ring_max + 1, dtype=np.int64),
                                 indexing="ij")
            za, zb = za.ravel(), zb.ravel()
            sel = (zb >= za + 2 * planet_min - dev_max) & ((za + zb) % k == 0)
            za, zb = za[sel], zb[sel]
            i_all = ratio({"a": za.astype(float), "b": zb.astype(float), "g": 1.0})
            ok = (np.abs(i_all) >= lo) & (np.abs(i_all) <= hi)
            za, zb, i_all = za[ok], zb[ok], i_all[ok]
            for n_db, d_b in enumerate(range(-dev_max, dev_max + 1)):
                zg = (zb - za - d_b) // 2
                m = ((zb - za - d_b) % 2 == 0) & (zg >= planet_min) & (zb - zg >= 4)
                n = int(m.sum())
                found.append((za[m], zg[m], zb[m], np.zeros(n, dtype=np.int64), i_all[m],
                              np.full(n, abs(d_b)), zb[m], np.full(n, n_db),
                              np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)))
        else:
            za, zg = np.meshgrid(za_block, np.arange(planet_min, ring_max, dtype=np.int64),
                                 indexing="ij")
            za, zg = za.ravel(), zg.ravel()
            sel = za + 2 * zg - dev_max <= ring_max
            za, zg = za[sel], zg[sel]
            for n_db, d_b in enumerate(range(-dev_max, dev_max + 1)):
                zb = za + 2 * zg + d_b
                mb = (zb <= ring_max) & (zb - zg >= 4) & ((za + zb) % k == 0)
                a_, g_, b_ = za[mb], zg[mb], zb[mb]
                for d_e in range(d_b + k, dev_max + 1, k):
                    e_ = a_ + 2 * g_ + d_e
                    i = ratio({"a": a_.astype(float), "b": b_.astype(float),
                               "e": e_.astype(float), "g": g_.astype(float)})
                    m = np.isfinite(i) & (np.abs(i) >= lo) & (np.abs(i) <= hi)
                    n = int(m.sum())
                    found.append((a_[m], g_[m], b_[m], e_[m], i[m],
                                  np.full(n, abs(d_b) + abs(d_e)), g_[m], np.full(n, n_db),
                                  np.full(n, d_e),
                                  np.zeros(n, dtype=np.int64)))
        total += sum(len(f[0]) for f in found)
        if found:
            kept = prune(found + ([tuple(kept)] if kept is not None else []))
    if kept is None or not len(kept[0]):
        return [], total
    a_, g_, b_, e_, i_, dev = kept[:6]
    err = (np.abs(i_) - target) / target * 100.0
    idx = range(len(a_))
    out = []
    for j in idx:
        z_a, z_g, z_b, z_e = int(a_[j]), int(g_[j]), int(b_[j]), int(e_[j])
        train = Train("2K-H", z_a, z_g, z_b, k) if scheme == "2K-H" else \
            Train("3K", z_a, z_g, z_b, k, None, z_e)
        out.append(Candidate(train, float(i_[j]), float(err[j]), int(dev[j])))
    out.sort(key=lambda c: (round(abs(c.error), 6), max(c.train.ring, c.train.ring2 or 0),
                            c.deviation, c.train.sun))
    return (out[:keep] if keep is not None else out), total


def shifted(cand: Candidate, lay: PG.Layout, step: int = 0) -> Candidate:
    """Step 3: centre distance and shifts of a candidate (see the module notes); ``step``
    raises a_w by 0.1·m per step above the largest reference centre distance."""
    lay = replace(lay, train=cand.train)
    meshes = PG.meshes_of(cand.train)
    a_w = max(PG.reference_center_distance(lay, m) for m in meshes) + A_W_STEP * step * lay.m
    sp = meshes[0]
    x_sum = PG.shift_sum_for(lay, sp, a_w)
    base = PairInput(lay.m, cand.train.sun, cand.train.planet, 0.0, 0.0, lay.beta, lay.b_w,
                     lay.rack)
    x_sun = balanced_shift_split(base, x_sum, steps=24)
    shifts, _ = PG.coaxial_shifts(lay, a_w, x_sun, None)
    return replace(cand, a_w=a_w, shifts=shifts)


def feasible(cand: Candidate, lay: PG.Layout, gap: float, tip_min: float, sliding_max: float
             ) -> tuple[bool, list]:
    """Geometry of a shifted candidate and whether it passes every error check (meshes,
    gears, neighbouring planets)."""
    lay = replace(lay, train=cand.train)
    try:
        meshes = PG.mesh_geometry(lay, cand.shifts)
    except GeometryError:
        return False, []
    checks = mesh_checks(meshes, sliding_max)
    sp = meshes[0].geom
    gears = {"sun": sp.g1, "planet": sp.g2}
    for mesh in meshes[1:]:
        gears[mesh.spec.wheel] = mesh.geom.g2
    alpha_t = {x: sp.alpha_t for x in gears}
    modules = {x: lay.m for x in gears}
    checks += gear_checks(gears, lay.rack.h_straight, alpha_t, lay.beta, modules, tip_min,
                          False)
    sp_ = A.spacing(cand.train)
    clearance = A.neighbour_clearance(cand.a_w, sp.g2.d_a, math.radians(sp_.min_angle))
    ok = (cand.train.planets == 1 or clearance >= gap * lay.m) and not [c for c in checks
                                           if not c.passed and c.severity == "error"]
    return ok, meshes


def search(scheme: str, planets: int, fixed: str, driving: str, driven: str, target: float,
           tol_pct: float, sun_min: int, planet_min: int, ring_max: int, dev_max: int,
           lay: PG.Layout, gap: float, tip_min: float, sliding_max: float, wanted: int
           ) -> tuple[list[Candidate], int, int]:
    """The procedure of the module notes.  Returns ``(feasible candidates, number of
    tooth-number candidates, number evaluated)``."""
    cands, total = candidates(scheme, planets, fixed, driving, driven, target, tol_pct,
                              sun_min, planet_min, ring_max, dev_max, keep=MAX_EVALUATED)
    found = []
    evaluated = 0
    for cand in cands:
        if evaluated >= MAX_EVALUATED or len(found) >= wanted:
            break
        for step in range(A_W_STEPS + 1):
            evaluated += 1
            try:
                c = shifted(cand, lay, step)
            except GeometryError:
                continue
            ok, meshes = feasible(c, lay, gap, tip_min, sliding_max)
            if ok:
                found.append(replace(c, d_ring=meshes[1].geom.g2.d_f))
                break
            if evaluated >= MAX_EVALUATED:
                break
    return found, total, evaluated
