"""Control blocks (hydroservo.components.control): amplifier, gain, saturation, PID, lag."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c
from hydroservo.errors import ModelError, ParameterError


def test_amplifier_saturation_gain_lag_pid() -> None:
    s = hs.System("chain", t_end=1.0)
    s.add(c.Step("e", unit="V", amplitude="3 V"))
    s.add(c.Amplifier("amp", G_a=2.0, R="100 ohm", I_max="50 mA"))
    s.add(c.Gain("gain", K=0.5))
    s.add(c.Saturation("sat", lower=-1.0, upper=1.0))
    s.add(c.PID("pid", Kp=2.0, Ki=4.0, upper=20.0))
    s.add(c.Lag("lag", K=2.0, tau="0.1 s"))
    s.connect("e.y", "amp.E", "gain.u", "pid.e", "lag.u")
    s.add(c.Lag("sink", tau=1.0))
    s.connect("gain.y", "sat.u")
    s.connect("sat.y", "sink.u")
    r = s.simulate(t_eval=[0.0, 0.5, 1.0, 2.0, 3.0], rtol=1e-10, atol=1e-12)
    assert r["amp.i"][-1] == pytest.approx(0.05)  # 2 * 3 V / 100 ohm = 60 mA, limited to 50 mA
    assert r["gain.y"][-1] == pytest.approx(1.5)
    assert r["sat.y"][-1] == pytest.approx(1.0)
    assert r["pid.y"][1] == pytest.approx(2 * 3 + 4 * 3 * 0.5, rel=1e-6)  # P + I at 0.5 s
    assert r["pid.y"][-1] == pytest.approx(20.0)  # clamped
    # anti-windup: the integral stops where 2 * 3 + 4 * I reaches 20, I = 3.5
    np.testing.assert_allclose(r["pid.I"][-2:], 3.5, rtol=1e-6)
    assert r["lag.y"][1] == pytest.approx(6.0 * (1 - np.exp(-5.0)), rel=1e-7)


def test_a_signal_in_millimetres_is_carried_in_metres_like_every_signal():
    # was: a Step in mm passed 0.2 into a block in m (same dimension, a factor 1000 off)
    s = hs.System("mm", t_end=0.01)
    s.add(c.Step("cmd", unit="mm", amplitude="0.2 mm"))
    s.add(c.Gain("g", unit="m"))
    s.connect("cmd.y", "g.u")
    r = s.simulate()
    assert r["g.y"][-1] == pytest.approx(2e-4) and r.units["cmd.y"] == "m"
    assert s["cmd"].unit == "mm"  # the model file keeps the unit the user wrote


def test_a_gain_between_two_units_is_checked_in_both():
    g = c.Gain("k", unit="V", input_unit="mm", K="20 V/mm")
    assert g.values["K"] == pytest.approx(2e4)  # V/m inside
    s = hs.System("s")
    s.add(g)
    s.add(c.Step("volts", unit="V"))
    with pytest.raises(ModelError, match=r"\[V\] -> 'k.u' \[m\]: the units have different dimensions"):
        s.connect("volts.y", "k.u")


def test_a_gain_given_a_unit_it_cannot_have_says_how_to_give_one():
    with pytest.raises(ParameterError, match=r"give both, e.g. Gain\('g', unit='V', input_unit='m', K='20 V/m'\)"):
        c.Gain("g", K="20 1/m")


def test_a_transducer_measures_any_quantity():
    s = hs.System("pt", t_end=0.01)
    s.add(c.ConstantPressure("supply", p="200 bar"))
    s.add(c.Transducer("pt", unit="mA", input_unit="bar", G="0.08 mA/bar"))  # 4-20 mA over 250 bar, less offset
    s.connect("supply.p", "pt.u")
    assert s.simulate()["pt.y"][-1] == pytest.approx(0.016)  # A
    assert c.Transducer("fb", G="-0.278 V/in").values["G"] == pytest.approx(-0.278 / 0.0254)  # V/m by default
