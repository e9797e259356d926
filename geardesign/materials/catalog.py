"""The material library as rows for ``geardesign materials``: gear steels (one row per grade
and heat treatment, with the GOST 21354-87 allowables at the ends of the treatment's hardness
range), worm-wheel rim materials and lubricating oils.  Read on demand only."""

from __future__ import annotations

from functools import lru_cache

FAMILIES = ("gear_steel", "worm_wheel", "oil")


def families() -> tuple[str, ...]:
    return FAMILIES


def _gear_steel_rows() -> list[dict]:
    from geardesign.materials import gear_steel as G

    lib = G.library()
    out = []
    for grade, steel in lib["steel"].items():
        for t in steel["treatments"]:
            treat = lib["treatment"][t]
            lo, hi = treat["range"]
            unit = treat["hardness"]
            sigma_T = [v for _, tt, v in steel["sigma_T"] if tt == t]
            ends = {}
            for h in (lo, hi):
                HB = h if unit == "HB" else G.hb_from_hrc(h if unit == "HRC" else G.hrc_from_hv(h))
                values = {"HB": HB, unit: h, "HRC_core": None, "sigma_T": None}
                ends[h] = G.linear(treat["sigma_Hlim"], values)
            out.append({
                "name": grade, "family": "gear_steel", "standard": steel["standard"],
                "treatment": t, "hardness": f"{lo:g}…{hi:g} {unit}",
                "sigma_T": min(sigma_T) if sigma_T else None,
                "sigma_B": steel.get("sigma_B"),
                "sigma_Hlim": f"{treat['sigma_Hlim']} ({ends[lo]:.0f}…{ends[hi]:.0f} MPa)",
                "sigma_Flim": treat.get("sigma_Flim_Ni" if steel["Ni"] else "sigma_Flim",
                                        treat["sigma_Flim"]),
                "iso6336_5": steel.get("iso6336_5", {}).get(t),
                "equivalents": list(steel.get("equivalents", [])),
                "section": steel.get("section"),
                "source": G.source_of(grade),
            })
    return out


def _worm_wheel_rows() -> list[dict]:
    from geardesign.materials import worm_wheel as W

    out = []
    for m in (W.get(n) for n in W.names()):
        out.append({"name": m.name, "family": "worm_wheel", "standard": m.description,
                    "treatment": m.casting, "hardness": None, "sigma_T": m.sigma_T,
                    "sigma_B": m.sigma_B, "group": m.group, "v_s_max": m.v_s_max,
                    "equivalents": [], "source": m.source})
    return out


def _oil_rows() -> list[dict]:
    from geardesign.materials import lubricants as O

    return [{"name": o.grade, "family": "oil", "standard": "ISO 3448", "treatment": None,
             "hardness": None, "sigma_T": None, "sigma_B": None, "nu40": o.nu40,
             "nu40_range": [o.nu40_min, o.nu40_max], "VI": o.VI, "density_15": o.density_15,
             "fzg_stage": o.fzg_stage, "equivalents": [f"ISO VG {o.grade[3:]}"],
             "source": o.cite} for o in O.grades()]


@lru_cache(maxsize=1)
def rows() -> tuple[dict, ...]:
    return tuple(_gear_steel_rows() + _worm_wheel_rows() + _oil_rows())
