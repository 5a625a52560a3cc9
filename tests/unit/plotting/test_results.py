"""How a result's plot names its panels and curves: one dimension per axis, labels that fit beside it."""

from __future__ import annotations

from hydroservo.plotting import axis_label as _axis_label
from hydroservo.plotting import by_dimension
from hydroservo.plotting import curve_label as _curve_label


def test_a_panel_of_pressures_and_flows_becomes_a_panel_each() -> None:
    """A Hopsan scope may hold pressures and flows: one axis of one unit each, in the order they first appear, a
    panel repeated drawn once."""
    units = {"p1": "Pa_abs", "q1": "m^3/s", "p2": "bar", "x": "m"}
    assert by_dimension([["p1", "q1", "p2"], ["x"], ["p1", "p2"]], units) == [["p1", "p2"], ["q1"], ["x"]]


def test_an_axis_is_labelled_by_its_names_or_by_what_they_measure() -> None:
    assert _axis_label(["cyl.pA", "cyl.pB"], {}, "MPa") == "cyl.pA, cyl.pB [MPa]"
    assert _axis_label(["Pressure_Transducer.out.Value"], {}, "Pa_abs") == "pressure [Pa_abs]"
    assert _axis_label(["Cylinder_block.P2.AngularVelocity"], {}, "rad/s") == "speed [rad/s]"
    # the quantity of the unit the signals are drawn in, shown as it is printed
    assert _axis_label(["Torque_Transducer.out.Value", "Torque_Transducer_1.out.Value"], {}, "m·N", "N*m") == (
        "torque [m·N]")
    assert _axis_label(["Centrifugal_Pump_J.Pin.Value"], {}, "W", "W") == "power [W]"
    assert _axis_label(["Calculation.lp1.out.Value", "Calculation.lp2.out.Value"], {}, "-") == "2 signals [-]"
    assert _axis_label(["Calculation_of_efficiencies.lp1.out.Value"], {}, "-") == "signal [-]"


def test_a_curve_is_not_labelled_by_a_description_that_only_spells_its_name_again() -> None:
    assert _curve_label("Mass.P2.Position", {"Mass.P2.Position": "Hopsan's Mass#P2#Position"}) == "Mass.P2.Position"
    assert _curve_label("cyl.pA", {"cyl.pA": "pressure, side A"}) == "cyl.pA: pressure, side A"
    assert _curve_label("cyl.pA", {}) == "cyl.pA"
