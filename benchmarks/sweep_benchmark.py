"""Candidates per second of the vectorised spur kernel on one core: geometry with shifts,
the error checks and the GOST 21354-87 or the ISO 6336:2019 fatigue rating (what
`geardesign sweep` runs per chunk), and the same through the whole sweep (candidate
generation, constraints, ranking, front).  Run: python benchmarks/sweep_benchmark.py"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from geardesign.core.registry import load_data
from geardesign.core.spec import load_toml
from geardesign.spur import sweep as SW
from geardesign.spur.kernel import evaluate, fixed_from_spec

SPECS = Path(__file__).resolve().parent.parent / "specs"
SPEC = SPECS / "sweep_spur_reducer.toml"
SPEC_ISO = SPECS / "sweep_spur_iso.toml"


def _fixed(path: Path):
    data = load_toml(path)
    data.pop("sweep")
    _, spec = load_data(data, "bench")
    return fixed_from_spec(spec)


def main() -> None:
    n = 1_000_000
    rng = np.random.default_rng(0)
    c = dict(m_n=rng.choice([2.0, 2.5, 3.0, 4.0, 5.0], n),
             z1=rng.integers(17, 40, n).astype(float), z2=rng.integers(40, 160, n).astype(float),
             x1=rng.uniform(-0.3, 0.8, n), x2=rng.uniform(-0.3, 0.8, n),
             beta=np.radians(rng.uniform(0.0, 20.0, n)), b_w=rng.uniform(20.0, 80.0, n))
    size = SW.CHUNK
    part = {k: v[:size] for k, v in c.items()}
    for path, name in ((SPEC, "GOST 21354-87"), (SPEC_ISO, "ISO 6336:2019")):
        fixed = _fixed(path)
        evaluate(part, fixed)
        t = time.perf_counter()
        reps = 5
        for _ in range(reps):
            evaluate(part, fixed)
        dt = (time.perf_counter() - t) / reps
        print(f"kernel (geometry + checks + {name}): {size / dt:,.0f} candidates/s "
              f"(chunk of {size:,})")
    for path, name in ((SPEC, "GOST 21354-87"), (SPEC_ISO, "ISO 6336:2019")):
        sweep_data, sw = SW.load_sweep(load_toml(path), "bench", ["gear.module=1.5:6:0.05"],
                                       None, None)
        t = time.perf_counter()
        out = SW.run_sweep(sweep_data, sw)
        dt = time.perf_counter() - t
        print(f"whole sweep, {name} ({sw.size:,} candidates, full grid): "
              f"{sw.size / dt:,.0f} candidates/s, {out['counts']['feasible']} feasible")


if __name__ == "__main__":
    main()
