"""The Sobol sample of ``geardesign sweep --samples``: the points of SciPy's engine, and work
linear in the sample (the generator's steps are counted per chunk, never timed)."""

from __future__ import annotations

import subprocess
import sys
import warnings

import numpy as np
import pytest

from geardesign.core.spec import load_toml
from geardesign.spur import sobol
from geardesign.spur import sweep as SW
from tests.test_sweep import SPEC


@pytest.mark.parametrize("d, seed", [(1, 0), (3, 7), (6, 12345)])
def test_points_are_scipys_drawn_in_any_chunks(d, seed):
    from scipy.stats import qmc

    ref = qmc.Sobol(d=d, scramble=True, seed=seed)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        want = ref.random(3000)
    eng = sobol.engine(d, seed)
    got = np.vstack([eng.random(n) for n in (1, 999, 1024, 976)])
    assert np.array_equal(got, want)
    assert np.array_equal(sobol.engine(d, seed, start=1234).random(500), want[1234:1734])


def test_the_sample_imports_no_scipy_stats():
    code = ("import sys\nfrom geardesign.spur.sobol import engine\nengine(4, 1).random(8)\n"
            "print('scipy.stats' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip() == "False", done.stderr


class _Counting:
    """Counts the sequence steps an engine takes (drawn or skipped), per call."""

    def __init__(self, monkeypatch):
        self.steps = []
        for cls in {type(sobol.engine(2, 0))}:
            for name in ("random", "fast_forward"):
                real = getattr(cls, name)

                def counted(eng, n, _real=real):
                    self.steps.append(n)
                    return _real(eng, n)

                monkeypatch.setattr(cls, name, counted)


@pytest.mark.parametrize("workers", [1, 2])
def test_generator_work_is_linear_in_the_sample(monkeypatch, workers):
    monkeypatch.setattr(SW, "CHUNK", 500)
    data, sw = SW.load_sweep(load_toml(SPEC), "s", (), 8000, 3)
    count = _Counting(monkeypatch)
    one = SW.run_sweep(data, sw, workers=workers)
    # each chunk costs its own points (drawn, or skipped by the engine that hands out the
    # copies), never the points before it: 16 chunks of 500, not 500 + 1000 + ... + 8000
    assert max(count.steps) == 500
    assert sum(count.steps) <= (1 if workers == 1 else 2) * 8000
    assert one["counts"]["evaluated"] == 8000


def test_chunks_see_the_sample_a_single_draw_gives(monkeypatch):
    data, sw = SW.load_sweep(load_toml(SPEC), "s", (), 3000, 11)
    whole = SW.candidates(sw, 0, 3000)
    bounds = [(0, 1000), (1000, 2000), (2000, 3000)]
    for copies in (False, True):
        parts = [SW.candidates(sw, a, b, e) for (a, b), e in
                 zip(bounds, SW.samplers(sw, bounds, copies=copies))]
        for k in whole:
            assert np.array_equal(np.concatenate([p[k] for p in parts]), whole[k])


def test_local_cluster_workers_keep_glibcs_dynamic_mmap_threshold():
    distributed = pytest.importorskip("distributed")
    import os

    with SW.local_cluster(1) as cluster, distributed.Client(cluster) as client:
        env = client.run(lambda: os.environ.get("MALLOC_TRIM_THRESHOLD_"))
    assert list(env.values()) == [os.environ.get("MALLOC_TRIM_THRESHOLD_")]


def test_a_sample_on_dask_is_the_local_sample(monkeypatch):
    distributed = pytest.importorskip("distributed")
    monkeypatch.setattr(SW, "CHUNK", 700)
    data, sw = SW.load_sweep(load_toml(SPEC), "s", (), 5000, 9)
    one = SW.run_sweep(data, sw)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        dist = SW.run_sweep(data, sw, scheduler=cluster.scheduler_address)
    assert one["counts"] == dist["counts"]
    for part in ("head", "front"):
        for k in one[part]:
            assert np.array_equal(one[part][k], dist[part][k])
