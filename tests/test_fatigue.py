"""The GOST 25.504-82 formulas live once, in :mod:`geardesign.fatigue`: their worked values
(from [Gutyria2017], the Raba 118/77 ring) run as doctests (tests/test_doctests.py), and neither the shaft, its
DIN 743 path nor the rim keeps a copy of a formula."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent / "geardesign"


# a characteristic piece of each formula of geardesign/fatigue/gost25504.py
FORMULAS = {
    "K_1": r"1\.0 - 0\.2 \* math\.log10",
    "ν_σ": r"0\.211 - 0\.000143",
    "K_F": r"1\.0 - 0\.22 \* math\.log10",
    "K_Fτ": r"0\.575 \*",
    "K_A": r"sigma_u / 6000",
    "ψ_σ": r"0\.02 \+ 2e-4",
    "K_σD": r"1\.0 / K_F - 1\.0",
    "v_σmax": r"0\.1 / \(1\.0 \+",
    "S": r"math\.hypot\(1\.0 / ",
    "m": r"5\.0 \+ sigma_u / 80",
}


@pytest.mark.parametrize("symbol", FORMULAS)
def test_one_formula_one_place(symbol):
    pattern = re.compile(FORMULAS[symbol])
    where = sorted(str(p.relative_to(ROOT)) for p in ROOT.rglob("*.py")
                   if pattern.search(p.read_text(encoding="utf-8")))
    assert len(where) == 1 and where[0].startswith("fatigue/"), where


def test_shaft_and_rim_call_the_shared_functions():
    from geardesign.fatigue import gost25504 as g25
    from geardesign.shaft import strength

    assert strength.mean_stress_sensitivity is g25.mean_stress_sensitivity
    # K_σD of a shaft section and K of the rim: one function
    f = strength.fatigue_safety(60.0, 10.0, 20.0, 20.0, 2.0, 1.6, 0.9, 0.95, 1.0, 300.0,
                                174.0, 0.1, 0.05)
    assert f.K_sigma_D == g25.reduction_factor(2.0, 0.9, 1.0)
    assert f.S == g25.combined_safety(f.S_sigma, f.S_tau)
