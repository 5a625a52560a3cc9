"""The first-order spool (hydroservo.components.spools.first_order)."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import components as c


def test_first_order_spool_reaches_63_percent_at_T63(driven) -> None:
    s = driven(c.SpoolFirstOrder("spool", tau="30 ms", xv_max="2 mm"), c.Step("u", amplitude=0.5))
    r = s.simulate(t_eval=[0.0, 0.03, 0.5], rtol=1e-10, atol=1e-12)
    assert r["spool.xv"][1] == pytest.approx(0.5 * 2e-3 * (1 - np.exp(-1)), rel=1e-7)  # Efe2014 eq. 3.28
    # command beyond the stroke saturates at x_max
    r2 = s.simulate(t_end=0.5, params={"u.amplitude": 3.0})
    assert r2["spool.xv"][-1] == pytest.approx(2e-3, rel=1e-6)
