"""The cost of the HTML report as a cold process, and what it imports.

    python benchmarks/time_report.py [--runs 7] [SPEC]

Times `python -m geardesign run SPEC --format json`, `--format html` and `--format html
--plot FILE.png` (a spur spec: the mesh plot through matplotlib), median and best of
--runs, with the bytecode kept as after `pip install`, and lists the largest imports of the
HTML run (python -X importtime): without --plot, matplotlib is never imported and the HTML
costs the report modules only.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def wall(cmd: list[str], runs: int, env: dict) -> tuple[float, float]:
    subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True)      # warm the bytecode
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True)
        times.append(time.perf_counter() - t)
    return statistics.median(times), min(times)


def imports(cmd: list[str], env: dict) -> list[tuple[int, str]]:
    r = subprocess.run([sys.executable, "-X", "importtime", *cmd[1:]], cwd=ROOT, env=env,
                       capture_output=True, text=True)
    out = []
    for line in r.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            parts = [p.strip() for p in line[len("import time:"):].split("|")]
            if parts[1].isdigit():
                out.append((int(parts[1]), parts[2]))
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("spec", nargs="?", default="specs/spur_plain.toml")
    ap.add_argument("--runs", type=int, default=7)
    a = ap.parse_args()
    tmp = Path(tempfile.mkdtemp())
    env = {**os.environ, "PYTHONPYCACHEPREFIX": str(tmp / "pycache")}
    base = [sys.executable, "-m", "geardesign", "run", a.spec]
    cases = {"json": base + ["--format", "json", "-o", str(tmp / "r.json")],
             "html": base + ["--format", "html", "-o", str(tmp / "r.html")],
             "html + --plot png": base + ["--format", "html", "-o", str(tmp / "r.html"),
                                          "--plot", str(tmp / "p.png")]}
    for name, cmd in cases.items():
        med, best = wall(cmd, a.runs, env)
        print(f"{name:<20} median {med:.3f} s   best {best:.3f} s")
    top = sorted(imports(cases["html"], env), reverse=True)
    names = {n for _, n in top}
    print("html run imports matplotlib:", any(n.startswith("matplotlib") for n in names))
    print("largest cumulative imports of the html run (µs):")
    for us, name in [t for t in top if "." not in t[1]][:8]:
        print(f"  {us:>8}  {name}")
    print("report modules:", ", ".join(sorted(n for n in names if n.startswith(
        "geardesign.rendering"))))


if __name__ == "__main__":
    main()
