"""The servovalve design study on the component: what each physical parameter does to each bench figure."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis import servovalve_bench as sb
from hydroservo.analysis.servovalve_design import FIGURES, design_study
from hydroservo.components import TwoStageServovalve
from hydroservo.errors import ParameterError

PARAMS = ["N", "K_f", "x_p0", "d_o", "k_n"]  # a few: the whole study is the CLI's (a slow test)


QUICK = ("rated_flow", "spool_travel", "flapper_tip", "leakage_null", "f_90", "f_3db", "rise_time", "overshoot")


@pytest.fixture(scope="module")
def study():  # type: ignore[no-untyped-def]
    return design_study(parameters=PARAMS, figures=QUICK)  # linearity and hysteresis: the slow test below


def test_force_feedback_sets_the_rated_flow(study) -> None:  # type: ignore[no-untyped-def]
    """Q ~ K_i / (K_f l_f): the turns (K_i, eq. 5) +1, the feedback spring -1 (nearly: the flapper's bending and
    the jets take a little), the air gap first (K_i ~ 1/x_p0^2, and the magnetic spring)."""
    e = study.elasticity["rated_flow"]
    assert e["N"] == pytest.approx(1.0, abs=0.02)
    assert e["K_f"] == pytest.approx(-1.0, abs=0.1)
    assert study.ranked("rated_flow", 1)[0][0] == "x_p0"
    assert study.figures["rated_flow"] * 6e4 == pytest.approx(11.99, abs=0.01)
    assert list(study.figures) == list(QUICK)


def test_exact_derivatives_agree_with_differences(study) -> None:  # type: ignore[no-untyped-def]
    """The implicit function theorem at the trim against central differences of the bench's static test."""
    for name in ("K_f", "d_o"):
        v = TwoStageServovalve.PARAMETERS[name].si_default()
        up = sb.static_tests(sb.BenchConditions(TwoStageServovalve("v", **{name: v * 1.001})), points=5).rated_flow
        down = sb.static_tests(sb.BenchConditions(TwoStageServovalve("v", **{name: v * 0.999})), points=5).rated_flow
        base = study.figures["rated_flow"]
        assert study.elasticity["rated_flow"][name] == pytest.approx((up - down) / (0.002 * base), abs=2e-3)


def test_the_torque_motor_sits_near_its_stability_limit(study) -> None:  # type: ignore[no-untyped-def]
    """The magnetic spring K_m = 4.18 N m/rad exceeds the flexure tube's 3.55: the transient hangs on the air gap
    (a 1 % change moves the rise time by tens of per cent), the small-signal phase far less."""
    assert abs(study.elasticity["rise_time"]["x_p0"]) > 10
    assert abs(study.elasticity["f_90"]["x_p0"]) < 2
    assert study.figures["f_90"] == pytest.approx(123.0, abs=2.0)  # Hz; the bench's +-5 % sine: 121 Hz
    assert np.isfinite(study.elasticity["overshoot"]["k_n"])


@pytest.mark.slow  # over 5 s (the default suite stays inside its 5 minutes)
def test_linearity_and_hysteresis_follow_the_bench() -> None:
    """The study's design point is the bench's: the same linearity (41 currents) and hysteresis (1/16 Hz)."""
    study = design_study(parameters=["x_p0", "N"], figures=["linearity", "hysteresis"])
    assert list(study.figures) == ["linearity", "hysteresis"] and set(FIGURES) >= set(study.figures)
    assert study.figures["linearity"] == pytest.approx(sb.static_tests().linearity, rel=1e-6)
    assert study.figures["hysteresis"] == pytest.approx(sb.hysteresis_test().hysteresis, rel=1e-6)
    assert abs(study.elasticity["hysteresis"]["x_p0"]) > abs(study.elasticity["linearity"]["x_p0"])


def test_unknown_parameters_and_steps_are_refused() -> None:
    with pytest.raises(ParameterError, match="nozzle: not parameters of TwoStageServovalve"):
        design_study(parameters=["nozzle"])
    with pytest.raises(ParameterError, match="step = 0.5"):
        design_study(step=0.5)
    with pytest.raises(ParameterError, match=r"figures \['bandwidth'\]"):
        design_study(figures=["bandwidth"])
