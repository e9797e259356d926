"""Never crash, never print garbage, never hang: each case found by fuzzing or by hand,
with its exact message and exit code (the property over all mutations is
``tests/test_fuzz_specs.py``)."""

from __future__ import annotations

import json
import os
import stat
import threading

import pytest

from tests.conftest import SPECS
from tests.helpers_cli import cli, run_bad, write_spec


def _spec(name: str, **replace: str) -> str:
    text = (SPECS / f"{name}.toml").read_text(encoding="utf-8")
    for old, new in replace.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _run(tmp_path, text: str, name: str = "s.toml"):
    code, out, err = cli("run", write_spec(tmp_path, text, name), "--format", "json")
    assert "Traceback" not in err and "internal error" not in err, err
    return code, out, err.replace(str(tmp_path / name), name)


def _no_bad_numbers(out: str) -> dict:
    doc = json.loads(out, parse_constant=lambda c: pytest.fail(f"{c} in JSON"))
    from tests.fuzz import bad_numbers

    assert bad_numbers(doc) is None
    return doc


# ------------------------------------------------------------------ the registry


@pytest.mark.parametrize("kind", ['["spur"]', "{}", "3"])
def test_kind_of_another_type_is_an_input_error(tmp_path, kind):
    lines = run_bad(tmp_path, f"kind = {kind}\n")
    assert len(lines) == 1
    assert lines[0].startswith("s.toml: kind = ") and ": must be one of " in lines[0]


# ------------------------------------------------------------------ files and size


def test_deeply_nested_array_is_refused(tmp_path):
    text = 'kind = "spur"\ntitle = ' + "[" * 3000 + "]" * 3000 + "\n"
    assert run_bad(tmp_path, text) == [
        "s.toml: arrays or tables nested too deeply to be a spec"]


def test_spec_over_the_size_limit_is_refused_before_parsing(tmp_path):
    text = 'kind = "spur"\ntitle = "' + "x" * (5 * 1024 * 1024) + '"\n'
    assert run_bad(tmp_path, text) == [
        "s.toml: cannot be used: larger than 4 MiB; a spec is a few kB"]


def test_long_title_and_long_array_are_refused(tmp_path):
    lines = run_bad(tmp_path, _spec("spur_plain", **{
        'title = "': 'title = "' + "x" * 2000}))
    assert len(lines) == 1 and lines[0].endswith("must be a string of at most 1000 characters")


def test_many_unknown_keys_give_a_bounded_answer(tmp_path):
    extra = "".join(f"k{i} = 1\n" for i in range(5000))
    lines = run_bad(tmp_path, _spec("spur_plain") + "\n[extra_table]\n" + extra)
    assert len(lines) <= 21


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_a_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "s.toml"
    os.mkfifo(fifo)
    result = {}

    def go():
        result["r"] = cli("run", fifo, "--format", "json")

    t = threading.Thread(target=go, daemon=True)
    t.start()
    t.join(10)
    assert not t.is_alive(), "reading a FIFO blocked"
    code, out, err = result["r"]
    assert code == 2 and err.strip().endswith("cannot be used: not a regular file")


def test_control_characters_are_escaped_in_error_lines(tmp_path):
    lines = run_bad(tmp_path, 'kind = "spur"\n"bad\\nkey\\u001b[31m" = "v\\u202ex"\n')
    assert any('bad\\x0akey\\x1b[31m = "v\\u202ex"' in line for line in lines), lines
    assert all("\x1b" not in line and "\u202e" not in line for line in lines)


def test_control_characters_in_the_title_do_not_reach_the_report(tmp_path):
    text = _spec("spur_plain").replace('title = "', 'title = "\\u001b[2J\\u202e')
    for fmt in ("table", "markdown"):
        code, out, err = cli("run", write_spec(tmp_path, text), "--format", fmt)
        assert code in (0, 1), err
        assert "\x1b" not in out and "\u202e" not in out
        if fmt == "markdown":          # as the reader sees it (backslashes are escaped)
            from markdown_it import MarkdownIt

            out = "".join(c.content for c in MarkdownIt("commonmark").parse(out)[1].children)
        assert "\\x1b[2J\\u202e" in out


# ------------------------------------------------------------------ drive stage files


DRIVE_HEAD = """kind = "drive"
[motor]
power = 1.5
speed = 1450.0
[load]
speed = 11.5
life_hours = 20000.0
"""


@pytest.mark.parametrize("name, message", [
    ("/etc/passwd", 'stage[0].file = "/etc/passwd": must be a path relative to the drive '
                    "spec's folder"),
    ("../outside.toml", 'stage[0].file = "../outside.toml": must be a file inside the drive '
                        "spec's folder"),
])
def test_stage_files_outside_the_spec_folder_are_refused(tmp_path, name, message):
    lines = run_bad(tmp_path, DRIVE_HEAD + f'[[stage]]\nfile = "{name}"\n')
    assert lines == [f"s.toml: {message}"]


def test_a_stage_file_that_is_a_device_is_refused(tmp_path):
    os.symlink("/dev/zero", tmp_path / "zero.toml")
    lines = run_bad(tmp_path, DRIVE_HEAD + '[[stage]]\nfile = "zero.toml"\n')
    assert lines == ['s.toml: stage[0].file = "zero.toml": must be a file inside the drive '
                     "spec's folder"]


@pytest.mark.parametrize("z1, expected", [
    ("0", "s.toml: stage[0]: gear.z1 = 0: must be an integer >= 1 and <= 1000"),
    ('"12"', 's.toml: stage[0]: gear.z1 = "12": must be an integer >= 1 and <= 1000'),
    ("[2]", "s.toml: stage[0]: gear.z1 = [2]: must be an integer >= 1 and <= 1000"),
])
def test_drive_worm_stage_tooth_numbers_are_checked_before_use(tmp_path, z1, expected):
    text = DRIVE_HEAD + f"""[[stage]]
kind = "worm"
[stage.gear]
module = 5.0
diameter_factor = 10.0
z1 = {z1}
z2 = 40
"""
    assert run_bad(tmp_path, text) == [expected]


def test_drive_stage_load_that_is_not_a_table(tmp_path):
    text = DRIVE_HEAD + """[[stage]]
kind = "spur"
[[stage.load]]
speed1 = 3.0
"""
    lines = run_bad(tmp_path, text)
    assert lines == ["s.toml: stage[0]: load = [... 1 items]: must be a table [load]"]


def test_drive_inline_planetary_operation_that_is_not_a_table(tmp_path):
    text = DRIVE_HEAD + '[[stage]]\nkind = "planetary"\noperation = 5\n'
    assert run_bad(tmp_path, text) == [
        "s.toml: stage[0]: operation = 5: must be a table [operation]"]


# ------------------------------------------------------------------ calculators


def test_bearing_iso_life_suggestion_with_catalogue_c_u(tmp_path):
    code, out, err = _run(tmp_path, """kind = "bearing"
method = "iso281_2007"
[bearing]
designation = "6208"
[load]
F_r = 6000.0
speed = 1000.0
[lubrication]
viscosity = 32.0
contamination = "normal"
[requirements]
life = 20000.0
""")
    assert code == 1
    doc = _no_bad_numbers(out)
    life = [c for c in doc["checks"] if c["code"] == "LIFE"][0]
    assert not life["passed"] and "use a bearing with C_r >=" in life["message"]


def test_ball_clutch_socket_angle_85_is_a_failed_check(tmp_path):
    code, out, _ = _run(tmp_path, _spec("ball_clutch_check", **{
        "socket_angle = 45.0": "socket_angle = 85.0"}))
    assert code == 1
    doc = _no_bad_numbers(out)
    assert any(c["code"] == "SELF_LOCKING" and not c["passed"] for c in doc["checks"])


def test_ball_clutch_limit_torques_never_negative(tmp_path):
    code, out, _ = _run(tmp_path, _spec("ball_clutch_check", **{"rate = 20.0": "rate = 1e-6"}))
    assert code == 1
    safety = _no_bad_numbers(out)["results"]["safety"]
    for key in ("T_lim", "T_lim_min", "T_lim_max", "T_lim_frictionless"):
        assert safety[key] == 0.0, key


def test_epicycle_rim_fatigue_coefficient_alpha(tmp_path):
    """10^α is the scatter of lg N at the endurance limit (0.01...1 decade): 2.5 is none."""
    assert run_bad(tmp_path, _spec("epicycle_rim_hardened", **{
        "[fatigue]": "[fatigue]\nslgn_alpha = 2.5"})) == [
        "s.toml: fatigue.slgn_alpha = 2.5: must be a number >= -2 and <= 0"]


def test_planetary_centre_distance_no_pair_of_shifts_can_reach(tmp_path):
    lines = run_bad(tmp_path, _spec("planetary_2kh_reducer", **{
        "module = 3.0": "module = 2.0"}))
    assert lines == ["s.toml: train.center_distance = 68.0: the teeth cannot reach it: it needs "
                     "shift.sun = 9.92, outside -1.5…3; the reference centre distance of the "
                     "sun–planet mesh is 45 mm (check the module)"]


def test_worm_at_the_highest_speed_gives_no_negative_allowable(tmp_path):
    code, out, _ = _run(tmp_path, _spec("worm_single_start_reducer", **{
        "speed1 = 1450.0": "speed1 = 100000.0"}))
    assert code == 1
    doc = _no_bad_numbers(out)
    assert doc["results"]["strength"]["sigma_HP"] > 0
    assert any(c["code"] == "SLIDING_SPEED" and not c["passed"] for c in doc["checks"])


def test_face_width_beyond_its_domain(tmp_path):
    lines = run_bad(tmp_path, _spec("spur_plain", **{"face_width = ": "face_width = 1e308 #"}))
    assert lines == ["s.toml: gear.face_width = 1e+308: must be a number >= 0.001 and "
                     "<= 100000 (mm)"]


def test_pzdn_start_up_beyond_the_resolved_periods_is_refused_at_once(tmp_path):
    lines = run_bad(tmp_path, _spec("pzdn_ko2_startup_closed_form", **{
        "J2 = 0.026": "J2 = 1e-9"}))
    assert len(lines) == 1
    assert lines[0].startswith("s.toml: startup: the start-up lasts 2 s and the stiffest mode")
    assert "more than the 5000 that are resolved in bounded time" in lines[0]


def test_bearing_spectrum_cost_is_linear(tmp_path):
    from tests.conftest import bounded_work

    blocks = "".join(f"[[load.spectrum]]\nF_r = {1000 + i}.0\nspeed = 1000.0\n"
                     f"time_share = 0.001\n" for i in range(1000))
    text = ('kind = "bearing"\nmethod = "gost18855_94"\n[bearing]\ndesignation = "6208"\n[requirements]\n'
            "life = 2000.0\n" + blocks)
    with bounded_work(0.15, "a spec of 1000 load blocks"):
        code, out, err = _run(tmp_path, text)
    assert code in (0, 1), err


def test_tiny_values_are_refused_not_divided_by(tmp_path):
    lines = run_bad(tmp_path, _spec("geneva_six_slot_table", **{
        "crank_speed = 60.0": "crank_speed = 5e-324"}))
    assert len(lines) == 1 and lines[0].startswith("s.toml: geneva.crank_speed = 5e-324: must be")


# ------------------------------------------------------------------ --output


def test_output_keeps_the_mode_of_an_existing_file(tmp_path):
    spec = write_spec(tmp_path, _spec("spur_plain"))
    out = tmp_path / "r.json"
    out.write_text("{}")
    os.chmod(out, 0o600)
    code, _, err = cli("run", spec, "--output", out)
    assert code in (0, 1), err
    assert stat.S_IMODE(os.stat(out).st_mode) == 0o600
    assert json.loads(out.read_text())["kind"] == "spur"


def test_output_through_a_symlink_replaces_the_target_and_keeps_the_link(tmp_path):
    spec = write_spec(tmp_path, _spec("spur_plain"))
    target = tmp_path / "target.json"
    target.write_text("{}")
    link = tmp_path / "link.json"
    link.symlink_to(target)
    code, _, err = cli("run", spec, "--output", link)
    assert code in (0, 1), err
    assert link.is_symlink() and json.loads(target.read_text())["kind"] == "spur"


def test_output_to_a_device_writes_it_directly(tmp_path):
    spec = write_spec(tmp_path, _spec("spur_plain"))
    code, _, err = cli("run", spec, "--output", "/dev/null", "--format", "json")
    assert code in (0, 1), err
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    assert not list(tmp_path.glob(".*.tmp"))


# ------------------------------------------------------------------ quantities with units


def test_quantities_with_units_are_converted_at_the_input_boundary(tmp_path):
    pytest.importorskip("pint")
    code, out, _ = _run(tmp_path, _spec("spur_reducer_through_hardened", **{
        "module = 4.0": 'module = "4 mm"', "torque1 = 520.0": 'torque1 = "520 kN*mm"'}))
    assert code in (0, 1)
    doc = json.loads(out)
    assert doc["inputs"]["gear"]["module"] == 4.0
    assert abs(doc["inputs"]["load"]["torque1"] - 520.0) < 1e-9


def test_a_quantity_of_the_wrong_dimension_is_refused(tmp_path):
    pytest.importorskip("pint")
    lines = run_bad(tmp_path, _spec("spur_reducer_through_hardened", **{
        "module = 4.0": 'module = "4 N"'}))
    assert lines == ['s.toml: gear.module = "4 N": must be a number >= 0.05 and <= 100 (mm), '
                     'or a quantity convertible to mm ("4 N" has another dimension)']


def test_pzdn_integration_has_its_own_bound(tmp_path):
    from tests.conftest import bounded_work

    with bounded_work(0.1, "refusing a start-up of 200 s"):
        lines = run_bad(tmp_path, _spec("pzdn_ko2_startup_comparison", **{
            'method = "both"': 'method = "both"\nt_end = 200.0'}))
    assert len(lines) == 1 and "resolved in bounded time by the integration" in lines[0]
