"""Bad input: one line per problem naming file, key, value and what is allowed; exit 2;
no traceback; nothing written."""

import pytest

from geardesign.core.registry import KINDS
from tests.helpers_cli import cli, cli_process, run_bad, write_spec as spec

KNOWN = ", ".join(f'"{k}"' for k in KINDS)

GOOD = """kind = "spur"
[gear]
module = 2.0
z1 = 20
z2 = 40
face_width = 20.0
"""


def replace(old, new):
    assert old in GOOD
    return GOOD.replace(old, new)


CASES = [
    ("missing key", replace("z1 = 20\n", ""),
     ["s.toml: gear.z1: missing; required: an integer >= 5 and <= 1000 "
      "(number of teeth, pinion)"]),
    ("unknown key", replace("module = 2.0", "modul = 2.0"),
     ['s.toml: gear.modul = 2.0: unknown key in [gear] (did you mean "module"?)',
      "s.toml: gear.module: missing; required: a number >= 0.05 and <= 100 (mm) (normal module)"]),
    ("z1 = 3", replace("z1 = 20", "z1 = 3"),
     ["s.toml: gear.z1 = 3: must be an integer >= 5 and <= 1000"]),
    ("z1 not an integer", replace("z1 = 20", "z1 = 20.5"),
     ["s.toml: gear.z1 = 20.5: must be an integer >= 5 and <= 1000"]),
    ("z1 a string", replace("z1 = 20", 'z1 = "20"'),
     ['s.toml: gear.z1 = "20": must be an integer >= 5 and <= 1000']),
    ("negative module", replace("module = 2.0", "module = -2.0"),
     ["s.toml: gear.module = -2.0: must be a number >= 0.05 and <= 100 (mm)"]),
    ("helix angle 45", GOOD + "helix_angle = 45.0\n",
     ["s.toml: gear.helix_angle = 45.0: must be a number >= 0 and < 45 (deg)"]),
    ("pressure angle 40", GOOD + "pressure_angle = 40\n",
     ["s.toml: gear.pressure_angle = 40: must be a number > 10 and < 35 (deg)"]),
    ("shift out of range", GOOD + "x1 = 3.0\n",
     ["s.toml: gear.x1 = 3.0: must be a number >= -1 and <= 2"]),
    ("x too negative: inv α_tw <= 0",
     replace("z1 = 20\nz2 = 40", "z1 = 10\nz2 = 10\nx1 = -1.0\nx2 = -1.0"),
     ["s.toml: gear.x1 + gear.x2 = -2.0: too negative: inv α_tw = -0.0578897 <= 0, no working "
      "pressure angle exists; x1 + x2 must be > -0.4095"]),
    ("centre distance smaller than possible", GOOD + "center_distance = 55.0\n",
     ["s.toml: gear.center_distance = 55.0: smaller than possible: must exceed "
      "(d_b1 + d_b2)/2 = 56.3816 mm, where the base circles touch (x1 + x2 = 0 gives "
      "a_w = 60 mm)"]),
    ("shifts disagree with centre distance", GOOD + "center_distance = 61.0\nx1 = 0.3\nx2 = 0.3\n",
     ["s.toml: gear.x1 + gear.x2 = 0.6: does not match center_distance = 61 mm, which needs "
      "x1 + x2 = 0.5298; give x1 or x2 only and the other follows"]),
    ("split without centre distance", GOOD + 'shift_split = "equal"\n',
     ['s.toml: gear.shift_split = "equal": applies only with gear.center_distance; remove it '
      "or give center_distance"]),
    ("bad choice", GOOD + 'center_distance = 61.0\nshift_split = "slidng"\n',
     ['s.toml: gear.shift_split = "slidng": must be one of "sliding", "equal" '
      '(did you mean "sliding"?)']),
    ("tip inside base circle", replace("z1 = 20\nz2 = 40",
             "z1 = 8\nz2 = 80\nx1 = -1.0\nx2 = 0.3\npressure_angle = 14.5"),
     ["s.toml: gear.x1 = -1.0: the tip circle of gear 1 (d_a = 15.4528 mm) lies inside its "
      "base circle (d_b = 15.4904 mm): no involute flank; increase x1 or z1"]),
    ("missing table", 'kind = "spur"\n',
     ["s.toml: give exactly one of [gear] (gear pair (external or internal, spur or helical)) or [design] "
      "(design mode: propose a pair for the load, then check it); the spec has neither"]),
    ("table given a value", GOOD.replace('kind = "spur"\n', 'kind = "spur"\nload = 5\n'),
     ["s.toml: load = 5: must be a table [load] (operating data)"]),
    ("unknown top-level key", GOOD.replace('kind = "spur"\n', 'kind = "spur"\ntitel = "x"\n'),
     ['s.toml: titel = "x": unknown key in the top level (did you mean "title"?)']),
    ("unknown kind", GOOD.replace('"spur"', '"spurr"'),
     ['s.toml: kind = "spurr": unknown calculator (did you mean "spur"?); known: ' + KNOWN]),
    ("no kind", GOOD.replace('kind = "spur"\n', ""),
     ['s.toml: kind: missing; required: one of ' + KNOWN + ' (the calculator)']),
    ("negative speed", GOOD + "[load]\nspeed1 = -100.0\n",
     ["s.toml: load.speed1 = -100.0: must be a number >= 0.001 and <= 1000000 (min^-1)"]),
    ("not TOML", "kind = spur\n",
     ["s.toml: not valid TOML: Invalid value (at line 1, column 8)"]),
]


@pytest.mark.parametrize("name, text, expected", CASES, ids=[c[0] for c in CASES])
def test_one_line_per_problem(tmp_path, name, text, expected):
    assert run_bad(tmp_path, text) == expected


def test_missing_file(tmp_path):
    code, out, err = cli("run", tmp_path / "nope.toml")
    assert code == 2 and out == ""
    assert err.strip().endswith("nope.toml: file not found")


def test_not_utf8(tmp_path):
    path = tmp_path / "s.toml"
    path.write_bytes(b'kind = "spur"\ntitle = "\xff"\n')
    code, _, err = cli("validate", path)
    assert code == 2 and "not UTF-8 text" in err


def test_every_problem_of_a_file_is_listed(tmp_path):
    lines = run_bad(tmp_path, replace("z1 = 20\nz2 = 40", "z1 = 3\nz2 = 2\nzz = 1"))
    assert len(lines) == 3
    assert lines[0].startswith("s.toml: gear.zz = 1: unknown key")


def test_nothing_written_on_bad_input(tmp_path):
    out = tmp_path / "report.json"
    out.write_text("old", encoding="utf-8")
    bad = spec(tmp_path, replace("z1 = 20", "z1 = 3"))
    good = spec(tmp_path, GOOD, "good.toml")
    code, stdout, _ = cli("run", good, bad, "--output", out)
    assert code == 2 and stdout == ""
    assert out.read_text(encoding="utf-8") == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["good.toml", "report.json", "s.toml"]


def test_validate_reports_the_same_rules(tmp_path):
    path = spec(tmp_path, GOOD + "center_distance = 55.0\n")
    code, out, err = cli("validate", path)
    assert code == 2 and out == "" and "smaller than possible" in err
    code, out, err = cli("validate", spec(tmp_path, GOOD, "ok.toml"))
    assert code == 0 and out.strip().endswith("ok.toml: ok (spur)")


def test_no_traceback_in_a_real_process(tmp_path):
    path = spec(tmp_path, "kind = [1, 2\n")
    proc = cli_process("run", path)
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1


def test_centre_distance_beyond_any_shift(tmp_path):
    lines = run_bad(tmp_path, GOOD + "center_distance = 2000.0\n")
    assert lines == ["s.toml: gear.center_distance = 2000.0: needs x1 + x2 = 2794.266, outside "
                     "what two shifts of −1…2 can give (-2…4); choose a_w nearer to a = 60 mm"]
