"""The rate-limited spool of FerreiraND Fig. 11 (hydroservo.components.spools.rate_limited): limits and delay."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import sine_response
from hydroservo.laws.spool_dynamics import rate_limited_spool_acceleration as rate_limited_spool
from hydroservo.validation.ferreira import bode_grid, published_dynamics

PUBLISHED = published_dynamics()
AMPS, FREQS = bode_grid()


def test_limiters_have_unit_gain_at_the_origin(rate_limited_spool_system) -> None:
    """Small signals see the plain second order: the Jacobian at rest is [[0, 1], [-wn^2, -2 xi wn]]."""
    s = rate_limited_spool_system()
    model = s.build()
    A = model.linearize(np.zeros(2), s.parameter_vector())
    wn, z = PUBLISHED["omega_n"], PUBLISHED["zeta"]
    np.testing.assert_allclose(A, [[0.0, 1.0], [-(wn**2), -2 * z * wn]], rtol=1e-12)
    # and the limits themselves: acceleration saturates at L_a, velocity demand at L_v
    L_v, L_a = PUBLISHED["L_v"], PUBLISHED["L_a"]
    acc = rate_limited_spool(1.0, 0.0, 0.0, wn, z, L_v, L_a)
    assert acc == pytest.approx(L_a)
    v_l = rate_limited_spool(1e9, 0.0, 0.0, 1.0, 0.5, L_v, 1e30)  # 2 zeta wn (v_l - 0) with a huge demand
    assert v_l == pytest.approx(L_v, rel=1e-6)


@pytest.mark.slow  # about 5 s (the default suite stays inside its 5 minutes)
def test_pade_delay_matches_the_exact_delay_in_the_band(rate_limited_spool_system) -> None:
    """The (2,2) Padé of the component against the exact phase -360 f dt: < 0.5 deg to 300 Hz, same gain.

    The Padé poles (about 4500 rad/s) need a finer grid at 10 Hz than the spool alone: 1024 steps per period.
    """
    exact = sine_response(
        rate_limited_spool_system("none"),
        "u",
        "spool.xs",
        [0.05],
        FREQS,
        delay=PUBLISHED["delay"],
        steps_per_period=1024,
    )
    pade = sine_response(rate_limited_spool_system("pade2"), "u", "spool.xs", [0.05], FREQS, steps_per_period=1024)
    np.testing.assert_allclose(pade.gain_db, exact.gain_db, atol=1e-6)
    assert np.max(np.abs(pade.phase_deg - exact.phase_deg)) < 0.5
    assert np.max(np.abs((pade.phase_deg - exact.phase_deg)[:, FREQS <= 200])) < 0.07  # 0.055 deg analytically
