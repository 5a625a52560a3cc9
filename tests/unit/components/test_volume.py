"""The lumped volume (hydroservo.components.volume)."""

from __future__ import annotations

import pytest

import hydroservo as hs
from hydroservo import components as c


def test_volume_integrates_net_flow() -> None:
    s = hs.System("vol")
    s.add(c.Volume("vol", V="1 L", beta_e="1.5 GPa"))
    s.add(c.Step("q", unit="m^3/s", amplitude="1 L/min"))
    s.connect("q.y", "vol.Q1")
    r = s.simulate(t_end=0.1)
    assert r["vol.p"][-1] == pytest.approx(1.5e9 / 1e-3 * (1e-3 / 60) * 0.1)
