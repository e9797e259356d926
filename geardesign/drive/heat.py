"""Losses and heat balance of a whole drive: the loss sources of every stage
(:mod:`.losses`) put together from the stage results, and the oil sump temperature from
the heat balance of the housing (:mod:`.thermal`).

Where the losses go (the stage whose efficiency they lower): a cylindrical stage's mesh
and the churning of its two gears; the bearings of shaft i (the input shaft of stage i),
and of the last shaft too, to the last stage; the lip seal of the input shaft to the first
stage, of the output shaft to the last.  A worm, planetary or Novikov stage keeps its own
efficiency (or the one the spec gives); its loss (1 − η)·P_in heats the oil all the same.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.drive import losses as L
from geardesign.drive import thermal as TH
from geardesign.materials import lubricants as OIL

T_SEARCH_MAX = 250.0        # °C: the sump temperature is searched up to here
TAU_SHAFT = 20.0            # MPa, [τ] of the preliminary shaft diameter ([Dunaev])


@dataclass(frozen=True)
class Oil:
    grade: str
    nu40: float
    nu100: float
    VI: float
    rho15: float
    X_L: float
    Ra: float | None            # µm, flank roughness given for every stage

    def nu(self, t: float) -> float:
        """Kinematic viscosity [mm²/s] at t [°C] (ASTM D341); held at 2 mm²/s, the lower
        end of the method, above the temperature where the oil gets that thin."""
        try:
            return OIL.viscosity_at(t, self.nu40, self.nu100)
        except OIL.OilError:
            return OIL.NU_MIN_D341

    def rho(self, t: float) -> float:
        return L.oil_density(self.rho15, t)

    def eta(self, t: float) -> float:
        """Dynamic viscosity [mPa·s] at t [°C]."""
        return self.nu(t) * self.rho(t) / 1000.0


@dataclass(frozen=True)
class Mesh:
    """A cylindrical involute stage: what the mesh loss needs (mm, deg, N, min⁻¹, W)."""

    P_in: float
    n1: float
    u: float
    z1: int
    beta_b: float
    alpha_tw: float
    eps_alpha: float
    eps_1: float
    d_w1: float
    d_w2: float
    b: float
    F_bt: float
    Ra: float | None = None     # µm, mean flank roughness of the stage (else the oil's)


@dataclass(frozen=True)
class DipGear:
    stage: int
    member: str           # "pinion" or "wheel"
    R_p: float            # mm, working pitch radius
    R_a: float            # mm, tip radius
    b: float
    z: int
    m_n: float
    alpha_n: float
    n: float


@dataclass(frozen=True)
class BearingLoad:
    stage: int            # the stage its loss is booked to
    name: str
    kind: str
    d_m: float
    n: float
    F_r: float
    F_a: float
    P0: float
    C0: float
    Y: float | None


@dataclass(frozen=True)
class Seal:
    stage: int
    d: float
    n: float
    where: str


@dataclass
class Model:
    """Everything the losses of the drive depend on, but the oil temperature and a
    scale of the transmitted load (for the thermal power limit)."""

    oil: Oil
    n_stages: int
    P_in: list[float]                       # W, input power of each stage
    meshes: dict[int, Mesh] = field(default_factory=dict)
    fixed: dict[int, float] = field(default_factory=dict)   # stage -> its own η
    dip: list[DipGear] = field(default_factory=list)
    immersion: dict[tuple[int, str], float] = field(default_factory=dict)
    V0: float = 1.0                         # l
    bearings: list[BearingLoad] = field(default_factory=list)
    seals: list[Seal] = field(default_factory=list)
    fixed_terms: dict = field(default_factory=dict, repr=False, compare=False)
    """Per stage, what its losses take that does not depend on the oil temperature or the
    load scale (:func:`_fixed_terms`), computed on first use; each bearing's load moment
    M1 at each load scale; and the losses at each operating point (oil temperature, load
    scale) computed (:func:`stage_losses`).  The model is not changed once its losses are
    asked for."""


def _fixed_terms(m: Model, i: int) -> tuple:
    """Stage ``i``'s terms that do not change with the oil temperature or the load scale:
    (v_ΣC, ρ_redC, H_V) of its mesh (None without one) and the loss of its seals [W]."""
    if i not in m.fixed_terms:
        mesh = None
        if i in m.meshes:
            g = m.meshes[i]
            mesh = (L.sum_velocity_pitch(g.n1, g.d_w1, g.alpha_tw),
                    L.reduced_radius_pitch(g.d_w1, g.d_w2, g.alpha_tw, g.beta_b),
                    L.tooth_loss_factor(g.u, g.z1, g.beta_b, g.eps_alpha, g.eps_1))
        seals = sum(L.seal_power_loss(s.d, s.n) for s in m.seals if s.stage == i)
        m.fixed_terms[i] = (mesh, seals)
    return m.fixed_terms[i]


@dataclass(frozen=True)
class StageLoss:
    P_in: float
    mesh: float
    churning: float
    bearings: float
    seals: float
    other: float
    mu: float | None = None
    H_V: float | None = None

    @property
    def total(self) -> float:
        return self.mesh + self.churning + self.bearings + self.seals + self.other

    @property
    def eta(self) -> float:
        return 1.0 - self.total / self.P_in if self.P_in > 0 else 1.0


def stage_losses(m: Model, t: float, scale: float = 1.0) -> list[StageLoss]:
    """The losses [W] of every stage at the oil temperature t [°C], with every transmitted
    load (torques and bearing loads) times ``scale``."""
    point = ("at", t, scale)
    if point in m.fixed_terms:
        return m.fixed_terms[point]
    oil = m.oil
    nu, rho = oil.nu(t), oil.rho(t)
    eta = nu * rho / 1000.0                 # Oil.eta
    out = []
    for i in range(m.n_stages):
        P = m.P_in[i] * scale
        mesh = other = 0.0
        mu = H = None
        terms, seals = _fixed_terms(m, i)
        if i in m.meshes:
            g = m.meshes[i]
            v, rr, H = terms
            Ra = oil.Ra if oil.Ra is not None else (g.Ra if g.Ra is not None else 0.8)
            mu = L.mean_friction_coefficient(g.F_bt * scale, g.b, v, rr, eta, Ra, oil.X_L)
            mesh = L.mesh_power_loss(P, mu, H)
        elif i in m.fixed:
            other = (1.0 - m.fixed[i]) * P
        churn = sum(L.churning_loss(rho, nu, d.n, d.R_p, d.b, m.immersion.get((i, d.member), 0.0),
                                    m.V0, d.z, d.m_n, d.alpha_n)
                    for d in m.dip if d.stage == i)
        brg = 0.0
        for k, b in enumerate(m.bearings):
            if b.stage == i:
                # L.bearing_friction_moment, its load part once per load scale
                M1 = m.fixed_terms.get(("M1", k, scale))
                if M1 is None:
                    M1 = m.fixed_terms["M1", k, scale] = L.bearing_load_moment(
                        b.kind, b.d_m, b.F_r * scale, b.F_a * scale, b.P0 * scale, b.C0, b.Y)
                brg += L.moment_power(L.bearing_no_load_moment(b.kind, b.d_m, b.n, nu) + M1,
                                      b.n)
        out.append(StageLoss(P, mesh, churn, brg, seals, other, mu, H))
    m.fixed_terms[point] = out
    return out


def total_loss(m: Model, t: float, scale: float = 1.0) -> float:
    return sum(s.total for s in stage_losses(m, t, scale))


@dataclass(frozen=True)
class Balance:
    t_oil: float
    iterations: int
    bracketed: bool          # False: the sump would exceed T_SEARCH_MAX
    P_V: float
    dissipation: TH.Dissipation
    scale_limit: float       # load scale at which the sump reaches t_max
    limit_bracketed: bool
    P_V_at_max: float        # losses at t_max and the present load
    P_Q_at_max: float        # heat flow at t_max


def balance(m: Model, hs: TH.Housing, t_air: float, t_max: float,
            limit: bool = True) -> Balance:
    """Sump temperature: P_V(ϑ) = P_Q(ϑ) solved between the ambient temperature and
    T_SEARCH_MAX by bisection (:func:`thermal.solve_bounded`); with ``limit`` the thermal
    power limit as well (:func:`with_limit`), else its fields are NaN (a pass of the
    drive needs the sump temperature only)."""
    def f(t):
        return TH.dissipation(hs, t, t_air).P_Q - total_loss(m, t)
    r = TH.solve_bounded(f, t_air, T_SEARCH_MAX)
    t = r.x
    nan = math.nan
    b = Balance(t, r.iterations, r.bracketed, total_loss(m, t), TH.dissipation(hs, t, t_air),
                nan, False, nan, nan)
    return with_limit(b, m, hs, t_air, t_max) if limit else b


def with_limit(b: Balance, m: Model, hs: TH.Housing, t_air: float, t_max: float) -> Balance:
    """The balance ``b`` with the thermal power limit: the load scale s at which
    P_V(ϑ_max, s) = P_Q(ϑ_max) (:func:`thermal.solve_increasing`), and the losses and the
    heat flow at ϑ_max."""
    PQmax = TH.dissipation(hs, t_max, t_air).P_Q
    s = TH.solve_increasing(lambda k: total_loss(m, t_max, k) - PQmax, 0.0, 1.0)
    return dataclasses.replace(b, scale_limit=s.x, limit_bracketed=s.bracketed,
                               P_V_at_max=total_loss(m, t_max), P_Q_at_max=PQmax)


def shaft_diameter(T: float) -> float:
    """Preliminary shaft diameter [mm] for a torque T [N·m] from torsion alone,
    d = (T/(0.2·[τ]))^(1/3) with [τ] = 20 MPa ([Dunaev]).

    Example: T = 400 N·m gives d = (400 000/(0.2·20))^(1/3) = 100 000^(1/3) = 46.42 mm:

    >>> round(shaft_diameter(400.0), 2)
    46.42
    """
    return (1000.0 * T / (0.2 * TAU_SHAFT)) ** (1.0 / 3.0)


def housing_box(stages: list[tuple[float, float, float]],
                b: list[float]) -> tuple[float, float, float, float]:
    """Box housing around parallel stages in line [mm]: (L, W, H, a).  ``stages``: the
    centre distance and the tip diameters of pinion and wheel of each stage, from the
    input; ``b`` their face widths.  The gap between the gears and the walls is
    a = L_g^(1/3) + 3 mm, L_g the length over the gears, and the sump below the largest
    wheel is 4·a deep ([Dunaev]): L = L_g + 2a, W = Σb + (n + 1)·a, H = d_a,max + 5a."""
    L_g = sum(s[0] for s in stages) + 0.5 * stages[0][1] + 0.5 * stages[-1][2]
    a = L_g ** (1.0 / 3.0) + 3.0
    d_max = max(max(s[1], s[2]) for s in stages)
    return L_g + 2 * a, sum(b) + (len(b) + 1) * a, d_max + 5 * a, a
