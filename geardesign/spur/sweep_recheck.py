"""The re-check of a sweep's reported variants by the whole calculator, and the spur spec of
a variant (``geardesign sweep --emit-spec``)."""

from __future__ import annotations

from geardesign.spur.sweep_chunk import _base_values, _chunk_inputs, _shift_rule, candidates
from geardesign.spur.sweep_input import FIXED_KEYS, MATERIAL_KEYS, VARIABLE, Sweep, _with_fixed


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


def full_check(data: dict, sw: Sweep, index: int, bases: dict | None = None) -> str:
    """The verdict of the whole calculator on candidate ``index``: "pass", or "fail: " and
    the failing error checks (those the kernel makes pass already).

    The variant is solved by :func:`geardesign.spur.solve.solve` on typed inputs: the
    :class:`~geardesign.spur.inputs.Inputs` of the base spec (with the candidate's
    materials, accuracy grade and bearing scheme; read once per combination and kept in
    ``bases``) with the candidate's pair data (module, teeth, shifts, helix angle, face width:
    the values the kernel rated), and reported by :func:`geardesign.spur.report.report`
    without the advice (the verdict only: no re-rating for fixes)."""
    import dataclasses

    from geardesign.core.errors import InputError as _IE
    from geardesign.spur.report import report
    from geardesign.spur.solve import solve

    bases = {} if bases is None else bases
    varied = candidates(sw, index, index + 1)
    chosen = {d.key: (d.choices[int(varied[d.key][0])] if d.choices
                      else int(varied[d.key][0]))
              for d in sw.dims if d.choices or d.key in FIXED_KEYS}
    try:
        key = repr(sorted(chosen.items()))
        if key not in bases:
            bases[key] = _base_inputs(_with_fixed(data, chosen))
        inputs, base = bases[key]
        pair = _chunk_inputs(sw, varied, base, inputs.pair.rack.alpha_n)
        variant = inputs.replace(**{k: float(v[0]) for k, v in pair.items()
                                    if k not in ("z1", "z2")},
                                 z1=int(pair["z1"][0]), z2=int(pair["z2"][0]))
        # the report echoes the base spec's other tables (its rows are not read here)
        res = report(solve(dataclasses.replace(variant, spec=inputs.spec)))
    except _IE as exc:
        return "input: " + exc.problems[0].key
    failed = [c.code for c in res.failed]
    return "pass" if not failed else "fail: " + ", ".join(failed[:4])


def _base_inputs(data: dict) -> tuple:
    """The typed inputs of the spec data ``data`` and its pair's values (:func:`_base_values`)."""
    from geardesign.core.registry import load_data
    from geardesign.spur.inputs import from_spec

    _, spec = load_data(data, "sweep")
    base = _base_values(spec)
    return from_spec(spec), base
