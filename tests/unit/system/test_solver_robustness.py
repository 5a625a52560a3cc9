"""Solver robustness on random valid parameter sets (issue 37; ``benchmarks/bench_robustness.py``).

Each set here failed before, drawn by the benchmark (seed 0) or by ``benchmarks/fuzz_models.py``; each now either
runs or is refused with a message that names its cause. Fixed parameter dicts (SI), so that the draw's code may
change without changing what is tested.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from hydroservo.errors import ParameterError, SolverError
from hydroservo.io import load_model
from hydroservo.laws.pseudo_section import check_sections

#: flight-simulator, benchmark set 102: the spool end area a hundredth of the default makes the servovalve's pilot
#: loop (torque motor, flapper-nozzle, spool, feedback wire) unstable. Before: the spool ran off to 1e17 m/s^2 and
#: the run failed ("step budget ... used up"); now the spool chatters between its stops and the run completes.
UNSTABLE_PILOT = {
    "feedback.G": -15.88031284931419,
    "spool.Av": 7.615060659547652e-07,
    "load.x_max": 2.199474849778531e28,
}

#: servo-solenoid-cylinder, fuzz set 130 (seed 0): k and x_t drawn alone, so that the variable-structure
#: pseudo-section's two branches differ by a factor 1e11 at x_t. Before: "the step fell to 5.09e-17 s".
DISCONTINUOUS_SECTION = {"supply.p": 11649428.757139618, "valve.k": 63.341324403383204, "valve.x_t": 0.906758687361733}


@pytest.fixture(scope="module")
def flight_simulator():
    return load_model("flight-simulator")


def test_an_unstable_pilot_stage_chatters_between_the_spool_stops(flight_simulator) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = flight_simulator.simulate(params=UNSTABLE_PILOT)
    xv_max = r.params["spool.xv_max"]
    assert xv_max == r.params["valve.xv_max"]  # one stroke with the valve
    xv = np.asarray(r["spool.xv"])
    assert np.all(np.isfinite(xv))
    assert np.max(np.abs(xv)) <= xv_max * (1 + 1e-5)  # each contact's step ends a hair past the stop
    assert np.max(np.abs(xv)) > 0.99 * xv_max  # it does reach them: the loop is unstable
    assert r.stats["nevents"] > 100  # each contact ends a step


def test_the_spool_stops_leave_the_published_run_alone(flight_simulator) -> None:
    r = flight_simulator.simulate()
    assert np.max(np.abs(r["spool.xv"])) < 0.5 * r.params["spool.xv_max"]
    assert r.stats["nevents"] == 0


def test_a_spool_start_beyond_its_travel_is_refused(flight_simulator) -> None:
    with pytest.raises(ParameterError, match=r"spool\.xv0 = 0\.003 m.*xv_max = 0\.00254 m"):
        flight_simulator.check_components({"spool.xv0": 3e-3})


def test_a_discontinuous_pseudo_section_is_refused_naming_its_parameters() -> None:
    system = load_model("servo-solenoid-cylinder")
    with pytest.raises(ParameterError, match=r"x_t = 0\.9068.*k = 63\.34.*continuous"):
        system.simulate(params=DISCONTINUOUS_SECTION)


def test_the_published_pseudo_section_is_continuous() -> None:
    check_sections("variable", dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=3.858e-2))
    with pytest.raises(ParameterError, match=r"differ by more than 5%"):
        check_sections("variable", dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=0.5))


@pytest.mark.parametrize("method", ["auto", "cvodes"])
def test_a_parameter_out_of_all_proportion_is_refused_alike_by_both_methods(method: str) -> None:
    """``load.B = 1e300 N*s/m``: the default method ran it (the load locked), CVODES gave NaN. Both now refuse it."""
    system = load_model("position-servo")
    with pytest.raises(ParameterError, match=r"load\.B = 1e\+300 N·s/m is out of all proportion.*1e-298 s"):
        system.simulate(params={"load.B": 1e300}, method=method)


def test_a_large_but_physical_rate_still_runs() -> None:
    """The limit is far from any circuit: B a million times its default runs (a time scale of 1e-9 s)."""
    system = load_model("position-servo")
    B = system.parameter_values()["load.B"]
    r = system.simulate(params={"load.B": 1e6 * B}, t_end=0.05)
    assert np.all(np.isfinite(r["load.x"]))


def test_a_horizon_far_too_long_says_so_with_its_numbers() -> None:
    """``t_end = 1e300 s`` said "the step fell to 0.000395 s" at t = 0: the floor of a step scaled with the span."""
    system = load_model("position-servo")
    with pytest.raises(SolverError) as err:
        system.simulate(t_end=1e300)
    message = str(err.value)
    assert "step fell" not in message
    assert "1e+300 s asked for would take 1e+30" in message


def test_the_step_budget_message_gives_how_far_the_run_got() -> None:
    system = load_model("position-servo")
    with pytest.raises(SolverError, match=r"step budget of 200 steps was used up .*mean step .* s of the 2 s asked"):
        system.simulate(t_end=2.0, max_steps=200)


def test_the_last_measurement_of_random_valid_sets_meets_issue_37s_floor() -> None:
    """benchmarks/results/robustness.json (bench_robustness.py, 150 valid sets per built-in model): under 3 % of
    the sets fail under the default method, for every built-in model (issue 37's floor); a measurement committed
    that misses it fails here."""
    import json
    from pathlib import Path

    from hydroservo.data import model_names

    data = json.loads((Path(__file__).resolve().parents[3] / "benchmarks" / "results" / "robustness.json").read_text())
    figures = data["figures"]
    for name in model_names():
        key = name.replace("-", "_")
        assert figures[f"{key}_auto_sets"] == 150, name
        assert figures[f"{key}_auto_failed_percent"] < 3.0, (name, figures[f"{key}_auto_failed_percent"])
