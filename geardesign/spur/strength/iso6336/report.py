"""The ISO 6336 rating of a spur spec as report sections and checks."""

from __future__ import annotations

from geardesign.spur.strength.common import add_rows
from geardesign.spur.strength.iso6336 import rating as IR
from geardesign.spur.strength.iso6336.spec import ISO_NAME, gear_checks, iso_setting


def add_iso_strength(res, geom, spec, inputs, rating=None, iso=None) -> dict:
    """Rate the pair of a spur spec to ISO 6336 (``inputs``: materials, duty, setting;
    ``rating`` and its ``iso`` setting when already rated): rows under the sections
    ``iso6336_*``, checks, method name; the rating's value record."""
    mats, duty, setting = inputs
    if rating is None:
        gear_checks(spec.data["iso"], geom)
        iso = iso_setting(spec)
        rating = IR.rate(geom, mats, duty, setting, iso)
    res.methods.append(ISO_NAME)
    add_rows(res, rating, IR.SECTIONS)
    internal = bool(getattr(geom, "internal", False))
    from geardesign.core.rerating import rerating

    found = None if internal or rerating() else _advice(rating.v, geom, mats, duty, setting,
                                                         iso)
    from geardesign.spur.strength.checks import rating_checks

    res.checks.extend(rating_checks(rating, found=found, internal=internal))
    from geardesign.spur.methods_differ import ISO, advised

    v = rating.v
    need = [v[f"sigma_Hlim{k}"] * v["S_Hmin"] / v.get(f"S_Hspec{k}", v[f"S_H{k}"])
            for k in (1, 2)]
    found = found or {}
    b, k = found.get("b") or (None, None, None), found.get("k") or (None, None, None)
    return {**v, "advice": advised(ISO, b[1] or b[2], None if k[1] is None else k[1] * k[0],
                                   max(need) if max(need) > max(v["sigma_Hlim1"],
                                                                v["sigma_Hlim2"]) else None)}


def iso_rating(spec) -> "IR.IsoRating":
    """The ISO 6336 rating record of a spur spec, without report rows or advice: for a
    caller that needs a factor of it (e.g. a drive's K_Hβ with the misalignment its shafts
    give).  The spec must rate strength (torque and materials).  A pair that cannot mesh
    as computed (:func:`geardesign.spur.solve.ratable`, as the spur calculator rates) is
    one :class:`InputError` naming ``gear``."""
    from geardesign.core.errors import InputError, Problem
    from geardesign.spur.solve import ratable
    from geardesign.spur.spec_inputs import _strength_inputs, solve_geometry

    geom, _ = solve_geometry(spec)
    if not ratable(geom):
        raise InputError(Problem("gear", "the pair cannot mesh as computed (ε_α < 1, a tip "
                                         "beyond the mate's tangency point, or a pointed "
                                         "tooth): not rated by ISO 6336"))
    mats, duty, setting = _strength_inputs(spec, spec.data["gear"])
    gear_checks(spec.data["iso"], geom)
    return IR.rate(geom, mats, duty, setting, iso_setting(spec))


def _advice(v: dict, geom, mats, duty, setting, iso) -> dict | None:
    """Face width and scale of the pair that pass pitting and bending, found by re-rating
    (the load factors change with the size), the face width within the proportions of
    :func:`geardesign.spur.strength.checks.face_advice_limit`; ``None`` when the rating passes."""
    from dataclasses import replace

    from geardesign.gears.geometry import pair_geometry
    from geardesign.spur.strength.advice import (face_advice_limit, least_passing,
                                                  reconciled_widths)

    fails = [kind for kind in ("H", "F") if not IR.passes(v, kind)]
    if not fails:
        return None
    inp = geom.inp

    def rerate(b: float) -> dict:
        return IR.rate(pair_geometry(replace(inp, b_w=b)), mats, duty, setting, iso).v

    def rescale(k: float) -> dict:
        return IR.rate(pair_geometry(replace(inp, m_n=k * inp.m_n, b_w=k * inp.b_w)), mats,
                       duty, setting, iso).v

    b = [inp.b_w, None, None]
    k = [geom.a_w, None, None]
    limit = face_advice_limit(inp.b_w, geom.g1.d_w)
    for i, kind in ((1, "H"), (2, "F")):
        if kind in fails:
            b[i] = least_passing(rerate, inp.b_w, lambda x, kind=kind: IR.passes(x, kind),
                                 limit)
            k[i] = least_passing(rescale, 1.0, lambda x, kind=kind: IR.passes(x, kind), 4.0)
    b[1], b[2] = reconciled_widths(b[1], b[2])
    return {"b": tuple(b), "k": tuple(k), "face_limit": limit}
