"""Every spec the tool writes as TOML (a REXS model imported, ``sweep --emit-spec``) and
every model it writes (REXS XML and JSON export) reads back as written, whatever text it
carries: a quote, a backslash, markup, a line break, a control character, a bidi override
or a lone surrogate (a file name that is not UTF-8, a JSON ``\\udcff``) in a value, a
comment or a file name never ends a line of the spec, never writes a key of its own, and
never makes the file unreadable."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.text import escape_controls, toml_string
from geardesign.rexs.importer import import_model
from geardesign.rexs.model import parse
from tests.helpers_cli import cli

DATA = Path(__file__).parent / "data" / "rexs"
SPECS = Path(__file__).resolve().parent.parent / "specs"
HOSTILE = 'a"b\\c\nkind = "evil"\n[motor]\npower = 99999\n#\r\x00\x1b[2J\x7f\u202e\u2028\udcff'
"""Text that would end a comment or a string and write TOML of its own if written raw."""


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.text())
def test_a_toml_string_reads_back_as_the_text(text):
    assert tomllib.loads(f"k = {toml_string(text)}")["k"] == text


@settings(max_examples=100, deadline=None, derandomize=True)
@given(st.text(st.characters(codec=None, categories=("Cs", "Cc", "Zl", "Zp", "Lu"))))
def test_a_toml_string_of_any_code_points_is_one_valid_line(text):
    """Lone surrogates included (no TOML string can hold one: its escape as text)."""
    written = toml_string(text)
    assert "\n" not in written and "\r" not in written
    assert tomllib.loads(f"k = {written}")["k"] == "".join(
        f"\\u{ord(c):04x}" if 0xD800 <= ord(c) < 0xE000 else c for c in text)


def _keys(d, prefix=""):
    """Every key path of a parsed TOML document (arrays of tables by index)."""
    out = set()
    for k, v in d.items():
        out.add(prefix + k)
        if isinstance(v, dict):
            out |= _keys(v, prefix + k + ".")
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for i, x in enumerate(v):
                out |= _keys(x, f"{prefix}{k}[{i}].")
    return out


def _hostile(doc: dict) -> dict:
    """The JSON model with every text a reader shows (program, version, date, every
    component's name and every string attribute) replaced by :data:`HOSTILE`."""
    m = doc["model"]
    m["applicationId"] = m["applicationVersion"] = HOSTILE
    m["date"] = HOSTILE
    for c in m["components"]:
        c["name"] = HOSTILE
        for a in c.get("attributes", []):
            if "string" in a:
                a["string"] = HOSTILE
    return doc


def test_an_imported_model_writes_no_toml_of_its_own():
    """A model whose every text is hostile, under a hostile file name: the imported spec
    parses, has exactly the keys of the same model with plain texts, and shows the texts
    escaped."""
    raw = (DATA / "FVA-Industriegetriebe_2stufig_1-4.rexsj").read_bytes()
    plain = import_model(parse(raw), "m.rexsj").text
    bad = json.dumps(_hostile(json.loads(raw)), ensure_ascii=True).encode()
    text = import_model(parse(bad), escape_controls(HOSTILE + ".rexsj")).text
    got, want = tomllib.loads(text), tomllib.loads(plain)
    assert _keys(got) == _keys(want)
    assert got["kind"] == want["kind"] and got.get("motor") == want.get("motor")
    assert "99999" not in "".join(line for line in text.splitlines()
                                  if not line.lstrip().startswith("#") and "#" not in line)
    assert "\u202e" not in text and "\udcff" not in text


def test_import_of_a_hostile_file_name_writes_a_spec_that_runs(tmp_path):
    model = tmp_path / (HOSTILE.replace("\x00", "").replace("/", "") + ".rexsj")
    model.write_bytes((DATA / "FVA-Industriegetriebe_2stufig_1-4.rexsj").read_bytes())
    out = tmp_path / "imported.toml"
    code, _, err = cli("import", model, "--output", out)
    assert code == 0, err
    spec = tomllib.loads(out.read_text(encoding="utf-8"))
    assert spec["kind"] == "drive" and "evil" not in json.dumps(spec)
    code, _, err = cli("run", out, "-f", "json")
    assert code in (0, 1), err


def test_an_emitted_sweep_variant_keeps_its_title(tmp_path):
    """``sweep --emit-spec``: the variant's spec reads back with the sweep spec's title,
    however that title is written."""
    title = 'a"b\\c\nd\x1b[2J\x7f\u202e'
    text = (SPECS / "sweep_spur_reducer.toml").read_text(encoding="utf-8")
    lines = [ln for ln in text.splitlines() if not ln.startswith("title")]
    head = [i for i, ln in enumerate(lines) if ln.startswith("kind")][0]
    lines.insert(head + 1, f"title = {json.dumps(title)}")
    spec = tmp_path / "s.toml"
    spec.write_text("\n".join(lines) + "\n", encoding="utf-8")
    code, out, err = cli("sweep", spec, "--emit-spec", "1")
    assert code == 0, err
    assert tomllib.loads(out)["title"] == title


def test_an_exported_model_is_well_formed_whatever_text_the_spec_holds(tmp_path):
    """REXS export of a spec whose title holds what XML cannot hold (an ESC), markup
    (``<``, ``&``, ``]]>``, quotes) and a bidi override: the XML is well-formed, the JSON
    loads, and both import again (the title shown with its escapes)."""
    import xml.etree.ElementTree as ET

    title = 'ti\x1btle \u202e " \' <x> &amp; ]]>'
    text = (SPECS / "spur_plain.toml").read_text(encoding="utf-8")
    lines = [ln for ln in text.splitlines() if not ln.startswith("title")]
    lines.insert(1, f"title = {json.dumps(title)}")
    spec = tmp_path / "s.toml"
    spec.write_text("\n".join(lines) + "\n", encoding="utf-8")
    for fmt, name in (("rexs", "m.rexs"), ("rexs-json", "m.rexsj")):
        code, _, err = cli("export", spec, "--format", fmt, "--output", tmp_path / name)
        assert code == 0, err
        raw = (tmp_path / name).read_bytes()
        if fmt == "rexs":
            ET.fromstring(raw)
        else:
            json.loads(raw)
        imported = tomllib.loads(import_model(parse(raw), name).text)
        assert imported["title"] == escape_controls(title)
