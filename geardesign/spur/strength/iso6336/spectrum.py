"""The load spectrum of an ISO 6336 rating ([ISO6336-6]): Miner's damage sums on the S-N
curves of parts 2 and 3 and the safety factors of the spectrum, in the record
:class:`Spectrum` (fields with their report metadata), filled by :func:`spectrum`.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.spur.strength.common import Record, q
from geardesign.spur.strength.iso6336 import part2 as P2
from geardesign.spur.strength.iso6336 import part3 as P3
from geardesign.spur.strength.iso6336 import part6 as P6

S6 = "[ISO6336-6]"


def _g(unit, symbol, name):
    return q(unit, symbol, name, S6, gear=True, group="D")


@dataclass(frozen=True, kw_only=True)
class Spectrum(Record):
    """Damage sums D = Σ n_i/N_i ([ISO6336-6] §5, Palmgren–Miner) and the safety factors S
    at which D = 1 (the block stresses scaled by S), per gear, pitting and bending."""

    SECTION = "iso6336_spectrum"
    method: str = q(None, "Σn/N", "damage accumulation", S6)
    D_H: tuple = _g("-", "D_H{k}", "damage sum, pitting (stresses as computed), {who}")
    S_Hspec: tuple = _g("-", "S_H,spec{k}", "safety factor for pitting of the spectrum (D = 1 "
                        "at S·σ_Hi), {who}")
    D_F: tuple = _g("-", "D_F{k}", "damage sum, bending (stresses as computed), {who}")
    S_Fspec: tuple = _g("-", "S_F,spec{k}", "safety factor for bending of the spectrum (D = 1 "
                        "at S·σ_Fi), {who}")


def spectrum(g, duty, types, sHlim, sFlim, contact, bending, iso) -> Spectrum:
    """Miner's damage sums and the safety factors of the spectrum ([ISO6336-6] §5, the S-N
    curves of [ISO6336-2] §10 and [ISO6336-3] §12).  Each block's stress is the nominal one
    scaled with its torque (σ_H ∝ √T, σ_F ∝ T; the load factors kept at their
    nominal-torque values).  ``contact``, ``bending``: the rating's section records;
    ``sHlim``, ``sFlim`` [MPa] per gear."""
    life = duty.life
    out: dict = {"D_H": [], "S_Hspec": [], "D_F": [], "S_Fspec": []}
    c, b = contact, bending
    for i in range(2):
        n_i = [60.0 * (duty.n1 / (1.0 if i == 0 else g.u)) * blk.speed_ratio * life.c[i]
               * life.L_h * blk.time_share for blk in life.blocks]
        N_st, N_ref = P2.reference_cycles_contact(types[i], iso.limited_pitting)
        fixed = c.Z_W[i] * c.Z_X[i]
        infl = c.Z_L * c.Z_v * c.Z_R

        def s_HG(N: float, i=i, N_st=N_st, N_ref=N_ref, fixed=fixed, infl=infl) -> float:
            return sHlim[i] * P2.z_nt(types[i], N, iso.limited_pitting, iso.optimum) * \
                P2.interpolated(infl, N, N_st, N_ref) * fixed

        sH = [c.sigma_H[i] * math.sqrt(blk.torque_ratio) for blk in life.blocks]
        out["D_H"].append(P6.damage(sH, n_i, s_HG))
        out["S_Hspec"].append(P6.spectrum_safety(sH, n_i, s_HG))
        Nb_st, Nb_ref = P3.reference_cycles_bending(types[i])
        Ybase = sFlim[i] * P3.Y_ST * b.Y_M[i]
        refs = (b.Y_deltarelT[i], b.Y_RrelT[i], b.Y_X[i])
        Yd_st = P3.y_delta_rel_static(types[i], b.Y_S[i], None)

        def s_FG(N: float, i=i, Ybase=Ybase, refs=refs, Yd_st=Yd_st, a=Nb_st, r=Nb_ref) -> float:
            return Ybase * P3.y_nt(types[i], N, iso.optimum) * \
                P2.interpolated(refs[0], N, a, r, Yd_st) * P2.interpolated(refs[1], N, a, r) * \
                P2.interpolated(refs[2], N, a, r)

        sF = [b.sigma_F[i] * blk.torque_ratio for blk in life.blocks]
        out["D_F"].append(P6.damage(sF, n_i, s_FG))
        out["S_Fspec"].append(P6.spectrum_safety(sF, n_i, s_FG))
    return Spectrum(method="Palmgren–Miner on the S-N curves of parts 2 and 3; block stresses "
                           "scaled from the nominal torque",
                    **{k: tuple(x) for k, x in out.items()})
