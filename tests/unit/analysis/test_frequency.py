"""Periodic frequency response (hydroservo.analysis.frequency) against a long time-domain run."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import sine_response
from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.errors import ParameterError


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


# -- crossings: one rule for every -3 dB and -90 deg figure ----------------------------------------------
def _response(H: np.ndarray, f: np.ndarray) -> FrequencyResponse:
    return FrequencyResponse(np.ones(H.shape[0]), f, 20 * np.log10(np.abs(H)), np.degrees(np.unwrap(np.angle(H), axis=1)))


def test_crossings_of_closed_form_responses() -> None:
    f = np.geomspace(1.0, 1e4, 81)  # 20 points a decade
    first = 1 / (1 + 1j * f / 100.0)  # -45 deg at 100 Hz; -3 dB at 100 sqrt(10^0.3 - 1) Hz
    zeta, fn = 0.4, 300.0
    second = 1 / (1 - (f / fn) ** 2 + 2j * zeta * f / fn)  # -90 deg at exactly fn
    r = _response(np.vstack([first, second]), f)
    f3_exact = 100.0 * np.sqrt(10**0.3 - 1)
    # Log-linear interpolation over a twentieth of a decade: within 0.1 % of the closed forms here.
    assert r.bandwidth()[0] == pytest.approx(f3_exact, rel=1e-3)
    assert r.crossing(-45.0, of="phase")[0] == pytest.approx(100.0, rel=1e-3)
    assert r.phase_crossing()[1] == pytest.approx(fn, rel=1e-3)


def test_a_crossing_not_reached_or_below_the_first_frequency_is_nan() -> None:
    f = np.geomspace(1.0, 50.0, 20)
    lag = 1 / (1 + 1j * f / 100.0)  # never -3 dB below 50 Hz
    r = _response(lag[None, :], f)
    assert np.isnan(r.bandwidth()[0])
    assert np.isnan(r.crossing(0.5, of="phase")[0])  # the phase starts below +0.5 deg: the crossing lies below 1 Hz
    with pytest.raises(ParameterError, match="expected 'gain' or 'phase'"):
        r.crossing(-3.0, of="magnitude")
