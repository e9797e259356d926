"""The re-check of a sweep's reported variants by the whole calculator, and the spur spec of
a variant (``geardesign sweep --emit-spec``)."""

from __future__ import annotations

from geardesign.spur.sweep_chunk import _base_values, _shift_rule, candidates
from geardesign.spur.sweep_input import MATERIAL_KEYS, VARIABLE, Sweep, _with_fixed

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


