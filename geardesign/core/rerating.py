"""Whether the present calculation is a candidate's re-rating by the advice search
(:func:`geardesign.core.advice.rerate`): a flag that a report reads without importing the
search itself."""

from __future__ import annotations

import contextvars

RERATING = contextvars.ContextVar("rerating", default=False)
"""Set by :func:`geardesign.core.advice.rerate` while it rates a candidate."""


def rerating() -> bool:
    """Whether the present calculation is a candidate's re-rating: only its error checks'
    verdicts are read, so a report may leave out what only words its messages (the face
    width found by re-rating, a nested stage's advice)."""
    return RERATING.get()
