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
