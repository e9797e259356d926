"""The performance goals of the command line, each figure beside its yardstick, in one run.

    python benchmarks/goals.py [--runs 5] [--samples 10000000] [--dask-samples N]
                               [--only startup|sweeps|dask] [--quick]

Every figure is the CPU time (user + system, ``getrusage(RUSAGE_CHILDREN)``) of whole
cold processes, the way a user runs them; the median of ``--runs`` runs, each run
alternating with one of its yardstick so that the load of a busy machine falls on both
alike.  Compiled bytecode is kept in a temporary ``PYTHONPYCACHEPREFIX`` (as after a
``pip install``).  Dask is timed in wall-clock seconds (parallelism is its point).

1. start-up: ``--help``, ``list``, ``template``, ``validate`` and the cold median over the
   example specs against ``python -c pass`` (the interpreter floor) and
   ``python -c "import numpy"``; the slowest specs.
2. sweeps: candidates per CPU-second end to end (GOST 21354 and ISO 6336 ratings, a Sobol
   sample of ``--samples``), the peak memory (with and without a Parquet dataset), and the
   fixed cost of ``--samples`` over a grid sweep.
3. Dask: a 2-worker LocalCluster (:func:`geardesign.spur.sweep.local_cluster`) against one
   local process in paired runs of alternating order (the spread of their ratio), the CPU
   of the workers and of the client, and whether their summaries are identical.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PY = sys.executable
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}

SMALL_GRID = """[sweep]
"gear.module" = {values = [2.5, 3.0]}
"gear.z1" = {from = 20, to = 26, step = 2}
"gear.face_width" = {from = 40.0, to = 60.0, step = 10.0}
"""
"""The [sweep] of a 24-variant grid, on the base of specs/sweep_spur_reducer.toml."""


def cpu(cmd: list[str]) -> float:
    """CPU seconds (user + system) of one run of ``cmd``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def paired(cmd: list[str], yardstick: list[str], runs: int) -> tuple[float, float]:
    """Medians of CPU seconds of ``cmd`` and ``yardstick``, run alternately."""
    cpu(cmd), cpu(yardstick)        # warm the bytecode and the page cache
    a, b = [], []
    for _ in range(runs):
        a.append(cpu(cmd))
        b.append(cpu(yardstick))
    return statistics.median(a), statistics.median(b)


def gd(*args: str) -> list[str]:
    return [PY, "-m", "geardesign", *args]


def startup(runs: int, quick: bool) -> None:
    floor = [PY, "-c", "pass"]
    numpy = [PY, "-c", "import numpy"]
    f, n = paired(floor, numpy, runs)
    print("1. start-up (CPU, median of paired cold runs)")
    print(f"   python -c pass {f * 1e3:7.1f} ms   python -c 'import numpy' {n * 1e3:7.1f} ms")
    for args in (("--help",), ("list",), ("template", "spur"),
                 ("validate", "specs/spur_design.toml")):
        t, f = paired(gd(*args), floor, runs)
        print(f"   geardesign {' '.join(args):32s} {t * 1e3:7.1f} ms = {t / f:5.1f} x floor")
    specs = sorted((ROOT / "specs").glob("*.toml"))
    if quick:
        specs = specs[::6]
    per = []
    for spec in specs:
        t, f = paired(gd("run", str(spec), "-f", "json"), floor, max(3, runs // 2))
        per.append((t, f, spec.stem))
    med = statistics.median(t for t, _, _ in per)
    fmed = statistics.median(f for _, f, _ in per)
    print(f"   cold median over {len(per)} example specs {med * 1e3:7.1f} ms = "
          f"{med / fmed:5.1f} x floor (goal <= 8), {med / n:4.2f} x import numpy")
    for t, _, name in sorted(per, reverse=True)[:5]:
        print(f"     slowest: {name:44s} {t:6.3f} s")


def peak(cmd: list[str]) -> tuple[float, float]:
    """CPU seconds and peak resident memory [MB] of one run of ``cmd`` (``wait4``)."""
    proc = subprocess.Popen(cmd, cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    _, _, use = os.wait4(proc.pid, 0)
    return use.ru_utime + use.ru_stime, use.ru_maxrss / 1024.0


def sweeps(runs: int, samples: int) -> None:
    print(f"2. sweeps (CPU, Sobol sample of {samples:,}, whole process)")
    floor = [PY, "-c", "pass"]
    for spec, name in (("sweep_spur_reducer.toml", "GOST 21354-87"),
                       ("sweep_spur_iso.toml", "ISO 6336:2019")):
        cmd = gd("sweep", f"specs/{spec}", "--samples", str(samples), "--seed", "1", "-q")
        t, f = paired(cmd, floor, max(1, runs // 3))
        with tempfile.TemporaryDirectory() as tmp:
            _, mb = peak(cmd)
            _, mb_data = peak(cmd + ["--data", str(Path(tmp) / "rows.parquet")])
        print(f"   {name:14s} {samples / t:12,.0f} candidates per CPU-second ({t:6.2f} s); "
              f"peak memory {mb:5.0f} MB, {mb_data:5.0f} MB with a Parquet dataset")
    with tempfile.TemporaryDirectory() as tmp:
        small = Path(tmp) / "small.toml"
        base = (ROOT / "specs" / "sweep_spur_reducer.toml").read_text("utf-8")
        small.write_text(base.split("[sweep]")[0] + SMALL_GRID, encoding="utf-8")
        t, g = paired(gd("sweep", str(small), "--samples", "24", "--seed", "1", "-q"),
                      gd("sweep", str(small), "-q"), runs)
    print(f"   fixed cost of --samples over a grid sweep of 24: {(t - g) * 1e3:7.1f} ms "
          f"(grid {g * 1e3:.0f} ms, sample {t * 1e3:.0f} ms)")


def _cpu_self() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def dask(samples: int, runs: int) -> None:
    """One local process against a 2-worker ``local_cluster``, ``runs`` paired runs in
    alternating order (the load of a shared machine falls on both alike): the median wall
    times and their ratio with its spread, the CPU seconds of each worker and of the client
    with the scheduler (one process), and whether the summaries are identical."""
    try:
        import distributed
    except ImportError:
        print("3. Dask: dask.distributed not installed")
        return
    sys.path.insert(0, str(ROOT))
    import numpy as np

    from geardesign.core.spec import load_toml
    from geardesign.spur import sweep as SW

    data, sw = SW.load_sweep(load_toml(ROOT / "specs" / "sweep_spur_reducer.toml"), "bench",
                             (), samples, 1)
    _, warm = SW.load_sweep(load_toml(ROOT / "specs" / "sweep_spur_reducer.toml"), "bench",
                            (), 4 * SW.CHUNK, 2)
    ones, twos, ratios, cpu = [], [], [], []
    with SW.local_cluster(2) as cluster, distributed.Client(cluster) as client:
        client.run(_warm)                # the workers' imports are start-up, not sweep
        SW.run_sweep(data, warm, scheduler=cluster.scheduler_address)
        SW.run_sweep(data, warm)
        for i in range(runs):
            t_one = t_two = 0.0
            for local in ((True, False) if i % 2 == 0 else (False, True)):
                if local:
                    t0 = time.perf_counter()
                    one = SW.run_sweep(data, sw)
                    t_one = time.perf_counter() - t0
                    continue
                w0, c0 = client.run(_cpu_self), _cpu_self()
                t0 = time.perf_counter()
                two = SW.run_sweep(data, sw, scheduler=cluster.scheduler_address)
                t_two = time.perf_counter() - t0
                w1, c1 = client.run(_cpu_self), _cpu_self()
                cpu.append(([w1[k] - w0[k] for k in w0], c1 - c0))
            ones.append(t_one)
            twos.append(t_two)
            ratios.append(t_one / t_two)
    same = one["counts"] == two["counts"] and all(
        np.array_equal(one[part][k], two[part][k]) for part in ("head", "front")
        for k in one[part])
    t_one, t_two = statistics.median(ones), statistics.median(twos)
    workers = [statistics.median(w[i] for w, _ in cpu) for i in range(2)]
    client_cpu = statistics.median(c for _, c in cpu)
    print(f"3. Dask, {samples:,} candidates (wall, median of {runs} paired runs in "
          f"alternating order): one local process {t_one:6.2f} s, 2-worker local_cluster "
          f"{t_two:6.2f} s = {statistics.median(ratios):4.2f} x faster (runs "
          f"{min(ratios):.2f} … {max(ratios):.2f}); summaries "
          f"{'identical' if same else 'DIFFER'}")
    print(f"   CPU of the cluster run: workers {workers[0]:.2f} s + {workers[1]:.2f} s, "
          f"client and scheduler {client_cpu:.2f} s (on a machine with two idle cores the "
          f"wall time is about the larger worker's)")


def _warm() -> None:
    import geardesign.spur.kernel  # noqa: F401
    import geardesign.spur.sweep  # noqa: F401


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--samples", type=int, default=10_000_000)
    ap.add_argument("--dask-samples", type=int, default=None,
                    help="candidates of the Dask comparison (default: --samples)")
    ap.add_argument("--only", choices=("startup", "sweeps", "dask"), default=None,
                    help="run one goal only")
    ap.add_argument("--quick", action="store_true", help="every sixth example spec only")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        ENV["PYTHONPYCACHEPREFIX"] = cache
        if args.only in (None, "startup"):
            startup(args.runs, args.quick)
        if args.only in (None, "sweeps"):
            sweeps(args.runs, args.samples)
    if args.only in (None, "dask"):
        dask(args.dask_samples or args.samples, max(3, args.runs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
