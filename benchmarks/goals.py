"""The performance goals of the command line, each figure beside its yardstick, in one run.

    python benchmarks/goals.py [--runs 5] [--samples 1000000] [--quick] [--only startup]

Every figure is the CPU time (user + system, ``getrusage(RUSAGE_CHILDREN)``) of whole
cold processes, the way a user runs them; the median of ``--runs`` runs, each run
alternating with one of its yardstick so that the load of a busy machine falls on both
alike.  Compiled bytecode is kept in a temporary ``PYTHONPYCACHEPREFIX`` (as after a
``pip install``).  Dask is timed in wall-clock seconds (parallelism is its point).

1. start-up: ``--help``, ``list``, ``template``, ``validate`` and the cold median over the
   example specs against ``python -c pass`` (the interpreter floor) and
   ``python -c "import numpy"``; the slowest specs.
2. sweeps: candidates per CPU-second end to end (GOST 21354 and ISO 6336 ratings, a Sobol
   sample of ``--samples``), and the fixed cost of ``--samples`` over a grid sweep.
3. Dask: a 2-worker LocalCluster (:func:`geardesign.spur.sweep.local_cluster`) against one
   local process, and whether their summaries are identical.
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


def sweeps(runs: int, samples: int) -> None:
    print(f"2. sweeps (CPU, Sobol sample of {samples:,}, whole process)")
    floor = [PY, "-c", "pass"]
    for spec, name in (("sweep_spur_reducer.toml", "GOST 21354-87"),
                       ("sweep_spur_iso.toml", "ISO 6336:2019")):
        t, f = paired(gd("sweep", f"specs/{spec}", "--samples", str(samples), "--seed", "1",
                         "-q"), floor, max(1, runs // 3))
        print(f"   {name:14s} {samples / t:12,.0f} candidates per CPU-second ({t:6.2f} s)")
    with tempfile.TemporaryDirectory() as tmp:
        small = Path(tmp) / "small.toml"
        base = (ROOT / "specs" / "sweep_spur_reducer.toml").read_text("utf-8")
        small.write_text(base.split("[sweep]")[0] + SMALL_GRID, encoding="utf-8")
        t, g = paired(gd("sweep", str(small), "--samples", "24", "--seed", "1", "-q"),
                      gd("sweep", str(small), "-q"), runs)
    print(f"   fixed cost of --samples over a grid sweep of 24: {(t - g) * 1e3:7.1f} ms "
          f"(grid {g * 1e3:.0f} ms, sample {t * 1e3:.0f} ms)")


def dask(samples: int) -> None:
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
    t0 = time.perf_counter()
    one = SW.run_sweep(data, sw)
    t_one = time.perf_counter() - t0
    def on(cluster):
        with cluster, distributed.Client(cluster) as client:
            client.run(_warm)            # the workers' imports are start-up, not sweep
            t0 = time.perf_counter()
            res = SW.run_sweep(data, sw, scheduler=cluster.scheduler_address)
            return time.perf_counter() - t0, res

    t_two, two = on(SW.local_cluster(2))
    t_dflt, _ = on(distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                            dashboard_address=None))
    same = one["counts"] == two["counts"] and all(
        np.array_equal(one[part][k], two[part][k]) for part in ("head", "front")
        for k in one[part])
    print(f"3. Dask, {samples:,} candidates (wall): one local process {t_one:6.2f} s, "
          f"2-worker local_cluster {t_two:6.2f} s = {t_one / t_two:4.2f} x faster "
          f"(with Dask's default MALLOC_TRIM_THRESHOLD_ {t_dflt:6.2f} s); "
          f"summaries {'identical' if same else 'DIFFER'}")


def _warm() -> None:
    import geardesign.spur.kernel  # noqa: F401
    import geardesign.spur.sweep  # noqa: F401


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--samples", type=int, default=1_000_000)
    ap.add_argument("--quick", action="store_true", help="every sixth example spec only")
    ap.add_argument("--only", choices=("startup", "sweeps", "dask"), help="one goal only")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as cache:
        ENV["PYTHONPYCACHEPREFIX"] = cache
        if args.only in (None, "startup"):
            startup(args.runs, args.quick)
        if args.only in (None, "sweeps"):
            sweeps(args.runs, args.samples)
    if args.only in (None, "dask"):
        dask(args.samples)
    return 0


if __name__ == "__main__":
    sys.exit(main())
