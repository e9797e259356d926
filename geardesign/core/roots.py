"""A root of a scalar function bracketed by a sign change, without scipy (whose import
costs more than a single calculation): used where a formula has no closed inverse."""

from __future__ import annotations

from typing import Callable


def bracket_root(f: Callable[[float], float], a: float, b: float, tol: float,
             closed: bool) -> float:
    """Where ``f`` changes sign on [a, b]: the end on a's side of the bracket once it is
    narrower than ``tol``; a's side holds f > 0 (``closed``: f >= 0), b's side the rest.
    Regula falsi in its Illinois form (the end kept twice in a row has its value halved in
    the interpolation), with a bisection whenever two steps have not halved the bracket: a
    bisection's certainty in a fraction of its steps ([Dowell1971])."""
    fa, fb = f(a), f(b)
    widths = [abs(b - a)] * 2
    kept = 0          # +1: a kept by the last step, −1: b kept
    bisect = False
    while abs(b - a) > tol:
        c = 0.5 * (a + b)
        if not bisect and fa != fb:
            c2 = b - fb * (b - a) / (fb - fa)
            if min(a, b) < c2 < max(a, b):
                c = c2
        fc = f(c)
        if fc > 0 or (closed and fc == 0):
            a, fa = c, fc
            if kept == -1:
                fb *= 0.5
            kept = -1
        else:
            b, fb = c, fc
            if kept == 1:
                fa *= 0.5
            kept = 1
        w = abs(b - a)
        bisect = w > 0.5 * widths[0]
        widths = [widths[1], w]
    return a
