"""Component parameters and ports (hydroservo.components.base): bad values and connections are named."""

from __future__ import annotations

import pytest

from hydroservo import components as c
from hydroservo.errors import ModelError, ParameterError


def test_bad_parameters_are_named(spring_mass) -> None:
    with pytest.raises(ParameterError, match=r"cyl\.A_A: '3 bar' has the wrong dimension"):
        c.Cylinder("cyl", A_A="3 bar")
    with pytest.raises(ParameterError, match=r"load\.m = '-2 kg'.*expected > 0 kg"):
        c.Mass("load", m="-2 kg")
    with pytest.raises(ParameterError, match=r"cyl\.beta.*expected > 0"):
        c.Cylinder("cyl", beta_e=-1.0)
    with pytest.raises(ParameterError, match="unknown parameter"):
        c.Mass("load", mass=3.0)
    with pytest.raises(ParameterError, match="expected one of constant, lee, eggerth"):
        c.Cylinder("cyl", bulk_modulus="magic")
    with pytest.raises(ModelError, match="has no output 'q'"):
        s = spring_mass()
        s.connect("load.q", "load.F")
    with pytest.raises(ModelError, match="different dimensions"):
        s = spring_mass()
        s.add(c.ConstantPressure("sup"))
        s.connect("sup.p", "load.F")
