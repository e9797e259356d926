"""Robustness of the REXS import (docs/rexs.md) as an attacker would feed it: the public
models of ``tests/data/rexs`` and the model exported from an example spec of every kind the
export writes, mutated — an attribute's value set to text that reads as NaN or infinity, to
a number at the ends of a double, negative, zero, a count beyond 64 bits; its unit swapped
for the largest one of its quantity (a length in m, a torque in kN m, an angle in rad: a
finite number that overflows once converted); a vector emptied, grown or made non-finite; a
component id duplicated, a relation dropped, duplicated or pointed elsewhere — either
refuses in one line (:class:`InputError`) or writes a spec that holds no NaN or infinity
and that computes or is refused naming a key (``tests/fuzz.py``).  A kind added to the
export is fuzzed with no change here.  Hypothesis runs derandomized: a red run repeats.
"""

from __future__ import annotations

import copy
import json
import random
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geardesign.core.errors import InputError
from geardesign.rexs.exporter import KINDS, export_spec
from geardesign.rexs.importer import import_model
from geardesign.rexs.model import _UNITS, Component, Ref, parse, read_model
from tests import fuzz

DATA = Path(__file__).parent / "data" / "rexs"

TEXTS = ("nan", "NaN", "inf", "-inf", "Infinity", "1e400", "-1e400", "1e308", "-1e308",
         "5e-324", "0", "-0", "-1", "-3", "99999999999999999999999", "", "abc")
NUMBERS = (float("nan"), float("inf"), -1e300, 1e300, 0.0, -1.0, 2 ** 70, -(2 ** 70))
BIG_UNIT = tuple(max(f, key=f.get) for f in _UNITS.values())
"""The unit of largest factor of each quantity the import converts."""
VECTORS = (["nan", "0", "0"], ["inf", "-inf", "0"], ["1e308", "-1e308", "0"], [], ["1"] * 40)


def _models() -> dict[str, object]:
    """``{label: Model}``: the public models, and the export of the first example spec of
    each kind the export writes (the first it writes; XML and JSON alternately)."""
    out = {p.name: read_model(p) for p in sorted(DATA.glob("*.rexs*"))}
    for i, (kind, specs) in enumerate(sorted(fuzz.base_specs().items())):
        if kind not in KINDS:
            continue
        fmt = ("xml", "json")[i % 2]
        for path, _ in specs:
            try:
                text = export_spec(path, fmt)
            except InputError:      # a drive with a bevel stage: refused by the export
                continue
            out[f"{path.name} ({fmt})"] = parse(text.encode())
            break
    return out


MODELS = _models()
LABELS = sorted(MODELS)


def test_every_exported_kind_is_fuzzed():
    assert set(KINDS) <= {lbl.split("_")[0] for lbl in LABELS if "(" in lbl}


def mutate(model, rng: random.Random):
    """One to three mutations of a copy of ``model`` (module docstring)."""
    m = copy.deepcopy(model)
    comps = list(m.components.values())
    for _ in range(rng.randint(1, 3)):
        op = rng.random()
        c = rng.choice(comps)
        if op < 0.7 and c.attributes:
            a = rng.choice(list(c.attributes.values()))
            if isinstance(a.value, list):
                a.value = copy.deepcopy(rng.choice(VECTORS))
            elif rng.random() < 0.3 and a.unit not in (None, "", "none"):
                a.unit = rng.choice(BIG_UNIT)
                a.value = rng.choice(("1e306", "1e300", 1e306, a.value))
            else:
                a.value = rng.choice(TEXTS + NUMBERS)
        elif op < 0.78:
            other = rng.choice(comps)
            m.components[other.id] = Component(other.id, c.type, c.name,
                                               copy.deepcopy(c.attributes))
        elif op < 0.86 and m.relations:
            del m.relations[rng.randrange(len(m.relations))]
        elif op < 0.93 and m.relations:
            m.relations.append(copy.deepcopy(rng.choice(m.relations)))
        elif m.relations:
            r = rng.choice(m.relations)
            if r.refs:
                k = rng.randrange(len(r.refs))
                old = r.refs[k]
                r.refs[k] = Ref(old.role, rng.choice((rng.choice(comps).id, "-1", "999999")),
                                old.hint)
    return m


@settings(max_examples=60, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(LABELS), st.integers(0, 2 ** 32 - 1))
def test_mutated_models_import_to_a_finite_spec_or_one_line(label, seed):
    model = mutate(MODELS[label], random.Random(seed))
    try:
        imported = import_model(model, label)
    except InputError as exc:
        assert len(exc.problems) == 1 and exc.problems[0].message
        assert not fuzz.NONFINITE_WORD.search(exc.problems[0].message.split("=", 1)[0])
        return
    data = tomllib.loads(imported.text)
    bad = fuzz.bad_numbers(json.loads(json.dumps(data, default=str)))
    assert bad is None, f"{label}: the imported spec holds {bad}"
    failure = fuzz.run_case(data, "imported.toml", DATA, seconds=60, formats=("json",))
    assert failure is None, f"{label}: {failure}"


def _largest_unit(unit: str) -> str | None:
    """The spelling of largest factor of the quantity ``unit`` belongs to, if above 1."""
    for factors in _UNITS.values():
        if unit in factors:
            big = max(factors, key=factors.get)
            return big if factors[big] > 1.0 else None
    return None


@pytest.mark.parametrize("label", [lbl for lbl in LABELS if "(" in lbl])
def test_every_attribute_non_finite_or_overflowing_is_one_line(label):
    """Every scalar attribute of an exported model set to the text "nan", and every one with
    a unit to 1e306 of the largest unit of its quantity (a finite number in the file,
    infinite once converted): refused in one line, or no NaN or infinity in the spec."""
    base = MODELS[label]
    for cid, c in base.components.items():
        for aid, a in c.attributes.items():
            if isinstance(a.value, list):
                continue
            big = _largest_unit((a.unit or "").strip())
            for unit, value in ((a.unit, "nan"),) + (((big, "1e306"),) if big else ()):
                m = copy.deepcopy(base)
                m.components[cid].attributes[aid].unit = unit
                m.components[cid].attributes[aid].value = value
                try:
                    imported = import_model(m, label)
                except InputError as exc:
                    assert len(exc.problems) == 1
                    continue
                bad = fuzz.bad_numbers(tomllib.loads(imported.text))
                assert bad is None, f"{label}: {cid} {aid} = {value} {unit}: {bad}"


@pytest.mark.parametrize("label", [lbl for lbl in LABELS if "(" not in lbl])
def test_every_shift_at_minus_one_in_a_public_model(label):
    """Each gear's addendum modification of a public model at −1, one at a time: a pair
    that cannot mesh as computed in a drive with analysed shafts (GOST-rated: the drive's
    informative ISO K_Hβ with the shafts' misalignment) is "not applicable", as the spur
    calculator says; it rated the pair and took a square root of a negative number."""
    base = MODELS[label]
    for cid, c in base.components.items():
        a = c.attributes.get("addendum_modification_coefficient")
        if a is None or isinstance(a.value, list):
            continue
        m = copy.deepcopy(base)
        m.components[cid].attributes["addendum_modification_coefficient"].value = "-1"
        try:
            imported = import_model(m, label)
        except InputError:
            continue
        failure = fuzz.run_case(tomllib.loads(imported.text), "imported.toml", DATA,
                                seconds=60, formats=("json",))
        assert failure is None, f"{label}: component {cid}: {failure}"
