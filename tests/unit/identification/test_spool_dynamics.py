"""Spool dynamics identification (hydroservo.identification.spool_dynamics): response and fits of every fidelity."""

from __future__ import annotations

import numpy as np

from hydroservo.analysis import FrequencyResponse
from hydroservo.identification import fit_spool_dynamics, spool_response
from hydroservo.validation.ferreira import published_dynamics

PUBLISHED = published_dynamics()


def test_response_is_amplitude_dependent_and_the_small_signal_limit_is_linear() -> None:
    resp = spool_response(PUBLISHED, [1e-4, 0.05, 0.5], [100.0, 200.0])
    wn, z = PUBLISHED["omega_n"], PUBLISHED["zeta"]
    w = 2 * np.pi * np.array([100.0, 200.0])
    linear = 20 * np.log10(wn**2 / np.abs(wn**2 - w**2 + 2j * z * wn * w))
    np.testing.assert_allclose(resp.gain_db[0], linear, atol=1e-4)  # tiny amplitude: limiters inactive
    assert np.all(np.diff(resp.gain_db, axis=0) < 0)  # larger amplitude, lower gain


def test_lower_fidelities_are_fitted_by_the_same_routine(published_bode: FrequencyResponse) -> None:
    second = fit_spool_dynamics(published_bode, "second-order")
    first = fit_spool_dynamics(published_bode, "first-order")
    assert set(second.params) == {"omega_n", "zeta", "delay"} and set(first.params) == {"tau", "delay"}
    # a linear model cannot follow amplitude-dependent data: errors of several dB where rate limits act
    assert second.max_gain_error(200.0) > 3.0 and first.max_gain_error(200.0) > 3.0
    assert second.cost < first.cost * 1.5
