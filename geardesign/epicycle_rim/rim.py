"""Thin-rim cross-checks of a ring gear: ISO 6336-3 rim thickness factor Y_B for internal
gears, the AGMA 2001 backup ratio and rim thickness factor K_B, and paper A's failure-mode
rule.  Pure functions; lengths in mm.
"""

from __future__ import annotations

import math

YB_INTERNAL_MIN = 1.75   # s_R/m_n below which ISO 6336-3 does not cover internal gears
YB_INTERNAL_FULL = 3.5   # s_R/m_n from which Y_B = 1
BACKUP_FULL = 1.2        # AGMA m_B from which K_B = 1


def rim_factor_iso_internal(rim_thickness: float, module: float) -> float:
    """ISO 6336-3 rim thickness factor of an internal gear.

    .. math::
        Y_B = 1.15 \\ln\\frac{8.324\\, m_n}{s_R}\\quad (1.75 < s_R/m_n < 3.5),\\qquad
        Y_B = 1\\quad (s_R/m_n \\ge 3.5)

    NaN below s_R/m_n = 1.75 (outside the standard's range).

    Parameters
    ----------
    rim_thickness : s_R, from the root circle to the outer surface [mm]; module : m_n [mm].

    References
    ----------
    ISO 6336-3:2006/2019, rim thickness factor for internal gears: quoted from memory (the
    standard's text was not available; found only the external
    form).  Unverified; used for a warning only.
    """
    r = rim_thickness / module
    if r >= YB_INTERNAL_FULL:
        return 1.0
    if r <= YB_INTERNAL_MIN:
        return math.nan
    return 1.15 * math.log(8.324 * module / rim_thickness)


def backup_ratio(rim_thickness: float, tooth_height: float) -> float:
    """AGMA backup ratio m_B = t_R/h_t (rim thickness below the root over tooth height)."""
    return rim_thickness / tooth_height


def rim_factor_agma(m_B: float) -> float:
    """AGMA 2001 rim thickness factor.

    .. math:: K_B = 1.6 \\ln(2.242/m_B)\\quad (m_B < 1.2),\\qquad K_B = 1\\quad (m_B \\ge 1.2)

    References
    ----------
    ANSI/AGMA 2001-D04, rim thickness factor (written for external gears); the same form is
    implemented in the public script ``DaviesDesmond/MSE3380-Design-Team-1``,
    ``Project/kbfunc.m``.
    """
    return 1.6 * math.log(2.242 / m_B) if m_B < BACKUP_FULL else 1.0


def failure_mode(rim_thickness: float, tooth_height: float) -> str:
    """Likely fatigue failure mode after paper A: tooth breakage when the rim is thicker than
    the tooth is high (hoop stresses small), rim fracture across the rim otherwise.

    References
    ----------
    Gutyria et al. 2017, introduction (δ > h: cracks run circumferentially and break teeth;
    small δ: σ_r and σ_t act together and the crack crosses the rim).
    """
    return "tooth breakage" if rim_thickness > tooth_height else "rim fracture"
