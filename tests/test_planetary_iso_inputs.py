"""The ISO 6336 inputs of the planetary calculator: every key of the spur calculator's
``[iso]``, ``[iso.pinion]``/``[iso.wheel]`` and ``[iso_factors]``, given per member and per
mesh, changes a planetary mesh's rating as it changes the rating of the same pair in the
spur calculator; keys the rating does not read are input errors.

The equivalent spur pair of a mesh: the same gears in the mesh's rating order (gear 1 =
pinion), the torque and speed of gear 1 relative to the carrier, the meshes per revolution
of the train (n_w for a central gear), the same materials.  The train has no shifts, so the
planet's tip (shortened by Δy in its sun mesh, carried into its ring mesh) is the nominal
tip of the spur pair.  The planetary-specific factors are taken out of the comparison:
K_γ = 1 (``load_sharing``), and in the sun–planet mesh K_v is given on both sides (the
reduced mass of a sun shared by n_w planets is the planetary calculator's own); Y_M of the
planet (loaded on both flanks in the train, a spur pair has one reversed-load ratio for
both gears) is given on both sides.
"""

from __future__ import annotations

import copy

import pytest

from geardesign.core.registry import run_data
from tests.reference.planetary._util import planetary
from geardesign.core.errors import InputError

BASE = {
    "train": {"planets": 3, "module": 3.0, "face_width": 30.0},
    "teeth": {"sun": 18, "planet": 27, "ring": 72},
    "ring": {"tip_shortening": 0.15},
    "cutter": {"teeth": 25},
    "operation": {"fixed": "ring", "input": "sun", "output": "carrier", "speed": 1450.0,
                  "torque": 200.0},
    "strength": {"method": "ISO 6336:2019", "life_hours": 20000.0, "load_sharing": 1.0,
                 "accuracy_grade": 7},
    "material": {
        "sun": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 59.0},
        "planet": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 59.0,
                   "roughness_Ra": 0.8},
        "ring": {"grade": "40KhN", "treatment": "improved", "hardness_HB": 280.0},
    },
}
#: mesh: gear 1, gear 2, the planet's index in the pair (its Y_M given), K_v given
MESHES = {"sun_planet": ("sun", "planet", 2, True), "planet_ring": ("planet", "ring", 1, False)}
#: rows that only the planetary report has
PLANETARY_ONLY = {"gear1", "gear2", "F_t_planet", "n1_rel"}


def _planetary_rows(data: dict, mesh: str) -> dict:
    return planetary(data)["results"][f"strength_{mesh}"]


def _spur_spec(data: dict, mesh: str) -> dict:
    """The spur spec of the pair of ``mesh`` with the same ISO inputs (member tables put
    as pinion and wheel, the mesh's pair keys and factors as the pair's)."""
    g1, g2, _, _ = MESHES[mesh]
    r = planetary(data)["results"]
    rows = r[f"strength_{mesh}"]
    internal = mesh == "planet_ring"
    tr = data["train"]
    gear = {"module": tr["module"], "z1": data["teeth"][g1], "z2": data["teeth"][g2],
            "face_width": tr["face_width"], "x1": 0.0, "x2": 0.0,
            "accuracy_grade": data["strength"]["accuracy_grade"]}
    if internal:
        gear.update(internal=True, cutter_teeth=data["cutter"]["teeth"],
                    internal_tip_shortening=data["ring"]["tip_shortening"])
    d1 = r["gears"][f"d_{g1}"]
    load = {"speed1": rows["n1_rel"], "torque1": rows["F_t_planet"] * d1 / 2000.0,
            "life_hours": data["strength"]["life_hours"],
            "meshes_pinion": 3 if g1 == "sun" else 1, "meshes_wheel": 3 if g2 != "planet" else 1}
    spec = {"kind": "spur", "gear": gear, "load": load, "options": {"method": "ISO 6336:2019"},
            "material": {"pinion": data["material"][g1], "wheel": data["material"][g2]}}
    iso_in = data.get("iso", {})
    iso = {k: v for k, v in iso_in.items() if not isinstance(v, dict)}
    iso.update(iso_in.get(mesh, {}))
    for who, member in (("pinion", g1), ("wheel", g2)):
        if member in iso_in:
            iso[who] = iso_in[member]
    if "lubricant_viscosity" in data["strength"]:
        iso["lubricant_viscosity"] = data["strength"]["lubricant_viscosity"]
    spec["iso"] = iso
    factors = data.get("iso_factors", {}).get(mesh)
    if factors:
        spec["iso_factors"] = factors
    return spec


def _spur_rows(spec: dict) -> dict:
    r = run_data(spec).document()["results"]
    out = {}
    for name, sec in r.items():
        if name.startswith("iso6336_"):
            out.update(sec)
    return out


def _with(data: dict, path: str, value) -> dict:
    out = copy.deepcopy(data)
    t = out
    keys = path.split(".")
    for k in keys[:-1]:
        t = t.setdefault(k, {})
    t[keys[-1]] = value
    return out


def _pinned(mesh: str) -> dict:
    """The planetary-specific factors given on both sides (see the module docstring)."""
    _, _, planet, kv = MESHES[mesh]
    f = {f"Y_M{planet}": 0.7}
    if kv:
        f["K_v"] = 1.05
    return f


def _pin(data: dict, mesh: str) -> dict:
    for k, v in _pinned(mesh).items():
        data = _with(data, f"iso_factors.{mesh}.{k}", v)
    return data


# key, value; "<m>" is gear 1 of the mesh, "<w>" gear 2 (member tables)
CASES = [
    ("iso.accuracy_grade", 5), ("iso.tip_relief", 12.0), ("iso.helix_modification", "crowning"),
    ("iso.f_ma", 6.0), ("iso.f_sh", 9.0), ("iso.f_pb", 11.0), ("iso.f_falpha", 8.0),
    ("iso.F_beta", 13.0), ("iso.S_Hmin", 1.3), ("iso.S_Fmin", 1.8),
    ("iso.limited_pitting", True), ("iso.optimum_conditions", True),
    ("iso.protuberance", 0.03),
    ("iso.shaft", {"shaft_K_prime": 0.48, "shaft_span": 120.0, "shaft_diameter": 30.0,
                   "pinion_offset": 12.0}),
    ("iso.<m>.quality", "ME"), ("iso.<w>.quality", "ML"), ("iso.<m>.sigma_Hlim", 1400.0),
    ("iso.<w>.sigma_Flim", 380.0), ("iso.<m>.Rz_flank", 3.0), ("iso.<w>.Rz_root", 4.0),
    ("iso.<m>.material_type", "NV"), ("iso.<m>.rim_thickness", 5.0),
    ("iso.<m>.web_ratio", 0.4), ("iso.<w>.rim_thickness", 5.0),
    ("iso_factors.<mesh>.Z_E", 190.0), ("iso_factors.<mesh>.K_Hbeta", 1.3),
    ("iso_factors.<mesh>.Y_F1", 1.6), ("iso_factors.<mesh>.Z_NT2", 1.1),
    ("strength.lubricant_viscosity", 100.0), ("iso.<m>.inner_diameter", 30.0),
]


@pytest.mark.parametrize("mesh", list(MESHES))
@pytest.mark.parametrize("key, value", CASES, ids=[c[0] for c in CASES])
def test_iso_key_changes_the_planetary_mesh_as_the_spur_pair(mesh, key, value):
    g1, g2, _, _ = MESHES[mesh]
    if mesh == "sun_planet" and key.endswith("inner_diameter"):
        pytest.skip("the bore acts through m_red alone, the planetary calculator's own in the "
                    "sun–planet mesh (K_v given there)")
    path = key.replace("<m>", g1).replace("<w>", g2).replace("<mesh>", mesh)
    if isinstance(value, dict):     # keys that act together
        data = copy.deepcopy(BASE)
        for k, v in value.items():
            data = _with(data, f"iso.{k}", v)
    else:
        data = _with(BASE, path, value)
    data, base = _pin(data, mesh), _pin(BASE, mesh)
    p, p0 = _planetary_rows(data, mesh), _planetary_rows(base, mesh)
    s = _spur_rows(_spur_spec(data, mesh))
    changed = {k for k in p if k not in PLANETARY_ONLY and p[k] != p0.get(k)}
    assert changed, f"{path} = {value!r} changes nothing in the {mesh} rating"
    skip = {"m_red", "n_E1", "N", "K_v_range"} if MESHES[mesh][3] else set()
    for k, v in p.items():
        if k in PLANETARY_ONLY or k in skip:
            continue
        assert k in s, (path, k)
        if isinstance(v, float):
            assert v == pytest.approx(s[k], rel=1e-9, abs=1e-12), (path, mesh, k, v, s[k])
        else:
            assert v == s[k], (path, mesh, k)


def test_mesh_table_replaces_the_pair_keys_of_one_mesh_only():
    data = _with(BASE, "iso.S_Hmin", 1.2)
    data = _with(data, "iso.planet_ring.S_Hmin", 1.5)
    r = planetary(data)["results"]
    assert r["strength_sun_planet"]["S_Hmin"] == 1.2
    assert r["strength_planet_ring"]["S_Hmin"] == 1.5


def test_required_safety_sets_the_verdict():
    """S_Hmin and S_Fmin decide the checks: just below and just above the computed safety."""
    rows = planetary(BASE)["results"]["strength_sun_planet"]
    S_H = min(rows["S_H1"], rows["S_H2"])
    S_F = min(rows["S_F1"], rows["S_F2"])
    for key, S, code in (("S_Hmin", S_H, "ISO_PITTING"), ("S_Fmin", S_F, "ISO_BENDING")):
        for factor, passed in ((0.99, True), (1.01, False)):
            if not 1.0 <= S * factor <= 5.0:
                continue
            doc = planetary(_with(BASE, f"iso.{key}", round(S * factor, 6)))
            found = [c for c in doc["checks"]
                     if c["code"].startswith(f"SUN_PLANET_{code}") and c["severity"] == "error"]
            assert found and all(c["passed"] for c in found) == passed, (key, factor, found)


def test_k_gamma_is_its_own_factor():
    """ISO 6336-1: F_t is the nominal force of one planet; K_γ multiplies the load factors
    (σ_H0, σ_F0 without it, σ_H with √K_γ, σ_F with K_γ)."""
    base = _pin(BASE, "sun_planet")
    data = _with(base, "strength.load_sharing", 1.2)
    a, b = (planetary(x)["results"]["strength_sun_planet"] for x in (base, data))
    assert b["K_gamma"] == 1.2 and "K_gamma" not in a
    for key in ("F_t", "F_t_planet", "sigma_H0", "sigma_F01", "sigma_F02"):
        assert b[key] == pytest.approx(a[key], rel=1e-12), key
    assert b["w"] == pytest.approx(1.2 * a["w"], rel=1e-12)


def test_planet_tip_of_the_sun_mesh_is_the_planet_tip_of_the_ring_mesh():
    """KISSsoft NREL stage 1 (shifted, Δy ≠ 0): the planet's tip diameter 905.470 mm
    (printed, shortened by k·m_n = −10.861 mm in the sun mesh) is used in the ring mesh:
    M1 = Z_B there is computed from it (the rating's d_a1)."""
    from tests.reference.planetary.test_kisssoft_nrel_stages import STAGE1

    from geardesign.core.spec import validate
    from geardesign.planetary import inputs as PI
    from geardesign.planetary.spec import SCHEMA

    spec = validate(SCHEMA, {"kind": "planetary", **copy.deepcopy(STAGE1)})
    meshes = PI.read(spec).meshes
    sun_planet, planet_ring = meshes
    assert sun_planet.geom.g2.d_a == pytest.approx(905.470, abs=0.002)
    assert planet_ring.geom.g1.d_a == sun_planet.geom.g2.d_a


# ----------------------------------------------------------------------------- input errors


@pytest.mark.parametrize("data, lines", [
    (_with(BASE, "iso.S_Hmim", 1.2),
     ['iso.S_Hmim = 1.2: unknown key in [iso] (did you mean "S_Hmin"?)']),
    (_with(BASE, "iso.sun.sigma_Flimb", 400.0),
     ['iso.sun.sigma_Flimb = 400.0: unknown key in [iso.sun] (did you mean "sigma_Flim"?)']),
    (_with(BASE, "iso_factors.sun_planet.K_gamma", 1.1),
     ["iso_factors.sun_planet.K_gamma = 1.1: unknown key in [iso_factors.sun_planet] (did you "
      "mean \"K_Bgamma\"?)"]),
    (_with(BASE, "iso.planet2.quality", "ME"),
     ["iso.planet2: this train has no planet2: leave [iso.planet2] out"]),
    (_with(BASE, "iso_factors.planet_ring2.Z_E", 190.0),
     ["iso_factors.planet_ring2: this train has no planet–ring2 mesh: leave "
      "[iso_factors.planet_ring2] out"]),
    (_with(_with(BASE, "strength.method", "GOST 21354-87"), "iso.S_Hmin", 1.2),
     ['iso: [iso] is read only by the ISO 6336 rating: set strength.method = "ISO 6336:2019" '
      'or leave the table out']),
    (_with(BASE, "material.sun.sigma_Flim", 900.0),
     ["material.sun.sigma_Flim = 900.0: is the GOST 21354-87 bending endurance limit σ_Flimb (about "
      "σ_FE = 2·σ_Flim of ISO 6336-5), not read by the ISO 6336 rating: give "
      "iso.sun.sigma_Flim (the ISO 6336-5 σ_Flim) instead"]),
    (_with(BASE, "material.ring.S_H", 1.2),
     ["material.ring.S_H = 1.2: is the GOST 21354-87 required safety, not read by the ISO 6336 "
      "rating: give iso.S_Hmin instead"]),
    (_with(BASE, "strength.tip_relief", True),
     ["strength.tip_relief = true: is the GOST 21354-87 switch, not read by the ISO 6336 rating: "
      "give iso.tip_relief (the amount C_a in µm) instead"]),
    (_with(BASE, "strength.bearing_scheme", 6),
     ["strength.bearing_scheme = 6: is the GOST 21354-87 chart of K_Hβ, not read by the ISO 6336 "
      "rating (K_Hβ by method C from f_sh and f_ma): give iso.f_sh or the shaft "
      "(iso.shaft_span, iso.shaft_diameter, iso.pinion_offset, iso.shaft_K_prime) instead"]),
    (_with(BASE, "strength.regime", "III"),
     ['strength.regime = "III": is the GOST 21354-87 typical load regime, not read by the ISO '
      '6336 rating (it rates the nominal torque over strength.life_hours): leave it out, or set '
      'strength.method = "GOST 21354-87"']),
    (_with(BASE, "strength.regime", "0"),
     ['strength.regime = "0": is the GOST 21354-87 typical load regime, not read by the ISO '
      '6336 rating (it rates the nominal torque over strength.life_hours): leave it out, or set '
      'strength.method = "GOST 21354-87"']),
    (_with(BASE, "strength.ring_form_factor", 2.1),
     ["strength.ring_form_factor = 2.1: is the GOST 21354-87 form factor Y_FS, not read by the ISO "
      "6336 rating: give iso_factors.<mesh>.Y_F2 and Y_S2 instead"]),
    (_with(BASE, "iso.ring.inner_diameter", 300.0),
     ["iso.ring.inner_diameter = 300.0: an internal gear has no bore: its body is the rim below the "
      "tooth roots (give iso.ring.rim_thickness, or leave the key out)"]),
    (_with(BASE, "iso.sun.inner_diameter", 60.0),
     ["iso.sun.inner_diameter = 60.0: must be smaller than the root diameter d_f = 46.500 mm"]),
    (_with(BASE, "iso.planet_ring.pinion_offset", 5.0),
     ["iso.planet_ring.pinion_offset = 5.0: given without iso.planet_ring.shaft_span and "
      "iso.planet_ring.shaft_diameter: the shaft deflection needs all three (or give "
      "iso.planet_ring.f_sh)"]),
    (_with(BASE, "iso.sun.quality", "XQ"),
     ['iso.sun.quality = "XQ": must be one of "ML", "MQ", "ME"']),
])
def test_iso_input_errors(data, lines):
    with pytest.raises(InputError) as exc:
        run_data({"kind": "planetary", **data})
    assert [p.line("") for p in exc.value.problems] == lines


def _bad_value(field):
    if field.type == "boolean":
        return "yes"
    if field.type == "string":
        return "nonsense"
    if field.type == "integer":
        return int(field.maximum) + 1
    if field.maximum is not None:
        return float(field.maximum) * 2 + 1
    return -1.0


def _planetary_fields():
    from geardesign.planetary.iso_inputs import ISO, ISO_FACTORS
    from geardesign.core.spec import Field

    for f in ISO.fields:
        if isinstance(f, Field):
            yield "iso", f
    for table in ("sun", "planet_ring"):
        for f in ISO.member(table).fields:
            yield f"iso.{table}", f
    for f in ISO_FACTORS.member("sun_planet").fields:
        yield "iso_factors.sun_planet", f


FIELDS = list(_planetary_fields())


@pytest.mark.parametrize("table, field", FIELDS, ids=[f"{t}.{f.key}" for t, f in FIELDS])
def test_every_iso_key_has_the_spur_domain(table, field):
    """Each planetary ISO key is the spur key: the same rule in the same words."""
    from geardesign.core.errors import format_value
    from geardesign.spur.strength.iso6336.spec import ISO as SPUR_ISO
    from geardesign.spur.strength.iso6336.spec import ISO_FACTORS as SPUR_FACTORS

    spur = {"iso": SPUR_ISO, "iso.sun": SPUR_ISO.member("pinion"), "iso.planet_ring": SPUR_ISO,
            "iso_factors.sun_planet": SPUR_FACTORS}[table].member(field.key)
    value = _bad_value(field)
    with pytest.raises(InputError) as exc:
        run_data({"kind": "planetary", **_with(BASE, f"{table}.{field.key}", value)})
    lines = [p.line("") for p in exc.value.problems]
    assert len(lines) == 1
    assert lines[0].startswith(f"{table}.{field.key} = {format_value(value)}: must be "
                               f"{spur.rule()}")
