"""Pressure sources (hydroservo.components.sources)."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ParameterError


def test_pressure_table_follows_record() -> None:
    s = hs.System("supply")
    s.add(c.PressureTable("supply", times=[0.0, 1.0, 2.0], pressures=[25e5, 35e5, 30e5]))
    s.add(c.Volume("vol", V=1e-3))
    s.add(c.FourWayValve("valve", c_v=1e-7))
    s.add(c.Step("xv", unit="m", amplitude=1e-4))
    s.add(c.Tank("tank"))
    s.connect("supply.p", "valve.pS")
    s.connect("tank.p", "valve.pT", "valve.pB")
    s.connect("vol.p", "valve.pA")
    s.connect("xv.y", "valve.xv")
    s.connect("valve.QA", "vol.Q1")
    r = s.simulate(t_eval=[0.0, 0.5, 1.5, 3.0])
    np.testing.assert_allclose(r["supply.p"], [25e5, 30e5, 32.5e5, 30e5])
    with pytest.raises(ParameterError, match="strictly increasing"):
        c.PressureTable("bad", times=[0.0, 0.0], pressures=[1.0, 2.0])
