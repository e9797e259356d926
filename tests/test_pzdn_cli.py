"""pzdn through the command line and as a library: template and schema, the cold process
imports nothing heavy outside the start-up integration, the start-up options (motor
characteristic, torque rise, damping, sticking), and the optional plot."""

import json
import subprocess
import sys
import tomllib

import pytest

from geardesign.core.registry import run_data
from tests.conftest import ROOT, SPECS
from tests.helpers_cli import cli

D1 = {"T1": 26.5, "T2": 4.4, "T3": 17.7, "J1": 0.038, "J2": 0.026, "J3": 0.021,
      "C12": 8.33, "C13": 25.0}


def test_template_is_a_valid_spec(tmp_path):
    code, text, _ = cli("template", "pzdn")
    assert code == 0
    path = tmp_path / "t.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    for section in ("spring1", "spring2", "coupling_gear", "coupling_gear_rating", "startup_model",
                    "closed_form", "ode", "startup_comparison", "startup_sweep"):
        assert section in doc["results"]
    # the KO-2 regression is fitted to that drive only: the template names it in a comment
    # (specs/pzdn_ko2_regression.toml reproduces it)
    assert "# [regression]" in text and "regression" not in doc["results"]


def test_schema_accepts_the_template():
    jsonschema = pytest.importorskip("jsonschema")
    _, schema, _ = cli("schema", "pzdn")
    _, template, _ = cli("template", "pzdn")
    jsonschema.validate(tomllib.loads(template), json.loads(schema))


def test_no_numpy_scipy_outside_the_integration():
    """Springs, regression, the closed form and the coupling gear run without numpy and
    scipy (one cold process computes all those golden specs)."""
    specs = [str(SPECS / f"{n}.toml") for n in (
        "pzdn_ko2_one_spring", "pzdn_ko2_two_springs", "pzdn_ko2_regression",
        "pzdn_ko2_startup_closed_form", "pzdn_ko2_coupling_gear")]
    code = ("import sys\nfrom geardesign.cli import main\nsys.argv = ['geardesign', 'run', *%r, "
            "'--format', 'json', '--quiet']\ntry:\n    main()\nexcept SystemExit as e:\n"
            "    assert e.code == 0, e.code\n"
            "heavy = [m for m in ('numpy', 'scipy', 'matplotlib') if m in sys.modules]\n"
            "assert not heavy, heavy\n" % specs)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert p.returncode == 0, p.stderr


def _startup(**extra):
    data = dict(D1, t_end=1.0, history_points=0)
    data.update(extra)
    return run_data({"kind": "pzdn", "startup": data}).document()


def test_torque_rise_and_damping_lower_the_peaks():
    step = _startup(method="ode", stick=False)["results"]["ode"]
    ramp = _startup(method="ode", stick=False, rise_time=0.05)["results"]["ode"]
    damped = _startup(method="ode", stick=False, damping_ratio=0.2)["results"]["ode"]
    assert ramp["T12max"] < step["T12max"] and ramp["T13max"] < step["T13max"]
    assert damped["T12max"] < step["T12max"] and damped["T13max"] < step["T13max"]
    assert damped["damping"][0] > 0


def test_motor_characteristics():
    """A Kloss characteristic and a tabulated curve reach the synchronous-speed region and
    give finite peaks; with a flat curve equal to T1 the result is the constant-torque one."""
    kloss = _startup(method="ode", motor_model="kloss", kloss_max_torque=48.6,
                     kloss_critical_slip=0.25, synchronous_speed=1000.0, t_end=3.0)
    o = kloss["results"]["ode"]
    assert 0 < o["final_speeds"][0] < 1000.0 * 3.14159 / 30.0
    flat = _startup(method="ode", motor_model="curve", curve_speed=[0.0, 2000.0],
                    curve_torque=[26.5, 26.5])["results"]["ode"]
    const = _startup(method="ode")["results"]["ode"]
    assert flat["T12max"] == pytest.approx(const["T12max"], rel=1e-9)
    assert flat["T13max"] == pytest.approx(const["T13max"], rel=1e-9)


def test_sticking_lowers_the_peaks_of_the_linear_model():
    doc = _startup(method="both", t_end=2.0)
    o, c = doc["results"]["ode"], doc["results"]["closed_form"]
    assert o["sticks"][1] >= 1
    assert o["T13max"] < c["T13max_t"]
    agree = next(x for x in doc["checks"] if x["code"] == "METHODS_AGREE")
    assert agree["severity"] == "info"


def test_mass_three_first_is_reported():
    doc = _startup(method="closed_form", C12=6.25, C13=33.3)
    c = doc["results"]["closed_form"]
    assert c["order"] == "3 first" and c["t_break"][1] < c["t_break"][0]
    branch = next(x for x in doc["checks"] if x["code"] == "CLOSED_FORM_BRANCH")
    assert not branch["passed"] and "general form" in branch["message"]


def test_history_arrays_and_no_nan():
    doc = _startup(method="both", history_points=11)
    h = doc["results"]["history"]
    assert len(h["t"]) == len(h["T12"]) == len(h["omega3"]) == 11
    assert doc["units"]["results.history.T12"] == "N·m"
    text = json.dumps(doc, allow_nan=False)
    assert "NaN" not in text


def test_plot_needs_matplotlib(tmp_path, monkeypatch):
    """Without matplotlib the plot key is an input problem with a clear line, exit 2."""
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    spec = tmp_path / "s.toml"
    spec.write_text('kind = "pzdn"\n[startup]\n' + "".join(f"{k} = {v}\n" for k, v in D1.items())
                    + 't_end = 0.5\nmethod = "closed_form"\nplot = "start.png"\n',
                    encoding="utf-8")
    code, out, err = cli("run", spec, "--format", "json")
    assert code == 2 and out == ""
    assert err.strip().replace(str(spec), "s.toml") == (
        's.toml: startup.plot = "start.png": matplotlib is not installed, so no plot can be '
        "written; install it with `pip install matplotlib` (an optional extra of geardesign), "
        "or leave the plot out")
    assert not (tmp_path / "start.png").exists()


def test_write_plot_without_matplotlib_raises(monkeypatch, tmp_path):
    from geardesign.pzdn.plot import PlotError, write_plot

    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(PlotError, match="matplotlib is not installed"):
        write_plot({"t": [0.0, 1.0], "T12": [0.0, 1.0], "T13": [0.0, 2.0]}, tmp_path / "x.png")
    with pytest.raises(PlotError, match="must end in .png or .svg"):
        write_plot({"t": [0.0, 1.0], "T12": [0.0, 1.0], "T13": [0.0, 2.0]}, tmp_path / "x.pdf")


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_from_spec_key(tmp_path, suffix):
    pytest.importorskip("matplotlib")
    spec = tmp_path / "s.toml"
    spec.write_text('kind = "pzdn"\n[startup]\n' + "".join(f"{k} = {v}\n" for k, v in D1.items())
                    + f't_end = 0.5\nmethod = "closed_form"\nplot = "start{suffix}"\n',
                    encoding="utf-8")
    code, out, _ = cli("run", spec, "--format", "json")
    assert code == 0
    written = tmp_path / f"start{suffix}"
    assert written.exists() and written.stat().st_size > 1000
    assert json.loads(out)["results"]["history"]["plot_file"] == str(written)


def test_write_plot_from_a_result(tmp_path):
    pytest.importorskip("matplotlib")
    from geardesign.pzdn.plot import write_plot

    res = run_data({"kind": "pzdn", "startup": dict(D1, t_end=0.5, method="closed_form")})
    path = write_plot(res, tmp_path / "r.svg")
    assert path.read_text(encoding="utf-8").lstrip().startswith("<?xml")
    path = write_plot(res.document(), tmp_path / "d.png")
    assert path.read_bytes()[:4] == b"\x89PNG"
