"""Design sweeps of a spur/helical pair: every variant of a grid (or a Sobol sample) of the
gear data, rated by the vectorised kernel (:mod:`geardesign.spur.kernel`), filtered by the
checks and the constraints, ranked by the objectives, with the Pareto front of the first two.

A sweep spec is a spur spec (the base design: materials, load, every key not varied) with a
``[sweep]`` table::

    [sweep]
    "gear.module" = {values = [2.0, 2.5, 3.0]}
    "gear.z1" = {from = 18, to = 30, step = 1}
    "gear.face_width" = {from = 30.0, to = 60.0, step = 5.0}
    ratio = [3.9, 4.1]               # window of u = z2/z1 (constraint)
    center_distance_range = [0.0, 160.0]
    psi_bd = [0.2, 1.6]              # window of b_w/d_w1 (default: that of the spur check)
    psi_ba = [0.1, 1.25]             # window of b_w/a_w (default: the GOST 2185-66 series)
    min_margin = 1.0                 # the smallest reserve of the rating (1 = just passes)
    objectives = ["mass", "margin"]  # ranked by the first, then the second
    top = 20

Evaluation runs in chunks of :data:`CHUNK` candidates, so memory stays bounded whatever the
size (the ranked head and the front are merged chunk by chunk); ``workers`` local processes
or a Dask cluster (``scheduler``) evaluate chunks in parallel, and the result is the same.
"""

from __future__ import annotations

import itertools

from geardesign.spur.sweep_chunk import candidates, evaluate_chunk, run_task, samplers
from geardesign.spur.sweep_dask import SchedulerError, connect, local_cluster, on_cluster
from geardesign.spur.sweep_input import (COLUMNS, FIXED_KEYS, FULL_CHECKS, MATERIAL_COLUMNS,
                                         MATERIAL_KEYS, MAX_GRID, MAX_POINTS, MAX_SAMPLES,
                                         OBJECTIVES, VARIABLE, Dim, Sweep, load_sweep,
                                         parse_sweep, parse_vary, rating_method)
from geardesign.spur.sweep_rank import Summary, range_edges
from geardesign.spur.sweep_recheck import full_check, variant_spec
from geardesign.spur.sweep_report import sweep_result

__all__ = ["CHUNK", "COLUMNS", "FIXED_KEYS", "FULL_CHECKS", "MATERIAL_COLUMNS", "MATERIAL_KEYS",
           "MAX_GRID", "MAX_POINTS", "MAX_SAMPLES", "OBJECTIVES", "VARIABLE", "Dim",
           "SchedulerError", "Sweep", "candidates", "connect", "evaluate_chunk", "full_check",
           "load_sweep", "local_cluster", "parse_sweep", "parse_vary", "range_edges",
           "rating_method", "run_data", "run_sweep", "samplers", "sweep_result", "task_bounds",
           "variant_spec"]

CHUNK = 50_000
"""Candidates per kernel call (the arrays of one chunk at a time: a sweep of 10⁷ candidates
peaks at about 95 MB by GOST 21354-87, 120 MB by ISO 6336, 190 MB with a Parquet dataset,
interpreter and numpy included)."""


TASK_CHUNKS = 8
"""Most chunks in one task of a worker process or a Dask worker (a task evaluates its chunks
one after the other, merging their summaries: memory of one chunk, the cost of sending a task
spread over up to 8 chunks)."""

TASKS_PER_WORKER = 8
"""Tasks per worker at least (a sample of 10⁶ in tasks of 100 000 candidates), so that the
workers finish together."""


def task_bounds(total: int, workers: int, rows: bool) -> list:
    """The ``(start, stop)`` of each task of a parallel run: whole chunks, at most
    :data:`TASK_CHUNKS` of them, at least :data:`TASKS_PER_WORKER` tasks per worker when
    there are chunks enough; one chunk per task when every candidate's row is returned
    (``--data``: a task's rows are held until written)."""
    chunks = -(-total // CHUNK)
    per = 1 if rows else max(1, min(TASK_CHUNKS, chunks // (TASKS_PER_WORKER * workers)))
    size = per * CHUNK
    return [(s, min(s + size, total)) for s in range(0, total, size)]


def run_sweep(spec_data: dict, sw: Sweep, workers: int = 1, scheduler: str | None = None,
              progress=None, rows_sink=None) -> dict:
    """Evaluate the whole sweep chunk by chunk (in parallel when asked) and return the
    merged summary: counts, failing checks, the ranked head and the Pareto front."""
    total = sw.size
    rows = rows_sink is not None
    summary = Summary(sw)

    def take(res):
        summary.add(res)
        if rows_sink is not None:
            rows_sink(res["rows"])
        if progress is not None:
            progress(res["counts"]["evaluated"])

    if scheduler is not None:
        for res in on_cluster(scheduler, spec_data, sw, rows, CHUNK,
                              lambda n: task_bounds(total, n, rows)):
            take(res)
    elif workers > 1 and total > CHUNK:
        from concurrent.futures import ProcessPoolExecutor

        from geardesign.core.io import worker_signals

        bounds = task_bounds(total, workers, rows)
        pool = ProcessPoolExecutor(max_workers=min(workers, len(bounds)),
                                   initializer=worker_signals)
        try:
            for res in pool.map(run_task, itertools.repeat(spec_data), itertools.repeat(sw),
                                bounds, itertools.repeat(rows), itertools.repeat(CHUNK),
                                samplers(sw, bounds, copies=True)):
                take(res)
        except BaseException:     # Ctrl-C or an error: stop at once, no queued chunk runs
            pool.shutdown(wait=False, cancel_futures=True)
            raise
        pool.shutdown()
    else:
        bounds = [(s, min(s + CHUNK, total)) for s in range(0, total, CHUNK)]
        for (a, b), e in zip(bounds, samplers(sw, bounds)):
            take(evaluate_chunk(spec_data, sw, a, b, rows, e))
    return summary.result()


def run_data(data: dict, source: str = ""):
    """The :class:`~geardesign.core.result.Result` of a parsed sweep spec, run in this
    process (what ``geardesign check`` compares with the golden file)."""
    base, sw = load_sweep(data, source)
    return sweep_result(base, sw, run_sweep(base, sw), source)
