"""The tables of the worm-pair calculation, read from ``tables.toml`` (data, not code),
and linear interpolation in them.

Every table carries its source in the TOML file; the functions here say how they
interpolate and what they do outside the tabulated range.  The friction, form-factor,
deflection-coefficient, worm-length and fan tables and the (m, q) pairs are textbook
tables quoted from textbooks whose text we could not consult ([GOST19650]; [Chernavsky]); none was
found in a located text ([WormPascal]),
and where the public Pascal worm program has another law the TOML file says so.
"""

from __future__ import annotations

import bisect
from functools import lru_cache
from pathlib import Path


@lru_cache(maxsize=1)
def data() -> dict:
    """The parsed ``tables.toml``."""
    from geardesign.core.data import toml_table

    return toml_table(Path(__file__).with_name("tables.toml"))


def interp(x: float, xs: list[float], ys: list[float], extrapolate: bool = False) -> float:
    """Piecewise-linear interpolation of a table ``ys(xs)`` (``xs`` increasing).

    Outside ``[xs[0], xs[-1]]`` the end value is returned, or with ``extrapolate`` the end
    segment is prolonged.
    """
    if x <= xs[0] and not extrapolate:
        return ys[0]
    if x >= xs[-1] and not extrapolate:
        return ys[-1]
    i = min(max(bisect.bisect_right(xs, x) - 1, 0), len(xs) - 2)
    t = (x - xs[i]) / (xs[i + 1] - xs[i])
    return ys[i] + t * (ys[i + 1] - ys[i])


FRICTION_LEVELS = ("low", "mean", "high")


def friction_coefficient(v_s: float, level: str = "mean") -> float:
    """Reduced friction coefficient f' of a tin-bronze wheel on a hardened ground steel worm
    at the sliding speed ``v_s`` [m/s], interpolated linearly in the table ([Ivanov], from memory);
    ``level`` picks the low end, the middle or the high end of the
    tabulated range.
    Below 0.01 m/s and above 15 m/s the end value is used.  The material-group factor is
    applied by the caller (:func:`friction_material_factor`).
    """
    t = data()["friction"]
    low = interp(v_s, t["v_s"], t["f_low"])
    high = interp(v_s, t["v_s"], t["f_high"])
    return {"low": low, "high": high}.get(level, 0.5 * (low + high))


def friction_material_factor(group: str) -> float:
    """Multiplier of f' for the wheel-material group (1.0 tin bronze; 1.4 otherwise, the
    middle of the textbooks' "+30 ... 50 %")."""
    return data()["friction"]["material_factor"][group]


def form_factor(z_v: float) -> float:
    """Tooth form factor Y_F2 of the wheel at the virtual number of teeth ``z_v``
    ([Dunaev], from memory), linear interpolation; end values outside
    20 ... 300."""
    t = data()["form_factor"]
    return interp(z_v, t["z_v"], t["Y_F"])


def theta(q: float, z1: int) -> float:
    """Worm deflection coefficient θ ([Chernavsky], from memory) for the diameter
    factor ``q`` and ``z1`` starts: linear in q within 8 ... 20 and prolonged linearly
    outside (the Pascal program's laws are linear in q too; θ stays > 0 for q >= 5);
    z1 = 3 takes the mean of the rows z1 = 2 and z1 = 4 (the table has no row for it)."""
    t = data()["theta"]
    if z1 == 3:
        return 0.5 * (interp(q, t["q"], t["z1_2"], True) + interp(q, t["q"], t["z1_4"], True))
    row = {1: "z1_1", 2: "z1_2", 4: "z1_4"}[z1]
    return interp(q, t["q"], t[row], True)


def worm_length_coefficients(x: float, z1: int) -> tuple[float, float, float]:
    """Coefficients (a, b, c) of b1 >= (a + b·z1 + c·z2)·m at the wheel shift ``x``,
    interpolated linearly between the rows x = -1, -0.5, 0, 0.5, 1 ([Dunaev])."""
    t = data()["worm_length"]
    rows = t["z1_1_2"] if z1 <= 2 else t["z1_3_4"]
    return tuple(interp(x, t["x"], [r[k] for r in rows]) for k in range(3))  # type: ignore


def ground_worm_extra_length(m: float) -> float:
    """Extra thread length [mm] of a ground (polished) worm by module ([Dunaev]: 25 mm for m < 10,
    35 ... 40 mm for 10 ... 16 (40 used), 50 mm above)."""
    t = data()["worm_length"]
    lim = t["ground_m_limits"]
    extra = t["ground_extra"]
    if m < lim[0]:
        return extra[0]
    if m <= lim[1]:
        return extra[1]
    return extra[2]


def fan_heat_transfer(speed: float) -> float:
    """Heat-transfer coefficient K_T [W/(m² K)] of the surface blown by a fan at ``speed``
    [min⁻¹] ([Chernavsky]: 750 -> 17, 1000 -> 21, 1500 -> 29, 3000 -> 40), linear
    interpolation, end values outside."""
    t = data()["fan"]
    return interp(speed, t["speed"], t["K_T"])


def series() -> dict:
    """The standard series (GOST 2144-76, GOST 19672-74) as quoted in ``tables.toml``."""
    return data()["series"]


def recommended_q(m: float) -> list[float] | None:
    """The recommended diameter factors for the module ``m`` (table from memory), or None
    when ``m`` has no row."""
    for row in series()["pairs"]:
        if abs(row["m"] - m) < 1e-9:
            return row["q"]
    return None
