"""Heat balance of a gear housing (pure functions).

The heat the losses make leaves through the housing wall by free convection, radiation
and, where a fan blows on it, forced convection; a cooler takes a fixed heat flow.  The
wall is taken at the oil sump temperature and the air at the ambient temperature (the
model of [ISOTR14179-1]: one temperature difference oil − air across the housing area).

* free convection on the walls: Churchill and Chu's correlation for a vertical plate over
  the whole range of Rayleigh numbers, [Incropera2007] eq. (9.26);
* forced convection by a fan: the average Nusselt number of a flat plate in parallel flow,
  laminar [Incropera2007] eq. (7.30), mixed laminar–turbulent eq. (7.38) above Re = 5·10⁵;
* radiation of a grey wall to large surroundings at the ambient temperature:
  h_r = ε·σ·(T_s² + T_∞²)·(T_s + T_∞), [Incropera2007] eq. (1.9).

Air properties at the film temperature from [Incropera2007] table A.4 (``losses.toml``).
The sump temperature solves P_V(ϑ) = P_Q(ϑ) by bisection with a bounded number of steps
(:func:`solve_increasing`); the losses fall and the heat flow rises with the temperature,
so the root is unique, and the bisection reads the sign at most of its midpoints from a
bracket narrowed first by the Illinois method (:func:`_bisect`).

>>> round(h_radiation(80.0, 20.0, 0.9), 2)
6.95
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.drive.losses import G, data

SIGMA = 5.670e-8            # W/(m²·K⁴), Stefan–Boltzmann constant [Incropera2007]
T0 = 273.15
MAX_ITERATIONS = 200


def air(T: float) -> tuple[float, float, float]:
    """(ν [m²/s], k [W/(m·K)], Pr) of air at T [K], linear in the table
    ([Incropera2007] table A.4), held at the ends of the table."""
    t = data()["air"]
    Ts = t["T"]
    T = min(max(T, Ts[0]), Ts[-1])
    i = max(j for j in range(len(Ts) - 1) if Ts[j] <= T)
    w = (T - Ts[i]) / (Ts[i + 1] - Ts[i])
    return tuple((1 - w) * t[k][i] + w * t[k][i + 1] for k in ("nu", "k", "Pr"))


def h_free(t_wall: float, t_air: float, height: float) -> float:
    """Heat transfer coefficient of free convection on a vertical wall of height H [mm]
    [W/(m²·K)]: Nu = {0.825 + 0.387·Ra^(1/6)/[1 + (0.492/Pr)^(9/16)]^(8/27)}²,
    Ra = g·β·ΔT·H³/(ν·α), β = 1/T_film.  [Incropera2007] eq. (9.26)"""
    dT = abs(t_wall - t_air)
    Tf = 0.5 * (t_wall + t_air) + T0
    nu, k, Pr = air(Tf)
    H = height / 1000.0
    Ra = G * (1.0 / Tf) * dT * H ** 3 / (nu * nu / Pr)
    Nu = (0.825 + 0.387 * Ra ** (1 / 6) / (1 + (0.492 / Pr) ** (9 / 16)) ** (8 / 27)) ** 2
    return Nu * k / H


def h_forced(velocity: float, length: float, t_wall: float, t_air: float) -> float:
    """Average heat transfer coefficient of a flat plate of length L [mm] in parallel air
    flow at v [m/s] [W/(m²·K)]: Nu = 0.664·Re^(1/2)·Pr^(1/3) (laminar, eq. 7.30);
    Nu = (0.037·Re^(4/5) − 871)·Pr^(1/3) above Re = 5·10⁵ (eq. 7.38).  [Incropera2007]"""
    if velocity <= 0.0:
        return 0.0
    nu, k, Pr = air(0.5 * (t_wall + t_air) + T0)
    L = length / 1000.0
    Re = velocity * L / nu
    Nu = (0.664 * Re ** 0.5 if Re <= 5e5 else 0.037 * Re ** 0.8 - 871.0) * Pr ** (1 / 3)
    return Nu * k / L


def h_radiation(t_wall: float, t_air: float, emissivity: float) -> float:
    """Radiation heat transfer coefficient of a grey wall to large surroundings
    [W/(m²·K)]: h_r = ε·σ·(T_s² + T_∞²)·(T_s + T_∞).  [Incropera2007] eq. (1.9)"""
    Ts, Ta = t_wall + T0, t_air + T0
    return emissivity * SIGMA * (Ts * Ts + Ta * Ta) * (Ts + Ta)


@dataclass(frozen=True)
class Housing:
    """The cooling surfaces: area A [m²], wall height H and length L along the fan's
    air flow [mm], emissivity ε, the share of the area a fan blows on at v [m/s], and a
    cooler's heat flow [W]."""

    area: float
    height: float
    length: float
    emissivity: float = 0.9
    fan_velocity: float = 0.0
    fan_share: float = 0.0
    cooler: float = 0.0


@dataclass(frozen=True)
class Dissipation:
    h_free: float
    h_forced: float
    h_rad: float
    alpha: float           # area-weighted total coefficient, W/(m²·K)
    P_convection: float    # W
    P_radiation: float     # W
    P_cooler: float        # W
    P_Q: float             # W, total


def dissipation(hs: Housing, t_oil: float, t_air: float) -> Dissipation:
    """Heat flow [W] out of the housing with its wall at the oil temperature t_oil [°C]:
    P_Q = A·(h_c + h_r)·(ϑ_oil − ϑ_air) + P_cooler, h_c = (1 − s)·h_free + s·max(h_free,
    h_forced) on the share s a fan blows on."""
    dT = t_oil - t_air
    hf = h_free(t_oil, t_air, hs.height) if dT > 0 else 0.0
    hv = h_forced(hs.fan_velocity, hs.length, t_oil, t_air) if hs.fan_share > 0 else 0.0
    hc = (1.0 - hs.fan_share) * hf + hs.fan_share * max(hf, hv)
    hr = h_radiation(t_oil, t_air, hs.emissivity)
    Pc = hs.area * hc * max(dT, 0.0)
    Pr = hs.area * hr * max(dT, 0.0)
    return Dissipation(hf, hv, hr, hc + hr, Pc, Pr, hs.cooler, Pc + Pr + hs.cooler)


@dataclass(frozen=True)
class Root:
    x: float
    iterations: int
    bracketed: bool         # False: no sign change within the search range; x is its end


def solve_increasing(f, lo: float, hi: float, tol: float = 1e-7,
                     max_iterations: int = MAX_ITERATIONS) -> Root:
    """Root of f, increasing from f(lo) <= 0 (else lo is returned) to a sign change,
    by bisection; the bracket [lo, hi] is doubled (at most 60 times) until f(hi) >= 0.
    At most ``max_iterations`` evaluations of f in the bisection.

    >>> r = solve_increasing(lambda x: x * x - 2.0, 0.0, 1.0)
    >>> round(r.x, 6), r.bracketed
    (1.414214, True)
    """
    f_lo = f(lo)
    if f_lo >= 0.0:
        return Root(lo, 1, True)
    width = hi - lo
    for _ in range(60):
        f_hi = f(hi)
        if f_hi >= 0.0:
            break
        lo, hi, f_lo = hi, hi + 2 * width, f_hi
        width *= 3
    else:
        return Root(hi, 60, False)
    return _bisect(f, lo, hi, tol, max_iterations, f_lo, f_hi)


NARROWING_STEPS = 8
"""At most this many steps of the Illinois method in :func:`_narrowed` (a heat balance
needs 5–6; a root where f is flat would take many, and the bisection then evaluates the
rest)."""


def _narrowed(f, a: float, fa: float, b: float, fb: float, width: float,
              steps: int = NARROWING_STEPS) -> tuple[float, float]:
    """A bracket [a, b] of the root of an increasing f (f(a) < 0 <= f(b)) narrowed to
    ``width`` (or by ``steps`` evaluations) by the Illinois method, the regula falsi whose
    retained end's value is halved when the same end is kept twice ([Dowell1971]:
    superlinear, each new point within the bracket).  Unlike
    :func:`geardesign.core.roots.bracket_root`, which must reach its tolerance and so
    bisects whenever two steps have not halved the bracket (some 90 evaluations of a
    drive's losses instead of 40 here), this returns both ends after a bounded number of
    steps: the bisection that follows (:func:`_bisect`) is the safeguard.

    >>> a, b = _narrowed(lambda x: x * x - 2.0, 1.0, -1.0, 2.0, 2.0, 1e-12, steps=12)
    >>> a < 2 ** 0.5 <= b, b - a <= 1e-12
    (True, True)
    >>> a, b = _narrowed(lambda x: x * x - 2.0, 1.0, -1.0, 2.0, 2.0, 1e-12)
    >>> a < 2 ** 0.5 <= b, b - a < 1e-6           # 8 steps
    (True, True)
    """
    kept = 0                  # +1: b was kept the step before, -1: a
    for _ in range(steps):
        if not b - a > width:
            break
        c = b - fb * (b - a) / (fb - fa)
        if not a < c < b:
            c = 0.5 * (a + b)
        fc = f(c)
        if fc >= 0.0:
            b, fb = c, fc
            if kept == -1:
                fa *= 0.5
            kept = -1
        else:
            a, fa = c, fc
            if kept == 1:
                fb *= 0.5
            kept = 1
    return a, b


def _bisect(f, lo: float, hi: float, tol: float, max_iterations: int, f_lo: float,
            f_hi: float) -> Root:
    """Bisection of a bracket [lo, hi] with f(lo) = ``f_lo`` < 0 <= f(hi) = ``f_hi``, f
    increasing (the module).  Its steps are those of plain bisection; the sign of f at a
    step's midpoint is known without evaluating f when the midpoint lies outside a bracket
    [a, b] of the root found first (:func:`_narrowed`): f(mid) <= f(a) < 0 left of it,
    f(mid) >= f(b) >= 0 right of it.  So f is evaluated a dozen times where the bisection takes some thirty
    steps, and the root is the bisection's to the last digit."""
    a, b = _narrowed(f, lo, f_lo, hi, f_hi, 0.125 * tol * max(1.0, abs(lo), abs(hi)))
    it = 0
    while hi - lo > tol * max(1.0, abs(hi)) and it < max_iterations:
        it += 1
        mid = 0.5 * (lo + hi)
        if mid <= a:
            lo = mid
        elif mid >= b:
            hi = mid
        elif f(mid) >= 0.0:
            hi = b = mid
        else:
            lo = a = mid
    return Root(0.5 * (lo + hi), it, True)


def solve_bounded(f, lo: float, hi: float, tol: float = 1e-7,
                  max_iterations: int = MAX_ITERATIONS) -> Root:
    """Root of an increasing f in [lo, hi] by bisection (at most ``max_iterations``
    steps); lo when f(lo) >= 0, hi (bracketed = False) when f(hi) < 0."""
    f_lo = f(lo)
    if f_lo >= 0.0:
        return Root(lo, 1, True)
    f_hi = f(hi)
    if f_hi < 0.0:
        return Root(hi, 2, False)
    return _bisect(f, lo, hi, tol, max_iterations, f_lo, f_hi)


def box_area(length: float, width: float, height: float, base: bool = False) -> float:
    """Outer area [m²] of a box housing L×W×H [mm]; the base (on its foundation) is left
    out unless ``base``."""
    A = 2 * (length * height + width * height) + length * width * (2 if base else 1)
    return A * 1e-6
