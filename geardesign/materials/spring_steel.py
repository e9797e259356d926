"""Spring steels and wires for helical compression springs (data in ``spring_steel.toml``).

The table gives, per grade, the tensile strength law R_m = A/d^m of drawn wire (m = 0 for a
heat-treated bar steel), its valid diameter range, the shear modulus G and the static
allowable shear stress as a share of R_m.  Sources and the values quoted from memory are
named in the data file.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

DATA = Path(__file__).with_name("spring_steel.toml")


@dataclass(frozen=True)
class SpringSteel:
    key: str
    name: str
    standard: str
    A: float          # MPa·mm^m
    m: float
    d_min: float      # mm
    d_max: float      # mm
    G: float          # MPa
    allowable: float  # static allowable shear stress / R_m

    def tensile_strength(self, d: float) -> float:
        """R_m = A/d^m [MPa] for a wire diameter d [mm].

        Reference: Shigley's Mechanical Engineering Design, Table 10-4 (ASTM wires);
        GOST 14959 minimum values for heat-treated spring steels (m = 0).
        """
        return self.A / d ** self.m

    def allowable_shear(self, d: float) -> float:
        """Static allowable shear stress [τ] = share·R_m [MPa] (Shigley Table 10-6; spring
        class II share 0.5 for GOST steels)."""
        return self.allowable * self.tensile_strength(d)

    def covers(self, d: float) -> bool:
        return self.d_min <= d <= self.d_max


@lru_cache(maxsize=1)
def table() -> dict[str, SpringSteel]:
    """All grades, by key."""
    from geardesign.core.data import toml_table

    raw = toml_table(DATA)
    return {k: SpringSteel(key=k, **v) for k, v in raw.items()}


def names() -> tuple[str, ...]:
    """The grade keys, in the order of the data file."""
    return tuple(table())


def get(key: str) -> SpringSteel:
    return table()[key]


# --- torsion springs (bending) ---------------------------------------------------------
# Added for helical torsion springs, whose coils work in bending: Young's modulus E and the
# static allowable bending stress.  The grade table above stays as it is.

#: Young's modulus E [MPa] of the grades above, for the stiffness of torsion springs.
#: Steel wires 207 000 MPa and 302 stainless 193 000 MPa: the public spring program ODOP
#: (GitHub thegrumpys/odop, client/src/designtypes/Spring/mat_metric.json, column "ee"),
#: which gives 207 000 MPa for all carbon and alloy spring-steel wires including the
#: EN 51CrV4/60Cr3 bar steels; the GOST 14959 steels 60S2A and 65G are given the same value
#: by analogy (GOST 13765 rounds to 2.0...2.1·10⁵ MPa; from memory, verify).
ELASTIC_MODULUS = {
    "music_wire": 207000.0,
    "hard_drawn": 207000.0,
    "oil_tempered": 207000.0,
    "chrome_vanadium": 207000.0,
    "chrome_silicon": 207000.0,
    "stainless_302": 193000.0,
    "60S2A": 207000.0,
    "65G": 207000.0,
}

#: Static bending yield of torsion-spring wire from the shear allowable of the table:
#: S_y = [τ]/0.577 (distortion energy), which gives Shigley's torsion-spring values
#: 0.78·R_m (cold-drawn and music wire, share 0.45), 0.87·R_m (hardened and tempered
#: carbon and low-alloy wire, 0.50) and 0.61·R_m (austenitic stainless, 0.35) —
#: Budynas & Nisbett, "Shigley's Mechanical Engineering Design", §10-12 (eq. 10-57); the
#: same 0.45/0.577 = 0.78 is used by GitHub OmriStein/MEtoolbox (helical torsion spring
#: example).
SHEAR_TO_BENDING = 0.577


def elastic_modulus(key: str) -> float | None:
    """Young's modulus [MPa] of a grade (``None`` if the table has no value for it)."""
    return ELASTIC_MODULUS.get(key)


def bending_allowable(steel: SpringSteel, d: float) -> float:
    """Static allowable bending stress of a torsion-spring wire of diameter d [mm]:
    [σ] = [τ]/0.577 = share·R_m/0.577 [MPa] (Shigley §10-12; see SHEAR_TO_BENDING)."""
    return steel.allowable_shear(d) / SHEAR_TO_BENDING
