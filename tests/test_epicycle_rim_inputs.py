"""Bad input of the epicycle_rim calculator: one line per problem naming file, key, value
and what is allowed; exit 2; no traceback; nothing on stdout.  One case per rule: single-key
rules from the schema, rules across keys from the calculator."""

import pytest

from tests.helpers_cli import cli, cli_process, run_bad

GOOD = '''kind = "epicycle_rim"
[ring]
module = 3.25
z = 64
face_width = 60.0
rim_thickness = 8.0
tooth_height = 7.3
[planets]
count = 3
z_sun = 26
z_planet = 19
contact_ratio = 1.42
[fillet]
root_chord = 9.0
radius = 0.2
radius_tolerance = 0.06
roughness = 25.0
[material]
grade = "30KhGSA"
blank_size = 34.0
[load]
bending_stress = 259.3
form_factor = 3.3
load_sharing = 1.4
hoop_stress_loaded = -72.5
hoop_stress_between = 51.6
[[stage]]
name = "acceleration"
tension_fillet = "right"
mu_F = 0.606
[[stage]]
name = "ed_braking"
tension_fillet = "left"
mu_F = 0.549
[fatigue]
concentrator_depth = 0.635
[vehicle]
wheel_radius = 500.0
speed_range = [5.0, 55.0]
[resonance]
natural_frequencies = [2233.0, 3770.0]
'''


def cut(text, table):
    """The spec without the table starting with the line ``table``."""
    out, skip = [], False
    for line in text.splitlines(keepends=True):
        if line.startswith("["):
            skip = line.strip() == table
        if not skip:
            out.append(line)
    return "".join(out)


def rep(old, new, text=GOOD):
    assert old in text, old
    return text.replace(old, new, 1)


CASES = {
    "ring z": rep("z = 64", "z = 5"),
    "planet count": rep("count = 3", "count = 1"),
    "contact ratio": rep("contact_ratio = 1.42", "contact_ratio = 1.0"),
    "mu_F": rep("mu_F = 0.606", "mu_F = 1.2"),
    "grade": rep('grade = "30KhGSA"', 'grade = "30HGSA"'),
    "probabilities": rep("concentrator_depth = 0.635", "concentrator_depth = 0.635\nprobabilities = [50.0, 100.0]"),
    "orders": rep("[resonance]\n", "[resonance]\norders = [0, 1]\n"),
    "shift range": rep("contact_ratio = 1.42", "contact_ratio = 1.42\nshifts = [1.5, -0.5, -1.0]"),
    "fillet side": rep('tension_fillet = "right"', 'tension_fillet = "middle"'),
    "fatigue exponent": rep("load_sharing = 1.4", "load_sharing = 1.4\nfatigue_exponent = 7"),
    "nothing": 'kind = "epicycle_rim"\n' + GOOD.split('kind = "epicycle_rim"\n')[1].split("[fillet]")[0],
    "partial fatigue": cut(GOOD, "[material]"),
    "fatigue options alone": cut(cut(cut(cut(GOOD.replace("[[stage]]", "[stagex]"), "[fillet]"), "[material]"), "[load]"), "[stagex]"),
    "z_sun alone": rep("z_planet = 19\n", ""),
    "coaxiality": rep("z_planet = 19", "z_planet = 17"),
    "angles and shifts": rep("contact_ratio = 1.42", "contact_ratio = 1.42\nangles = [0.0, 120.0, 240.0]\nshifts = [0.4, 0.2, -0.6]"),
    "angles count": rep("contact_ratio = 1.42", "contact_ratio = 1.42\nangles = [0.0, 180.0]"),
    "shifts count": rep("contact_ratio = 1.42", "contact_ratio = 1.42\nshifts = [0.4, -0.4]"),
    "shifts sum": rep("contact_ratio = 1.42", "contact_ratio = 1.42\nshifts = [0.4, 0.2, -0.5]"),
    "fillet radius": rep("radius = 0.2", "radius = 4.5"),
    "no strength": rep('grade = "30KhGSA"', 'sigma_u = 717.0\nsigma_y = 550.0'),
    "yield above ultimate": rep('grade = "30KhGSA"', 'grade = "30KhGSA"\nsigma_y = 800.0'),
    "endurance above ultimate": rep('grade = "30KhGSA"', 'grade = "30KhGSA"\nsigma_m1 = 800.0'),
    "nu negative": rep('grade = "30KhGSA"', 'grade = "30KhGSA"\nsigma_u = 1500.0'),
    "two bending inputs": rep("load_sharing = 1.4", "load_sharing = 1.4\nnominal_bending_stress = 78.6"),
    "no form factor": rep("form_factor = 3.3\n", ""),
    "hoop missing": rep("hoop_stress_between = 51.6\n", ""),
    "pressure angle unused": rep("load_sharing = 1.4", "load_sharing = 1.4\npressure_angle = 20.0"),
    "thin ring with hoop": rep("load_sharing = 1.4", 'load_sharing = 1.4\nhoop_source = "thin_ring"\nring_torque = 4023.0'),
    "thin ring no torque": rep("hoop_stress_loaded = -72.5\nhoop_stress_between = 51.6\n", 'hoop_source = "thin_ring"\n'),
    "stage name": rep('name = "ed_braking"', 'name = "ED braking"'),
    "stage twice": rep('name = "ed_braking"', 'name = "acceleration"'),
    "two mode inputs": rep("mu_F = 0.549", 'mu_F = 0.549\nmode = "light"'),
    "no mode input": rep("mu_F = 0.549\n", ""),
    "fractions without levels": rep("mu_F = 0.549", "mu_F = 0.549\ntime_fractions = [1.0]"),
    "fractions count": rep("mu_F = 0.549", "torque_levels = [1.0, 0.5]\ntime_fractions = [1.0]"),
    "levels without fractions": rep("mu_F = 0.549", "torque_levels = [1.0, 0.5]"),
    "shares": rep("mu_F = 0.549", "mu_F = 0.549\ndistance_share = 0.7", rep("mu_F = 0.606", "mu_F = 0.606\ndistance_share = 0.5")),
    "no gradient": rep("concentrator_depth = 0.635", 'mean_stress_model = "cubic"'),
    "gradient twice": rep("concentrator_depth = 0.635", "concentrator_depth = 0.635\nstress_gradient = 13.0"),
    "quantile": rep("concentrator_depth = 0.635", "concentrator_depth = 0.635\nscatter_total = 0.5\nprobabilities = [50.0, 99.0]"),
    "required quantile": rep("concentrator_depth = 0.635", "concentrator_depth = 0.635\nscatter_total = 0.5\nrequired_probability = 99.5"),
    "resonance without eps": rep("contact_ratio = 1.42\n", ""),
    "speed range": rep("speed_range = [5.0, 55.0]", "speed_range = [55.0, 5.0]"),
    "sun-planet geometry": rep("module = 3.25\nz = 64", "module = 3.25\nz = 18").replace("z_sun = 26\nz_planet = 19", "z_sun = 6\nz_planet = 6\nx_sun = -1.0\nx_planet = -1.0"),
}
EXPECTED = {
    'ring z': [
        's.toml: ring.z = 5: must be an integer >= 12 and <= 1000',
    ],
    'planet count': [
        's.toml: planets.count = 1: must be an integer >= 2 and <= 12',
    ],
    'contact ratio': [
        's.toml: planets.contact_ratio = 1.0: must be a number > 1 and <= 4',
    ],
    'mu_F': [
        's.toml: stage[0].mu_F = 1.2: must be a number >= 0.01 and <= 1',
    ],
    'grade': [
        's.toml: material.grade = "30HGSA": must be one of "30KhGSA" (did you mean "30KhGSA"?)',
    ],
    'probabilities': [
        's.toml: fatigue.probabilities = [50.0, 100.0]: must be a list of 1 to 20 numbers >= 50 and < 100 (%)',
    ],
    'orders': [
        's.toml: resonance.orders = [0, 1]: must be a list of 1 to 30 integers >= 1 and <= 30',
    ],
    'shift range': [
        's.toml: planets.shifts = [1.5, -0.5, -1.0]: must be a list of 2 to 12 numbers >= -1 and <= 1',
    ],
    'fillet side': [
        's.toml: stage[0].tension_fillet = "middle": must be one of "left", "right"',
    ],
    'fatigue exponent': [
        's.toml: load.fatigue_exponent = 7: must be one of 6, 9',
    ],
    'nothing': [
        's.toml: nothing to compute: give the fatigue tables ([fillet], [material], [load], [[stage]]) or [resonance], or both',
    ],
    'partial fatigue': [
        's.toml: material: missing table [material]: the fatigue analysis (started by [fillet]) needs [fillet], [material], [load] and [[stage]]',
    ],
    'fatigue options alone': [
        's.toml: fatigue: applies to the fatigue analysis, which needs [fillet], [material], [load] and [[stage]]; remove [fatigue] or add them',
    ],
    'z_sun alone': [
        's.toml: planets.z_planet: missing: give both z_sun and z_planet (or neither)',
    ],
    'coaxiality': [
        's.toml: ring.z = 64: does not fit the planets: z_sun + 2·z_planet = 60 (coaxial trains need z_r = z_s + 2·z_p, ±2 with profile shifts)',
    ],
    'angles and shifts': [
        's.toml: planets.shifts = [0.4, 0.2, -0.6]: give planets.angles or planets.shifts, not both',
    ],
    'angles count': [
        's.toml: planets.angles = [0.0, 180.0]: must list 3 angles (planets.count = 3)',
    ],
    'shifts count': [
        's.toml: planets.shifts = [0.4, -0.4]: must list 3 shifts (planets.count = 3)',
    ],
    'shifts sum': [
        's.toml: planets.shifts = [0.4, 0.2, -0.5]: must sum to 0 (the spacings add up to 360°); the sum is 0.1',
    ],
    'fillet radius': [
        's.toml: fillet.radius = 4.5: must be less than half the root chord S/2 = 4.5 mm',
    ],
    'no strength': [
        's.toml: material.sigma_m1: missing: give the endurance limit or a material.grade',
    ],
    'yield above ultimate': [
        's.toml: material.sigma_y = 800.0: must be below sigma_u = 717 MPa',
    ],
    'endurance above ultimate': [
        's.toml: material.sigma_m1 = 800.0: must be below sigma_u = 717 MPa',
    ],
    'nu negative': [
        's.toml: material.sigma_u = 1500.0: must be < 1475 MPa: the sensitivity ν_σ = 0.211 − 0.000143·σ_u of GOST 25.504-82 is <= 0 above',
    ],
    'two bending inputs': [
        's.toml: load.nominal_bending_stress = 78.6: give either nominal_bending_stress or bending_stress with form_factor, not both',
    ],
    'no form factor': [
        's.toml: load.form_factor: missing: give bending_stress with form_factor, or nominal_bending_stress',
    ],
    'hoop missing': [
        's.toml: load.hoop_stress_between: missing: give both hoop stresses, or hoop_source = "thin_ring" with ring_torque',
    ],
    'pressure angle unused': [
        's.toml: load.pressure_angle = 20.0: applies only with hoop_source = "thin_ring"; remove it',
    ],
    'thin ring with hoop': [
        's.toml: load.hoop_stress_loaded = -72.5: not used with hoop_source = "thin_ring" (the estimate replaces it); remove it',
    ],
    'thin ring no torque': [
        's.toml: load.ring_torque: missing: hoop_source = "thin_ring" needs the ring torque',
    ],
    'stage name': [
        's.toml: stage[1].name = "ED braking": must be a lower-case name of letters, digits and _ starting with a letter (it names the result keys), e.g. "ed_braking"',
    ],
    'stage twice': [
        's.toml: stage[1].name = "acceleration": used twice; stage names must differ',
    ],
    'two mode inputs': [
        's.toml: stage[1]: give exactly one of mu_F, mode, or torque_levels with time_fractions (given: mu_F, mode)',
    ],
    'no mode input': [
        's.toml: stage[1]: give exactly one of mu_F, mode, or torque_levels with time_fractions',
    ],
    'fractions without levels': [
        's.toml: stage[1].time_fractions = [1.0]: applies only with torque_levels',
    ],
    'fractions count': [
        's.toml: stage[1].time_fractions = [1.0]: must list one duration per torque level (2)',
    ],
    'levels without fractions': [
        's.toml: stage[1].time_fractions: missing: give the duration of each torque level',
    ],
    'shares': [
        's.toml: stage.distance_share = [0.5, 0.7]: the shares sum to 1.2; they must not exceed 1',
    ],
    'no gradient': [
        's.toml: fatigue.concentrator_depth: missing: give the depth of the concentrator t, or the stress_gradient G directly',
    ],
    'gradient twice': [
        's.toml: fatigue.concentrator_depth = 0.635: not used when stress_gradient is given; remove one of them',
    ],
    'quantile': [
        's.toml: fatigue.probabilities = [50.0, 99.0]: P = 99 % makes σ_-1D(P) = σ_-1D·(1 − z_P·v) <= 0 with v = 0.5; use P < 97.72 %',
    ],
    'required quantile': [
        's.toml: fatigue.required_probability = 99.5: P = 99.5 % makes σ_-1D(P) = σ_-1D·(1 − z_P·v) <= 0 with v = 0.5; use P < 97.72 %',
    ],
    'resonance without eps': [
        's.toml: planets.contact_ratio: missing: [resonance] needs the transverse contact ratio of the ring-planet mesh',
    ],
    'speed range': [
        's.toml: vehicle.speed_range = [55.0, 5.0]: must be [lowest, highest] with lowest < highest',
    ],
    'sun-planet geometry': [
        's.toml: planets.x_planet = -1.0: no sun-planet pair with these shifts (inv α_tw = -0.106419 <= 0); check x_sun and x_planet',
    ],
}


@pytest.mark.parametrize("name", CASES)
def test_one_line_per_problem(tmp_path, name):
    assert run_bad(tmp_path, CASES[name]) == EXPECTED[name]


def test_good_spec_is_usable(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(GOOD, encoding="utf-8")
    code, out, err = cli("validate", path)
    assert code == 0 and out.strip().endswith("s.toml: ok (epicycle_rim)")


def test_no_traceback_in_a_real_process(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(CASES["shifts sum"], encoding="utf-8")
    proc = cli_process("run", path)
    assert proc.returncode == 2 and proc.stdout == "" and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1
