"""The shuttle valve (hydroservo.components.valves.shuttle) against the closed form."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c


def test_the_outlet_is_fed_from_the_higher_inlet_both_ways() -> None:
    v = c.ShuttleValve("v", G_open=2e-7)
    # P1 higher: Q3 = G (p1 - p3) drawn from P1, P2 shut; the outlet above P1 drains back into it
    out = v.output_equations(0.0, {}, {"p1": 80e5, "p2": 50e5, "p3": 79e5}, v.values)
    assert float(out["Q3"]) == pytest.approx(2e-7 * 1e5, rel=1e-12)
    assert float(out["Q1"]) == float(out["Q3"]) and float(out["Q2"]) == 0.0 and float(out["out"]) == -1.0
    out = v.output_equations(0.0, {}, {"p1": 80e5, "p2": 50e5, "p3": 81e5}, v.values)
    assert float(out["Q1"]) == pytest.approx(-2e-7 * 1e5, rel=1e-12) and float(out["Q2"]) == 0.0
    # P2 higher, by more than half the shift band
    out = v.output_equations(0.0, {}, {"p1": 80e5 - 51.0, "p2": 80e5, "p3": 70e5}, v.values)
    assert float(out["Q2"]) == pytest.approx(2e-7 * (80e5 - 70e5), rel=1e-12)
    assert float(out["Q1"]) == 0.0 and float(out["out"]) == 1.0
    # balanced: the ball floats, both seats half open, the outlet still fed at the inlets' pressure
    out = v.output_equations(0.0, {}, {"p1": 80e5, "p2": 80e5, "p3": 70e5}, v.values)
    assert float(out["Q1"]) == pytest.approx(float(out["Q2"]), rel=1e-12)
    assert float(out["Q3"]) == pytest.approx(2e-7 * (80e5 - 70e5), rel=1e-12) and float(out["out"]) == 0.0


def test_a_volume_behind_it_settles_where_its_drain_takes_the_flow_through_the_seat() -> None:
    """Volume V behind the outlet, drained by a laminar orifice K to tank: the steady pressure is the divider
    G p_max / (G + K) (gauge), reached with the time constant V / (beta (G + K))."""
    s = hs.System("shuttle")
    s.add(c.ShuttleValve("sv", G_open=1e-9))
    s.add(c.Tank("high", p=100e5))
    s.add(c.Tank("low", p=60e5))
    s.add(c.Volume("vol", V=1e-3, beta_e=1e9, p0=0.0))
    s.add(c.LaminarOrifice("drain", G_lam=1e-10))
    s.add(c.Tank("tank"))
    s.connect("low.P", "sv.P1")
    s.connect("high.P", "sv.P2")
    s.connect("sv.P3", "vol.P")
    s.connect("vol.P", "drain.A")
    s.connect("drain.B", "tank.P")
    tau = 1e-3 / (1e9 * 1.1e-9)
    t = np.array([0.0, tau, 20.0 * tau])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    p_end = 1e-9 * 100e5 / 1.1e-9
    np.testing.assert_allclose(r["vol.p"], p_end * (1.0 - np.exp(-t / tau)), rtol=1e-5, atol=1.0)
    assert np.all(np.asarray(r["sv.Q1"]) == 0.0)
