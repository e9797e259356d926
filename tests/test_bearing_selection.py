"""Selection from the built-in catalogue at typical reducer loads for every bore it holds
(issue 18): F_r = 9 kN·(d/40 mm)², n = 40 000/d min⁻¹ (mm), L_10h >= 10 000 h, some type of
bearing of that bore (deep groove, cylindrical, spherical or tapered roller, angular contact)
must pass.  12 mm is the one exception: the largest 12 mm bearing, SKF 6301 (C = 9.75 kN),
gives about 8 700 h at 810 N and 3 333 min⁻¹."""

import pytest

from geardesign.bearing import catalogue as CAT
from geardesign.core.registry import run_data

TYPES = ("deep_groove_ball", "cylindrical_roller", "spherical_roller", "tapered_roller",
         "angular_contact_ball")


def _select(kind, d, F, n, life):
    return run_data({"kind": "bearing", "method": "iso281_2007", "mode": "select",
                     "bearing": {"type": kind, "d": d}, "load": {"F_r": F, "speed": n},
                     "requirements": {"life": life}}).document()


def test_40_mm_bore_at_9_kN_finds_a_bearing():
    doc = _select("cylindrical_roller", 40.0, 9000.0, 1000.0, 20000.0)
    assert doc["verdict"] == "pass"
    assert doc["results"]["selection"]["selected"] == "SKF NU 2208 ECP"


def test_every_bore_finds_a_bearing_at_reducer_loads():
    bores = sorted({b for k in TYPES for b in CAT.bores(k)})
    assert bores[0] == 10 and bores[-1] == 200
    missing = []
    for d in bores:
        F, n = 9000.0 * (d / 40.0) ** 2, 40000.0 / d
        if not any(_select(k, d, F, n, 10000.0)["verdict"] == "pass"
                   for k in TYPES if d in CAT.bores(k)):
            missing.append(d)
    assert missing == [12.0]
