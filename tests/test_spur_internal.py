"""Internal pairs in the spur calculator (``gear.internal = true``).

The spur result of an internal pair must equal the planetary calculator's planet–ring mesh
for the same gears: geometry, checks and GOST 21354-87 stresses.  Both calculators call
the same functions (:mod:`geardesign.gears.internal`,
:func:`geardesign.spur.checks.internal_mesh_checks`, the spur rating), so the comparison
is to rounding (1e-9).  The planetary train is a stepped 2K-H train whose second crown
(planet2, meshing only the ring) is the pinion: it has its own tip circle (no Δy of a sun
mesh) and is loaded on one flank, as a pinion of a single internal pair is.  Bad inputs:
one line, exit 2.
"""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from tests.conftest import flat
from tests.helpers_cli import cli, write_spec

M, Z1, Z2, X1, X2, B = 3.0, 24, 72, 0.3, 0.25, 30.0
K2, Z0 = 0.1, 25
PLANETS, T_IN, N_IN, LIFE = 3, 200.0, 1450.0, 20000.0

MATS = {
    "pinion": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 59.0},
    "wheel": {"grade": "40KhN", "treatment": "improved", "hardness_HB": 280.0},
}


def planetary_data(**strength) -> dict:
    """A stepped 2K-H train: sun 18 – planet 27, planet2 = Z1 – ring Z2 (ring fixed);
    ``strength`` adds keys to its [strength] table."""
    return {
        "kind": "planetary",
        "train": {"scheme": "2K-H-stepped", "planets": PLANETS, "module": M, "face_width": B},
        "teeth": {"sun": 18, "planet": 27, "planet2": Z1, "ring": Z2},
        "shift": {"sun": 0.0, "planet": 0.0, "planet2": X1, "ring": X2},
        "ring": {"tip_shortening": K2},
        "cutter": {"teeth": Z0},
        "operation": {"fixed": "ring", "input": "sun", "output": "carrier", "speed": N_IN,
                      "torque": T_IN},
        "strength": {"life_hours": LIFE, "load_sharing": 1.0, **strength},
        "material": {"sun": MATS["pinion"], "planet": MATS["pinion"], "ring": MATS["wheel"]},
    }


def planetary_doc() -> dict:
    """The train of :func:`planetary_data`, rated to GOST 21354-87."""
    return run_data(planetary_data()).document()


def spur_doc(T1: float | None = None, n1: float | None = None, **gear) -> dict:
    data = {"kind": "spur", "gear": {
        "internal": True, "module": M, "z1": Z1, "z2": Z2, "x1": X1, "x2": X2, "face_width": B,
        "internal_tip_shortening": K2, "cutter_teeth": Z0, "bearing_scheme": 6}}
    for key, value in gear.items():
        if value is None:
            data["gear"].pop(key)
        else:
            data["gear"][key] = value
    if T1 is not None:
        data["load"] = {"speed1": n1, "torque1": T1, "life_hours": LIFE,
                        "meshes_wheel": PLANETS}
        data["material"] = MATS
    return run_data(data).document()


@pytest.fixture(scope="module")
def both():
    p = planetary_doc()
    r = p["results"]
    mesh = r["planet2_ring"]
    st = r["strength_planet2_ring"]
    # the torque of the pinion (planet2) of one planet, from the mesh force at its reference
    # circle, and its speed relative to the carrier
    d1 = Z1 * M
    T1 = st["F_t_planet"] * d1 / 2000.0
    s = spur_doc(T1, st["n1_rel"])
    return p, mesh, st, s


def test_geometry_equals_planetary_mesh(both):
    p, mesh, _, s = both
    v = flat(s)
    gears = p["results"]["gears"]
    assert v["internal"] is True and mesh["internal"] is True
    pairs = {"x_diff": "x_diff", "alpha_tw": "alpha_tw", "a": "a", "a_w": "a_w", "y": "y",
             "delta_y": "delta_y", "d_w1": "d_w_planet2", "d_w2": "d_w_ring",
             "d_p1": "d_p_planet2", "d_p2": "d_p_ring", "g_w": "g_w", "g_alpha": "g_alpha",
             "p_bt": "p_bt", "eps_alpha": "eps_alpha", "eps_beta": "eps_beta",
             "c_12": "c_12", "c_21": "c_21", "delta_tip": "delta_tip",
             "alpha_tw0": "alpha_tw0", "a_w0": "a_w0", "d_a0": "d_a0", "delta_cut": "delta_cut"}
    for ours, theirs in pairs.items():
        assert v[ours] == pytest.approx(mesh[theirs], rel=1e-9, abs=1e-9), ours
    for ours, theirs in {"d_a2": "d_a_ring", "d_f2": "d_f_ring", "d_l2": "d_l_ring",
                         "s_n2": "s_n_ring", "s_an2": "s_an_ring", "W2": "W_ring",
                         "k2": "k_ring", "d_a1": "d_a_planet2", "d_f1": "d_f_planet2",
                         "d_l1": "d_l_planet2", "s_an1": "s_an_planet2",
                         "x2_iso": "x_ring_iso"}.items():
        assert v[ours] == pytest.approx(gears[theirs], rel=1e-9, abs=1e-9), ours
    # the internal-pair formulas themselves: a = m(z2 − z1)/2, inv α_w from x2 − x1,
    # d_a2 = d2 − 2m(h_a* − x2 − k2)
    inv = lambda a: math.tan(a) - a  # noqa: E731
    a20 = math.radians(20.0)
    assert v["a"] == pytest.approx(M * (Z2 - Z1) / 2)
    assert inv(math.radians(v["alpha_tw"])) == pytest.approx(
        2 * (X2 - X1) * math.tan(a20) / (Z2 - Z1) + inv(a20), rel=1e-12)
    assert v["d_a2"] == pytest.approx(Z2 * M - 2 * M * (1.0 - X2 - K2))


def test_checks_equal_planetary_mesh(both):
    p, _, _, s = both
    theirs = {c["code"]: c for c in p["checks"]}
    ours = {c["code"]: c for c in s["checks"]}
    for code in ("INTERFERENCE_PINION", "INTERFERENCE_WHEEL", "TIP_INTERFERENCE",
                 "CUTTING_INTERFERENCE"):
        other = "PLANET2_RING_" + code.replace("PINION", "PLANET2").replace("WHEEL", "RING")
        assert ours[code]["passed"] == theirs[other]["passed"], code
        assert ours[code]["value"] == pytest.approx(theirs[other]["value"], rel=1e-9), code
        assert ours[code]["limit"] == pytest.approx(theirs[other]["limit"], rel=1e-9), code
    assert ours["CONTACT_RATIO"]["value"] == pytest.approx(
        theirs["PLANET2_RING_CONTACT_RATIO"]["value"], rel=1e-9)
    assert ours["ROOT_CLEARANCE"]["value"] == pytest.approx(
        theirs["PLANET2_RING_ROOT_CLEARANCE"]["value"], rel=1e-9)
    assert ours["POINTED_TIP_WHEEL"]["value"] == pytest.approx(
        theirs["POINTED_TIP_RING"]["value"], rel=1e-9)


def test_stresses_equal_planetary_mesh(both):
    _, _, st, s = both
    v = flat(s)
    for key in ("F_t", "Z_H", "Z_E", "Z_eps", "K_Hv", "K_Hbeta", "K_Fbeta", "sigma_H",
                "sigma_HP", "S_H1", "S_H2", "Y_FS1", "Y_FS2", "sigma_F1", "sigma_F2", "S_F1",
                "S_F2", "N_K1", "N_K2"):
        assert v[key] == pytest.approx(st[key], rel=1e-9), key


def test_contact_stress_uses_u_minus_1(both):
    _, _, _, s = both
    v = flat(s)
    u = Z2 / Z1
    ext = v["Z_E"] * v["Z_H"] * v["Z_eps"] * math.sqrt(
        v["F_tH"] * v["K_H"] * (u - 1) / (B * Z1 * M * u))
    assert v["sigma_H"] == pytest.approx(ext, rel=1e-9)


def test_iso6336_internal_pair_uses_the_shaper_or_names_the_rack(both):
    """With the shaper (cutter_teeth) the internal gear's Y_F, Y_S come from the fillet it
    generates (ISO 6336-3, internal gears); without it from the rack, and the note says so.
    The shaper's fillet gives a thicker root chord than the rack's: Y_F below the rack's."""
    _, _, st, _ = both
    d1 = Z1 * M
    gear = {"internal": True, "module": M, "z1": Z1, "z2": Z2, "x1": X1, "x2": X2,
            "face_width": B, "internal_tip_shortening": K2, "cutter_teeth": Z0,
            "bearing_scheme": 5}
    spec = {"kind": "spur", "gear": gear,
            "load": {"speed1": st["n1_rel"], "torque1": st["F_t_planet"] * d1 / 2000.0,
                     "life_hours": LIFE, "meshes_wheel": PLANETS},
            "material": MATS, "options": {"method": "ISO 6336:2019"}}
    docs = {}
    for cut in (True, False):
        if not cut:
            gear.pop("cutter_teeth")
        docs[cut] = run_data(spec).document()
        assert "ISO 6336:2019" in docs[cut]["methods"]
    bend = {cut: docs[cut]["results"]["iso6336_bending"] for cut in docs}
    assert bend[True]["form_internal"] == f"shaper z0 = {Z0}" and bend[False]["form_internal"] == "rack"
    assert bend[True]["s_Fn2"] > bend[False]["s_Fn2"] and bend[True]["Y_F2"] < bend[False]["Y_F2"]
    notes = {cut: [c for c in docs[cut]["checks"] if c["code"] == "ISO_INTERNAL_FORM_FACTOR"]
             for cut in docs}
    assert not notes[True] and "rack" in notes[False][0]["message"]


def test_internal_velocities_relative_speed():
    s = spur_doc(100.0, 1000.0)
    v = flat(s)
    assert v["n2"] == pytest.approx(1000.0 * Z1 / Z2)
    w1, w2 = math.pi * 1000.0 / 30.0, math.pi * 1000.0 / 30.0 * Z1 / Z2
    rho_w1 = 0.5 * v["d_w1"] * math.sin(math.radians(v["alpha_tw"]))
    assert v["v_s_E"] == pytest.approx((w1 - w2) * (v["rho_a1"] - rho_w1) / 1000.0)


def test_center_distance_gives_the_shift_difference():
    s = spur_doc(center_distance=73.0, x1=None, x2=0.5)
    v = flat(s)
    assert v["a_w"] == pytest.approx(73.0, abs=1e-9)
    assert v["x2"] == pytest.approx(0.5) and v["x_diff"] == pytest.approx(v["x2"] - v["x1"])


def test_report_names_the_internal_pair(tmp_path):
    path = write_spec(tmp_path, _toml())
    code, out, err = cli("run", path, "--format", "markdown")
    assert code in (0, 1), err
    assert "internal pair" in out and "GOST 19274-73" in out


def _toml(**over) -> str:
    gear = {"internal": "true", "module": "3.0", "z1": "24", "z2": "72", "face_width": "30.0",
            **{k: str(v) for k, v in over.items()}}
    return 'kind = "spur"\n[gear]\n' + "".join(f"{k} = {v}\n" for k, v in gear.items())


@pytest.mark.parametrize("over, line", [
    ({"z2": 24}, "s.toml: gear.z2 = 24: an internal gear needs at least 4 teeth more than the "
                 "pinion (gear.z1 = 24): with fewer the pair cannot run (tip interference); use "
                 "z2 >= 28"),
    ({"z2": 20}, "s.toml: gear.z2 = 20: an internal gear needs at least 4 teeth more than the "
                 "pinion (gear.z1 = 24): with fewer the pair cannot run (tip interference); use "
                 "z2 >= 28"),
    ({"cutter_teeth": 70}, "s.toml: gear.cutter_teeth = 70: a shaper cuts an internal gear only "
                           "with fewer teeth: at most 68 for the 72-tooth internal gear "
                           "(gear.z2; the same rule as for the pinion)"),
    ({"cutter_teeth": 5}, "s.toml: gear.cutter_teeth = 5: must be an integer >= 8 and <= 300"),
    ({"cutter_teeth": 301}, "s.toml: gear.cutter_teeth = 301: must be an integer >= 8 and <= 300"),
    ({"cutter_shift": 0.2}, "s.toml: gear.cutter_shift = 0.2: applies only with "
                            "gear.cutter_teeth (the shaper cutter); give it or remove "
                            "cutter_shift"),
    ({"tip_shortening": "false"}, "s.toml: gear.tip_shortening = false: applies to external "
                                  "pairs (the Δy shortening of GOST 16532-70); the tip of an "
                                  "internal gear is set by gear.internal_tip_shortening"),
    ({"center_distance": 60.0}, "s.toml: gear.center_distance = 60.0: smaller than possible for "
                                "an internal pair: must exceed (d_b2 − d_b1)/2 = 67.6579 mm, "
                                "where the base circles touch (x2 − x1 = 0 gives a_w = 72 mm)"),
    ({"internal": "false", "cutter_teeth": 25}, "s.toml: gear.cutter_teeth = 25: applies to "
                                                "internal pairs only; set gear.internal = true "
                                                "or remove it"),
    ({"internal": "false", "internal_tip_shortening": 0.1},
     "s.toml: gear.internal_tip_shortening = 0.1: applies to internal pairs only; set "
     "gear.internal = true or remove it"),
])
def test_bad_input_one_line_exit_2(tmp_path, over, line):
    path = write_spec(tmp_path, _toml(**over))
    code, out, err = cli("run", path)
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].endswith(line), err


def test_iso6336_stresses_equal_planetary_mesh():
    """ISO 6336:2019 with its internal-gear rules (Z_D = 1, ρ_red with r2 − r1, the internal
    gear's Y_F, Y_S as a rack): the same in both calculators."""
    data = planetary_data(method="ISO 6336:2019")
    st = run_data(data).document()["results"]["strength_planet2_ring"]
    s = run_data({"kind": "spur", "gear": {
        "internal": True, "module": M, "z1": Z1, "z2": Z2, "x1": X1, "x2": X2, "face_width": B,
        "internal_tip_shortening": K2, "cutter_teeth": Z0, "bearing_scheme": 6},
        "load": {"speed1": st["n1_rel"], "torque1": st["F_t_planet"] * Z1 * M / 2000.0,
                 "life_hours": LIFE, "meshes_wheel": PLANETS},
        "material": MATS, "options": {"method": "ISO 6336:2019"}}).document()
    v = flat(s)
    for key in ("Z_H", "Z_E", "Z_B", "Z_D", "sigma_H0", "sigma_H1", "sigma_H2", "sigma_F1",
                "sigma_F2", "Y_F2", "Y_S2", "S_H1", "S_H2", "S_F1", "S_F2"):
        assert v[key] == pytest.approx(st[key], rel=1e-9), key


def test_a_pair_that_cannot_mesh_is_not_rated():
    """The internal gear's tip reaches beyond the pinion's tangency point (ρ_p1 < 0): the
    interference check fails and the rating is refused by a check, not by an exception
    (a negative ε_α is refused as input by the result guard)."""
    s = spur_doc(1830.0, 4250.0, z1=10, z2=181, x1=-0.735, x2=0.4916, cutter_teeth=126,
                 internal_tip_shortening=0.277, bearing_scheme=6)
    codes = {c["code"]: c for c in s["checks"]}
    assert s["verdict"] == "fail"
    assert codes["STRENGTH_NOT_RATED"]["passed"] is False
    assert not codes["INTERFERENCE_PINION"]["passed"]


@settings(max_examples=150, deadline=None)
@given(z1=st.integers(5, 60), dz=st.integers(4, 120), x1=st.floats(-1.0, 2.0),
       x2=st.floats(-1.0, 2.0), k2=st.floats(-0.5, 1.0), z0=st.one_of(st.none(),
                                                                     st.integers(8, 60)),
       beta=st.floats(0.0, 40.0), iso=st.booleans())
def test_any_internal_pair_computes_or_is_refused(z1, dz, x1, x2, k2, z0, beta, iso):
    """No exception, no NaN: a result (pass or fail) or a one-line input error."""
    gear = {"internal": True, "module": 2.0, "z1": z1, "z2": z1 + dz, "x1": x1, "x2": x2,
            "face_width": 20.0, "helix_angle": beta, "internal_tip_shortening": k2,
            "bearing_scheme": 6}
    if z0 is not None:
        gear["cutter_teeth"] = z0
    data = {"kind": "spur", "gear": gear,
            "load": {"speed1": 1000.0, "torque1": 100.0, "life_hours": 1000.0},
            "material": MATS}
    if iso:
        data["options"] = {"method": "ISO 6336:2019"}
    try:
        doc = run_data(data).document()
    except InputError as exc:
        assert len(str(exc).splitlines()) >= 1
        return
    json.dumps(doc, allow_nan=False)
