"""ISO 6336 dynamic factor and work hardening of the two spur planetary stages of the
KISSsoft NREL 5 MW reports, mesh by mesh, through the planetary calculator's rating seam.

Source: [KISSsoft2017], "CALCULATION OF A SPUR PLANETARY GEAR STAGE", GitHub
``gfsReboucas/Drivetrain``, files ``@NREL_5MW/stage_01.rtf`` and ``stage_02.rtf`` at commit
4a88df348fc70d04254c84bd375bb2bab0d15d0d, method "ISO 6336:2006 Method B".  Transcribed:

* section 1 "Tooth geometry and material": three planets, K_A = 1.25, K_γ = 1.10,
  175 200 h; bores d_i (stage 1: sun 482.33, planet 408.99 mm; stage 2: 194.32, 576.96 mm);
  sun and planets case-carburized 18CrNiMo7-6 (HRC 61, σ_Hlim 1500, σ_Flim 430 MPa), the
  ring 34CrNiMo6 through-hardened (HBW 240, σ_Hlim 700, σ_Flim 290 MPa); flank R_z 4.8,
  4.8, 8.0 µm; tip relief C_a = 2 µm (sun, planet); ν40 = 220 mm²/s.
* section 7 "Gear accuracy", ISO 1328-1:1995 class 6: f_pbT and f_fαT of each gear (the
  larger of each mesh enters K_v, as the printed running-in values y_p, y_f show).
* section 2 "Factors of general influence": C_R = 0.862 (b_s/b = 0.25; the rim s_R/m_n =
  3.4875 that gives it), c', c_γα, m_red, n_E1, N, K_v; section 4: Z_W.

The bores, the web and the given tolerances are inputs the planetary spec does not take yet
(they come with the planetary calculator's ISO inputs), so the test drives the calculator's
own pieces: its geometry and kinematics (``mesh_duties``, the rating order and relative
speeds), its count of shared meshes (``shared_meshes``) and the spur ISO rating, with the
report's values for those inputs.

Editions: the report rates to ISO 6336:2006, we to 2019.  m_red, n_E1, N and K_v are the
same in both.  Z_W: 2006 prints 1.2 − (HB − 130)/1700 = 1.135; 2019 multiplies by
(3/R_zH)^0.15, which is 1 here (R_zH = 2.2 µm < 3 µm on these large, slow gears): the
printed value is met without an edition allowance.

Stage 1's K_v are "user specified" in the report (1.01, 1.05): not a computed value, not
compared.  Stage 2's are computed (K_V12 = 1.02, K_V23 = 1.06, printed to 0.01).

Tolerances: c_γα carries the printed C_R = 0.862 (±0.0005, ±0.06 %), so n_E1 ∝ √c_γα
carries ±0.03 %, and n_E1 is printed to 1 min⁻¹ (±0.05 % at 993): 0.08 %; m_red to ±0.00005 kg/mm (printed to 4 decimals); N to its printed
3 decimals; K_v and Z_W to half a unit of the printed last digit.  The sun of stage 1 has
more teeth than its planet: we rate it with the planet as gear 1 (n_E1 of the planet);
the resonance speed in mesh frequency z1·n_E1 is the same, and the report's n_E1 of the sun
is compared as z_planet·n_E1/z_sun.
"""

from __future__ import annotations

import pytest

from geardesign.core.registry import load_data
from geardesign.planetary import calculator as C
from geardesign.planetary import strength as PS
from geardesign.spur.strength.iso6336 import part1 as P1
from geardesign.spur.strength.iso6336.rating import IsoGear, IsoSetting, rate
from geardesign.spur.strength.rating import Duty, Life, Setting
from tests.conftest import assert_ref
from tests.reference.planetary._util import planetary
from tests.reference.planetary.test_kisssoft_nrel_stages import STAGE1, STAGE2
from tests.reference.spur.test_iso6336_kisssoft import HARD, RING

S_R = 3.4875          # s_R/m_n of the printed C_R = 0.862 with b_s/b = 0.25
BORES = {1: (482.33, 408.99), 2: (194.32, 576.96)}
TOL_1995 = {  # section 7: (f_pbT, f_fαT) µm
    1: {"sun": (31.0, 33.0), "planet": (31.0, 33.0), "ring": (35.7, 40.0)},
    2: {"sun": (16.9, 21.0), "planet": (17.9, 23.0), "ring": (20.7, 27.0)},
}
DATA = {1: STAGE1, 2: STAGE2}
TEETH = {1: {"sun": 19, "planet": 17}, 2: {"sun": 18, "planet": 36}}

# stage, mesh: printed (section 2 and 4)
PRINTED = {
    (1, "sun_planet"): {"m_red": 0.6606, "n_E1_sun": 2266.0, "N": 0.016, "Z_W": (1.000, 1.000)},
    (1, "planet_ring"): {"m_red": 2.4597, "n_E1": 1435.0, "N": 0.028, "Z_W": (1.000, 1.135)},
    (2, "sun_planet"): {"m_red": 0.1534, "n_E1": 5357.0, "N": 0.046, "K_v": 1.02,
                        "Z_W": (1.000, 1.000)},
    (2, "planet_ring"): {"m_red": 1.4684, "n_E1": 993.0, "N": 0.124, "K_v": 1.06,
                         "Z_W": (1.000, 1.135)},
}


def _train_and_duties(data: dict):
    """The planetary calculator's train and mesh duties (rating order, relative speeds,
    per-planet torque with K_γ = 1.1) for a spec given as a dict."""
    _, spec = load_data({"kind": "planetary", **data})
    d = spec.data
    train, conv = C.train_from_teeth(d)
    lay = C._layout(d, train)
    shifts, _, _ = C.resolve_shifts(d, spec, lay, conv)
    meshes = C._geometry(lay, shifts, conv)
    s = C._speeds(train, d["operation"])
    power = planetary(data)["results"]["power"]
    T = {m: power[f"T_{m}_ideal"] for m in train.members}
    duties = PS.mesh_duties(train, meshes, s, T, 1.1, {"planet": True})
    return train, dict(zip((m.name for m in meshes), duties))


def _iso_gears(stage: int) -> dict:
    m = DATA[stage]["train"]["module"]
    sun, planet = BORES[stage]
    return {"sun": IsoGear("Eh", "MQ", 1500.0, 430.0, 4.8, 20.0, sun, S_R * m, 0.25),
            "planet": IsoGear("Eh", "MQ", 1500.0, 430.0, 4.8, 20.0, planet, S_R * m, 0.25),
            "ring": IsoGear("V_alloy", "MQ", 700.0, 290.0, 8.0, 20.0, 0.0, None, None)}


def rate_stage_mesh(stage: int, mesh: str, n1: float | None = None,
                    meshes: tuple[int, int] | None = None) -> dict:
    """The ISO rating of one mesh of a report stage with the report's inputs (K_Hβ = 1.15
    "user specified" as printed); ``n1`` and ``meshes`` replace the calculator's speed and
    shared-mesh count."""
    train, duties = _train_and_duties(DATA[stage])
    md = duties[mesh]
    gears = _iso_gears(stage)
    tol = TOL_1995[stage]
    iso = IsoSetting(grade=6, nu40=220.0, C_a=2.0, S_Hmin=1.25, S_Fmin=1.56,
                     f_pb=max(tol[m][0] for m in md.members),
                     f_falpha=max(tol[m][1] for m in md.members),
                     gears=tuple(gears[m] for m in md.members), overrides={"K_Hbeta": 1.15},
                     meshes=meshes or PS.shared_meshes(train, md.members))
    mats = tuple(RING if m == "ring" else HARD for m in md.members)
    duty = Duty(md.T1, md.n1 if n1 is None else n1, 1.25, None, 0.0,
                Life(175200.0, md.c), md.reverse)
    v = rate(md.geom, mats, duty, Setting(grade=6), iso).v
    return {"members": md.members, **v}


@pytest.mark.parametrize("stage, mesh", list(PRINTED))
def test_dynamic_factor_and_work_hardening(stage, mesh):
    v = rate_stage_mesh(stage, mesh)
    p = PRINTED[(stage, mesh)]
    name = f"KISSsoft NREL stage {stage} {mesh}"
    assert_ref(v["m_red"], p["m_red"], 0.00005, f"{name} m_red")
    if "n_E1_sun" in p:     # rated with the planet as gear 1, see the module notes
        assert v["members"] == ("planet", "sun")
        n_E1_sun = v["n_E1"] * TEETH[stage]["planet"] / TEETH[stage]["sun"]
        assert abs(n_E1_sun / p["n_E1_sun"] - 1.0) < 8e-4, (name, n_E1_sun)
    else:
        assert abs(v["n_E1"] / p["n_E1"] - 1.0) < 8e-4, (name, v["n_E1"])
    assert_ref(v["N"], p["N"], 0.0005, f"{name} N")
    if "K_v" in p:
        assert_ref(v["K_v"], p["K_v"], 0.005, f"{name} K_v")
    assert v["K_v_range"] == "subcritical"
    # Z_W computed (2019 with the flank roughness), not given
    soft = v["members"].index("ring") if "ring" in v["members"] else None
    for k in (1, 2):
        printed = p["Z_W"][1] if soft == k - 1 else p["Z_W"][0]
        assert_ref(v[f"Z_W{k}"], printed, 0.0005, f"{name} Z_W{k}")


def test_sun_shared_by_the_planets_in_the_reduced_mass():
    """The sun's mass is shared by n_P = 3 planets; taking the pair formula instead would
    misstate m_red by (m_S + n_P m_P)/(m_S + m_P) (×1.96 and ×2.50 on the two stages)."""
    for stage, printed in ((1, 0.6606), (2, 0.1534)):
        pair = rate_stage_mesh(stage, "sun_planet", meshes=(1, 1))["m_red"]
        assert pair > 1.9 * printed
    ring = rate_stage_mesh(2, "planet_ring")
    assert ring["members"] == ("planet", "ring")
    assert rate_stage_mesh(2, "planet_ring", meshes=(1, 1))["m_red"] == ring["m_red"]


def test_speed_sweep_through_resonance():
    """Stage 2 sun–planet mesh swept in speed: the ranges of K_v follow the printed
    resonance speed n_E1 = 5357 min⁻¹ (N_S = 0.85 at this line load, main resonance up to
    N = 1.15, intermediate to 1.5).  At n_E1 the mesh is in the main resonance (K_v ≈ 2.1);
    with the pair reduced mass the same speed would be rated supercritical (K_v ≈ 1.05:
    σ_H −29 %, σ_F −49 %)."""
    n_E1 = 5357.0
    expected = ((0.5, "subcritical"), (0.84, "subcritical"), (0.86, "main resonance"),
                (1.0, "main resonance"), (1.14, "main resonance"), (1.3, "intermediate"),
                (1.6, "supercritical"), (2.0, "supercritical"))
    K = {}
    for N, rng in expected:
        v = rate_stage_mesh(2, "sun_planet", n1=N * n_E1)
        assert abs(v["N"] / N - 1.0) < 5e-4, (N, v["N"])
        assert v["K_v_range"] == rng, (N, v["K_v_range"])
        K[N] = v["K_v"]
    assert max(K, key=K.get) in (0.86, 1.0, 1.14)
    assert K[1.0] > 2.0 and K[2.0] < 1.1
    main = rate_stage_mesh(2, "sun_planet", n1=n_E1)
    pair = rate_stage_mesh(2, "sun_planet", n1=n_E1, meshes=(1, 1))
    assert pair["K_v_range"] == "supercritical"
    assert pair["sigma_H1"] < 0.75 * main["sigma_H1"] and pair["sigma_F1"] < 0.55 * main["sigma_F1"]


def test_planetary_calculator_rates_with_the_shared_sun():
    """Through the whole planetary calculator (ISO 6336 method): the sun–planet mesh's
    m_red is m_S m_P/(n_P m_P + m_S) of its own gear masses (no bores given), the
    planet–ring mesh's the planet's mass; the virtual tooth numbers are reported (the ring
    negative, ISO sign: the report prints z_n = −93.000 for stage 2)."""
    data = {**STAGE2, "strength": {"method": "ISO 6336:2019", "life_hours": 175200.0,
                                   "application_factor": 1.25, "load_sharing": 1.1,
                                   "accuracy_grade": 6},
            "material": {"sun": {"treatment": "carburized", "hardness_HRC": 61.0,
                                 "sigma_Hlim": 1500.0},
                         "planet": {"treatment": "carburized", "hardness_HRC": 61.0,
                                    "sigma_Hlim": 1500.0},
                         "ring": {"grade": "42CrMo4", "treatment": "improved",
                                  "hardness_HB": 240.0, "sigma_Hlim": 700.0}}}
    r = planetary(data)["results"]
    g = r["gears"]
    mass = {m: P1.gear_mass(g[f"d_a_{m}"], g[f"d_f_{m}"], g[f"d_b_{m}"], 0.0)
            for m in ("sun", "planet")}
    sp, pr = r["strength_sun_planet"], r["strength_planet_ring"]
    assert sp["m_red"] == pytest.approx(mass["sun"] * mass["planet"]
                                        / (3 * mass["planet"] + mass["sun"]), rel=1e-9)
    assert pr["m_red"] == pytest.approx(mass["planet"], rel=1e-9)
    assert (sp["z_n1"], sp["z_n2"]) == pytest.approx((18.0, 36.0), abs=1e-9)
    assert (pr["z_n1"], pr["z_n2"]) == pytest.approx((36.0, -93.0), abs=1e-9)
