"""GOST 21354-87 allowable-stress chain: printed output of the public GOST program ZPCIL.

Source: GitHub ``s-berlin/ZPCIL_test``, ``ZPCIL_test/RESULT1`` at commit
0edb8befd2583cd023d0c178f86e0f5fd535691c, run "R-277": helical pair 41/90, m_n = 3,
β = 10°30′, a_w = 200, life 30000 h at 1120 min⁻¹, one load step, pinion surface-hardened
60 HRC (σ_Hlim = 17·60 + 200 = 1220), wheel through-hardened 30 HRC (18·30 + 150 = 690).

Only the allowable side is a reference.  That run computed the loads with T = 1 N·m
instead of 1000 (σ_H = 26.7 MPa printed), and the C++ port has known table bugs (K_Hv,
K_Hβ, Z_ε, Y_N, wheel Y_FS, σ_FPmax): those printed values are not used.  The values below
do not depend on the torque.  ZPCIL runs in single precision: tolerance 2·10⁻⁵ relative
(printed to 6 digits) unless stated.

The hardnesses lie outside the ranges GOST gives for the two treatments (the run used
them anyway): geardesign computes the same numbers and warns (HARDNESS_RANGE_*).
"""

import pytest

from geardesign.core.registry import run_data
from tests.conftest import dms, flat

SPEC = {
    "kind": "spur",
    "gear": {"module": 3.0, "z1": 41, "z2": 90, "helix_angle": dms(10, 30), "face_width": 80.0,
             "center_distance": 200.0, "x1": 0.0, "accuracy_grade": 8, "bearing_scheme": 6},
    "load": {"speed1": 1120.0, "torque1": 1000.0, "life_hours": 30000.0, "peak_torque1": 2000.0},
    "material": {
        "pinion": {"treatment": "induction", "hardness_HRC": 60.0, "sigma_T": 1000.0},
        "wheel": {"treatment": "through_hardened", "hardness_HRC": 30.0, "sigma_T": 800.0},
    },
}

PRINTED = {  # key: (value, relative tolerance)
    "v_H": (7.33594, 2e-5),       # circumferential velocity at d1, m/s
    "N_HE1": (2016e6, 1e-9),      # 60·1120·30000
    "N_HE2": (918.4e6, 5e-5),     # printed 918.4 (10⁶)
    "N_HG1": (120e6, 1e-9),       # capped
    "N_HG2": (20.4269e6, 2e-5),   # 30·HB^2.4, HB from 30 HRC by the ZPCIL fit
    "Z_N1": (0.868429, 2e-5),
    "Z_N2": (0.82672, 2e-5),
    "Z_v1": (1.02191, 2e-5),      # 0.925·v^0.05 (hard pinion)
    "Z_v2": (1.03744, 2e-5),      # 0.85·v^0.1 (wheel <= 350 HB)
    "sigma_HP2": (537.996, 2e-5),
    "Y_X1": (1.03436, 2e-5),
    "Y_delta": (0.999935, 2e-5),
    "S_H1_min": (1.2, 1e-12),
    "S_H2_min": (1.1, 1e-12),
    "Z_H": (2.45241, 5e-4),       # ZPCIL prints 2.45241; double precision gives 2.4514
}


@pytest.fixture(scope="module")
def values():
    return flat(run_data(SPEC).document())


@pytest.mark.parametrize("key", PRINTED)
def test_printed_allowable_chain(values, key):
    expected, rel = PRINTED[key]
    assert abs(values[key] - expected) <= rel * abs(expected), (key, values[key], expected)


def test_outside_the_treatment_ranges_warns():
    doc = run_data(SPEC).document()
    warned = {c["code"] for c in doc["checks"] if not c["passed"] and c["severity"] == "warning"}
    assert {"HARDNESS_RANGE_PINION", "HARDNESS_RANGE_WHEEL"} <= warned
