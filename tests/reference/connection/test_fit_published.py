"""Interference fits against published worked examples (values this code did not produce).

* [Bhandari] examples 22.6 and 22.8, as computed in [FOSSEE] (GitHub
  ``FOSSEE/Scilab-TBC-Uploads``, commit b1f5c3f8d6671b4331cef1dcebdf63b7a43a3a2b, book 764,
  ``CH22/EX22.6.b/result22_6.txt`` and ``CH22/EX22.8.b/result22_8.txt``): a steel tube shrunk
  into a steel jacket, E = 207 000 N/mm², i.e. a hollow shaft in a hub of the same material.
  22.6: D1 = 20 (bore), D2 = 40 (joint), D3 = 60 mm (jacket); the jacket's hoop stress at its
  bore is limited to 100 N/mm², so p = 100·(D3² − D2²)/(D3² + D2²) = 38.4615 N/mm², and the
  printed jacket bore 39.968289 mm gives the interference 31.711 µm.  22.8: D1 = 50, D2 = 75,
  D3 = 100 mm; printed p = 3.615169 N/mm² and jacket bore 74.991916 mm (interference
  8.084 µm).  The calculator, given the interference (no smoothing: Rz = 0), must return the
  printed pressure and hoop stress.  Tolerance: the printed bore has six decimals (±0.5e-6 mm),
  which moves p by ±6e-4 (22.6) and ±2.3e-4 N/mm² (22.8).
* [PressFitCalc] worked example: d = 50 mm, hub D = 80 mm, L = 40 mm, δ = 0.04 mm,
  E = 210 GPa, μ = 0.12 (solid steel shaft, same material): p = 51.2 MPa (table), axial force
  ≈ 38.6 kN, torque ≈ 965 N·m, hub hoop stress ≈ 117 MPa.  Tolerance: half a unit of the
  last printed digit.
* [DopuskiPosadki] fig. 1.2, the ISO 286 deviations at 25 mm ([ISO286] tables, ``iso286.csv``):
  H7 +21/0; f6 −20/−33 (clearance 20...54 µm); r6 +41/+28 (interference 7...41 µm); k6 +15/+2
  (interference −19...15 µm).  Exact.
"""

import pytest

from geardesign.connection import iso286
from geardesign.core.registry import run_data
from tests.conftest import assert_ref


def _fit(d, D_a, D_i, U, E, length=40.0, mu=None):
    fit = {"diameter": d, "hub_outer_diameter": D_a, "shaft_bore": D_i, "length": length,
           "interference_min": U, "interference_max": U, "rz_shaft": 0.0, "rz_hub": 0.0,
           "shaft_modulus": E, "hub_modulus": E, "shaft_yield": 1000.0, "hub_yield": 1000.0}
    if mu is not None:
        fit["friction"] = mu
    return run_data({"kind": "connection", "load": {"torque": 1.0}, "fit": fit}
                    ).document()["results"]


def test_bhandari_22_6_compound_tube():
    r = _fit(40.0, 60.0, 20.0, (40.0 - 39.968289) * 1e3, 207000.0)
    assert_ref(r["capacity"]["p_max"], 100 * (60 ** 2 - 40 ** 2) / (60 ** 2 + 40 ** 2), 6e-4,
               "[Bhandari] 22.6 shrinkage pressure")
    assert_ref(r["stress"]["sigma_t_hub"], 100.0, 0.002, "[Bhandari] 22.6 jacket hoop stress")


def test_bhandari_22_8_compound_tube():
    r = _fit(75.0, 100.0, 50.0, (75.0 - 74.991916) * 1e3, 207000.0)
    assert_ref(r["capacity"]["p_max"], 3.615169, 3e-4, "[Bhandari] 22.8 shrinkage pressure")


def test_press_fit_calculator_example():
    r = _fit(50.0, 80.0, 0.0, 40.0, 210000.0, length=40.0, mu=0.12)
    assert_ref(r["capacity"]["p_min"], 51.2, 0.05, "[PressFitCalc] p")
    assert_ref(r["capacity"]["F_slip"] / 1e3, 38.6, 0.05, "[PressFitCalc] axial force kN")
    assert_ref(r["capacity"]["T_slip"], 965.0, 0.5, "[PressFitCalc] torque N·m")
    assert_ref(r["stress"]["sigma_t_hub"], 117.0, 0.5, "[PressFitCalc] hub hoop stress")


@pytest.mark.parametrize("name, ES, es, ei, U_max, U_min", [
    ("H7/f6", 21, -20, -33, -20, -54),
    ("H7/r6", 21, 41, 28, 41, 7),
    ("H7/k6", 21, 15, 2, 15, -19),
])
def test_iso286_deviations_at_25_mm(name, ES, es, ei, U_max, U_min):
    f = iso286.fit(name, 25.0)
    assert (f.ES, f.EI, f.es, f.ei, f.U_max, f.U_min) == (ES, 0, es, ei, U_max, U_min)
