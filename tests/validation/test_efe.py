"""Stribeck friction against Table 5.2 of Efe2014 (simulated column)."""

from __future__ import annotations

import pytest

from hydroservo.laws.friction import stribeck

# Simulated column of Table 5.2 with c_s = 0.01, F_v = 280, F_c0 = 78, F_s0 = 5.
# The table prints two decimals, so the tolerance is half a unit in the last place.
TABLE_5_2 = [(0.165, 124.20), (0.123, 112.44), (0.078, 99.84), (0.048, 91.48), (0.022, 84.71), (0.01, 82.64)]


@pytest.mark.parametrize(("v", "force"), TABLE_5_2)
def test_stribeck_reproduces_table_5_2(v: float, force: float) -> None:
    assert stribeck(v, 280.0, 78.0, 5.0, 0.01) == pytest.approx(force, abs=0.005)
