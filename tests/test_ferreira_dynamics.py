"""The spool dynamics of FerreiraND: Fig. 11 model, amplitude-dependent frequency response, Bode identification.

The published fit (section 6, the parameter set ``FerreiraND``): omega_n =
1007 rad/s, xi = 0.48, L_v = 125 1/s, L_a = 81184 1/s^2, delay 7.625e-4 s.
The manufacturer's curves are not available, so identification is proven on
data generated from these values.
"""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.analysis import FrequencyResponse, sine_response
from hydroservo.components import Sine, SpoolRateLimited
from hydroservo.errors import ParameterError
from hydroservo.identification import fit_spool_dynamics, spool_response
from hydroservo.io import read_bode, write_bode
from hydroservo.laws.spool_dynamics import rate_limited_spool_acceleration as rate_limited_spool
from hydroservo.validation.ferreira import bode_grid, published_dynamics

PUBLISHED = published_dynamics()
AMPS, FREQS = bode_grid()


def spool_system(delay_model: str = "none") -> hs.System:
    s = hs.System("spool")
    s.add(Sine("u"))
    s.add(SpoolRateLimited("spool", delay_model=delay_model))
    s.connect("u.y", "spool.u")
    return s


def test_limiters_have_unit_gain_at_the_origin() -> None:
    """Small signals see the plain second order: the Jacobian at rest is [[0, 1], [-wn^2, -2 xi wn]]."""
    s = spool_system()
    model = s.build()
    A = model.linearize(np.zeros(2), s.parameter_vector())
    wn, z = PUBLISHED["omega_n"], PUBLISHED["zeta"]
    np.testing.assert_allclose(A, [[0.0, 1.0], [-(wn**2), -2 * z * wn]], rtol=1e-12)
    # and the limits themselves: acceleration saturates at L_a, velocity demand at L_v
    acc = rate_limited_spool(1.0, 0.0, 0.0, wn, z, 125.0, 81184.0)
    assert acc == pytest.approx(81184.0)
    v_l = rate_limited_spool(1e9, 0.0, 0.0, 1.0, 0.5, 125.0, 1e30)  # 2 zeta wn (v_l - 0) with a huge demand
    assert v_l == pytest.approx(125.0, rel=1e-6)


def test_periodic_response_agrees_with_a_long_cvodes_run() -> None:
    """Shooting + fixed-step RK4 against CVODES (rtol 1e-10) integrated through 60 periods."""
    s = spool_system()
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


def test_pade_delay_matches_the_exact_delay_in_the_band() -> None:
    """The (2,2) Padé of the component against the exact phase -360 f dt: < 0.5 deg to 300 Hz, same gain.

    The Padé poles (about 4500 rad/s) need a finer grid at 10 Hz than the spool alone: 1024 steps per period.
    """
    exact = sine_response(
        spool_system("none"), "u", "spool.xs", [0.05], FREQS, delay=PUBLISHED["delay"], steps_per_period=1024
    )
    pade = sine_response(spool_system("pade2"), "u", "spool.xs", [0.05], FREQS, steps_per_period=1024)
    np.testing.assert_allclose(pade.gain_db, exact.gain_db, atol=1e-6)
    assert np.max(np.abs(pade.phase_deg - exact.phase_deg)) < 0.5
    assert np.max(np.abs((pade.phase_deg - exact.phase_deg)[:, FREQS <= 200])) < 0.07  # 0.055 deg analytically


def test_response_is_amplitude_dependent_and_the_small_signal_limit_is_linear() -> None:
    resp = spool_response(PUBLISHED, [1e-4, 0.05, 0.5], [100.0, 200.0])
    wn, z = PUBLISHED["omega_n"], PUBLISHED["zeta"]
    w = 2 * np.pi * np.array([100.0, 200.0])
    linear = 20 * np.log10(wn**2 / np.abs(wn**2 - w**2 + 2j * z * wn * w))
    np.testing.assert_allclose(resp.gain_db[0], linear, atol=1e-4)  # tiny amplitude: limiters inactive
    assert np.all(np.diff(resp.gain_db, axis=0) < 0)  # larger amplitude, lower gain


@pytest.fixture(scope="module")
def published_bode() -> FrequencyResponse:
    # Data with twice the integration grid of the fit (512 steps per period), so the fit does not see its own numbers.
    return spool_response(PUBLISHED, AMPS, FREQS, steps_per_period=512)


def test_identification_round_trip(published_bode: FrequencyResponse) -> None:
    """Seed 000 eq. 43 from a start 35-40 % away from every value: recover all within 1 % (issue floor)."""
    start = {"omega_n": 1007 * 1.35, "zeta": 0.48 * 0.65, "L_v": 125 * 1.4, "L_a": 81184 * 0.6}
    fit = fit_spool_dynamics(published_bode, "rate-limited", start)
    for k, v in PUBLISHED.items():
        assert fit.params[k] == pytest.approx(v, rel=1e-2), k
        assert abs(fit.params[k] / v - 1) < 1e-4, k  # what is actually achieved, noise free
    assert fit.max_gain_error(200.0) < 1e-3


def test_lower_fidelities_are_fitted_by_the_same_routine(published_bode: FrequencyResponse) -> None:
    second = fit_spool_dynamics(published_bode, "second-order")
    first = fit_spool_dynamics(published_bode, "first-order")
    assert set(second.params) == {"omega_n", "zeta", "delay"} and set(first.params) == {"tau", "delay"}
    # a linear model cannot follow amplitude-dependent data: errors of several dB where rate limits act
    assert second.max_gain_error(200.0) > 3.0 and first.max_gain_error(200.0) > 3.0
    assert second.cost < first.cost * 1.5


def test_bode_csv_round_trip_and_bad_files(tmp_path, published_bode: FrequencyResponse) -> None:
    path = write_bode(published_bode, tmp_path / "bode.csv")
    back = read_bode(path)
    np.testing.assert_allclose(back.gain_db, published_bode.gain_db, rtol=1e-9)
    np.testing.assert_allclose(back.amplitudes, AMPS)
    bad = tmp_path / "bad.csv"
    bad.write_text("frequency [Hz],gain [dB]\n10,0.1\n")
    with pytest.raises(ParameterError, match="missing column.*amplitude"):
        read_bode(bad)
    bad.write_text("frequency [rad/s],amplitude [%],gain [dB]\n10,5,0.1\n")
    with pytest.raises(ParameterError, match="expected unit \\[hz\\]"):
        read_bode(bad)
    bad.write_text("frequency [Hz],amplitude [%],gain [dB]\n10,5,0.1\n20,25,0.1\n")
    with pytest.raises(ParameterError, match="every amplitude at every frequency"):
        read_bode(bad)
    with pytest.raises(ParameterError, match="fractions of the stroke"):
        spool_response(PUBLISHED, [5.0], [10.0])


def test_validation_table_of_seed_000() -> None:
    from hydroservo.validation import validate

    checks = validate("servo-solenoid-cylinder")
    assert {c.verdict for c in checks} <= {"reproduced", "info"}
    assert sum(c.verdict == "reproduced" for c in checks) == 15
