"""Where a section of a stepped shaft lies (the step at x, the step boundary at x) and the
torsional stress split by its cycle: shared by the section ratings of both methods
(:mod:`geardesign.shaft.section_gost`, :mod:`geardesign.shaft.din743.section`)."""

from __future__ import annotations


def step_at(bounds: list[float], xm: float) -> int:
    for i in range(len(bounds) - 1):
        if xm <= bounds[i + 1]:
            return i
    return len(bounds) - 2


def boundary_at(bounds: list[float], n_steps: int, xs: float) -> int | None:
    """The index i of the step boundary at x = ``xs`` (between steps i − 1 and i; within
    10⁻⁹ of the length), ``None`` inside a step."""
    tol = 1e-9 * max(1.0, bounds[-1])
    return next((i for i in range(1, n_steps) if abs(bounds[i] - xs) <= tol), None)


def torsion(tau: float, cycle: str) -> tuple[float, float]:
    """Amplitude and mean of the torsional stress τ by ``torsion_cycle``: pulsating
    τ_a = τ_m = τ/2, reversed τ_a = τ, τ_m = 0, else static τ_a = 0, τ_m = τ ([Dunaev];
    [DIN743-1])."""
    if cycle == "pulsating":
        return tau / 2.0, tau / 2.0
    if cycle == "reversed":
        return tau, 0.0
    return 0.0, tau
