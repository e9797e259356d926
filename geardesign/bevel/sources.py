"""Citations used in the bevel reports, in one place so that a reference is corrected once.
The keys are entries of ``docs/references.md``."""

GEOM_STRAIGHT = "[GOST19624] table 1; [ISO23509] §5"
GEOM_SPIRAL = "[GOST19326] table 1; [ISO23509] §5"
CONE = "[ISO23509] §5.2 (pitch cone angles, cone distances)"
VIRTUAL = "[ISO10300-1] annex A (virtual cylindrical gear, method B1)"
CONTACT_RATIO = "[ISO10300-1] annex A (ε_vα, ε_vβ, ε_vγ = ε_vα + ε_vβ)"
CHORD_VIRTUAL = " (chord on the virtual gear, [GOST16532] rule)"
CHORD_ISO = "[ISO23509] 7.8, formulae (206)-(215) (mean normal section)"
SPEED_OUTER = "[Shigley] §15-1 (AGMA pitch line speed at the outer pitch circle, π d_e n1)"
FORCES = ("[ISO10300-1] §5 (F_mt at the mean cone); axial and radial: components of the "
          "normal force on the flank, hand as [ISO23509] defines it (docs/bevel.md, Forces)")
ISO_H = "[ISO10300-2] method B1"
ISO_F = "[ISO10300-3] method B1"
ISO_K = "[ISO10300-1] §8 (K_Hβ = 1.5·K_Hβ-be, method C)"
TOOTH_FORM = "[ISO10300-3] §6.4 (load at the tip of the virtual gear, [ISO6336-3] method B)"
GOST = "[GOST21354] via the virtual spur pair, [Dunaev] §2.6 (θ_H, θ_F)"
UNDERCUT = "[GOST16532] on the virtual gear ([GOST19624] table 1 note)"
PRACTICE = "design practice ([Dunaev] §2.6)"
PUBLISHED = ("[BevGear2023] ([ISO23509] spiral bevel example), [ISO23509] annex F.2 "
             "(tooth thickness, chords), [ISOTR10300-30] sample 1, [KHK] straight bevel "
             "examples, [Shigley] example 15-1; docs/bevel.md, published cases")
DESIGN = "design mode by re-rating ([GOST9563] first-series modules), docs/bevel.md"
