"""A drive with ``[lubrication]`` (and ``[thermal]``): its stages' efficiencies from their
losses, the oil sump temperature from the heat balance, and the report of both.

The passes: the chain of stages is computed with the efficiencies of the pass before
(first: the calculators' or 0.98), the losses are put together from its results
(:mod:`.heat`), the sump temperature solves the heat balance, and the efficiencies follow
from the losses at that temperature; until they change by less than 1e-6 (at most
``MAX_PASSES`` passes).  A pass needs of each stage its ratio, efficiency and mesh forces
only: a spur stage gives them from its geometry, unrated (``LIGHT`` adapters of
:mod:`.calculator`); the stages are rated once, at the efficiencies of the last pass and
with the scuffing oil at the last sump temperature.  The bearings then get the drive's oil
at the sump temperature.
The report of the balance is :mod:`.heat_report`.
"""

from __future__ import annotations

import copy

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.drive import heat as HEAT
from geardesign.drive import losses as L
from geardesign.drive import thermal as TH

from geardesign.materials import lubricants as OIL
from geardesign.gears.losses import EPS_ALPHA_RANGE, loss_factor_applies

MAX_PASSES = 5
EFFICIENCY_TOL = 1e-6
SRC_MESH = "[ISOTR14179-2] (μ_mz Schlenk, H_V Ohlendorf)"
SRC_CHURN = "[Changenet2007]"
SRC_BEARING = "[Palmgren1959] M0 + M1"
SRC_SEAL = "[ISOTR14179-2] P_VD"
SRC_HEAT = "[Incropera2007] eqs. (9.26), (7.30), (1.9)"
ETA_SOURCE = "losses ([ISOTR14179-2], [Changenet2007], [Palmgren1959])"


@dataclass
class Thermal:
    T_in: float
    runs: list
    model: HEAT.Model
    housing: TH.Housing
    box: dict                 # L, W, H [mm], a (wall gap), estimated: bool
    balance: HEAT.Balance
    losses: list              # HEAT.StageLoss per stage
    passes: int
    t_air: float
    t_max: float
    oil_info: dict
    seal_source: str
    bearings_counted: bool
    bearing_oil: object = None


def _oil(spec: ValidatedSpec) -> tuple[HEAT.Oil, dict]:
    lub = spec.data["lubrication"]
    oil = OIL.find(lub["oil"])
    if oil is None:
        close = OIL.close_matches(lub["oil"])
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
        raise InputError.at("lubrication.oil", lub["oil"], "not an ISO VG grade of the "
                            "library (`geardesign materials oil`)" + hint)
    VI = lub["viscosity_index"]
    try:
        nu100 = OIL.nu100_from_vi(oil.nu40, VI)
    except OIL.OilError as exc:
        raise InputError.at("lubrication.viscosity_index", VI, str(exc)) from None
    o = HEAT.Oil(oil.grade, oil.nu40, nu100, VI, lub["density"],
                 L.lubricant_factor(lub["base_oil"]), lub["roughness_Ra"])
    return o, dict(grade=oil.grade, source=oil.cite, nu100=nu100)


def _mesh(run, stage: int) -> tuple[HEAT.Mesh | None, list[HEAT.DipGear], tuple | None]:
    """Mesh data of a cylindrical involute stage (spur calculator), its two gears for the
    churning and (a_w, d_a1, d_a2, b) for the housing; (None, [], None) for others
    (worm, planetary, Novikov, an internal pair)."""
    g = run.geometry
    if run.kind != "spur" or g is None:
        return None, [], None
    data = run.inputs
    gear = data.get("gear") or {}
    pair = g.inp
    g1, g2 = g.g1, g.g2
    b = gear.get("face_width") or pair.b_w
    z1, z2 = pair.z1, pair.z2
    if b is None or z2 < 0 or g2.d_w <= 0 or getattr(g, "internal", False):
        return None, [], None
    # the loss model takes the angles in degrees
    v = dict(p_bt=g.p_bt, d_a1=g1.d_a, d_a2=g2.d_a, d_b1=g1.d_b, d_b2=g2.d_b,
             alpha_tw=math.degrees(g.alpha_tw), u=g.u, beta_b=math.degrees(g.beta_b),
             eps_alpha=g.eps_alpha, d_w1=g1.d_w, d_w2=g2.d_w, a_w=g.a_w)
    pbt = v["p_bt"]
    e1, _ = L.partial_contact_ratios(v["d_a1"], v["d_a2"], v["d_b1"], v["d_b2"],
                                     v["alpha_tw"], pbt)
    P_in = run.T_in * run.n_in * math.pi / 30.0
    F_bt = 2000.0 * run.T_in / v["d_b1"]
    mat = data.get("material") or {}
    ras = [m.get("roughness_Ra") for m in (mat.get("pinion") or {}, mat.get("wheel") or {})
           if isinstance(m, dict) and m.get("roughness_Ra") is not None]
    Ra = sum(ras) / len(ras) if ras else None
    mesh = HEAT.Mesh(P_in, run.n_in, v["u"], z1, v["beta_b"], v["alpha_tw"], v["eps_alpha"],
                     e1, v["d_w1"], v["d_w2"], b, F_bt, Ra)
    m_n, a_n = pair.m_n, gear.get("pressure_angle", 20.0)
    dip = [HEAT.DipGear(stage, "pinion", v["d_w1"] / 2, v["d_a1"] / 2, b, z1, m_n, a_n,
                        run.n_in),
           HEAT.DipGear(stage, "wheel", v["d_w2"] / 2, v["d_a2"] / 2, b, z2, m_n, a_n,
                        run.n_out)]
    return mesh, dip, (v["a_w"], v["d_a1"], v["d_a2"], b)


def _build(spec, stages, runs, oil: HEAT.Oil) -> tuple:
    """The loss model without bearings and seals, the housing and its dimensions."""
    d = spec.data
    lub, th = d["lubrication"], d["thermal"] or {}
    n = len(runs)
    P_in = [r.T_in * r.n_in * math.pi / 30.0 for r in runs]
    m = HEAT.Model(oil, n, P_in)
    geo = []
    for i, ((key, _, _, eta), r) in enumerate(zip(stages, runs)):
        mesh, dip, g = (None, [], None) if eta is not None else _mesh(r, i)
        if mesh is not None and not loss_factor_applies(mesh.eps_alpha):
            lo, hi = EPS_ALPHA_RANGE
            raise InputError(Problem(
                f"{key}.efficiency", f"missing; [lubrication] computes the mesh loss of "
                f"stage {i + 1} with Ohlendorf's H_V (ISO/TR 14179-2), which holds for "
                f"{lo:g} <= ε_α <= {hi:g}, and the stage has ε_α = {mesh.eps_alpha:.4g}: give "
                f"the stage's efficiency, or change its geometry"))
        if mesh is not None:
            m.meshes[i] = mesh
            m.dip += dip
            geo.append(g)
        else:
            m.fixed[i] = r.efficiency
            geo.append(None)
    # housing: the dimensions given, the missing ones estimated around the gears
    dims = [th.get("length"), th.get("width"), th.get("height")]
    box = dict(a=None, estimated=False)
    if None in dims:
        if any(g is None for g in geo):
            if th.get("area") is None or th.get("height") is None:
                missing = "area" if th.get("area") is None else "height"
                raise InputError(Problem(f"thermal.{missing}", "missing; the housing is "
                                         "estimated only around cylindrical stages in line: "
                                         "give thermal.area and thermal.height (and length "
                                         "for a fan)"))
            dims = [dims[0] or dims[2], dims[1], dims[2]]
        else:
            est = HEAT.housing_box([(g[0], g[1], g[2]) for g in geo], [g[3] for g in geo])
            box.update(a=est[3], estimated=True)
            dims = [x if x is not None else e for x, e in zip(dims, est[:3])]
    box.update(L=dims[0], W=dims[1], H=dims[2])
    area = th.get("area")
    if area is None:
        area = TH.box_area(box["L"], box["W"], box["H"], th.get("base_cooled", False))
    box["area_given"] = th.get("area") is not None
    hs = TH.Housing(area, box["H"], box["L"], th.get("emissivity", 0.9),
                    th.get("fan_velocity", 0.0), th.get("fan_share", 0.5)
                    if th.get("fan_velocity", 0.0) > 0 else 0.0,
                    1000.0 * th.get("cooler", 0.0))
    # dip lubrication: the oil level by the largest wheel
    if m.dip:
        big = max(m.dip, key=lambda x: x.R_a)
        h = lub["immersion"]
        if h is None:
            h = 2.25 * big.m_n
        if h > big.R_p:
            raise InputError.at("lubrication.immersion", lub["immersion"],
                                f"deeper than the largest wheel's pitch radius "
                                f"{big.R_p:.1f} mm (the churning model holds up to h = R_p)")
        level = big.R_a - h
        m.immersion = {(x.stage, x.member): min(max(x.R_a - level, 0.0), x.R_p)
                       for x in m.dip}
        box["immersion"] = h
    V0 = lub["oil_volume"]
    if V0 is None and m.dip and box["W"] is None:
        raise InputError(Problem("lubrication.oil_volume", "missing; give the oil volume "
                                 "(l) or the housing's length, width and height"))
    if V0 is None and not m.dip:
        V0 = 0.0
    elif V0 is None:
        depth = 4 * (box.get("a") or 10.0) + box.get("immersion", 0.0)
        V0 = box["L"] * box["W"] * depth * 1e-6
    m.V0 = V0
    box["V0"] = V0
    return m, hs, box


def bore(rated) -> float | None:
    """The bore d [mm] of a rated bearing (:class:`geardesign.bearing.solve.Rated`) as its
    report gives it: from a catalogue row with its dimensions, else none."""
    f = rated.facts
    return f.d if f.catalogue is not None and f.B is not None else None


def _bearings(cases, records, n_stages: int) -> list[HEAT.BearingLoad]:
    """The bearings' data of the loss model from their records
    (:class:`geardesign.bearing.solve.Rated`): type, mean diameter, loads, static load and
    rating, axial factor Y."""
    out = []
    for c, r in zip(cases, records):
        a, d = r.a, bore(r)
        kind = a.bearing.kind
        if kind not in L.bearing_types() or d is None or r.facts.D is None:
            continue
        stage = min(c["shaft"], n_stages) - 1
        P0 = a.static.P0 if a.static is not None else c["F_r"]
        Y = a.blocks[0].factors.Y if len(a.blocks) == 1 else None
        out.append(HEAT.BearingLoad(stage, f"{c['name']} {c['side'].upper()}", kind,
                                    0.5 * (d + r.facts.D), c["n"], c["F_r"], c["F_a"],
                                    P0, a.bearing.C_0r or 0.0, Y))
    return out


def prepare(spec: ValidatedSpec) -> None:
    """Defaults that depend on other inputs, filled in before the inputs are echoed: the
    viscosity index of the grade, and the [thermal] table's defaults when it is left out."""
    from geardesign.drive.spec import THERMAL

    d = spec.data
    lub = d["lubrication"]
    oil = OIL.find(lub["oil"])
    if oil is not None and lub["viscosity_index"] is None:
        lub["viscosity_index"] = oil.VI
        spec.assumed.append("lubrication.viscosity_index")
    if d["thermal"] is None:
        d["thermal"] = {f.key: f.default for f in THERMAL.fields}
        spec.assumed += [f"thermal.{f.key}" for f in THERMAL.fields if f.default is not None]


SCUFFING_T_MAX = 150.0     # °C, the largest iso.scuffing.oil_temperature of a stage spec


# the drive's base oil names ([lubrication] base_oil) as the scuffing table's lubricant names
SCUFFING_LUBRICANT = {"mineral": "mineral", "pao": "polyalphaolefin",
                      "pag_insoluble": "polyglycol", "pag_soluble": "polyglycol_water_soluble",
                      "traction": "traction_fluid", "phosphate_ester": "phosphate_ester"}


def _scuffing_tables(data: dict) -> tuple[dict, dict] | None:
    """(the table that holds ``lubricant_viscosity``, the scuffing table) of a stage spec
    rated for scuffing: ``[iso]``/``[iso.scuffing]`` of a cylindrical stage,
    ``[strength]``/``[strength.scuffing]`` of a planetary stage; None for the others."""
    holder = {"spur": "iso", "planetary": "strength"}.get(data.get("kind"))
    t = data.get(holder) if holder else None
    sc = t.get("scuffing") if isinstance(t, dict) else None
    return (t, sc) if isinstance(sc, dict) else None


def scuffing_oil(spec: ValidatedSpec, stages: list) -> dict:
    """The stages rated for scuffing (ISO/TS 6336-21: ``[iso.scuffing]`` of a cylindrical
    stage, ``[strength.scuffing]`` of a planetary one): ``{stage index: "balance" |
    "given"}``.  Their spec data is copied in ``stages`` and takes the drive's oil where it
    names none: ``lubricant_viscosity`` = ν40 of ``[lubrication] oil``, and in the scuffing
    table ``oil_viscosity_100``, ``oil_density`` and ``lubricant`` (the base oil).  A stage
    that gives no ``oil_temperature`` takes the sump temperature of the heat balance (the
    oil before the mesh of a dip-lubricated gear, [ISO6336-21] Θ_oil); until the balance is
    known it starts at the permissible sump temperature."""
    d = spec.data
    lub = d["lubrication"]
    oil, _ = _oil(spec)
    t0 = min(d["thermal"]["max_oil_temperature"], SCUFFING_T_MAX)
    out = {}
    for i, (where, name, data, eta) in enumerate(stages):
        if _scuffing_tables(data) is None:
            continue
        data = copy.deepcopy(data)
        holder, sc = _scuffing_tables(data)
        if holder.get("lubricant_viscosity") is None:
            holder["lubricant_viscosity"] = oil.nu40
        sc.setdefault("oil_viscosity_100", oil.nu100)
        sc.setdefault("oil_density", lub["density"])
        sc.setdefault("lubricant", SCUFFING_LUBRICANT[lub["base_oil"]])
        if sc.get("oil_temperature") is None:
            sc["oil_temperature"] = t0
            out[i] = "balance"
        else:
            out[i] = "given"
        stages[i] = (where, name, data, eta)
    return out


def _set_scuffing_oil(stages: list, scuff: dict, t_oil: float) -> bool:
    """Put the sump temperature into the stages whose scuffing takes it; True if one
    changed."""
    t = min(t_oil, SCUFFING_T_MAX)
    changed = False
    for i, how in scuff.items():
        if how == "balance":
            sc = _scuffing_tables(stages[i][2])[1]
            changed |= sc["oil_temperature"] != t
            sc["oil_temperature"] = t
    return changed


def solve(spec: ValidatedSpec, stages, chain, T_in, runs, n_m, scuff: dict | None = None,
          memo: dict | None = None) -> Thermal:
    """The passes of efficiencies and stages until the efficiencies settle (module
    docstring); ``memo``: the run's store of validated specs (:mod:`.reuse`)."""
    from geardesign.drive.shaft_loads import rate_bearing, shaft_cases

    memo = {} if memo is None else memo

    d = spec.data
    lub, th = d["lubrication"], d["thermal"]
    t_air, t_max = th["ambient"], th["max_oil_temperature"]
    if t_max <= t_air:
        raise InputError.at("thermal.max_oil_temperature", t_max, f"must be above the "
                            f"ambient temperature {t_air:g} °C")
    oil, info = _oil(spec)
    L_h = d["load"]["life_hours"]
    etas_before = None
    rate_as: tuple = (None, None)    # the arguments of the chain that gave ``runs``
    bal = m = hs = box = None
    seal_source = ""
    passes = 0
    for passes in range(1, MAX_PASSES + 1):
        m, hs, box = _build(spec, stages, runs, oil)
        cases, brs = [], []
        if d["shaft"]:
            cases = shaft_cases(d["shaft"], runs, n_m, L_h)
            for c in cases:        # geometry and static load: without the oil temperature
                c = dict(c, data={k: v for k, v in c["data"].items() if k != "lubrication"})
                brs.append(rate_bearing(c, memo))
            m.bearings = _bearings(cases, brs, len(runs))
        bores = {}
        for c, br in zip(cases, brs):
            bores.setdefault(c["shaft"], bore(br))
        speeds = [n_m] + [r.n_out for r in runs]
        torques = [T_in] + [r.T_out for r in runs]
        last = len(runs) + 1
        ds = lub["seal_diameters"]
        if ds is not None:
            d_in, d_out, seal_source = ds[0], ds[1], "given"
        else:
            d_in = bores.get(1) or HEAT.shaft_diameter(torques[0])
            d_out = bores.get(last) or HEAT.shaft_diameter(torques[-1])
            seal_source = ("bearing bores" if (1 in bores and last in bores) else
                           "estimated: d = (T/(0.2·[τ]))^(1/3), [τ] = 20 MPa ([Dunaev])")
        box.update(d_seal_in=d_in, d_seal_out=d_out)
        m.seals = [HEAT.Seal(0, d_in, speeds[0], "input"),
                   HEAT.Seal(len(runs) - 1, d_out, speeds[-1], "output")]
        bal = HEAT.balance(m, hs, t_air, t_max, limit=False)
        sl = HEAT.stage_losses(m, bal.t_oil)
        for i, s in enumerate(sl):
            if s.total >= s.P_in:
                parts = ", ".join(f"{k} {v:.0f} W" for k, v in (
                    ("mesh", s.mesh), ("churning", s.churning), ("bearings", s.bearings),
                    ("seals", s.seals), ("own η", s.other)) if v > 0)
                raise InputError(Problem("motor.power", f"the losses of stage {i + 1} "
                                         f"({s.total:.0f} W: {parts}) reach its input power "
                                         f"({s.P_in:.0f} W): the drive would not turn; raise "
                                         f"the power, or check the oil grade, the immersion "
                                         f"and the oil volume"))
        etas = {i: s.eta for i, s in enumerate(sl) if i in m.meshes}
        oil_moved = _set_scuffing_oil(stages, scuff or {}, bal.t_oil)
        if etas_before is not None and all(
                abs(etas[i] - etas_before[i]) <= EFFICIENCY_TOL for i in etas):
            break
        if not etas:
            break
        etas_before = etas
        rate_as = (etas, runs)
        T_in, runs = chain(etas, runs, light=True)
    else:
        oil_moved = False
    if oil_moved:
        # the stages rated for scuffing at the sump temperature of the last balance
        rate_as = (etas_before or None, runs)
    # the stages rated once, as the last pass computed them (its efficiencies and ratios)
    T_in, runs = chain(*rate_as)
    for i in (rate_as[0] or {}):
        runs[i].efficiency_source = ETA_SOURCE
    bal = HEAT.with_limit(bal, m, hs, t_air, t_max)
    losses = sl                      # the losses of the last model at its sump temperature
    info.update(nu40=oil.nu40, VI=oil.VI, X_L=oil.X_L)
    t_bearing = min(bal.t_oil, 150.0)

    def bearing_oil(case: dict) -> None:
        lt = case["data"].get("lubrication")
        if not lt or case["data"].get("method") != "iso281_2007":
            return
        if all(lt.get(k) is None for k in ("viscosity", "oil", "nu40", "kappa", "nu1")):
            lt["oil"] = oil.grade
            if lt.get("viscosity_index") is None:
                lt["viscosity_index"] = oil.VI
        if lt.get("oil") is not None or lt.get("nu40") is not None:
            if lt.get("temperature") is None:
                lt["temperature"] = t_bearing
    return Thermal(T_in, runs, m, hs, box, bal, losses, passes, t_air, t_max, info,
                   seal_source, bool(m.bearings), bearing_oil)
