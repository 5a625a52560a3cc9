"""Periodic frequency response (hydroservo.analysis.frequency) against a long time-domain run."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import sine_response


def test_periodic_response_agrees_with_a_long_cvodes_run(rate_limited_spool_system) -> None:
    """Shooting + fixed-step RK4 against CVODES (rtol 1e-10) integrated through 60 periods."""
    s = rate_limited_spool_system()
    f, a = 300.0, 0.5
    resp = sine_response(s, "u", "spool.xs", [a], [f])
    res = s.simulate(t_end=60 / f, params={"u.amplitude": a, "u.frequency": f}, n_points=12001, rtol=1e-10, atol=1e-12)
    t, y = res.t, res.get("spool.xs")
    sel = t >= t[-1] - 10 / f
    tt, yy = t[sel], y[sel]
    span = tt[-1] - tt[0]
    a1 = 2 * np.trapezoid(yy * np.sin(2 * np.pi * f * tt), tt) / span
    b1 = 2 * np.trapezoid(yy * np.cos(2 * np.pi * f * tt), tt) / span
    assert 20 * np.log10(np.hypot(a1, b1) / a) == pytest.approx(resp.gain_db[0, 0], abs=2e-3)
    assert np.degrees(np.arctan2(b1, a1)) == pytest.approx(resp.phase_deg[0, 0] % 360 - 360, abs=0.05)
