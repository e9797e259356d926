"""Forcing frequencies and vibration discriminants of the BELAZ motor-wheel reducer.

Source: Gavrilov S. A., Ishin N. N., Goman A. M., Skorokhodov A. S., "Vibration
monitoring of the technical condition of gear wheels of planetary reducers", Bulletin of
NTU "KhPI" 2017 No. 25 ([Gavrilov2017]).

Table 1 (L2078-2118): first planetary row of the 130-t BELAZ motor-wheel reducer, sun
z1 = 21, planets z2 = 47, ring z3 = 117, motor (sun) shaft 894 min⁻¹, mesh frequency
274 Hz; every value is rounded to the analyser resolution of 1 Hz, so the tolerance is
0.5 Hz.  The table holds only if the ring of that row turns (f_H = f_0 − f_1 ≈ 1.85 Hz,
ring −0.49 Hz: a differential row whose ring drives the hub); with a fixed ring the same
teeth give f_H = 2.27 Hz and f_z = 265.3 Hz, not 274 Hz.  This is an inference, not
printed in the paper; it is no misprint, and the test takes the carrier speed that the
printed f_z implies.  The admissible fluctuations Δf are ±15 % of each frequency (the
paper states it for the motor shaft).

Table 2 (L2217-2226): amplitudes of the first five mesh harmonics of the second-row sun at
three mileages and the discriminants S_fz (printed 1.84, 2.23, 4.17 m/s²) and P_fz (0,
0.21, 1.27), 2 decimals, tolerance 0.006.
"""

import pytest

from geardesign.planetary.kinematics import (Train, discriminant, frequencies,
                                             relative_growth, speeds)
from tests.conftest import assert_ref
from tests.reference.planetary._util import planetary

Z1, Z2, Z3 = 21, 47, 117
N_MOTOR = 894.0
F_Z = 274.0


def _row1():
    f0 = N_MOTOR / 60.0
    n_h = 60.0 * (f0 - F_Z / Z1)        # carrier speed implied by the printed mesh frequency
    t = Train("2K-H", Z1, Z2, Z3, 3)
    return frequencies(t, speeds(t, {"sun": N_MOTOR, "carrier": n_h}))


def test_table1_frequencies():
    fr = _row1()
    printed = {"f0": 15, "fz": 274, "f1": 13, "f2": 6, "f3": 2, "fH": 2}
    got = {"f0": fr.f["sun"], "fz": fr.f_mesh, "f1": fr.f_rel["sun"],
           "f2": fr.f_rel["planet"], "f3": fr.f_rel["ring"], "fH": fr.f_carrier}
    for key, value in printed.items():
        assert_ref(got[key], value, 0.5, f"BELAZ Table 1 {key}")
    for key, base, value in (("Δf0", got["f0"], 2), ("Δf1", got["f1"], 2), ("Δf2", got["f2"], 1)):
        assert_ref(0.15 * base, value, 0.5, f"BELAZ Table 1 {key} (±15 %)")


def test_fixed_ring_would_not_give_the_printed_mesh_frequency():
    t = Train("2K-H", Z1, Z2, Z3, 3)
    fr = frequencies(t, speeds(t, {"sun": N_MOTOR, "ring": 0.0}))
    assert abs(fr.f_mesh - F_Z) > 5.0 and fr.f_mesh == pytest.approx(265.3, abs=0.05)


def test_table1_through_the_calculator():
    """The same row as a spec: a differential (fixed = "none") with the carrier speed
    imposed."""
    n_h = 60.0 * (N_MOTOR / 60.0 - F_Z / Z1)
    doc = planetary({
        "train": {"planets": 3, "module": 8.0, "face_width": 80.0,
                  "center_distance": 8.0 * (Z3 - Z2) / 2},
        "teeth": {"sun": Z1, "planet": Z2, "ring": Z3},
        "ring": {"tip_shortening": 0.2},
        "operation": {"fixed": "none", "input": "sun", "output": "ring", "control": "carrier",
                      "speed": N_MOTOR, "control_speed": n_h},
        "frequencies": {"amplitudes": [0.40, 0.75, 1.50, 1.40, 0.20],
                        "baseline": [0.70, 0.85, 0.30, 0.35, 1.4]},
    })
    f = doc["results"]["frequencies"]
    assert_ref(f["f_mesh"], 274, 0.5, "f_z")
    assert_ref(f["f_sun_rel"], 13, 0.5, "f1")
    assert_ref(f["f_planet_rel"], 6, 0.5, "f2")
    assert_ref(f["f_ring_rel"], 2, 0.5, "f3")
    assert_ref(f["f_carrier"], 2, 0.5, "fH")
    assert_ref(f["S_fz"], 2.23, 0.006, "S_fz at 194809 km")
    assert_ref(f["P_fz"], 0.21, 0.006, "P_fz at 194809 km")


TABLE2 = [  # mileage km: amplitudes of f_z..5f_z (m/s²), printed S_fz, printed P_fz
    (164044, [0.70, 0.85, 0.30, 0.35, 1.4], 1.84, 0.0),
    (194809, [0.40, 0.75, 1.50, 1.40, 0.20], 2.23, 0.21),
    (233357, [0.50, 1.50, 2.25, 1.75, 2.60], 4.17, 1.27),
]


@pytest.mark.parametrize("km, amps, S, P", TABLE2, ids=[str(r[0]) for r in TABLE2])
def test_table2_discriminants(km, amps, S, P):
    S0 = discriminant(TABLE2[0][1])
    assert_ref(discriminant(amps), S, 0.006, f"S_fz at {km} km")
    assert_ref(relative_growth(discriminant(amps), S0), P, 0.006, f"P_fz at {km} km")
