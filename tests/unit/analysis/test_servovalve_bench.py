"""The servovalve test bench on the two-stage servovalve of [GordicND] (Table 1)."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import servovalve_bench as sb
from hydroservo.components import Orifice, TwoStageServovalve
from hydroservo.errors import ModelError, ParameterError

RATED = 0.01


def test_static_tests_reproduce_the_rated_flow_at_rest() -> None:
    """12 L/min at 10 mA and 210 bar ([GordicND] section 3) from the component's trim, nothing tuned."""
    st = sb.static_tests(points=11)
    assert st.rated_flow * 6e4 == pytest.approx(11.99, abs=0.01)
    assert st.rated_flow_negative == pytest.approx(-st.rated_flow, rel=1e-9)  # the valve is symmetric
    assert 0 < st.linearity < 0.03
    assert 1.4 < st.flow_gain_null * 6e4 / 1e3 < 1.7  # L/min/mA, near the rated line's 1.2 (rounded edges add)
    assert 0.5 < st.internal_leakage_null * 6e4 < 1.5


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_the_25_percent_square_wave_is_slower_because_the_flapper_hits_the_nozzle() -> None:
    """[GordicND] section 4, Fig. 9, as the bench measures it."""
    steps = {s.fraction: s for s in sb.step_tests()}
    assert [steps[f].reaches_nozzle for f in (0.05, 0.10, 0.25)] == [False, False, True]
    assert steps[0.25].rise_time > 1.4 * steps[0.05].rise_time
    static = sb.static_tests(points=201)
    for st in steps.values():  # each step settles on the characteristic at rest (within the null's jump)
        at_rest = float(np.interp(st.fraction * RATED, static.currents, static.flows))
        assert st.flow[-1] == pytest.approx(at_rest, rel=0.03)


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_hysteresis_comes_from_the_feedback_ball_clearance_and_friction() -> None:
    """Hysteresis 'can be spotted in the numerically obtained curve' ([GordicND] Fig. 10): with Table 1's ball
    clearance and dry friction a slow sine leaves a loop; without them it nearly closes."""
    with_play = sb.hysteresis_test()
    without = sb.hysteresis_test(sb.BenchConditions(TwoStageServovalve("v", z=0.0, F_c0=0.0, F_cn=0.0)))
    assert 0.001 < with_play.hysteresis < 0.02
    assert without.hysteresis < 0.5 * with_play.hysteresis
    assert abs(with_play.null_shift) < 1e-3 * RATED  # symmetric: the loop is centred


def test_the_threshold_away_from_null_is_below_a_hundredth_of_a_per_cent() -> None:
    """Away from null the spool moves with the current as soon as it reverses: the ball's clearance is taken up
    by the pressure force that holds the spool, and dry friction is 3 mN against newtons."""
    th = sb.threshold_test()
    assert th.reversals.size == 4
    assert 0 <= th.threshold < 1e-4
    # a hundred times the spool's dry friction (0.3 N) holds it after each reversal: the threshold shows it
    sticky = sb.threshold_test(sb.BenchConditions(TwoStageServovalve("v", F_c0=0.3, F_cn=0.3)))
    assert sticky.threshold > 5 * th.threshold and sticky.threshold > 2e-4


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_blocked_ports_give_load_pressure_and_leakage() -> None:
    bl = sb.blocked_tests()
    span = 209e5
    assert bl.load_pressure.max() > 0.9 * span and bl.load_pressure.min() < -0.9 * span
    assert bl.pressure_gain_40 > 0 and bl.null_width >= 0
    # Table 1's valve jumps: the gain grows as the sweep slows, so it is reported as a lower bound
    assert not bl.resolved and bl.pressure_gain_40 > 1.5 * bl.pressure_gain_40_fast
    peak = int(np.argmax(bl.leak_flows))
    assert abs(bl.leak_currents[peak]) < 0.05 * RATED  # the leakage peaks at null
    assert bl.leak_flows.min() > 0


def test_frequency_response_starts_at_the_static_gain() -> None:
    """At 5 Hz the valve follows: the fundamental's gain is the characteristic's slope at 5 % of rated current,
    and the phase lags more as the frequency rises."""
    bode = sb.frequency_test(amplitudes=(0.05,), frequencies=(5.0, 50.0, 200.0))
    low = bode.info["low_frequency_gain"][0] * 6e4 / 1e3  # L/min/mA
    st = sb.static_tests(points=41)
    slope = float(np.interp(0.05 * RATED, st.currents, st.flows)) / (0.05 * RATED) * 6e4 / 1e3
    assert low == pytest.approx(slope, rel=0.1)  # the sine's fundamental against the chord to 5 %
    assert bode.gain_db[0, 0] == 0.0
    assert 0 > bode.phase_deg[0, 0] > bode.phase_deg[0, 1] > bode.phase_deg[0, 2]
    assert not bode.info["unsettled"]


def test_a_bench_refuses_what_is_not_a_servovalve_or_a_test() -> None:
    with pytest.raises(ModelError, match="is not a servovalve"):
        sb.BenchConditions(Orifice("o"))
    with pytest.raises(ParameterError, match="rated current"):
        sb.BenchConditions(i_rated=-1.0)
    with pytest.raises(ParameterError, match="step fraction"):
        sb.step_tests(fractions=(3.0,))
    with pytest.raises(ParameterError, match="tests noise: unknown"):
        sb.bench_report(tests=("noise",))
    with pytest.raises(ParameterError, match="supply p_s"):
        sb.BenchConditions(p_s=0.5e5)
