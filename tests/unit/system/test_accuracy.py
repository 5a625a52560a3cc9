"""``accuracy=``: the tolerances it picks keep the main signals within that fraction of their range.

The reference is the same model at rtol 1e-11; the deviation of a signal is its largest difference from the
reference over the run, divided by the reference's range (max - min). The two models are the fast ones among
the built-in models (docs/engine.md, "Accuracy", has all four, measured by benchmarks/bench_accuracy.py).
"""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo.errors import ParameterError
from hydroservo.system.integration import DEFAULT_ACCURACY, SolverSettings, tolerances
from hydroservo.system.native import has_compiler

needs_compiler = pytest.mark.skipif(not has_compiler(), reason="no C compiler")


def deviation(result: hs.Result, reference: hs.Result, names: list[str]) -> float:
    worst = 0.0
    for name in names:
        span = float(np.ptp(reference[name]))
        if span > 0:
            worst = max(worst, float(np.max(np.abs(result[name] - reference[name]))) / span)
    return worst


@pytest.mark.parametrize("method", ["cvodes", pytest.param("rodas3", marks=needs_compiler)])
@pytest.mark.parametrize("model", ["flight-simulator", "servo-solenoid-cylinder"])
def test_each_accuracy_holds_on_the_main_signals(model: str, method: str) -> None:
    system = hs.load_model(model)
    names = [n for panel in system.default_panels() for n in panel]
    reference = system.simulate(rtol=1e-11, atol=1e-13, max_steps=10_000_000, method="cvodes")
    steps = []
    for accuracy in (1e-3, 1e-4, 1e-5):
        result = system.simulate(accuracy=accuracy, method=method)
        assert deviation(result, reference, names) <= accuracy, (model, accuracy)
        steps.append(result.stats["nsteps"])
    assert steps == sorted(steps) and steps[0] < steps[-1]  # a looser accuracy costs fewer steps


def test_the_default_is_the_stated_accuracy_and_tolerances_come_from_one_place() -> None:
    assert tolerances(DEFAULT_ACCURACY) == (1e-6, 1e-8)
    assert (SolverSettings.of().rtol, SolverSettings.of().atol) == (1e-6, 1e-8)
    assert SolverSettings.of(rtol=1e-4).atol == pytest.approx(1e-6)  # atol follows rtol unless given
    assert SolverSettings.of(rtol=1e-4, atol=1e-9).atol == 1e-9
    with pytest.raises(ParameterError, match="not both"):
        SolverSettings.of(rtol=1e-4, accuracy=1e-3)
    with pytest.raises(ParameterError, match="accuracy = 0.5"):
        SolverSettings.of(accuracy=0.5)
    result = hs.load_model("flight-simulator").simulate(t_end=0.1, accuracy=1e-2)
    assert (result.stats["rtol"], result.stats["atol"]) == pytest.approx((1e-4, 1e-6))
