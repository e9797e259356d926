"""The report of a planetary train: the solved record (:mod:`geardesign.planetary.solve`)
turned into report rows and checks (assembly, gears, meshes, kinematics, efficiency, power
flow, strength of every mesh, frequencies)."""

from __future__ import annotations

import math

from geardesign.core.result import Result, check
from geardesign.gears import losses as GL
from geardesign.planetary import checks as C
from geardesign.planetary import geometry as PG
from geardesign.planetary import kinematics as K
from geardesign.planetary import sources as S
from geardesign.planetary.inputs import Inputs
from geardesign.planetary.solve import (
    Assembly,
    Solution,
    assembly,
    central_of,
)
from geardesign.planetary.report_strength import strength_report
from geardesign.gears import internal as I


def geometry_rows(res: Result, inp: Inputs, sol: Solution) -> None:
    """The synthesis, train, gears and mesh sections."""
    if inp.synthesis is not None:
        sec = res.section("synthesis", "Synthesis")
        for row in inp.synthesis:
            sec.add(*row)
    _rows_train(res, inp.train, inp.op, inp.conv)
    _gear_rows(res, sol.gears, inp.conv)
    sec = res.section("train", "Train")
    sec.add("shift_source", inp.how, None, "", "how the shifts were obtained", S.COAX)
    for mesh in inp.meshes:
        _mesh_rows(res, mesh)


def geometry_checks(res: Result, d: dict, train: K.Train, meshes, lay: PG.Layout,
                    shifts: dict, conv: dict, gears: dict, asm: Assembly | None = None
                    ) -> list:
    """The assembly checks (with their rows in ``res``) and the geometry checks of every
    gear and mesh (``asm``: the solved assembly, else solved here)."""
    lim, tr = d["limits"], d["train"]
    if asm is None:
        asm = assembly(train, meshes, lay, shifts, conv, gears, tr["spacing"],
                       lim["neighbour_gap"])
    checks = _assembly(res, d, train, meshes, lay, asm)
    alpha_t = {x: meshes[0].geom.alpha_t for x in gears}
    second = {mesh.spec.pinion: mesh.spec.second for mesh in meshes} | \
        {mesh.spec.wheel: mesh.spec.second for mesh in meshes[1:]}
    modules = {x: lay.m2 if second.get(x, False) else lay.m for x in gears}
    checks += C.gear_checks(gears, lay.rack.h_straight, alpha_t, lay.beta, modules,
                            lim["tip_thickness"], tr["allow_undercut"])
    checks += C.mesh_checks(meshes, lim["specific_sliding"])
    return checks


def _assembly(res: Result, d: dict, train: K.Train, meshes, lay: PG.Layout,
              asm: Assembly) -> list:
    """Coaxiality, spacing, neighbours and phasing: rows and checks."""
    lim = d["limits"]
    checks = []
    asec = res.section("assembly", "Assembly conditions")
    for mesh in meshes:
        asec.add(f"a_w_{mesh.name}", mesh.geom.a_w, "mm", f"a_w,{mesh.name}",
                 f"working centre distance of the {C.MESH_NAMES.get(mesh.name)} mesh", S.COAX)
    asec.add("coaxiality_residual", asm.residual, "mm", "Δa_w",
             "largest difference of the meshes' centre distances", S.COAX)
    m = lay.m
    checks += C.coaxiality_checks(meshes, lim["coaxiality"] * m, dict(asm.needed),
                                  dict(asm.sign_note))
    spc, uneven = asm.spacing, asm.uneven
    for x, n in spc.N.items():
        asec.add(f"N_{x}", n, "-", f"N_{x}", f"admissible planet positions per turn ({x} against "
                 "the ring)", S.ASSEMBLY)
    asec.add("equal_spacing", spc.equal_ok, None, "", f"{train.planets} planets can be equally "
             "spaced", S.ASSEMBLY)
    if spc.equal_ok or uneven:
        asec.add("planet_angles", spc.angles, "deg", "θ_i", "angles of the planets", S.ASSEMBLY)
    if train.planets > 1:
        asec.add("neighbour_clearance", asm.clearance, "mm", "c_n",
                 "gap between the tips of neighbouring planets", S.KUDRYAVTSEV)
    asec.add("planets_max", asm.n_max, "-", "n_w,max",
             f"most equally spaced planets with a gap of {lim['neighbour_gap']:g}·m", S.KUDRYAVTSEV)
    ph = asm.phasing
    asec.add("phase_sun", ph.sun, "-", "γ_s", "sun-mesh phase of each planet (mesh cycles)",
             S.PHASING)
    asec.add("phase_ring", ph.ring, "-", "γ_r", "ring-mesh phase of each planet (mesh cycles)",
             S.PHASING)
    asec.add("phasing", ph.kind, None, "", "mesh phasing of the planets", S.PHASING)
    checks.append(C.assembly_check(train, spc, uneven, asm.advice))
    checks += C.neighbour_checks(asm.clearance, lim["neighbour_gap"], m, asm.n_max,
                                 train.planets)
    checks.append(check("PHASING", True, "info", "", f"planet meshes are {ph.kind}"
                        + (" (sun teeth a multiple of the planets: mesh forces add up; a "
                           "sequential phasing cancels part of the mesh excitation)"
                           if ph.kind == "in phase" else ""), None, None, S.PHASING))
    return checks


def _rows_train(res: Result, train: K.Train, op: dict, conv: dict) -> None:
    sec = res.section("train", "Train")
    sec.add("scheme", train.scheme, None, "", "scheme", S.KUDRYAVTSEV)
    sec.add("ring_convention", "ISO 21771 (z < 0, x_ISO = −x_GOST)" if conv.get("ring", 1) < 0
            else "GOST 19274-73 (z > 0, x > 0 away from the axis)", None, "",
            "sign convention of the internal gears (as given)", S.G19274)
    if op["fixed"] != "none":
        sec.add("i", K.ratio(train, op["fixed"], op["input"], op["output"]), "-", "i",
                f"ratio n_{op['input']}/n_{op['output']} ({op['fixed']} fixed)", S.WILLIS)
        free = [m for m in train.members if m != op["fixed"] and
                not (train.scheme == "3K" and m == "carrier")]
        for a_ in free:
            for b_ in free:
                if a_ < b_:
                    sec.add(f"i_{a_}_{b_}", K.ratio(train, op["fixed"], a_, b_), "-",
                            f"i_{a_},{b_}", f"ratio n_{a_}/n_{b_} ({op['fixed']} fixed)",
                            S.WILLIS)
    for x, y in (("sun", "ring"), ("sun", "ring2"), ("ring2", "ring")):
        if x in train.central and y in train.central:
            sec.add(f"u_h_{x}_{y}", train.willis(x, y), "-", f"u^h_{x},{y}",
                    f"fixed-carrier (Willis) ratio (ω_{x} − ω_h)/(ω_{y} − ω_h)", S.WILLIS)
    if train.scheme == "3K" and op["fixed"] == "ring" and {op["input"], op["output"]} == \
            {"sun", "ring2"}:
        sec.add("U_b_a_e", K.ratio(train, "ring", "sun", "ring2"), "-", "U^b_ae",
                "3K ratio sun → ring2, ring fixed: (1 + z_b/z_a)/(1 − z_b z_f/(z_g z_e))",
                S.MATUSEVICH_1)


def _gear_rows(res: Result, gears: dict, conv: dict) -> None:
    sec = res.section("gears", "Gears")
    for member, g in gears.items():
        ring = member.startswith("ring")
        sec.add(f"z_{member}", g.z, "-", f"z_{member}", f"teeth, {member}", S.G16532)
        sec.add(f"x_{member}", g.x, "-", f"x_{member}",
                f"profile shift, {member}" + (" (GOST 19274-73 sign)" if ring else ""),
                S.G19274 if ring else S.G16532)
        if ring:
            sec.add(f"x_{member}_iso", I.x_to_iso(g.x), "-", f"x_{member},ISO",
                    f"profile shift, {member} (ISO 21771 sign)", S.G19274)
        src = S.G19274 if ring else S.G16532
        sec.add(f"d_{member}", g.d, "mm", f"d_{member}", f"reference diameter, {member}", src)
        sec.add(f"d_b_{member}", g.d_b, "mm", f"d_b,{member}", f"base diameter, {member}", src)
        sec.add(f"d_a_{member}", g.d_a, "mm", f"d_a,{member}",
                f"tip diameter, {member}" + (" (internal)" if ring else ""), src)
        sec.add(f"d_f_{member}", g.d_f, "mm", f"d_f,{member}", f"root diameter, {member}", src)
        sec.add(f"d_l_{member}", g.d_l, "mm", f"d_l,{member}", f"form circle diameter, {member}",
                src)
        sec.add(f"s_n_{member}", g.s_n, "mm", f"s_n,{member}",
                f"normal tooth thickness at the reference circle, {member}", src)
        sec.add(f"s_an_{member}", g.s_an, "mm", f"s_an,{member}",
                f"normal tooth thickness at the tip, {member}",
                S.MATUSEVICH + (" (36)" if ring else " (35)"))
        if not ring:
            sec.add(f"x_min_{member}", g.x_min, "-", f"x_min,{member}",
                    f"least shift without undercut, {member}", S.G16532)
        sec.add(f"k_{member}", g.k, "-", f"k_{member}",
                f"teeth (ring: spaces) spanned, {member}", S.G16532 if not ring else S.G19274)
        sec.add(f"W_{member}", g.W, "mm", f"W_{member}", f"base tangent length, {member}",
                S.G16532 if not ring else S.G19274)


def _mesh_rows(res: Result, mesh: PG.Mesh) -> None:
    g, sp = mesh.geom, mesh.spec
    p1, p2 = sp.pinion, sp.wheel
    mn = C.MESH_NAMES.get(mesh.name, mesh.name)
    src = S.G19274 if sp.internal else S.G16532
    sec = res.section(mesh.name, f"Mesh {mn}" + (" (internal)" if sp.internal else ""))
    sec.add("internal", sp.internal, None, "", "internal mesh", src)
    sec.add("u", g.u, "-", "u", f"tooth ratio z_{p2}/z_{p1}", src)
    sec.add("m_n", g.inp.m_n, "mm", "m_n", "normal module", src)
    if sp.internal:
        sec.add("x_diff", g.x_diff, "-", "x_d", f"shift difference x_{p2} − x_{p1} (GOST sign)",
                src)
    else:
        sec.add("x_sum", g.x_sum, "-", "x_Σ", f"shift sum x_{p1} + x_{p2}", src)
    sec.add("alpha_tw", g.alpha_tw, "rad", "α_tw", "working transverse pressure angle", src)
    sec.add("a", g.a, "mm", "a", "reference centre distance", src)
    sec.add("a_w", g.a_w, "mm", "a_w", "working centre distance", src)
    sec.add("y", g.y, "-", "y", "centre distance modification coefficient", src)
    sec.add("delta_y", g.dy, "-", "Δy", "x_Σ − y (applied to the tips of external meshes only)",
            src)
    sec.add(f"d_w_{p1}", g.g1.d_w, "mm", f"d_w,{p1}", f"working pitch diameter, {p1}", src)
    sec.add(f"d_w_{p2}", g.g2.d_w, "mm", f"d_w,{p2}", f"working pitch diameter, {p2}", src)
    sec.add(f"d_p_{p1}", g.g1.d_p, "mm", f"d_p,{p1}",
            f"lower point of active profile, {p1}", src)
    sec.add(f"d_p_{p2}", g.g2.d_p, "mm", f"d_p,{p2}",
            f"{'outer end' if sp.internal else 'lower point'} of active profile, {p2}", src)
    sec.add("g_w", g.g_w, "mm", "g_w", "N1N2 = a_w sin α_tw", src)
    sec.add("g_alpha", g.g_alpha, "mm", "g_α", "length of the active line of action", src)
    sec.add("p_bt", g.p_bt, "mm", "p_bt", "transverse base pitch", src)
    sec.add("eps_alpha", g.eps_alpha, "-", "ε_α", "transverse contact ratio",
            S.MATUSEVICH + " (31)")
    sec.add("eps_beta", g.eps_beta, "-", "ε_β", "overlap ratio", src)
    sec.add("c_12", g.c_12, "mm", f"c_{p1}", f"radial clearance, {p1} tip to {p2} root", src)
    sec.add("c_21", g.c_21, "mm", f"c_{p2}", f"radial clearance, {p2} tip to {p1} root", src)
    sl = mesh.sliding
    sec.add("theta_p", sl.theta1_A, "-", "ϑ_p",
            f"specific sliding at the {p1} root (meets the {p2} tip)", S.MATUSEVICH + " (32)")
    sec.add("theta_q", sl.theta2_E, "-", "ϑ_q",
            f"specific sliding at the {p2} root (meets the {p1} tip)", S.MATUSEVICH + " (33)")
    sec.add("theta_tip_p", sl.theta1_E, "-", f"ϑ_a,{p1}", f"specific sliding at the {p1} tip",
            S.SLIDING)
    sec.add("theta_tip_q", sl.theta2_A, "-", f"ϑ_a,{p2}", f"specific sliding at the {p2} tip",
            S.SLIDING)
    sec.add("delta_theta", PG.sliding_balance(sl.theta1_A, sl.theta2_E), "-", "Δϑ",
            "sliding imbalance |ϑ_p| − |ϑ_q|", S.MATUSEVICH + " (37)")
    sec.add("eta_p", PG.specific_pressure(g.inp.z1, g.inp.z2, g.alpha_t, g.alpha_tw,
                                          sp.internal), "-", "η",
            "specific-pressure coefficient m/ρ_red", S.MATUSEVICH + " (34)")
    if sp.internal:
        from geardesign.spur.calculator import internal_rows

        internal_rows(sec, g)


def operation_report(res: Result, inp: Inputs, sol: Solution) -> list:
    """Kinematics, efficiency, torques and power flow, planet bearing, strength and
    frequencies: rows into ``res``, the checks returned."""
    d, train, meshes, op = inp.data, inp.train, inp.meshes, inp.op
    out = []
    s, has_speed = sol.speeds, sol.has_speed
    inp_, outp = op["input"], op["output"]
    two_dof = op["fixed"] == "none"
    ksec = res.section("kinematics", "Kinematics (Willis)")
    if has_speed:
        for mbr in train.members:
            ksec.add(f"n_{mbr}", s.n[mbr], "min^-1", f"n_{mbr}", f"speed of the {mbr}", S.WILLIS)
        ksec.add("n_planet", s.n_planet, "min^-1", "n_g", "absolute speed of the planet",
                 S.WILLIS)
        for mbr in train.central:
            ksec.add(f"n_{mbr}_rel", s.rel(mbr), "min^-1", f"n_{mbr}−n_h",
                     f"speed of the {mbr} relative to the carrier", S.WILLIS)
        ksec.add("n_planet_rel", s.n_planet_rel, "min^-1", "n_g−n_h",
                 "speed of the planet relative to the carrier (planet bearing speed)", S.WILLIS)
        if two_dof:
            ksec.add("i", s.n[inp_] / s.n[outp] if s.n[outp] != 0 else math.nan, "-", "i",
                     f"ratio n_{inp_}/n_{outp} at the imposed {op['control']} speed", S.WILLIS)
        for mesh in meshes:
            mo = sol.motion[mesh.name]
            ksec.add(f"v_{mesh.name}", mo.v, "m/s", f"v_{mesh.name}",
                     f"pitch-line velocity of the {C.MESH_NAMES.get(mesh.name)} mesh (relative "
                     "to the carrier)", S.SLIDING)
            ksec.add(f"v_s_{mesh.name}", mo.v_s, "m/s", f"v_s,{mesh.name}",
                     f"largest sliding velocity of the {C.MESH_NAMES.get(mesh.name)} mesh",
                     S.SLIDING)

    # -- efficiency
    ef = sol.efficiency
    eta, hv = ef.eta, ef.hv
    esec = res.section("efficiency", "Efficiency and self-locking")
    for mesh in meshes:
        central = central_of(mesh)
        mn = C.MESH_NAMES.get(mesh.name)
        if GL.loss_factor_applies(mesh.geom.eps_alpha):   # else only a given efficiency
            esec.add(f"H_V_{mesh.name}", hv[mesh.name], "-", f"H_V,{mesh.name}",
                     f"tooth loss factor of the {mn} mesh", S.HV)
        esec.add(f"eta_{mesh.name}", eta[central], "-", f"η_{mesh.name}",
                 f"efficiency of the {mn} mesh", S.HV if d["efficiency"]["model"] == "niemann"
                 else "spec")
    for x, y in (("sun", "ring"), ("ring2", "ring")):
        if x in train.central and y in train.central:
            esec.add(f"eta_h_{x}_{y}", eta[x] * eta[y], "-", f"η^h_{x},{y}",
                     f"fixed-carrier efficiency of the chain {x} → {y}", S.TORQUE)
    esec.add("eta", ef.eta_f, "-", "η", f"efficiency {inp_} → {outp}"
             + (" (all outputs/all inputs)" if two_dof else ""), S.TORQUE)
    if two_dof:
        control = op["control"]
        esec.add("eta_branch", ef.eta_branch, "-", "η_13",
                 f"branch efficiency −P_{outp}/(P_{inp_} + P_{control}) with the {control} "
                 "controlled", S.MALASHCHENKO)
    esec.add("eta_reverse", ef.eta_r, "-", "η'", f"reverse efficiency {outp} → {inp_} (formal "
             "value; ≤ 0 or no consistent power flow: self-locking)", S.TORQUE)
    esec.add("self_locking", ef.self_locking, None, "", "the output cannot drive the input",
             S.TORQUE)
    out += C.efficiency_checks(ef.forward.consistent, ef.eta_f, ef.reverse.consistent,
                               ef.eta_r, d["efficiency"]["self_locking"],
                               d["efficiency"]["near_self_locking"])
    if sol.power is not None:
        _power_rows(res, inp, sol)
        if sol.strength is not None:
            out += strength_report(res, inp, sol.strength)
    if sol.frequencies is not None:
        _frequency_rows(res, inp, sol)
    return out


def _power_rows(res: Result, inp: Inputs, sol: Solution) -> None:
    """Torques and power flow, and the planet bearing load."""
    train, op, pw, eta = inp.train, inp.op, sol.power, sol.efficiency.eta
    loaded, f, T_in = train.loaded, pw.flow, pw.T_in
    psec = res.section("power", "Torques and power flow")
    for mbr in train.members:
        if mbr in loaded:
            psec.add(f"T_{mbr}", f.T[mbr], "N·m", f"T_{mbr}",
                     f"torque on the {mbr} (with mesh losses)", S.TORQUE)
    for mbr in train.members:
        if mbr in loaded:
            psec.add(f"T_{mbr}_ideal", pw.ideal.T[mbr] * T_in, "N·m", f"T_{mbr},0",
                     f"torque on the {mbr} without losses", S.WILLIS)
    if sol.has_speed:
        for mbr in train.members:
            if mbr in loaded:
                psec.add(f"P_{mbr}", f.P[mbr], "kW", f"P_{mbr}",
                         f"power delivered by the {mbr} (> 0 input, < 0 output)", S.TORQUE)
        for mesh in inp.meshes:
            central = central_of(mesh)
            P_rel = abs(f.P_mesh[central])
            psec.add(f"P_mesh_{mesh.name}", P_rel, "kW", f"P_{mesh.name}",
                     f"rolling power of the {C.MESH_NAMES.get(mesh.name)} meshes (all "
                     "planets, carrier frame)", S.TORQUE)
            psec.add(f"P_loss_{mesh.name}", P_rel * (1.0 - eta[central]) /
                     (eta[central] if f.k[central] < 0 else 1.0), "kW",
                     f"P_V,{mesh.name}", "power lost in these meshes", S.HV)
        P_in = abs(f.P[op["input"]])
        if P_in > 0.0:
            psec.add("circulating_ratio", max(abs(v) for v in f.P_mesh.values()) / P_in,
                     "-", "P_mesh/P_in", "largest rolling power over the input power "
                     "(circulating power when > 1)", S.KUDRYAVTSEV)
    bl = pw.bearing
    bsec = res.section("planet_bearing", "Planet bearing")
    bsec.add("F_bearing", bl.F_r, "N", "F_r", "load on one planet bearing (vector sum of the "
             "mesh forces, nominal torque, no K_γ)", S.KUDRYAVTSEV)
    bsec.add("F_bearing_t", bl.F_t, "N", "F_t", "its component along the carrier's motion",
             S.KUDRYAVTSEV)
    bsec.add("F_bearing_r", bl.F_n, "N", "F_n", "its component along the carrier radius",
             S.KUDRYAVTSEV)
    if sol.has_speed:
        bsec.add("n_bearing", bl.n, "min^-1", "n", "speed of the planet on its bearing",
                 S.WILLIS)


def _frequency_rows(res: Result, inp: Inputs, sol: Solution) -> None:
    train, fq, f = inp.train, inp.data["frequencies"], sol.frequencies
    fr = f.fr
    sec = res.section("frequencies", "Frequencies for diagnostics")
    for mbr in train.members:
        sec.add(f"f_{mbr}", fr.f[mbr], "Hz", f"f_{mbr}", f"rotation frequency of the {mbr}",
                S.BELAZ)
    for mbr, v in fr.f_rel.items():
        sec.add(f"f_{mbr}_rel", v, "Hz", f"f_{mbr},rel",
                f"rotation frequency of the {mbr} relative to the carrier", S.BELAZ)
    sec.add("f_mesh", fr.f_mesh, "Hz", "f_z", "mesh frequency z_a|f_a − f_h|", S.BELAZ)
    if fr.f_mesh2 is not None:
        sec.add("f_mesh2", fr.f_mesh2, "Hz", "f_z2", "mesh frequency of the second crown's mesh",
                S.BELAZ)
    sec.add("f_mesh_harmonics", [h * fr.f_mesh for h in range(1, fq["harmonics"] + 1)], "Hz",
            "h·f_z", "mesh harmonics", S.BELAZ)
    delta = fq["speed_fluctuation"]
    sec.add("f_mesh_band", [fr.f_mesh * (1 - delta), fr.f_mesh * (1 + delta)], "Hz",
            "f_z(1 ± δ)", "mesh frequency band for the admissible speed fluctuation", S.BELAZ)
    sec.add("planet_pass", fr.planet_pass, "Hz", "f_pp", "planet-pass frequency n_w|f_b − f_h|",
            S.BELAZ)
    for mbr, v in fr.fault.items():
        sec.add(f"f_fault_{mbr}", v, "Hz", f"f_d,{mbr}",
                f"local-fault frequency of the {mbr}", S.BELAZ)
    for mbr in ("sun", "planet", "ring"):
        sec.add(f"sidebands_{mbr}", f.sidebands[mbr], "Hz", f"h f_z ± k f_d ± l f_h ({mbr})",
                f"sideband families around the mesh harmonics, {mbr} fault", S.BELAZ)
    if f.S_fz is not None:
        sec.add("S_fz", f.S_fz, "m/s^2", "S_fz", "discriminant: root sum of squares of the "
                "harmonic amplitudes", S.BELAZ + " (1)")
        if f.S_fz0 is not None:
            sec.add("S_fz0", f.S_fz0, "m/s^2", "S_fz0", "discriminant at the start of "
                    "monitoring", S.BELAZ + " (1)")
            sec.add("P_fz", f.P_fz, "-", "P_fz", "relative growth of the discriminant",
                    S.BELAZ + " (2)")
