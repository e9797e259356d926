"""The report of a drive's losses and heat balance (:mod:`.lubrication`): the thermal
section, the table of the losses per stage, the THERMAL check with its advice (cooler,
area, fan) and the oil temperature each stage was rated at for scuffing."""

from __future__ import annotations

from geardesign.core.result import DataTable, Result, check
from geardesign.drive import heat as HEAT
from geardesign.drive import thermal as TH
from geardesign.drive.lubrication import (SCUFFING_T_MAX, SRC_HEAT, SRC_MESH, Thermal,
                                          _scuffing_tables)


def report(res: Result, t: Thermal, stages) -> None:
    b, m, hs = t.balance, t.model, t.housing
    D = b.dissipation
    sec = res.section("thermal", "Losses and heat balance")
    sec.add("oil", t.oil_info["grade"], None, "", "oil, ISO VG grade", t.oil_info["source"])
    sec.add("nu40", m.oil.nu40, "mm^2/s", "ν40", "viscosity at 40 °C", t.oil_info["source"])
    sec.add("VI", m.oil.VI, "-", "VI", "viscosity index", "ASTM D2270 / ISO 2909")
    sec.add("X_L", m.oil.X_L, "-", "X_L", "lubricant factor of the mesh friction", SRC_MESH)
    sec.add("t_oil", b.t_oil, "°C", "ϑ_oil", "oil sump temperature (heat balance)", SRC_HEAT)
    sec.add("nu_oil", m.oil.nu(b.t_oil), "mm^2/s", "ν", "oil viscosity at the sump temperature",
            "ASTM D341")
    sec.add("eta_oil", m.oil.eta(b.t_oil), "mPa·s", "η_oil", "dynamic viscosity at the sump "
            "temperature", "ASTM D341")
    sec.add("P_V", b.P_V, "W", "P_V", "total power loss at the sump temperature", "losses")
    sec.add("P_Q", D.P_Q, "W", "P_Q", "heat given off at the sump temperature", SRC_HEAT)
    sec.add("A", hs.area, "m^2", "A", "cooling area of the housing" + (
        "" if t.box.get("area_given") else " (box without its base)" if not
        (res.inputs.get("thermal") or {}).get("base_cooled") else " (box)"),
        "given" if t.box.get("area_given") else "thermal dimensions")
    for k, name in (("L", "housing length"), ("W", "housing width"), ("H", "housing height")):
        sec.add(f"housing_{k}", t.box[k], "mm", k, name + (" (estimated)" if t.box.get(
            "estimated") else ""), "[Dunaev] wall gap L_g^(1/3) + 3 mm" if t.box.get(
            "estimated") else "given")
    if "immersion" in t.box:
        sec.add("immersion", t.box["immersion"], "mm", "h", "immersion of the largest wheel",
                "lubrication")
    for k, name in (("in", "input"), ("out", "output")):
        sec.add(f"d_seal_{k}", t.box[f"d_seal_{k}"], "mm", f"d_s,{k}", f"shaft diameter at the "
                f"{name} lip seal", t.seal_source)
    sec.add("V0", m.V0, "l", "V_0", "oil volume", "given" if res.inputs[
        "lubrication"].get("oil_volume") else "housing floor × oil depth")
    sec.add("h_free", D.h_free, "W/(m^2·K)", "α_free", "free convection coefficient",
            "[Incropera2007] eq. (9.26)")
    if hs.fan_share > 0:
        sec.add("h_fan", D.h_forced, "W/(m^2·K)", "α_fan", "forced convection coefficient "
                f"(fan, {100 * hs.fan_share:.0f} % of the area)", "[Incropera2007] eq. (7.30)")
    sec.add("h_rad", D.h_rad, "W/(m^2·K)", "α_rad", "radiation coefficient",
            "[Incropera2007] eq. (1.9)")
    sec.add("alpha", D.alpha, "W/(m^2·K)", "α", "total heat transfer coefficient", SRC_HEAT)
    if hs.cooler > 0:
        sec.add("P_cooler", hs.cooler, "W", "P_cool", "heat taken by the cooler", "given")
    sec.add("iterations", b.iterations, "-", "", "bisection steps of the heat balance",
            "heat balance")
    sec.add("passes", t.passes, "-", "", "passes of efficiencies and stages", "drive")
    P1 = m.P_in[0]
    sec.add("P_thermal", b.scale_limit * P1 / 1000.0, "kW", "P_T",
            f"thermal power limit: input power at which the sump reaches {t.t_max:g} °C",
            SRC_HEAT)
    rows = []
    for i, ((_, name, _, _), s) in enumerate(zip(stages, t.losses)):
        rows.append(dict(stage=i + 1, name=name, P_in=s.P_in / 1000.0, mesh=s.mesh,
                         churning=s.churning, bearings=s.bearings, seals=s.seals,
                         other=s.other, total=s.total, eta=s.eta, mu=s.mu, H_V=s.H_V))
    res.tables.append(DataTable("losses", f"Power losses at {b.t_oil:.1f} °C (W)", [
        ("stage", "stage", None), ("name", "name", None), ("P_in", "P_in", "kW"),
        ("mesh", "mesh", "W"), ("churning", "churning", "W"), ("bearings", "bearings", "W"),
        ("seals", "seals", "W"), ("other", "by own η", "W"), ("total", "total", "W"),
        ("eta", "η", "-"), ("mu", "μ_mz", "-"), ("H_V", "H_V", "-")], rows))
    if not t.bearings_counted:
        res.checks.append(check(
            "BEARING_LOSSES", False, "info",
            "bearing losses are not in the efficiencies: give the shafts ([[shaft]]) with "
            "their bearings", "", None, None, "drive"))
    ok = b.t_oil <= t.t_max and b.bracketed
    dT = t.t_max - t.t_air
    need = b.P_V_at_max - b.P_Q_at_max
    advice = []
    if need > 0:
        advice.append(f"an oil cooler of {(need + hs.cooler) / 1000.0:.2f} kW")
        conv = b.P_Q_at_max - hs.cooler
        if conv > 0:
            advice.append(f"a housing area of {hs.area * (b.P_V_at_max - hs.cooler) / conv:.2f}"
                          f" m² (now {hs.area:.2f} m²)")
        if hs.fan_share == 0:
            fan = TH.Housing(hs.area, hs.height, hs.length, hs.emissivity, 10.0, 0.5, hs.cooler)
            advice.append(f"a fan (10 m/s on half the area gives "
                          f"{TH.dissipation(fan, t.t_max, t.t_air).P_Q / 1000.0:.2f} kW at "
                          f"{t.t_max:g} °C)")
    where = (f"{b.t_oil:.1f} °C" if b.bracketed else f"above {HEAT.T_SEARCH_MAX:g} °C")
    res.checks.append(check(
        "THERMAL", ok, "error",
        f"the oil sump reaches {where}, above the permissible {t.t_max:g} °C: the losses "
        f"{b.P_V_at_max:.0f} W at {t.t_max:g} °C exceed the {b.P_Q_at_max:.0f} W the housing "
        f"gives off ({dT:g} K over the ambient); add " + ", or ".join(advice)
        + f"; the thermal power limit is {b.scale_limit * P1 / 1000.0:.2f} kW",
        f"the oil sump settles at {b.t_oil:.1f} °C <= {t.t_max:g} °C (losses {b.P_V:.0f} W); "
        f"thermal power limit {b.scale_limit * P1 / 1000.0:.2f} kW",
        b.t_oil, t.t_max, SRC_HEAT))


def scuffing_checks(res: Result, t: Thermal, stages: list, scuff: dict) -> None:
    """Say at which oil temperature each stage was rated for scuffing: the sump temperature
    of the balance, or the stage's own value (a warning when it is below the sump's)."""
    t_oil = t.balance.t_oil
    for i, how in sorted(scuff.items()):
        t_st = _scuffing_tables(stages[i][2])[1]["oil_temperature"]
        if how == "balance":
            capped = (f" (capped at {SCUFFING_T_MAX:g} °C, the method's limit)"
                      if t_oil > SCUFFING_T_MAX else "")
            res.checks.append(check(
                f"SCUFFING_OIL_{i + 1}", True, "info", "",
                f"stage {i + 1} is rated for scuffing at the sump temperature of the heat "
                f"balance, Θ_oil = {t_st:.1f} °C{capped}", t_st, None, "heat balance"))
        else:
            low = t_st < t_oil - 0.5
            res.checks.append(check(
                f"SCUFFING_OIL_{i + 1}", not low, "warning",
                f"stage {i + 1} is rated for scuffing at Θ_oil = {t_st:g} °C (its "
                f"scuffing table's oil_temperature) but the heat balance gives a sump of "
                f"{t_oil:.1f} °C: leave oil_temperature out to rate it at the sump "
                f"temperature, or cool the oil (fan, cooler)",
                f"stage {i + 1} is rated for scuffing at Θ_oil = {t_st:g} °C, not below the "
                f"sump temperature {t_oil:.1f} °C of the heat balance", t_st, t_oil,
                "heat balance"))

