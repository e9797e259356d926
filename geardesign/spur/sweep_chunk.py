"""One chunk of a design sweep: the varied values of candidates ``start`` … ``stop − 1``
(grid indices or points of a scrambled Sobol sequence), the kernel over them
(:mod:`geardesign.spur.kernel`, one call per group of fixed data), the objectives and the
constraints, and the chunk's summary (counts, ranked head, Pareto front).
:func:`evaluate_chunk` is a pure function of its arguments: the local loop, a worker process
and a Dask worker run it alike."""

from __future__ import annotations

import itertools
import math

import numpy as np

from geardesign.spur.checks import face_width_ratio_ok
from geardesign.gears.geometry import disc_mass, disc_volume
from geardesign.spur.sweep_input import (COLUMNS, FIXED_KEYS, MATERIAL_COLUMNS,
                                         Sweep, _with_fixed)
from geardesign.spur.sweep_rank import Summary, _front, _rank

def _base_values(spec) -> dict:
    """The pair of the base spec (keys of :data:`VARIABLE`)."""
    from geardesign.spur.calculator import pair_input_from_spec

    g = spec.data["gear"]
    given = {k: g.get(k) for k in ("x1", "x2", "center_distance")}
    p, _ = pair_input_from_spec(spec)
    return {"gear.module": p.m_n, "gear.z1": float(p.z1), "gear.z2": float(p.z2),
            "gear.x1": p.x1, "gear.x2": p.x2, "gear.helix_angle": math.degrees(p.beta),
            "gear.face_width": p.b_w, "gear.center_distance": given["center_distance"],
            "x1_given": given["x1"] is not None, "x2_given": given["x2"] is not None}


def _shift_rule(varied, base: dict) -> str:
    """How x1, x2 follow for each candidate: "given" (no centre distance), or with the
    centre distance fixed or varied, "x1"/"x2" (that one given or varied, the other
    x_Σ − it) or "equal" (x_Σ split equally)."""
    if "gear.center_distance" not in varied and base["gear.center_distance"] is None:
        return "given"
    if "gear.x1" in varied:
        return "x1"
    if "gear.x2" in varied:
        return "x2"
    if base["x1_given"]:
        return "x1"
    if base["x2_given"]:
        return "x2"
    return "equal"


def candidates(sw: Sweep, start: int, stop: int, sampler=None) -> dict:
    """The varied values of candidates ``start`` … ``stop − 1``: grid indices in C order, or
    points of a scrambled Sobol sequence (``seed``) mapped on the ranges (a value list is
    sampled by index).  ``sampler``: the sequence's engine positioned at ``start``
    (:func:`samplers`), drawn on; without it one is positioned here."""
    n = stop - start
    out = {}
    if sw.samples is None:
        shape = tuple(len(d.values) for d in sw.dims)
        idx = np.unravel_index(np.arange(start, stop), shape)
        for d, i in zip(sw.dims, idx):
            out[d.key] = d.values[i]
        return out
    from geardesign.spur.sobol import engine

    if sampler is None:
        sampler = engine(len(sw.dims), sw.seed, start)
    if sampler.num_generated != start:
        raise ValueError(f"the sampler stands at {sampler.num_generated}, not {start}")
    pts = sampler.random(n)
    for j, d in enumerate(sw.dims):
        k = np.minimum((pts[:, j] * len(d.values)).astype(np.int64), len(d.values) - 1)
        out[d.key] = d.values[k] if len(d.values) <= 64 or d.integer \
            else d.low + pts[:, j] * (d.high - d.low)
    return out


def _chunk_inputs(sw: Sweep, varied: dict, base: dict, alpha_n: float) -> dict:
    n = len(next(iter(varied.values())))

    def col(key):
        if key in varied:
            return np.asarray(varied[key], dtype=float)
        return np.full(n, float(base[key]))

    m_n, z1, z2 = col("gear.module"), col("gear.z1"), col("gear.z2")
    beta = np.radians(col("gear.helix_angle"))
    b_w = col("gear.face_width")
    rule = _shift_rule(varied, base)
    if rule != "given":
        from geardesign.involute import inv

        a_w = col("gear.center_distance")
        alpha_t = np.arctan(math.tan(alpha_n) / np.cos(beta))
        a = 0.5 * m_n * (z1 + z2) / np.cos(beta)
        cos_tw = np.clip(a * np.cos(alpha_t) / a_w, -1.0, 1.0)
        x_sum = (z1 + z2) * (inv(np.arccos(cos_tw)) - inv(alpha_t)) / (2.0 * math.tan(alpha_n))
        x_sum = np.where(a_w > a * np.cos(alpha_t) * (1 + 1e-9), x_sum, np.nan)
        if rule == "x1":
            x1 = col("gear.x1")
            x2 = x_sum - x1
        elif rule == "x2":
            x2 = col("gear.x2")
            x1 = x_sum - x2
        else:
            x1 = x2 = 0.5 * x_sum
    else:
        x1, x2 = col("gear.x1"), col("gear.x2")
    return dict(m_n=m_n, z1=z1, z2=z2, x1=x1, x2=x2, beta=beta, b_w=b_w)



def _evaluate_in_groups(spec_data: dict, sw: Sweep, varied: dict, base: dict) -> tuple:
    """The kernel over the candidates, one call per combination of the varied keys that are
    fixed data of the kernel (materials, accuracy grade, bearing scheme).  Returns the
    inputs and the result arrays."""
    from geardesign.core.registry import load_data
    from geardesign.spur.kernel import evaluate, fixed_from_spec

    gdims = [d for d in sw.dims if d.choices or d.key in FIXED_KEYS]
    n = len(next(iter(varied.values())))
    codes = [varied[d.key].astype(np.int64) for d in gdims]
    combos = sorted(set(zip(*codes))) if gdims else [()]
    c = out = None
    for combo in combos:
        chosen = {d.key: (d.choices[k] if d.choices else int(k)) for d, k in zip(gdims, combo)}
        _, spec = load_data(_with_fixed(spec_data, chosen), "sweep")
        fixed = fixed_from_spec(spec)
        if c is None:
            c = _chunk_inputs(sw, varied, base, fixed.rack.alpha_n)
            bad = ~np.isfinite(c["x1"]) | ~np.isfinite(c["x2"])
            c["x1"] = np.where(bad, 0.0, c["x1"])
            c["x2"] = np.where(bad, 0.0, c["x2"])
            c["bad"] = bad
        if len(combos) == 1:    # one group: the chunk's arrays as they are, no masked copies
            part = evaluate({k: v for k, v in c.items() if k != "bad"}, fixed)
            return c, part       # a value shared by the chunk stays a broadcast view
        sel = np.ones(n, dtype=bool)
        for code, k in zip(codes, combo):
            sel &= code == k
        part = evaluate({k: v[sel] for k, v in c.items() if k != "bad"}, fixed)
        if out is None:
            out = {k: np.empty(n, dtype=np.asarray(v).dtype) for k, v in part.items()}
        for k, v in part.items():
            if k in out:
                out[k][sel] = v
    return c, out


HEAP = {"M_TRIM_THRESHOLD": (-1, 256 << 20), "M_MMAP_THRESHOLD": (-3, 32 << 20)}
"""glibc ``mallopt`` settings of a process that evaluates chunks (parameter number, bytes):
the freed arrays of one chunk stay in the heap for the next instead of going back to the
system.  With glibc's defaults the heap top above the dynamic trim threshold (twice the
largest freed mapping, here a few arrays) is returned after every chunk and faulted in again
by the next: page faults that doubled the CPU time of an ISO 6336 sweep (system time 1.0 s of
3.4 s per 10⁶ candidates).  Both settings together: either alone turns the dynamic
thresholds off and is worse.  The peak memory is the same (it is one chunk's arrays)."""

_HEAP_SET: list = []


def steady_heap() -> None:
    """Set :data:`HEAP` once in this process (glibc only; elsewhere nothing)."""
    if _HEAP_SET:
        return
    _HEAP_SET.append(True)
    import ctypes
    import sys

    if not sys.platform.startswith("linux"):
        return
    try:
        mallopt = ctypes.CDLL(None).mallopt     # the process's own C library
    except (OSError, AttributeError):     # not glibc (musl has no mallopt)
        return
    for param, value in HEAP.values():
        mallopt(ctypes.c_int(param), ctypes.c_int(value))


def evaluate_chunk(spec_data: dict, sw: Sweep, start: int, stop: int, rows: bool = False,
                   sampler=None) -> dict:
    """Evaluate candidates ``start`` … ``stop − 1`` and return the chunk's summary: counts,
    the ranked head and the Pareto front (as column arrays).  A pure function of its
    arguments: a worker process or a Dask worker runs it as the local loop does.  With
    ``rows`` it also returns every candidate's columns (the dataset of ``--data``);
    ``sampler``: a Sobol sample's engine positioned at ``start`` (:func:`samplers`)."""
    from geardesign.core.registry import load_data

    steady_heap()
    _, spec = load_data(spec_data, "sweep")
    base = _base_values(spec)
    varied = candidates(sw, start, stop, sampler)
    c, r = _evaluate_in_groups(spec_data, sw, varied, base)
    bad = c["bad"]
    r["valid"] &= ~bad
    r["passed"] &= ~bad
    r["helix_angle"] = np.degrees(c["beta"])
    r["m_n"], r["b_w"] = c["m_n"], c["b_w"]
    for d, col in ((d, MATERIAL_COLUMNS[d.key]) for d in sw.dims if d.choices):
        r[col] = varied[d.key].astype(float)
    for d in sw.dims:
        if d.key in FIXED_KEYS:
            r[d.key.split(".", 1)[1]] = varied[d.key].astype(float)
    with np.errstate(all="ignore"):
        r["psi_bd"] = r["b_w"] / r["d_w1"]
        r["psi_ba"] = r["b_w"] / r["a_w"]
    r["ok_FACE_WIDTH_RATIO"] = (face_width_ratio_ok(r["psi_bd"], *sw.psi_bd)
                                & face_width_ratio_ok(r["psi_ba"], *sw.psi_ba))
    feasible = (r["passed"] & r["ok_FACE_WIDTH_RATIO"]
                & (r["margin"] >= sw.min_margin * (1 - 1e-12)))
    if sw.ratio is not None:
        feasible &= (r["u"] >= sw.ratio[0] - 1e-12) & (r["u"] <= sw.ratio[1] + 1e-12)
    if sw.center_distance_range is not None:
        lo, hi = sw.center_distance_range
        feasible &= (r["a_w"] >= lo - 1e-9) & (r["a_w"] <= hi + 1e-9)
    index = np.arange(start, stop)
    valid = r["valid"]
    n_valid = np.count_nonzero(valid)
    counts = {"evaluated": stop - start, "valid": int(n_valid),
              "passed": int(np.count_nonzero(r["passed"])),
              "feasible": int(np.count_nonzero(feasible))}
    # a kernel flag ok_<CODE> holds on valid candidates only: the failures are the rest
    fails = {k[3:]: int(n_valid - np.count_nonzero(r[k] if k != "ok_FACE_WIDTH_RATIO"
                                                   else r[k] & valid))
             for k in r if k.startswith("ok_")}
    keep = COLUMNS + ("S_Hmin",) + tuple(MATERIAL_COLUMNS[d.key] for d in sw.dims
                                         if d.choices) + tuple(
        d.key.split(".", 1)[1] for d in sw.dims if d.key in FIXED_KEYS)
    if rows:     # the dataset has every candidate's objectives
        _objectives(r, sw.friction)
        pick = np.flatnonzero(feasible)
        sel = {k: r[k][pick] for k in keep}
    else:        # the objectives of the feasible candidates only
        pick = np.flatnonzero(feasible)
        sel = {k: r[k][pick] for k in set(keep + OBJECTIVE_INPUTS) if k in r}
        _objectives(sel, sw.friction)
        sel = {k: sel[k] for k in keep}
    sel["index"] = index[pick]
    head = _rank(sel, sw)
    front = _front(sel, sw)
    return {"counts": counts, "fails": fails, "head": head, "front": front,
            "rows": _dataset(r, feasible, index) if rows else None}


OBJECTIVE_INPUTS = ("d1", "d2", "b_w", "S_H1", "S_H2", "rho_a1", "rho_a2", "rho_p1", "rho_p2",
                    "d_w1", "alpha_tw", "p_bt", "eps_alpha", "z1", "u", "beta_b")
"""The kernel's columns :func:`_objectives` reads."""


def _objectives(r: dict, friction: float) -> None:
    """The objectives' columns of the candidates ``r`` (arrays of :data:`OBJECTIVE_INPUTS`):
    volume and steel mass of the two gears, the smaller contact safety factor, the tooth loss
    factor H_V and the mesh efficiency at ``friction``, the larger specific sliding."""
    from geardesign.planetary.efficiency import loss_factor
    from geardesign.spur.kinematics import specific_sliding

    r["volume"] = (disc_volume(r["d1"], r["b_w"]) + disc_volume(r["d2"], r["b_w"])) / 1000.0
    r["mass"] = disc_mass(r["d1"], r["b_w"]) + disc_mass(r["d2"], r["b_w"])
    r["S_Hmin"] = np.minimum(r["S_H1"], r["S_H2"])
    eps_1 = (r["rho_a1"] - 0.5 * r["d_w1"] * np.sin(r["alpha_tw"])) / r["p_bt"]
    r["H_V"] = loss_factor(r["eps_alpha"], eps_1, r["z1"], r["u"], r["beta_b"])
    r["eta"] = 1.0 - friction * r["H_V"]
    with np.errstate(all="ignore"):
        th1A = specific_sliding(r["rho_p1"], r["rho_a2"], r["u"])[0]
        th2E = specific_sliding(r["rho_a1"], r["rho_p2"], r["u"])[1]
    r["sliding"] = np.where((r["rho_p1"] > 0) & (r["rho_p2"] > 0),
                            np.maximum(np.abs(th1A), np.abs(th2E)), np.inf)


def _dataset(r: dict, feasible, index) -> dict:
    cols = {"index": index}
    for k in COLUMNS + tuple(MATERIAL_COLUMNS.values()):
        if k in r:
            cols[k] = np.ascontiguousarray(r[k])     # a broadcast value written out
    for k in r:
        if k.startswith("ok_"):
            cols[k] = np.ascontiguousarray(r[k])     # a broadcast value written out
    cols["valid"], cols["passed"], cols["feasible"] = r["valid"], r["passed"], feasible
    return cols


def samplers(sw: Sweep, bounds: list, copies: bool = False):
    """For each chunk ``(start, stop)`` of ``bounds`` in order, the Sobol engine positioned
    at ``start`` (``None`` for a grid): one engine drawn on chunk after chunk, so the
    sequence's work is linear in the sample.  With ``copies`` (chunks evaluated elsewhere,
    in any order) each chunk gets a copy and the one engine skips the chunk's points."""
    if sw.samples is None:
        yield from itertools.repeat(None, len(bounds))
        return
    import copy

    from geardesign.spur.sobol import engine

    eng = engine(len(sw.dims), sw.seed, bounds[0][0] if bounds else 0)
    for a, b in bounds:
        if not copies:
            yield eng
            continue
        yield copy.deepcopy(eng)
        eng.fast_forward(b - a)




def evaluate_task(spec_data: dict, sw: Sweep, start: int, stop: int, chunk: int,
                  sampler=None) -> dict:
    """The merged summary of candidates ``start`` … ``stop − 1`` evaluated chunk by chunk
    (``chunk`` candidates at a time, so a task's memory is one chunk's whatever its size):
    the work of one task of a worker process or a Dask worker, large enough that the cost of
    sending it is small beside its evaluation.  ``sampler`` as for :func:`evaluate_chunk`."""
    bounds = [(a, min(a + chunk, stop)) for a in range(start, stop, chunk)]
    engines = samplers(sw, bounds) if sampler is None else itertools.repeat(sampler)
    out = Summary(sw)
    for (a, b), e in zip(bounds, engines):
        out.add(evaluate_chunk(spec_data, sw, a, b, False, e))
    return out.result()


def run_task(spec_data: dict, sw: Sweep, bounds: tuple, rows: bool, chunk: int, sampler):
    """One task of a parallel run: a chunk with its rows, or a range of chunks merged."""
    a, b = bounds
    if rows:
        return evaluate_chunk(spec_data, sw, a, b, True, sampler)
    return evaluate_task(spec_data, sw, a, b, chunk, sampler)
