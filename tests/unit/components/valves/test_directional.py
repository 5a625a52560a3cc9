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


def test_a_pilot_operated_three_way_valve_settles_where_its_spool_balances_the_pilot() -> None:
    """ThreeWayPressureValve: B_v ẋ = A_v (p_X - p_ref) - (k_s + k_f) x, k_f = 2 cos φ c √(ρ/2) |Δp| of each open
    edge. Pilot pressures above the setting open P-A (flow force of P-A only), below it A-T (A-T's only, once its
    opening passes x_ATf); the static position solves the balance, and the spool stops at its bounds."""
    p_tr = transition_pressure(1e-3, 870.0, 32e-6, 1000.0)
    c_pa, c_at, phi, rho = 2e-4, 1e-4, 1.0, 870.0
    ks, area, p_ref = 3e4, 1e-5, 100e5
    ps, pt, pa = 200e5, 1e5, 80e5

    def k_f(c_v: float, dp: float) -> float:
        return 2.0 * np.cos(phi) * c_v * np.sqrt(rho / 2.0) * abs(dp)

    for px, expected in ((110e5, area * 10e5 / (ks + k_f(c_pa, ps - pa))),
                         (95e5, -area * 5e5 / (ks + k_f(c_at, pa - pt))),
                         (300e5, 2e-4)):  # held at x_max
        s = hs.System("pilot")
        s.add(c.ThreeWayPressureValve("v", c_PA=c_pa, c_AT=c_at, A_v=area, p_ref=p_ref, k_s=ks, B_v=10.0,
                              phi=phi, x_min=-2e-4, x_max=2e-4, x_ATf=1e-6))
        for name, p in (("P", ps), ("T", pt), ("A", pa), ("X", px)):
            s.add(c.Tank(f"s{name}", p=p))
            s.connect(f"v.{name}", f"s{name}.P")
        r = s.simulate(t_eval=[0.0, 0.05], accuracy=1e-9)
        xv = float(r["v.xv"][-1])
        assert xv == pytest.approx(expected, rel=1e-5)
        q_pa = c_pa * max(xv, 0.0) * _g(ps - pa, p_tr)
        q_at = c_at * max(-xv, 0.0) * _g(pa - pt, p_tr)
        assert float(r["v.QA"][-1]) == pytest.approx(q_pa - q_at, rel=1e-5)
        assert float(r["v.QX"][-1]) == 0.0
    # A-T's flow force acts only once it has opened by x_ATf: just inside, the spring alone
    v = c.ThreeWayPressureValve("v", c_PA=c_pa, c_AT=c_at, A_v=area, p_ref=p_ref, k_s=ks, B_v=10.0, phi=phi,
                        x_ATf=1e-5, dx_f=1e-8)
    u = {"pS": ps, "pT": pt, "pA": pa, "pX": p_ref - ks * 5e-6 / area}
    rate = v.state_equations(0.0, {"x_v": -5e-6}, u, v.values, {"xv": -5e-6})["x_v"]
    assert abs(float(rate)) < 1e-9
