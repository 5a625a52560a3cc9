"""A bare number in the Python API is SI, as documented; where the model speaks another unit (load.W in lbf)
it is said, not taken silently (the CLI refuses the same number, which it cannot tell from a typo)."""

from __future__ import annotations

import warnings

import pytest

import hydroservo as hs
from hydroservo.errors import BareNumberWarning
from hydroservo.workflows import simulate


@pytest.fixture(scope="module")
def flight() -> hs.System:
    return hs.load_model("flight-simulator")


def test_a_bare_number_for_a_parameter_the_model_gives_in_lbf_warns(flight) -> None:
    with pytest.warns(BareNumberWarning, match=r"params 'load.W': 3000 is taken in SI, 3000 N, but the model gives "
                                                r"load.W in lbf \('6400 lbf'\).*'3000 lbf'.*'3000 N'"):
        bare = flight.simulate(t_end=0.1, n_points=11, params={"load.W": 3000})
    assert bare.params["load.W"] == 3000.0  # taken as documented: SI
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # with its unit, zero, or a parameter the model gives in SI: nothing to say
        flight.simulate(t_end=0.1, n_points=11, params={"load.W": "3000 lbf"})
        flight.trim(params={"source.amplitude": 0.0, "load.W": 0})
        hs.load_model("robot-arm").simulate(t_end=0.05, n_points=6, params={"load.B": 320.0})
    with pytest.warns(BareNumberWarning, match="load.m"):
        flight.trim(params={"load.m": 2900})


def test_the_workflow_warns_of_a_number_and_refuses_the_same_as_text_as_the_cli_does() -> None:
    with pytest.warns(BareNumberWarning, match="sets load.W=3000: taken in SI, 3000 N"):
        simulate.Simulate("flight-simulator", sets={"load.W": 3000}, write="none")
    with pytest.raises(hs.ParameterError, match=r"--set load.W=3000: the model gives load.W in lbf"):
        simulate.Simulate("flight-simulator", sets=["load.W=3000"], write="none", cli=True)
