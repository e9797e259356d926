"""The verdict of a fatigue rating, the same record for both methods: whether each gear
passes contact (pitting) and bending, and by how much (margins ≥ 1 pass).

The rules, once for the calculator, the advice by re-rating, the comparison of methods
and the sweep kernel (numbers or arrays of candidates, :mod:`geardesign.core.xp`):

* GOST 21354-87: σ_H ≤ σ_HP of the pair (contact, judged for the pair: both gears carry the
  same verdict), S_F ≥ S_Fmin per gear (bending) [GOST21354];
* ISO 6336:2019: S_H ≥ S_Hmin and S_F ≥ S_Fmin per gear, of the load spectrum when one is
  rated [ISO6336-2] §4, [ISO6336-3] §4.

Each comparison allows a relative 1e-12 (a value computed at the limit passes).
"""

from __future__ import annotations

from geardesign.core import xp
from geardesign.core.records import dataclass

GOST = "GOST 21354-87"
ISO = "ISO 6336:2019"
RTOL = 1e-12
"""Relative tolerance of the comparisons with the limits."""


@dataclass(frozen=True)
class Verdict:
    """Contact and bending verdicts of a rating, per gear (pinion, wheel)."""

    method: str
    contact_ok: tuple
    bending_ok: tuple
    contact_margin: tuple
    """σ_HP/σ_H of the pair (GOST), S_H/S_Hmin per gear (ISO)."""
    bending_margin: tuple
    """S_F/S_Fmin per gear."""

    @property
    def contact_passes(self):
        return self.contact_ok[0] & self.contact_ok[1]

    @property
    def bending_passes(self):
        return self.bending_ok[0] & self.bending_ok[1]

    @property
    def passes(self):
        """Contact and bending pass on both gears."""
        return self.contact_passes & self.bending_passes

    @property
    def margin(self):
        """The least margin: ≥ 1 when the rating passes."""
        c, b = self.contact_margin, self.bending_margin
        return xp.minimum(xp.minimum(c[0], c[1]), xp.minimum(b[0], b[1]))


def verdict(rating) -> Verdict:
    """The verdict of a rating record (a GOST 21354-87 :class:`GostRating`, an ISO 6336
    rating) or of its values by report key (``rating.v``)."""
    v = rating if isinstance(rating, dict) else rating.v
    if "S_Hmin" in v:
        return _iso(v)
    return _gost(v)


def _gost(v: dict) -> Verdict:
    sH, sHP = v["sigma_H"], v["sigma_HP"]
    ok = sH <= sHP * (1 + RTOL)
    S_F = (v["S_F1"], v["S_F2"])
    S_Fmin = (v["S_F1_min"], v["S_F2_min"])
    margin = sHP / sH
    return Verdict(GOST, (ok, ok), tuple(S_F[i] >= S_Fmin[i] * (1 - RTOL) for i in range(2)),
                   (margin, margin), tuple(S_F[i] / S_Fmin[i] for i in range(2)))


def _iso(v: dict) -> Verdict:
    def pair(kind: str):
        spec = "spec" if f"S_{kind}spec1" in v else ""
        S = tuple(v[f"S_{kind}{spec}{k}"] for k in (1, 2))
        need = v[f"S_{kind}min"]
        return tuple(s >= need * (1 - RTOL) for s in S), tuple(s / need for s in S)

    (c_ok, c_m), (b_ok, b_m) = pair("H"), pair("F")
    return Verdict(ISO, c_ok, b_ok, c_m, b_m)
