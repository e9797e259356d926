"""geardesign: design calculations for mechanical drives.

Each calculator is a package (``geardesign.spur``, ...) of pure functions on plain data;
``geardesign.core`` holds what they share: spec schemas and validation, the result model,
checks and the renderers.  The command line (``geardesign.cli``) is a thin layer on top.

The Python API (docs/api.md): :func:`load` (a spec file -> typed inputs), :func:`solve`
(inputs -> record), :func:`report` (record -> result), :func:`rows` (records -> flat
dicts).  Importing ``geardesign`` imports none of them until first use.
"""

__version__ = "0.1.0"

_API = ("load", "solve", "report", "rows", "asdict")


def __getattr__(name: str):
    import importlib

    if name in _API:
        return getattr(importlib.import_module("geardesign.api"), name)
    if not name.startswith("_"):
        try:
            return importlib.import_module(f"geardesign.{name}")
        except ModuleNotFoundError as exc:
            if exc.name != f"geardesign.{name}":
                raise
    raise AttributeError(f"module 'geardesign' has no attribute {name!r}")
