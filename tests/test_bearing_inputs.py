"""Bearing calculator: bad input gives one line naming file, key, value and what is allowed,
exit 2, no traceback, nothing on stdout."""

import pytest

from tests.helpers_cli import run_bad

GOOD = """kind = "bearing"
method = "gost18855_94"
[bearing]
designation = "6208"
[load]
F_r = 3000.0
F_a = 1000.0
speed = 1000.0
"""
ISO = GOOD.replace('"gost18855_94"', '"iso281_2007"')
SINGLE = "F_r = 3000.0\nF_a = 1000.0\nspeed = 1000.0\n"


def rep(old, new, text=GOOD):
    assert old in text
    return text.replace(old, new)


CATALOGUE = ("it holds deep groove 60/62/63/64, angular contact 72 B/73 B, cylindrical roller "
             "NU/NJ/NUP 2/3/22/23, tapered roller 302/303/313/322/323, spherical roller "
             "222/223/230/231 and thrust ball 511/512 (`geardesign bearings` lists them); or "
             "give bearing.type, C_r and C_0r instead")

CASES = [
    ("unknown designation, close matches", rep('"6208"', '"6280"'),
     [f's.toml: bearing.designation = "6280": not in the built-in catalogue (did you mean '
      f'"6028", "6208", "6328"?); {CATALOGUE}']),
    ("unknown designation", rep('"6208"', '"XYZ-9"'),
     [f's.toml: bearing.designation = "XYZ-9": not in the built-in catalogue; {CATALOGUE}']),
    ("negative radial load", rep("F_r = 3000.0", "F_r = -3000.0"),
     ["s.toml: load.F_r = -3000.0: must be a number >= 0 and <= 100000000 (N)"]),
    ("negative axial load", rep("F_a = 1000.0", "F_a = -1.0"),
     ["s.toml: load.F_a = -1.0: must be a number >= 0 and <= 100000000 (N)"]),
    ("negative spectrum load", rep(SINGLE, "[[load.spectrum]]\nF_r = -5.0\nspeed = 100.0\n"
                                           "time_share = 1.0\n"),
     ["s.toml: load.spectrum[0].F_r = -5.0: must be a number >= 0 and <= 100000000 (N)"]),
    ("reliability below 90 %", GOOD + "[requirements]\nreliability = 85.0\n",
     ["s.toml: requirements.reliability = 85.0: must be a number >= 90 and <= 99.95 (%)"]),
    ("reliability above 99.95 %", ISO + "[requirements]\nreliability = 99.99\n",
     ["s.toml: requirements.reliability = 99.99: must be a number >= 90 and <= 99.95 (%)"]),
    ("GOST 18855-94 a1 ends at 99 %", GOOD + "[requirements]\nreliability = 99.5\n",
     ['s.toml: requirements.reliability = 99.5: GOST 18855-94 tabulates a1 only up to 99 %; '
      'use method = "iso281_2007" for up to 99.95 %']),
    ("a_ISO without viscosity", ISO + '[lubrication]\ncontamination = "normal"\n',
     ["s.toml: lubrication.viscosity: missing; give the viscosity at the operating temperature "
      "(mm^2/s), or oil and temperature, or nu40 (and nu100) and temperature, or kappa"]),
    ("a_ISO without contamination", ISO + "[lubrication]\nviscosity = 20.0\n",
     ['s.toml: lubrication.contamination: missing; give contamination (one of "extreme", '
      '"high", "normal", "slight", "typical", "severe", "very_severe") or e_C']),
    ("no method", rep('method = "gost18855_94"\n', ""),
     ['s.toml: method: missing; required: one of "gost18855_94", "iso281_2007" (edition of '
      'the life calculation)']),
    ("no type", rep('designation = "6208"', "C_r = 30000.0"),
     ['s.toml: bearing.type: missing; required without bearing.designation: one of '
      '"deep_groove_ball", "angular_contact_ball", "self_aligning_ball", "cylindrical_roller", '
      '"tapered_roller", "spherical_roller", "thrust_ball", "thrust_roller"']),
    ("no rating", rep('designation = "6208"', 'type = "deep_groove_ball"'),
     ["s.toml: bearing.C_r: missing; give C_r (N), a catalogue designation, or the geometry "
      "Z, D_w and D_pw (or d and D) of a radial bearing"]),
    ("axial load without C_0r", rep('designation = "6208"', 'type = "deep_groove_ball"\n'
                                                            'C_r = 30000.0'),
     ["s.toml: bearing.C_0r: missing; required to find e, X, Y of a deep groove ball bearing "
      "under axial load (static rating, N)"]),
    ("type contradicts the catalogue", rep('designation = "6208"', 'designation = "6208"\n'
                                                                   'type = "tapered_roller"'),
     ['s.toml: bearing.type = "tapered_roller": contradicts the catalogue: 6208 is a deep '
      'groove ball bearing; remove bearing.type']),
    ("time shares", rep(SINGLE, "[[load.spectrum]]\nF_r = 1000.0\nspeed = 100.0\n"
                                "time_share = 0.5\n[[load.spectrum]]\nF_r = 1000.0\n"
                                "speed = 100.0\ntime_share = 0.4\n"),
     ["s.toml: load.spectrum = [0.5, 0.4]: time shares add up to 0.9; they must add up to 1"]),
    ("single load and spectrum", GOOD + "[[load.spectrum]]\nF_r = 1000.0\nspeed = 100.0\n"
                                        "time_share = 1.0\n",
     ["s.toml: load.F_r = 3000.0: give either a single load case or [[load.spectrum]] blocks, "
      "not both; remove it"]),
    ("angular contact without angle",
     rep('designation = "6208"', 'type = "angular_contact_ball"\nC_r = 30000.0\nC_0r = 20000.0'),
     ["s.toml: bearing.contact_angle: missing; required for an angular contact ball bearing "
      "(deg)"]),
    ("radial load on a thrust bearing", rep('designation = "6208"', 'type = "thrust_ball"\n'
                                                                    'C_r = 30000.0'),
     ["s.toml: load.F_r = 3000.0: a thrust bearing with α = 90° carries no radial load; use 0, "
      "or a radial or angular bearing",
      # an independent problem of the same spec, in the same round
      "s.toml: factors.a23: missing; required for a thrust ball bearing (no textbook a23): a "
      "number > 0"]),
    ("no load", rep("F_a = 1000.0", "F_a = 0.0", rep("F_r = 3000.0", "F_r = 0.0")),
     ["s.toml: load.F_r = 0.0: F_r = F_a = 0: give the radial or the axial load"]),
    ("temperature beyond the K_т table", GOOD + "[factors]\ntemperature = 300.0\n",
     ["s.toml: factors.temperature = 300.0: must be a number >= -60 and <= 250 (°C)"]),
    ("select without required life",
     rep('designation = "6208"', 'type = "deep_groove_ball"\nd = 40.0',
         rep('method = "gost18855_94"', 'method = "gost18855_94"\nmode = "select"')),
     ['s.toml: requirements.life: missing; required in mode = "select": a number > 0 (h)']),
    ("select, bore not in the catalogue",
     rep('designation = "6208"', 'type = "deep_groove_ball"\nd = 42.0',
         rep('method = "gost18855_94"', 'method = "gost18855_94"\nmode = "select"'))
     + "[requirements]\nlife = 1000.0\n",
     ["s.toml: bearing.d = 42.0: no catalogue deep groove ball bearing has this bore; "
      "nearest catalogue bores: 40, 45 mm (of 10…200 mm)"]),
    ("select with a designation of another bore",
     rep('designation = "6208"', 'designation = "6208"\nd = 45.0',
         rep('method = "gost18855_94"', 'method = "gost18855_94"\nmode = "select"')),
     ['s.toml: requirements.life: missing; required in mode = "select": a number > 0 (h)',
      's.toml: bearing.d = 45.0: contradicts bearing.designation = "6208" (deep groove ball, '
      'd = 40 mm), which names the type and bore to select in; remove one of them']),
    ("bare 72xx is ambiguous", rep('"6208"', '"7208"'),
     ['s.toml: bearing.designation = "7208": ambiguous: ISO 7208 B (angular contact ball, '
      'α = 40°) or GOST 7208 = ISO 30208 (tapered roller); write "7208 B" or "30208"']),
    ("unknown maker", rep('designation = "6208"', 'designation = "6208"\nmaker = "XYZ"'),
     ['s.toml: bearing.maker = "XYZ": not in the built-in catalogue; known: "SKF", "NTN"']),
    ("maker without the row", rep('designation = "6208"', 'designation = "NU 208"\nmaker = "NTN"'),
     ['s.toml: bearing.designation = "NU 208": not in the NTN tables of the built-in catalogue; '
      'SKF lists it: remove bearing.maker or set it to "SKF"']),
    ("unknown oil grade", ISO + '[lubrication]\noil = "VG 250"\ntemperature = 70.0\n'
                                'contamination = "normal"\n',
     ['s.toml: lubrication.oil = "VG 250": not an ISO VG grade (did you mean "VG 220", "VG 320"?); '
      'grades: VG 2, VG 3, VG 5, VG 7, VG 10, VG 15, VG 22, VG 32, VG 46, VG 68, VG 100, '
      'VG 150, VG 220, VG 320, VG 460, VG 680, VG 1000, VG 1500']),
    ("oil without temperature", ISO + '[lubrication]\noil = "VG 68"\ncontamination = "normal"\n',
     ["s.toml: lubrication.temperature: missing; required with lubrication.oil: the operating "
      "temperature (°C)"]),
    ("two viscosity routes", ISO + '[lubrication]\noil = "VG 68"\nviscosity = 20.0\n'
                                  'temperature = 60.0\ncontamination = "normal"\n',
     ['s.toml: lubrication.oil = "VG 68": give one of lubrication.viscosity, oil or nu40, not '
      'viscosity and oil']),
    ("pair table without pair mode", GOOD + '[pair]\narrangement = "back_to_back"\nF_r = 1.0\n',
     ['s.toml: pair: used only with mode = "pair"; remove [pair] or set mode = "pair"']),
    ("pair of deep groove bearings", rep('method = "gost18855_94"', 'method = "gost18855_94"\n'
                                         'mode = "pair"') + '[pair]\narrangement = '
                                         '"back_to_back"\nF_r = 1000.0\n',
     ['s.toml: bearing.designation = "6208": a pair with induced axial loads is one of angular '
      'contact ball or tapered roller bearings']),
    ("speed beyond any bearing", rep("speed = 1000.0", "speed = 1e300"),
     ["s.toml: load.speed = 1e+300: must be a number >= 0.01 and <= 200000 (min^-1)"]),
]


@pytest.mark.parametrize("name, text, expected", CASES, ids=[c[0] for c in CASES])
def test_one_line_per_problem(tmp_path, name, text, expected):
    assert run_bad(tmp_path, text) == expected
