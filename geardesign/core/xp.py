"""One formula for floats and arrays: the elementary functions a formula module calls, taken
from :mod:`math` for Python numbers and from numpy for arrays.

A rating formula written with these runs unchanged in the scalar calculator (plain floats,
no numpy import, no overhead beyond a type test) and in the sweep kernel (numpy arrays of
candidates, one call per chunk), so that one formula change reaches both paths.  numpy is
imported only when an array arrives.

Branches: :func:`where` picks ``a`` or ``b`` by a condition; for arrays both sides are
evaluated (the kernel silences the warnings of the side it does not keep).
"""

from __future__ import annotations

import math

_SCALARS = (int, float)


def _np():
    import numpy

    return numpy


def scalar(*xs) -> bool:
    """Whether every argument is a Python number (bool included)."""
    for x in xs:
        if not isinstance(x, _SCALARS):
            return False
    return True


def sqrt(x):
    return math.sqrt(x) if isinstance(x, _SCALARS) else _np().sqrt(x)


def sin(x):
    return math.sin(x) if isinstance(x, _SCALARS) else _np().sin(x)


def cos(x):
    return math.cos(x) if isinstance(x, _SCALARS) else _np().cos(x)


def tan(x):
    return math.tan(x) if isinstance(x, _SCALARS) else _np().tan(x)


def acos(x):
    return math.acos(x) if isinstance(x, _SCALARS) else _np().arccos(x)


def asin(x):
    return math.asin(x) if isinstance(x, _SCALARS) else _np().arcsin(x)


def atan(x):
    return math.atan(x) if isinstance(x, _SCALARS) else _np().arctan(x)


def log10(x):
    return math.log10(x) if isinstance(x, _SCALARS) else _np().log10(x)


def log(x):
    return math.log(x) if isinstance(x, _SCALARS) else _np().log(x)


def exp(x):
    return math.exp(x) if isinstance(x, _SCALARS) else _np().exp(x)


def degrees(x):
    return math.degrees(x) if isinstance(x, _SCALARS) else _np().degrees(x)


def floor(x):
    return float(math.floor(x)) if isinstance(x, _SCALARS) else _np().floor(x)


def hypot(x, y):
    if isinstance(x, _SCALARS) and isinstance(y, _SCALARS):
        return math.hypot(x, y)
    return _np().hypot(x, y)


def minimum(a, b):
    if isinstance(a, _SCALARS) and isinstance(b, _SCALARS):
        return min(a, b)
    return _np().minimum(a, b)


def maximum(a, b):
    if isinstance(a, _SCALARS) and isinstance(b, _SCALARS):
        return max(a, b)
    return _np().maximum(a, b)


def clip(x, lo, hi):
    """``min(max(x, lo), hi)``."""
    if isinstance(x, _SCALARS) and isinstance(lo, _SCALARS) and isinstance(hi, _SCALARS):
        return min(max(x, lo), hi)
    return minimum(maximum(x, lo), hi)


def rnd(x, ndigits: int = 0):
    """Python's ``round(x, ndigits)`` (correctly rounded, halves to even) as a float, for a
    number or elementwise for an array.  An array is rounded by numpy and the elements within
    a hair of a half (where scaling by 10^ndigits may tip the decision) again by Python."""
    if isinstance(x, _SCALARS):
        return float(round(x, ndigits))
    np = _np()
    x = np.asarray(x, dtype=float)
    out = np.round(x, ndigits)
    scaled = np.abs(x) * 10.0 ** ndigits
    near = np.flatnonzero(np.abs(scaled - np.floor(scaled) - 0.5) < 1e-6)
    if near.size:
        flat = out.reshape(-1)
        src = x.reshape(-1)
        for i in near:
            flat[i] = round(float(src[i]), ndigits)
    return out


def all_(x) -> bool:
    """Whether ``x`` holds (a number) or holds everywhere (an array)."""
    return bool(x) if isinstance(x, (bool, int, float)) else bool(_np().all(x))


def where(cond, a, b):
    """``a`` where ``cond`` holds, else ``b``: a Python conditional for a scalar condition,
    ``numpy.where`` for an array."""
    if cond is True or cond is False or isinstance(cond, int) or \
            type(cond).__name__ in ("bool_", "bool"):
        return a if cond else b
    return _np().where(cond, a, b)


def take(table, index):
    """``table[index]`` for an integer index, ``numpy.asarray(table)[index]`` for an array of
    indices (a row of a data table chosen per candidate)."""
    if isinstance(index, int):
        return table[index]
    return _np().asarray(table)[index]
