"""A planetary train computed from its typed inputs (:class:`~geardesign.planetary.inputs.
Inputs`) into one frozen record: gears, assembly conditions, kinematics, efficiency and
self-locking, torques and power flow, the planet bearing load, the strength of every mesh
and the diagnostic frequencies.  Pure: no spec, no report rows (those are
:mod:`geardesign.planetary.report`'s).  Formulas in :mod:`.kinematics`, :mod:`.assembly`,
:mod:`.geometry`, :mod:`geardesign.gears.losses` and :mod:`.efficiency`, :mod:`.strength`."""

from __future__ import annotations

import math
from typing import Mapping

from geardesign.core.records import dataclass
from geardesign.gears import losses as GL
from geardesign.planetary import assembly as A
from geardesign.planetary import efficiency as E
from geardesign.planetary import geometry as PG
from geardesign.planetary import kinematics as K
from geardesign.planetary.inputs import Inputs, input_torque, speeds
from geardesign.planetary.train import MIN_RING_EXCESS
from geardesign.planetary.shifts import _gost_to_user
from geardesign.gears import geometry as G
from geardesign.spur.kinematics import velocities


def members_gears(meshes) -> dict:
    """The gear of every member (sun, planet, ring, planet2, ring2) from the meshes."""
    sp = meshes[0].geom
    gears = {"sun": sp.g1, "planet": sp.g2}
    for mesh in meshes[1:]:
        if mesh.spec.pinion not in gears:
            gears[mesh.spec.pinion] = mesh.geom.g1
        gears[mesh.spec.wheel] = mesh.geom.g2
    return gears


def central_of(mesh) -> str:
    """The central member of a mesh: the sun, or the ring it meshes."""
    return "sun" if mesh.spec.pinion == "sun" else mesh.spec.wheel


@dataclass(frozen=True)
class Assembly:
    """Coaxiality, spacing, neighbours and phasing of the planets ([Kudryavtsev])."""

    a_ref: float                  # working centre distance of the sun–planet mesh [mm]
    needed: Mapping               # ring -> its shift for coaxiality (user's sign; nan: none)
    sign_note: Mapping            # ring -> the sign convention of that shift
    residual: float               # largest difference of the meshes' a_w [mm]
    spacing: A.Spacing
    uneven: bool
    clearance: float              # tip gap of neighbouring planets [mm]
    n_max: int                    # most equally spaced planets
    phasing: A.Phasing
    advice: str                   # the change that makes equal spacing possible


def assembly_advice(train: K.Train) -> str:
    """The nearest ring teeth with which the planets can be equally spaced."""
    k = train.planets
    zb = train.ring
    for step in range(1, k):
        for cand in (zb - step, zb + step):
            t2 = K.Train(train.scheme, train.sun, train.planet, cand, k, train.planet2,
                         train.ring2)
            if cand - train.crown("ring") >= MIN_RING_EXCESS and A.spacing(t2).equal_ok:
                return (f"change the ring to {cand} teeth (and make the meshes coaxial with "
                        f"shifts, train.center_distance)")
    return "change the sun or ring teeth"


def assembly(train: K.Train, meshes, lay: PG.Layout, shifts: Mapping, conv: Mapping,
             gears: Mapping, spacing_mode: str, neighbour_gap: float) -> Assembly:
    """The assembly conditions of the train ([Kudryavtsev]; [Matusevich2017] coaxiality)."""
    a_ref = meshes[0].geom.a_w
    needed, sign_note = {}, {}
    for mesh in meshes[1:]:
        ring = mesh.spec.wheel
        try:
            xd = PG.shift_sum_for(lay, mesh.spec, a_ref)
            needed[ring] = _gost_to_user(shifts[mesh.spec.pinion] + xd, conv.get(ring, 1))
        except G.GeometryError:
            needed[ring] = math.nan
        sign_note[ring] = "ISO 21771 sign" if conv.get(ring, 1) < 0 else "GOST 19274-73 sign"
    spc = A.spacing(train)
    uneven = spacing_mode == "uneven"
    crowns = [gears["planet"].d_a] + ([gears["planet2"].d_a] if "planet2" in gears else [])
    d_a_max = max(crowns)
    clearance = A.neighbour_clearance(a_ref, d_a_max, math.radians(spc.min_angle
                                                                    if uneven else
                                                                    360.0 / train.planets))
    n_max = A.max_planets(a_ref, d_a_max, neighbour_gap * lay.m)
    return Assembly(a_ref, needed, sign_note, max(abs(m.geom.a_w - a_ref) for m in meshes),
                    spc, uneven, clearance, n_max, A.phasing(train, spc.angles),
                    assembly_advice(train))


@dataclass(frozen=True)
class MeshMotion:
    """Pitch-line and largest sliding velocity of a mesh relative to the carrier [m/s]."""

    v: float
    v_s: float


@dataclass(frozen=True)
class Efficiency:
    """Mesh efficiencies, the train's forward and reverse efficiency ([Kudryavtsev])."""

    eta: Mapping                  # central member -> efficiency of its meshes
    hv: Mapping                   # mesh name -> loss factor H_V
    forward: E.Flow
    eta_f: float
    eta_branch: float | None      # a differential: −P_out/(P_in + P_control)
    reverse: E.Flow
    eta_r: float
    self_locking: bool


def mesh_efficiencies(meshes, eff: Mapping) -> tuple[dict, dict]:
    """The efficiency of each central member's meshes: 1 − μ·H_V ([ISOTR14179-2], H_V of
    Ohlendorf) or given."""
    by_member, hv = {}, {}
    for mesh in meshes:
        H = GL.mesh_loss_factor(mesh.geom)
        hv[mesh.name] = H
        if eff["model"] == "given":
            eta = eff["internal"] if mesh.spec.internal else eff["external"]
        else:
            eta = 1.0 - eff["friction"] * H
        by_member[central_of(mesh)] = eta
    return by_member, hv


def efficiency(train: K.Train, meshes, s: K.Speeds, op: Mapping, eff: Mapping) -> Efficiency:
    """The power flow with mesh losses, forward and reverse: efficiency and self-locking."""
    eta, hv = mesh_efficiencies(meshes, eff)
    inp, outp, fixed = op["input"], op["output"], op["fixed"]
    two_dof = fixed == "none"
    loaded = train.loaded
    control = op["control"] if two_dof else None
    unknown = (outp, control) if two_dof else (fixed, outp)
    sign_in = 1.0 if s.n[inp] > 0 else -1.0
    f_fwd = E.flow(train, s, eta, inp, sign_in, unknown, driven=outp)
    driving = (inp, control) if two_dof else (inp,)
    if two_dof:
        eta_f = -sum(min(f_fwd.P[mb], 0.0) for mb in loaded) / \
            sum(max(f_fwd.P[mb], 0.0) for mb in loaded)
    else:
        eta_f = E.efficiency(f_fwd, (inp,), outp)
    branch = E.efficiency(f_fwd, driving, outp) if two_dof else None
    sign_out = 1.0 if s.n[outp] > 0 else -1.0
    unknown_r = tuple(mb for mb in unknown if mb != outp) + (inp,)
    f_rev = E.flow(train, s, eta, outp, sign_out, unknown_r, driven=inp)
    eta_r = E.efficiency(f_rev, (outp, control) if two_dof else (outp,), inp)
    return Efficiency(eta, hv, f_fwd, eta_f, branch, f_rev, eta_r,
                      (not f_rev.consistent) or not eta_r > 0.0)


@dataclass(frozen=True)
class Power:
    """Torques and power flow at the input torque, and the planet bearing load."""

    T_in: float                   # [N·m]
    flow: E.Flow                  # with mesh losses
    ideal: E.Flow                 # without, per N·m of input torque
    ideal_T: Mapping              # member -> torque without losses [N·m]
    bearing: object               # :class:`geardesign.planetary.strength.BearingLoad`


def power(train: K.Train, meshes, s: K.Speeds, op: Mapping, eta: Mapping) -> Power | None:
    """Torques of the members with and without losses, and the planet bearing load
    ([Kudryavtsev]); ``None`` without a torque or power."""
    from geardesign.planetary.strength import planet_bearing_load

    inp, outp, fixed = op["input"], op["output"], op["fixed"]
    unknown = (outp, op["control"]) if fixed == "none" else (fixed, outp)
    sign_in = 1.0 if s.n[inp] > 0 else -1.0
    T_in = input_torque(op)
    if T_in is None:
        return None
    ideal = E.flow(train, s, {x: 1.0 for x in train.central}, inp, sign_in, unknown)
    f = E.flow(train, s, eta, inp, sign_in * T_in, unknown, driven=outp)
    ideal_T = {x: ideal.T[x] * T_in for x in train.members}
    return Power(T_in, f, ideal, ideal_T,
                 planet_bearing_load(train, meshes, ideal_T, 1.0, s.n_planet_rel))


@dataclass(frozen=True)
class MeshStrength:
    """The rating of one mesh (``rating`` ``None``: the mesh cannot run as computed)."""

    mesh: PG.Mesh
    duty: object                  # :class:`geardesign.planetary.strength.MeshDuty`
    pair: tuple                   # the members' materials
    rating: object | None


@dataclass(frozen=True)
class Strength:
    """The strength of every mesh to GOST 21354-87 or ISO 6336 (the spur rating)."""

    method: str
    iso: bool
    peak_ratio: float | None
    meshes: tuple[MeshStrength, ...]
    lightest: Mapping | None      # rating values of the mesh with the least contact load


def material_table(d: Mapping, member: str) -> dict:
    """The [material.X] table of a member (planet2 and ring2 fall back to the planet's
    and the ring's)."""
    mat = d["material"]
    if mat.get(member) is None:
        member = {"planet2": "planet", "ring2": "ring"}[member]
    return mat[member]


def strength(inp: Inputs, s: K.Speeds, T_ideal: Mapping) -> Strength:
    """Every mesh rated by the spur rating of the strength method with the duty of one
    planet ([Kudryavtsev] load sharing K_γ; ISO 6336 takes K_γ as its own factor)."""
    from geardesign.planetary.strength import mesh_duties, rate_mesh
    from geardesign.spur.checks import contact_load_fraction
    from geardesign.spur.strength import method
    from geardesign.spur.strength.rating import Setting

    d, train, meshes, mats = inp.data, inp.train, list(inp.meshes), inp.mats
    st, op = d["strength"], d["operation"]
    rate = method(st["method"]).rate
    # a crown meshing a sun and a ring is loaded on both flanks (alternating bending)
    both = {"planet": train.scheme != "2K-H-stepped", "planet2": False}
    iso = st["method"] == "ISO 6336:2019"
    duties = mesh_duties(train, meshes, s, T_ideal, 1.0 if iso else st["load_sharing"], both)
    T_in = abs(T_ideal[op["input"]])
    peak_ratio = st["peak_torque"] / T_in if st["peak_torque"] is not None else None
    out = []
    for mesh, md in zip(meshes, duties):
        pair = (mats[md.members[0]], mats[md.members[1]])
        if iso:
            from geardesign.spur.calculator import ratable

            if not ratable(mesh.geom):
                out.append(MeshStrength(mesh, md, pair, None))
                continue
        overrides = {}
        if mesh.spec.internal and st.get("ring_form_factor") is not None:
            overrides["Y_FS2"] = st.get("ring_form_factor")
        ra = tuple(material_table(d, mb)["roughness_Ra"] for mb in md.members)
        # the GOST-only keys are left out of an ISO 6336 spec (iso_inputs.prepare)
        setting = Setting(st["accuracy_grade"], st.get("tip_relief", False),
                          st.get("bearing_scheme"), ra, overrides)
        mesh_rate = rate
        if iso:
            from geardesign.planetary.iso_inputs import mesh_rate_function

            mesh_rate = mesh_rate_function(rate, d, train, meshes, mesh, md)
        rating = rate_mesh(mesh_rate, md, pair, st["application_factor"], st["life_hours"],
                           st.get("regime"), (), peak_ratio, setting)
        out.append(MeshStrength(mesh, md, pair, rating))
    rated = [m.rating.v for m in out if m.rating is not None]
    lightest = min(rated, key=lambda x: contact_load_fraction(x)[0]) if rated else None
    return Strength(st["method"], iso, peak_ratio, tuple(out), lightest)


@dataclass(frozen=True)
class Frequencies:
    """Frequencies for diagnostics and the discriminant of measured amplitudes
    ([Gavrilov2017])."""

    fr: K.Frequencies
    sidebands: Mapping            # member -> sideband families around the mesh harmonics
    S_fz: float | None
    S_fz0: float | None
    P_fz: float | None


def frequencies(train: K.Train, s: K.Speeds, fq: Mapping) -> Frequencies:
    fr = K.frequencies(train, s)
    side = {mbr: K.sidebands(fr.f_mesh, fr.fault[mbr], fr.f_carrier, fq["harmonics"],
                             fq["sideband_orders"]) for mbr in ("sun", "planet", "ring")}
    amps, base = fq["amplitudes"], fq["baseline"]
    Sd = S0 = P = None
    if amps is not None:
        Sd = K.discriminant(amps)
        if base is not None:
            S0 = K.discriminant(base)
            P = K.relative_growth(Sd, S0)
    return Frequencies(fr, side, Sd, S0, P)


@dataclass(frozen=True)
class Solution:
    """Everything the report shows of a planetary train."""

    gears: Mapping
    assembly: Assembly
    speeds: K.Speeds              # at the input speed, or per min⁻¹ without one
    has_speed: bool
    motion: Mapping               # mesh name -> MeshMotion (with a speed)
    efficiency: Efficiency
    power: Power | None
    strength: Strength | None
    frequencies: Frequencies | None


def solve(inp: Inputs) -> Solution:
    """The train analysed: assembly, kinematics (Willis), efficiency, torques, strength
    and frequencies."""
    d, train, meshes, op = inp.data, inp.train, inp.meshes, inp.op
    gears = members_gears(meshes)
    asm = assembly(train, meshes, inp.lay, inp.shifts, inp.conv, gears, d["train"]["spacing"],
                   d["limits"]["neighbour_gap"])
    has_speed = op["speed"] is not None
    s = speeds(train, op, unit=not has_speed)
    motion = {}
    if has_speed:
        for mesh in meshes:
            g = mesh.geom
            n1 = s.rel("sun") if mesh.spec.pinion == "sun" else s.n_planet_rel
            sv = velocities(g, abs(n1))   # ω1 ± ω2: external or internal mesh
            motion[mesh.name] = MeshMotion(abs(math.pi * n1 / 30.0) * g.g1.d_w / 2000.0,
                                           max(abs(sv.v_s_A), abs(sv.v_s_E)))
    eff = efficiency(train, meshes, s, op, d["efficiency"])
    pw = power(train, meshes, s, op, eff.eta)
    rating = (strength(inp, s, pw.ideal_T) if pw is not None and inp.mats is not None
              else None)
    fq = frequencies(train, s, d["frequencies"]) if has_speed else None
    return Solution(gears, asm, s, has_speed, motion, eff, pw, rating, fq)
