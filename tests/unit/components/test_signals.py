"""Signal sources (hydroservo.components.signals): step, ramp, sine, square, table."""

from __future__ import annotations

import numpy as np

import hydroservo as hs
from hydroservo import components as c


def test_sources() -> None:
    s = hs.System("sources", t_end=1.0)
    s.add(c.Step("step", amplitude=2.0, t_step=0.5))
    s.add(c.Ramp("ramp", slope=3.0, t_start=0.2, limit=1.5))
    s.add(c.Sine("sine", amplitude=1.0, frequency=2.0))
    s.add(c.Square("square", amplitude=1.0, frequency=2.0))
    s.add(c.Table("table", times=[0.0, 1.0], values=[0.0, 10.0]))
    s.add(c.Sum("sum", gain1=1.0, gain2=1.0))
    s.add(c.Lag("lag", tau=1.0))
    s.connect("step.y", "sum.u1")
    s.connect("ramp.y", "sum.u2")
    s.connect("sum.y", "lag.u")
    for name in ("sine", "square", "table"):
        s.add(c.Lag(f"l_{name}", tau=1.0))
        s.connect(f"{name}.y", f"l_{name}.u")
    r = s.simulate(t_eval=[0.0, 0.3, 0.4, 0.6, 0.9, 1.0])
    np.testing.assert_allclose(r["step.y"], [0, 0, 0, 2, 2, 2])
    np.testing.assert_allclose(r["ramp.y"], [0, 0.3, 0.6, 1.2, 1.5, 1.5])
    np.testing.assert_allclose(r["sine.y"], np.sin(4 * np.pi * r.t), atol=1e-12)
    np.testing.assert_allclose(r["square.y"], [1, -1, -1, 1, -1, 1])  # 2 Hz: + on the first half of each 0.5 s period
    np.testing.assert_allclose(r["table.y"], 10 * r.t)
