"""The HTML report without a browser: typesetting, governing margins, the order of the
first screen, the hierarchy of a drive, valid and escaped HTML, the PDF's refusal without
a browser, and no matplotlib on a cold run (the browser's view: test_report_browser.py)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from geardesign.core.registry import run_data
from geardesign.core.render import render
from geardesign.rendering.margins import margins
from geardesign.rendering.typeset import number_parts, symbol_html, unit_html, unit_text
from tests.conftest import SPECS
from tests.helpers_cli import cli_process


def _run(name: str):
    from geardesign.core.registry import load

    calc, spec = load(SPECS / f"{name}.toml")
    return calc.compute(spec)


@pytest.fixture(scope="module")
def drive():
    return _run("drive_reducer_shafts_keys_thermal")


@pytest.mark.parametrize("sym, html", [
    ("K_Hbeta", "K<sub>Hβ</sub>"), ("eps_alpha", "ε<sub>α</sub>"),
    ("S_H,st1", "S<sub>H,st1</sub>"), ("sigma_Hlim", "σ<sub>Hlim</sub>"),
    ("b_w/d_w1", "b<sub>w</sub>/d<sub>w1</sub>"), ("x_min1", "x<sub>min1</sub>"),
    ("<i>_x", "&lt;i&gt;<sub>x</sub>"), ("theta", "θ"), ("u", "u"), ("omega2", "ω2"),
    ("rotation_ring", "rotation_ring"), ("T_lim", "T<sub>lim</sub>")])
def test_symbols_are_typeset(sym, html):
    assert symbol_html(sym) == html


@pytest.mark.parametrize("unit, text", [
    ("mm^2/s", "mm²/s"), ("min^-1", "min⁻¹"), ("kg*m^2", "kg·m²"), ("deg", "°"),
    ("-", ""), ("N·m", "N·m"), ("W/(m^2·K)", "W/(m²·K)"), ("10^6 rev", "10⁶ rev"),
    ("MPa^0.5", "√MPa")])
def test_units_are_typeset(unit, text):
    assert unit_text(unit) == text


def test_fractional_powers_are_superscripts():
    assert unit_html("N/(mm·s^0.5·K)") == "N/(mm·s<sup>0.5</sup>·K)"


@pytest.mark.parametrize("value, unit, parts", [
    (147.5, "mm", ("147", ".500")), (1.31651, "-", ("1", ".317")), (988.78, "MPa", ("988", ".8")),
    (0.00012346, "-", ("0", ".0001235")), (1550275226.2, "h", ("1550275226", "")),
    (3e-9, "mm", ("3", ".000e-09")), (12, "mm", ("12", "")), (0.0, "mm", ("0", ""))])
def test_numbers_keep_the_precision_of_their_unit(value, unit, parts):
    assert number_parts(value, unit) == parts


def test_margins_read_safety_factors_and_checks(drive):
    ms = margins(drive)
    assert [m.ratio for m in ms] == sorted(m.ratio for m in ms)
    by = {m.label: m for m in ms}
    # a torque within its nominal: value <= limit; a life at least its requirement
    assert not by["MOTOR_TORQUE"].at_least and by["BEARING_1A"].at_least
    assert by["MOTOR_TORQUE"].ratio == pytest.approx(49.22317827584392 / 44.809505930980045)
    spur = margins(_run("spur_gost_vs_iso"))
    s_h1 = [m for m in spur if m.label == "S_H1"]
    assert {m.section for m in s_h1} == {"Contact fatigue", "ISO 6336: pitting"}
    assert all(m.limit in (1.2, 1.0) for m in s_h1)


def test_a_failed_check_that_failed_for_another_reason_is_no_bar():
    """The contact ratio of teeth that interfere fails although ε_α >= 1: no bar (a
    margin above 1 that failed would mislead); it is listed with the failed checks."""
    ms = margins(_run("spur_undercut_pinion"))
    assert "CONTACT_RATIO" not in {m.label for m in ms}


def _order(html: str, *needles: str) -> list[int]:
    return [html.index(n) for n in needles]


def test_first_screen_order_and_inputs_last():
    html = render([_run("spur_undercut_pinion")], "html")
    pos = _order(html, "<h1>", 'class="verdict fail"', "Governing margins",
                 "Failed checks (3)", "Warnings (1)", '<nav class="toc"', ">Geometry</h2>",
                 ">Checks</h2>", ">Inputs</h2>")
    assert pos == sorted(pos)
    assert "<title>Small pinion 12/50 without shift (fails: undercut) — geardesign report" \
        in html
    inputs = html[html.index(">Inputs</h2>"):]
    assert "assumed default" in inputs and "<td class=\"src\">given</td>" in inputs


def test_failed_checks_carry_their_advice():
    res = _run("novikov_narrow_face")
    fixed = [c for c in res.failed if c.fix]
    assert fixed
    first = render([res], "html").split('<nav class="toc"')[0]
    for c in fixed:
        assert "Advice: in the spec: " in first and c.fix[0][0] in first


def test_drive_parts_are_headed_below_the_drive(drive):
    html = render([drive], "html")
    heads = re.findall(r"<h([1-6])[^>]*>([^<]*)</h\1>", html)
    levels = {title: int(lv) for lv, title in heads}
    assert levels["Stage calculations"] == 2 and levels["Shaft calculations"] == 2
    assert levels["Stage 1: high-speed helical (spur)"] == 3
    assert levels["Losses and heat balance"] == 2
    stage = html.index("Stage 1: high-speed helical (spur)</h3>")
    assert re.search(r"<h4[^>]*>Geometry</h4>", html[stage:])
    assert "min⁻¹" in html and "mm²/s" in html and "<td class=\"unit\">min^" not in html


@pytest.mark.parametrize("name", ["spur_undercut_pinion", "drive_reducer_shafts_keys_thermal",
                                  "shaft_reducer_output", "bearing_select"])
def test_html_parses_without_errors(name):
    html5lib = pytest.importorskip("html5lib")
    parser = html5lib.HTMLParser()
    parser.parse(render([_run(name)], "html"))
    assert parser.errors == []


def test_every_user_string_is_escaped():
    html5lib = pytest.importorskip("html5lib")
    evil = '<script>alert(1)</script>"\'&\x1b[31m'
    res = run_data({"kind": "spur", "title": evil,
                    "gear": {"module": 4.0, "z1": 20, "z2": 40, "face_width": 30.0}},
                   "<x>.toml")
    html = render([res], "html")
    assert "<script>" not in html and "&lt;script&gt;" in html and "\x1b" not in html
    assert "&lt;x&gt;.toml" in html
    parser = html5lib.HTMLParser()
    parser.parse(html)
    assert parser.errors == []


def test_self_contained():
    html = render([_run("drive_reducer_shafts_keys_thermal")], "html")
    assert not re.search(r"""(src|href)=["']?(https?:|//)""", html)
    assert "<script" not in html and "@import" not in html and "url(http" not in html


def test_profile_svg_has_a_view_box_and_a_stroke_relative_to_the_module(tmp_path):
    from geardesign.spur.export import PROFILE_STROKE, write_profile

    res = _run("spur_plain")
    text = write_profile(res, tmp_path / "p.svg").read_text()
    m_n = res.pair_geometry.inp.m_n
    assert "viewBox=" in text
    assert f'stroke-width="{PROFILE_STROKE * m_n:.4f}"' in text
    for circle in ("pitch", "base", "tip", "root"):
        assert f'id="pinion_{circle}"' in text and f'id="wheel_{circle}"' in text


def test_pdf_refused_without_a_browser(tmp_path):
    """No Chromium: one line with the install hint, exit 2, nothing written."""
    out = tmp_path / "r.pdf"
    env = {**os.environ, "GEARDESIGN_CHROMIUM": str(tmp_path / "no-such-browser")}
    r = cli_process("run", SPECS / "spur_plain.toml", "--format", "pdf", "-o", out, env=env)
    assert r.returncode == 2 and r.stdout == "" and not out.exists()
    assert r.stderr.count("\n") == 1 and "pip install 'geardesign[report]'" in r.stderr


def test_pdf_to_a_text_only_stream_is_one_line(monkeypatch):
    """An embedding program's standard output without a byte buffer (a StringIO) has no
    place for a PDF: one line asking for --output, exit 2 (it was an internal error)."""
    from tests.helpers_cli import cli

    code, out, err = cli("run", SPECS / "spur_plain.toml", "--format", "pdf")
    assert code == 2 and out == ""
    assert err.strip().count("\n") == 0
    assert "give --output FILE.pdf" in err or "install" in err   # (no browser: the hint)


def test_cold_html_report_imports_no_matplotlib(tmp_path):
    r = subprocess.run([sys.executable, "-X", "importtime", "-m", "geardesign", "run",
                        str(SPECS / "spur_plain.toml"), "--format", "html", "-o",
                        str(tmp_path / "r.html")], capture_output=True, text=True,
                       cwd=Path(__file__).resolve().parent.parent)
    assert r.returncode == 0, r.stderr[-500:]
    assert "matplotlib" not in r.stderr and "playwright" not in r.stderr


def test_plot_svg_of_the_report_pictures(tmp_path):
    from tests.helpers_cli import cli

    code, _, err = cli("shaft", SPECS / "shaft_reducer_output.toml", "--plot",
                       tmp_path / "s.svg", "-q")
    assert code == 0, err
    text = (tmp_path / "s.svg").read_text()
    assert text.startswith("<?xml") and text.count('class="chart"') == 3
    code, _, err = cli("shaft", SPECS / "shaft_reducer_output.toml", "--plot",
                       tmp_path / "s.png", "-q")
    assert code == 2 and err.endswith("--plot of a shaft result writes .svg\n")
    code, _, err = cli("run", SPECS / "bearing_select.toml", "--plot", tmp_path / "b.svg")
    assert code == 2 and "a bearing result has no picture" in err
    assert not (tmp_path / "b.svg").exists() and not (tmp_path / "s.png").exists()


def test_pdf_refused_when_the_browser_does_not_start(tmp_path):
    pytest.importorskip("playwright")
    out = tmp_path / "r.pdf"
    env = {**os.environ, "GEARDESIGN_CHROMIUM": "/bin/false"}
    r = cli_process("run", SPECS / "spur_plain.toml", "-o", out, env=env)
    assert r.returncode == 2 and not out.exists()
    assert r.stderr.count("\n") == 1 and "did not start as Chromium" in r.stderr
