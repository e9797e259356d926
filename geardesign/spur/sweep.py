"""Design sweeps of a spur/helical pair: every variant of a grid (or a Sobol sample) of the
gear data, rated by the vectorised kernel (:mod:`geardesign.spur.kernel`), filtered by the
checks and the constraints, ranked by the objectives, with the Pareto front of the first two.

A sweep spec is a spur spec (the base design: materials, load, every key not varied) with a
``[sweep]`` table::

    [sweep]
    "gear.module" = {values = [2.0, 2.5, 3.0]}
    "gear.z1" = {from = 18, to = 30, step = 1}
    "gear.face_width" = {from = 30.0, to = 60.0, step = 5.0}
    ratio = [3.9, 4.1]               # window of u = z2/z1 (constraint)
    center_distance_range = [0.0, 160.0]
    psi_bd = [0.2, 1.6]              # window of b_w/d_w1 (default: that of the spur check)
    psi_ba = [0.1, 1.25]             # window of b_w/a_w (default: the GOST 2185-66 series)
    min_margin = 1.0                 # the smallest reserve of the rating (1 = just passes)
    objectives = ["mass", "margin"]  # ranked by the first, then the second
    top = 20

Evaluation runs in chunks of :data:`CHUNK` candidates, so memory stays bounded whatever the
size (the ranked head and the front are merged chunk by chunk); ``workers`` local processes
or a Dask cluster (``scheduler``) evaluate chunks in parallel, and the result is the same.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import field

import numpy as np

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.spur.checks import PSI_BA_WINDOW, PSI_BD_MAX, PSI_BD_MIN, face_width_ratio_ok
from geardesign.spur.geometry import disc_mass, disc_volume

CHUNK = 50_000
"""Candidates per kernel call (about 60 MB of arrays at a time: 10⁷ candidates run in
about 150 MB)."""

MAX_GRID = 200_000_000
"""Largest full grid (about 4 minutes on one core); beyond it a sample is required."""

MAX_SAMPLES = 100_000_000

MAX_POINTS = 1_000_000
"""Largest number of values of one varied key."""

VARIABLE = {
    # key: (integer, minimum, maximum, unit)
    "gear.module": (False, 0.05, 100.0, "mm"),
    "gear.z1": (True, 5, 1000, "-"),
    "gear.z2": (True, 5, 10000, "-"),
    "gear.x1": (False, -2.0, 5.0, "-"),
    "gear.x2": (False, -2.0, 5.0, "-"),
    "gear.helix_angle": (False, 0.0, 45.0, "deg"),
    "gear.face_width": (False, 0.1, 5000.0, "mm"),
    "gear.center_distance": (False, 1.0, 100000.0, "mm"),
    "gear.accuracy_grade": (True, 6, 11, "-"),
    "gear.bearing_scheme": (True, 1, 7, "-"),
}
"""The keys a sweep may vary, with their type and the domain of the spur spec."""

FIXED_KEYS = ("gear.accuracy_grade", "gear.bearing_scheme")
"""Varied keys that are fixed data of the kernel (the rating setting): the candidates are
rated in groups, one kernel call per combination, as for the materials."""

MATERIAL_KEYS = ("material.pinion", "material.wheel")
"""Keys varied over a list of material tables (``{values = [{grade = "40Kh", treatment =
"improved", hardness_HB = 280.0}, ...]}``), each a ``[material.pinion]`` table of the spur
spec."""

OBJECTIVES = {
    # name: (result column, +1 minimise / −1 maximise, unit, description)
    "center_distance": ("a_w", 1, "mm", "working centre distance"),
    "volume": ("volume", 1, "cm^3", "volume of the two gears π/4·(d1² + d2²)·b_w"),
    "mass": ("mass", 1, "kg", "mass of the two gears as steel discs (7850 kg/m³)"),
    "face_width": ("b_w", 1, "mm", "face width"),
    "margin": ("margin", -1, "-", "smallest reserve of the rating: σ_HP/σ_H, S_F1/S_Fmin1, "
               "S_F2/S_Fmin2 (GOST 21354-87); S_H1/S_Hmin, S_H2/S_Hmin, S_F1/S_Fmin, "
               "S_F2/S_Fmin (ISO 6336:2019)"),
    "contact_safety": ("S_Hmin", -1, "-", "smaller contact safety factor S_H"),
    "efficiency": ("eta", -1, "-", "mesh efficiency 1 − μ·H_V (Ohlendorf's tooth loss factor "
                   "H_V, μ = sweep.friction)"),
    "sliding": ("sliding", 1, "-", "larger specific sliding at the roots max(|ϑ1(A)|, "
                "|ϑ2(E)|)"),
}

COLUMNS = ("m_n", "z1", "z2", "x1", "x2", "helix_angle", "b_w", "psi_bd", "u", "a_w",
           "eps_alpha",
           "eps_beta", "sigma_H", "sigma_HP", "S_H1", "S_H2", "S_F1", "S_F2", "margin",
           "volume", "mass", "H_V", "eta", "sliding")
"""Result columns of a ranked variant (and of the candidate dataset)."""

MATERIAL_COLUMNS = {"material.pinion": "material1", "material.wheel": "material2"}

FULL_CHECKS = 50
"""Reported variants (of each table) rated again by the whole calculator (column "full
check"): the peak-torque checks and the warnings the kernel does not make."""
"""Columns of the varied materials: the index into the key's list of material tables."""



@dataclass
class Dim:
    key: str
    values: np.ndarray
    low: float
    high: float
    integer: bool
    choices: tuple = ()     # a material key: the material tables, ``values`` their indices


@dataclass
class Sweep:
    dims: list
    samples: int | None = None
    seed: int = 0
    objectives: tuple = ("mass", "margin")
    ratio: tuple | None = None
    center_distance_range: tuple | None = None
    psi_bd: tuple = (PSI_BD_MIN, PSI_BD_MAX)
    psi_ba: tuple = PSI_BA_WINDOW
    min_margin: float = 1.0
    friction: float = 0.05
    top: int = 20
    base: dict = field(default_factory=dict)

    @property
    def grid_size(self) -> int:
        return math.prod(len(d.values) for d in self.dims)

    @property
    def size(self) -> int:
        return self.samples if self.samples else self.grid_size


# ----------------------------------------------------------------------------- input


def _range(key: str, spec, where: str) -> Dim:
    integer, lo_dom, hi_dom, unit = VARIABLE[key]
    if isinstance(spec, dict):
        keys = set(spec)
        if keys == {"values"}:
            vals = spec["values"]
            if not isinstance(vals, list) or not vals:
                raise InputError.at(where, vals, "an empty list of values: give at least one")
            values = vals
        elif keys <= {"from", "to", "step"} and {"from", "to"} <= keys:
            a, b = spec["from"], spec["to"]
            step = spec.get("step", 1 if integer else None)
            for name, v in (("from", a), ("to", b), ("step", step)):
                if v is None:
                    raise InputError.at(f"{where}.step", None, "missing: give the step of the "
                                        "range (or values = [...])")
                if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                    raise InputError.at(f"{where}.{name}", v, "must be a finite number")
            if step == 0:
                raise InputError.at(f"{where}.step", step, "must not be 0")
            if (b - a) * step < 0:
                raise InputError.at(f"{where}.step", step, f"has the wrong sign: from {a} to "
                                    f"{b} needs a step of sign {'+' if b >= a else '-'}")
            span = (b - a) / step            # may overflow to inf for a denormal step
            if not span < MAX_POINTS:
                raise InputError.at(f"{where}.step", step, f"gives more than {MAX_POINTS} "
                                    f"values, the most per key: use a larger step")
            count = int(math.floor(span + 1e-9)) + 1
            if count > MAX_POINTS:
                raise InputError.at(f"{where}.step", step, f"gives {count} values; at most "
                                    f"{MAX_POINTS} per key: use a larger step")
            values = [a + i * step for i in range(count)]
        else:
            raise InputError.at(where, spec, "must be {values = [...]} or {from = ..., to = "
                                "..., step = ...}")
    else:
        raise InputError.at(where, spec, "must be {values = [...]} or {from = ..., to = ..., "
                            "step = ...}")
    out = []
    for v in values:
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
            raise InputError.at(where, v, "every value must be a finite number")
        if integer and float(v) != int(v):
            raise InputError.at(where, v, "must be whole numbers (tooth counts)")
        if not lo_dom <= v <= hi_dom:
            raise InputError.at(where, v, f"outside the domain of {key}: {lo_dom:g} to "
                                f"{hi_dom:g} {unit}")
        out.append(float(round(v, 12)))
    arr = np.array(sorted(set(out)), dtype=float)
    return Dim(key, arr, float(arr[0]), float(arr[-1]), integer)


def _materials(key: str, spec, where: str) -> Dim:
    """A material key: ``{values = [table, ...]}`` of material tables (checked against the
    spur spec when the sweep is loaded)."""
    vals = spec.get("values") if isinstance(spec, dict) and set(spec) == {"values"} else None
    if not isinstance(vals, list) or not vals or not all(isinstance(v, dict) for v in vals):
        raise InputError.at(where, spec, "must be {values = [{grade = ..., treatment = ..., "
                            "hardness_HB = ...}, ...]}: a list of material tables")
    if len(vals) > 100:
        raise InputError.at(where, len(vals), "at most 100 materials per key")
    idx = np.arange(len(vals), dtype=float)
    return Dim(key, idx, 0.0, float(len(vals) - 1), True, tuple(dict(v) for v in vals))


def parse_vary(text: str) -> tuple[str, object]:
    """``--vary KEY=FROM:TO:STEP`` or ``KEY=V1,V2,...`` into ``(key, range table)``."""
    if "=" not in text:
        raise InputError(Problem("--vary", "must be KEY=FROM:TO:STEP or KEY=V1,V2,...", text))
    key, _, rng = text.partition("=")
    key = key.strip()
    try:
        if ":" in rng:
            parts = [float(p) for p in rng.split(":")]
            if len(parts) not in (2, 3):
                raise ValueError
            spec = {"from": parts[0], "to": parts[1]}
            if len(parts) == 3:
                spec["step"] = parts[2]
        else:
            spec = {"values": [float(p) for p in rng.split(",") if p.strip()]}
    except ValueError:
        raise InputError(Problem(f"--vary {key}", "must be FROM:TO:STEP or V1,V2,... of "
                                 "numbers", rng)) from None
    return key, spec


def _did_you_mean(key: str) -> str:
    import difflib

    near = difflib.get_close_matches(key, list(VARIABLE) + list(MATERIAL_KEYS), n=1)
    return f" (did you mean {near[0]}?)" if near else ""


def parse_sweep(table: dict | None, vary: list[str], samples: int | None, seed: int | None
                ) -> Sweep:
    """The :class:`Sweep` of a ``[sweep]`` table and the command-line options.  Raises
    :class:`InputError` with one problem per bad key."""
    table = dict(table or {})
    opts = {k: table.pop(k) for k in ("ratio", "center_distance_range", "psi_bd", "psi_ba",
                                      "min_margin",
                                      "objectives", "top", "samples", "seed", "friction")
            if k in table}
    ranges = dict(table)
    for text in vary:
        k, r = parse_vary(text)
        ranges[k] = r
    if not ranges:
        raise InputError(Problem("sweep", "nothing to vary: give [sweep] \"gear.module\" = "
                                 "{values = [...]} or --vary KEY=FROM:TO:STEP"))
    dims = []
    for key, r in ranges.items():
        if key in MATERIAL_KEYS:
            dims.append(_materials(key, r, f"sweep.{key}"))
            continue
        if key not in VARIABLE:
            raise InputError(Problem(f"sweep.{key}", f"cannot be varied{_did_you_mean(key)}; "
                                     f"a sweep varies {', '.join([*VARIABLE, *MATERIAL_KEYS])}",
                                     r))
        dims.append(_range(key, r, f"sweep.{key}"))
    sw = Sweep(dims)
    if "gear.center_distance" in ranges and "gear.x1" in ranges and "gear.x2" in ranges:
        raise InputError(Problem("sweep.gear.x2", "cannot be varied together with gear.x1 and "
                                 "gear.center_distance (x1 + x2 follows from the centre "
                                 "distance)", None))
    samples = samples if samples is not None else opts.get("samples")
    if samples is not None:
        if isinstance(samples, bool) or not isinstance(samples, int) or not \
                1 <= samples <= MAX_SAMPLES:
            raise InputError(Problem("sweep.samples", f"must be an integer from 1 to "
                                     f"{MAX_SAMPLES}", samples))
        sw.samples = samples
    elif sw.grid_size > MAX_GRID:
        raise InputError(Problem("sweep", f"the grid has {sw.grid_size:.3g} candidates, more "
                                 f"than {MAX_GRID:.0e}: give --samples N (a Sobol sample of "
                                 f"the ranges) or coarser steps", sw.grid_size))
    s = seed if seed is not None else opts.get("seed", 0)
    if isinstance(s, bool) or not isinstance(s, int) or s < 0:
        raise InputError(Problem("sweep.seed", "must be an integer >= 0", s))
    sw.seed = s
    for name in ("ratio", "center_distance_range"):
        if name in opts:
            v = opts[name]
            if not (isinstance(v, list) and len(v) == 2 and all(
                    isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
                    for x in v) and v[0] <= v[1] and v[0] >= 0):
                raise InputError(Problem(f"sweep.{name}", "must be [low, high] with 0 <= low "
                                         "<= high", v))
            setattr(sw, name, (float(v[0]), float(v[1])))
    for name in ("psi_bd", "psi_ba"):
        if name in opts:
            v = opts[name]
            if not (isinstance(v, list) and len(v) == 2 and all(
                    isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)
                    for x in v) and 0 < v[0] <= v[1] <= 10):
                raise InputError(Problem(f"sweep.{name}", "must be [low, high] with 0 < low "
                                         "<= high <= 10 (a window of the face width ratio "
                                         + ("b_w/d_w1" if name == "psi_bd" else "b_w/a_w")
                                         + ")", v))
            setattr(sw, name, (float(v[0]), float(v[1])))
    if "min_margin" in opts:
        v = opts["min_margin"]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0.1 <= v <= 10.0:
            raise InputError(Problem("sweep.min_margin", "must be a number from 0.1 to 10", v))
        sw.min_margin = float(v)
    if "friction" in opts:
        v = opts["friction"]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0.005 <= v <= 0.3:
            raise InputError(Problem("sweep.friction", "must be a number from 0.005 to 0.3 "
                                     "(the mean coefficient of friction of the mesh)", v))
        sw.friction = float(v)
    if "objectives" in opts:
        v = opts["objectives"]
        if not (isinstance(v, list) and 1 <= len(v) <= 4 and all(isinstance(x, str) for x in v)):
            raise InputError(Problem("sweep.objectives", f"must be a list of 1 to 4 of "
                                     f"{', '.join(OBJECTIVES)}", v))
        for x in v:
            if x not in OBJECTIVES:
                raise InputError(Problem("sweep.objectives", f"unknown objective; one of "
                                         f"{', '.join(OBJECTIVES)}", x))
        sw.objectives = tuple(dict.fromkeys(v))
    if "top" in opts:
        v = opts["top"]
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 1000:
            raise InputError(Problem("sweep.top", "must be an integer from 1 to 1000", v))
        sw.top = v
    return sw


# ----------------------------------------------------------------------------- candidates


def _base_values(spec) -> dict:
    """The pair of the base spec (keys of :data:`VARIABLE`)."""
    from geardesign.spur.calculator import pair_input_from_spec

    g = spec.data["gear"]
    given = {k: g.get(k) for k in ("x1", "x2", "center_distance")}
    p, _ = pair_input_from_spec(spec)
    return {"gear.module": p.m_n, "gear.z1": float(p.z1), "gear.z2": float(p.z2),
            "gear.x1": p.x1, "gear.x2": p.x2, "gear.helix_angle": math.degrees(p.beta),
            "gear.face_width": p.b_w, "gear.center_distance": given["center_distance"],
            "x1_given": given["x1"] is not None, "x2_given": given["x2"] is not None}


def _shift_rule(varied, base: dict) -> str:
    """How x1, x2 follow for each candidate: "given" (no centre distance), or with the
    centre distance fixed or varied, "x1"/"x2" (that one given or varied, the other
    x_Σ − it) or "equal" (x_Σ split equally)."""
    if "gear.center_distance" not in varied and base["gear.center_distance"] is None:
        return "given"
    if "gear.x1" in varied:
        return "x1"
    if "gear.x2" in varied:
        return "x2"
    if base["x1_given"]:
        return "x1"
    if base["x2_given"]:
        return "x2"
    return "equal"


def candidates(sw: Sweep, start: int, stop: int, sampler=None) -> dict:
    """The varied values of candidates ``start`` … ``stop − 1``: grid indices in C order, or
    points of a scrambled Sobol sequence (``seed``) mapped on the ranges (a value list is
    sampled by index).  ``sampler``: the sequence's engine positioned at ``start``
    (:func:`samplers`), drawn on; without it one is positioned here."""
    n = stop - start
    out = {}
    if sw.samples is None:
        shape = tuple(len(d.values) for d in sw.dims)
        idx = np.unravel_index(np.arange(start, stop), shape)
        for d, i in zip(sw.dims, idx):
            out[d.key] = d.values[i]
        return out
    from geardesign.spur.sobol import engine

    if sampler is None:
        sampler = engine(len(sw.dims), sw.seed, start)
    if sampler.num_generated != start:
        raise ValueError(f"the sampler stands at {sampler.num_generated}, not {start}")
    pts = sampler.random(n)
    for j, d in enumerate(sw.dims):
        k = np.minimum((pts[:, j] * len(d.values)).astype(np.int64), len(d.values) - 1)
        out[d.key] = d.values[k] if len(d.values) <= 64 or d.integer \
            else d.low + pts[:, j] * (d.high - d.low)
    return out


def _chunk_inputs(sw: Sweep, varied: dict, base: dict, alpha_n: float) -> dict:
    n = len(next(iter(varied.values())))

    def col(key):
        if key in varied:
            return np.asarray(varied[key], dtype=float)
        return np.full(n, float(base[key]))

    m_n, z1, z2 = col("gear.module"), col("gear.z1"), col("gear.z2")
    beta = np.radians(col("gear.helix_angle"))
    b_w = col("gear.face_width")
    rule = _shift_rule(varied, base)
    if rule != "given":
        from geardesign.involute import inv

        a_w = col("gear.center_distance")
        alpha_t = np.arctan(math.tan(alpha_n) / np.cos(beta))
        a = 0.5 * m_n * (z1 + z2) / np.cos(beta)
        cos_tw = np.clip(a * np.cos(alpha_t) / a_w, -1.0, 1.0)
        x_sum = (z1 + z2) * (inv(np.arccos(cos_tw)) - inv(alpha_t)) / (2.0 * math.tan(alpha_n))
        x_sum = np.where(a_w > a * np.cos(alpha_t) * (1 + 1e-9), x_sum, np.nan)
        if rule == "x1":
            x1 = col("gear.x1")
            x2 = x_sum - x1
        elif rule == "x2":
            x2 = col("gear.x2")
            x1 = x_sum - x2
        else:
            x1 = x2 = 0.5 * x_sum
    else:
        x1, x2 = col("gear.x1"), col("gear.x2")
    return dict(m_n=m_n, z1=z1, z2=z2, x1=x1, x2=x2, beta=beta, b_w=b_w)


def _with_fixed(spec_data: dict, chosen: dict) -> dict:
    """The spec data with the material tables ``chosen`` ({"material.pinion": table, ...})
    and the fixed gear data ({"gear.accuracy_grade": 7, ...})."""
    if not chosen:
        return spec_data
    data = dict(spec_data)
    mat = dict(data.get("material") or {})
    gear = dict(data.get("gear") or {})
    for key, value in chosen.items():
        table, name = key.split(".", 1)
        if table == "material":
            mat[name] = dict(value)
        else:
            gear[name] = value
    data["material"], data["gear"] = mat, gear
    return data


def _evaluate_in_groups(spec_data: dict, sw: Sweep, varied: dict, base: dict) -> tuple:
    """The kernel over the candidates, one call per combination of the varied keys that are
    fixed data of the kernel (materials, accuracy grade, bearing scheme).  Returns the
    inputs and the result arrays."""
    from geardesign.core.registry import load_data
    from geardesign.spur.kernel import evaluate, fixed_from_spec

    gdims = [d for d in sw.dims if d.choices or d.key in FIXED_KEYS]
    n = len(next(iter(varied.values())))
    codes = [varied[d.key].astype(np.int64) for d in gdims]
    combos = sorted(set(zip(*codes))) if gdims else [()]
    c = out = None
    for combo in combos:
        chosen = {d.key: (d.choices[k] if d.choices else int(k)) for d, k in zip(gdims, combo)}
        _, spec = load_data(_with_fixed(spec_data, chosen), "sweep")
        fixed = fixed_from_spec(spec)
        if c is None:
            c = _chunk_inputs(sw, varied, base, fixed.rack.alpha_n)
            bad = ~np.isfinite(c["x1"]) | ~np.isfinite(c["x2"])
            c["x1"] = np.where(bad, 0.0, c["x1"])
            c["x2"] = np.where(bad, 0.0, c["x2"])
            c["bad"] = bad
        if len(combos) == 1:    # one group: the chunk's arrays as they are, no masked copies
            part = evaluate({k: v for k, v in c.items() if k != "bad"}, fixed)
            return c, {k: np.broadcast_to(v, (n,)).copy() if np.shape(v) != (n,) else v
                       for k, v in part.items()}
        sel = np.ones(n, dtype=bool)
        for code, k in zip(codes, combo):
            sel &= code == k
        part = evaluate({k: v[sel] for k, v in c.items() if k != "bad"}, fixed)
        if out is None:
            out = {k: np.empty(n, dtype=np.asarray(v).dtype) for k, v in part.items()}
        for k, v in part.items():
            if k in out:
                out[k][sel] = v
    return c, out


def evaluate_chunk(spec_data: dict, sw: Sweep, start: int, stop: int, rows: bool = False,
                   sampler=None) -> dict:
    """Evaluate candidates ``start`` … ``stop − 1`` and return the chunk's summary: counts,
    the ranked head and the Pareto front (as column arrays).  A pure function of its
    arguments: a worker process or a Dask worker runs it as the local loop does.  With
    ``rows`` it also returns every candidate's columns (the dataset of ``--data``);
    ``sampler``: a Sobol sample's engine positioned at ``start`` (:func:`samplers`)."""
    from geardesign.core.registry import load_data

    _, spec = load_data(spec_data, "sweep")
    base = _base_values(spec)
    varied = candidates(sw, start, stop, sampler)
    c, r = _evaluate_in_groups(spec_data, sw, varied, base)
    bad = c["bad"]
    r["valid"] &= ~bad
    r["passed"] &= ~bad
    r["helix_angle"] = np.degrees(c["beta"])
    r["m_n"], r["b_w"] = c["m_n"], c["b_w"]
    r["volume"] = (disc_volume(r["d1"], r["b_w"]) + disc_volume(r["d2"], r["b_w"])) / 1000.0
    r["mass"] = disc_mass(r["d1"], r["b_w"]) + disc_mass(r["d2"], r["b_w"])
    r["S_Hmin"] = np.minimum(r["S_H1"], r["S_H2"])
    from geardesign.planetary.efficiency import loss_factor
    from geardesign.spur.kinematics import specific_sliding

    eps_1 = (r["rho_a1"] - 0.5 * r["d_w1"] * np.sin(r["alpha_tw"])) / r["p_bt"]
    r["H_V"] = loss_factor(r["eps_alpha"], eps_1, r["z1"], r["u"], r["beta_b"])
    r["eta"] = 1.0 - sw.friction * r["H_V"]
    with np.errstate(all="ignore"):
        th1A = specific_sliding(r["rho_p1"], r["rho_a2"], r["u"])[0]
        th2E = specific_sliding(r["rho_a1"], r["rho_p2"], r["u"])[1]
    r["sliding"] = np.where((r["rho_p1"] > 0) & (r["rho_p2"] > 0),
                            np.maximum(np.abs(th1A), np.abs(th2E)), np.inf)
    for d, col in ((d, MATERIAL_COLUMNS[d.key]) for d in sw.dims if d.choices):
        r[col] = varied[d.key].astype(float)
    for d in sw.dims:
        if d.key in FIXED_KEYS:
            r[d.key.split(".", 1)[1]] = varied[d.key].astype(float)
    with np.errstate(all="ignore"):
        r["psi_bd"] = r["b_w"] / r["d_w1"]
        r["psi_ba"] = r["b_w"] / r["a_w"]
    r["ok_FACE_WIDTH_RATIO"] = (face_width_ratio_ok(r["psi_bd"], *sw.psi_bd)
                                & face_width_ratio_ok(r["psi_ba"], *sw.psi_ba))
    feasible = (r["passed"] & r["ok_FACE_WIDTH_RATIO"]
                & (r["margin"] >= sw.min_margin * (1 - 1e-12)))
    if sw.ratio is not None:
        feasible &= (r["u"] >= sw.ratio[0] - 1e-12) & (r["u"] <= sw.ratio[1] + 1e-12)
    if sw.center_distance_range is not None:
        lo, hi = sw.center_distance_range
        feasible &= (r["a_w"] >= lo - 1e-9) & (r["a_w"] <= hi + 1e-9)
    index = np.arange(start, stop)
    counts = {"evaluated": stop - start, "valid": int(r["valid"].sum()),
              "passed": int(r["passed"].sum()), "feasible": int(feasible.sum())}
    fails = {k[3:]: int((r["valid"] & ~r[k]).sum()) for k in r if k.startswith("ok_")}
    sel = {k: r[k][feasible] for k in COLUMNS + ("S_Hmin",) + tuple(
        MATERIAL_COLUMNS[d.key] for d in sw.dims if d.choices) + tuple(
        d.key.split(".", 1)[1] for d in sw.dims if d.key in FIXED_KEYS)}
    sel["index"] = index[feasible]
    head = _rank(sel, sw)
    front = _front(sel, sw)
    return {"counts": counts, "fails": fails, "head": head, "front": front,
            "rows": _dataset(r, feasible, index) if rows else None}


def _dataset(r: dict, feasible, index) -> dict:
    cols = {"index": index}
    for k in COLUMNS + tuple(MATERIAL_COLUMNS.values()):
        if k in r:
            cols[k] = r[k]
    for k in r:
        if k.startswith("ok_"):
            cols[k] = r[k]
    cols["valid"], cols["passed"], cols["feasible"] = r["valid"], r["passed"], feasible
    return cols


def _keys(sel: dict, sw: Sweep) -> list:
    """Sort keys, most significant first: the objectives in order, then the candidate index
    (a stable, machine-independent order)."""
    keys = [sel["index"]]
    for name in reversed(sw.objectives):
        col, sign, _, _ = OBJECTIVES[name]
        keys.append(sign * sel[col])
    return keys


def _rank(sel: dict, sw: Sweep) -> dict:
    if not len(sel["index"]):
        return sel
    order = np.lexsort(_keys(sel, sw))[: sw.top]
    return {k: v[order] for k, v in sel.items()}


def _front(sel: dict, sw: Sweep) -> dict:
    """The non-dominated candidates of the first two objectives (one objective: the best).
    Sorted by the first objective; a candidate enters when it improves on the second."""
    if not len(sel["index"]):
        return sel
    names = sw.objectives[:2]
    c1, s1, _, _ = OBJECTIVES[names[0]]
    if len(names) == 1:
        order = np.lexsort((sel["index"], s1 * sel[c1]))[:1]
        return {k: v[order] for k, v in sel.items()}
    c2, s2, _, _ = OBJECTIVES[names[1]]
    f1, f2 = s1 * sel[c1], s2 * sel[c2]
    order = np.lexsort((sel["index"], f2, f1))
    f2s = f2[order]
    best = np.minimum.accumulate(f2s)
    keep = np.ones(len(order), dtype=bool)
    keep[1:] = f2s[1:] < best[:-1]
    return {k: v[order[keep]] for k, v in sel.items()}


def _merge(a: dict, b: dict) -> dict:
    if a is None:
        return b
    return {k: np.concatenate([a[k], b[k]]) for k in a}


CONNECT_TIMEOUT = 10.0
"""Seconds to reach a Dask scheduler before the sweep is refused (a scheduler on the network
answers within a second)."""


class SchedulerError(Exception):
    """The Dask scheduler given cannot be reached (one line for the user)."""


def connect(address: str, timeout: float | None = None):
    """A Dask client of the scheduler at ``address``; :class:`SchedulerError` when dask is
    not installed, the address is malformed or nothing answers within ``timeout`` s
    (default :data:`CONNECT_TIMEOUT`)."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise SchedulerError("dask.distributed is not installed; install it with "
                             "`pip install \"dask[distributed]\"`") from None
    timeout = CONNECT_TIMEOUT if timeout is None else timeout
    try:
        return Client(address, timeout=timeout)
    except (OSError, ValueError, TypeError) as exc:
        why = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise SchedulerError(f"cannot reach the Dask scheduler within {timeout:g} s "
                             f"({why[:200]})") from None


def samplers(sw: Sweep, bounds: list, copies: bool = False):
    """For each chunk ``(start, stop)`` of ``bounds`` in order, the Sobol engine positioned
    at ``start`` (``None`` for a grid): one engine drawn on chunk after chunk, so the
    sequence's work is linear in the sample.  With ``copies`` (chunks evaluated elsewhere,
    in any order) each chunk gets a copy and the one engine skips the chunk's points."""
    if sw.samples is None:
        yield from itertools.repeat(None, len(bounds))
        return
    import copy

    from geardesign.spur.sobol import engine

    eng = engine(len(sw.dims), sw.seed, bounds[0][0] if bounds else 0)
    for a, b in bounds:
        if not copies:
            yield eng
            continue
        yield copy.deepcopy(eng)
        eng.fast_forward(b - a)


def local_cluster(workers: int = 2):
    """A Dask ``LocalCluster`` of ``workers`` single-threaded worker processes for sweeps
    (the benchmark and the tests; ``--scheduler`` takes its address).

    Dask's nanny starts workers with ``MALLOC_TRIM_THRESHOLD_=65536``, which fixes glibc's
    mmap threshold: every array of a chunk above 128 kB is then mapped and unmapped anew
    (page faults, system time about six times the local run's), and two such workers were
    slower than one local process.  Unset here, glibc keeps its dynamic threshold as a local
    process does.  A cluster started otherwise (``dask worker``) is set the same way with
    ``distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_: null`` in its Dask
    configuration (docs/sweep.md)."""
    import dask
    from distributed import LocalCluster

    with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                            dashboard_address=None)


def run_sweep(spec_data: dict, sw: Sweep, workers: int = 1, scheduler: str | None = None,
              progress=None, rows_sink=None) -> dict:
    """Evaluate the whole sweep chunk by chunk (in parallel when asked) and return the
    merged summary: counts, failing checks, the ranked head and the Pareto front."""
    total = sw.size
    bounds = [(s, min(s + CHUNK, total)) for s in range(0, total, CHUNK)]
    rows = rows_sink is not None
    counts = {"evaluated": 0, "valid": 0, "passed": 0, "feasible": 0}
    fails: dict = {}
    head = front = None

    def take(res):
        nonlocal head, front
        for k in counts:
            counts[k] += res["counts"][k]
        for k, v in res["fails"].items():
            fails[k] = fails.get(k, 0) + v
        head = _rank(_merge(head, res["head"]), sw)
        front = _front(_merge(front, res["front"]), sw)
        if rows_sink is not None:
            rows_sink(res["rows"])
        if progress is not None:
            progress(res["counts"]["evaluated"])

    if scheduler is not None:
        from dask.distributed import as_completed

        with connect(scheduler) as client:
            futures = [client.submit(evaluate_chunk, spec_data, sw, a, b, rows, e, pure=False)
                       for (a, b), e in zip(bounds, samplers(sw, bounds, copies=True))]
            order = {fut.key: i for i, fut in enumerate(futures)}
            done = {}
            for fut in as_completed(futures):
                done[order[fut.key]] = fut.result()
            for i in range(len(bounds)):
                take(done[i])
    elif workers > 1 and len(bounds) > 1:
        from concurrent.futures import ProcessPoolExecutor

        from geardesign.core.io import worker_signals

        pool = ProcessPoolExecutor(max_workers=min(workers, len(bounds)),
                                   initializer=worker_signals)
        try:
            for res in pool.map(evaluate_chunk, itertools.repeat(spec_data), itertools.repeat(sw),
                                [a for a, _ in bounds], [b for _, b in bounds],
                                itertools.repeat(rows), samplers(sw, bounds, copies=True)):
                take(res)
        except BaseException:     # Ctrl-C or an error: stop at once, no queued chunk runs
            pool.shutdown(wait=False, cancel_futures=True)
            raise
        pool.shutdown()
    else:
        for (a, b), e in zip(bounds, samplers(sw, bounds)):
            take(evaluate_chunk(spec_data, sw, a, b, rows, e))
    return {"counts": counts, "fails": fails, "head": head, "front": front}


# ----------------------------------------------------------------------------- report


def variant_spec(spec_data: dict, sw: Sweep, index: int) -> dict:
    """The spur spec (without ``[sweep]``) of candidate ``index``: the base spec with the
    varied values written in (``geardesign run`` of it reproduces the variant)."""
    from geardesign.core.registry import load_data

    varied = candidates(sw, index, index + 1)
    _, spec = load_data(spec_data, "sweep")
    rule = _shift_rule(varied, _base_values(spec))
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in spec_data.items()}
    gear = dict(data["gear"])
    chosen = {}
    for key, arr in varied.items():
        if key in MATERIAL_KEYS:
            dim = next(d for d in sw.dims if d.key == key)
            chosen[key] = dim.choices[int(arr[0])]
            continue
        name = key.split(".", 1)[1]
        v = float(arr[0])
        gear[name] = int(v) if VARIABLE[key][0] else v
    if rule != "given":
        keep = {"x1": gear.get("x1"), "x2": gear.get("x2")}
        for k in ("x1", "x2", "shift_split"):
            gear.pop(k, None)
        if rule in ("x1", "x2"):
            gear[rule] = keep[rule]
        else:
            gear["shift_split"] = "equal"
    data["gear"] = gear
    return _with_fixed(data, chosen)


def load_sweep(data: dict, source: str, vary=(), samples=None, seed=None):
    """Split a parsed sweep spec into the base spur spec data and the :class:`Sweep`;
    validate both (one problem per bad key, :class:`InputError`)."""
    from geardesign.core.registry import load_data

    data = dict(data)
    table = data.pop("sweep", None)
    if table is not None and not isinstance(table, dict):
        raise InputError(Problem("sweep", "must be a table ([sweep])", table))
    if data.get("kind") != "spur":
        raise InputError(Problem("kind", "a sweep varies a spur pair: kind = \"spur\"",
                                 data.get("kind")))
    sw = parse_sweep(table, list(vary), samples, seed)
    _, spec = load_data(data, source)          # the base design must itself be valid
    for d in sw.dims:
        for i, choice in enumerate(d.choices):
            try:
                load_data(_with_fixed(data, {d.key: choice}), source)
            except InputError as exc:
                p = exc.problems[0]
                raise InputError(Problem(f"sweep.{d.key}.values[{i}]: {p.key}", p.message,
                                         p.value)) from None
    if spec.data.get("mode") == "design":
        raise InputError(Problem("mode", "a sweep varies a given pair; remove mode = "
                                 "\"design\"", "design"))
    if spec.data["gear"].get("internal"):
        raise InputError(Problem("gear.internal", "a sweep rates external pairs", True))
    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen

    if not any(d.key == "gear.bearing_scheme" for d in sw.dims):
        from geardesign.spur.calculator import _strength_inputs

        # the base design's strength inputs (a missing bearing scheme of the GOST rating):
        # input errors here, not inside the evaluation
        _strength_inputs(spec, spec.data["gear"])
    methods = chosen(spec.data["options"])
    if len(methods) > 1:
        raise InputError(Problem("options.methods", "a sweep rates by one method: give "
                                 "options.method = \"GOST 21354-87\" or \"ISO 6336:2019\", "
                                 "then rate the ranked variants by the other with --emit-spec "
                                 "and geardesign run", methods))
    if methods == [ISO_NAME]:
        if (spec.data.get("load") or {}).get("spectrum"):
            raise InputError(Problem("load.spectrum", "a sweep rates ISO 6336 at the nominal "
                                     "torque only: remove the load spectrum (or sweep by GOST "
                                     "21354-87), then rate the ranked variants with the spectrum "
                                     "with --emit-spec and geardesign run", "[[load.spectrum]]"))
        if (spec.data.get("iso") or {}).get("scuffing") is not None:
            raise InputError(Problem("iso.scuffing", "a sweep does not rate scuffing: remove "
                                     "[iso.scuffing], then rate the ranked variants for "
                                     "scuffing with --emit-spec and geardesign run",
                                     "[iso.scuffing]"))
    return data, sw


def rating_method(data: dict) -> str:
    """The strength method of a sweep's base spec data (one, as :func:`load_sweep` checks)."""
    opts = data.get("options") or {}
    names = opts.get("methods") or [opts.get("method") or "GOST 21354-87"]
    return names[0]


def sweep_result(data: dict, sw: Sweep, summary: dict, source: str = ""):
    """The :class:`~geardesign.core.result.Result` of a finished sweep: counts, the ranked
    variants, the Pareto front, and a check that a feasible variant exists (with the checks
    that rejected the most candidates as advice)."""
    from geardesign.core.result import DataTable, Result, Row, check

    inputs = {"sweep": {d.key: {"values": len(d.values), "from": d.low, "to": d.high}
                        for d in sw.dims},
              "samples": sw.samples, "seed": sw.seed, "objectives": list(sw.objectives),
              "ratio": list(sw.ratio) if sw.ratio else None,
              "center_distance_range": list(sw.center_distance_range)
              if sw.center_distance_range else None,
              "psi_bd": list(sw.psi_bd), "psi_ba": list(sw.psi_ba),
              "min_margin": sw.min_margin, "friction": sw.friction, "top": sw.top,
              "base": {k: v for k, v in data.items() if k not in ("kind", "title")}}
    rows = [Row(f"sweep.{d.key}", "; ".join(_material_label(t) for t in d.choices)
                if d.choices else f"{len(d.values)} values, {d.low:g} … {d.high:g}", None,
                d.key, "varied key") for d in sw.dims]
    res = Result("sweep", data.get("title"), ["GOST 16532-70", rating_method(data)], inputs,
                 rows, source=source)
    c = summary["counts"]
    sec = res.section("counts", "Candidates")
    sec.add("evaluated", c["evaluated"], "-", "N", "candidates evaluated ("
            + (f"Sobol sample, seed = {sw.seed}" if sw.samples else "full grid") + ")")
    sec.add("valid", c["valid"], "-", "N_valid", "candidates that form a gear pair")
    sec.add("passed", c["passed"], "-", "N_pass", "candidates that pass every error check")
    sec.add("feasible", c["feasible"], "-", "N_feas", "passing candidates within the "
            "constraints (ratio, centre distance, ψ_bd and ψ_ba windows, margin)")
    fails = res.section("rejections", "Candidates rejected, by check")
    for code, n in sorted(summary["fails"].items(), key=lambda kv: (-kv[1], kv[0])):
        if n:
            fails.add(code, n, "-", code, f"valid candidates failing {code}")
    cols = [("rank", "rank", "-"), ("index", "candidate", "-"), ("m_n", "m_n", "mm"),
            ("z1", "z1", "-"), ("z2", "z2", "-"), ("x1", "x1", "-"), ("x2", "x2", "-"),
            ("helix_angle", "β", "deg"), ("b_w", "b_w", "mm"), ("psi_bd", "ψ_bd", "-"),
            ("u", "u", "-"),
            ("a_w", "a_w", "mm"), ("S_H1", "S_H1", "-"), ("S_F1", "S_F1", "-"),
            ("S_F2", "S_F2", "-"), ("margin", "margin", "-"), ("mass", "mass", "kg")]
    for name in sw.objectives:
        col, _, unit, _ = OBJECTIVES[name]
        if col not in [c[0] for c in cols]:
            cols.append((col, col, unit))
    cols.append(("full_check", "full check", None))
    mdims = [d for d in sw.dims if d.choices]
    for i, d in enumerate(mdims):
        cols.insert(2 + i, (MATERIAL_COLUMNS[d.key], d.key.split(".")[1], None))
    for d in sw.dims:
        if d.key in FIXED_KEYS:
            name = d.key.split(".", 1)[1]
            cols.insert(2, (name, name.replace("_", " "), "-"))
    verified: dict = {}
    for key, title, block in (("ranked", f"Ranked variants (by {', '.join(sw.objectives)})",
                               summary["head"]),
                              ("pareto", "Pareto front of " + " and ".join(sw.objectives[:2]),
                               summary["front"])):
        t = DataTable(key, title, cols)
        if block is not None:
            for i in range(len(block["index"])):
                r = {k: float(block[k][i]) for k in block if k in dict((c[0], 1) for c in cols)}
                r["rank"] = i + 1
                r["index"] = int(block["index"][i])
                for d in mdims:
                    r[MATERIAL_COLUMNS[d.key]] = _material_label(
                        d.choices[int(block[MATERIAL_COLUMNS[d.key]][i])])
                r["z1"], r["z2"] = int(r["z1"]), int(r["z2"])
                for d in sw.dims:
                    if d.key in FIXED_KEYS:
                        name = d.key.split(".", 1)[1]
                        r[name] = int(r[name])
                if r["index"] not in verified and i < FULL_CHECKS:
                    verified[r["index"]] = full_check(data, sw, r["index"])
                r["full_check"] = verified.get(r["index"], "not run")
                t.rows.append(r)
        res.tables.append(t)
    failing = sorted(i for i, v in verified.items() if v != "pass")
    if failing:
        res.checks.append(check(
            "SWEEP_FULL_CHECK", False, "warning",
            f"{len(failing)} reported variant(s) fail checks the kernel does not make (column "
            f"full check; e.g. the peak-torque checks): candidates "
            f"{', '.join(map(str, failing[:10]))}; take a variant that passes, or rate one with "
            f"--emit-spec and geardesign run for its full report", "", len(failing), 0,
            "sweep"))
    edge = range_edges(sw, summary["head"])
    if edge:
        res.checks.append(check(
            "SWEEP_RANGE_EDGE", False, "warning",
            f"the first ranked variant sits on the boundary of a varied range: "
            f"{'; '.join(edge)}: a better variant may lie beyond it; widen that range (or "
            f"fix the key if the boundary is a limit of the design)", "", len(edge), 0,
            "sweep"))
    top = sorted(((n, k) for k, n in summary["fails"].items() if n), reverse=True)[:3]
    why = ", ".join(f"{k} ({n})" for n, k in top)
    res.checks.append(check(
        "SWEEP_FEASIBLE", c["feasible"] > 0, "error",
        f"no variant of the {c['evaluated']} candidates is feasible"
        + (f"; the checks that rejected the most: {why}" if why else "")
        + ": widen the ranges (larger modules or face widths, other tooth counts), relax the "
          "constraints (ratio window, centre distance range, psi_bd and psi_ba windows, "
          "min_margin) or use stronger "
          "materials",
        f"{c['feasible']} of {c['evaluated']} candidates are feasible", c["feasible"], 1,
        "sweep"))
    return res


RANGE_COLUMNS = {"gear.module": "m_n", "gear.z1": "z1", "gear.z2": "z2", "gear.x1": "x1",
                 "gear.x2": "x2", "gear.helix_angle": "helix_angle", "gear.face_width": "b_w",
                 "gear.center_distance": "a_w", "gear.accuracy_grade": "accuracy_grade",
                 "gear.bearing_scheme": "bearing_scheme"}
"""The column of the ranked variants that holds each varied key's value."""

EDGE_SAMPLE = 0.02
"""In a sample (not a grid), a value within this part of its range of an end is at it."""


def range_edges(sw: Sweep, head: dict | None) -> list[str]:
    """The varied keys (of more than one value) whose value in the first ranked variant is
    an end of their range, as "gear.helix_angle = 15 at the top of 0 … 15"."""
    if head is None or not len(head["index"]):
        return []
    out = []
    for d in sw.dims:
        col = RANGE_COLUMNS.get(d.key)
        if col is None or col not in head or d.high <= d.low:
            continue
        v = float(head[col][0])
        tol = (EDGE_SAMPLE if sw.samples else 1e-9) * (d.high - d.low)
        for end, word in ((d.high, "top"), (d.low, "bottom")):
            if abs(v - end) <= tol:
                out.append(f"{d.key} = {v:.6g} at the {word} of {d.low:g} … {d.high:g}")
                break
    return out


def full_check(data: dict, sw: Sweep, index: int) -> str:
    """The verdict of the whole calculator on candidate ``index`` (its emitted spec): "pass",
    or "fail: " and the failing error checks (those the kernel makes pass already)."""
    from geardesign.core.errors import InputError as _IE
    from geardesign.core.registry import load_data

    try:   # the verdict only: rated without the advice (no re-rating for fixes)
        calc, spec = load_data(variant_spec(data, sw, index))
        res = calc.rate(spec)
    except _IE as exc:
        return "input: " + exc.problems[0].key
    failed = [c.code for c in res.failed]
    return "pass" if not failed else "fail: " + ", ".join(failed[:4])


def _material_label(t: dict) -> str:
    """A material table in a few words: grade, treatment and hardness."""
    parts = [str(t.get("grade", "")), str(t.get("treatment", ""))]
    for k, unit in (("hardness_HB", "HB"), ("hardness_HRC", "HRC"), ("hardness_HV", "HV")):
        if k in t:
            parts.append(f"{t[k]:g} {unit}")
    return " ".join(p for p in parts if p)


def run_data(data: dict, source: str = ""):
    """The :class:`~geardesign.core.result.Result` of a parsed sweep spec, run in this
    process (what ``geardesign check`` compares with the golden file)."""
    base, sw = load_sweep(data, source)
    return sweep_result(base, sw, run_sweep(base, sw), source)
