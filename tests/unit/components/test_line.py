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


def lowest_mode(s: System) -> complex:
    """The eigenvalue of the lowest oscillating mode."""
    model = s.build()
    p = s.parameter_vector()
    eig = np.linalg.eigvals(model.linearize(model.initial_state(p), p))
    eig = eig[np.abs(eig.imag) > 1e-6]
    return complex(eig[np.argmin(np.abs(eig.imag))])


def test_a_lossless_line_of_impedance_and_delay_is_the_ladder_of_c_and_l_they_give():
    # Z_c = sqrt(L/C), T = sqrt(L C): a line closed at one end and held at the other resonates at 1/(4T), undamped
    s = System("quarter")
    s.add(c.LosslessLine("line", ends="flow-pressure", segments=19, Z_c=2e9, deltat=0.02, f_max=10.0,
                           p_init="10 bar"))
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("src.P", "line.A")
    mode = lowest_mode(s)
    assert abs(mode.imag) / (2 * np.pi) == pytest.approx(1.0 / (4 * 0.02), rel=5e-4)
    assert mode.real == pytest.approx(0.0, abs=1e-9)
    line = c.LosslessLine("l", segments="auto", deltat=0.02, f_max=100.0)
    assert line.segments == 20 and "w0" not in line.STATES  # n >= 10 f_max T ([Efe2014] eq. 3.30 per segment)
    with pytest.raises(ParameterError, match="a line of delay 1 s needs 1000 segments"):
        c.LosslessLine("l", segments="auto", deltat=1.0, f_max=100.0)


def test_a_lossless_line_fed_a_flow_answers_with_its_impedance_until_the_wave_returns():
    # flow q into end A, end B held: p_A = p_0 + Z_c q until the wave comes back inverted at 2T
    s = System("impedance", t_end=0.03)
    s.add(c.FlowSource("q", q=1e-5))
    s.add(c.LosslessLine("line", segments=60, Z_c=1e9, deltat=0.01, p_init="10 bar"))
    s.add(c.LaminarOrifice("o", G_lam=1e-3))
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("q.P", "line.A")
    s.connect("line.B", "o.A")
    s.connect("o.B", "src.P")
    t = np.linspace(0.0, 0.03, 601)
    p = s.simulate(t_eval=t)["line.pA"] - 10e5
    assert np.mean(p[(t > 0.005) & (t < 0.015)]) == pytest.approx(1e9 * 1e-5, rel=0.01)
    assert np.mean(p[(t > 0.025) & (t < 0.03)]) == pytest.approx(-1e9 * 1e-5, rel=0.02)


def test_a_viscous_wall_damps_the_waves_as_its_bypassed_resistance_and_leaves_the_steady_drop():
    # the lowest mode of a frictionless line with a viscous wall decays at Re(Z_w(jw))/(2 L), Z_w = R_w s tau/(1 +
    # s tau), tau = 2 L/R_w (small damping: the mode's own frequency w)
    length, d, rho, beta, eta_w = 10.0, 0.02, 870.0, 1e9, 0.01
    s = System("wall")
    s.add(c.Line("line", ends="flow-pressure", segments=19, l=length, d=d, rho=rho, beta_e=beta, nu=1e-12,
                 wall="viscous", eta_w=eta_w, p_init="10 bar", f_max=10.0))
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("src.P", "line.A")
    area = np.pi * d**2 / 4
    inertance, r_w = rho * length / area, 128 * eta_w * length / (np.pi * d**4)
    w = 2 * np.pi * np.sqrt(beta / rho) / (4 * length)
    tau = 2 * inertance / r_w
    mode = lowest_mode(s)
    assert -mode.real == pytest.approx(r_w * (w * tau) ** 2 / (1 + (w * tau) ** 2) / (2 * inertance), rel=0.01)
    assert {"w0", "w18"} <= set(s["line"].STATES) and "w19" not in s["line"].STATES  # one per oil column
    # a flow ramped at a, through a line held at its end: once the waves have died out, the drop is R q + L a + 2 L a,
    # the wall's resistance passing the flow's slow part through its bypass inertance 2 L (a steady flow: no drop)
    s = System("ramp", t_end=3.0)
    s.add(c.Ramp("r", unit="m^3/s", slope=1e-3))
    s.add(c.FlowSource("q", q=0.0))
    s.add(c.Line("line", segments=5, l=10.0, d=0.02, nu=1e-6, wall="viscous", eta_w=0.1, p_init="10 bar", f_max=10.0))
    s.add(c.LaminarOrifice("o", G_lam=1e-3))
    s.add(c.ConstantPressure("src", p="10 bar"))
    s.connect("r.y", "q.u")
    s.connect("q.P", "line.A")
    s.connect("line.B", "o.A")
    s.connect("o.B", "src.P")
    r = s.simulate(t_eval=[0.0, 3.0], method="cvodes")
    inertance, R = 870.0 * 10.0 / (np.pi * 0.02**2 / 4), 128 * 870.0 * 1e-6 * 10.0 / (np.pi * 0.02**4)
    assert r["line.pA"][-1] - r["line.pB"][-1] == pytest.approx(R * 3e-3 + 3 * inertance * 1e-3, rel=2e-3)


@pytest.mark.parametrize(("dp", "turbulent"), [(0.5e5, False), (20e5, True)])
def test_friction_turns_from_hagen_poiseuille_to_blasius_above_a_reynolds_number_of_2300(dp, turbulent):
    # steady flow through a line between two pressures: dp = R q below Re 2300, dp = k q^1.75 (Blasius) above
    d, length, rho, nu = 0.004, 2.0, 870.0, 10e-6
    s = System("friction", t_end=1.0)
    s.add(c.ConstantPressure("a", p=f"{10e5 + dp} Pa"))
    s.add(c.Tank("b", p="10 bar"))
    s.add(c.Line("line", ends="flow", segments=3, l=length, d=d, nu=nu, rho=rho, friction="laminar-blasius",
                 p_init="10 bar", f_max=10.0))
    s.connect("a.P", "line.A")
    s.connect("line.B", "b.P")
    q = s.simulate(t_eval=[0.0, 1.0], method="cvodes")["line.QA"][-1]
    mu = rho * nu
    k = 32 * rho * 0.079 * (4 * rho / (np.pi * d * mu)) ** -0.25 * length / (np.pi**2 * d**5)
    expected = (dp / k) ** (1 / 1.75) if turbulent else dp * np.pi * d**4 / (128 * mu * length)
    assert q == pytest.approx(expected, rel=1e-5)
    assert (4 * rho * q / (np.pi * d * mu) > 2300) == turbulent
