"""The load-sensing pump (hydroservo.components.LoadSensingPump, Hopsan's HydraulicPressureControlledPump) against
closed forms: its static characteristic and its rate limit."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c

Q_MAX = 1.25e-3  # m^3/s at 125 rad/s


def _pump(**values: object) -> c.LoadSensingPump:
    return c.LoadSensingPump("pump", **{"D": Q_MAX / 125.0, "omega": 125.0, "C_leak": 1e-12, "p_dif": 2e6,
                                        "tau_v": 1e-3, **values})


def test_it_settles_where_its_static_characteristic_meets_the_load() -> None:
    """At rest g_2 y = u: the displacement flow is (p_dif - p + p_X)/r_p; into a laminar drain K (and its own
    leakage) the outlet settles at p = (p_dif + p_X)/r_p / (1/r_p + C_leak + K) (gauge, tank at 0)."""
    s = hs.System("ls")
    s.add(_pump())
    s.add(c.Tank("tank"))
    s.add(c.Tank("load", p=50e5))
    s.add(c.Volume("vol", V=1e-4, beta_e=1e9, p0=0.0))
    s.add(c.LaminarOrifice("drain", G_lam=2e-10))
    s.connect("tank.P", "pump.S")
    s.connect("pump.P", "vol.P")
    s.connect("vol.P", "drain.A")
    s.connect("drain.B", "tank.P")
    s.connect("load.P", "pump.X")
    r = s.simulate(t_eval=[0.0, 3.0])
    r_p = 1e9
    p_end = (2e6 + 50e5) / r_p / (1.0 / r_p + 1e-12 + 2e-10)
    assert float(r["vol.p"][-1]) == pytest.approx(p_end, rel=1e-6)
    assert float(r["pump.eps"][-1]) == pytest.approx((2e6 + 50e5 - p_end) / r_p / Q_MAX, rel=1e-6)
    assert float(r["pump.QX"][-1]) == 0.0  # port X only reads its pressure


def test_from_rest_it_strokes_no_faster_than_t_p_allows() -> None:
    """Against a held outlet pressure p far below its setting the displacement flow rises at its rate limit,
    Q_max sqrt(|p - p_0|/(p_nom t_p)) (p_0 Hopsan's 1e5 Pa absolute), until it reaches Q_max."""
    s = hs.System("stroke")
    s.add(_pump(p_dif=300e5))
    s.add(c.Tank("tank"))
    s.add(c.Tank("out", p=70e5))
    s.connect("tank.P", "pump.S")
    s.connect("pump.P", "out.P")
    s.connect("tank.P", "pump.X")
    s.set_initial("pump.w", 300e5 - 70e5)  # at rest: the lagged error at its start value
    rate = Q_MAX * np.sqrt((70e5 + 1325.0) / (7e6 * 0.15))
    t = np.array([0.0, 0.05, 0.1, 0.2, 0.5])
    r = s.simulate(t_eval=t, accuracy=1e-7)
    q = np.asarray(r["pump.eps"]) * Q_MAX
    np.testing.assert_allclose(q[:4], rate * t[:4], rtol=2e-3, atol=1e-8)
    assert q[-1] == pytest.approx(Q_MAX, rel=1e-6)  # full stroke takes sqrt(t_p p_nom/p) = 0.39 s here
