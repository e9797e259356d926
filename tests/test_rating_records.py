"""The GOST 21354-87 rating record: frozen, its report rows built from the fields' metadata
(one row per reported value, in the order of the values), the given factors marked, the
same rate() on arrays of candidates as on one pair (every value, not only the kernel's
columns), and one verdict for both methods."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.registry import load_data
from geardesign.core.spec import load_toml
from geardesign.gears.geometry import GeometryError, PairInput, pair_core, pair_geometry
from geardesign.spur.kernel import fixed_from_spec, pair_view
from geardesign.spur.strength.common import rows, values
from geardesign.spur.strength.gost21354.rating import GostRating, rate
from geardesign.spur.strength.verdict import verdict
from tests.conftest import SPECS

SPEC_NAMES = ("spur_reducer_through_hardened.toml", "spur_helical_carburized_spectrum.toml",
              "spur_gost_vs_iso.toml")


def _fixed(name: str, **setting):
    d = load_toml(SPECS / name)
    _, spec = load_data(d, name)
    f = fixed_from_spec(spec)
    if setting:
        f = dataclasses.replace(f, setting=dataclasses.replace(f.setting, **setting))
    return f


def _rating(f, m_n=3.0, z1=21, z2=64, x1=0.2, x2=0.1, beta=0.2, b_w=40.0):
    g = pair_geometry(PairInput(m_n, z1, z2, x1, x2, beta, b_w, f.rack,
                                tip_shortening=f.tip_shortening))
    return g, rate(g, f.mats, f.duty, f.setting)


@pytest.mark.parametrize("name", SPEC_NAMES)
@pytest.mark.parametrize("beta", [0.0, 0.25])
def test_rows_follow_the_values_and_carry_metadata(name, beta):
    f = _fixed(name, contact_model="popov_n07", crowning=0.02,
               overrides={"K_Hbeta": 1.2, "Y_FS2": 3.9})
    _, r = _rating(f, beta=beta)
    assert isinstance(r, GostRating)
    out = rows(r)
    v = values(r)
    assert [row.key for row in out] == list(v)          # one row per value, same order
    assert len({row.key for row in out}) == len(out)    # no key twice
    for row in out:
        value = v[row.key]
        assert row.value == ({True: "yes", False: "no"}[value] if isinstance(value, bool)
                             else value)
        assert row.symbol and row.name and row.source
        assert (row.unit is None) == isinstance(row.value, str)   # text: no unit
        assert "{" not in row.name and "{" not in row.symbol
    given_rows = {row.key: row for row in out if row.name.endswith("(given)")}
    assert set(given_rows) == {"K_Hbeta", "Y_FS2"} == set(r.given)
    assert all(row.source == "spec" for row in given_rows.values())
    assert ("c_gamma" in v) == (beta > 0.0)
    assert {"rho_w", "sigma_H_n07", "b_K"} <= set(v)


def test_record_is_frozen():
    _, r = _rating(_fixed(SPEC_NAMES[0]))
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.contact.sigma_H = 0.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.contact = None


def test_values_of_a_frozen_record_are_collected_once_and_copied():
    """``record.v`` is :func:`values` of the record, collected once; a caller that changes
    its dict changes neither the record's next ``v`` nor another caller's."""
    _, r = _rating(_fixed(SPEC_NAMES[0]))
    first = r.v
    assert first == values(r) and first is not r.v
    first["S_H1"] = -1.0
    first.pop("K_Hbeta")
    assert r.v == values(r)


pairs = st.tuples(st.sampled_from([1.5, 2.0, 3.0, 5.0, 8.0]), st.integers(14, 40),
                  st.integers(25, 150), st.floats(-0.3, 0.8), st.floats(-0.3, 0.8),
                  st.sampled_from([0.0, 0.1, 0.3, 0.5]), st.floats(10.0, 150.0))


@settings(max_examples=25, deadline=None)
@given(st.lists(pairs, min_size=1, max_size=12), st.sampled_from(SPEC_NAMES))
def test_rate_on_arrays_is_rate_on_each_pair(cands, name):
    """rate() on a chunk of candidates gives, for every value it reports (forces, life,
    factors, contact, bending, the peak load), the value of rate() on each pair."""
    f = _fixed(name, contact_model="popov_n07", crowning=0.02)
    arr = {k: np.array([float(c[i]) for c in cands])
           for i, k in enumerate(("m_n", "z1", "z2", "x1", "x2", "beta", "b_w"))}
    with np.errstate(all="ignore"):
        g = pair_core(*(arr[k] for k in ("m_n", "z1", "z2", "x1", "x2", "beta", "b_w")),
                      f.rack, f.tip_shortening)
        g.update(m_n=arr["m_n"], b_w=arr["b_w"], beta=arr["beta"])
        many = values(rate(pair_view(g), f.mats, f.duty, f.setting))
    for i, c in enumerate(cands):
        try:
            _, one = _rating(f, c[0], c[1], c[2], c[3], c[4], c[5], c[6])
        except GeometryError:
            continue
        one_v = values(one)
        optional = {"K_Hw", "c_gamma", "f_pb", "K_Halpha_max", "K_Falpha_max",
                    "K_Halpha_capped", "K_Falpha_capped"}
        assert set(one_v) - optional <= set(many)
        for key, want in one_v.items():
            if isinstance(want, str) or key not in many or key in optional:
                continue
            got = many[key]
            got = float(got[i]) if np.ndim(got) else float(got)
            assert math.isclose(got, float(want), rel_tol=1e-9, abs_tol=1e-9), (key, got, want)


def test_one_verdict_for_both_methods():
    """The GOST verdict judges contact for the pair (σ_H ≤ σ_HP) and bending per gear; the
    ISO verdict each gear, of the spectrum when one is rated."""
    _, r = _rating(_fixed(SPEC_NAMES[0]))
    v = values(r)
    j = verdict(r)
    assert j.method == "GOST 21354-87"
    assert j.contact_passes == (v["sigma_H"] <= v["sigma_HP"])
    assert j.bending_ok == tuple(v[f"S_F{k}"] >= v[f"S_F{k}_min"] for k in (1, 2))
    assert j.margin == pytest.approx(min(v["sigma_HP"] / v["sigma_H"], v["S_F1"] / v["S_F1_min"],
                                         v["S_F2"] / v["S_F2_min"]))
    iso = {"S_Hmin": 1.0, "S_Fmin": 1.4, "S_H1": 1.2, "S_H2": 0.9, "S_F1": 2.0, "S_F2": 1.5}
    j = verdict(iso)
    assert j.method == "ISO 6336:2019"
    assert j.contact_ok == (True, False) and j.bending_ok == (True, True)
    assert not j.passes and j.margin == pytest.approx(0.9)
    j = verdict({**iso, "S_Hspec1": 1.1, "S_Hspec2": 1.05, "S_Fspec1": 1.5, "S_Fspec2": 1.3})
    assert j.contact_passes and not j.bending_passes     # the spectrum's safety factors


# ----------------------------------------------------------------------------- ISO 6336

SCUFFING = "spur_iso_scuffing_nrel_stage3.toml"
ISO_SPECS = SPEC_NAMES + (SCUFFING,)
VALUE_ONLY = {"X_eps_branch", "nu40_scuffing"}     # read by the scuffing advice, not shown


def _iso_rating(name, overrides=None, beta=0.2, **pair):
    """The ISO rating of a pair (m_n 3, 21:64, b_w 40 unless given) with the spec's
    materials and duty; the scuffing spec's own pair (its rack and oil fit only that)."""
    from geardesign.spur.strength.iso6336 import rating as IR

    if name == SCUFFING:
        from geardesign.spur.spec_inputs import _strength_inputs, solve_geometry
        from geardesign.spur.strength.iso6336.spec import iso_setting

        _, spec = load_data(load_toml(SPECS / name), name)
        geom, _ = solve_geometry(spec)
        mats, duty, setting = _strength_inputs(spec, spec.data["gear"])
        return IR.rate(geom, mats, duty, setting, iso_setting(spec, overrides))
    f = _fixed(name)
    iso = f.iso or IR.default_setting(f.setting)
    if overrides:
        iso = dataclasses.replace(iso, overrides=overrides)
    g = pair_geometry(PairInput(pair.get("m_n", 3.0), pair.get("z1", 21), pair.get("z2", 64),
                                0.2, 0.1, beta, pair.get("b_w", 40.0), f.rack,
                                tip_shortening=f.tip_shortening))
    return IR.rate(g, f.mats, f.duty, f.setting, iso)


@pytest.mark.parametrize("name", ISO_SPECS)
@pytest.mark.parametrize("beta", [0.0, 0.25])
def test_iso_rows_follow_the_values_and_carry_metadata(name, beta):
    from geardesign.spur.strength.iso6336.record import SECTIONS, IsoRating

    r = _iso_rating(name, {"K_Hbeta": 1.3, "Y_F2": 2.4, "Z_NT1": 1.05}, beta=beta)
    assert isinstance(r, IsoRating)
    out, v = rows(r), values(r)
    assert v == r.v and [x.key for x in r.rows] == [x.key for x in out]
    assert [x.key for x in out] == [k for k in v if k not in VALUE_ONLY]
    assert len({x.key for x in out}) == len(out)
    for x in out:
        assert x.value == v[x.key]
        assert x.section in SECTIONS
        assert x.symbol is not None and x.name and x.source
        assert "{" not in x.name
    given_rows = {x.key for x in out if x.name.endswith("(given)")}
    assert {"K_Hbeta", "Y_F2", "Z_NT1"} <= given_rows
    assert all(x.source == "spec" for x in out if x.key in {"K_Hbeta", "Y_F2", "Z_NT1"})
    assert v["K_Hbeta"] == 1.3 and v["Y_F2"] == 2.4 and v["Z_NT1"] == 1.05
    # every section a frozen record of its own; Z_ε computed among the load factors (the
    # limit of K_Hα), reported under pitting
    assert r.contact.SECTION == "iso6336_contact" and "Z_eps" in dataclasses.asdict(r.factors)
    assert list(v).index("Z_eps") < list(v).index("K_Halpha")
    assert next(x for x in out if x.key == "Z_eps").section == "iso6336_contact"


def test_iso_record_is_declared():
    """The ISO 6336 record's sections are classes declared in the package (the same class
    whatever the inputs), every value a field with its metadata: no class built while
    rating."""
    from geardesign.spur.strength.iso6336 import record as R
    from geardesign.spur.strength.iso6336 import scuffing as Sc
    from geardesign.spur.strength.iso6336 import spectrum as Sp

    declared = {R.Materials, R.Factors, R.Contact, R.Bending, R.Static, Sc.Scuffing,
                Sp.Spectrum}
    for name in ISO_SPECS:
        for beta in (0.0, 0.25):
            r = _iso_rating(name, beta=beta)
            parts = [getattr(r, f.name) for f in dataclasses.fields(r)
                     if hasattr(getattr(r, f.name), "SECTION")]
            assert {type(part) for part in parts} <= declared
            for part in parts:
                reported = {f.name for f in dataclasses.fields(part) if "report" in f.metadata}
                assert reported, type(part)
                for f in dataclasses.fields(part):
                    if "report" in f.metadata:
                        meta = f.metadata["report"]
                        assert meta["symbol"] is not None and meta["name"] and meta["source"]


def test_iso_record_is_frozen_and_sections_by_inputs():
    r = _iso_rating(SCUFFING)
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.bending.S_F1 = 0.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.contact = None
    assert r.scuffing is not None and r.scuffing.S_intS == r.v["S_intS"]
    assert "X_eps_branch" in r.v and "X_eps_branch" not in {x.key for x in r.rows}
    plain = _iso_rating(SPEC_NAMES[0])
    assert plain.scuffing is None and "S_intS" not in plain.v


@settings(max_examples=10, deadline=None)
@given(st.sampled_from(SPEC_NAMES), st.sampled_from([1.5, 2.0, 3.0, 5.0]),
       st.integers(14, 40), st.integers(25, 150), st.sampled_from([0.0, 0.1, 0.3]),
       st.floats(10.0, 150.0))
def test_iso_checks_read_the_record(name, m_n, z1, z2, beta, b_w):
    """rating_checks of the record judges as the verdict of its values, one check per gear
    and kind."""
    from geardesign.spur.strength.iso6336.checks import rating_checks

    try:
        r = _iso_rating(name, beta=beta, m_n=m_n, z1=z1, z2=z2, b_w=b_w)
    except GeometryError:
        return
    got = {c.code: c.passed for c in rating_checks(r)}
    j = verdict(r.v)
    assert (got["ISO_PITTING_PINION"], got["ISO_PITTING_WHEEL"]) == j.contact_ok
    assert (got["ISO_BENDING_PINION"], got["ISO_BENDING_WHEEL"]) == j.bending_ok


@settings(max_examples=15, deadline=None)
@given(st.lists(pairs, min_size=1, max_size=12), st.sampled_from(SPEC_NAMES))
def test_iso_rate_on_arrays_is_rate_on_each_pair(cands, name):
    """The ISO 6336 rate() on a chunk of candidates gives, for every value it reports
    (materials, load factors, pitting, bending), the value of rate() on each pair; only the
    rows of one pair (the tolerance range, Z_LvR) are absent from a chunk."""
    from geardesign.spur.strength.iso6336 import rating as IR

    f = _fixed(name)
    iso = f.iso or IR.default_setting(f.setting)
    arr = {k: np.array([float(c[i]) for c in cands])
           for i, k in enumerate(("m_n", "z1", "z2", "x1", "x2", "beta", "b_w"))}
    duty = dataclasses.replace(f.duty, T_peak=None, life=dataclasses.replace(f.duty.life,
                                                                             blocks=()))
    with np.errstate(all="ignore"):
        g = pair_core(*(arr[k] for k in ("m_n", "z1", "z2", "x1", "x2", "beta", "b_w")),
                      f.rack, f.tip_shortening)
        g.update(m_n=arr["m_n"], b_w=arr["b_w"], beta=arr["beta"])
        many = values(IR.rate(pair_view(g, f.rack), f.mats, duty, f.setting, iso))
    for i, c in enumerate(cands):
        try:
            g1, _ = _rating(f, c[0], c[1], c[2], c[3], c[4], c[5], c[6])
            one_v = values(IR.rate(g1, f.mats, duty, f.setting, iso))
        except (GeometryError, ValueError, ZeroDivisionError):
            continue
        assert set(one_v) - set(many) <= {"tolerance_range1", "tolerance_range2", "ZLvR1",
                                          "ZLvR2"}
        for key, want in one_v.items():
            if isinstance(want, str) or key not in many:
                continue
            got = many[key]
            got = float(got[i]) if np.ndim(got) else float(got)
            assert math.isclose(got, float(want), rel_tol=1e-9, abs_tol=1e-9), (key, got, want)


@settings(max_examples=10, deadline=None)
@given(st.sampled_from(SPEC_NAMES), st.sampled_from([1.5, 2.0, 3.0, 5.0]),
       st.integers(14, 40), st.integers(25, 150), st.sampled_from([0.0, 0.1, 0.3]),
       st.floats(10.0, 150.0), st.booleans())
def test_one_checks_function_judges_either_record(name, m_n, z1, z2, beta, b_w, iso):
    """``spur.strength.checks.rating_checks`` judges a record of either method from the
    record alone (the GOST record carries its materials, grade and peak torque): contact and
    bending checks per gear as the verdict, the members named in the codes."""
    from geardesign.spur.strength.checks import rating_checks

    members = ("sun", "planet")
    try:
        if iso:
            r = _iso_rating(name, beta=beta, m_n=m_n, z1=z1, z2=z2, b_w=b_w)
        else:
            r = _rating(_fixed(name), m_n=m_n, z1=z1, z2=z2, beta=beta, b_w=b_w)[1]
    except GeometryError:
        return
    got = {c.code: c.passed for c in rating_checks(r, members)}
    j = verdict(r)
    if iso:
        contact = (got["ISO_PITTING_SUN"], got["ISO_PITTING_PLANET"])
        bending = (got["ISO_BENDING_SUN"], got["ISO_BENDING_PLANET"])
    else:
        assert len(r.materials) == 2
        contact = (got["CONTACT_FATIGUE"],) * 2
        bending = (got["BENDING_FATIGUE_SUN"], got["BENDING_FATIGUE_PLANET"])
        assert ("STATIC_NOT_CHECKED" in got) == (r.static is None)
    assert contact == tuple(bool(x) for x in j.contact_ok)
    assert bending == tuple(bool(x) for x in j.bending_ok)
