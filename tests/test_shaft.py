"""kind = "shaft": the beam model against closed forms of beam theory ([Timoshenko]; [Roark]),
equilibrium and diagram properties, the critical speed of a uniform shaft, the strength
formulas, every input rule (exact one-line message, exit 2) and a failing design (exit 1,
advice)."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.shaft import strength as ST
from geardesign.shaft.records import ARCMIN, Load, Material, Options, Step, Support
from geardesign.shaft.solve import analyse
from tests.helpers_cli import cli, failed_errors, run_bad, run_failing, write_spec

E = 2.06e5
MAT = Material(900.0, 650.0, 380.0, 230.0, 0.2, 0.1, E=E)


def inertia(d, d0=0.0):
    return math.pi * (d ** 4 - d0 ** 4) / 64.0


# ----------------------------------------------------------------------- closed forms


@pytest.mark.parametrize("a", [200.0, 100.0, 330.0])
def test_simply_supported_point_load(a):
    """Deflection under the load F·a²b²/(3EIL), slopes at the supports F·b(L²−b²)/(6EIL)
    and F·a(L²−a²)/(6EIL), reactions F·b/L, F·a/L, largest moment F·a·b/L ([Roark]
    table 8.1 case 1e)."""
    d, L, F = 40.0, 400.0, 1500.0
    b = L - a
    EI = E * inertia(d)
    r = analyse([Step(L, d)], [Load(a, Fy=F)], [Support(0.0), Support(L)], MAT)
    assert r.loads[0].w_y == pytest.approx(F * a * a * b * b / (3 * EI * L), rel=1e-9)
    assert r.supports[0].slope == pytest.approx(F * b * (L * L - b * b) / (6 * EI * L),
                                                rel=1e-9)
    assert r.supports[1].slope == pytest.approx(F * a * (L * L - a * a) / (6 * EI * L),
                                                rel=1e-9)
    assert -r.supports[0].R_y == pytest.approx(F * b / L, rel=1e-9)
    assert -r.supports[1].R_y == pytest.approx(F * a / L, rel=1e-9)
    assert max(abs(m) for m in r.M_y) == pytest.approx(F * a * b / L / 1e3, rel=1e-9)
    if a == L / 2:
        assert r.loads[0].w_y == pytest.approx(F * L ** 3 / (48 * EI), rel=1e-9)
        assert r.supports[0].slope == pytest.approx(F * L * L / (16 * EI), rel=1e-9)


def test_overhung_load():
    """Load F at the end of an overhang a beyond the right support of a span L: tip
    deflection F·a²(L + a)/(3EI), slope at the left support F·a·L/(6EI), at the right one
    F·a·L/(3EI) ([Roark] table 8.1, overhanging beam)."""
    d, L, a, F = 35.0, 300.0, 80.0, 900.0
    EI = E * inertia(d)
    r = analyse([Step(L + a, d)], [Load(L + a, Fz=F)], [Support(0.0), Support(L)], MAT)
    assert r.loads[0].w_z == pytest.approx(F * a * a * (L + a) / (3 * EI), rel=1e-9)
    assert r.supports[0].slope == pytest.approx(F * a * L / (6 * EI), rel=1e-9)
    assert r.supports[1].slope == pytest.approx(F * a * L / (3 * EI), rel=1e-9)
    # reactions: -F·a/L at the left support, F·(L + a)/L at the right one (on the shaft)
    assert r.supports[0].R_z == pytest.approx(F * a / L, rel=1e-9)
    assert r.supports[1].R_z == pytest.approx(-F * (L + a) / L, rel=1e-9)
    assert r.M_z[-1] == 0.0 and r.M_z[0] == 0.0


def test_stepped_shaft_by_castigliano():
    """Symmetric stepped shaft (d1 on the outer lengths c, d2 between), central load F:
    by Castigliano δ = (F/2)·[c³/(3EI1) + ((L/2)³ − c³)/(3EI2)], and the slope at a support
    θ = (F/4)·[c²/(EI1) + ((L/2)² − c²)/(EI2)] (unit-moment integral)."""
    L, c, d1, d2, F = 500.0, 120.0, 40.0, 55.0, 3000.0
    EI1, EI2 = E * inertia(d1), E * inertia(d2)
    steps = [Step(c, d1), Step(L - 2 * c, d2), Step(c, d1)]
    r = analyse(steps, [Load(L / 2, Fy=F)], [Support(0.0), Support(L)], MAT)
    delta = F / 2 * (c ** 3 / (3 * EI1) + ((L / 2) ** 3 - c ** 3) / (3 * EI2))
    theta = F / 4 * (c ** 2 / EI1 + ((L / 2) ** 2 - c ** 2) / EI2)
    assert r.loads[0].w_y == pytest.approx(delta, rel=1e-9)
    assert r.supports[0].slope == pytest.approx(theta, rel=1e-9)


def test_hollow_shaft_uses_the_bore():
    L, d, d0, F = 400.0, 50.0, 30.0, 2000.0
    r = analyse([Step(L, d, bore=d0)], [Load(L / 2, Fy=F)], [Support(0.0), Support(L)], MAT)
    assert r.loads[0].w_y == pytest.approx(F * L ** 3 / (48 * E * inertia(d, d0)), rel=1e-9)


def test_spring_supports_add_their_deflection():
    """Central load on springs k: the supports sink F/(2k) each; the centre moves by
    F·L³/(48EI) + F/(2k) (superposition)."""
    L, d, F, k = 400.0, 40.0, 2000.0, 1.0e5
    r = analyse([Step(L, d)], [Load(L / 2, Fy=F)],
                [Support(0.0, stiffness=k), Support(L, stiffness=k)], MAT)
    assert r.loads[0].w_y == pytest.approx(F * L ** 3 / (48 * E * inertia(d)) + F / (2 * k),
                                           rel=1e-9)
    assert sum(s.R_y for s in r.supports) == pytest.approx(-F, rel=1e-9)


def test_two_span_continuous_shaft():
    """Three supports, equal spans l, load P in the middle of the first span: reactions
    13P/32, 11P/16, −3P/32 ([Roark] table 8.1, continuous beams; three-moment equation)."""
    l, P = 200.0, 1000.0
    r = analyse([Step(2 * l, 40.0)], [Load(l / 2, Fy=P)],
                [Support(0.0), Support(l), Support(2 * l)], MAT)
    R = [-s.R_y for s in r.supports]
    assert R == pytest.approx([13 * P / 32, 11 * P / 16, -3 * P / 32], rel=1e-9)


def test_couple_of_an_axial_force():
    """A couple C at mid-span: reactions ±C/L, moment ±C/2 either side of it (the section
    takes the larger)."""
    L, C = 400.0, 100.0     # N·m
    r = analyse([Step(L, 40.0)], [Load(L / 2, moment_y=C)], [Support(0.0), Support(L)], MAT)
    assert abs(r.supports[0].R_y) == pytest.approx(C * 1e3 / L, rel=1e-9)
    sec = next(s for s in r.sections if s.label == "load 1")
    assert sec.M == pytest.approx(C / 2, rel=1e-9)


def test_critical_speed_of_a_uniform_shaft():
    """Simply supported uniform shaft: ω1 = π²·√(EI/(ρA·L⁴)) ([Timoshenko] vibration of
    beams); the consistent-mass elements converge to it from above."""
    L, d = 800.0, 30.0
    r = analyse([Step(L, d)], [Load(L / 2)], [Support(0.0), Support(L)], MAT)
    rho_A = 7850.0 * math.pi * (d / 1000) ** 2 / 4
    omega = math.pi ** 2 * math.sqrt(E * 1e6 * inertia(d) * 1e-12 / (rho_A * (L / 1000) ** 4))
    assert r.omega_cr == pytest.approx(omega, rel=1e-6)
    assert r.omega_cr >= omega
    assert r.n_cr == pytest.approx(omega * 30 / math.pi, rel=1e-6)


def test_critical_speed_of_a_disc_on_a_light_shaft():
    """A heavy disc at mid-span: ω = √(k/(m + 17/35·m_s)), k = 48EI/L³ (Rayleigh with the
    static deflection shape; the shaft adds 17/35 of its mass, [Timoshenko]).  With a shaft
    1000 times lighter than the disc the eigenvalue stays well conditioned."""
    L, d, m = 600.0, 30.0, 40.0
    for rho in (7.85, 7850.0):
        mat = Material(900.0, 650.0, 380.0, 230.0, 0.2, 0.1, E=E, density=rho)
        r = analyse([Step(L, d)], [Load(L / 2, mass=m)], [Support(0.0), Support(L)], mat)
        k = 48 * E * inertia(d) / L ** 3          # N/mm
        m_s = rho * 1e-9 * math.pi * d * d / 4 * L
        assert r.omega_cr == pytest.approx(math.sqrt(k * 1000 / (m + 17 / 35 * m_s)),
                                           rel=2e-5)


# ----------------------------------------------------------------------- properties


def _magnitude(hi: float, signed: bool = True):
    """0 or a magnitude in the spec's physical domain (no force or torque below 1 mN or
    1 mN·m: core/spec.UNIT_DOMAINS refuses them), up to ``hi``, of either sign."""
    mag = st.one_of(st.just(0.0), st.floats(1e-3, hi))
    if not signed:
        return mag
    return st.tuples(mag, st.sampled_from((-1.0, 1.0))).map(lambda t: t[0] * t[1])


@st.composite
def shafts(draw):
    n = draw(st.integers(1, 5))
    steps = [Step(draw(st.floats(10, 200)), draw(st.floats(15, 120)),
                  fillet=draw(st.floats(0.3, 5)), keyway=draw(st.booleans()),
                  press_fit=draw(st.booleans())) for _ in range(n)]
    L = sum(s.length for s in steps)
    a = draw(st.floats(0, 0.45)) * L
    b = draw(st.floats(0.55, 1.0)) * L
    loads = []
    for k in range(draw(st.integers(1, 4))):
        loads.append(Load(draw(st.floats(0, 1)) * L, Fy=draw(_magnitude(5e3)),
                          Fz=draw(_magnitude(5e3)), Fx=draw(_magnitude(2e3))))
    T = draw(_magnitude(2000.0, signed=False))
    loads.append(Load(draw(st.floats(0, 1)) * L, torque=T))
    loads.append(Load(draw(st.floats(0, 1)) * L, torque=-T))
    return steps, loads, [Support(a), Support(b)]


@settings(max_examples=40, deadline=None)
@given(shafts())
def test_equilibrium_free_ends_and_positive_safeties(case):
    steps, loads, supports = case
    r = analyse(steps, loads, supports, MAT, Options(speed=100.0))
    big = max(1.0, max(abs(m) for m in r.M))
    force = max([1.0] + [abs(ld.Fy) + abs(ld.Fz) for ld in loads])
    # ΣF = 0 in both planes and axially
    # 1e-5 of the load: a random shaft may put a sub-millimetre element beside a long thick
    # step (stiffness ratio ~1e10), and the reactions from the residual keep ~6 digits
    assert abs(sum(s.R_y for s in r.supports) + sum(ld.Fy for ld in loads)) < 1e-5 * force
    assert abs(sum(s.R_z for s in r.supports) + sum(ld.Fz for ld in loads)) < 1e-5 * force
    assert abs(sum(s.R_x for s in r.supports) + sum(ld.Fx for ld in loads)) < 1e-6
    # moments vanish at the free ends (no couple is applied there)
    assert abs(r.M[0]) < 1e-6 * big and abs(r.M[-1]) < 1e-6 * big
    assert abs(r.T[-1]) < 1e-9 * max(1.0, max(abs(t) for t in r.T))
    for s in r.sections:
        assert s.S > 0 and s.S_static > 0 and s.S_sigma > 0 and s.S_tau > 0
        assert s.K_sigma_D >= 1.0 and s.K_tau_D >= 1.0
    assert r.omega_cr > 0


# ----------------------------------------------------------------------- strength parts


def test_fatigue_combination_and_factors():
    f = ST.fatigue_safety(40.0, 0.0, 10.0, 10.0, 2.5, 2.0, 0.9, 0.575 * 0.9 + 0.425, 1.0,
                          380.0, 230.0, 0.2, 0.1)
    K_sD = 2.5 + 1 / 0.9 - 1
    assert f.K_sigma_D == pytest.approx(K_sD)
    assert f.S_sigma == pytest.approx(380.0 / (K_sD * 40.0))
    assert f.S == pytest.approx(f.S_sigma * f.S_tau / math.hypot(f.S_sigma, f.S_tau))
    # σ_-1 and τ_-1 estimates, ψ by GOST 25.504-82
    assert ST.endurance_estimates(1000.0) == pytest.approx((430.0, 249.4))
    assert ST.mean_stress_sensitivity(800.0) == pytest.approx((0.18, 0.09))


def test_factor_tables_interpolate_and_grow_with_strength():
    ks5, kt5, _ = ST.fillet_factors(2.0, 1.0, 50.0, 500.0)       # t/r 2, r/d 0.02
    assert (ks5, kt5) == pytest.approx((1.80, 1.55))
    ks12, _, _ = ST.fillet_factors(2.0, 1.0, 50.0, 1200.0)
    assert ks12 == pytest.approx(2.15)
    mid, _, _ = ST.fillet_factors(2.0, 1.0, 50.0, 600.0)
    assert mid == pytest.approx((1.80 + 1.90) / 2)
    assert ST.keyway_factors(700.0) == pytest.approx((2.01, 1.88))
    rs, rt = ST.press_fit_ratios(50.0, 900.0)
    assert rs == pytest.approx(4.5) and rt == pytest.approx(0.6 * 4.5 + 0.4)
    assert ST.size_factors(40.0, alloy=False) == pytest.approx((0.85, 0.73))
    assert ST.size_factors(40.0, alloy=True) == pytest.approx((0.73, 0.73))
    # K_F: 1 for a polished surface, below 1 and falling with roughness
    assert ST.surface_factors(1.0, 900.0)[0] == 1.0
    assert ST.surface_factors(20.0, 900.0)[0] < ST.surface_factors(3.2, 900.0)[0] < 1.0
    # t/r above the table is flagged (the nearest row may understate K_σ)
    assert ST.fillet_factors(10.0, 1.0, 50.0, 700.0)[2]
    assert not ST.fillet_factors(1.0, 1.0, 50.0, 700.0)[2]


# ----------------------------------------------------------------------- command line

BASE = """kind = "shaft"
[shaft]
speed = 200.0
[material]
grade = "45"
hardness_HB = 270.0
[[step]]
length = 40.0
diameter = 45.0
[[step]]
length = 80.0
diameter = 55.0
keyway = true
[[step]]
length = 60.0
diameter = 45.0
[[load]]
position = 80.0
Fy = 3000.0
torque = 500.0
[[load]]
position = 170.0
Fz = 1000.0
torque = -500.0
[[support]]
position = 20.0
[[support]]
position = 140.0
"""


def test_template_runs(tmp_path):
    code, out, err = cli("template", "shaft")
    assert code == 0
    code, out, err = cli("run", write_spec(tmp_path, out), "--format", "json")
    assert code == 0, err


def test_base_spec_passes():
    from geardesign.core.spec import parse_toml

    doc = run_data(parse_toml(BASE)).document()
    assert doc["verdict"] == "pass"
    assert doc["results"]["strength"]["S"] > 2.0


@pytest.mark.parametrize("change, line", [
    (("[[step]]\nlength = 60.0\ndiameter = 45.0\n",
      "[[step]]\nlength = 60.0\ndiameter = 45.0\nstart = 100.0\n"),
     "s.toml: step[2].start = 100.0: overlaps step[1], which ends at 120 mm; steps follow "
     "each other without gaps: give start = 120 or leave it out"),
    (("position = 170.0", "position = 190.0"),
     "s.toml: load[1].position = 190.0: outside the shaft: must be within 0…180 mm (the sum "
     "of the step lengths)"),
    (("position = 140.0", "position = 181.0"),
     "s.toml: support[1].position = 181.0: outside the shaft: must be within 0…180 mm (the "
     "sum of the step lengths)"),
    (("position = 140.0", "position = 20.0"),
     "s.toml: support: a free shaft needs at least two supports at different positions to "
     "carry its loads; add a [[support]]"),
    (("torque = -500.0", "torque = -400.0"),
     "s.toml: load: the torques do not balance: their sum is 100 N·m; a shaft in steady "
     "rotation takes out what is put in: give the output torque(s) with the opposite sign "
     "so that the sum is 0"),
    (('grade = "45"', 'grade = "46"'),
     "s.toml: material.grade = \"46\": unknown shaft steel (did you mean '45'?); known: 45, "
     "40Kh, 40KhN, 20Kh, 12KhN3A, 18KhGT; or leave out grade and give sigma_B and sigma_T"),
    (("length = 40.0\ndiameter = 45.0", "length = 40.0\ndiameter = 45.0\nbore = 45.0"),
     "s.toml: step[0].bore = 45.0: must be smaller than the diameter 45 mm"),
    (("length = 60.0\ndiameter = 45.0", "length = 60.0\ndiameter = 45.0\ngroove_K_sigma = 2.0"),
     "s.toml: step[2].groove_K_sigma = 2.0: a groove sits at the right end of its step, and "
     "the last step ends with the shaft: give it on the step to the left of the groove's "
     "shoulder"),
])
def test_input_errors(tmp_path, change, line):
    old, new = change
    assert old in BASE
    assert run_bad(tmp_path, BASE.replace(old, new, 1)) == [line]


def test_single_support_is_refused(tmp_path):
    text = BASE.replace("[[support]]\nposition = 140.0\n", "")
    assert run_bad(tmp_path, text) == [
        "s.toml: support: a free shaft needs at least two supports at different positions "
        "to carry its loads; add a [[support]]"]


def test_material_without_grade_needs_strengths(tmp_path):
    text = BASE.replace('grade = "45"\nhardness_HB = 270.0\n', "sigma_B = 800.0\n")
    assert run_bad(tmp_path, text) == [
        "s.toml: material.sigma_T: missing; required without a grade: the ultimate and the "
        "yield strength of the shaft steel (or give material.grade)"]


def test_weak_shaft_fails_with_advice(tmp_path):
    text = BASE.replace("torque = 500.0", "torque = 3000.0").replace(
        "torque = -500.0", "torque = -3000.0")
    doc = run_failing(tmp_path, text)
    codes = {c["code"] for c in failed_errors(doc)}
    assert "FATIGUE" in codes
    fat = next(c for c in doc["checks"] if c["code"] == "FATIGUE")
    assert "scale every step's diameter (and bore and fillet radius) by" in fat["message"]


def apply_scale_advice(text: str, message: str) -> dict:
    """The spec with the advice of a FATIGUE or STATIC_STRENGTH message applied: every
    step's diameter, bore and fillet radius times the advised factor (and a groove's depth,
    radius and width and a cross-bore's diameter with them)."""
    import re

    from geardesign.core.spec import parse_toml

    k = float(re.search(r"fillet radius\) by ([\d.]+), which reaches", message).group(1))
    data = parse_toml(text)
    for s in data["step"]:
        for key in ("diameter", "bore", "fillet", "groove_depth", "groove_radius",
                    "groove_width", "cross_bore"):
            if s.get(key) is not None:
                s[key] *= k
        s.setdefault("fillet", 1.0 * k)          # the default radius scales too
    return data


@pytest.mark.parametrize("T", [1500.0, 3000.0, 6000.0])
def test_advice_reaches_the_required_safety(tmp_path, T):
    """The advised scale, applied to the whole shaft, passes FATIGUE: the calculator
    analysed the scaled shaft again (size factors and the neighbours' shoulders change with
    the diameters), so the advice leads to a passing design."""
    text = BASE.replace("torque = 500.0", f"torque = {T}").replace(
        "torque = -500.0", f"torque = -{T}")
    doc = run_failing(tmp_path, text)
    fat = next(c for c in doc["checks"] if c["code"] == "FATIGUE")
    assert not fat["passed"]
    doc2 = run_data(apply_scale_advice(text, fat["message"])).document()
    assert doc2["results"]["strength"]["S"] >= 2.0
    assert next(c for c in doc2["checks"] if c["code"] == "FATIGUE")["passed"]


def test_static_advice_reaches_the_required_safety(tmp_path):
    text = BASE.replace("[shaft]\n", "[shaft]\nS_min = 1.0\nS_static_min = 3.0\n", 1) \
        .replace("torque = 500.0", "torque = 2500.0").replace("torque = -500.0",
                                                              "torque = -2500.0")
    doc = run_failing(tmp_path, text)
    c = next(c for c in doc["checks"] if c["code"] == "STATIC_STRENGTH")
    assert not c["passed"], c["message"]
    doc2 = run_data(apply_scale_advice(text, c["message"])).document()
    assert next(x for x in doc2["checks"] if x["code"] == "STATIC_STRENGTH")["passed"]


def test_bearing_tilt_fails_on_a_soft_shaft(tmp_path):
    text = BASE.replace("position = 20.0", 'position = 0.0\ntype = "cylindrical_roller"'
                        ).replace("diameter = 55.0", "diameter = 22.0").replace(
        "diameter = 45.0", "diameter = 20.0").replace("diameter = 45.0", "diameter = 20.0")
    text = text.replace("Fy = 3000.0", "Fy = 6000.0").replace(
        "torque = 500.0", "torque = 5.0").replace("torque = -500.0", "torque = -5.0")
    doc = run_failing(tmp_path, text)
    tilt = [c for c in doc["checks"] if c["code"] == "BEARING_TILT"]
    assert tilt and not tilt[0]["passed"] and tilt[0]["severity"] == "error"
    assert tilt[0]["value"] > 4.0


def test_document_units_and_tables():
    from geardesign.core.spec import parse_toml

    doc = run_data(parse_toml(BASE)).document()
    assert doc["units"]["results.supports[].slope"] == "arcmin"
    assert len(doc["results"]["sections"]) == len(doc["results"]["fatigue"])
    labels = [s["label"] for s in doc["results"]["sections"]]
    assert "step 1|2" in labels and "step 2|3" in labels
    x = doc["results"]["diagrams"]["x"]
    assert x[0] == 0.0 and x[-1] == pytest.approx(180.0)
    assert ARCMIN > 0


def test_unloaded_shaft_passes_with_unbounded_safeties():
    """Only a mass on the shaft: no stress anywhere; the safeties are unbounded (null in
    JSON), the checks pass, the critical speed is computed."""
    from geardesign.core.spec import parse_toml

    data = parse_toml(BASE)
    data["load"] = [{"position": 80.0, "mass": 5.0}]
    doc = run_data(data).document()
    assert doc["verdict"] == "pass"
    fat = next(c for c in doc["checks"] if c["code"] == "FATIGUE")
    assert fat["passed"] and fat["value"] is None
    assert doc["results"]["shaft"]["n_cr"] > 0


def test_soft_supports_against_a_stiff_shaft_are_refused_or_computed(tmp_path):
    """A spring support of 1e-6 N/mm under a stiff shaft either computes (the shaft floats
    on its springs) or is refused with one line; never another error."""
    text = BASE.replace("position = 20.0", "position = 20.0\nstiffness = 1e-6").replace(
        "position = 140.0", "position = 140.0\nstiffness = 1e-6")
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code in (0, 1, 2) and "Traceback" not in err


def _doc(text):
    from geardesign.core.spec import parse_toml

    return run_data(parse_toml(text)).document()


def _check(doc, code):
    return [c for c in doc["checks"] if c["code"] == code]


def test_hardness_below_the_grade_is_refused(tmp_path):
    assert run_bad(tmp_path, BASE.replace("hardness_HB = 270.0", "hardness_HB = 150.0")) == [
        "s.toml: material.hardness_HB = 150.0: below the lowest hardness listed for steel "
        "45 (200 HB); give sigma_B and sigma_T instead"]


def test_grade_rows_by_hardness_and_cyrillic_name():
    doc = _doc(BASE.replace('grade = "45"', 'grade = "40Х"').replace(
        "hardness_HB = 270.0", "hardness_HB = 250.0"))
    m = doc["results"]["material"]
    assert (m["sigma_B"], m["sigma_T"], m["sigma_m1"], m["tau_m1"]) == (800.0, 650.0, 360.0,
                                                                         210.0)
    assert m["alloy"] is True


def test_estimates_without_endurance_limits():
    doc = _doc(BASE.replace('grade = "45"\nhardness_HB = 270.0',
                            "sigma_B = 700.0\nsigma_T = 400.0"))
    m = doc["results"]["material"]
    assert m["sigma_m1"] == pytest.approx(0.43 * 700)
    assert m["tau_m1"] == pytest.approx(0.58 * 0.43 * 700)
    assert m["psi_sigma"] == pytest.approx(0.16) and m["psi_tau"] == pytest.approx(0.08)


def test_strength_beyond_the_tables_warns():
    doc = _doc(BASE.replace('grade = "45"\nhardness_HB = 270.0',
                            "sigma_B = 1500.0\nsigma_T = 1200.0"))
    w = _check(doc, "FACTOR_TABLE_RANGE")
    assert w and not w[0]["passed"] and "σ_B = 1500 MPa" in w[0]["message"]
    assert not _check(_doc(BASE), "FACTOR_TABLE_RANGE")


def test_bearing_tilt_between_the_limits_warns():
    """A deep groove ball bearing: 2′ warns, 10′ fails; find a load that gives a slope in
    between and check the severity."""
    text = BASE.replace("position = 20.0", 'position = 20.0\ntype = "deep_groove_ball"')
    doc = _doc(text.replace("Fy = 3000.0", "Fy = 60000.0"))
    tilt = _check(doc, "BEARING_TILT")[0]
    assert 2.0 < tilt["value"] <= 10.0
    assert not tilt["passed"] and tilt["severity"] == "warning"


def test_heavy_fast_rotor_fails_the_critical_speed(tmp_path):
    text = BASE.replace("speed = 200.0", "speed = 20000.0").replace(
        "Fy = 3000.0", "Fy = 3000.0\nmass = 500.0")
    doc = run_failing(tmp_path, text)
    c = _check(doc, "CRITICAL_SPEED")[0]
    assert not c["passed"] and "stiffen the shaft" in c["message"]
    assert doc["results"]["shaft"]["n_cr"] == pytest.approx(c["value"] * 20000.0)


def test_gear_deflection_limit():
    text = BASE.replace("Fy = 3000.0", "Fy = 3000.0\nmodule = 0.3")
    c = _check(_doc(text), "GEAR_DEFLECTION")[0]
    assert c["limit"] == pytest.approx(0.003)
    assert c["passed"] == (c["value"] <= 0.003)
    c = _check(_doc(text.replace("Fy = 3000.0", "Fy = 30000.0")), "GEAR_DEFLECTION")[0]
    assert not c["passed"] and c["severity"] == "warning"


def test_reactions_agree_with_the_drive_statics():
    """The drive's two-bearing statics (geardesign.drive.shafts) and the beam model give the
    same bearing reactions for gears with radial, tangential and axial forces (the axial
    force at the pitch radius acts as a couple).  Axes: drive (x, y, z = shaft axis) ->
    shaft (y, z, x); a moment about the drive's y is the shaft's moment_y, about its x
    minus the shaft's moment_z."""
    from geardesign.drive.shafts import GearLoad, gear_force, reactions

    gears = [GearLoad(4480.0, 1680.0, 1120.0, 125.0, 80.0, math.radians(30.0), False, 1),
             GearLoad(9000.0, 3300.0, 2000.0, 40.0, 190.0, math.radians(200.0), True, -1)]
    zA, zB, L = 20.0, 150.0, 230.0
    ref = reactions(zA, zB, gears, rotation=1)
    loads = []
    for g in gears:
        (fx, fy, fz), (px, py, pz) = gear_force(g, 1)
        loads.append(Load(pz, Fy=fx, Fz=fy, Fx=fz, moment_y=-px * fz / 1e3,
                          moment_z=-py * fz / 1e3))
    r = analyse([Step(L, 50.0)], loads, [Support(zA), Support(zB)], MAT)
    A, B = r.supports
    assert (A.R_y, A.R_z) == pytest.approx(ref.R_A, rel=1e-9, abs=1e-6)
    assert (B.R_y, B.R_z) == pytest.approx(ref.R_B, rel=1e-9, abs=1e-6)
    assert abs(A.R_x) == pytest.approx(ref.axial, rel=1e-12)
