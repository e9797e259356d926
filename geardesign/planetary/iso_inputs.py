"""ISO 6336 inputs of a planetary train: the ``[iso]`` and ``[iso_factors]`` tables and the
:class:`~geardesign.spur.strength.iso6336.rating.IsoSetting` of each mesh.

The keys are the spur calculator's (one definition, :mod:`geardesign.spur.strength.iso6336.spec`):

* ``[iso]`` holds the pair keys of the spur ``[iso]`` table (tolerance class, tip relief,
  helix modification, f_ma, f_sh and the gear-1 shaft, given deviations, S_Hmin, S_Fmin,
  limited pitting, optimum conditions, protuberance) for every mesh; the oil stays
  ``strength.lubricant_viscosity`` (one oil for the train, its scuffing and a drive);
* ``[iso.sun]``, ``[iso.planet]``, ``[iso.ring]``, ``[iso.planet2]``, ``[iso.ring2]`` hold
  the gear keys of the spur ``[iso.pinion]`` per member (planet2 and ring2 default to the
  planet's and the ring's table, as their materials do);
* ``[iso.<mesh>]`` (``sun_planet``, ``planet_ring``, …) the pair keys of one mesh, each
  replacing the ``[iso]`` value for that mesh;
* ``[iso_factors.<mesh>]`` the spur ``[iso_factors]`` of one mesh, gear 1 and gear 2 in the
  mesh's rating order (the report's ``gear1``/``gear2``).

Each mesh is rated by :func:`geardesign.spur.strength.iso6336.rating.rate` with these inputs
and the load-sharing factor K_γ = ``strength.load_sharing`` as its own factor: F_t, σ_H0 and
σ_F0 are those of ISO 6336 (the nominal force of one planet, without K_γ).
"""

from __future__ import annotations

from dataclasses import replace

from geardesign.core.errors import InputError, Problem
from geardesign.core.spec import Field, Table
from geardesign.spur.strength.iso6336 import spec as ISPEC
from geardesign.planetary.strength import shared_meshes

MEMBERS = ("sun", "planet", "ring", "planet2", "ring2")
MESHES = ("sun_planet", "planet_ring", "planet2_ring", "planet_ring2", "planet2_ring2")
_FALLBACK = {"planet2": "planet", "ring2": "ring"}

#: the pair keys of the spur ``[iso]`` table, without the oil (``strength.lubricant_viscosity``)
PAIR_FIELDS = tuple(replace(f, hint="strength.accuracy_grade when not given")
                    if f.key == "accuracy_grade" else f for f in ISPEC.ISO.fields
                    if isinstance(f, Field) and f.key != "lubricant_viscosity")


def _mesh_table(mesh: str) -> Table:
    return Table(mesh, f"ISO 6336 pair data of the {mesh.replace('_', '–')} mesh, replacing "
                 "the [iso] value for this mesh", tuple(
                     replace(f, default=None, example=None,
                             hint=f"default: iso.{f.key}" + (f" ({f.hint})" if f.hint else ""))
                     for f in PAIR_FIELDS), required=False)


ISO = Table("iso", "ISO 6336:2019 rating data (with strength.method = \"ISO 6336:2019\"): "
            "the pair keys of the spur calculator's [iso] for every mesh, a table per member "
            "and per mesh", PAIR_FIELDS
            + tuple(replace(ISPEC._gear(m), description=f"ISO 6336 data of the {m}"
                            + (f" (default: [iso.{_FALLBACK[m]}])" if m in _FALLBACK else ""))
                    for m in MEMBERS)
            + tuple(_mesh_table(m) for m in MESHES), required=False, in_template=False,
            hint="gear 1 of a mesh (its shaft: shaft_span, pinion_offset, shaft_diameter) is the "
                 "report's gear1 of the mesh")

ISO_FACTORS = Table("iso_factors", "ISO 6336 factors given instead of computed, per mesh "
                    "(1 = the mesh's gear 1, 2 = its gear 2, as the report names them)", tuple(
                        replace(ISPEC.ISO_FACTORS, key=m, description=f"factors of the "
                                f"{m.replace('_', '–')} mesh") for m in MESHES),
                    required=False, in_template=False, hint=ISPEC.ISO_FACTORS.hint)

#: ``[strength]`` keys that only the GOST 21354-87 rating reads, and what ISO takes instead
GOST_ONLY_STRENGTH = {
    "tip_relief": "is the GOST 21354-87 switch, not read by the ISO 6336 rating: give "
                  "iso.tip_relief (the amount C_a in µm) instead",
    "bearing_scheme": "is the GOST 21354-87 chart of K_Hβ, not read by the ISO 6336 rating "
                      "(K_Hβ by method C from f_sh and f_ma): give iso.f_sh or the shaft "
                      "(iso.shaft_span, iso.shaft_diameter, iso.pinion_offset, "
                      "iso.shaft_K_prime) instead",
    "ring_form_factor": "is the GOST 21354-87 form factor Y_FS, not read by the ISO 6336 "
                        "rating: give iso_factors.<mesh>.Y_F2 and Y_S2 instead",
    "regime": "is the GOST 21354-87 typical load regime, not read by the ISO 6336 rating "
              "(it rates the nominal torque over strength.life_hours): leave it out, or set "
              "strength.method = \"GOST 21354-87\"",
}


def prepare(spec, train, meshes: list) -> None:
    """Check the ISO inputs of a planetary spec against its method and its train and fill
    the defaults of ``[iso]`` (echoed as assumed) when it rates by ISO 6336.  An ISO key
    with the GOST method, a GOST-only key with the ISO method, a member or mesh the train
    lacks, or a pair rule broken is an input error.  Raises :class:`InputError`."""
    from geardesign.core.spec import _validate_table

    d = spec.data
    st = d["strength"]
    names = {mesh.name for mesh in meshes}
    members = {mesh.spec.pinion for mesh in meshes} | {mesh.spec.wheel for mesh in meshes}
    problems: list = []
    if st is None or st["method"] != ISPEC.ISO_NAME:
        for key in ("iso", "iso_factors"):
            if d.get(key) is not None:
                problems.append(Problem(key, f"[{key}] is read only by the ISO 6336 rating: "
                                        f"set strength.method = \"{ISPEC.ISO_NAME}\" or leave "
                                        f"the table out", Problem.NO_VALUE))
        if problems:
            raise InputError(problems)
        return
    for key, message in GOST_ONLY_STRENGTH.items():
        # st.get: a spec read before (the advice re-rates a copy of it) lacks the default
        if f"strength.{key}" not in spec.assumed and st.get(key) not in (None, False):
            problems.append(Problem(f"strength.{key}", message, st[key]))
        elif f"strength.{key}" in spec.assumed:     # a GOST default: not echoed as used
            spec.assumed.remove(f"strength.{key}")
            st.pop(key, None)
    if d.get("iso") is None:
        d["iso"] = _validate_table(ISO, {}, "iso", problems, spec.assumed)
    iso = d["iso"]
    for who in MEMBERS:
        if iso.get(who) is not None and who not in members:
            problems.append(Problem(f"iso.{who}", f"this train has no {who}: leave "
                                    f"[iso.{who}] out", Problem.NO_VALUE))
        elif iso.get(who) is None and who in members and who not in _FALLBACK:
            iso[who] = _validate_table(ISO.member(who), {}, f"iso.{who}", problems,
                                       spec.assumed)
    factors = d.get("iso_factors") or {}
    for where, tables in (("iso", iso), ("iso_factors", factors)):
        for mesh in MESHES:
            if tables.get(mesh) is not None and mesh not in names:
                problems.append(Problem(f"{where}.{mesh}", f"this train has no "
                                        f"{mesh.replace('_', '–')} mesh: leave "
                                        f"[{where}.{mesh}] out", Problem.NO_VALUE))
    for mesh in meshes:
        path = f"iso.{mesh.name}" if iso.get(mesh.name) is not None else "iso"
        problems += ISPEC.pair_problems(pair_values(iso, mesh.name), path)
    for who in sorted(members):
        t = d["material"].get(who)
        if t is not None:
            problems += ISPEC.gost_material_problems(t, f"material.{who}", f"iso.{who}", "iso")
    if problems:
        raise InputError(problems)


def pair_values(iso: dict, mesh: str) -> dict:
    """The pair keys of one mesh: ``[iso.<mesh>]`` where given, else ``[iso]``."""
    own = iso.get(mesh) or {}
    return {f.key: own[f.key] if own.get(f.key) is not None else iso[f.key]
            for f in PAIR_FIELDS}


def member_table(iso: dict, member: str) -> dict:
    """The ``[iso.<member>]`` table (planet2 and ring2 fall back to the planet's and the
    ring's)."""
    while iso.get(member) is None and member in _FALLBACK:
        member = _FALLBACK[member]
    return iso[member]


def member_path(iso: dict, member: str) -> str:
    """The key of the table :func:`member_table` returns, for messages."""
    while iso.get(member) is None and member in _FALLBACK:
        member = _FALLBACK[member]
    return f"iso.{member}"


def mesh_setting(d: dict, train, mesh, members: tuple[str, str], geom, scuffing):
    """The ISO inputs of one mesh rated with ``members`` as gear 1 and gear 2 on the
    geometry ``geom`` (the gears in that order): the pair keys, the members' tables, the
    mesh's given factors, the train's oil, K_γ, ``scuffing`` and the meshes that share
    each member for the reduced mass of K_v (:func:`.strength.shared_meshes`: the sun is
    shared by the planets, the ring is rigid).  The members' bores and
    rims are checked against ``geom``."""
    iso = d["iso"]
    gears = tuple(member_table(iso, m) for m in members)
    ISPEC.gear_checks(iso, geom, tuple(member_path(iso, m) for m in members), gears)
    factors = (d.get("iso_factors") or {}).get(mesh.name) or {}
    overrides = {k: v for k, v in factors.items() if v is not None}
    st = d["strength"]
    oil = {} if st["lubricant_viscosity"] is None else {"nu40": st["lubricant_viscosity"]}
    return ISPEC.setting_from(pair_values(iso, mesh.name), gears, overrides, scuffing,
                              K_gamma=st["load_sharing"], meshes=shared_meshes(train, members),
                              **oil)


def mesh_rate_function(rate, d: dict, train, meshes: list, mesh, md):
    """The spur ISO 6336 ``rate`` bound to the inputs of one mesh (:func:`mesh_setting`),
    with ``[strength.scuffing]`` for the scuffing rating: the multiple mesh factor X_mp
    counts the meshes of the mesh's gear 1, a central gear meshing every planet, a planet
    crown each central gear it engages ([ISO6336-21], X_mp)."""
    pinion = md.members[0]
    n_p = train.planets if pinion in ("sun", "ring", "ring2") else sum(
        1 for m in meshes if pinion in (m.spec.pinion, m.spec.wheel))
    scuffing = ISPEC.scuffing_setting(d["strength"].get("scuffing"), meshes=n_p,
                                      nu40=d["strength"]["lubricant_viscosity"],
                                      where="strength.scuffing")
    iso = mesh_setting(d, train, mesh, md.members, md.geom, scuffing)

    def iso_rate(g, mats, duty, setting):
        return rate(g, mats, duty, setting, iso)

    return iso_rate
