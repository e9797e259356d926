"""The pzdn coupling gear composes the spur calculator through its typed interface: the
spur inputs of the coupling table solved once by :func:`geardesign.spur.solve.solve`, the
pzdn figures read from that record (issue 28, "composition through the API")."""

from __future__ import annotations

from pathlib import Path

from geardesign.core.registry import run_data
from geardesign.core.spec import load_toml

SPEC = Path(__file__).resolve().parent.parent / "specs" / "pzdn_ko2_coupling_gear.toml"


def test_the_coupling_gear_is_solved_once_and_not_run_as_a_spec(monkeypatch):
    import geardesign.core.registry as R
    import geardesign.spur.solve as SOLVE

    calls = []
    real = SOLVE.solve

    def counting(inputs):
        calls.append(inputs)
        return real(inputs)

    monkeypatch.setattr(SOLVE, "solve", counting)
    data = load_toml(SPEC)
    real_run = R.run_data

    def no_nested_run(d, source=""):
        assert d.get("kind") != "spur", "the coupling gear ran the spur calculator on a spec"
        return real_run(d, source)

    monkeypatch.setattr(R, "run_data", no_nested_run)
    res = run_data(data, "p.toml")
    assert len(calls) == 1
    rec = real(calls[0])
    rows = {r.key: r.value for s in res.sections for r in s.rows}
    # the pzdn rows are the record's values (one source of truth), the pinion torque per
    # mesh the record's input
    for key in ("sigma_H", "sigma_HP", "sigma_F1", "sigma_F2", "S_F1", "S_F2"):
        assert rows[key] == rec.values[key], key
    assert calls[0].strength.duty.T1 == rows["T1_mesh"]
