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


def test_a_head_tank_drains_exponentially_through_a_laminar_orifice_and_gives_vacuum_when_empty() -> None:
    """HeadTank: p = p0 + rho g h_full m/m_full, dm/dt = rho Q. Drained through G to a tank at p0, Q = -G rho g
    h_full m/m_full: m = m0 exp(-G rho^2 g h_full t/m_full). Drawn at a constant flow q it empties at
    m0/(rho q), where its outlet falls to vacuum and its mass stops at m_min; m_used is m0 - m."""
    rho, g, h, m_full, m0, G = 700.0, 9.82, 5.0, 100.0, 50.0, 1e-6
    s = hs.System("drain")
    s.add(c.HeadTank("tank", p0=1e5, rho=rho, g=g, h_full=h, m_full=m_full, m0=m0, m_max=m_full))
    s.add(c.LaminarOrifice("o", G_lam=G))
    s.add(c.Tank("sink", p=1e5))
    s.connect("tank.P", "o.A")
    s.connect("o.B", "sink.P")
    t = np.array([0.0, 5.0, 20.0])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    m = m0 * np.exp(-G * rho**2 * g * h * t / m_full)
    np.testing.assert_allclose(r["tank.mass"], m, rtol=1e-6)
    np.testing.assert_allclose(r["tank.p"], 1e5 + rho * g * h * m / m_full, rtol=1e-9)
    np.testing.assert_allclose(r["tank.m_used"], m0 - m, rtol=1e-6, atol=1e-9)
    s = hs.System("draw")
    s.add(c.HeadTank("tank", p0=1e5, rho=rho, g=g, h_full=h, m_full=m_full, m0=m0, m_max=m_full))
    s.add(c.FlowSource("q", q=-0.002))
    s.connect("tank.P", "q.P")
    t_empty = m0 / (rho * 0.002)
    r = s.simulate(t_eval=[0.0, 0.5 * t_empty, 1.5 * t_empty], accuracy=1e-8)
    assert r["tank.mass"][1] == pytest.approx(0.5 * m0, rel=1e-6)
    assert r["tank.mass"][2] == pytest.approx(-1e-4, abs=1e-9) and r["tank.p"][2] == pytest.approx(-101325.0)
