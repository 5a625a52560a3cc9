"""The flight-simulator actuator against the figures of FlightSimulatorND: Appendix C, sections 4.2-4.4."""

from __future__ import annotations

import tomllib

import pytest

import hydroservo as hs
from hydroservo.data import model_text
from hydroservo.validation import format_checks, regressions

IN, LBF = 0.0254, 4.4482216152605  # m per inch, N per pound-force (exact by definition)


def appendix_c(component: str, name: str) -> float:
    """The number of a value of the built-in model file, which holds Appendix C as printed (in its units)."""
    text = tomllib.loads(model_text("flight-simulator"))["components"][component][name]
    return float(text.split()[0])


@pytest.fixture
def checks(validated):
    return {c.quantity: c for c in validated("flight-simulator")}


def test_appendix_c_conversions() -> None:
    s = hs.load_model("flight-simulator")
    # c_v = Cd sqrt(2/rho) w = 104.5 in^2/(lbf^0.5 s) x 2.36 in: Appendix C prints the two factors, the model file
    # holds only their product, so they are typed here to check it; 1 in^3/(s lbf^0.5) = 7.7704e-6 m^2/(s Pa^0.5)
    assert appendix_c("valve", "c_v") == pytest.approx(104.5 * 2.36, rel=1e-12)
    assert s["valve"].values["c_v"] == pytest.approx(appendix_c("valve", "c_v") * IN**3 / LBF**0.5, rel=1e-12)
    # the model's SI values are Appendix C's converted with the exact inch and pound-force
    assert s["cyl"].values["A_A"] == pytest.approx(appendix_c("cyl", "A_A") * IN**2)  # A2 = 8.29 in^2
    assert s["load"].values["m"] == pytest.approx(appendix_c("load", "m") * LBF / IN)  # M = 16.6 lbf s^2/in
    # Appendix D: P2 starts at W/A2 = 6400 lbf / 8.29 in^2 = 772 psi (pot Q14 = W/(2000 A2) = 0.386)
    r = s.simulate(t_end=0.01, n_points=2)
    assert r.get("p2", "psi")[0] == pytest.approx(appendix_c("load", "W") / appendix_c("cyl", "A_A"))


@pytest.mark.parametrize(
    "quantity",
    [
        "steady-state full-end pressure P2",
        "steady-state rod-end pressure P1",
        "spool null offset x_v",
        "actuator hydraulic natural frequency",
        "first-stage natural frequency",
        "lag of spool behind error voltage E_o, +2 V",
        "lag of spool behind error voltage E_o, -2 V",
    ],
)
def test_published_figures_reproduced(checks, quantity: str) -> None:
    # Each published value, where FlightSimulatorND prints it (eqs. 4-6, 4-7, 4-9, sections 4.2 and 4.3.1) and its
    # tolerance with the reason are the row's (hydroservo/validation/flight_simulator.py, docs/validation.md).
    c = checks[quantity]
    assert c.verdict == "reproduced", (
        f"{quantity} ({c.source}): published {c.published}, computed {c.computed}, tolerance {c.tolerance}: {c.why}"
    )


def test_figures_not_reproduced_are_reported_honestly(checks) -> None:
    # These differ from FlightSimulatorND by more than its precision (docs/validation.md explains why); the test
    # pins the direction so a change is noticed. Overshoot ratio: published 1.16 (section 4.3.3), the model gives
    # 1.56; velocity per volt: published 4.8 in/s/V (section 4.4), the model about 120 (Appendix C's gains give
    # that, see the row); largest chamber pressure: published at most 1500 psi (section 4.3.4), the model 1630.
    # The bounds 1.3 and 50 lie between the published and the computed values.
    assert checks["max. / steady-state displacement, retraction"].computed > 1.3
    assert checks["velocity per volt of error voltage, retraction"].computed > 50
    assert checks["largest chamber pressure for +-2 V steps"].verdict == "NOT reproduced"
    text = format_checks("flight-simulator", list(checks.values()))
    assert "7 reproduced, 8 not reproduced, 1 for information" in text
    assert not regressions(list(checks.values()))  # every verdict is the one docs/validation.md explains
