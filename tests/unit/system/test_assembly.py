"""Assembly of a system (hydroservo.system.assembly): algebraic loops and open inputs are reported."""

from __future__ import annotations

import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ModelError


def test_algebraic_loop_is_reported() -> None:
    s = hs.System("loop")
    s.add(c.Gain("a"))
    s.add(c.Gain("b"))
    s.add(c.Lag("lag"))
    s.connect("a.y", "b.u")
    s.connect("b.y", "a.u", "lag.u")
    with pytest.raises(ModelError, match="algebraic loop"):
        s.build()


def test_unconnected_input_is_reported() -> None:
    s = hs.System("open")
    s.add(c.Lag("lag"))
    with pytest.raises(ModelError, match="'lag.u'.*not connected"):
        s.build()


def test_an_alias_reads_the_signal_where_a_parameter_has_its_name() -> None:
    """An output and a parameter may share a name (a source's p, a pump's p_rated); an alias names signals, so
    'src.y' is the output. (Met importing Hopsan's pressure-controlled pump, whose source follows a step: the
    alias read the source's setting, not the pressure the signal drove.)"""
    from typing import Any, ClassVar

    from hydroservo import System
    from hydroservo.components.base import Component, Output, Param, Port

    class Doubler(Component):
        PARAMETERS: ClassVar = {"y": Param(1.0, "", "a setting named as the output")}
        INPUTS: ClassVar = {"u": Port("", "input", default=0.0)}
        OUTPUTS: ClassVar = {"y": Output("", "twice the setting, plus the input")}

        def output_equations(self, t: Any, x: Any, u: Any, p: Any) -> dict[str, Any]:
            return {"y": 2.0 * p["y"] + u["u"]}

    s = System("clash")
    s.add(Doubler("src", y=3.0))
    s.add(c.Step("cmd", amplitude=5.0, t_step=0.5))
    s.connect("cmd.y", "src.u")
    s.alias("reading", "src.y + 1")
    r = s.simulate(t_eval=[0.0, 1.0])
    assert list(r["reading"]) == pytest.approx([7.0, 12.0])
