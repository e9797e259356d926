"""Long fuzz run: ``python benchmarks/fuzz_long.py [N] [--workers W] [--seed S]``.

Mutates the example specs N times (default 100 000) with the engine of ``tests/fuzz.py``
(schema fields at their bounds, degenerate numbers, swapped types, deleted and added keys,
resized arrays), in W processes, computes each case and renders it in every report format
(the slow rich table every ``--table-every`` cases).  Prints the count of internal errors
(what the command line reports as exit 3: an exception, a renderer crash, a timeout), of
non-finite values (NaN or infinity in a document, ``nan``/``inf`` in a message), of input
errors naming no key, the peak memory of a worker and the mean time per case; then each
distinct signature with its count and the first case that produced it.  Exit status 1
when anything was found.
"""

from __future__ import annotations

import argparse
import collections
import json
import os
import resource
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
# as the command line and the test suite do: one OpenBLAS thread (its spinning threads count
# towards the CPU-time bound of a case on a busy machine); read when numpy is first imported
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

from tests import fuzz  # noqa: E402

CHUNK = 250


def _chunk(args):
    seed, n, table_every = args
    found = []
    other = tuple(f for f in fuzz.FORMATS if f != "table")
    for i, (data, source, base) in enumerate(fuzz.cases(seed, n, include_slow=True)):
        formats = other + (("table",) if i % table_every == 0 else ())
        sig = fuzz.run_case(data, source, base, seconds=60, formats=formats)
        if sig:
            found.append((sig, json.dumps(data, default=str)[:2000]))
    return found, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def classify(sig: str) -> str:
    """``non-finite``, ``nameless`` (an input error naming no key) or ``exit 3``."""
    if "garbage:" in sig or "non-finite" in sig:
        return "non-finite"
    if "input error naming no key" in sig:
        return "nameless"
    return "exit 3"


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("n", nargs="?", type=int, default=100_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--table-every", type=int, default=10,
                    help="render the rich table every this many cases (1: every case)")
    ap.add_argument("--progress", action="store_true", help="a line on stderr per chunk")
    a = ap.parse_args()
    chunks = [(a.seed * 100003 + i, min(CHUNK, a.n - i * CHUNK), a.table_every)
              for i in range((a.n + CHUNK - 1) // CHUNK)]
    counts, first, peak = collections.Counter(), {}, 0
    start = time.perf_counter()
    with ProcessPoolExecutor(a.workers) as ex:
        for done, (found, rss) in enumerate(ex.map(_chunk, chunks), 1):
            peak = max(peak, rss)
            for sig, case in found:
                counts[sig] += 1
                first.setdefault(sig, case)
            if a.progress:
                print(f"  {done * CHUNK} cases, {time.perf_counter() - start:.0f} s, "
                      f"{sum(counts.values())} failures, peak {peak / 1024:.0f} MiB",
                      file=sys.stderr, flush=True)
    wall = time.perf_counter() - start
    n = sum(c[1] for c in chunks)
    classes = collections.Counter()
    for sig, k in counts.items():
        classes[classify(sig)] += k
    print(f"{n} cases in {wall:.0f} s with {a.workers} workers: "
          f"{1000 * wall * a.workers / max(n, 1):.1f} ms per case (one core)")
    print(f"exit 3: {classes['exit 3']}, non-finite: {classes['non-finite']}, "
          f"input errors naming no key: {classes['nameless']}, "
          f"peak memory of a worker: {peak / 1024:.0f} MiB")
    print(f"{sum(counts.values())} failures, {len(counts)} signatures")
    for sig, k in counts.most_common():
        print(f"{k:6d}  {sig}\n        {first[sig][:400]}")
    return 1 if sum(classes.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
