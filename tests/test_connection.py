"""kind = "connection": every input rule (exact one-line message, exit 2), the failed checks
with their advice (exit 1), properties of the formulas (pressure ∝ torque, safety >= 0, the
key length advice passes), and the template."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.connection import fit as F
from geardesign.connection import iso286, tables
from geardesign.connection import key as K
from geardesign.core.registry import run_data
from tests.helpers_cli import cli, failed_errors, run_bad, run_failing, write_spec

KEY = """kind = "connection"
[load]
torque = 250.0
[key]
shaft_diameter = 40.0
length = 56.0
"""
SPL = """kind = "connection"
[load]
torque = 400.0
[spline]
designation = "W 40x2x18"
length = 40.0
"""
FIT = """kind = "connection"
[load]
torque = 600.0
[fit]
diameter = 50.0
hub_outer_diameter = 90.0
length = 40.0
fit = "H7/s6"
shaft_yield = 355.0
hub_yield = 355.0
"""
BOTH = ("s.toml: give exactly one of [key] (parallel key (GOST 23360-78 / DIN 6885-1)) or "
        "[spline] (involute spline, 30° (DIN 5480 / GOST 6033-80)) or [fit] (cylindrical "
        "interference fit (DIN 7190-1, elastic)); the spec has ")
TABLE = ("outside the key table of GOST 23360-78 / DIN 6885-1 (over 6 up to 500 mm); give "
         "key.width, key.height and key.shaft_depth for another key")

BAD = [
    ("key longer than the hub", KEY + "hub_length = 50.0\n",
     ["s.toml: key.length = 56.0: longer than the hub (key.hub_length = 50 mm): use a "
      "standard key of at most 50 mm or a longer hub"]),
    ("shaft above the key table", KEY.replace("shaft_diameter = 40.0", "shaft_diameter = 520.0"),
     [f"s.toml: key.shaft_diameter = 520.0: {TABLE}"]),
    ("shaft below the key table", KEY.replace("shaft_diameter = 40.0", "shaft_diameter = 5.0"),
     [f"s.toml: key.shaft_diameter = 5.0: {TABLE}"]),
    ("key shorter than its width", KEY.replace("length = 56.0", "length = 10.0"),
     ["s.toml: key.length = 10.0: must be longer than the key width b = 12 mm (derived "
      "from key.shaft_diameter = 40 mm by the key table; form A: bearing length l_p = -2 "
      "mm)"]),
    ("part of a key not from the table", KEY + "width = 12.0\n",
     ["s.toml: key.height: missing; a key not from the table needs key.width, key.height and "
      "key.shaft_depth together"]),
    ("keyway as deep as the key", KEY + "width = 12.0\nheight = 8.0\nshaft_depth = 8.0\n",
     ["s.toml: key.shaft_depth = 8.0: must be less than the key height key.height = 8 mm (the "
      "key must stand out into the hub)"]),
    ("DIN 6892 without strengths", KEY + 'standard = "DIN 6885-1"\n',
     ["s.toml: key.shaft_strength: missing; DIN 6892 method C needs the shaft yield strength "
      "R_e (MPa), or give key.allowable_pressure and key.allowable_shear",
      "s.toml: key.hub_strength: missing; DIN 6892 method C needs the hub strength (R_e of "
      "steel, R_m of cast iron) (MPa), or give key.allowable_pressure and key.allowable_shear",
      "s.toml: key.key_strength: missing; DIN 6892 method C needs the key yield strength R_e "
      "(MPa), or give key.allowable_pressure and key.allowable_shear"]),
    ("two keys", KEY + "count = 3\n",
     ["s.toml: key.count = 3: must be one of 1, 2"]),
    ("hub outer diameter not above the shaft",
     FIT.replace("hub_outer_diameter = 90.0", "hub_outer_diameter = 50.0"),
     ["s.toml: fit.hub_outer_diameter = 50.0: must be larger than the joint diameter "
      "fit.diameter = 50 mm (the hub needs a wall)"]),
    ("bore of the shaft as large as the shaft", FIT + "shaft_bore = 50.0\n",
     ["s.toml: fit.shaft_bore = 50.0: must be smaller than the joint diameter fit.diameter = "
      "50 mm (0 for a solid shaft)"]),
    ("clearance fit", FIT.replace('"H7/s6"', '"H7/g6"'),
     ['s.toml: fit.fit = "H7/g6": "H7/g6" gives no interference at 50 mm (largest -9 µm): a '
      "clearance or transition fit transmits nothing by friction; choose an interference fit "
      "such as H7/s6"]),
    ("not a fit", FIT.replace('"H7/s6"', '"s6/H7"'),
     ['s.toml: fit.fit = "s6/H7": must be a hole-basis fit such as "H7/s6" (hole H, grade '
      "5...11 / shaft f, g, h, js, k, m, n, p, r, s, t, u, grade 5...11)"]),
    ("t below 24 mm", FIT.replace('"H7/s6"', '"H7/t6"').replace("diameter = 50.0\n",
                                                                  "diameter = 20.0\n")
     .replace("hub_outer_diameter = 90.0", "hub_outer_diameter = 40.0"),
     ['s.toml: fit.fit = "H7/t6": shaft deviation t is defined by ISO 286 only above 24 mm']),
    ("beyond the ISO 286 tables", FIT.replace("diameter = 50.0\n", "diameter = 510.0\n")
     .replace("hub_outer_diameter = 90.0", "hub_outer_diameter = 900.0"),
     ['s.toml: fit.fit = "H7/s6": ISO 286 tables cover nominal sizes up to 500 mm']),
    ("fit and interferences", FIT + "interference_min = 10.0\n",
     ["s.toml: fit.interference_min = 10.0: give either fit.fit or the interferences, not "
      "both"]),
    ("one interference", FIT.replace('fit = "H7/s6"\n', "interference_min = 10.0\n"),
     ['s.toml: fit.interference_max: missing; give fit.fit (e.g. "H7/s6") or '
      "fit.interference_min and fit.interference_max (µm)"]),
    ("interferences swapped", FIT.replace('fit = "H7/s6"\n', "interference_min = 30.0\n"
                                          "interference_max = 20.0\n"),
     ["s.toml: fit.interference_min = 30.0: must not exceed fit.interference_max = 20 µm"]),
    ("no connection", 'kind = "connection"\n[load]\ntorque = 1.0\n', [BOTH + "neither"]),
    ("two connections", KEY + '[spline]\ndesignation = "W 40x2x18"\nlength = 40.0\n',
     [BOTH + "both"]),
    ("spline designation unreadable", SPL.replace("W 40x2x18", "W 40-2-18"),
     ['s.toml: spline.designation = "W 40-2-18": must read d_B x m x z, e.g. "W 40x2x18" (or '
      'd_B x m, e.g. "40x2", for a size of the series table)']),
    ("short designation not in the series", SPL.replace("W 40x2x18", "42x2"),
     ['s.toml: spline.designation = "42x2": the series table has no spline 42 x 2; give the '
      "number of teeth (d_B x m x z)"]),
    ("spline profile shift outside DIN 5480", SPL.replace("W 40x2x18", "W 40x2x16"),
     ['s.toml: spline.designation = "W 40x2x16": z = 16 on d_B = 40 mm with m = 2 mm gives '
      "the profile shift x = 1.450, outside -0.05...0.45 of DIN 5480: use z = 18 or 19"]),
    ("designation and numbers", SPL + "module = 2.0\n",
     ["s.toml: spline.module = 2.0: give either spline.designation or the numbers "
      "(reference_diameter, module, teeth), not both"]),
    ("spline not in the series", SPL.replace('designation = "W 40x2x18"\n',
                                             "reference_diameter = 42.0\nmodule = 2.0\n"),
     ["s.toml: spline.module = 2.0: the series table has no spline 42 x 2; give "
      "spline.teeth"]),
    ("soft teeth sliding under load", SPL + 'use = "sliding_loaded"\n',
     ['s.toml: spline.use = "sliding_loaded": a hub sliding under load needs hardened teeth: '
      'give spline.hardness = "hardened" (the default is "soft") or spline.allowable_pressure']),
    ("soft teeth given, sliding under load", SPL + 'use = "sliding_loaded"\nhardness = "soft"\n',
     ['s.toml: spline.hardness = "soft": a hub sliding under load needs hardened teeth '
      '(spline.hardness = "hardened") or give spline.allowable_pressure']),
]


@pytest.mark.parametrize("name", [b[0] for b in BAD])
def test_bad_input_one_line_exit_2(tmp_path, name):
    _, text, expected = next(b for b in BAD if b[0] == name)
    assert run_bad(tmp_path, text) == expected


FAILS = [
    ("key too short", KEY.replace("torque = 250.0", "torque = 400.0") + "hub_length = 80.0\n",
     ["KEY_PRESSURE"],
     "bearing pressure on the hub side p = 151.5 MPa exceeds 130.0 MPa: a single key would "
     "need 63.3 mm, beyond the 60 mm a key may have (1.5·d = 60 mm, hub 80 mm); use two keys "
     "of the standard length 50 mm (key.count = 2, key.length = 50; re-rated, they pass)"),
    ("key needs more than the hub", KEY.replace("torque = 250.0", "torque = 400.0")
     + "hub_length = 60.0\nlength = 56.0\n".replace("length = 56.0\n", ""),
     ["KEY_PRESSURE"],
     "bearing pressure on the hub side p = 151.5 MPa exceeds 130.0 MPa: a single key would "
     "need 63.3 mm, beyond the 60 mm a key may have (1.5·d = 60 mm, hub 60 mm); use two keys "
     "of the standard length 50 mm (key.count = 2, key.length = 50; re-rated, they pass)"),
    ("spline overloaded", SPL.replace("torque = 400.0", "torque = 1200.0"), ["SPLINE_PRESSURE"],
     "flank pressure p = 65.3 MPa exceeds 60.0 MPa: lengthen the hub to at least 43.5 mm, use "
     "a larger spline or hardened teeth"),
    ("fit slips", FIT, ["FIT_SLIP"],
     "the joint slips: safety 0.62 < 1.5 at the smallest interference; raise the smallest "
     "interference to 34.6 µm or more (a tighter fit), use degreased (dry) joint faces or "
     "lengthen the joint; the fit must lie between 34.6 µm (slip) and 95.1 µm (yield)"),
    ("hub yields", FIT.replace('"H7/s6"', '"H7/u6"').replace("torque = 600.0",
                                                                  "torque = 100.0")
     .replace("hub_yield = 355.0", "hub_yield = 250.0"),
     ["FIT_HUB_YIELD"],
     "the hub yields at the largest interference: safety 0.86 < 1.1 (DIN 7190-1); keep the "
     "largest interference below 68.9 µm (a looser fit) or use a stronger material (a thicker wall "
     "hardly helps: the stress at the bore follows the interference)"),
]


@pytest.mark.parametrize("name", [f[0] for f in FAILS])
def test_design_failures_exit_1_with_advice(tmp_path, name):
    _, text, codes, message = next(f for f in FAILS if f[0] == name)
    doc = run_failing(tmp_path, text)
    failed = failed_errors(doc)
    assert [c["code"] for c in failed] == codes
    assert failed[0]["message"] == message


def _doc(text: str) -> dict:
    import tomllib

    return run_data(tomllib.loads(text)).document()


def test_key_advice_passes():
    """The key length the advice names passes the pressure check (and one shorter standard
    length does not)."""
    d = _doc(KEY.replace("torque = 250.0", "torque = 400.0"))
    l_std = d["results"]["design"]["l_std"]
    assert l_std == 70.0
    ok = _doc(KEY.replace("torque = 250.0", "torque = 400.0").replace("length = 56.0",
                                                                        "length = 70.0"))
    assert ok["verdict"] == "pass"
    short = _doc(KEY.replace("torque = 250.0", "torque = 400.0").replace("length = 56.0",
                                                                           "length = 63.0"))
    assert short["verdict"] == "fail"


def test_two_keys_carry_one_and_a_half():
    one = _doc(KEY)["results"]["strength"]["p_hub"]
    two = _doc(KEY + "count = 2\n")["results"]["strength"]["p_hub"]
    assert one / two == pytest.approx(1.5, rel=1e-12)


def test_key_forms_bearing_length():
    rows = {f: _doc(KEY + f'form = "{f}"\n')["results"]["geometry"]["l_p"] for f in "ABC"}
    assert rows == {"A": 44.0, "B": 56.0, "C": 50.0}


def test_key_table_rows_are_continuous():
    sizes = tables.key_sizes()
    for a, b in zip(sizes, sizes[1:]):
        assert a.d_to == b.d_over
        assert b.b >= a.b and b.h >= a.h and 0 < a.t1 < a.h and 0 < a.t2 < a.h


def test_fit_from_interferences_equals_fit_from_iso286():
    f = iso286.fit("H7/s6", 50.0)
    a = _doc(FIT)["results"]
    b = _doc(FIT.replace('fit = "H7/s6"\n', f"interference_min = {f.U_min}\n"
                         f"interference_max = {f.U_max}\n"))["results"]
    assert a["capacity"] == b["capacity"] and a["stress"] == b["stress"]


def test_template_runs(tmp_path):
    code, text, _ = cli("template", "connection")
    assert code == 0
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code == 0, err


torques = st.floats(min_value=1.0, max_value=5000.0)


@settings(max_examples=40, deadline=None)
@given(T=torques, k=st.floats(min_value=1.1, max_value=4.0))
def test_key_pressure_proportional_to_torque(T, k):
    text = KEY.replace("torque = 250.0", f"torque = {T!r}")
    r1 = _doc(text)["results"]["strength"]
    r2 = _doc(KEY.replace("torque = 250.0", f"torque = {T * k!r}"))["results"]["strength"]
    assert r2["p_hub"] / r1["p_hub"] == pytest.approx(k, rel=1e-9)
    assert r2["tau"] / r1["tau"] == pytest.approx(k, rel=1e-9)
    assert r1["S_hub"] >= 0 and r2["S_hub"] >= 0


@settings(max_examples=40, deadline=None)
@given(T=torques, k=st.floats(min_value=1.1, max_value=4.0))
def test_spline_pressure_proportional_to_torque(T, k):
    r1 = _doc(SPL.replace("torque = 400.0", f"torque = {T!r}"))["results"]["strength"]
    r2 = _doc(SPL.replace("torque = 400.0", f"torque = {T * k!r}"))["results"]["strength"]
    assert r2["p"] / r1["p"] == pytest.approx(k, rel=1e-9)
    assert r1["S_p"] >= 0


@settings(max_examples=60, deadline=None)
@given(d=st.floats(min_value=10.0, max_value=400.0), ratio=st.floats(min_value=1.05,
                                                                      max_value=4.0),
       bore=st.floats(min_value=0.0, max_value=0.9), U=st.floats(min_value=1.0,
                                                                   max_value=500.0))
def test_fit_pressure_proportional_to_interference(d, ratio, bore, U):
    C = F.compliance(d, d * ratio, d * bore, 210e3, 0.3, 210e3, 0.3)
    p1, p2 = F.pressure(U, d, C), F.pressure(2 * U, d, C)
    assert p1 > 0 and p2 / p1 == pytest.approx(2.0, rel=1e-12)
    assert F.interference_for(p1, d, C) == pytest.approx(U, rel=1e-12)
    s = F.stresses(p1, d, d * ratio, d * bore)
    assert s.sigma_v_hub >= s.sigma_t_hub > 0 and s.sigma_v_shaft >= p1 * (1 - 1e-12)
    # the pressure limits give exactly the yield safety they were asked for
    p_lim = F.hub_pressure_limit_von_mises(355.0, d, d * ratio, 1.0)
    assert F.stresses(p_lim, d, d * ratio, d * bore).sigma_v_hub == pytest.approx(355.0)


@settings(max_examples=40, deadline=None)
@given(T=st.floats(min_value=1.0, max_value=3000.0))
def test_fit_safeties_non_negative_and_slip_inverse_to_torque(T):
    r = _doc(FIT.replace("torque = 600.0", f"torque = {T!r}"))["results"]
    assert r["capacity"]["S_slip"] >= 0 and r["stress"]["S_P_hub"] >= 0
    assert r["capacity"]["S_slip"] * T == pytest.approx(r["capacity"]["T_slip"], rel=1e-9)


def test_key_bearing_length_inverse():
    for form in K.FORMS:
        assert K.length_for(K.bearing_length(56.0, 12.0, form), 12.0, form) == 56.0
    assert K.standard_length(44.05, tables.key_lengths()) == 45.0
    assert math.isinf(K.standard_length(501.0, tables.key_lengths()))


@pytest.mark.parametrize("how", ['designation = "40x2"', 'designation = "N 40 x 2 x 18"',
                                 "reference_diameter = 40.0\nmodule = 2.0",
                                 "reference_diameter = 40.0\nmodule = 2.0\nteeth = 18"])
def test_spline_size_from_the_series_table(how):
    text = SPL.replace('designation = "W 40x2x18"', how)
    geo = _doc(text)["results"]["geometry"]
    assert (geo["z"], geo["x"]) == (18, pytest.approx(0.45, abs=1e-12))


def test_spline_gost_heights():
    geo = _doc(SPL + 'standard = "GOST 6033-80"\n')["results"]["geometry"]
    assert (geo["h_w"], geo["d_m"]) == (pytest.approx(1.6), 36.0)
