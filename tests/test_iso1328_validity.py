"""The range of validity of ISO 1328-1 (2013: 5 ≤ d ≤ 15 000, 0.5 ≤ m_n ≤ 70, 4 ≤ b ≤ 1 200
mm; 1995: 5 ≤ d ≤ 10 000, 0.5 ≤ m ≤ 70, 4 ≤ b ≤ 1 000 mm, [ISO1328-1] 1 and
[ISO1328-1-1995] 1) has one source: the drawing refuses a gear outside it, the ISO 6336
rating (spur and planetary) rates it with a warning naming the edition's range and the
gear's d, m_n and b."""

from __future__ import annotations

import copy

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.spur.tolerances import iso1328
from geardesign.spur.tolerances.gost1643 import ToleranceError
from tests.reference.planetary.test_kisssoft_nrel_iso6336 import report_spec
from tests.reference.planetary._util import planetary
from tests.test_iso6336_inputs import DATA

EDITIONS = {iso1328.STANDARD: {"d": (5.0, 15000.0), "m_n": (0.5, 70.0), "b": (4.0, 1200.0)},
            iso1328.STANDARD_1995: {"d": (5.0, 10000.0), "m_n": (0.5, 70.0),
                                    "b": (4.0, 1000.0)}}


def test_validity_ranges_are_the_standards():
    for standard, rng in EDITIONS.items():
        assert iso1328.validity(standard) == rng


@settings(max_examples=200, deadline=None)
@given(st.sampled_from(sorted(EDITIONS)), st.floats(1.0, 20000.0), st.floats(0.2, 90.0),
       st.floats(1.0, 1500.0), st.booleans())
def test_drawing_refuses_exactly_what_the_rating_warns_of(standard, d, m_n, b, internal):
    """flank_tolerances (the drawing) raises if and only if outside_validity (the rating's
    warning) names a size, for either edition and an internal gear's negative d."""
    outside = iso1328.outside_validity(-d if internal else d, m_n, b, standard)
    rng = EDITIONS[standard]
    expected = [k for k, v in (("d", d), ("m_n", m_n), ("b", b))
                if not rng[k][0] <= v <= rng[k][1]]
    assert [o[0] for o in outside] == expected
    try:
        iso1328.flank_tolerances(6, -d if internal else d, m_n, b, standard)
        refused = False
    except ToleranceError:
        refused = True
    assert refused == bool(outside)


def _range_checks(doc: dict) -> list:
    return [c for c in doc["checks"] if "TOLERANCE_RANGE" in c["code"]]


@pytest.mark.parametrize("standard, gear, words", [
    (iso1328.STANDARD_1995, {"face_width": 1100.0},
     "b = 1100 mm: the face width lies outside the range of ISO 1328-1:1995 (5 ≤ d ≤ 10000, "
     "0.5 ≤ m_n ≤ 70, 4 ≤ b ≤ 1000 mm); the 1995 size ranges end there"),
    (iso1328.STANDARD, {"module": 0.4},
     "m_n = 0.4 mm, b = 30 mm: the normal module lies outside the range of ISO 1328-1:2013 "
     "(5 ≤ d ≤ 15000, 0.5 ≤ m_n ≤ 70, 4 ≤ b ≤ 1200 mm); the 2013 formulas were extrapolated"),
])
def test_spur_rating_warns_outside_the_edition(standard, gear, words):
    d = copy.deepcopy(DATA)
    d["gear"].update(gear)
    d["iso"] = {"tolerance_standard": standard}
    found = _range_checks(run_data(d).document())
    assert [c["code"] for c in found] == ["ISO_TOLERANCE_RANGE_PINION",
                                          "ISO_TOLERANCE_RANGE_WHEEL"]
    for c, d_ref in zip(found, (20 * d["gear"]["module"], 60 * d["gear"]["module"])):
        assert c["severity"] == "warning" and not c["passed"]
        assert f"d = {d_ref:g} mm" in c["message"] and words in c["message"]
    inside = copy.deepcopy(DATA)
    inside["iso"] = {"tolerance_standard": standard}
    assert not _range_checks(run_data(inside).document())


def test_planetary_ring_beyond_the_1995_face_width():
    """NREL stage 1 with a 1 100 mm face width: every gear of both meshes is outside the
    1995 range (b ≤ 1000 mm), each mesh warns for its two members; at the report's 491 mm
    no warning."""
    data = report_spec(1)
    assert not _range_checks(planetary(data))
    data["train"]["face_width"] = 1100.0
    codes = sorted(c["code"] for c in _range_checks(planetary(data)))
    assert codes == ["PLANET_RING_ISO_TOLERANCE_RANGE_PLANET",
                     "PLANET_RING_ISO_TOLERANCE_RANGE_RING",
                     "SUN_PLANET_ISO_TOLERANCE_RANGE_PLANET",
                     "SUN_PLANET_ISO_TOLERANCE_RANGE_SUN"]
