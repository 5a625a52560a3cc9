"""Control blocks (hydroservo.components.control): amplifier, gain, saturation, PID, lag."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c


def test_amplifier_saturation_gain_lag_pid() -> None:
    s = hs.System("chain", t_end=1.0)
    s.add(c.Step("e", unit="V", amplitude="3 V"))
    s.add(c.Amplifier("amp", G_a=2.0, R="100 ohm", I_max="50 mA"))
    s.add(c.Gain("gain", K=0.5))
    s.add(c.Saturation("sat", lower=-1.0, upper=1.0))
    s.add(c.PID("pid", Kp=2.0, Ki=4.0, upper=20.0))
    s.add(c.Lag("lag", K=2.0, tau="0.1 s"))
    s.connect("e.y", "amp.E", "gain.u", "pid.e", "lag.u")
    s.add(c.Lag("sink", tau=1.0))
    s.connect("gain.y", "sat.u")
    s.connect("sat.y", "sink.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.0, 2.0, 3.0], rtol=1e-10, atol=1e-12)
    assert r["amp.i"][-1] == pytest.approx(0.05)  # 2 * 3 V / 100 ohm = 60 mA, limited to 50 mA
    assert r["gain.y"][-1] == pytest.approx(1.5)
    assert r["sat.y"][-1] == pytest.approx(1.0)
    assert r["pid.y"][1] == pytest.approx(2 * 3 + 4 * 3 * 0.5, rel=1e-6)  # P + I at 0.5 s
    assert r["pid.y"][-1] == pytest.approx(20.0)  # clamped
    # anti-windup: the integral stops where 2 * 3 + 4 * I reaches 20, I = 3.5
    np.testing.assert_allclose(r["pid.I"][-2:], 3.5, rtol=1e-6)
    assert r["lag.y"][1] == pytest.approx(6.0 * (1 - np.exp(-5.0)), rel=1e-7)
