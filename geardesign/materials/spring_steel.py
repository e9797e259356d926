"""Spring steels and wires for helical compression springs (data in ``spring_steel.toml``).

The table gives, per grade, the tensile strength law R_m = A/d^m of drawn wire (m = 0 for a
heat-treated bar steel), its valid diameter range, the shear modulus G and the static
allowable shear stress as a share of R_m.  Sources and the values quoted from memory are
named in the data file.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

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
    import tomllib

    raw = tomllib.loads(DATA.read_text(encoding="utf-8"))
    return {k: SpringSteel(key=k, **v) for k, v in raw.items()}


def names() -> tuple[str, ...]:
    """The grade keys, in the order of the data file."""
    return tuple(table())


def get(key: str) -> SpringSteel:
    return table()[key]
