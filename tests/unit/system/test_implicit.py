"""Algebraic unknowns solved inside the model (hydroservo.system.implicit), against closed forms."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from hydroservo import System
from hydroservo.components.base import Algebraic, Component, Output, Param, Port, State
from hydroservo.errors import ModelError, SolverError
from hydroservo.system.implicit import TOLERANCE


class CubicDecay(Component):
    """dx/dt = -k z with z + z^3 = x + x^3 (so z = x, the only real root): x = x0 exp(-k t)."""

    PARAMETERS = {"k": Param(2.0, "1/s", "rate"), "x0": Param(1.0, "", "initial value")}
    STATES = {"x": State("", "the state", initial="x0")}
    ALGEBRAIC = {"z": Algebraic("", "the implicit unknown", nominal=1.0)}
    OUTPUTS = {"y": Output("", "twice the unknown")}

    def __init__(self, name: str, guess: str = "zero", **values: Any) -> None:
        self.guess = guess
        super().__init__(name, **values)

    def output_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"y": 2 * x["z"]}

    def state_equations(self, t, x, u, p, y):  # type: ignore[no-untyped-def]
        return {"x": -p["k"] * x["z"]}

    def residual_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": x["z"] + x["z"] ** 3 - (x["x"] + x["x"] ** 3)}

    def guess_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": {"zero": 0.0, "state": x["x"], "self": x["z"]}[self.guess]}

    def structure_key(self) -> tuple[Any, ...]:
        return (self.guess,)


class Hopeless(Component):
    """z^2 + c + x^2 = 0 has no real root for c > 0."""

    PARAMETERS = {"c": Param(1.0, "", "constant")}
    STATES = {"x": State("", "a state", initial=0.5)}
    ALGEBRAIC = {"z": Algebraic("", "an unknown with no solution")}

    def state_equations(self, t, x, u, p, y):  # type: ignore[no-untyped-def]
        return {"x": -x["z"]}

    def residual_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": x["z"] ** 2 + p["c"] + x["x"] ** 2}

    def guess_equations(self, t, x, u, p):  # type: ignore[no-untyped-def]
        return {"z": 0.3}


class Follower(Component):
    """Reads another component's unknown through a signal: dw/dt = u - w."""

    STATES = {"w": State("", "follower")}
    INPUTS = {"u": Port("", "input")}

    def state_equations(self, t, x, u, p, y):  # type: ignore[no-untyped-def]
        return {"w": u["u"] - x["w"]}


@pytest.mark.parametrize("guess", ["zero", "state"])
def test_implicit_decay_matches_closed_form(guess: str) -> None:
    """x(t) = x0 exp(-k t): the unknown is solved at every right-hand side, and recorded as an output."""
    s = System("cubic")
    s.add(CubicDecay("c", guess=guess, k=2.0, x0=1.0))
    r = s.simulate(1.5, rtol=1e-10, atol=1e-12, n_points=31)
    exact = np.exp(-2.0 * r.t)
    assert np.max(np.abs(r["c.x"] - exact)) < 1e-8
    assert np.max(np.abs(r["c.z"] - exact)) < 1e-8  # the unknown itself is an output
    assert np.max(np.abs(r["c.y"] - 2 * exact)) < 1e-8


@pytest.mark.parametrize("guess", ["zero", "state"])
def test_implicit_jacobian_is_exact(guess: str) -> None:
    """d(dx/dt)/dx = -k dz/dx = -k (1 + 3x^2)/(1 + 3z^2) = -k at z = x: the implicit function theorem's,
    wherever Newton has converged from the guess."""
    s = System("cubic")
    s.add(CubicDecay("c", guess=guess, k=3.0))
    model = s.build()
    for x in (0.2, 1.0, 1.5):
        A = model.linearize(np.array([x]), s.parameter_vector())
        assert A[0, 0] == pytest.approx(-3.0, rel=1e-12)


def test_guess_too_far_is_caught() -> None:
    """From z = 0, eight Newton steps do not reach z = 3 (z + z^3 = 30): the run fails instead of drifting."""
    s = System("cubic")
    s.add(CubicDecay("c", guess="zero", x0=3.0))
    with pytest.raises(SolverError, match=r"c\.z .* not solved at t = 0 s: Newton's last correction was 0\.3"):
        s.simulate(0.1, n_points=3)


def test_unknown_feeds_other_components() -> None:
    """Another component reads the unknown through an output: w' = 2 exp(-t) - w, w(0) = 0, gives w = 2 t exp(-t)."""
    s = System("chain")
    s.add(CubicDecay("c", guess="state", k=1.0))
    s.add(Follower("f"))
    s.connect("c.y", "f.u")
    r = s.simulate(2.0, rtol=1e-10, atol=1e-12, n_points=21)
    assert np.max(np.abs(r["f.w"] - 2 * r.t * np.exp(-r.t))) < 1e-8


def test_trim_and_batch_solve_the_unknown() -> None:
    s = System("cubic")
    s.add(CubicDecay("c", guess="state", k=1.0))
    model = s.build()
    assert model.trim(s.parameter_vector())["c.x"] == pytest.approx(0.0, abs=1e-9)
    batch = s.batch({"c.x0": [0.5, 1.0, 1.5]}, 1.0, n_points=11)
    for j, x0 in enumerate((0.5, 1.0, 1.5)):
        assert batch["c.z"][j, -1] == pytest.approx(x0 * math.exp(-1.0), rel=1e-5)


def test_unsolvable_unknown_fails_naming_it() -> None:
    s = System("hopeless")
    s.add(Hopeless("h"))
    with pytest.raises(SolverError, match=r"h\.z \(an unknown with no solution\) was not solved at t = 0 s"):
        s.simulate(0.1, n_points=3)
    batch = s.batch({"h.c": [1.0, -1.0]}, 0.1, n_points=3)  # the second has a root: z = sqrt(1 - x^2)
    assert list(batch.failed) == [0] and "h.z" in batch.failed[0]
    assert np.all(np.isfinite(batch["h.z"][1]))


def test_guess_must_be_explicit() -> None:
    s = System("bad guess")
    s.add(CubicDecay("c", guess="self"))
    with pytest.raises(ModelError, match="first guess of the algebraic unknown c.z depends on algebraic unknowns"):
        s.build()


def test_tolerance_is_tight() -> None:
    assert TOLERANCE <= 1e-8
