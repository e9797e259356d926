"""The ring rim solved: ``solve(inputs) -> Solution``, pure (no rows, no spec, the inputs
unchanged), from the functions of :mod:`.stress`, :mod:`.endurance`,
:mod:`geardesign.fatigue`, :mod:`.mesh`, :mod:`.mathieu`, :mod:`.resonance` and :mod:`.rim`.  :mod:`.report` turns the record into
rows and checks.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.epicycle_rim import endurance as E
from geardesign.epicycle_rim import mathieu as M
from geardesign.epicycle_rim import mesh
from geardesign.epicycle_rim import resonance as R
from geardesign.epicycle_rim import rim
from geardesign.epicycle_rim import stress as ST
from geardesign.epicycle_rim.fatigue_inputs import Fatigue, part_endurance
from geardesign.epicycle_rim.floquet import floquet_band
from geardesign.epicycle_rim.inputs import Inputs, Planets, Ring, Vehicle, sun_planet_pair
from geardesign.fatigue import gost25504 as g25
from geardesign.fatigue import probability as FP

# ----------------------------------------------------------------------------- geometry


@dataclass(frozen=True)
class PlanetGeometry:
    """Sun and planets: coaxiality, assembly and neighbouring conditions."""

    coaxiality: int                      # z_r − z_s − 2 z_p
    assembly_index: tuple[float, ...]
    assembly_step: float                 # [deg]
    nearest: tuple[float, ...]           # nearest assemblable relative angles [deg]
    a_w: float                           # sun-planet centre distance [mm]
    d_a_planet: float                    # [mm]
    spacing_min: float                   # [deg]
    spacing_limit: float                 # [deg]


@dataclass(frozen=True)
class Geometry:
    d: float
    pitch_angle: float
    angles: tuple[float, ...]
    delta_m: float
    Y_B: float                           # NaN outside δ/m > 1.75
    m_B: float
    K_B: float
    failure_mode: str
    planets: PlanetGeometry | None


def _geometry(ring: Ring, pl: Planets) -> Geometry:
    m, z, delta, h = ring.module, ring.z, ring.rim_thickness, ring.tooth_height
    angles = pl.angles
    planets = None
    if pl.z_sun is not None:
        zs = pl.z_sun
        rel = [a - angles[0] for a in angles]
        pg = sun_planet_pair(ring, pl)
        planets = PlanetGeometry(
            z - zs - 2 * pl.z_planet, tuple(mesh.assembly_index(a, zs, z) for a in rel),
            mesh.assembly_step(zs, z), tuple(mesh.nearest_assemblable(rel, zs, z)), pg.a_w,
            pg.g2.d_a, mesh.min_spacing(list(angles)), mesh.spacing_limit(pg.g2.d_a, pg.a_w))
    return Geometry(m * z, 360.0 / z, angles, delta / m, rim.rim_factor_iso_internal(delta, m),
                    rim.backup_ratio(delta, h), rim.rim_factor_agma(rim.backup_ratio(delta, h)),
                    rim.failure_mode(delta, h), planets)


# ----------------------------------------------------------------------------- fatigue


@dataclass(frozen=True)
class Case:
    """One fillet in one stage: its cycle, equivalent amplitude, safety and probability."""

    cycle: ST.Cycle
    sigma_eq: float          # NaN outside the diagram
    n: float
    P: float                 # probability of non-failure (0…1)


@dataclass(frozen=True)
class Advice:
    """What reaches the required probability, other inputs held: the hardening factor and
    the fillet radius (None: not reachable by it)."""

    K_V: float | None
    rho: float | None


@dataclass(frozen=True)
class FatigueResult:
    part: E.PartEndurance
    psi: float
    psi_D: float
    stresses: ST.RimStresses
    cases: tuple[Case, ...]
    worst_domain: ST.Cycle               # largest |σ_m| + σ_a
    worst_max: ST.Cycle                  # largest σ_max
    governing: ST.Cycle                  # largest σ_-1eq
    sigma_eq_max: float
    by_model: tuple[tuple[str, float], ...]   # the governing σ_-1eq by each diagram
    probabilities: tuple[float, ...]     # 0…1
    z_P: tuple[float, ...]
    sigma_m1D_P: tuple[float, ...]
    P: float                             # governing case
    P_required: float
    m_slope: float
    lg_N_P: tuple[float, ...]
    cycles_per_km: float | None
    life_km: tuple[tuple[str, tuple[float, ...]], ...]
    advice: Advice | None                # when the rim fails
    s_lgn: float | None                  # S_lgN at the governing case when lg N_P < 0
    lg_N_min: float | None


def _lg_life(pe: E.PartEndurance, m_slope: float, f: Fatigue, eq: float, P: float) -> float:
    o = f.options
    if eq != eq:
        return math.nan
    return FP.lg_life(eq, pe.sigma_m1D, pe.v, P, m_slope, o.knee_cycles, o.slgn_alpha,
                     o.slgn_beta)


def _advice(ring: Ring, f: Fatigue, pe: E.PartEndurance, sigma_eq: float, P_req: float
            ) -> Advice:
    """The fillet hardening factor and radius that reach the required probability."""
    u = FP.normal_quantile(P_req)
    v, va = pe.v, f.options.stress_scatter
    denom = 1.0 - u * u * v * v
    kv = rho = None
    if denom > 0.0:
        n_req = (1.0 + math.sqrt(1.0 - denom * (1.0 - u * u * va * va))) / denom
        kv = f.fillet.hardening_factor * n_req * sigma_eq / pe.sigma_m1D
    if f.options.stress_concentration is None and f.options.stress_gradient is None:
        def prob(r: float) -> float:
            p = part_endurance(ring, f, r)
            return FP.probability_of_non_failure(sigma_eq, p.sigma_m1D, p.v, va)

        lo, hi = f.fillet.radius, 0.5 * f.fillet.root_chord * 0.999
        if prob(hi) >= P_req:
            for _ in range(50):
                mid = 0.5 * (lo + hi)
                if prob(mid) >= P_req:
                    hi = mid
                else:
                    lo = mid
            rho = hi
    return Advice(kv, rho)


def _life_km(f: Fatigue, cases: tuple[Case, ...], probs, per_km: float, lgN) -> tuple:
    out = []
    for fillet in ST.FILLETS:
        lives = []
        for P in probs:
            dmg = 0.0
            for c in cases:
                if c.cycle.fillet != fillet:
                    continue
                share = next(s.share for s in f.stages if s.name == c.cycle.stage)
                x = lgN(c.sigma_eq, P)
                if x != x:
                    dmg = math.nan
                elif math.isfinite(x):
                    # lg N_P < -300: no cycle at all (10**x underflows); the scatter check
                    # says which coefficients put the model there
                    dmg += share * per_km * 10.0 ** -x if x > -300.0 else math.inf
            lives.append(math.inf if dmg == 0.0 else (math.nan if dmg != dmg else 1.0 / dmg))
        out.append((fillet, tuple(lives)))
    return tuple(out)


def _fatigue(ring: Ring, count: int, f: Fatigue, vehicle: Vehicle | None) -> FatigueResult:
    mat, ld, o = f.material, f.load, f.options
    pe = part_endurance(ring, f)
    psi = g25.mean_stress_sensitivity(mat.sigma_u)[0]
    psi_D = psi / pe.K
    rs = ST.rim_stresses(ld.sigma_Fn, ld.hoop_loaded, ld.hoop_between)
    va = o.stress_scatter
    cases = []
    for s in f.stages:
        for c in ST.fillet_cycles(rs, ld.load_sharing, s.name, s.mu_F, s.tension_fillet):
            eq = ST.equivalent_amplitude(c.s_a, c.s_m, mat.sigma_u, o.mean_stress_model, psi_D)
            n = pe.sigma_m1D / eq if not math.isnan(eq) else math.nan
            P = FP.probability_of_non_failure(eq, pe.sigma_m1D, pe.v, va) if n == n else math.nan
            cases.append(Case(c, eq, n, P))
    cases = tuple(cases)
    valid = [c for c in cases if not math.isnan(c.sigma_eq)]
    worst_dom = max(cases, key=lambda c: abs(c.cycle.s_m) + c.cycle.s_a).cycle
    worst_max = max(cases, key=lambda c: c.cycle.s_max).cycle
    if valid:
        g = max(valid, key=lambda c: c.sigma_eq)
        gov, gov_eq = g.cycle, g.sigma_eq
    else:
        gov, gov_eq = worst_dom, math.nan
    by_model = tuple((alt, ST.equivalent_amplitude(gov.s_a, gov.s_m, mat.sigma_u, alt, psi_D))
                     for alt in ST.MEAN_STRESS_MODELS)
    probs = tuple(p / 100.0 for p in o.probabilities)
    P_gov = (FP.probability_of_non_failure(gov_eq, pe.sigma_m1D, pe.v, va)
             if gov_eq == gov_eq else math.nan)
    m_slope = FP.sn_slope(mat.sigma_u, pe.K)

    def lgN(eq: float, P: float) -> float:
        return _lg_life(pe, m_slope, f, eq, P)

    lg_gov = tuple(lgN(gov_eq, P) for P in probs)
    per_km = lives = None
    if vehicle is not None and all(s.share is not None for s in f.stages):
        per_km = count * vehicle.carrier_ratio * 1e6 / (2.0 * math.pi * vehicle.wheel_radius)
        lives = _life_km(f, cases, probs, per_km, lgN)
    P_req = o.required_probability / 100.0
    advice = None
    if gov_eq == gov_eq and (P_gov < P_req or gov_eq > pe.sigma_m1D):
        advice = _advice(ring, f, pe, gov_eq, P_req)
    below = [x for x in lg_gov if x < 0.0]
    s_lgn = None
    if below:
        sb = gov_eq / pe.sigma_m1D
        s_lgn = 10.0 ** min(o.slgn_alpha + o.slgn_beta * math.log10(sb), 300.0)
    return FatigueResult(
        pe, psi, psi_D, rs, cases, worst_dom, worst_max, gov, gov_eq, by_model, probs,
        tuple(FP.normal_quantile(P) for P in probs),
        tuple(FP.quantile_endurance(pe.sigma_m1D, pe.v, P) for P in probs), P_gov, P_req,
        m_slope, lg_gov, per_km, lives or (), advice, s_lgn, min(below) if below else None)


# ----------------------------------------------------------------------------- resonance


@dataclass(frozen=True)
class Order:
    """Resonance of one order: frequencies per natural frequency k0, speeds with a
    vehicle."""

    band: R.OrderBand
    omega: tuple[float, ...]             # Ω [Hz]
    f_mesh: tuple[float, ...]            # f_m [Hz]
    V: tuple[float, ...] | None          # [km/h]
    V_band: tuple[tuple[float, float], ...] | None


@dataclass(frozen=True)
class ResonanceResult:
    phases: tuple[float, ...]
    pulsation: mesh.Pulsation
    excitation: R.Excitation
    bands: tuple[M.Band, ...]            # exact, per order of the inputs
    series: tuple[M.Band | None, ...]    # paper B's series (orders 1 to 3)
    linear: M.Band | None
    orders: tuple[Order, ...]            # per order band used (stiffness model)
    hits: tuple[str, ...]                # bands inside the operating speed range
    chart_b_max: float
    chart: tuple[tuple[str, tuple[float, ...]], ...]
    floquet: tuple[tuple[float, float] | None, ...] | None
    floquet_dev: float | None
    actual: R.Excitation | None          # excitation of the actual phases (paper model)


def _orders(used, exc: R.Excitation, z: int, k0s, vehicle: Vehicle | None):
    out, hits = [], []
    for ob in used:
        n = ob.order
        omega = tuple(R.resonance_frequency(k, n) for k in k0s)
        f_m = tuple(o / exc.h for o in omega)
        V = Vb = None
        if vehicle is not None:
            V = tuple(R.speed_from_mesh_frequency(x, z, vehicle.wheel_radius,
                                                  vehicle.carrier_ratio) for x in f_m)
            if ob.mesh_lo is not None:
                Vb = tuple((R.speed_from_mesh_frequency(ob.mesh_lo * k, z, vehicle.wheel_radius,
                                                        vehicle.carrier_ratio),
                            R.speed_from_mesh_frequency(ob.mesh_hi * k, z, vehicle.wheel_radius,
                                                        vehicle.carrier_ratio)) for k in k0s)
                rng = vehicle.speed_range
                if rng is not None:
                    for k, (lo, hi) in zip(k0s, Vb):
                        if hi > lo and R.overlaps(lo, hi, rng[0], rng[1]):
                            hits.append(f"n = {n}, k0 = {k:g} Hz at {lo:.1f}…{hi:.1f} km/h")
        out.append(Order(ob, omega, f_m, V, Vb))
    return tuple(out), tuple(hits)


def _resonance(inp: Inputs) -> ResonanceResult:
    rz, pl, z = inp.resonance, inp.planets, inp.ring.z
    eps = pl.contact_ratio
    phases = mesh.mesh_phases(list(pl.angles), z, rz.phase_model)
    p = mesh.pulsation(phases, eps, rz.harmonics)
    exc = R.excitation(p, rz.depth)
    orders = list(rz.orders)
    bands = tuple(M.band_exact(n, exc.mu) for n in orders)
    b_max = rz.chart_b_max
    if b_max is None:
        b_max = max(0.5, 1.25 * 0.5 * exc.mu * max(b.a_hi for b in bands))
    series = tuple(M.band_series(n, exc.mu) if n in M.SERIES_ORDERS else None for n in orders)
    used = R.order_bands(p, exc, orders, rz.stiffness_model)
    per_order, hits = _orders(used, exc, z, rz.natural_frequencies, inp.vehicle)
    chart = M.stability_chart(max(orders), b_max, rz.chart_points)
    floquet = dev = None
    if rz.floquet_check:
        floquet = tuple(floquet_band(n, exc.mu, b) for n, b in zip(orders, bands))
        dev = max((max(abs(fb[0] - b.a_lo), abs(fb[1] - b.a_hi))
                   for fb, b in zip(floquet, bands) if fb is not None), default=0.0)
    actual = None
    if rz.phase_model == "paper":
        pa = mesh.pulsation(mesh.mesh_phases(list(pl.angles), z, "actual"), eps, rz.harmonics)
        actual = R.excitation(pa, rz.depth)
    return ResonanceResult(
        tuple(phases), p, exc, bands, series, M.band_linear(exc.mu) if 1 in orders else None,
        per_order, hits, b_max, tuple((k, tuple(v)) for k, v in chart.items()),
        None if floquet is None else tuple(None if fb is None else tuple(fb) for fb in floquet),
        dev, actual)


# ----------------------------------------------------------------------------- entry


@dataclass(frozen=True)
class Solution:
    """The ring rim solved: geometry, and the fatigue and resonance analyses asked for."""

    geometry: Geometry
    fatigue: FatigueResult | None
    resonance: ResonanceResult | None


def solve(inp: Inputs) -> Solution:
    """Solve the rim for typed inputs (:func:`geardesign.epicycle_rim.inputs.read`)."""
    fat = (_fatigue(inp.ring, inp.planets.count, inp.fatigue, inp.vehicle)
           if inp.fatigue is not None else None)
    res = _resonance(inp) if inp.resonance is not None else None
    return Solution(_geometry(inp.ring, inp.planets), fat, res)
