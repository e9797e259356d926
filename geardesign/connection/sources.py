"""Citations used in the shaft-hub connection reports, in one place so that a reference is
corrected once.  Keys are entries of ``docs/references.md``."""

KEY_TABLE = "[GOST23360] table 1; [DIN6885-1] table 1"
KEY_LENGTHS = "[GOST23360] length series"
KEY_GOST = "[Ivanov] ch. 6; [Dunaev] ch. 6"
KEY_PRACTICE = ("[Ivanov] ch. 6; [Dunaev] ch. 6 (hub length (0.8 ... 1.5)·d, the key shorter than "
                "the hub)")
KEY_DIN = "[DIN6892] method C"
KEY_SHARE = "[DIN6892] load share φ; [Ivanov] ch. 6"
KEY_ALLOW_GOST = "[Dunaev] ch. 6 (lower end; unverified)"
KEY_ALLOW_DIN = "[DIN6892] method C (f_S·f_H·R; unverified)"
SPLINE_GEOM = "[DIN5480] (d_B = m·z + 2·x·m + 1.1·m)"
SPLINE_GOST = "[GOST6033]; [Ivanov] ch. 6"
SPLINE_DIN = "[DIN5466] (p = 2T/(d_m·z·h_w·l·ψ)); [Niemann] Band I"
SPLINE_ALLOW = "[Ivanov] ch. 6 ([σ]см of splines); [InventorSplines]"
ISO286 = "[ISO286] tables 1 and 2"
LAME = "[DIN7190-1] (Lamé, elastic); [Roark] thick cylinders"
SMOOTHING = "[DIN7190-1] (smoothing 0.8·(Rz_i + Rz_a))"
FRICTION = "[DIN7190-1] friction table; [RoloffMatek] TB 12-6"
FRICTION_PRESS_IN = ("[DIN7190-1] longitudinal press fits (release μ_ll; [WHZPressfit] eq. "
                     "(15)); [RoloffMatek] TB 12-6")
PRESSURE_LIMIT = {
    "DIN 7190-1": "[DIN7190-1] (GEH: R_e·(1 − Q²)/√3; [WHZPressfit] eqs. (8)-(10))",
    "von Mises": "[Roark] thick cylinders (von Mises, plane stress)",
}
SLIP = "[DIN7190-1] (T = π/2·d²·l·μ·p)"
ASSEMBLY = "[DIN7190-1] (press-in force, shrink temperature)"
VON_MISES = "[Roark] thick cylinders (von Mises, plane stress)"
PRACTICE = "design practice"
