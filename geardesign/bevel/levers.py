"""Levers of the bevel advice (:mod:`geardesign.core.advice`), each re-rated.

A pair short of pitting or bending safety (``ISO_PITTING``, ``ISO_BENDING``,
``GOST_PITTING``, ``GOST_BENDING``, and the same at the peak torque: ``ISO_STATIC_PITTING``,
``ISO_STATIC_BENDING``, ``GOST_STATIC_CONTACT``, ``GOST_STATIC_BENDING``) first gets a wider
face (``pair.face_width`` up to 1.5 times, within the R_e/2 the inputs allow), then a larger
module (``pair.module``, up to twice): the stresses fall with b^-1/2 and b^-1 for contact and
bending, with the module (and so d_m1 and m_nm) faster.  An undercut pinion gets the least profile shift that clears
it (``pair.x1``, the check's limit rounded up to 0.01)."""

from __future__ import annotations

from geardesign.core.advice import Lever, scaled, to_limit

STRENGTH = ("ISO_PITTING", "ISO_BENDING", "GOST_PITTING", "GOST_BENDING",
            "ISO_STATIC_PITTING", "ISO_STATIC_BENDING", "GOST_STATIC_CONTACT",
            "GOST_STATIC_BENDING")

LEVERS = (
    Lever(STRENGTH, scaled("pair.face_width", (1.1, 1.2, 1.3, 1.4, 1.5), digits=1),
          "a wider face"),
    Lever(STRENGTH, scaled("pair.module", (1.12, 1.25, 1.4, 1.6, 1.8, 2.0), digits=2),
          "a larger module"),
    Lever(("UNDERCUT",), to_limit("UNDERCUT", "pair.x1", up=True, digits=2),
          "the least profile shift without undercut"),
)
