"""``hydroservo fluid``: properties of the built-in fluids against temperature and pressure."""

from __future__ import annotations

import json

import pytest


def test_fluid_cli(cli) -> None:
    code, out, _ = cli("fluid", "all", "--temperature", "-40,20", "--pressure", "0,30 MPa", "--json")
    assert code == 0
    data = json.loads(out)
    assert len(data["values"]) == 4 and data["units"]["kinematic_viscosity"] == "cSt"
    row = data["values"][2]  # 20 degC, 0 Pa: hydroservo's reference state of Skydrol (hydroservo.fluids; none printed)
    assert row["density"] == pytest.approx(1008.0) and row["temperature_degC"] == 20.0
    code, _, err = cli("fluid", "density", "--temperature", "150", "--strict")
    assert code == 2
    assert "outside" in err
    code, _, err = cli("fluid", "density", "--pressure", "3 m")
    assert code == 2
    assert "wrong dimension" in err
    code, out, _ = cli("fluid", "kinematic-viscosity", "--fluid", "iso-vg32", "--temperature", "104 degF")
    assert code == 0
    assert "32" in out
