"""The backlash chain of a gear pair: tooth-thickness allowances, the centre-distance
tolerance and the temperatures give the range of the normal backlash.

Normal backlash from the thickness allowances E_sn1, E_sn2 [µm] (negative: thinner teeth)
and a change Δa of the centre distance ([ISO21771] backlash; [ISO10064-2] 5.3):

.. math:: j_{bn} = -(E_{sn1} + E_{sn2})\\cos α_n + 2Δa \\sin α_{wt} \\cos β_b

Thermal expansion at operating temperature ([ISO10064-2] 5.3; [GOST1643], annex on the
backlash needed for temperature compensation): the housing of expansion coefficient α_h
and temperature t_h moves the centres apart by a_w·α_h·(t_h − 20 °C); each gear grows its
pitch radius by ½d_w·α_i·(t_i − 20 °C), which acts as a smaller centre distance:

.. math:: Δa_θ = a_w α_h Δt_h - \\tfrac12 (d_{w1} α_1 Δt_1 + d_{w2} α_2 Δt_2)

Internal pairs (an external pinion in an internal gear).  The tooth thickness allowances
of the internal gear are those of its teeth, negative as for an external gear: a thinner
internal tooth is a wider space, E_en = −E_sn ([DIN3967] 2; [ISO21771] 6, the internal
gear's s_n; KISSsoft prints A_s.e/i = −0.430/−0.590 mm for the NREL stage-1 ring and a
larger dimension between balls with them, [KISSsoft2017] section 6), so the backlash from the
allowances is the same sum.  The centre distance acts the other way: a larger a_w pushes the
pinion into the internal teeth and closes the backlash ([DIN3967] 2, A_a of an internal
pair with the opposite sign; KISSsoft prints A_a.e/i = −0.045/+0.045 mm for the internal
mesh against +0.045/−0.045 mm for the external one, [KISSsoft2017] section 6).  The least
backlash is therefore at a_w + f_a; with a symmetric ±f_a the range is unchanged.  In the
thermal change the housing and the internal gear swap roles (a_w = r_w2 − r_w1):

.. math:: Δa_θ = -a_w α_h Δt_h + \\tfrac12 (d_{w2} α_2 Δt_2 - d_{w1} α_1 Δt_1)
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

T_REF = 20.0
"""Reference temperature of the drawing dimensions [°C]."""


@dataclass(frozen=True)
class Thermal:
    """Operating temperatures [°C] and expansion coefficients [1/K] of housing, pinion, wheel."""

    t_housing: float
    t1: float
    t2: float
    alpha_housing: float
    alpha1: float
    alpha2: float

    def delta_a(self, a_w: float, d_w1: float, d_w2: float, internal: bool = False) -> float:
        """Equivalent centre-distance change Δa_θ [mm], positive when it opens the backlash
        (module docstring; ``internal``: gear 2 is an internal gear)."""
        if internal:
            return (-a_w * self.alpha_housing * (self.t_housing - T_REF)
                    + 0.5 * (d_w2 * self.alpha2 * (self.t2 - T_REF)
                             - d_w1 * self.alpha1 * (self.t1 - T_REF)))
        return (a_w * self.alpha_housing * (self.t_housing - T_REF)
                - 0.5 * (d_w1 * self.alpha1 * (self.t1 - T_REF)
                         + d_w2 * self.alpha2 * (self.t2 - T_REF)))


@dataclass(frozen=True)
class Backlash:
    """Normal backlash range [µm]: cold (20 °C) and at operating temperature."""

    j_thickness_min: float   # −(E_sns1 + E_sns2)·cos α_n
    j_thickness_max: float   # −(E_sni1 + E_sni2)·cos α_n
    j_fa: float              # 2·f_a·sin α_wt·cos β_b
    j_thermal: float         # 2·Δa_θ·sin α_wt·cos β_b (0 without temperatures)
    jn_min: float
    jn_max: float
    jn_min_hot: float
    jn_max_hot: float


def centre_distance_effect(delta_a_um: float, alpha_tw: float, beta_b: float) -> float:
    """Normal backlash change [µm] from a centre-distance change Δa [µm]:
    2·Δa·sin α_wt·cos β_b ([ISO21771]).

    >>> round(centre_distance_effect(10.0, math.radians(20.0), 0.0), 4)
    6.8404
    """
    return 2.0 * delta_a_um * math.sin(alpha_tw) * math.cos(beta_b)


def backlash_range(upper: tuple[float, float], lower: tuple[float, float], fa_um: float,
                   alpha_n: float, alpha_tw: float, beta_b: float,
                   thermal_um: float = 0.0) -> Backlash:
    """Least and largest normal backlash [µm] from the upper and lower thickness allowances
    of both gears [µm], the centre-distance tolerance ±f_a [µm] and the thermal change
    ``thermal_um`` = 2·Δa_θ·sin α_wt·cos β_b [µm] (module docstring)."""
    j_lo = -(upper[0] + upper[1]) * math.cos(alpha_n)
    j_hi = -(lower[0] + lower[1]) * math.cos(alpha_n)
    j_fa = centre_distance_effect(fa_um, alpha_tw, beta_b)
    return Backlash(j_lo, j_hi, j_fa, thermal_um, j_lo - j_fa, j_hi + j_fa,
                    j_lo - j_fa + thermal_um, j_hi + j_fa + thermal_um)


def upper_allowances(jn_required: float, fa_um: float, alpha_n: float, alpha_tw: float,
                     beta_b: float, thermal_um: float = 0.0) -> float:
    """Upper thickness allowance of each gear [µm, ≤ 0], the two equal, for which the least
    backlash, cold and at operating temperature, is ``jn_required`` with the centre distance
    at a_w − f_a:

    .. math:: E_{sns} = -\\frac{j_{n,min} + 2 f_a \\sin α_{wt}\\cos β_b
              - \\min(0, j_θ)}{2\\cos α_n}

    Pitch, profile and alignment deviations are not compensated here (GOST 1643-81 builds a
    compensation into its table of E_Hs; give E_Hs from that table to use it).
    """
    need = jn_required + centre_distance_effect(fa_um, alpha_tw, beta_b) - min(0.0, thermal_um)
    return -max(need, 0.0) / (2.0 * math.cos(alpha_n))
