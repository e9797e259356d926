"""Every dotted name ``geardesign.x.y`` that the package's docstrings and comments and the
``docs/*.md`` pages cite resolves to a real module or attribute: a function or module that
moved leaves no stale path behind."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NAME = re.compile(r"(?<![\w/.])geardesign(?:\.[A-Za-z_]\w*)+")


def _cited() -> dict[str, list[str]]:
    """Dotted names by the files that cite them."""
    out: dict[str, list[str]] = {}
    files = sorted((ROOT / "geardesign").rglob("*.py")) + sorted((ROOT / "docs").glob("*.md")) \
        + [ROOT / "README.md"]
    for path in files:
        if "__pycache__" in path.parts or not path.is_file():
            continue
        for name in set(NAME.findall(path.read_text(encoding="utf-8"))):
            out.setdefault(name, []).append(path.relative_to(ROOT).as_posix())
    return out


def resolves(name: str) -> bool:
    """Whether ``name`` is a module, or an attribute (at any depth) of the longest module
    prefix of it."""
    parts = name.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attr in parts[cut:]:
            if attr in getattr(obj, "__dataclass_fields__", {}):   # a field with a factory
                return True
            if not hasattr(obj, attr):
                return False
            obj = getattr(obj, attr)
        return True
    return False


CITED = _cited()


def test_names_are_found():
    assert "geardesign.spur.strength.verdict.verdict" in CITED


def test_every_cited_dotted_name_resolves():
    stale = [f"{name} (cited in {', '.join(files)})" for name, files in sorted(CITED.items())
             if not resolves(name)]
    assert not stale, "names of no module or attribute: correct the paths:\n" + \
        "\n".join(stale)


ROLE = re.compile(r":(?:func|class|mod|data|attr|meth|exc):`~?(\.[A-Za-z_][\w.]*)`")


def _relative() -> dict[tuple[str, str], list[str]]:
    """Relative Sphinx references (``:func:`.module.name```) of the package's modules, by
    (citing module, reference)."""
    out: dict[tuple[str, str], list[str]] = {}
    for path in sorted((ROOT / "geardesign").rglob("*.py")):
        if "__pycache__" in path.parts:
            continue
        module = ".".join(path.relative_to(ROOT).with_suffix("").parts)
        for ref in set(ROLE.findall(path.read_text(encoding="utf-8"))):
            out.setdefault((module, ref), []).append(path.relative_to(ROOT).as_posix())
    return out


RELATIVE = _relative()


def test_every_relative_reference_resolves():
    """``.x.y`` names ``x.y`` in the citing module's package, or in the module itself."""
    stale = [f"{ref} (cited in {module})" for module, ref in sorted(RELATIVE)
             if not resolves(module.rsplit(".", 1)[0] + ref) and not resolves(module + ref)]
    assert not stale, "relative references to nothing:\n" + "\n".join(stale)
