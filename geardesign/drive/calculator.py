"""``kind = "drive"``: a whole drive, motor to output.

Torque, speed and power are carried from stage to stage with each stage's efficiency;
every stage is computed by its own calculator (:mod:`.stages`); shafts on two bearings get
their reactions from the gear forces (:mod:`.shafts`) and each bearing its life from the
bearing calculator; the bearings' system life follows.  If the driven machine's torque is
given, the stages are rated for it (the torque is carried back to the motor, which is then
checked); otherwise for the motor's nominal torque.
"""

from __future__ import annotations

import math
from pathlib import Path

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import DataTable, Result, check
from geardesign.core.io import confined
from geardesign.core.spec import ValidatedSpec, load_toml
from geardesign.drive import split as SPLIT
from geardesign.drive.shaft_loads import (_shaft_rotation, bearing_report, bearing_runs,
                                          shaft_loads)
from geardesign.drive import stages as ST
from geardesign.drive.bevel_stage import run_bevel
from geardesign.drive.spur_stage import light_spur, probe_spur, run_spur
from geardesign.drive.stages import Duty, StageRun

DRIVE_KEYS = ("name", "file", "efficiency")

ADAPTERS = {"spur": run_spur, "worm": ST.run_worm, "novikov": ST.run_novikov,
            "planetary": ST.run_planetary, "bevel": run_bevel}
"""The stage adapters by kind (:mod:`.spur_stage`, :mod:`.bevel_stage`, :mod:`.stages`):
``adapter(stage spec, T_in, n_in, duty, efficiency or None, where) -> StageRun``, the stage
solved once from its typed inputs.  A new stage kind adds its adapter here."""

PROBES = {"spur": probe_spur}
"""Adapters of the probe pass (the ratios and efficiencies that carry the machine's torque
back to the motor) for the kinds whose ratio and efficiency do not need the rating; the
other kinds are solved by their :data:`ADAPTERS`."""

LIGHT = {"spur": light_spur}
"""Adapters of the passes of the heat balance (:mod:`.lubrication`: ratio, efficiency and
mesh forces, which the losses and the bearings need) for the kinds that give them without
the rating; the other kinds are solved by their :data:`ADAPTERS`.  The stages are rated
once, at the efficiencies of the last pass."""

PASSES = {"probe": PROBES, "light": LIGHT}


def _torque_from_power(P: float, n: float) -> float:
    from geardesign.spur.loads import torque_from_power

    return torque_from_power(P, n)


def stage_path(name: str, base: Path | None, root: Path | None,
               allow_outside: bool = False) -> Path:
    """The stage file ``name`` relative to ``base``, resolved (links followed).

    Stage files are regular files inside the folder of the drive spec (``root``): an
    absolute path, or one that leaves that folder (``..``, a link pointing elsewhere), is
    refused unless ``allow_outside`` (:func:`geardesign.core.io.confined`); a FIFO or a
    device is refused when read (:func:`geardesign.core.io.read_toml`), so that a spec can
    neither hang the run nor make it read a file it should not.  The message never shows
    the foreign file.
    """
    if allow_outside:
        from geardesign.core.paths import resolved

        path = Path(name)
        path = base / path if base is not None and not path.is_absolute() else path
        try:
            return resolved(path)
        except OSError:
            return path          # reading it says why (a loop of links)
    return confined(name, base, root, "the drive spec's folder")


def resolve_stages(stages: list, base: Path | None, where: str = "stage",
                   chain: tuple = (), root: Path | None = None,
                   allow_outside: bool = False) -> list[tuple[str, str, dict, float | None]]:
    """Stage specs in order: ``(where, name, data, efficiency)``.  A ``file`` is read
    relative to ``base`` and must lie inside ``root`` (the top drive spec's folder, see
    :func:`stage_path`); a stage file that is itself a drive contributes its stages (in
    place).  Missing files and cycles of references are input errors."""
    root = root if root is not None else base
    out = []
    for i, st in enumerate(stages):
        key = f"{where}[{i}]"
        name = st.get("name") or f"stage {len(out) + 1}"
        extra = {k: v for k, v in st.items() if k not in DRIVE_KEYS and v is not None}
        if st.get("file") is not None:
            if set(extra) - {"kind"}:
                raise InputError.at(f"{key}.file", st["file"], "give a file or the stage's "
                                    "tables inline, not both")
            try:
                path = stage_path(st["file"], base, root, allow_outside)
            except ValueError as exc:
                raise InputError.at(f"{key}.file", st["file"], str(exc)) from None
            if path in chain:
                raise InputError.at(f"{key}.file", st["file"],
                                    "the stage files refer to each other in a cycle: "
                                    + " -> ".join(p.name for p in chain + (path,)))
            try:
                data = load_toml(path)
            except InputError as exc:
                raise InputError.at(f"{key}.file", st["file"],
                                    f"{exc.problems[0].message} ({path.name})") from None
            if data.get("kind") == "drive":
                inner = data.get("stage") or []
                if not isinstance(inner, list) or not all(isinstance(x, dict) for x in inner):
                    raise InputError.at(f"{key}.file", st["file"], "its [[stage]] entries "
                                        "must be tables")
                out += resolve_stages(inner, path.parent, f"{key}→{path.name}:stage",
                                      chain + (path,), root, allow_outside)
                continue
            out.append((f"{key} ({path.name})", name, data, st.get("efficiency")))
        else:
            if st.get("kind") is None:
                raise InputError(Problem(f"{key}.kind", "missing; give the stage's calculator "
                                         "(kind = \"spur\", \"bevel\", \"worm\", \"novikov\", \"planetary\") and its "
                                         "tables, or file = a spec file"))
            if st["kind"] == "drive":
                raise InputError.at(f"{key}.kind", "drive", "an inline stage cannot be a "
                                    "drive; refer to the drive's file instead")
            out.append((key, name, extra, st.get("efficiency")))
    return out


def _run_chain(stages, T1: float, n1: float, duty: Duty, probe: bool | str = False
               ) -> list[StageRun]:
    """The stages in order, each from the output torque and speed of the one before;
    ``probe``: an unrated pass, ``True`` or ``"probe"`` the probe pass (:data:`PROBES`),
    ``"light"`` a pass of the heat balance (:data:`LIGHT`).  A stage whose spec, input
    torque, speed and efficiency are those of a pass before keeps that pass's run
    (``duty.memo``): a kind solved by its adapter in every pass is solved once."""
    runs = []
    T, n = T1, n1
    table = PASSES["probe" if probe is True else probe] if probe else {}
    for where, _, data, eta in stages:
        kind = data.get("kind")
        if not isinstance(kind, str) or kind not in ADAPTERS:
            raise InputError.at(f"{where}: kind", kind, "not a drive stage; stages can be "
                                + ", ".join(f'"{k}"' for k in ADAPTERS))
        adapter = table.get(kind, ADAPTERS[kind])
        key = ("run", probe if kind in table else False, where, kind, T, n, eta, repr(data))
        run = duty.memo.get(key)
        if run is None:
            run = duty.memo[key] = adapter(data, T, n, duty, eta, where)
        runs.append(run)
        T, n = run.T_out, run.n_out
    return runs


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.drive import CALCULATOR

    d = spec.data
    motor, load = d["motor"], d["load"]
    if d["thermal"] is not None and d["lubrication"] is None:
        raise InputError(Problem("lubrication", "missing; the heat balance [thermal] needs "
                                 "the oil: give [lubrication] oil = \"VG 220\" (a grade)"))
    if d["lubrication"] is not None:
        from geardesign.drive import lubrication as LUB

        LUB.prepare(spec)
    res = CALCULATOR.new_result(spec)
    if motor["power"] is None and motor["torque"] is None:
        raise InputError(Problem("motor.power", "missing; give the motor's power (kW) or "
                                 "torque (N·m)"))
    if motor["power"] is not None and motor["torque"] is not None:
        raise InputError.at("motor.torque", motor["torque"], "give power or torque, not both")
    n_m = motor["speed"]
    T_m = motor["torque"] if motor["torque"] is not None else _torque_from_power(motor["power"],
                                                                                n_m)
    stages = resolve_stages(d["stage"] or [], spec.base_dir)
    split = d["split"]
    if not stages and split is None:
        raise InputError(Problem("stage", "missing; give the stages ([[stage]]) or a ratio "
                                 "split request ([split])"))
    sec = res.section("drive", "Drive")
    sec.add("T_m", T_m, "N·m", "T_m", "motor nominal torque", "motor")
    sec.add("P_m", T_m * n_m * math.pi / 30000.0, "kW", "P_m", "motor nominal power", "motor")

    if split is not None:
        _add_split(res, split, n_m, load, stages)
    if not stages:
        return res

    duty = Duty(load["life_hours"], load["regime"], load["application_factor"],
                motor["peak_ratio"], load["method"])
    lub = d["lubrication"]

    def chain(etas: dict | None = None, prev: list | None = None, light: bool = False):
        """T_in and the stage runs; ``etas`` replaces the efficiencies of the stages that
        give none, ``prev`` (the runs of the pass before) gives the ratios instead of a
        first pass; ``light``: a pass of the heat balance, the stages unrated
        (:data:`LIGHT`)."""
        how = "light" if light else False
        st = stages if not etas else [
            (w, n_, data, e if e is not None else etas.get(i))
            for i, (w, n_, data, e) in enumerate(stages)]
        if load["torque"] is not None:
            # first pass for the ratios and efficiencies, then rate for the machine's torque
            probe = prev if prev is not None else _run_chain(st, T_m, n_m, duty, True)
            factor = math.prod(r.ratio * (etas[i] if etas and i in etas and st[i][3] is not None
                                          else r.efficiency) for i, r in enumerate(probe))
            T1 = load["torque"] / factor
            return T1, _run_chain(st, T1, n_m, duty, how)
        return T_m, _run_chain(st, T_m, n_m, duty, how)

    scuff = LUB.scuffing_oil(spec, stages) if lub is not None else {}
    T_in, runs = chain(light=lub is not None)
    thermal = None
    if lub is not None:
        thermal = LUB.solve(spec, stages, chain, T_in, runs, n_m, scuff, duty.memo)
        T_in, runs = thermal.T_in, thermal.runs

    u = math.prod(r.ratio for r in runs)
    eta = math.prod(r.efficiency for r in runs)
    out = runs[-1]
    sec.add("u", u, "-", "u", "overall ratio", "stages")
    sec.add("eta", eta, "-", "η", "overall efficiency (gear meshes)" if thermal is None else
            "overall efficiency (meshes, churning, bearings, seals)", "stages")
    sec.add("T_in", T_in, "N·m", "T_in", "input torque the stages are rated for", "drive")
    sec.add("T_out", out.T_out, "N·m", "T_out", "output torque", "drive")
    sec.add("n_out", out.n_out, "min^-1", "n_out", "output speed", "drive")
    sec.add("P_out", out.T_out * out.n_out * math.pi / 30000.0, "kW", "P_out", "output power",
            "drive")
    bearings = bearing_runs(d["shaft"], runs, n_m, load["life_hours"],
                             thermal.bearing_oil if thermal is not None else None) \
        if d["shaft"] else None
    layout = None
    for k, sh in enumerate(d["shaft"] or []):
        if sh["key"] and not sh["step"]:
            raise InputError(Problem(f"shaft[{k}].step", "missing; the connections "
                                     "[[shaft.key]] need the shaft's steps [[shaft.step]] "
                                     "(diameters, torque)"))
    if any(sh["step"] for sh in d["shaft"] or []):
        layout = _analyse_shafts(d["shaft"], stages, runs, bearings, n_m, duty, motor)
    res.tables.append(DataTable("stages", "Stages", [
        ("stage", "stage", None), ("name", "name", None), ("kind", "type", None),
        ("ratio", "u", "-"), ("efficiency", "η", "-"), ("T_in", "T_in", "N·m"),
        ("n_in", "n_in", "min^-1"), ("T_out", "T_out", "N·m"), ("n_out", "n_out", "min^-1"),
        ("margin", "worst S/S_min", "-"), ("margin_of", "of", None), ("verdict", "verdict", None),
    ], [dict(stage=i + 1, name=st[1], kind=r.kind, ratio=r.ratio, efficiency=r.efficiency,
             T_in=r.T_in, n_in=r.n_in, T_out=r.T_out, n_out=r.n_out, margin=r.margin,
             margin_of=r.margin_of, verdict=r.result.verdict)
        for i, (st, r) in enumerate(zip(stages, runs))]))

    for i, (st, r) in enumerate(zip(stages, runs), 1):
        res.parts.append(("stage_reports", f"Stage {i}: {st[1]} ({r.kind})", r.result))
        failed = [c.code for c in r.result.failed]
        res.checks.append(check(
            f"STAGE_{i}", not failed, "error",
            f"stage {i} \"{st[1]}\" ({r.kind}) fails {', '.join(failed)}: see its report "
            f"below for what to change",
            f"stage {i} \"{st[1]}\" ({r.kind}) passes (worst margin {r.margin:.2f}, "
            f"{r.margin_of})", r.margin, 1.0, "stage calculator"))
    from geardesign.core.units_guard import given, lifted

    typed = (given(motor, {"power": "kW", "torque": "N·m"}, "motor")
             + given(load, {"torque": "N·m"}, "load"))
    for i, r in enumerate(runs, 1):
        found = lifted(r.result, "UNITS_LOAD", typed, f"stage {i}")
        if found:
            res.checks.extend(found)
            break

    if load["torque"] is not None:
        res.checks.append(check(
            "MOTOR_TORQUE", T_in <= T_m * (1 + 1e-9), "error",
            f"the machine needs {T_in:.1f} N·m at the motor, more than its nominal {T_m:.1f} N·m "
            f"({100 * (T_in / T_m - 1):.0f} % over): choose a motor of at least "
            f"{T_in * n_m * math.pi / 30000.0:.2f} kW or raise the overall ratio",
            f"the machine needs {T_in:.1f} N·m at the motor, within its nominal {T_m:.1f} N·m "
            f"({100 * T_in / T_m:.0f} %)", T_in, T_m, "drive"))
    if load["speed"] is not None:
        dev = (out.n_out - load["speed"]) / load["speed"] * 100.0
        res.checks.append(check(
            "OUTPUT_SPEED", abs(dev) <= load["speed_tolerance"], "error",
            f"output speed {out.n_out:.2f} min⁻¹ is {dev:+.1f} % off the required "
            f"{load['speed']:g} min⁻¹ (tolerance ±{load['speed_tolerance']:g} %): change the "
            f"stage ratios to an overall u = {n_m / load['speed']:.3f}",
            f"output speed {out.n_out:.2f} min⁻¹ within ±{load['speed_tolerance']:g} % of "
            f"{load['speed']:g} min⁻¹ ({dev:+.2f} %)", dev, load["speed_tolerance"], "drive"))

    if split is not None and split["ratio"] is not None:
        want, tol = split["ratio"], load["speed_tolerance"]
        dev = (u - want) / want * 100.0
        res.checks.append(check(
            "OVERALL_RATIO", abs(dev) <= tol, "error",
            f"the stages give u = {u:.4g}, {dev:+.1f} % off split.ratio = {want:g} (tolerance "
            f"±{tol:g} %, load.speed_tolerance): give the stages the proposed ratios of the "
            f"split table, or correct split.ratio",
            f"the stages give u = {u:.4g} within ±{tol:g} % of split.ratio = {want:g} "
            f"({dev:+.2f} %)", dev, tol, "drive"))

    if thermal is not None:
        from geardesign.drive import heat_report

        heat_report.report(res, thermal, stages)
        heat_report.scuffing_checks(res, thermal, stages, scuff)
    if d["shaft"]:
        bearing_report(res, bearings, load["life_hours"])
    if layout is not None:
        from geardesign.drive.shaft_report import report as shaft_report

        shaft_report(res, *layout)
    return res


def _analyse_shafts(shafts: list, stages: list, runs: list[StageRun], bearings: list,
                    n_m: float, duty: Duty, motor: dict):
    """The shafts with steps by the shaft calculator, their connections, and the spur
    stages rated with the misalignment from the shafts (:mod:`.shaft_analysis`,
    :mod:`.misalignment`)."""
    from geardesign.drive import misalignment as MIS
    from geardesign.drive import shaft_analysis as SA

    rot = _shaft_rotation(runs)
    speeds = [n_m] + [r.n_out for r in runs]
    peak = motor["peak_ratio"] or 2.0
    modules = {}
    for i, r in enumerate(runs, 1):
        g = r.inputs.get("gear") if isinstance(r.inputs, dict) else None
        if r.kind in ("spur", "novikov") and isinstance(g, dict):
            modules[i] = (g.get("module"), g.get("face_width") or 0.0)
    by_side = {(c["shaft"], c["side"], c["key"]): br for c, br in bearings}
    shaft_runs = []
    for k, sh in enumerate(shafts):
        if not sh["step"]:
            continue
        idx = sh["index"]
        members = {(g["stage"], 0 if g["stage"] == idx else 1) for g in sh["gear"]}
        need = {(idx - 1, 1)} if idx > len(runs) else (
            {(idx, 0)} if idx == 1 else {(idx - 1, 1), (idx, 0)})
        if not need <= members:
            names = " and ".join(f"the {'input' if w == 0 else 'output'} member of stage {s_}"
                                 for s_, w in sorted(need - members))
            raise InputError(Problem(f"shaft[{k}].gear", f"shaft {idx} is analysed (it has "
                                     f"steps), so the torque's path needs all its gears: add "
                                     f"a [[shaft.gear]] for {names}"))
        gears = [SA.GearOnShaft(j, g["stage"], which, ld,
                                -runs[g["stage"] - 1].T_in if which == 0
                                else runs[g["stage"] - 1].T_out)
                 for j, (g, which, ld) in enumerate(shaft_loads(sh, k, runs))]
        brs = {side: by_side[(idx, side, f"shaft[{k}]")] for side in ("a", "b")}
        shaft_runs.append(SA.shaft_run(k, sh, gears, brs, speeds[idx - 1], rot[idx - 1],
                                       len(runs) + 1, peak, modules, duty.K_A))
    mis = MIS.misalignment({sr.idx: sr for sr in shaft_runs}, runs)
    kh_rows = MIS.rate_with_misalignment(mis, stages, runs, duty, run_spur)
    return shaft_runs, kh_rows, mis


def _add_split(res: Result, split: dict, n_m: float, load: dict, stages) -> None:
    u = split["ratio"]
    if u is None:
        if load["speed"] is None:
            raise InputError(Problem("split.ratio", "missing; give the overall ratio, or "
                                     "load.speed (then u = motor speed / load.speed)"))
        u = n_m / load["speed"]
    kinds = split["kinds"] or [st[2].get("kind") for st in stages]
    if not kinds:
        raise InputError(Problem("split.kinds", "missing; give the kinds of the stages"))
    try:
        ratios = SPLIT.split_ratio(u, kinds, split["rule"])
    except ValueError as exc:
        raise InputError.at("split.kinds", kinds, str(exc)) from None
    res.tables.append(DataTable("split", f"Ratio split ({split['rule']}), u = {u:.4g}", [
        ("stage", "stage", None), ("kind", "type", None), ("ratio", "proposed u", "-")],
        [dict(stage=i + 1, kind=k, ratio=r) for i, (k, r) in enumerate(zip(kinds, ratios))]))
