"""Stribeck friction (eq. 3.47) against Table 5.2 of Efe2014 (simulated column), from the parameter set Efe2014."""

from __future__ import annotations

import pytest

from hydroservo.data import parameter_set
from hydroservo.laws.friction import stribeck
from hydroservo.units import to_si

EFE = parameter_set("Efe2014")
# Simulated column of Table 5.2 with its friction parameters c_s, F_v, F_c0, F_s0, as the parameter set holds them.
# The table prints two decimals, so the tolerance is half a unit in the last place.
TABLE_5_2 = list(zip(EFE.table("table_5_2")["velocity"], EFE.table("table_5_2")["simulated"], strict=True))


@pytest.mark.parametrize(("v", "force"), TABLE_5_2)
def test_stribeck_reproduces_table_5_2(v: str, force: str) -> None:
    c_s, F_v = EFE.si("stribeck", "c_s", "m/s"), EFE.si("stribeck", "F_v", "N*s/m")
    F_c0, F_s0 = EFE.si("stribeck", "F_c0", "N"), EFE.si("stribeck", "F_s0", "N")
    assert stribeck(to_si(v, "m/s"), F_v, F_c0, F_s0, c_s) == pytest.approx(to_si(force, "N"), abs=0.005)
