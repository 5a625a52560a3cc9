"""Catalogue servovalve models fitted to a servovalve's small-signal response: the lower rungs of the ladder."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from hydroservo.analysis import servovalve_bench as sb
from hydroservo.errors import ParameterError
from hydroservo.identification.servovalve_catalogue import catalogue_response, fit_catalogue

RATED = dict(rated_flow=12 / 6e4, i_rated=0.01, dp_rated=209e5)


@pytest.mark.parametrize(
    ("order", "params"),
    [("1", {"tau": 2e-3}), ("2", {"omega_n": 800.0, "zeta": 0.6}), ("3", {"tau": 1e-3, "omega_n": 1200.0, "zeta": 0.4})],
)
def test_a_catalogue_response_is_recovered_exactly(order: str, params: dict[str, float]) -> None:
    f = np.geomspace(5.0, 300.0, 15)
    H = catalogue_response(order, params, f)
    data = SimpleNamespace(
        frequencies=f, gain_db=[20 * np.log10(np.abs(H) / abs(H[0]))], phase_deg=[np.degrees(np.unwrap(np.angle(H)))]
    )
    fit = fit_catalogue(data, order, **RATED)
    for key, value in params.items():
        assert fit.params[key] == pytest.approx(value, rel=1e-6)
    assert fit.gain_error_db < 1e-6 and fit.phase_error_deg < 1e-6


@pytest.fixture(scope="module")
def physical() -> tuple[sb.Bode, sb.StaticTests]:
    """The Table 1 valve's response at +-5 % of rated current, 5 to 150 Hz (its -90 deg frequency is 121 Hz)."""
    return sb.frequency_test(amplitudes=(0.05,), frequencies=np.geomspace(5.0, 150.0, 10)), sb.static_tests(points=11)


def test_the_ladder_follows_the_physical_model_closer_with_each_order(physical) -> None:  # type: ignore[no-untyped-def]
    """Up to 150 Hz: third order within 0.5 dB and 3 deg, second within 2.5 dB and 8 deg, first order only to
    5 dB and 60 deg (a first-order lag cannot pass -90 deg, which the valve does at 121 Hz)."""
    bode, static = physical
    fits = {o: fit_catalogue(bode, o, rated_flow=static.rated_flow, i_rated=0.01, dp_rated=209e5) for o in "123"}
    assert fits["3"].gain_error_db < 0.5 and fits["3"].phase_error_deg < 3.0
    assert fits["2"].gain_error_db < 2.5 and fits["2"].phase_error_deg < 8.0
    assert fits["1"].phase_error_deg > 30.0 and fits["1"].gain_error_db > fits["2"].gain_error_db
    # the fitted component on the same bench gives the response it was fitted to, and the rated flow
    third = fits["3"]
    again = sb.frequency_test(sb.BenchConditions(third.valve), amplitudes=(0.05,), frequencies=bode.frequencies)
    assert np.max(np.abs(again.gain_db[0] - third.gain_db)) < 0.02
    assert np.max(np.abs(again.phase_deg[0] - third.phase_deg)) < 0.2
    assert sb.static_tests(sb.BenchConditions(third.valve), points=5).rated_flow == pytest.approx(static.rated_flow, rel=1e-3)


def test_a_fit_needs_enough_frequencies_and_a_known_order() -> None:
    data = SimpleNamespace(frequencies=np.array([5.0, 10.0]), gain_db=[[0.0, -0.1]], phase_deg=[[-3.0, -6.0]])
    with pytest.raises(ParameterError, match="order 3 needs at least 4"):
        fit_catalogue(data, "3", **RATED)
    with pytest.raises(ParameterError, match="order = '4'"):
        fit_catalogue(data, "4", **RATED)
