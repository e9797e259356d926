"""Citations used in the bevel reports, in one place so that a reference is corrected once.
The keys are entries of ``docs/references.md``."""

GEOM_STRAIGHT = "[GOST19624] table 1; [ISO23509] §5"
GEOM_SPIRAL = "[GOST19326] table 1; [ISO23509] §5"
CONE = "[ISO23509] §5.2 (pitch cone angles, cone distances)"
VIRTUAL = "[ISO10300-1] annex A (virtual cylindrical gear, method B1)"
CONTACT_RATIO = "[ISO10300-1] annex A (ε_vα, ε_vβ, ε_vγ = ε_vα + ε_vβ)"
FORCES = "[ISO10300-1] §5 (tangential force at the mean cone); [ISO23509] annex (axial, radial)"
ISO_H = "[ISO10300-2] method B1"
ISO_F = "[ISO10300-3] method B1"
ISO_K = "[ISO10300-1] §8 (K_Hβ = 1.5·K_Hβ-be, method C)"
TOOTH_FORM = "[ISO10300-3] §6.4 (load at the tip of the virtual gear, [ISO6336-3] method B)"
GOST = "[GOST21354] via the virtual spur pair, [Dunaev] §2.6 (θ_H, θ_F); [ConeGear]"
UNDERCUT = "[GOST16532] on the virtual gear ([GOST19624] table 1 note)"
PRACTICE = "design practice ([Dunaev] §2.6)"
PUBLISHED = ("[BevGear2023] ([ISO23509] spiral bevel example), [ISOTR10300-30] sample 1, "
             "[KHK] straight bevel examples; docs/bevel.md, published cases")
DESIGN = "design mode by re-rating ([GOST9563] first-series modules), docs/bevel.md"
LOAD_FACTORS = "[ISO10300-1] method B (K_v, K_Hα = K_Fα: the [ISO6336-1] forms, bevel ranges)"
ISO_STATIC = ("[ISO10300-2], [ISO10300-3] at the peak torque; static limits of [ISO6336-2] "
              "§10, [ISO6336-3] §12")
GOST_STATIC = "[GOST21354] peak load via the virtual spur pair ([ZPCIL] SIGMAX.h)"
