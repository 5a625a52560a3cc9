"""Edges of circuits built from ports, found in review: round trips, renamed states, units, ratings."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.errors import ModelError, ParameterError
from hydroservo.io.model_file import model_to_toml, system_from_dict
from hydroservo.units import coherent_unit


def round_trip(s: System) -> System:
    return system_from_dict(tomllib.loads(model_to_toml(s)))


def test_a_line_of_fixed_segments_and_a_transducer_between_volts_read_back():
    s = System("s")
    s.add(c.Line("ln", segments=4, ends="flow"))
    s.add(c.Transducer("iso", unit="V", input_unit="V"))
    s.add(c.Step("vin", unit="V"))
    s.add(c.ConstantPressure("a"))
    s.add(c.Tank("b"))
    s.connect("a.P", "ln.A")
    s.connect("ln.B", "b.P")
    s.connect("vin.y", "iso.u")
    back = round_trip(s)
    assert back["ln"].segments == 4 and back["iso"].input_unit == "V"
    assert back.parameter_values() == s.parameter_values()


def test_initial_conditions_of_states_that_are_gone_are_refused():
    s = System("s")
    s.add(c.Cylinder("cyl"))
    s.add(c.ConstantPressure("sup"))
    s.add(c.Mass("load", incline=0.0))
    s.set_initial("cyl.pA", "50 bar")
    s.set("cyl.pressure_floor", "cavity")  # the chamber's state is now pA_state
    with pytest.raises(ModelError, match=r"initial condition 'cyl.pA': 'cyl' has no state 'pA'.*pA_state"):
        s.build()


def test_a_lines_first_pressure_state_is_not_hidden_by_a_parameter():
    s = System("s", t_end=0.05)
    s.add(c.Line("ln", ends="flow-pressure", l=2.0, p_init="20 bar"))
    s.add(c.ConstantPressure("src", p="20 bar"))
    s.connect("src.P", "ln.A")
    s.alias("first", "ln.p0", "Pa")
    r = s.simulate()
    np.testing.assert_array_equal(r["first"], r["ln.p0"])
    with pytest.warns(Warning, match="now called 'p_init'"):
        c.Line("old", p0="5 bar")


def test_a_pump_dead_headed_far_beyond_its_rating_is_flagged():
    s = System("dead-head", t_end=1.0)
    s.add(c.Tank("t"))
    s.add(c.Pump("pump", p_rated="250 bar"))
    s.add(c.Volume("v", V="1 L"))
    s.connect("t.P", "pump.S")
    s.connect("pump.P", "v.P")
    with pytest.warns(Warning, match=r"v.p = .* more than 50% above the highest source pressure \(pump.p_rated = 25 MPa"):
        s.simulate()


def test_units_with_a_percent_and_absolute_pressures_as_signal_units():
    assert coherent_unit("%/s") == "second^-1" and c.Step("s", unit="%/s", amplitude="10 %/s").values["amplitude"] == pytest.approx(0.1)
    with pytest.raises(ParameterError, match="an absolute pressure is a value, not a signal's unit"):
        c.Step("s", unit="bar_abs")
    with pytest.raises(ParameterError, match="input_unit = 'bar_abs'"):
        c.Transducer("pt", input_unit="bar_abs", G="0.04 V/bar")


def test_a_pressure_control_valve_needs_a_transition_above_zero():
    with pytest.raises(ParameterError, match="relief.p_tr"):
        c.ReliefValve("relief", p_tr=0.0)


def test_a_stroke_given_for_one_run_is_both_even_if_both_are_set_on_the_components():
    s = System("s")
    s.add(c.Step("u", amplitude=1.0))
    s.add(c.SpoolFirstOrder("spool", xv_max="1 mm"))
    s.add(c.FourWayValve("valve", xv_max="1 mm"))
    s.add(c.ConstantPressure("sup"))
    s.add(c.Tank("t"))
    s.add(c.Volume("a"))
    s.add(c.Volume("b"))
    for link in (("u.y", "spool.u"), ("spool.xv", "valve.xv"), ("sup.P", "valve.P"), ("valve.T", "t.P"), ("valve.A", "a.P"), ("valve.B", "b.P")):
        s.connect(*link)
    values = dict(zip(s.build().parameter_names, s.parameter_vector({"spool.xv_max": "2 mm"}), strict=True))
    assert values["valve.xv_max"] == values["spool.xv_max"] == 2e-3
