"""Sources a reader can follow: every citation key used in the package and its docs is an
entry of ``docs/references.md``, and nothing in the repository points to working files
outside it."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
REFERENCES = (ROOT / "docs" / "references.md").read_text(encoding="utf-8")
DEFINED = set(re.findall(r"^\| \[([^\]]+)\] \|", REFERENCES, flags=re.M))
# entries of a branch waiting to be merged into references.md (docs/refs_<branch>.md)
for _p in sorted((ROOT / "docs").glob("refs_*.md")):
    DEFINED |= set(re.findall(r"^\| \[([^\]]+)\] \|", _p.read_text(encoding="utf-8"), flags=re.M))

# A citation key: a standard (GOST21354, ISO281, EN13906-3) or an author/journal and a year
# (Korotkin2017); other bracketed names in the code are Python types ([Row], [Path]).
KEY = re.compile(r"\[((?:GOST|ISO|EN)[0-9][0-9A-Z-]*|[A-Z][A-Za-z]+(?:19|20)[0-9]{2})\]")
NAMED = {"ZPCIL", "Lopukhov", "RotaryDevices", "KISSsoft", "NREL", "MESYS", "KHK", "WormGear",
         "NTN", "FOSSEE", "Dunaev", "Ivanov", "Kudryavtsev", "Niemann", "Timoshenko",
         "Hibbeler", "Bhandari", "Wahl", "ZhangJin"}
FORBIDDEN = re.compile(r"seed [0-9]|seed l|method note|shared/|standards_check", re.I)


def _files():
    for sub in ("geardesign", "tests", "docs", "benchmarks", "specs"):
        for p in (ROOT / sub).rglob("*"):
            if p.is_file() and p.suffix in (".py", ".md", ".toml", ".json", ".txt"):
                yield p
    yield ROOT / "README.md"


def test_every_cited_key_is_in_the_bibliography():
    missing = set()
    for p in _files():
        for key in KEY.findall(p.read_text(encoding="utf-8")):
            if key not in DEFINED:
                missing.add(f"{key} ({p.relative_to(ROOT)})")
    assert not missing, sorted(missing)


def test_named_keys_are_in_the_bibliography():
    assert NAMED <= DEFINED, sorted(NAMED - DEFINED)


def test_nothing_points_outside_the_repository():
    me = Path(__file__).resolve()
    hits = []
    for p in _files():
        if p.resolve() == me:
            continue
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
            if FORBIDDEN.search(line):
                hits.append(f"{p.relative_to(ROOT)}:{i}: {line.strip()[:100]}")
    assert not hits, hits
