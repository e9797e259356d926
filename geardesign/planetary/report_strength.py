"""The strength part of the planetary report: materials, the rating rows of every mesh and
its checks, built by the spur rating's check builders with the mesh's members and keys."""

from __future__ import annotations

from dataclasses import replace

from geardesign.core.result import Check, Result, check
from geardesign.planetary import checks as C
from geardesign.planetary import sources as S
from geardesign.planetary.inputs import Inputs
from geardesign.planetary.solve import Strength


def strength_report(res: Result, inp: Inputs, st: Strength) -> list:
    """Materials and the strength section of every mesh; the checks of each mesh by the
    spur rating's check builders, named by the mesh and its members."""
    from geardesign.materials.gear_steel import data_used
    from geardesign.spur.strength.checks import light_load_checks, rating_checks
    from geardesign.core.units_guard import given

    d, train = inp.data, inp.train
    sd, op = d["strength"], d["operation"]
    out = []
    if sd.get("scuffing") is not None and not st.iso:
        out.append(check("SCUFFING_NOT_RATED", False, "warning",
                         "[strength.scuffing] is not rated: scuffing is rated by ISO/TS 6336-21 "
                         "with the ISO 6336 rating; set strength.method = \"ISO 6336:2019\"",
                         "", None, None, "[ISO6336-21]"))
    res.methods.append(st.method)
    msec = res.section("materials", "Materials")
    for key, m in inp.mats.items():
        if key in ("planet2",) and train.planet2 is None or key == "ring2" and \
                train.scheme != "3K":
            continue
        msec.add(f"material_{key}", m.label, None, f"mat_{key}", key,
                 "library" if not m.given else "library + spec")
        msec.add(f"material_{key}_source", data_used(m), None, f"src_{key}",
                 f"data used, {key}", "library" if m.grade else "spec")
        msec.add(f"HB_{key}", m.HB, "HB", f"HB_{key}", "surface hardness in HB (converted)",
                 "GOST 21354-87 (ZPCIL fit)")
    for ms in st.meshes:
        mesh, md, rating = ms.mesh, ms.duty, ms.rating
        mn = C.MESH_NAMES.get(mesh.name)
        if rating is None:
            out.append(check(
                f"{mesh.name.upper()}_STRENGTH_NOT_RATED", False, "error",
                f"{mn}: the strength was not rated: this mesh "
                f"cannot run as computed (ε_α < 1, a tip beyond the mate's tangency point "
                f"or a pointed tooth; see the failed geometry checks); correct the "
                f"geometry first", "", None, None, "[ISO6336-2]"))
            continue
        sec = res.section(f"strength_{mesh.name}", f"Strength of the {mn} mesh "
                          f"({md.members[0]} = gear 1, {md.members[1]} = gear 2)")
        sec.add("gear1", md.members[0], None, "", "gear 1 of the rating", S.G21354)
        sec.add("gear2", md.members[1], None, "", "gear 2 of the rating", S.G21354)
        sec.add("F_t_planet", md.F_t, "N", "F_t", "tangential force on one planet at the "
                "reference circle" + (" (ISO 6336: nominal, K_γ a factor of its own)" if st.iso
                                      else ", with K_γ"), S.KUDRYAVTSEV)
        sec.add("n1_rel", md.n1, "min^-1", "n_1", "speed of gear 1 relative to the carrier",
                S.WILLIS)
        for row in rating.rows:
            sec.add(row.key, row.value, row.unit, row.symbol,
                    members_words(row.name, md.members), row.source)
        found = rating_checks(rating, md.members, internal=bool(mesh.spec.internal),
                              peak_key="strength.peak_torque")
        out.extend(mesh_check(c, mesh.name) for c in found)
    if st.lightest is not None:   # a load typed in a unit a thousand times too small
        out.extend(light_load_checks(st.lightest, given(op, {"torque": "N·m", "power": "kW"},
                                                        "operation")))
    return out


_WORDS = {"pinion": 0, "wheel": 1}


def members_words(text: str, members: tuple[str, str]) -> str:
    """A spur rating row's name for a planetary mesh: the words "pinion" and "wheel" name
    the members (gear 1 and gear 2 of the rating).  The rating's rows are those of the spur
    rating until it returns a record whose fields the report names itself."""
    out, word = [], ""
    for ch in text + " ":
        if ch.isalnum() or ch == "_":
            word += ch
            continue
        out.append(members[_WORDS[word]] if word in _WORDS else word)
        out.append(ch)
        word = ""
    return "".join(out)[:-1]


def mesh_check(c: Check, mesh: str) -> Check:
    """A check of one mesh's rating: its code carries the mesh, its message starts with
    the mesh's name (the builders already name the members and the keys)."""
    return replace(c, code=f"{mesh.upper()}_{c.code}",
                   message=f"{C.MESH_NAMES.get(mesh)}: {c.message}")
