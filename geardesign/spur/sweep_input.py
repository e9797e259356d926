"""The input of a design sweep: the ``[sweep]`` table and the command-line options read into
a :class:`Sweep` (the varied keys as :class:`Dim`, the constraints, the objectives), and a
sweep spec split into its base spur spec and the sweep (:func:`load_sweep`).  The keys a
sweep may vary and the objectives it ranks by are listed here (docs/sweep.md)."""

from __future__ import annotations

import math
from dataclasses import field

import numpy as np

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.spur.checks import PSI_BA_WINDOW, PSI_BD_MAX, PSI_BD_MIN

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
"""Columns of the varied materials: the index into the key's list of material tables."""

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

