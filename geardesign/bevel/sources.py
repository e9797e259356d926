"""Citations used in the bevel reports, in one place so that a reference is corrected once.
The keys are entries of ``docs/references.md``."""

GEOM_STRAIGHT = "[GOST19624] table 1; [ISO23509] §5"
GEOM_SPIRAL = "[GOST19326] table 1; [ISO23509] §5"
CONE = "[ISO23509] §5.2 (pitch cone angles, cone distances)"
VIRTUAL = "[ISO10300-1] annex A (virtual cylindrical gear, method B1)"
CONTACT_RATIO = "[ISO10300-1] annex A (ε_vα, ε_vβ, ε_vγ = ε_vα + ε_vβ)"
CHORD_VIRTUAL = " (chord on the virtual gear, [GOST16532] rule)"
CHORD_CONSTANT = " (constant chord s cos²α_n, h_a − ¼ s sin 2α_n, [GOST16532] form)"
CHORD_ISO = "[ISO23509] 7.8, formulae (206)-(215) (mean normal section)"
SPEED_OUTER = "[Shigley] §15-1 (AGMA pitch line speed at the outer pitch circle, π d_e n1)"
FORCES = ("[ISO10300-1] §5 (F_mt at the mean cone); axial and radial: components of the "
          "normal force on the flank, hand as [ISO23509] defines it (docs/bevel.md, Forces)")
ISO_H = "[ISO10300-2] method B1"
ISO_F = "[ISO10300-3] method B1"
ISO_K = "[ISO10300-1] §8 (K_Hβ = 1.5·K_Hβ-be, method C)"
TOOTH_FORM = "[ISO10300-3] §6.4 (load at the tip of the virtual gear, [ISO6336-3] method B)"
GOST = "[GOST21354] via the virtual spur pair, [Dunaev] §2.6 (θ_H, θ_F); [ConeGear]"
UNDERCUT = "[GOST16532] on the virtual gear ([GOST19624] table 1 note)"
PRACTICE = "design practice ([Dunaev] §2.6)"
PUBLISHED = ("[BevGear2023] ([ISO23509] spiral bevel example), [ISO23509] annex F.2 "
             "(tooth thickness, chords), [ISOTR10300-30] sample 1, [KHK] straight bevel "
             "examples, [Shigley] example 15-1; docs/bevel.md, published cases")
DESIGN = "design mode by re-rating ([GOST9563] first-series modules), docs/bevel.md"
LOAD_FACTORS = "[ISO10300-1] method B (K_v, K_Hα = K_Fα: the [ISO6336-1] forms, bevel ranges)"
ISO_STATIC = ("[ISO10300-2], [ISO10300-3] at the peak torque; static limits of [ISO6336-2] "
              "§10, [ISO6336-3] §12")
GOST_STATIC = "[GOST21354] peak load via the virtual spur pair ([ZPCIL] SIGMAX.h)"

VERIFIED = {
    True: "the spiral pair's cones, mean-section modules, diameters and heights "
          "([ISO23509] spiral example), its virtual gears, contact ratios and the ISO 10300 "
          "method B1 stresses with K_v and K_Hα by ISO 10300-1 method B (subcritical range) "
          "([ISOTR10300-30] sample 1), its mean normal tooth thickness "
          "and chordal dimensions s_mn, s_mt, d_mn, s_mnc, h_amc ([ISO23509] annex F.2); "
          "docs/bevel.md",
    False: "the outer-cone geometry in both depth forms (cones, cone distance, heights, "
           "addendum/dedendum and face/root angles, tip diameters, apex distance B, b_ax, "
           "d_ai, the back-cone gear: [KHK] standard and Gleason straight bevel examples), "
           "the outer pitch diameter and pitch line speed v_et ([Shigley] example 15-1), "
           "the virtual gears and the ISO 10300 method B1 formulas shared with spiral teeth "
           "([ISOTR10300-30] sample 1, a spiral pair; docs/bevel.md)",
}
"""What of each tooth form has been checked against a published worked example (by
``teeth == "spiral"``); docs/bevel.md lists the cases."""

UNVERIFIED = {
    True: ("addendum/dedendum angles (standard depth, not the cutter's duplex taper), "
           "the chordal height h_c of the virtual gear (without the cos δ of ISO 23509's "
           "h_amc; GOST 19326 not at hand) and the constant chord s_cc, h_cc, the axial and "
           "radial forces and their signs by hand and rotation, ISO 10300 K_Hβ-be other "
           "than 1.10, K_v by method B outside the subcritical range and the upper limit of "
           "K_Hα, the static checks at a peak torque (ISO and GOST), and strength by GOST "
           "21354 (θ_H, θ_F of circular teeth: only against an independent program, which "
           "has θ_H = 1.23 + 0.13u, not 1.13 + 0.13u, for a hard pinion on a soft wheel)"),
    False: ("tooth thickness and chordal dimensions at the outer cone (s, s_c, h_c and the "
            "constant chord s_cc, h_cc of GOST 19624) and the ISO 23509 mean-section rows of "
            "straight teeth (their formulas are checked on a spiral pair only), the axial and "
            "radial forces, ISO 10300 for straight teeth (Z_LS = 1, Y_BS = 1, K_Hβ-be other "
            "than 1.10, K_v and K_Hα by method B), the static checks at a peak torque (ISO "
            "and GOST), and strength by GOST 21354 (θ_H = θ_F = 0.85: only against an "
            "independent program)"),
}
"""The parts not yet checked against a published worked example, by tooth form."""
