"""Time every spec in specs/ as a whole cold process (the way a user runs it).

    python benchmarks/time_specs.py [--runs 7] [--format json] [--no-bytecode]

Prints the median and the best wall time of `python -m geardesign run SPEC` per spec, and
of `python -c pass` (the interpreter's own start-up) for comparison.

By default the compiled bytecode is kept (in a temporary PYTHONPYCACHEPREFIX, warmed by
one run), as after a normal `pip install`.  With --no-bytecode every run compiles the
package from source, as on a machine with PYTHONDONTWRITEBYTECODE=1 and an editable
install (the development machine of this project).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


ENV = dict(os.environ)


def wall(cmd: list[str], runs: int) -> tuple[float, float]:
    subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT, env=ENV)
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT,
                       env=ENV)
        times.append(time.perf_counter() - t0)
    return statistics.median(times), min(times)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--format", default="json", choices=("json", "table", "markdown"))
    ap.add_argument("--no-bytecode", action="store_true",
                    help="compile from source on every run (PYTHONDONTWRITEBYTECODE=1)")
    ap.add_argument("--only", default="", help="time only the specs whose name contains this")
    args = ap.parse_args()
    import tempfile

    if args.no_bytecode:
        ENV["PYTHONDONTWRITEBYTECODE"] = "1"
        ENV.pop("PYTHONPYCACHEPREFIX", None)
    else:
        ENV.pop("PYTHONDONTWRITEBYTECODE", None)
        ENV["PYTHONPYCACHEPREFIX"] = tempfile.mkdtemp(prefix="geardesign-pyc-")
    print("bytecode:", "compiled every run" if args.no_bytecode else "cached (as installed)")
    base = wall([sys.executable, "-c", "pass"], args.runs)
    print(f"{'spec':45s} {'median s':>9s} {'best s':>8s}")
    print(f"{'(python -c pass)':45s} {base[0]:9.3f} {base[1]:8.3f}")
    worst = 0.0
    for spec in sorted((ROOT / "specs").glob("*.toml")):
        if args.only not in spec.name:
            continue
        command = "sweep" if "\n[sweep]" in spec.read_text(encoding="utf-8") else "run"
        med, best = wall([sys.executable, "-m", "geardesign", command, str(spec), "--format",
                          args.format], args.runs)
        worst = max(worst, med)
        print(f"{spec.name:45s} {med:9.3f} {best:8.3f}")
    print(f"slowest median: {worst:.3f} s (target: well under 0.5 s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
