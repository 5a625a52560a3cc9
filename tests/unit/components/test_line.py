"""Lines: steady laminar loss, wave resonances of the lumped ladders, segments by Efe's criterion."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.components.line import LineResolutionWarning
from hydroservo.errors import ParameterError

OIL = {"rho": 870.0, "nu": 1e-6, "beta_e": 1e9, "f_max": 10.0}
C_WAVE = np.sqrt(1e9 / 870.0)  # wave speed [m/s]


def lowest_frequency(s: System) -> float:
    model = s.build()
    p = s.parameter_vector()
    eig = np.linalg.eigvals(model.linearize(model.initial_state(p), p))
    f = np.sort(np.abs(eig.imag)) / (2 * np.pi)
    return float(f[f > 1e-6][0])


def test_steady_flow_meets_hagen_poiseuille():
    s = System("drop", t_end=2.0)
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.add(c.Tank("tank", p="5 bar"))  # the start-up waves stay well above vacuum (a line does not cavitate)
    s.add(c.Line("line", ends="flow", l=5.0, d=0.004, rho=870.0, nu=46e-6, beta_e=1e9, p_init="7.5 bar"))
    s.connect("src.P", "line.A")
    s.connect("line.B", "tank.P")
    r = s.simulate()
    R = 128 * 870.0 * 46e-6 * 5.0 / (np.pi * 0.004**4)  # Hagen-Poiseuille, by hand
    assert r["line.QA"][-1] == pytest.approx(5e5 / R, rel=1e-5)
    assert r["line.QB"][-1] == pytest.approx(-5e5 / R, rel=1e-5)  # flow into the line at B: it leaves there


@pytest.mark.parametrize(("segments", "tolerance"), [(1, 0.11), (4, 0.007), (19, 0.0005)])
@pytest.mark.parametrize("ends", ["flow-pressure", "pressure-flow"])
def test_a_line_closed_at_one_end_resonates_at_a_quarter_wave(ends, segments, tolerance):
    # pressure imposed at the open end, the other closed: f = c/(4l); the ladder's error falls as 1/n^2
    s = System("quarter")
    s.add(c.Line("line", ends=ends, segments=segments, l=10.0, d=0.02, p_init="10 bar", **OIL))
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("src.P", "line.A" if ends.startswith("flow") else "line.B")
    exact = C_WAVE / 40.0
    assert lowest_frequency(s) == pytest.approx(exact, rel=tolerance)


@pytest.mark.parametrize("ends", ["flow", "pressure"])
def test_open_open_and_closed_closed_lines_resonate_at_a_half_wave(ends):
    s = System("half")
    s.add(c.Line("line", ends=ends, segments=19, l=10.0, d=0.02, p_init="10 bar", **OIL))
    if ends == "flow":
        s.add(c.ConstantPressure("a", p="10 bar"))
        s.add(c.ConstantPressure("b", p="10 bar"))
        s.connect("a.P", "line.A")
        s.connect("b.P", "line.B")
    assert lowest_frequency(s) == pytest.approx(C_WAVE / 20.0, rel=2e-3)


def test_auto_segments_meet_efes_criterion_and_follow_the_fluid():
    line = c.Line("line", segments="auto", l=10.0, **{**OIL, "f_max": 50.0})
    # c/(10 f_max) = 2.14 m per segment at most: 10 m needs 5
    assert line.segments == 5 and len(line.STATES) == 2 * 5 + 1
    s = System("s")
    line = s.add(c.Line("line", segments="auto", l=10.0, f_max=50.0))  # the oil from the circuit
    s.set_fluid("iso-vg46", "40 degC", bulk_modulus="0.5 GPa")  # soft: slower waves, more segments
    c_soft = np.sqrt(0.5e9 / line.values["rho"])
    assert line.values["beta_e"] == 0.5e9 and line.segments == int(np.ceil(10.0 / (c_soft / 500.0)))
    line.set(l="20 m")
    assert line.segments == int(np.ceil(20.0 / (c_soft / 500.0)))


def test_too_few_segments_for_f_max_warn_with_the_number_needed():
    s = System("s")
    s.add(c.Line("line", segments=2, l=10.0, **{**OIL, "f_max": 50.0}))
    with pytest.warns(LineResolutionWarning, match="use segments=5 or 'auto'"):
        s.build()


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"segments": 0}, "expected a whole number from 1 to 200"),
        ({"segments": 2.5}, "expected a whole number from 1 to 200"),
        ({"ends": "both"}, "expected one of pressure, flow, pressure-flow, flow-pressure"),
        ({"d": "-1 mm"}, "line.d"),
    ],
)
def test_bad_lines_are_refused(kwargs, message):
    with pytest.raises(ParameterError, match=message):
        c.Line("line", **kwargs)


# a valve step into 3 m lines swings them below vacuum, which the lines (no cavitation) report
@pytest.mark.filterwarnings("ignore::hydroservo.errors.ImplausibleResultWarning")
def test_the_ends_decide_which_ports_a_line_joins():
    # a valve (flow ports) to a cylinder (pressure ports) through a line with a pressure end at the valve
    s = System("valve-line-cylinder", t_end=0.2)
    s.add(c.ConstantPressure("supply", p="100 bar"))
    s.add(c.Tank("tank"))
    s.add(c.FourWayValve("valve"))
    s.add(c.Line("lineA", ends="pressure-flow", l=3.0, d=0.01, p_init="50 bar"))
    s.add(c.Line("lineB", ends="pressure-flow", l=3.0, d=0.01, p_init="50 bar"))
    s.add(c.Cylinder("cyl", k_stop=1e8, c_stop=1e5, pA0="50 bar", pB0="50 bar"))
    s.add(c.Mass("load", m=50.0, incline=0.0))
    s.add(c.Step("cmd", unit="m", amplitude="0.1 mm"))
    s.connect("cmd.y", "valve.xv")
    s.connect("supply.P", "valve.P")
    s.connect("valve.T", "tank.P")
    s.connect("valve.A", "lineA.A")
    s.connect("lineA.B", "cyl.A")
    s.connect("valve.B", "lineB.A")
    s.connect("lineB.B", "cyl.B")
    s.connect("cyl.F", "load.F")
    s.connect("load.x", "cyl.x")
    s.connect("load.v", "cyl.v")
    r = s.simulate()
    assert r["load.x"][-1] > 1e-3


def test_a_hoses_wall_softens_its_oil_and_slows_its_waves():
    oil = {k: v for k, v in OIL.items() if k != "f_max"}
    hose = c.Hose("hose", ends="flow-pressure", segments=19, l=10.0, d=0.02, p_init="10 bar", k_wall=1e-9, **oil)
    beta = 1 / (1 / 1e9 + 1e-9)  # 0.5 GPa: the wall as compliant as the oil
    s = System("hose")
    s.add(hose)
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("src.P", "hose.A")
    assert lowest_frequency(s) == pytest.approx(np.sqrt(beta / 870.0) / 40.0, rel=5e-4)
    assert c.Hose("h", segments="auto", l=10.0, f_max=50.0, k_wall=1e-9, **oil).segments == 7  # slower: more
