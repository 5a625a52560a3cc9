"""The second-order spool (hydroservo.components.spools.second_order)."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import components as c


def test_second_order_spool_natural_frequency_and_stroke_limit(driven) -> None:
    wn, zeta = 2 * np.pi * 50, 0.2
    s = driven(c.SpoolSecondOrder("spool", omega_n=wn, zeta=zeta, xv_max="1 mm"), c.Step("u", amplitude=0.5))
    r = s.simulate(t_end=0.1, n_points=2001, rtol=1e-10, atol=1e-12)
    t = r.t
    wd = wn * np.sqrt(1 - zeta**2)
    exact = 0.5e-3 * (1 - np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * t)))
    np.testing.assert_allclose(r["spool.xv"], exact, atol=1e-9)
    r2 = s.simulate(t_end=0.1, params={"u.amplitude": 0.95})
    assert r2["spool.xv"].max() == pytest.approx(1e-3)  # the overshoot is clipped at the stroke
