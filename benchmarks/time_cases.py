"""Speed goals of cases that are not example specs, timed (the tests only guard against
unbounded work; see tests/conftest.py, ``bounded_work``).

    python benchmarks/time_cases.py [--runs 5]

* a three-shaft drive as a cold process (two GOST stages, three analysed shafts, four keys
  and a fit: the golden spec drive_reducer_shafts_keys_thermal without the heat balance),
  goal 0.3 s;
* a five-stage spur drive as a cold process, goal 0.5 s;
* the widest 3K tooth-number search of the planetary synthesis in process, goal 1 s;
* a bearing load spectrum of 100 000 blocks in process, goal 2 s; its mean load, 0.5 s.

Cold processes keep the compiled bytecode (a temporary PYTHONPYCACHEPREFIX warmed by one
run, as after ``pip install``).  Prints the median and the best of the runs and each goal;
the figures of the development machine are in README.md (Performance).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from benchmarks.time_specs import ENV, wall  # noqa: E402


def _timed(fn, runs: int) -> tuple[float, float]:
    fn()
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), min(times)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    from geardesign.bearing import life as L
    from geardesign.bearing.assess import Bearing, Block, Conditions, assess
    from geardesign.planetary import synthesis as S
    from tests.test_drive import five_stage_text
    from tests.test_drive_shafts import fast_text

    ENV.pop("PYTHONDONTWRITEBYTECODE", None)
    ENV["PYTHONPYCACHEPREFIX"] = tempfile.mkdtemp(prefix="geardesign-pyc-")
    folder = Path(tempfile.mkdtemp(prefix="geardesign-cases-"))
    rows = []
    for name, text, goal in (("three-shaft drive (cold process)", fast_text(), 0.3),
                             ("five-stage drive (cold process)", five_stage_text(), 0.5)):
        path = folder / (name.split()[0] + ".toml")
        path.write_text(text, encoding="utf-8")
        rows.append((name, *wall([sys.executable, "-m", "geardesign", "run", str(path),
                                  "--format", "json"], args.runs), goal))
    widest = ("3K", 3, "ring", "sun", "ring2", 300.0, 20.0, 6, 6, 1000, 6)
    rows.append(("widest 3K synthesis search",
                 *_timed(lambda: S.candidates(*widest, keep=S.MAX_EVALUATED), args.runs), 1.0))
    bearing = Bearing("deep_groove_ball", C_r=32500.0, C_0r=19000.0, f0=14.0, D_pw=60.0)
    blocks = [Block(1000.0 + (i % 7), 100.0 * (i % 3), 500.0 + i % 11, 1e-5)
              for i in range(100000)]
    rows.append(("bearing spectrum, 100 000 blocks", *_timed(
        lambda: assess(bearing, blocks, Conditions("gost18855_94", a23=1.0)), args.runs), 2.0))
    F = [1000.0 + i % 7 for i in range(100000)]
    rows.append(("mean load of 100 000 blocks", *_timed(
        lambda: L.spectrum_mean(F, [1000.0] * 100000, [1e-5] * 100000, 3.0), args.runs), 0.5))
    print(f"cpu count {os.cpu_count()}, load average {os.getloadavg()[0]:.2f}")
    print(f"{'case':40s} {'median s':>9s} {'best s':>8s} {'goal s':>7s}")
    late = 0
    for name, med, best, goal in rows:
        late += med > goal
        print(f"{name:40s} {med:9.3f} {best:8.3f} {goal:7.2f}{'  over' if med > goal else ''}")
    return 1 if late else 0


if __name__ == "__main__":
    sys.exit(main())
