"""Checks of a planetary train, each with what to change.

Limits: ε_α ≥ 1 (error), < 1.2 (warning); undercut x ≥ x_min; tip thickness > 0 (error),
≥ limits.tip_thickness·m (warning); involute interference (error) at both roots of every
mesh; tip interference of the internal meshes δ ≥ 0 (error); radial clearance ≥ 0
(error), ≥ 0.1 m (warning); |ϑ| ≤ limits.specific_sliding at the roots (warning);
coaxiality |Δa_w| ≤ limits.coaxiality·m (error); neighbouring planets: gap > 0 (error),
≥ limits.neighbour_gap·m (warning); equal spacing (error unless train.spacing =
"uneven"); forward drive possible (error); self-locking per efficiency.self_locking.
The limits that the spur checks use are imported from there.
"""

from __future__ import annotations

import math

from geardesign.core.result import Check, check
from geardesign.planetary import sources as S
from geardesign.planetary.geometry import Mesh
from geardesign.spur.checks import (
    CLEARANCE_WARN,
    EPS_MIN,
    EPS_WARN,
    InternalNames,
    interference_check,
    internal_mesh_checks,
    round_up,
)

NAMES = {"sun": "sun", "planet": "planet", "planet2": "second planet crown", "ring": "ring",
         "ring2": "second ring"}
SHIFT_REASONABLE = 3.0   # |x| beyond which a shift is no remedy (the spec's range)
MESH_NAMES = {"sun_planet": "sun–planet", "planet_ring": "planet–ring",
              "planet2_ring": "planet2–ring", "planet_ring2": "planet–ring2",
              "planet2_ring2": "planet2–ring2"}


def gear_checks(gears: dict, rack_h_straight: float, alpha_t: dict, beta: float,
                modules: dict, tip_min: float, allow_undercut: bool) -> list[Check]:
    """Undercut of the external gears, pointed and thin tips of every gear.

    ``gears``: member -> GearGeometry; ``alpha_t``/``modules``: member -> value."""
    out = []
    for member, g in gears.items():
        n, suf = NAMES[member], member.upper()
        m = modules[member]
        if member in ("sun", "planet", "planet2"):
            z_needed = math.ceil(2.0 * math.cos(beta) * (rack_h_straight - g.x)
                                 / math.sin(alpha_t[member]) ** 2 - 1e-9)
            out.append(check(
                f"UNDERCUT_{suf}", g.x >= g.x_min - 1e-9,
                "warning" if allow_undercut else "error",
                f"{n} undercut: x = {g.x:.4f} < x_min = {g.x_min:.4f}; increase shift.{member} "
                f"to at least {round_up(g.x_min)} (or use teeth.{member} >= {z_needed}), or set "
                f"train.allow_undercut = true if it is deliberate",
                f"{n} not undercut (x = {g.x:.4f} >= x_min = {g.x_min:.4f})", g.x, g.x_min,
                S.G16532))
        external = member in ("sun", "planet", "planet2")
        advice = (f"reduce shift.{member} or the addendum coefficient" if external else
                  f"reduce the GOST-sign shift of the {n} (a larger one thins its teeth; with the "
                  f"ISO sign increase it) or shorten its tips (ring.tip_shortening)")
        out.append(check(
            f"POINTED_TIP_{suf}", g.s_an > 0.0, "error",
            f"{n} tooth is pointed (s_an = {g.s_an:.3f} mm <= 0); {advice}",
            f"{n} tip not pointed (s_an = {g.s_an:.3f} mm)", g.s_an, 0.0,
            S.G16532 if external else S.G19274))
        if g.s_an > 0.0:
            out.append(check(
                f"TIP_THICKNESS_{suf}", g.s_an >= tip_min * m - 1e-12, "warning",
                f"{n} tip is thin: s_an = {g.s_an:.3f} mm = {g.s_an / m:.2f}·m < {tip_min:g}·m; "
                + advice,
                f"{n} tip thickness s_an = {g.s_an / m:.2f}·m >= {tip_min:g}·m", g.s_an,
                tip_min * m, S.MATUSEVICH + " (35), (36)"))
    return out


def mesh_checks(meshes: list[Mesh], sliding_max: float) -> list[Check]:
    """Contact ratio, interference, clearance and sliding of every mesh."""
    out = []
    for mesh in meshes:
        g, sp = mesh.geom, mesh.spec
        code, mn = mesh.name.upper(), MESH_NAMES.get(mesh.name, mesh.name)
        p1, p2 = sp.pinion, sp.wheel
        m = g.inp.m_n
        helical = g.inp.beta > 0.0
        eps, sym = (g.eps_gamma, "ε_γ") if helical else (g.eps_alpha, "ε_α")
        out.append(check(
            f"{code}_CONTACT_RATIO", eps >= EPS_MIN, "error",
            f"{sym} = {eps:.3f} < 1 in the {mn} mesh: the mesh is not continuous; increase the "
            f"tooth numbers, lower the working pressure angle (smaller shifts) or use helical "
            f"teeth", f"{mn}: {sym} = {eps:.3f} >= 1", eps, EPS_MIN,
            S.G19274 if sp.internal else S.G16532))
        if eps >= EPS_MIN:
            out.append(check(
                f"{code}_CONTACT_RATIO_LOW", eps >= EPS_WARN, "warning",
                f"{mn}: {sym} = {eps:.3f} < {EPS_WARN}: little overlap of tooth pairs; increase "
                f"the tooth numbers or lower the working pressure angle",
                f"{mn}: {sym} = {eps:.3f} >= {EPS_WARN}", eps, EPS_WARN, S.PRACTICE))
        g1, g2 = g.g1, g.g2
        if not sp.internal:
            for gear, own, mate in ((g1, p1, p2), (g2, p2, p1)):
                out.append(interference_check(
                    f"{code}_INTERFERENCE_{own.upper()}", gear, NAMES[own], NAMES[mate], "",
                    f"increase shift.{own} or teeth.{own}, or reduce shift.{mate}",
                    f"increase shift.{own} or reduce shift.{mate}", prefix=f"{mn}: "))
        else:
            out.extend(_internal_checks(g, code, mn, p1, p2))
        c = min(g.c_12, g.c_21)
        out.append(check(
            f"{code}_ROOT_CLEARANCE", c >= -1e-9, "error",
            f"{mn}: radial clearance {c:.3f} mm < 0: a tip touches the mating root; reduce the "
            f"addendum or the shifts" + (", or shorten the ring tip (ring.tip_shortening)"
                                         if sp.internal else ""),
            f"{mn}: radial clearance {c:.3f} mm >= 0", c, 0.0,
            S.G19274 if sp.internal else S.G16532))
        if c >= -1e-9:
            out.append(check(
                f"{code}_ROOT_CLEARANCE_SMALL", c >= CLEARANCE_WARN * m - 1e-9, "warning",
                f"{mn}: radial clearance {c:.3f} mm < {CLEARANCE_WARN}·m: little room for "
                f"lubricant and tolerances; increase the clearance coefficient c*",
                f"{mn}: radial clearance {c:.3f} mm >= {CLEARANCE_WARN}·m", c,
                CLEARANCE_WARN * m, S.PRACTICE))
        sl = mesh.sliding
        worst = max(abs(sl.theta1_A), abs(sl.theta2_E))
        if math.isfinite(worst):
            out.append(check(
                f"{code}_SPECIFIC_SLIDING", worst <= sliding_max, "warning",
                f"{mn}: specific sliding at the roots is high (ϑ_{p1} = {sl.theta1_A:.2f}, "
                f"ϑ_{p2} = {sl.theta2_E:.2f}; limit ±{sliding_max:g}): wear and scuffing risk; "
                f"increase shift.{p1} (and reduce shift.{p2}) to balance them",
                f"{mn}: specific sliding at the roots within ±{sliding_max:g} (ϑ_{p1} = "
                f"{sl.theta1_A:.2f}, ϑ_{p2} = {sl.theta2_E:.2f})", worst, sliding_max,
                S.QUALITY))
    return out


def _internal_checks(g, code: str, mn: str, planet: str, ring: str) -> list[Check]:
    """Involute interference at both roots, tip interference, cutting interference: the
    spur package's :func:`geardesign.spur.checks.internal_mesh_checks`, naming the
    members and the spec keys of the train."""
    names = InternalNames(NAMES[planet], NAMES[ring], f"shift.{planet}", f"shift.{ring}",
                          f"teeth.{planet}", f"teeth.{ring}", "ring tip (ring.tip_shortening",
                          mn, (planet.upper(), ring.upper()))
    return internal_mesh_checks(g, f"{code}_", names, S.G19274, S.G19274_MEMORY)


def coaxiality_checks(meshes: list[Mesh], tol: float, needed: dict, sign_note: dict
                      ) -> list[Check]:
    """|a_w,i − a_w,sun–planet| ≤ tol for every internal mesh.  ``needed``: ring member ->
    the shift (user's sign) that would make it coaxial; ``sign_note``: ring -> wording."""
    out = []
    a_ref = meshes[0].geom.a_w
    for mesh in meshes[1:]:
        d = mesh.geom.a_w - a_ref
        ring = mesh.spec.wheel
        mn = MESH_NAMES.get(mesh.name, mesh.name)
        x = needed[ring]
        fix = (f"set shift.{ring} = {x:.4f} ({sign_note[ring]}) or give train.center_distance "
               f"and let the shifts follow" if math.isfinite(x) and abs(x) <= SHIFT_REASONABLE
               else "no reasonable ring shift makes them coaxial; change the tooth numbers "
                    "(with equal modules the ring needs about z_sun + 2·z_planet teeth)")
        out.append(check(
            f"{mesh.name.upper()}_COAXIALITY", abs(d) <= tol, "error",
            f"the {mn} mesh runs at a_w = {mesh.geom.a_w:.4f} mm, the sun–planet mesh at "
            f"{a_ref:.4f} mm (Δ = {d:+.4f} mm): the gears are not coaxial; {fix}",
            f"{mn}: coaxial with the sun–planet mesh (Δa_w = {d:+.5f} mm)", abs(d), tol,
            S.COAX))
    return out


def neighbour_checks(clearance: float, gap: float, m: float, n_max: int, planets: int
                     ) -> list[Check]:
    """NEIGHBOUR (the tips of neighbouring planets clear) and NEIGHBOUR_GAP (by the gap
    Kudryavtsev recommends); a single planet has no neighbour and passes both."""
    if planets == 1:
        return [check("NEIGHBOUR", True, "error", "", "one planet: no neighbouring planet",
                      None, None, S.KUDRYAVTSEV)]
    out = [check(
        "NEIGHBOUR", clearance > 0.0, "error",
        f"the tips of neighbouring planets overlap (clearance {clearance:.3f} mm <= 0): use at "
        f"most {n_max} planets, or a larger centre distance (more sun teeth) with smaller planets",
        f"neighbouring planets clear each other (clearance {clearance:.3f} mm)", clearance, 0.0,
        S.KUDRYAVTSEV)]
    if clearance > 0.0:
        out.append(check(
            "NEIGHBOUR_GAP", clearance >= gap * m - 1e-12, "warning",
            f"the gap between neighbouring planets is small: {clearance:.3f} mm < {gap:g}·m; use "
            f"fewer planets (at most {n_max} with this gap) or a larger centre distance",
            f"gap between neighbouring planets {clearance:.3f} mm >= {gap:g}·m", clearance,
            gap * m, S.KUDRYAVTSEV))
    return out


def assembly_check(train, sp, uneven: bool, advice: str) -> Check:
    k = train.planets
    parts = ", ".join(f"N_{x} = {n}" for x, n in sp.N.items())
    if sp.equal_ok:
        return check("ASSEMBLY", True, "error", "",
                     f"{k} planets can be assembled equally spaced ({parts}, each a multiple of "
                     f"{k})", None, None, S.ASSEMBLY)
    angles = ", ".join(f"{a:.2f}" for a in sp.angles)
    if uneven:
        return check("ASSEMBLY", True, "info", "",
                     f"equal spacing is impossible ({parts} not all multiples of {k}); the "
                     f"planets are placed at the admissible angles {angles} deg", None, None,
                     S.ASSEMBLY)
    return check(
        "ASSEMBLY", False, "error",
        f"{k} equally spaced planets cannot be assembled ({parts}: each must be a multiple of "
        f"{k}); {advice}, or set train.spacing = \"uneven\" to place them at {angles} deg",
        "", None, None, S.ASSEMBLY)


def efficiency_checks(forward_ok: bool, eta_f: float, reverse_ok: bool | None,
                      eta_r: float | None, mode: str, near: float) -> list[Check]:
    out = [check(
        "FORWARD_DRIVE", forward_ok and eta_f > 0.0, "error",
        f"the input cannot drive the output (efficiency {eta_f:.3f}): the train is self-locking "
        f"in the working direction; lower the friction (efficiency.friction), use a train with a "
        f"lower ratio per stage, or drive from the other member",
        f"the input drives the output (efficiency {eta_f:.4f})", eta_f, 0.0, S.TORQUE)]
    if reverse_ok is None:
        return out
    locked = not reverse_ok or eta_r <= 0.0
    r = "" if eta_r is None or not math.isfinite(eta_r) else f" (formal value {eta_r:.3f})"
    if mode == "require":
        out.append(check(
            "SELF_LOCKING", locked, "error",
            f"the train is not self-locking: the output can drive the input back with efficiency "
            f"{eta_r:.3f}; to hold the load, raise the ratio of a 3K train or the mesh friction, "
            f"or add a brake",
            f"self-locking: the output cannot drive the input{r}", eta_r, 0.0, S.TORQUE))
    else:
        out.append(check(
            "SELF_LOCKING", not locked, "error" if mode == "forbid" else "warning",
            f"the train is self-locking: the output cannot drive the input back{r}; the drive "
            f"cannot be back-driven (a hoist may want that: efficiency.self_locking = "
            f"\"require\"); to avoid it lower the ratio or the mesh friction",
            f"not self-locking (reverse efficiency {eta_r:.4f})", eta_r, 0.0, S.TORQUE))
        if not locked:
            out.append(check(
                "NEAR_SELF_LOCKING", eta_r >= near, "warning",
                f"the reverse efficiency {eta_r:.3f} is below {near:g}: close to self-locking; "
                f"small changes of friction may lock the train",
                f"reverse efficiency {eta_r:.3f} >= {near:g}", eta_r, near, S.TORQUE))
    return out
