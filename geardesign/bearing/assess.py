"""One bearing under one load case or spectrum: equivalent load, basic and adjusted life,
static safety.  Pure: plain dataclasses in, a dataclass out (no spec, no report)."""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.bearing import life as L
from geardesign.bearing import load_factors as LF
from geardesign.bearing import a_iso as AI
from geardesign.bearing import tables as T
from geardesign.core.records import dataclass


@dataclass(frozen=True)
class Bearing:
    kind: str
    rows: int = 1
    alpha: float | None = None          # contact angle, deg
    e: float | None = None              # catalogue e (α from e = 1.5·tan α)
    Y: float | None = None              # catalogue Y for F_a/F_r > e
    C_r: float = 0.0                    # N (C_a for thrust bearings)
    C_0r: float | None = None           # N (C_0a for thrust bearings)
    C_u: float | None = None            # N, fatigue load limit
    C_u_estimated: bool = False
    f0: float | None = None
    D_pw: float | None = None           # mm
    designation: str = ""
    Y1: float | None = None             # catalogue Y for F_a/F_r <= e (double row, spherical)
    Y0: float | None = None             # catalogue static axial factor


@dataclass(frozen=True)
class Block:
    F_r: float
    F_a: float
    n: float
    share: float = 1.0


@dataclass(frozen=True)
class Conditions:
    method: str                         # "gost18855_94" | "iso281_2007"
    reliability: float = 90.0
    V: float = 1.0
    K_b: float = 1.0
    K_t: float = 1.0
    a23: float | None = None            # GOST method
    viscosity: float | None = None      # mm²/s at operating temperature (ISO a_ISO)
    nu1: float | None = None            # given rated viscosity, mm²/s (replaces ISO 281 ν1)
    kappa: float | None = None          # given viscosity ratio κ
    oil: dict | None = None             # oil data for the report (grade, ν40, ν100, VI, t)
    e_C: float | None = None
    ep_additives: bool = False
    K_E: float | None = None            # typical load regime
    life_required: float | None = None  # h
    s0_min: float = T.S0_MIN_DEFAULT
    F_r0: float | None = None           # peak static loads, N
    F_a0: float | None = None
    system_lives: tuple = ()            # h, other bearings of the system
    weibull_slope: float | None = None

    @property
    def lubricated(self) -> bool:
        """a_ISO is applied (a viscosity or κ is known)."""
        return self.viscosity is not None or self.kappa is not None


@dataclass
class BlockResult:
    block: Block
    factors: LF.LoadFactors
    P: float
    L10h: float
    nu1: float | None = None
    kappa: float | None = None
    a_iso: AI.AIso | None = None
    life_h: float = math.nan            # adjusted life at this block


@dataclass
class Assessment:
    bearing: Bearing
    cond: Conditions
    p: float
    blocks: list
    P: float                            # equivalent (mean) load used for L10, N
    P_before_KE: float
    n: float                            # (mean) speed, min⁻¹
    L10: float                          # 10⁶ rev
    L10h: float
    a1: float
    a23: float | None
    life_h: float                       # adjusted life L_sah (GOST) / L_nmh (ISO), h
    life_name: str
    a_eff: float                        # life_h / L10h
    C_req: float | None = None
    margin: float | None = None
    spectrum: L.SpectrumResult | None = None
    static: LF.StaticLoad | None = None
    s0: float | None = None
    system_life: float | None = None
    slope: float | None = None
    notes: list = field(default_factory=list)

    @property
    def passes(self) -> bool:
        ok_life = self.cond.life_required is None or self.life_h >= self.cond.life_required
        ok_static = self.s0 is None or self.s0 >= self.cond.s0_min
        return ok_life and ok_static


def assess(b: Bearing, blocks: list, c: Conditions) -> Assessment:
    """Equivalent load, L10, adjusted life (a1·a23 or a1·a_ISO), required rating, static
    safety and system life of one bearing (formulas in :mod:`.life`)."""
    thrust = b.kind in T.THRUST_TYPES
    gost = c.method == "gost18855_94"
    p = L.life_exponent(b.kind)
    V = c.V if gost else 1.0
    results = []
    for blk in blocks:
        lf = LF.load_factors(b.kind, blk.F_r, blk.F_a, rows=b.rows, alpha_deg=b.alpha, V=V,
                            C_0r=b.C_0r, f0=b.f0, e_given=b.e, Y_given=b.Y, Y1_given=b.Y1)
        P = LF.equivalent_load(blk.F_r, blk.F_a, lf, V, c.K_b, c.K_t, thrust)
        if P <= 0.0:
            raise L.BearingError("load.F_r", "the equivalent load is zero: give a radial or "
                                             "axial load")
        results.append(BlockResult(blk, lf, P, L.hours(L.basic_life(b.C_r, P, p), blk.n)))

    spectrum = None
    if len(blocks) == 1:
        P0, n = results[0].P, blocks[0].n
    else:
        spectrum = L.spectrum_mean([r.P for r in results], [r.block.n for r in results],
                                   [r.block.share for r in results], p)
        P0, n = spectrum.P_m, spectrum.n_m
    P = P0 * c.K_E if c.K_E is not None else P0
    L10 = L.basic_life(b.C_r, P, p)
    L10h = L.hours(L10, n)
    a1 = L.a1_factor(c.reliability, c.method)

    a23 = None
    if gost:
        a23 = c.a23 if c.a23 is not None else 1.0
        life_h = a1 * a23 * L10h
        name = "L_sah"
        for r in results:
            r.life_h = a1 * a23 * r.L10h
    elif c.lubricated:
        k_e = c.K_E if c.K_E is not None else 1.0
        for r in results:
            P_r = r.P * k_e
            if c.kappa is not None:
                r.kappa = c.kappa
                r.nu1 = c.viscosity / c.kappa if c.viscosity is not None else None
            else:
                r.nu1 = c.nu1 if c.nu1 is not None else AI.nu1(r.block.n, b.D_pw)
                r.kappa = c.viscosity / r.nu1
            r.a_iso = AI.a_iso(b.kind, r.kappa, c.e_C, b.C_u, P_r, c.ep_additives)
            r.life_h = a1 * r.a_iso.value * L.hours(L.basic_life(b.C_r, P_r, p), r.block.n)
        life_h = results[0].life_h if len(results) == 1 else L.miner_hours(
            [r.life_h for r in results], [r.block.share for r in results])
        name = "L_nmh"
    else:
        life_h = a1 * L10h
        name = "L_nmh"
        for r in results:
            r.life_h = a1 * r.L10h
    if not all(math.isfinite(x) and x > 0.0 for x in (L10, L10h, life_h)):
        raise L.BearingError("load", f"the life is not a finite positive number (P = {P:.3g} N "
                                     f"against C_r = {b.C_r:.3g} N): the load is too small for "
                                     f"a rating life; give the real loads")
    a_eff = life_h / L10h

    out = Assessment(b, c, p, results, P, P0, n, L10, L10h, a1, a23, life_h, name, a_eff)
    if spectrum is not None:
        out.spectrum = spectrum
    if c.life_required is not None:
        out.C_req = L.required_rating(P, c.life_required, n, p, a_eff)
        out.margin = life_h / c.life_required
    if b.C_0r is not None:
        F_r0 = c.F_r0 if c.F_r0 is not None else max(x.F_r for x in blocks) * c.K_b
        F_a0 = c.F_a0 if c.F_a0 is not None else max(x.F_a for x in blocks) * c.K_b
        out.static = LF.static_load(b.kind, F_r0, F_a0, rows=b.rows, alpha_deg=b.alpha,
                                   e_given=b.e, Y0_given=b.Y0)
        out.s0 = b.C_0r / out.static.P0 if out.static.P0 > 0 else math.inf
    if c.system_lives:
        out.slope = c.weibull_slope or T.WEIBULL_SLOPE["ball" if L.is_ball(b.kind) else "roller"]
        out.system_life = L.system_life([life_h, *c.system_lives], out.slope)
    return out
