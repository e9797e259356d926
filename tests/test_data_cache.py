"""geardesign.core.data keeps parsed data files beside the bytecode: the same value as
parsing, parsed again whenever the file, the parser's module or the cache is not what the
cache was made from, nothing written when Python writes no bytecode, and every data file
of the package read through it equal to its parse."""

from __future__ import annotations

import marshal
import os
import sys
import tomllib
from pathlib import Path

import pytest

import geardesign
from geardesign.core import data


@pytest.fixture
def writes(monkeypatch):
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    monkeypatch.setattr(sys, "pycache_prefix", None)


def _cache(path: Path) -> Path:
    return data._cache_file(path, data._toml)


def test_a_parsed_file_is_kept_and_read_back(tmp_path, writes):
    f = tmp_path / "t.toml"
    f.write_text('a = 1.5\n[b]\nc = ["x", true]\n', "utf-8")
    first = data.toml_table(f)
    assert first == tomllib.loads(f.read_text("utf-8"))
    assert _cache(f).is_file()
    assert _cache(f).name == f"t.toml.toml.{sys.implementation.cache_tag}.data"
    stamp, kept = marshal.loads(_cache(f).read_bytes())
    assert kept == first
    again = data.toml_table(f)
    assert again == first and again is not first


def test_a_changed_file_is_parsed_again(tmp_path, writes):
    f = tmp_path / "t.toml"
    f.write_text("a = 1\n", "utf-8")
    assert data.toml_table(f) == {"a": 1}
    f.write_text("a = 22\n", "utf-8")
    st = os.stat(f)
    os.utime(f, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000))
    assert data.toml_table(f) == {"a": 22}


def test_a_broken_or_foreign_cache_is_ignored(tmp_path, writes):
    f = tmp_path / "t.toml"
    f.write_text("a = 1\n", "utf-8")
    for junk in (b"", b"\x00garbage", marshal.dumps(("other", {"a": 2})),
                 marshal.dumps(((0, (0, 0), None, (0, 0), "_toml"), {"a": 3}))):
        _cache(f).parent.mkdir(exist_ok=True)
        _cache(f).write_bytes(junk)
        assert data.toml_table(f) == {"a": 1}


def test_nothing_is_written_without_bytecode(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "dont_write_bytecode", True)
    f = tmp_path / "t.toml"
    f.write_text("a = 1\n", "utf-8")
    assert data.toml_table(f) == {"a": 1}
    assert not (tmp_path / "__pycache__").exists()


def test_the_cache_follows_the_pycache_prefix(tmp_path, monkeypatch):
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    monkeypatch.setattr(sys, "pycache_prefix", str(tmp_path / "prefix"))
    f = tmp_path / "d" / "t.toml"
    f.parent.mkdir()
    f.write_text("a = 1\n", "utf-8")
    assert data.toml_table(f) == {"a": 1}
    assert not (f.parent / "__pycache__").exists()
    assert list((tmp_path / "prefix").rglob("t.toml.toml.*.data"))


def test_a_value_marshal_cannot_write_and_a_failed_write_leave_no_cache(tmp_path, writes,
                                                                      monkeypatch):
    f = tmp_path / "t.toml"
    f.write_text("when = 1979-05-27\n", "utf-8")       # a date: not marshal data
    assert data.toml_table(f) == tomllib.loads(f.read_text("utf-8"))
    assert not _cache(f).exists()
    g = tmp_path / "u.toml"
    g.write_text("a = 1\n", "utf-8")

    def refuse(*args):
        raise PermissionError("read-only")

    monkeypatch.setattr(data.os, "replace", refuse)
    assert data.toml_table(g) == {"a": 1}
    assert list((tmp_path / "__pycache__").iterdir()) == []


@pytest.mark.parametrize("path", sorted(Path(geardesign.__file__).parent.rglob("*.toml")),
                         ids=lambda p: str(p.relative_to(Path(geardesign.__file__).parent)))
def test_every_data_file_of_the_package_reads_as_its_parse(path):
    assert data.toml_table(path) == tomllib.loads(path.read_text("utf-8"))


def test_the_bearing_catalogue_reads_as_its_parse():
    from geardesign.bearing import catalogue

    text = catalogue._FILE.read_text("utf-8")
    assert data.parsed(catalogue._FILE, catalogue._parse) == catalogue._parse(text)
    rows = catalogue.bearings()
    assert len(rows) == len(catalogue._table()[0]) > 700
    assert catalogue.makers() == tuple(dict.fromkeys(b.maker for b in rows))
    iso, gost = catalogue._index()
    for b in rows:            # each row is found under each of its designations
        for k in {catalogue._key(b.designation), catalogue._key(b.maker_designation)} - {""}:
            assert b in iso[k]
        if b.gost:
            assert b in gost[catalogue._key(b.gost)]


def test_the_oil_table_reads_as_its_parse():
    from geardesign.materials import lubricants

    text = lubricants._FILE.read_text("utf-8")
    rows = data.parsed(lubricants._FILE, lubricants._parse)
    assert rows == lubricants._parse(text)
    assert [tuple(vars(o).values()) for o in lubricants.grades()] == rows


@pytest.mark.parametrize("path", sorted(Path(geardesign.__file__).parent.rglob("*.csv")),
                         ids=lambda p: str(p.relative_to(Path(geardesign.__file__).parent)))
def test_every_csv_file_of_the_package_reads_as_the_csv_module_reads_it(path):
    import csv

    with path.open(encoding="utf-8") as fh:
        expected = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    assert data.csv_table(path) == expected
