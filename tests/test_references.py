"""Sources a reader can follow: every citation key used in the package, its docs and its
reports is an entry of ``docs/references.md``, and nothing in the repository points to
working files outside it.

Key syntax (also stated in ``docs/references.md``): a key is a bracketed word that is not an
index or a type subscript (the ``[`` does not follow a name or a closing bracket) and
that is either

* a standard: ``GOST``, ``ISO``, ``ISOTR``, ``EN``, ``DIN``, ``AGMA`` or ``VDI`` followed by the
  number: ``[GOST21354]``, ``[ISO281]``, ``[EN13906-3]``;
* a paper: a capitalised name and a four-digit year, optionally a letter: ``[Korotkin2017]``,
  ``[Dobrov2017a]``;
* a named source (book, thesis, program): a capitalised word written in a citation place,
  i.e. followed by a locator (`` eq.``, `` table``, `` §``, `` fig.``, a program file name
  such as `` CONTAU.h``, ...) or standing alone
  between ``(``/``;``/``,``/``:``/a quote and ``)``/``;``/``,``/``.``/``:``/a quote.

Bracketed units and symbols (``[MPa]``, ``[Hz]``, ``[N·m]``) are not keys.
"""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
REFERENCES = (ROOT / "docs" / "references.md").read_text(encoding="utf-8").split(
    "## Known misprints")[0]
DEFINED = set(re.findall(r"^\| \[([^\]]+)\] \|", REFERENCES, flags=re.M))

NOT_A_NAME = r"(?<![\w\])])"
STANDARD = r"(?:GOST|ISOTR|ISO|EN|DIN|AGMA|VDI)[0-9][0-9A-Za-z.-]*"
PAPER = r"[A-Z][A-Za-z]+(?:19|20)[0-9]{2}[a-z]?"
KEY = re.compile(NOT_A_NAME + rf"\[({STANDARD}|{PAPER})\]")
LOCATOR = (r" (?:eqs?\.|table|tables|fig\.|§|system|appendix|p\.|pp\.|worked example|clause"
           r"|[A-Za-z0-9_]+\.(?:h|m|py|pas|f|for|cs)\b)")
NAMED = re.compile(NOT_A_NAME + r"(?<=[(;,:\"'` ])\[([A-Z][A-Za-z0-9-]{2,})\]"
                   rf"(?=[);,.:\"'`]|{LOCATOR})")
UNITS = {"MPa", "GPa", "Hz", "kHz", "rpm", "Nm", "Nmm", "Pa", "RPM",
         "FILTER"}  # units and command-line metavars, not keys
# working files outside the repository, written so that this line does not match itself
FORBIDDEN = re.compile(r"seed [0-9]|seed l|method[ ]note|share[d]/|standards[_]check", re.I)
SUFFIXES = (".py", ".md", ".toml", ".json", ".txt", ".csv")


def _files(*subdirs):
    for sub in subdirs:
        for p in sorted((ROOT / sub).rglob("*")):
            if p.is_file() and p.suffix in SUFFIXES and "__pycache__" not in p.parts:
                yield p
    if "docs" in subdirs:
        yield ROOT / "README.md"


def _cited(text: str) -> set[str]:
    keys = set(KEY.findall(text))
    keys |= {k for k in NAMED.findall(text) if k not in UNITS}
    return keys


def test_key_syntax():
    assert _cited("as in [Korotkin2017] eq. (3); [GOST21354] table 6 ([ZPCIL] CONTAU.h)") == {
        "Korotkin2017", "GOST21354", "ZPCIL"}
    assert _cited("rows[GOST21354], list[Check], x[KEY2017], f(x)[Dunaev]") == set()
    assert _cited("stress [MPa] at speed [Hz]; rows: list[Row]") == set()
    assert _cited("([Lopukhov] §2.1); \"[RotaryDevices]\"") == {"Lopukhov", "RotaryDevices"}


def test_every_cited_key_is_in_the_bibliography():
    missing = []
    for p in _files("geardesign", "docs", "specs", "tests"):
        if p.name == "references.md" or p.resolve() == Path(__file__).resolve():
            continue
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            for key in _cited(line):
                if key not in DEFINED:
                    missing.append(f"{p.relative_to(ROOT)}:{i}: [{key}]")
    assert not missing, missing


def test_every_package_source_cites_a_key():
    """The package cites its sources: keys are used in every calculator package."""
    for pkg in sorted(p for p in (ROOT / "geardesign").iterdir() if p.is_dir()):
        if pkg.name in ("core", "__pycache__", "testing", "materials"):
            continue
        text = "".join(p.read_text(encoding="utf-8") for p in pkg.rglob("*.py"))
        assert _cited(text), f"{pkg.name}: no [key] citation"


def test_bibliography_entries_are_complete():
    rows = re.findall(r"^\| \[([^\]]+)\] \| (.+) \|$", REFERENCES, flags=re.M)
    assert len(rows) == len(DEFINED), "a key is listed twice"
    for key, entry in rows:
        assert len(entry) > 30, f"[{key}] has no full entry"


def test_nothing_points_outside_the_repository():
    me = Path(__file__).resolve()
    hits = []
    for p in _files("geardesign", "tests", "docs", "benchmarks", "specs"):
        if p.resolve() == me:
            continue
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            if FORBIDDEN.search(line):
                hits.append(f"{p.relative_to(ROOT)}:{i}: {line.strip()[:100]}")
    assert not hits, hits


def test_pzdn_models_are_named_after_what_they_are():
    from geardesign.pzdn import spring

    assert "thesis" in spring.CURVATURE_MODELS and "thesis" in spring.LEG_MODELS
    assert "seed" not in spring.CURVATURE_MODELS + spring.LEG_MODELS
