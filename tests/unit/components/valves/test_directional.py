"""The three-way and two-way spool valves (hydroservo.components.valves.directional) against the closed form."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.laws.orifice import transition_pressure


def _g(dp: float, p_tr: float) -> float:
    """The regularised turbulent pressure term, dp / (dp^2 + p_tr^2)^(1/4)."""
    return dp / (dp * dp + p_tr * p_tr) ** 0.25


def test_three_way_valve_edges_laps_and_coefficients() -> None:
    v = c.ThreeWayValve("v", c_PA=2e-4, c_AT=1e-4, x_PA=1e-4, x_AT=-5e-5, D_h=2e-3, lambda_crit=100.0)
    p_tr = transition_pressure(2e-3, 870.0, 32e-6, 100.0)
    u = {"pS": 200e5, "pT": 1e5, "pA": 80e5}
    # P-A open by 3e-4 - 1e-4; A-T (underlapped by 5e-5) closed once -xv < -5e-5
    out = v.output_equations(0.0, {}, {**u, "xv": 3e-4}, v.values)
    q_pa = 2e-4 * 2e-4 * _g(120e5, p_tr)
    assert float(out["QA"]) == pytest.approx(q_pa, rel=1e-12)
    assert float(out["QS"]) == pytest.approx(q_pa, rel=1e-12)
    assert float(out["QT"]) == 0.0
    # at the centre: P-A covered (overlap 1e-4), A-T open by its underlap 5e-5
    out = v.output_equations(0.0, {}, {**u, "xv": 0.0}, v.values)
    q_at = 1e-4 * 5e-5 * _g(79e5, p_tr)
    assert float(out["QS"]) == 0.0
    assert float(out["QT"]) == pytest.approx(q_at, rel=1e-12)
    assert float(out["QA"]) == pytest.approx(-q_at, rel=1e-12)
    # A above supply: P-A flows backwards
    out = v.output_equations(0.0, {}, {**u, "pA": 250e5, "xv": 2e-4}, v.values)
    assert float(out["QS"]) == pytest.approx(2e-4 * 1e-4 * _g(-50e5, p_tr), rel=1e-12)
    assert float(out["QS"]) < 0.0


def test_two_way_valve_opens_past_its_overlap_in_a_circuit() -> None:
    s = hs.System("v22")
    s.add(c.TwoWayValve("valve", c_v=5e-4, x_AB=1e-4))
    s.add(c.Step("xv", unit="m", offset=5e-5, amplitude=3e-4, t_step=0.05))
    s.add(c.ConstantPressure("sup", p=100e5))
    s.add(c.Tank("tank"))
    s.connect("xv.y", "valve.xv")
    s.connect("sup.P", "valve.A")
    s.connect("valve.B", "tank.P")
    r = s.simulate(t_eval=[0.0, 0.04, 0.1])
    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 1000.0)
    assert float(r["valve.Q"][1]) == 0.0  # xv = 0.05 mm, inside the 0.1 mm overlap
    assert float(r["valve.Q"][-1]) == pytest.approx(5e-4 * 2.5e-4 * _g(100e5, p_tr), rel=1e-9)
    assert np.all(np.asarray(r["valve.Q"]) >= 0.0)
