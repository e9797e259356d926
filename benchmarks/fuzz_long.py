"""Long fuzz run: ``python benchmarks/fuzz_long.py [N] [--workers W] [--seed S]``.

Mutates the example specs N times (default 20 000) with the engine of ``tests/fuzz.py``,
in W processes, and prints each distinct crash signature with its count and the first
case that produced it.  Exit status 1 when anything was found.
"""

from __future__ import annotations

import argparse
import collections
import json
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from tests import fuzz  # noqa: E402


def _chunk(args):
    seed, n = args
    found = []
    for data, source, base in fuzz.cases(seed, n, include_slow=True):
        sig = fuzz.run_case(data, source, base)
        if sig:
            found.append((sig, json.dumps(data, default=str)[:2000]))
    return found


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("n", nargs="?", type=int, default=20000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    chunks = [(a.seed * 100003 + i, 250) for i in range((a.n + 249) // 250)]
    counts, first = collections.Counter(), {}
    with ProcessPoolExecutor(a.workers) as ex:
        for found in ex.map(_chunk, chunks):
            for sig, case in found:
                counts[sig] += 1
                first.setdefault(sig, case)
    print(f"{len(chunks) * 250} cases, {sum(counts.values())} failures, "
          f"{len(counts)} signatures")
    for sig, n in counts.most_common():
        print(f"{n:6d}  {sig}\n        {first[sig][:400]}")
    return 1 if counts else 0


if __name__ == "__main__":
    sys.exit(main())
