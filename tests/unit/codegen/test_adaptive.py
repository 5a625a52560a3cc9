"""The variable-step solvers of every C export (``integrate``: dopri5 and ros23): their order, their error
control, their dense output, their agreement with CVODES and their refusals.

The order is observed on the driven spring of ``test_c`` (a closed-form solution): with steps of at most h and
tolerances too loose to bind, every step but the first few is h long, so the error at the end falls as h^p for
a method of order p. Deviations from CVODES are relative to the range of each
signal over the run, CVODES at rtol 1e-10 (about 1e-9 of range).
"""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.codegen.c import CStepper, compiler
from hydroservo.errors import ParameterError, SolverError

from .test_c import _driven_spring, _driven_spring_position

try:
    compiler()
except ParameterError:
    pytest.skip("no C compiler", allow_module_level=True)


@pytest.fixture(scope="module")
def spring() -> CStepper:
    return CStepper(_driven_spring(), step=1e-3)


def _end_error(stepper: CStepper, method: str, h: float = 0.0, rtol: float = 0.5, atol: float = 1.0) -> float:
    stepper.reset()
    states, _ = stepper.integrate([0.0, 1.0], method=method, rtol=rtol, atol=atol, max_step=h)
    return abs(states[-1, stepper.export.states.index("load.x")] - _driven_spring_position(np.array([1.0]))[0])


@pytest.mark.parametrize(("method", "order"), [("dopri5", 5), ("ros23", 2)])
def test_observed_order(spring: CStepper, method: str, order: int) -> None:
    """Halving the step divides the error by 2^p, within half an order (a wrong coefficient loses one or more)."""
    coarse, fine = _end_error(spring, method, 0.02), _end_error(spring, method, 0.01)
    observed = np.log2(coarse / fine)
    assert order - 0.5 < observed < order + 0.7, (coarse, fine, observed)


@pytest.mark.parametrize("method", ["dopri5", "ros23"])
def test_error_control_follows_the_tolerance(spring: CStepper, method: str) -> None:
    """The tolerance sets the steps: the error at 1 s (of a 10 mm swing) stays within 1000 rtol of the amplitude
    (a local tolerance: the global error of three undamped periods adds up over the steps, most for the
    second-order ros23, 670 rtol at rtol 1e-7), and shrinks by at least 10x for a 1000x tighter tolerance."""
    errors = [_end_error(spring, method, rtol=rtol, atol=rtol / 100) for rtol in (1e-4, 1e-7)]
    assert errors[0] < 1000 * 1e-4 * 0.01 and errors[1] < 1000 * 1e-7 * 0.01
    assert errors[1] < errors[0] / 10


@pytest.mark.parametrize("method", ["dopri5", "ros23"])
def test_dense_output_between_steps(spring: CStepper, method: str) -> None:
    """Output times inside steps come from the cubic Hermite interpolant: within 1000 rtol of the swing of the
    closed form (the bound of the steps' own global error, above) at every one of 2001 times."""
    spring.reset()
    times = np.linspace(0.0, 1.0, 2001)
    states, _ = spring.integrate(times, method=method, rtol=1e-6, atol=1e-8)
    x = states[:, spring.export.states.index("load.x")]
    assert np.max(np.abs(x - _driven_spring_position(times))) < 1000 * 1e-6 * 0.01
    stats = spring.integration_statistics()
    assert stats["steps"] < 2000 and stats["rejected"] < stats["steps"]  # fewer steps than outputs: interpolated


@pytest.fixture(scope="module")
def flight() -> tuple[CStepper, hs.Result]:
    system = hs.load_model("flight-simulator")
    grid = np.linspace(0.0, 2.0, 401)
    return CStepper(system, step=1e-4), system.simulate(t_eval=grid, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("method", ["dopri5", "ros23"])
def test_flight_simulator_agrees_with_cvodes(flight: tuple[CStepper, hs.Result], method: str) -> None:
    """At rtol 1e-5 (accuracy 1e-3) the states and the main outputs are within 1e-3 of their range of CVODES'."""
    stepper, ref = flight
    stepper.reset()
    states, outputs = stepper.integrate(ref.t, method=method, rtol=1e-5, atol=1e-7)
    for name in ("y", "p1", "p2", "xv"):
        if name in stepper.export.states:
            column = states[:, stepper.export.states.index(name)]
        else:
            column = outputs[:, stepper.export.outputs.index(name)]
        assert np.max(np.abs(column - ref[name])) <= 1e-3 * np.ptp(ref[name]), name


def test_refusals_name_the_reason(flight: tuple[CStepper, hs.Result]) -> None:
    stepper, _ = flight
    stepper.reset()
    with pytest.raises(ParameterError, match="expected one of dopri5, ros23"):
        stepper.integrate([0.0, 1.0], method="euler")
    with pytest.raises(SolverError, match="not after the one before"):
        stepper.integrate([0.0, 1.0, 1.0], method="ros23")
    with pytest.raises(SolverError, match="step budget of 10 steps was used up"):
        stepper.integrate([0.0, 2.0], method="dopri5", max_steps=10)
    assert 0.0 < stepper.time < 2.0  # left at the last accepted step
