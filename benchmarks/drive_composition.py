"""CPU time of composed drives, before and after, side by side in one process.

    python benchmarks/drive_composition.py [--base 5a58329] [--rounds 15]

The package at ``--base`` (a commit: checked out into a temporary ``git worktree``) and
the package of this checkout are both imported into this one process, each under its own
``sys.modules`` (swapped in for its calls, so that the imports inside functions resolve
to the right version).  Each round times one warm run of each spec by each version
(``time.process_time``: CPU time of the process, one BLAS thread), alternating which
version goes first; the figures are the medians over the rounds and the median of the
paired ratios old/new.  The cases: the drive golden with shafts, keys and heat balance
(``specs/drive_reducer_shafts_keys_thermal.toml``), a two-stage drive rated by GOST
21354-87 and ISO 6336 (``specs/drive_two_stage_reducer.toml`` with both methods), and the
spur golden ``specs/spur_plain.toml`` for scale.  A run is the calculator's ``compute``
and the JSON document of its result.

``--instructions`` counts instead of timing (``valgrind --tool=callgrind``: a count no
other load on the machine moves): the cold processes of the drive golden and
``spur_plain`` of each version, their ratio, and the floor of that ratio for this checkout:
the cold ``spur_plain`` process plus one warm run of the drive golden (validation,
calculation and JSON text in a process that has imported everything already), over
the cold ``spur_plain`` process: what the drive golden would cost if each module it
needs beyond the spur calculator's were free to import.

``--cold N`` adds the cold ratio of the issue's acceptance: N alternating runs of
``python -m geardesign run SPEC -f json`` of each version, the drive golden and
``specs/spur_plain.toml``, each a new process; its CPU time (user + system, from
``resource.getrusage(RUSAGE_CHILDREN)``), medians over the runs; with the bytecode kept
(as after ``pip install``), or ``--no-bytecode``: compiled in every process.

Figures (2 shared cores under load, 7-15 rounds, 7 cold runs, against 5a58329): drive
golden 89-154 -> 28-48 ms (3.2-3.8x over seven runs at load averages of 0.8-4.6),
two-stage GOST + ISO drive 452-707 -> 72-109 ms (5.8-6.7x); cold drive golden / spur_plain
with the bytecode kept 2.04-2.21 (379-499 / 172-245 ms; 5a58329 on the same machine:
2.55-2.80), compiled in every process 1.60 (1089 / 683 ms; 5a58329: 2.17, measured before
the probe pass went unrated).  With the records made without compiling, the JSON indented around the C encoder and the data files kept
parsed (``--base fa84a7d --rounds 3 --cold 7``, bytecode kept): 224 -> 148 ms / 82 -> 69 ms,
ratio 2.73 -> 2.14 (three runs under a varying load: 1.99-2.73 -> 1.84-2.29).  With the
JSON document of a cleaned result taking its values as they are (``--base 2444eba
--rounds 3 --cold 9``, five runs, bytecode kept, load averages 1-2): ratio 2.03-2.28
(median 2.15) -> 2.04-2.41 (median 2.07), within the spread of the load; instructions
counted by ``valgrind --tool=callgrind`` (no load disturbs them): drive golden 679.1 ->
670.6-672.7 M, spur_plain 270.8 -> 270.8-271.1 M, ratio 2.51 -> 2.47-2.48.
``--instructions`` at 2276e12: 5a58329 drive golden 2244.3 M, spur_plain 586.2 M (ratio
3.83); this checkout 672.5 M / 271.2 M (ratio 2.48); one warm run of the drive golden
276.1 M, so the floor of the ratio with every further module free to import is 2.02: the
drive's own calculation and document alone cost what the whole cold spur_plain process
costs.  Against the fixed yardstick, spur_plain at 5a58329: 672.5 / 586.2 = 1.15.
"""

from __future__ import annotations

import argparse
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import contextlib  # noqa: E402
import copy  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"


def _ours() -> dict:
    return {k: m for k, m in sys.modules.items()
            if k == "geardesign" or k.startswith("geardesign.")}


def load_version(root: Path) -> dict:
    """Import ``geardesign`` from ``root`` into its own set of modules."""
    saved = _ours()
    for k in saved:
        del sys.modules[k]
    sys.path.insert(0, str(root))
    try:
        import geardesign.core.registry  # noqa: F401
        import geardesign.core.spec  # noqa: F401
        mods = _ours()
    finally:
        sys.path.remove(str(root))
        for k in _ours():
            del sys.modules[k]
        sys.modules.update(saved)
    assert Path(mods["geardesign"].__file__).resolve().is_relative_to(root.resolve())
    return mods


@contextlib.contextmanager
def active(mods: dict):
    saved = _ours()
    for k in saved:
        del sys.modules[k]
    sys.modules.update(mods)
    try:
        yield mods
    finally:
        mods.update(_ours())          # modules imported lazily during the call stay
        for k in _ours():
            del sys.modules[k]
        sys.modules.update(saved)


def two_methods(data: dict) -> dict:
    """The two-stage reducer with both stages rated by GOST 21354-87 and ISO 6336."""
    d = copy.deepcopy(data)
    for st in d["stage"]:
        st.setdefault("options", {})["methods"] = ["GOST 21354-87", "ISO 6336:2019"]
        st["options"].pop("method", None)
        st.get("load", {}).pop("regime", None)
    d["load"].pop("method", None)
    return d


def runner(mods: dict, name: str, transform=None):
    with active(mods):
        reg = sys.modules["geardesign.core.registry"]
        spec_mod = sys.modules["geardesign.core.spec"]
        path = SPECS / name
        data = spec_mod.load_toml(path)
    if transform is not None:
        data = transform(data)

    def run() -> float:
        with active(mods):
            d = copy.deepcopy(data)
            t0 = time.process_time()
            calc, spec = reg.load_data(d, str(path))
            spec.base_dir = path.parent
            calc.compute(spec).document()
            return time.process_time() - t0
    return run


CASES = [("drive golden: shafts, keys, heat balance", "drive_reducer_shafts_keys_thermal.toml",
          None),
         ("two-stage drive, GOST 21354-87 + ISO 6336", "drive_two_stage_reducer.toml",
          two_methods),
         ("spur golden (scale)", "spur_plain.toml", None)]


NO_BYTECODE = Path(tempfile.gettempdir()) / "geardesign-no-bytecode"
"""An empty bytecode folder: with PYTHONDONTWRITEBYTECODE nothing is written to it, so a
process finds no bytecode and compiles every module it imports."""


def cold_cpu(name: str, root: Path = ROOT, bytecode: bool = True) -> float:
    """CPU time [s] of one ``python -m geardesign run specs/NAME -f json`` process of the
    package at ``root``; ``bytecode``: with the compiled modules kept (as after ``pip
    install``), else compiled in every process (PYTHONDONTWRITEBYTECODE=1)."""
    import resource

    env = dict(os.environ)
    if bytecode:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    else:      # no bytecode read or written: an empty cache folder elsewhere
        NO_BYTECODE.mkdir(exist_ok=True)
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        env["PYTHONPYCACHEPREFIX"] = str(NO_BYTECODE)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-m", "geardesign", "run", str(SPECS / name), "-f",
                    "json"], cwd=root, env=env, check=False, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cold(runs: int, roots: dict, bytecode: bool = True) -> None:
    """Cold CPU of the drive golden against the spur golden (alternating, medians), for
    each version (``roots``: label -> checkout)."""
    for label, root in roots.items():
        if bytecode:                               # compile once, then keep the bytecode
            cold_cpu("spur_plain.toml", root)
            cold_cpu(CASES[0][1], root)
        drive, spur = [], []
        for i in range(runs):
            pair = [("d", CASES[0][1]), ("s", "spur_plain.toml")]
            for tag, name in (pair if i % 2 == 0 else pair[::-1]):
                (drive if tag == "d" else spur).append(cold_cpu(name, root, bytecode))
        d, s = statistics.median(drive), statistics.median(spur)
        how = "bytecode kept" if bytecode else "compiled every run"
        print(f"cold CPU ({label}, {how}): drive golden {1e3 * d:.0f} ms, spur_plain "
              f"{1e3 * s:.0f} ms, ratio {d / s:.2f}")


WARM = """
import sys
from pathlib import Path
from geardesign.core import registry
from geardesign.core.render import render
path = Path(sys.argv[1])
for _ in range(int(sys.argv[2])):
    calc, spec = registry.load(path, None)
    render([calc.compute(spec)], "json")
"""


def instructions(args: list[str], root: Path) -> int:
    """Instructions of one process ``python ARGS`` run in ``root`` with the bytecode kept,
    counted by ``valgrind --tool=callgrind`` (after one run that writes the bytecode)."""
    import re

    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    subprocess.run([sys.executable, *args], cwd=root, env=env, check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                          sys.executable, *args], cwd=root, env=env, check=False,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True).stderr
    found = re.search(r"Collected : (\d+)", out)
    if found is None:
        raise SystemExit(f"valgrind did not count: {out.strip()[-300:]}")
    return int(found.group(1))


def count(roots: dict) -> None:
    """``--instructions``: cold drive golden / spur_plain in instructions for each version
    (``roots``: label -> checkout), and the floor of the ratio for the last one."""
    drive = str(SPECS / CASES[0][1])
    for label, root in roots.items():
        d = instructions(["-m", "geardesign", "run", drive, "-f", "json"], root)
        s = instructions(["-m", "geardesign", "run", str(SPECS / "spur_plain.toml"), "-f",
                          "json"], root)
        print(f"instructions ({label}): drive golden {d / 1e6:.1f} M, spur_plain "
              f"{s / 1e6:.1f} M, ratio {d / s:.2f}")
    one = instructions(["-c", WARM, drive, "2"], root)
    three = instructions(["-c", WARM, drive, "4"], root)
    warm = (three - one) / 2
    print(f"warm run of the drive golden ({label}): {warm / 1e6:.1f} M; floor of the cold "
          f"ratio with every further module free to import: {(s + warm) / s:.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default="5a58329")
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--cold", type=int, default=0, metavar="N",
                    help="also N alternating cold runs of the drive golden and spur_plain, "
                         "for both versions")
    ap.add_argument("--no-bytecode", action="store_true",
                    help="cold runs compile the package in every process")
    ap.add_argument("--instructions", action="store_true",
                    help="count instructions (valgrind) of the cold runs instead of timing")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        old_root = Path(tmp) / "base"
        subprocess.run(["git", "worktree", "add", "--detach", str(old_root), args.base],
                       cwd=ROOT, check=True, capture_output=True)
        try:
            if args.instructions:
                count({args.base: old_root, "this checkout": ROOT})
                return
            if args.cold:
                cold(args.cold, {args.base: old_root, "this checkout": ROOT},
                     not args.no_bytecode)
            old, new = load_version(old_root), load_version(ROOT)
            print(f"{'case':45s} {'old ms':>8s} {'new ms':>8s} {'old/new':>8s}")
            for title, name, tf in CASES:
                ro, rn = runner(old, name, tf), runner(new, name, tf)
                ro(), rn()                       # warm: imports, caches
                to, tn, ratio = [], [], []
                for i in range(args.rounds):
                    a, b = (ro(), rn()) if i % 2 == 0 else tuple(reversed((rn(), ro())))
                    to.append(a)
                    tn.append(b)
                    ratio.append(a / b)
                print(f"{title:45s} {1e3 * statistics.median(to):8.1f} "
                      f"{1e3 * statistics.median(tn):8.1f} {statistics.median(ratio):8.2f}")
        finally:
            subprocess.run(["git", "worktree", "remove", "--force", str(old_root)], cwd=ROOT,
                           capture_output=True)


if __name__ == "__main__":
    main()
