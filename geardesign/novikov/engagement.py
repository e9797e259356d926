"""The phase loop of Korotkin's NOVGOST-17 algorithm: for every engagement phase the load
sharing among the theoretical contact points (system (2)), the phase bending and contact
stresses at every point, and the critical (maximum) stresses with their phase, tooth,
line and position ([Korotkin2017]).

Error cases (``deviations``): with ``model = "grades"`` each tooth pair in contact is in
turn the *study tooth* that leads by the design pitch deviation e_p, and the lead mismatch
is taken with both signs of its random part; the reported values of a point are the
envelope (maximum) over these cases.  ``"explicit"`` uses the given per-tooth gaps and
lead, ``"none"`` only the misalignment θ.  The *ideal* case (no deviations, no θ) is
always computed as well, so that the report can show how much of σ_max the deviations
cause.
"""

from __future__ import annotations

from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.novikov import deviations as dev
from geardesign.novikov.factors import psi_in_range
from geardesign.novikov.geometry import PhasePoint
from geardesign.novikov.sharing import share_load
from geardesign.novikov.stress import sigma_F, sigma_H


@dataclass(frozen=True)
class MeshData:
    """Everything the phase loop needs, in N, mm, µm, rad."""

    F_sum: float        # total tangential force (× K_A) [N]
    m: float
    b_w: float
    alpha_k: float
    l_k: float
    rho_p: float
    k_a: float          # a = k_a·√F [mm/√N]
    c_p: float          # base stiffness of a contact point [N/µm]
    Y_v1: float
    Y_v2: float
    relief: float       # end relief Δ [µm]


@dataclass(frozen=True)
class ErrorCase:
    """One deterministic set of gaps: per-tooth pitch gaps [µm] and a lead mismatch [µm]
    over the face (positive: the entry end b = 0 closes first)."""

    label: str
    lead: float
    pitch: dict = field(default_factory=dict)


@dataclass(frozen=True)
class PointStress:
    """Result at one point in one case."""

    k: int
    i: int
    zub: int
    j: int
    b: float
    t: float
    F: float
    psi: float
    sigma_F: float
    sigma_H: float
    case: str

    @property
    def psi_clamped(self) -> bool:
        return self.F > 0.0 and not psi_in_range(self.psi)


@dataclass
class PointEnvelope:
    """The maxima over the error cases at one point of one phase."""

    point: PhasePoint
    F_ideal: float = 0.0
    F_max: float = 0.0
    sigma_F: float = 0.0
    sigma_H: float = 0.0
    psi_at_H: float = 0.0
    case_F: str = ""
    case_H: str = ""


@dataclass
class Critical:
    """The critical (maximum) stress and where it occurs."""

    value: float = 0.0
    at: PointStress | None = None

    def offer(self, value: float, at: PointStress) -> None:
        if at is not None and value > self.value * (1.0 + 1e-12):
            self.value, self.at = value, at


@dataclass
class Engagement:
    """Results of the phase loop."""

    envelopes: list[list[PointEnvelope]]
    sigma_F: Critical            # overall (both gears), as printed by Korotkin
    sigma_F1: Critical           # j = 1 points: pinion addendum loaded, pinion bending
    sigma_F2: Critical           # j = 2 points: wheel bending
    sigma_H: Critical
    ideal_F: Critical
    ideal_H: Critical
    evaluations: int = 0         # loaded point evaluations in the design cases
    clamped: int = 0             # ... of which with ψ outside [0.05, 0.25]
    psi_min: float = 0.0         # least and greatest ψ of the loaded evaluations
    psi_max: float = 0.0
    min_active: int = 0          # least number of loaded points in any phase/case
    unloaded_phases: int = 0     # phases where a theoretical point carried no load


def point_stress(p: PhasePoint, F: float, psi: float, mesh: MeshData, case: str) -> PointStress:
    """σ_F (eq. (3), Y_v of the gear whose addendum is loaded) and σ_H (eq. (4))."""
    Y_v = mesh.Y_v1 if p.j == 1 else mesh.Y_v2
    t = p.t
    return PointStress(p.k, p.i, p.zub, p.j, p.b, t, F, psi,
                       sigma_F(F, mesh.m, Y_v, t, psi),
                       sigma_H(F, mesh.l_k, mesh.rho_p, mesh.alpha_k, t, psi), case)


def solve_case(points: list[PhasePoint], case: ErrorCase, mesh: MeshData
               ) -> tuple[list[PointStress], int]:
    """Load sharing and stresses of one phase for one error case; returns the per-point
    results (input order) and the number of loaded points."""
    gaps = [case.pitch.get(p.zub, 0.0) + dev.lead_gap(case.lead, p.b)
            + dev.relief_gap(mesh.relief, p.t) for p in points]
    sh = share_load(mesh.F_sum, [p.t for p in points], gaps, mesh.c_p, mesh.k_a, mesh.b_w)
    return [point_stress(p, F, psi, mesh, case.label)
            for p, F, psi in zip(points, sh.F, sh.psi)], sh.active


def design_cases(model: str, teeth: list[int], theta_lead: float, lead_design: float,
                 pitch_design: float, pitch_errors: dict[int, float] | None = None,
                 lead_error: float = 0.0) -> list[ErrorCase]:
    """The error cases of one phase whose teeth in contact are ``teeth``.

    * ``"grades"``: for s = +1, −1 and each study tooth z: lead θ·b_w + s·e_l, pitch gap
      −e_p on tooth z (it leads), 0 on the others ([GOST1643], worst sign pattern).
    * ``"explicit"``: the given gaps per tooth and lead θ·b_w + lead_error.
    * ``"none"``: lead θ·b_w only.
    """
    if model == "grades":
        out = []
        for s, sign in ((1.0, "+"), (-1.0, "−")):
            lead = theta_lead + s * lead_design
            for z in teeth:
                out.append(ErrorCase(f"tooth {z} leads by e_p, lead {sign}e_l", lead,
                                     {z: -pitch_design}))
        return out
    if model == "explicit":
        return [ErrorCase("given deviations", theta_lead + lead_error, dict(pitch_errors or {}))]
    return [ErrorCase("misalignment only", theta_lead)]


def run_phases(rows: list[list[PhasePoint]], mesh: MeshData, model: str, theta_lead: float,
               lead_design: float = 0.0, pitch_design: float = 0.0,
               pitch_errors: dict[int, float] | None = None,
               lead_error: float = 0.0) -> Engagement:
    """The NOVGOST-17 phase loop over the phases ``rows`` (each a list of points inside
    the face).  Returns envelopes per point and the critical stresses (design cases) and
    the ideal-pair maxima."""
    eng = Engagement([], Critical(), Critical(), Critical(), Critical(), Critical(),
                     Critical(), min_active=10 ** 9)
    ideal = ErrorCase("ideal pair", 0.0)
    psis: list[float] = []
    for points in rows:
        envs = [PointEnvelope(p) for p in points]
        eng.envelopes.append(envs)
        if not points:
            continue
        res, _ = solve_case(points, ideal, mesh)
        for env, r in zip(envs, res):
            env.F_ideal = r.F
            eng.ideal_F.offer(r.sigma_F, r)
            eng.ideal_H.offer(r.sigma_H, r)
        teeth = sorted({p.zub for p in points})
        unloaded = False
        for case in design_cases(model, teeth, theta_lead, lead_design, pitch_design,
                                 pitch_errors, lead_error):
            res, active = solve_case(points, case, mesh)
            eng.min_active = min(eng.min_active, active)
            unloaded = unloaded or active < len(points)
            for env, r in zip(envs, res):
                if r.F > 0.0:
                    eng.evaluations += 1
                    eng.clamped += r.psi_clamped
                    psis.append(r.psi)
                if r.F > env.F_max:
                    env.F_max = r.F
                if r.sigma_F > env.sigma_F:
                    env.sigma_F, env.case_F = r.sigma_F, r.case
                if r.sigma_H > env.sigma_H:
                    env.sigma_H, env.case_H, env.psi_at_H = r.sigma_H, r.case, r.psi
                eng.sigma_F.offer(r.sigma_F, r)
                (eng.sigma_F1 if r.j == 1 else eng.sigma_F2).offer(r.sigma_F, r)
                eng.sigma_H.offer(r.sigma_H, r)
        eng.unloaded_phases += unloaded
    if eng.min_active == 10 ** 9:
        eng.min_active = 0
    if psis:
        eng.psi_min, eng.psi_max = min(psis), max(psis)
    return eng
