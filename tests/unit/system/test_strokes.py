"""One stroke per valve: the spool that drives a valve and the valve share ``xv_max``."""

from __future__ import annotations

import tomllib

import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.io.model_file import model_to_toml, system_from_dict


def spool_valve(**spool: str) -> System:
    s = System("stroke", t_end=0.02)
    s.add(c.Step("u", amplitude=1.0))
    s.add(c.SpoolFirstOrder("spool", **spool))
    s.add(c.FourWayValve("valve"))
    s.add(c.ConstantPressure("supply"))
    s.add(c.Tank("tank"))
    s.add(c.Volume("a"))
    s.add(c.Volume("b"))
    s.connect("u.y", "spool.u")
    s.connect("spool.xv", "valve.xv")
    s.connect("supply.P", "valve.P")
    s.connect("valve.T", "tank.P")
    s.connect("valve.A", "a.P")
    s.connect("valve.B", "b.P")
    return s


def strokes(s: System, params: dict[str, str] | None = None) -> tuple[float, float]:
    values = dict(zip(s.build().parameter_names, s.parameter_vector(params), strict=True))
    return values["spool.xv_max"], values["valve.xv_max"]


def test_the_stroke_set_on_either_is_the_others():
    assert spool_valve().stroke_pairs() == [("valve.xv_max", "spool.xv_max")]
    assert strokes(spool_valve(xv_max="0.5 mm")) == (5e-4, 5e-4)
    s = spool_valve()
    s.set("valve.xv_max", "2 mm")
    assert strokes(s) == (2e-3, 2e-3)
    assert strokes(spool_valve(), {"spool.xv_max": "3 mm"}) == (3e-3, 3e-3)  # for one run too


def test_two_different_strokes_are_refused():
    s = spool_valve(xv_max="1 mm")
    s.set("valve.xv_max", "2 mm")
    with pytest.raises(ParameterError, match="the spool 'spool' drives the valve 'valve', and they have one stroke"):
        s.simulate()


def test_a_batch_varies_the_one_stroke():
    s = spool_valve()
    b = s.batch({"spool.xv_max": ["1 mm", "2 mm"]})
    assert not b.failed
    assert b.params["valve.xv_max"].tolist() == [1e-3, 2e-3]
    b = s.batch({"spool.xv_max": ["1 mm", "2 mm"], "valve.xv_max": ["1 mm", "3 mm"]})
    assert list(b.failed) == [1]


def test_a_model_file_writes_the_stroke_once():
    s = spool_valve(xv_max="0.8 mm")
    text = model_to_toml(s)
    assert "# xv_max = " in text and "the stroke of 'spool'" in text
    edited = system_from_dict(tomllib.loads(text.replace('xv_max = "0.8 mm"', 'xv_max = "1.2 mm"')))
    assert strokes(edited) == (1.2e-3, 1.2e-3)
