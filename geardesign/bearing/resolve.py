"""The bearing of a spec: a catalogue row (read as a written designation is read, with the
maker's prefix and seal or shield suffixes) and/or given ratings, geometry or angles, and
the facts the report says of where its data come from; bearing B of a pair likewise."""

from __future__ import annotations

from dataclasses import replace

from geardesign.bearing import catalogue as CAT
from geardesign.bearing import life as L
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Bearing
from geardesign.bearing.conditions import _type_words
from geardesign.bearing.conditions import fmt as _f
from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec


@dataclass(frozen=True)
class Facts:
    """What the report says of where a bearing's data come from."""

    source: str = "given"
    note: str = ""
    geometry: L.RatingFromGeometry | None = None
    catalogue: CAT.CatalogueBearing | None = None
    rating: str = "given"
    d: float | None = None
    D: float | None = None
    B: float | None = None
    lubricant: str | None = "oil"
    reading: str = ""


def _catalogue_row(b: dict, info: dict | None = None):
    """The catalogue row of ``bearing.designation`` (with ``bearing.maker``), read as
    :func:`.catalogue.read` reads a written designation (maker's prefix, seal and shield
    suffixes; ``info["reading"]`` says which variant was read as which row); an input
    error naming the designation when the catalogue has none or several."""
    try:
        reading = CAT.read(b["designation"], b["maker"])
    except ValueError as exc:    # an ambiguous designation, or two makers named
        raise InputError.at("bearing.designation", b["designation"], str(exc)) from None
    row = reading.row
    if info is not None:
        info["reading"] = reading.note
    if row is None:
        other = CAT.read(b["designation"]).row if b["maker"] is not None else None
        if other is not None:
            raise InputError.at("bearing.designation", b["designation"],
                                f"not in the {b['maker']} tables of the built-in catalogue; "
                                f"{other.maker} lists it: remove bearing.maker or set it to "
                                f"\"{other.maker}\"")
        close = CAT.close_matches(b["designation"])
        hint = (" (did you mean " + ", ".join(f'"{c}"' for c in close) + "?)") if close else ""
        raise InputError.at(
            "bearing.designation", b["designation"],
            f"not in the built-in catalogue{hint}; it holds deep groove 60/62/63/64, angular "
            f"contact 72 B/73 B, cylindrical roller NU/NJ/NUP 2/3/22/23, tapered roller "
            f"302/303/313/322/323, spherical roller 222/223/230/231 and thrust ball 511/512 "
            f"(`geardesign bearings` lists them); or give bearing.type, C_r and C_0r instead")
    return row


def resolve_bearing(spec: ValidatedSpec) -> tuple[Bearing, Facts]:
    """The bearing of a spec: catalogue row and/or given values (given values override);
    returns the :class:`Bearing` and facts for the report (source, d, D, geometry, ...)."""
    b = spec.data["bearing"]
    info: dict = {"source": "given", "note": "", "geometry": None, "catalogue": None}
    row = None
    if b["maker"] is not None and b["maker"].upper() not in {m.upper() for m in CAT.makers()}:
        raise InputError.at("bearing.maker", b["maker"], "not in the built-in catalogue; known: "
                            + ", ".join(f'"{m}"' for m in CAT.makers()))
    if b["designation"] is not None:
        row = _catalogue_row(b, info)
        if b["type"] is not None and b["type"] != row.type:
            raise InputError.at("bearing.type", b["type"],
                                f"contradicts the catalogue: {row.designation} is a "
                                f"{_type_words(row.type)} bearing; remove bearing.type")
        info.update(source=row.cite, note=row.note, catalogue=row)
    kind = b["type"] if b["type"] is not None else (row.type if row else None)
    if kind is None:
        raise InputError(Problem("bearing.type", "missing; required without bearing.designation: "
                                 "one of " + ", ".join(f'"{t}"' for t in T.TYPES)))

    def pick(key: str, cat_value):
        return b[key] if b[key] is not None else cat_value

    d = pick("d", row.d if row else None)
    D = pick("D", row.D if row else None)
    D_pw = b["D_pw"] if b["D_pw"] is not None else (0.5 * (d + D) if d and D else None)
    if d is not None and D is not None and D <= d:
        raise InputError.at("bearing.D", D, f"must be larger than the bore d = {_f(d)} mm")
    alpha = b["contact_angle"]
    if alpha is None and row is not None and row.alpha is not None:
        alpha = row.alpha
    if alpha is not None and kind in ("deep_groove_ball", "cylindrical_roller") and alpha != 0:
        raise InputError.at("bearing.contact_angle", alpha,
                            f"does not apply to a {_type_words(kind)} bearing (α = 0); remove it "
                            f"or choose type \"angular_contact_ball\"")
    if kind in T.THRUST_TYPES and alpha is None:
        alpha = 90.0
    if kind in ("deep_groove_ball", "cylindrical_roller"):
        alpha = 0.0 if kind == "cylindrical_roller" else None
    e = pick("e", row.e if row else None)
    if alpha is not None and b["e"] is not None and kind in (
            "tapered_roller", "spherical_roller", "self_aligning_ball"):
        raise InputError.at("bearing.e", b["e"], "give either contact_angle or e, not both")
    if b["contact_angle"] is not None and b["e"] is None:
        e = None          # a given angle overrides the catalogue e
    C_r = b["C_r"] if b["C_r"] is not None else (row.C_r if row else None)
    if C_r is not None:
        info["rating"] = "given" if b["C_r"] is not None else "catalogue"
    else:
        geo = [b[k] for k in ("Z", "D_w")]
        if None in geo or D_pw is None or kind in T.THRUST_TYPES:
            raise InputError(Problem(
                "bearing.C_r", "missing; give C_r (N), a catalogue designation, or the geometry "
                "Z, D_w and D_pw (or d and D) of a radial bearing"))
        try:
            g = L.dynamic_rating(kind, b["Z"], b["D_w"], D_pw, alpha or 0.0, b["rows"], b["L_we"])
        except L.BearingError as exc:
            raise InputError.at(exc.key, b.get(exc.key.split(".")[1]), str(exc)) from None
        C_r = g.C_r
        info.update(rating="geometry (ISO 281)", geometry=g)
    C_0r = pick("C_0r", row.C_0r if row else None)
    C_u = pick("C_u", row.C_u if row else None)
    rows = b["rows"]
    if row is not None and row.type == "spherical_roller" and "bearing.rows" in spec.assumed:
        rows = 2                        # a spherical roller bearing has two rows
    own_angle = b["contact_angle"] is not None or b["e"] is not None
    Y1 = row.Y1 if row is not None and not own_angle else None
    Y0 = row.Y0 if row is not None and not own_angle else None
    f0 = b["f0"] if b["f0"] is not None else (row.f0 if row else None)
    bearing = Bearing(kind, rows, alpha, e, pick("Y", row.Y if row else None), C_r, C_0r,
                      C_u, False, f0, D_pw, row.designation if row else "", Y1, Y0)
    info.update(d=d, D=D, B=row.B if row else None, lubricant=b["lubricant"])
    return bearing, Facts(**info)


def catalogue_bearing(row, template: Bearing | None = None) -> Bearing:
    kind = row.type
    alpha = 90.0 if kind in T.THRUST_TYPES else row.alpha
    f0 = row.f0
    if f0 is None and template is not None and template.designation == "":
        f0 = template.f0
    return Bearing(kind, 2 if kind == "spherical_roller" else 1, alpha, row.e, row.Y, row.C_r,
                   row.C_0r, row.C_u, False, f0, 0.5 * (row.d + row.D), row.designation, row.Y1,
                   row.Y0)


_PAIR_RATING_KEYS = ("C_r", "C_0r", "C_u", "e", "Y", "contact_angle", "d", "D")


def _bearing_b(spec: ValidatedSpec, kind: str) -> tuple[Bearing, Facts]:
    """Bearing B of a pair from [pair] (its designation, or its ratings, or bearing A's
    designation), resolved like [bearing]."""
    p = spec.data["pair"]
    a = spec.data["bearing"]
    b = {k: None for k in a}
    b.update(rows=1, series=None)
    given = {k: p[k] for k in _PAIR_RATING_KEYS if p[k] is not None}
    b.update(given)
    if p["designation"] is not None:
        b.update(designation=p["designation"], maker=p["maker"])
    elif not given and a["designation"] is not None:
        b.update(designation=a["designation"], maker=a["maker"])
    else:
        b["type"] = kind
    if b["designation"] is None:
        b["type"] = kind
    sub = ValidatedSpec(dict(spec.data, bearing=b), list(spec.assumed), spec.source,
                        spec.base_dir)
    try:
        bearing, info = resolve_bearing(sub)
    except InputError as exc:
        raise InputError([replace(pr, key=pr.key.replace("bearing.", "pair.", 1))
                          for pr in exc.problems]) from None
    if bearing.kind != kind:
        raise InputError.at("pair.designation", p["designation"],
                            f"bearing B must be a {_type_words(kind)} bearing like bearing A")
    return bearing, info
