"""A module that can be called as its main function: ``spur.solve(inputs)`` where
``geardesign.spur.solve`` is also the module of the record types (``spur.solve.Record``).

A package's submodule is set as the package's attribute when it is first imported, so a
function of the same name in the package would be replaced by the module; making the
module callable keeps one name for both."""

from __future__ import annotations

import sys
import types


class _Callable(types.ModuleType):
    """A module whose call is its function named in ``__call_name__`` (looked up at each
    call, so that a replaced function is the one called)."""

    def __call__(self, *args, **kwargs):
        return getattr(self, self.__dict__["__call_name__"])(*args, **kwargs)


def callable_module(module_name: str, function: str) -> None:
    """Make the module ``module_name`` callable as its function ``function``."""
    mod = sys.modules[module_name]
    mod.__call_name__ = function
    mod.__class__ = _Callable
