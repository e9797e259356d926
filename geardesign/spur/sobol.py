"""The scrambled Sobol' sequence of ``geardesign sweep --samples``, drawn chunk after chunk.

The points are those of ``scipy.stats.qmc.Sobol(d, scramble=True, seed=seed)`` (Joe and
Kuo direction numbers, linear matrix scrambling with a digital shift; reference
[Sobol1967], [JoeKuo2008], as implemented by SciPy): same seed, same points in the same
order.  ``scipy.stats`` as a whole costs seconds of CPU and about 70 MB to import, of which
the sequence needs only its compiled kernel ``scipy.stats._sobol``; :func:`engine` loads that
kernel alone and falls back to ``qmc.Sobol`` when it cannot (another SciPy layout).
tests/test_sweep_sampling.py checks the two give identical points.

An engine keeps its position: drawing ``n`` points costs ``n`` steps of the sequence, and a
sweep draws chunk after chunk from one engine (a copy positioned at each chunk's start for
parallel workers), so the work grows linearly with the sample.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import importlib.resources  # noqa: F401 (the kernel reads its data through it)
import importlib.util
import types
import warnings
from pathlib import Path

import numpy as np

BITS = 30
"""Bits of the sequence (SciPy's default): at most 2³⁰ points."""


def _kernel():
    """``scipy.stats._sobol`` loaded without running ``scipy.stats/__init__``; the direction
    numbers it reads from the ``scipy.stats`` package folder are found through the package's
    import spec, which imports nothing."""
    stats = importlib.util.find_spec("scipy.stats")
    if stats is None or not stats.submodule_search_locations:
        raise ImportError("scipy.stats not found")
    folder = Path(stats.submodule_search_locations[0])
    origin = next((folder / f"_sobol{suffix}" for suffix in
                   importlib.machinery.EXTENSION_SUFFIXES
                   if (folder / f"_sobol{suffix}").is_file()), None)
    if origin is None:
        raise ImportError("scipy.stats._sobol not found")
    package = importlib.util.module_from_spec(stats)    # not executed: only its location

    def import_module(name, package_=None):
        if name == "scipy.stats":
            return package
        return importlib.import_module(name, package_)

    def files(anchor):
        if anchor == "scipy.stats" or anchor is package:
            return folder
        return importlib.resources.files(anchor)

    resources = types.ModuleType("importlib.resources")
    resources.__dict__.update(vars(importlib.resources))
    resources.files = files
    shim = types.ModuleType("importlib")
    shim.__dict__.update(vars(importlib))
    shim.import_module = import_module
    shim.resources = resources
    spec = importlib.util.spec_from_file_location("scipy.stats._sobol", origin)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if hasattr(module, "importlib"):
        module.importlib = shim
    return module


class _Engine:
    """A scrambled Sobol' engine on the compiled kernel (the state of ``qmc.Sobol``:
    direction numbers ``sv``, the last point ``quasi``, the count drawn)."""

    def __init__(self, kernel, d: int, seed) -> None:
        self._k = kernel
        self.d = d
        self._sv = np.zeros((d, BITS), dtype=np.uint32)
        kernel._initialize_v(self._sv, dim=d, bits=BITS)
        rng = np.random.default_rng(seed)
        shift = np.dot(rng.integers(0, 2, size=(d, BITS), dtype=np.uint32),
                       2 ** np.arange(BITS, dtype=np.uint32))
        ltm = np.tril(rng.integers(0, 2, size=(d, BITS, BITS), dtype=np.uint32))
        kernel._cscramble(dim=d, bits=BITS, ltm=ltm, sv=self._sv)
        self._quasi = shift.copy()
        self._scale = 1.0 / 2 ** BITS
        self.num_generated = 0

    def __getstate__(self) -> dict:     # a copy or a worker process loads the kernel itself
        return {k: v for k, v in self.__dict__.items() if k != "_k"}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._k = _loaded()

    def random(self, n: int) -> np.ndarray:
        sample = np.empty((n, self.d), dtype=np.float64)
        if n == 0:
            return sample
        if self.num_generated + n > 2 ** BITS:
            raise ValueError(f"at most 2**{BITS} points")
        if self.num_generated == 0:
            first = (self._quasi * self._scale).reshape(1, -1).astype(np.float64)
            if n > 1:
                self._k._draw(n=n - 1, num_gen=0, dim=self.d, scale=self._scale, sv=self._sv,
                              quasi=self._quasi, sample=sample)
            sample = np.concatenate([first, sample])[:n]
        else:
            self._k._draw(n=n, num_gen=self.num_generated - 1, dim=self.d, scale=self._scale,
                          sv=self._sv, quasi=self._quasi, sample=sample)
        self.num_generated += n
        return sample

    def fast_forward(self, n: int) -> "_Engine":
        if n > 0:
            first = self.num_generated == 0
            self._k._fast_forward(n=n - 1 if first else n,
                                  num_gen=0 if first else self.num_generated - 1,
                                  dim=self.d, sv=self._sv, quasi=self._quasi)
            self.num_generated += n
        return self


class _Quiet:
    """``qmc.Sobol`` without its warning that a draw is not a power of 2 (the sample is
    drawn in chunks; the balance of the whole sample is what counts)."""

    def __init__(self, d: int, seed) -> None:
        from scipy.stats import qmc

        self._e = qmc.Sobol(d=d, scramble=True, seed=seed)

    @property
    def num_generated(self) -> int:
        return self._e.num_generated

    def random(self, n: int) -> np.ndarray:
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message=".*balance properties of Sobol")
            return self._e.random(n)

    def fast_forward(self, n: int):
        if n > 0:
            self._e.fast_forward(n)
        return self


_KERNEL: list = []


def _loaded():
    """The compiled kernel, loaded once per process (``None``: use ``qmc.Sobol``)."""
    if not _KERNEL:
        try:
            kernel = _kernel()
            _Engine(kernel, 2, 0).random(3)
            _KERNEL.append(kernel)
        except Exception:   # another SciPy layout: the public engine, same points
            _KERNEL.append(None)
    return _KERNEL[0]


def engine(d: int, seed, start: int = 0):
    """A scrambled Sobol' engine of dimension ``d`` positioned at point ``start``."""
    from geardesign.core.io import signals_deferred

    with signals_deferred():   # compiled code that would swallow a Ctrl-C
        kernel = _loaded()
        eng = _Engine(kernel, d, seed) if kernel is not None else _Quiet(d, seed)
        return eng.fast_forward(start)
