"""No import cycle among the package's modules.

Every ``import`` and ``from … import`` of every module of ``geardesign`` is read with
:mod:`ast`, at module level and inside functions alike (an import inside a function
still makes the two modules depend on each other; it only hides the cycle at start-up).
An edge A -> B means A names B (``from geardesign.x import y`` names the module
``geardesign.x.y`` when it is one, else ``geardesign.x``).  The test fails on any cycle
and prints it.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import geardesign

ROOT = Path(geardesign.__file__).resolve().parent


def _modules() -> dict[str, Path]:
    out = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _resolve(name: str, level: int, module: str, is_pkg: bool) -> str:
    if level == 0:
        return name
    base = module.split(".") if is_pkg else module.split(".")[:-1]
    base = base[:len(base) - (level - 1)]
    return ".".join(base + ([name] if name else []))


def import_graph() -> dict[str, set[str]]:
    """Module -> the package's modules it imports anywhere in its source (a copy of the
    graph, parsed once for both tests)."""
    return {m: set(t) for m, t in _parsed_graph().items()}


@functools.cache
def _parsed_graph() -> dict[str, set[str]]:
    mods = _modules()
    graph: dict[str, set[str]] = {m: set() for m in mods}
    for mod, path in mods.items():
        is_pkg = path.name == "__init__.py"
        tree = ast.parse(path.read_text(encoding="utf-8"))
        typing_only = {id(n) for node in ast.walk(tree) if isinstance(node, ast.If)
                       and "TYPE_CHECKING" in ast.unparse(node.test)
                       for n in ast.walk(node)}
        for node in ast.walk(tree):
            if id(node) in typing_only:     # not imported at run time
                continue
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(node.module or "", node.level, mod, is_pkg)
                for a in node.names:
                    full = f"{base}.{a.name}"
                    targets.append(full if full in mods else base)
            for t in targets:
                while t and t not in mods:      # a name inside a module: the module
                    t = t.rpartition(".")[0]
                if t and t != mod and t != "geardesign":
                    graph[mod].add(t)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    import sys

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 10000))
    try:
        for v in sorted(graph):
            if v not in index:
                visit(v)
    finally:
        sys.setrecursionlimit(limit)
    return out


def test_the_walker_sees_imports_inside_functions(tmp_path):
    """The graph has the edges of imports inside functions (e.g. the drive's calculator
    importing the shaft analysis inside a function)."""
    g = import_graph()
    assert "geardesign.drive.shaft_analysis" in g["geardesign.drive.calculator"]
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


#: Cycles tolerated: none is left (the package <-> calculator cycles went with the lazy
#: ``CALCULATOR`` of :func:`geardesign.core.registry.lazy_calculator`).  A new cycle fails.
KNOWN: set[frozenset[str]] = set()


def test_no_import_cycle():
    found = [c for c in cycles(import_graph()) if frozenset(c) not in KNOWN]
    assert not found, "import cycles:\n" + "\n".join(" <-> ".join(c) for c in found)


def test_a_calculator_package_does_not_import_its_calculator():
    """The cause of the package <-> calculator cycles, for every calculator at once: a
    package's ``__init__`` builds ``CALCULATOR`` lazily and imports none of its calculator's
    modules (which import the package back for ``CALCULATOR``)."""
    from geardesign.core.registry import KINDS

    g = import_graph()
    known = {m for c in KNOWN for m in c}
    eager = [k for k, mod in KINDS.items() if mod not in known
             and any(t.startswith(mod + ".") for t in g[mod])]
    assert not eager, f"packages importing their own modules in __init__: {eager}"


def test_shared_gear_code_depends_on_no_calculator():
    """``geardesign.gears`` (geometry, span, internal pairs, losses) is shared by the spur,
    planetary, pzdn, worm, bevel and drive calculators: it imports none of them, only
    core code, the involute and itself."""
    from geardesign.core.registry import KINDS

    g = import_graph()
    calculators = tuple(f"{mod}." for mod in KINDS.values())
    bad = {m: sorted(t for t in ts if t in KINDS.values() or t.startswith(calculators))
           for m, ts in g.items() if m == "geardesign.gears" or m.startswith("geardesign.gears.")}
    assert not any(bad.values()), bad
