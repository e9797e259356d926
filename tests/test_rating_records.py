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
from geardesign.spur.geometry import GeometryError, PairInput, pair_core, pair_geometry
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
