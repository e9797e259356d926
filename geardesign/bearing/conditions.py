"""The conditions of a bearing's life rating from its spec: the method's factors (a23 or
a_ISO), the lubricant's viscosity (given, an ISO VG grade, or ν40/ν100 at a temperature) and
contamination, the fatigue load limit C_u; a rule across keys raises a one-line
:class:`InputError`."""

from __future__ import annotations

from dataclasses import replace

from geardesign.bearing import a_iso as AI
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Bearing, Conditions
from geardesign.core.errors import InputError, Problem
from geardesign.core.spec import ValidatedSpec

GOST = "gost18855_94"


def fmt(x: float, digits: int = 4) -> str:
    """A number for a message: ``digits`` significant digits."""
    return f"{x:.{digits}g}"


def type_words(kind: str) -> str:
    """A bearing type as words (``deep groove ball``)."""
    return kind.replace("_", " ")


_type_words = type_words


def resolve_conditions(spec: ValidatedSpec, bearing: Bearing) -> tuple[Conditions, tuple]:
    """The method's conditions for ``bearing`` and the inputs the method does not use."""
    data = spec.data
    method = data["method"]
    fac, lub, req, ld = data["factors"], data["lubrication"], data["requirements"], data["load"]
    gost = method == GOST
    ignored = []
    a23 = None
    if gost:
        if fac["a23"] is not None:
            a23 = fac["a23"]
        else:
            if bearing.kind not in T.A23:
                raise InputError(Problem("factors.a23", f"missing; required for a "
                                         f"{_type_words(bearing.kind)} bearing (no textbook a23): "
                                         f"a number > 0"))
            if fac["conditions"] is None:
                fac["conditions"] = "usual"
                spec.assumed.append("factors.conditions")
            a23 = AI.a23_default(bearing.kind, fac["conditions"])
        if req["reliability"] > T.A1_GOST94[-1][0]:
            raise InputError.at("requirements.reliability", req["reliability"],
                                "GOST 18855-94 tabulates a1 only up to 99 %; use method = "
                                "\"iso281_2007\" for up to 99.95 %")
        if lub is not None:
            ignored.append("[lubrication] (a_ISO belongs to ISO 281:2007)")
    else:
        if fac["a23"] is not None or fac["conditions"] is not None:
            ignored.append("factors.a23/conditions (GOST 18855-94 only)")
        if ld["rotating_ring"] == "outer":
            ignored.append("load.rotating_ring (ISO 281 has no rotation factor V)")
    V = T.V_OUTER if (gost and ld["rotating_ring"] == "outer"
                      and bearing.kind != "self_aligning_ball") else 1.0
    K_t = AI.k_t(fac["temperature"])
    viscosity = e_C = None
    ep = False
    nu1 = kappa = None
    oil: dict = {}
    if not gost and lub is not None:
        viscosity, nu1, kappa, oil = resolve_viscosity(lub, spec)
        ep = lub["ep_additives"]
        if bearing.D_pw is None and nu1 is None and kappa is None:
            raise InputError(Problem("bearing.D_pw", "missing; required for ν1 of a_ISO: give "
                                                     "D_pw, or d and D (mm)"))
        if lub["e_C"] is not None:
            e_C = lub["e_C"]
        elif lub["contamination"] is not None:
            e_C = AI.e_c_guide(lub["contamination"], bearing.D_pw)
        else:
            raise InputError(Problem("lubrication.contamination", "missing; give contamination "
                                     "(one of " + ", ".join(f'"{k}"' for k in T.E_C_GUIDE) +
                                     ") or e_C"))
    K_E = T.K_E[ld["regime"]] if ld["regime"] is not None else None
    return Conditions(
        method=method, reliability=req["reliability"], V=V, K_b=fac["K_b"], K_t=K_t, a23=a23,
        viscosity=viscosity, nu1=nu1, kappa=kappa, oil=oil, e_C=e_C, ep_additives=ep, K_E=K_E,
        life_required=req["life"],
        s0_min=req["s0_min"], F_r0=ld["F_r0"], F_a0=ld["F_a0"],
        system_lives=tuple(req["system_lives"] or ()),
        weibull_slope=req["weibull_slope"]), tuple(ignored)


def resolve_viscosity(lub: dict, spec: ValidatedSpec) -> tuple:
    """(ν at the operating temperature or None, given ν1 or None, given κ or None, the oil's
    data for the report) of [lubrication]."""
    from geardesign.materials import lubricants as OIL

    routes = [k for k in ("viscosity", "oil", "nu40") if lub[k] is not None]
    if len(routes) > 1:
        raise InputError.at(f"lubrication.{routes[1]}", lub[routes[1]],
                            f"give one of lubrication.viscosity, oil or nu40, not "
                            f"{' and '.join(routes)}")
    if lub["kappa"] is not None and lub["nu1"] is not None:
        raise InputError.at("lubrication.nu1", lub["nu1"], "give kappa or nu1, not both")
    if not routes and lub["kappa"] is None:
        raise InputError(Problem("lubrication.viscosity", "missing; give the viscosity at the "
                                 "operating temperature (mm^2/s), or oil and temperature, or "
                                 "nu40 (and nu100) and temperature, or kappa"))
    oil_info: dict = {}
    viscosity = lub["viscosity"]
    if lub["oil"] is not None or lub["nu40"] is not None:
        if lub["temperature"] is None:
            key = "oil" if lub["oil"] is not None else "nu40"
            raise InputError(Problem("lubrication.temperature", f"missing; required with "
                                     f"lubrication.{key}: the operating temperature (°C)"))
        VI = lub["viscosity_index"]
        if lub["oil"] is not None:
            oil = OIL.find(lub["oil"])
            if oil is None:
                close = OIL.close_matches(lub["oil"])
                hint = (" (did you mean " + ", ".join(f'"{c}"' for c in close) + "?)"
                        if close else "")
                raise InputError.at("lubrication.oil", lub["oil"],
                                    f"not an ISO VG grade{hint}; grades: "
                                    + ", ".join(o.grade for o in OIL.grades()))
            nu40 = oil.nu40
            if VI is None and lub["nu100"] is None:
                VI = lub["viscosity_index"] = oil.VI
                spec.assumed.append("lubrication.viscosity_index")
            oil_info.update(oil=oil.grade, oil_source=oil.cite)
        else:
            nu40 = lub["nu40"]
        try:
            if lub["nu100"] is not None:
                if lub["viscosity_index"] is not None:
                    raise InputError.at("lubrication.viscosity_index", VI,
                                        "give nu100 or viscosity_index, not both")
                nu100 = lub["nu100"]
                if nu100 >= nu40:
                    raise InputError.at("lubrication.nu100", nu100,
                                        f"must be below nu40 = {nu40:g} mm^2/s")
                VI = OIL.viscosity_index(nu40, nu100)
            else:
                if VI is None:
                    raise InputError(Problem("lubrication.nu100", "missing; give nu100 or "
                                             "viscosity_index with nu40"))
                nu100 = OIL.nu100_from_vi(nu40, VI)
            viscosity = OIL.viscosity_at(lub["temperature"], nu40, nu100)
        except OIL.OilError as exc:
            raise InputError(Problem("lubrication", str(exc))) from None
        oil_info.update(nu40=nu40, nu100=nu100, VI=VI, t=lub["temperature"])
    return viscosity, lub["nu1"], lub["kappa"], oil_info


def with_c_u(bearing: Bearing, cond: Conditions) -> Bearing:
    """Fill in an estimated C_u when a_ISO needs it."""
    if not cond.lubricated or bearing.C_u is not None:
        return bearing
    if bearing.C_0r is None:
        raise InputError(Problem("bearing.C_u", "missing; required for a_ISO: give C_u (N), or "
                                                "C_0r from which it is estimated"))
    return replace(bearing, C_u=AI.c_u_estimate(bearing.kind, bearing.C_0r, bearing.D_pw),
                   C_u_estimated=True)
