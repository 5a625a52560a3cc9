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


def _step_response(tf: c.TransferFunction, t_step: float, times: np.ndarray) -> np.ndarray:
    s = hs.System("tf", t_end=float(times[-1]))
    s.add(c.Step("u", amplitude=1.0, t_step=t_step))
    s.add(tf)
    s.connect("u.y", f"{tf.name}.u")
    return s.simulate(t_eval=times, accuracy=1e-8)[f"{tf.name}.y"]


def test_transfer_functions_step_responses_are_their_closed_forms() -> None:
    """Hopsan's filters as continuous transfer functions (the coefficients as Hopsan's .hpp set them): a
    first-order high pass s/(s + w) answers a unit step with exp(-w t); a lead-lag k (s/w_n + 1)/(s/w_d + 1)
    with k (1 + (w_d/w_n - 1) exp(-w_d t)); a second-order low pass of damping 0.5 with the textbook
    underdamped response."""
    t = np.linspace(0.0, 0.6, 61)
    tau = np.clip(t - 0.1, 0.0, None)
    after = t >= 0.1
    w = 20.0
    hp = _step_response(c.TransferFunction("hp", a0=0.0, a1=1.0 / w, b0=1.0, b1=1.0 / w), 0.1, t)
    np.testing.assert_allclose(hp, np.where(after, np.exp(-w * tau), 0.0), atol=1e-6)
    k, wn, wd = 2.0, 5.0, 30.0
    ll = _step_response(c.TransferFunction("ll", a0=k, a1=k / wn, b0=1.0, b1=1.0 / wd), 0.1, t)
    np.testing.assert_allclose(ll, np.where(after, k * (1 + (wd / wn - 1) * np.exp(-wd * tau)), 0.0), atol=1e-5)
    d = 0.5
    lp2 = c.TransferFunction("lp2", order="2", a0=1.0, a1=0.0, b0=1.0, b1=2 * d / w, b2=1.0 / w**2)
    wdamp = w * np.sqrt(1 - d * d)
    closed = 1 - np.exp(-d * w * tau) * (np.cos(wdamp * tau) + d / np.sqrt(1 - d * d) * np.sin(wdamp * tau))
    np.testing.assert_allclose(_step_response(lp2, 0.1, t), np.where(after, closed, 0.0), atol=1e-5)


def test_a_second_order_transfer_function_with_a_direct_part_and_a_start_value() -> None:
    """G = (2 s^2 + 3 s + 4)/(s^2 + 5 s + 6) from y(0) = 0.5 at rest: the step response is d u + x1 with the
    partial fractions of (G - 2)/s = (-7 s - 8)/(s (s + 2)(s + 3)), -4/3 s^-1 - 3 (s + 2)^-1 + 13/3 (s + 3)^-1, and the free response of x1 from 0.5 with
    zero rate, 0.5 (3 e^{-2t} - 2 e^{-3t})."""
    t = np.linspace(0.0, 3.0, 31)
    tf = c.TransferFunction("g", order="2", a2=2.0, a1=3.0, a0=4.0, b2=1.0, b1=5.0, b0=6.0, y0=0.5)
    y = _step_response(tf, 0.0, t)
    forced = 2.0 - 4.0 / 3.0 - 3.0 * np.exp(-2 * t) + (13.0 / 3.0) * np.exp(-3 * t)
    free = 0.5 * (3 * np.exp(-2 * t) - 2 * np.exp(-3 * t))
    np.testing.assert_allclose(y, forced + free, atol=1e-6)


def test_a_transfer_function_refuses_coefficients_its_order_cannot_have() -> None:
    s = hs.System("tf")
    s.add(c.TransferFunction("g", a2=1.0))
    with pytest.raises(ParameterError, match=r"g: a2 = 1, b2 = 0 with order = '1'"):
        s.simulate()
    s.replace(c.TransferFunction("g", order="2"))
    with pytest.raises(ParameterError, match=r"g.b2 = 0"):
        s.simulate()
    assert list(c.TransferFunction("g", order="2").STATES) == ["x1", "x2"]


def test_a_selector_routes_the_input_its_route_chooses() -> None:
    s = hs.System("route", t_end=3.5)
    s.add(c.Staircase("stairs", height=1.0, width=1.0))
    for i in (1, 2, 3, 4):
        s.add(c.Constant(f"c{i}", value=10.0 * i))
    s.add(c.Selector("sel"))
    s.add(c.Selector("dual", limit12=1.5, limit23=1e300, limit34=1e300))
    for name in ("sel", "dual"):
        s.connect("stairs.y", f"{name}.route")
        for i in (1, 2, 3, 4):
            s.connect(f"c{i}.y", f"{name}.u{i}")
    r = s.simulate(t_eval=[0.5, 1.5, 2.5, 3.5])
    np.testing.assert_allclose(r["sel.y"], [10, 20, 30, 40])
    np.testing.assert_allclose(r["dual.y"], [10, 10, 20, 20])


def test_each_function_is_its_closed_form_and_flags_its_domain() -> None:
    """Function against NumPy's functions on a ramp from -2 to 2; outside a domain Hopsan's values (sqrt and log
    of what is not positive: 0; asin and acos clamped at +-1) with error = 1; sign is 1 at 0, as Hopsan's."""
    t = np.array([0.0, 0.5, 1.0, 1.5, 2.0, 2.2, 2.5, 3.0, 3.5, 4.0])
    u = t - 2.0
    h = np.clip(u, 0.0, 1.0)
    expected = {
        "sqrt": (np.sqrt(np.clip(u, 0, None)), u < 0),
        "exp": (np.exp(u), 0 * u),
        "log": (np.log(np.where(u > 0, u, 1.0)), u <= 0),
        "log10": (np.log10(np.where(u > 0, u, 1.0)), u <= 0),
        "sin": (np.sin(u), 0 * u),
        "cos": (np.cos(u), 0 * u),
        "tan": (np.tan(u), 0 * u),
        "asin": (np.arcsin(np.clip(u, -1, 1)), np.abs(u) > 1),
        "acos": (np.arccos(np.clip(u, -1, 1)), np.abs(u) > 1),
        "atan": (np.arctan(u), 0 * u),
        "atan2": (np.arctan2(u, -1.0), 0 * u),
        "sinh": (np.sinh(u), 0 * u),
        "cosh": (np.cosh(u), 0 * u),
        "tanh": (np.tanh(u), 0 * u),
        "square": (u * u, 0 * u),
        "sign": (np.where(u >= 0, 1.0, -1.0), 0 * u),
        "floor": (np.floor(u), 0 * u),
        "ceil": (np.ceil(u), 0 * u),
        "round": (np.sign(u) * np.floor(np.abs(u) + 0.5), 0 * u),  # half away from zero
        "greater": ((u > 1.0).astype(float), 0 * u),  # u2 unconnected: 1
        "smaller": ((u < 1.0).astype(float), 0 * u),
        "and": ((u > 0.5).astype(float), 0 * u),
        "or": (np.ones_like(u), 0 * u),
        "xor": ((u <= 0.5).astype(float), 0 * u),  # u2 unconnected: 1, on
        "not": ((u <= 0.5).astype(float), 0 * u),
        "max": (np.maximum(u, 1.0), 0 * u),
        "min": (np.minimum(u, 1.0), 0 * u),
        # a round port of diameter 1 (u2 unconnected), radius 0.5, uncovered by h: the textbook segment
        # r^2 acos((r - h)/r) - (r - h) sqrt(2 r h - h^2), and its chord
        "round_port_area": (0.25 * np.arccos((0.5 - h) / 0.5) - (0.5 - h) * np.sqrt(h - h * h), 0 * u),
        "round_port_width": (2.0 * np.sqrt(h * (1.0 - h)), 0 * u),
    }
    assert set(expected) == set(c.Function.OPTIONS["function"].choices)
    s = hs.System("functions", t_end=4.0)
    s.add(c.Ramp("r", offset=-2.0, slope=1.0))
    s.add(c.Constant("x", value=-1.0))
    for f in expected:
        s.add(c.Function(f"f_{f}", function=f))
        s.connect("r.y", f"f_{f}.u")
    s.connect("x.y", "f_atan2.u2")
    r = s.simulate(t_eval=t)
    for f, (y, error) in expected.items():
        np.testing.assert_allclose(r[f"f_{f}.y"], y, atol=1e-12, err_msg=f)
        np.testing.assert_array_equal(r[f"f_{f}.error"], np.asarray(error, dtype=float), err_msg=f)


def test_a_round_port_of_no_diameter_is_closed_and_flagged() -> None:
    """The round port's area and width are 0 with error = 1 for a diameter of 0 or less (Hopsan divides by it),
    and its switches sit at the port's edges u = 0 and u = u2."""
    s = hs.System("ports", t_end=1.0)
    s.add(c.Ramp("r", offset=-0.5, slope=1.0))
    s.add(c.Constant("d", value=0.0))
    s.add(c.Constant("neg", value=-0.2))
    for name, d in (("a0", "d"), ("w0", "d"), ("an", "neg")):
        s.add(c.Function(name, function="round_port_width" if name.startswith("w") else "round_port_area"))
        s.connect("r.y", f"{name}.u")
        s.connect(f"{d}.y", f"{name}.u2")
    r = s.simulate(t_eval=[0.0, 0.5, 1.0])
    for name in ("a0", "w0", "an"):
        np.testing.assert_array_equal(r[f"{name}.y"], [0.0, 0.0, 0.0], err_msg=name)
        np.testing.assert_array_equal(r[f"{name}.error"], [1.0, 1.0, 1.0], err_msg=name)
    f = c.Function("f", function="round_port_area")
    switches = f.switch_equations(0.0, {}, {"u": 0.3, "u2": 0.1}, {}, {})
    assert {k: v[0] for k, v in switches.items()} == pytest.approx({"closed": 0.3, "open": 0.2})


def test_a_dead_zone_subtracts_its_edges_outside_and_is_zero_inside() -> None:
    s = hs.System("dead zone", t_end=4.0)
    s.add(c.Ramp("r", offset=-2.0, slope=1.0))
    s.add(c.DeadZone("dz", u_dstart=-0.5, u_dend=1.0))
    s.connect("r.y", "dz.u")
    t = np.linspace(0.0, 4.0, 9)
    u = t - 2.0
    r = s.simulate(t_eval=t)
    np.testing.assert_allclose(r["dz.y"], np.where(u < -0.5, u + 0.5, np.where(u > 1.0, u - 1.0, 0.0)), atol=1e-12)
    with pytest.raises(ParameterError, match="u_dstart = 1: expected at most u_dend = 0"):
        c.DeadZone("bad", u_dstart=1.0, u_dend=0.0).check()


def test_a_rate_limiter_ramps_at_its_limits_and_follows_a_slow_input() -> None:
    """A unit step at 0.5 s is reached at the rising limit (1/s, so at 1.5 s), the step back at 2 s at the falling
    limit (2/s, back at 0 by 2.5 s); a sine slower than the limits (amplitude 0.1 at 1 Hz: 0.63/s) is followed
    within tau times its rate."""
    s = hs.System("rate limiter", t_end=4.0)
    s.add(c.Pulse("p", amplitude=1.0, t_start=0.5, duration=1.5))
    s.add(c.RateLimiter("rl", c_up=1.0, c_down=-2.0))
    s.add(c.Sine("slow", amplitude=0.1, frequency=1.0))
    s.add(c.RateLimiter("follow", c_up=1.0, c_down=-1.0))
    s.connect("p.y", "rl.u")
    s.connect("slow.y", "follow.u")
    t = np.array([0.5, 1.0, 1.4, 1.6, 2.0, 2.25, 2.6, 3.3])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    expected = np.array([0.0, 0.5, 0.9, 1.0, 1.0, 0.5, 0.0, 0.0])
    np.testing.assert_allclose(r["rl.y"], expected, atol=1e-5)
    np.testing.assert_allclose(r["follow.y"], 0.1 * np.sin(2 * np.pi * t), atol=1e-5)


def _pid_on_unit_step(**pid: object) -> hs.Result:
    s = hs.System("pid", t_end=3.0)
    s.add(c.Step("r", amplitude=1.0, t_step=0.0))
    s.add(c.Constant("d", value=0.5))
    s.add(c.PID("p", **pid))
    s.connect("r.y", "p.e")
    if pid.get("derivative") == "input":
        s.connect("d.y", "p.de")
    return s.simulate(t_eval=[0.0, 0.25, 0.5, 1.0, 2.0, 3.0], accuracy=1e-8)


def test_pid_tracking_anti_windup_pulls_the_integral_back_with_t_t() -> None:
    """anti_windup = tracking (Hopsan's SignalPID2): v = 2 + I rises at Ki e = 1/s to the tracked limit 2.5
    (t = 0.5 s), then Ki I' = 1 + (2.5 - v)/T_t, so I -> 1 as 1 - 0.5 exp(-(t - 0.5)/T_t); the output is not
    clamped to the tracked limits, only to lower/upper (here 2.9)."""
    r = _pid_on_unit_step(Kp=2.0, Ki=1.0, anti_windup="tracking", T_t=0.5, track_upper=2.5, upper=2.9)
    t = r.t
    integral = np.where(t < 0.5, t, 1.0 - 0.5 * np.exp(-(t - 0.5) / 0.5))
    np.testing.assert_allclose(r["p.I"], integral, atol=1e-6)
    np.testing.assert_allclose(r["p.y"], np.minimum(2.0 + integral, 2.9), atol=1e-6)
    with pytest.raises(ParameterError, match="tracking needs Ki > 0"):
        _pid_on_unit_step(Kp=1.0, Ki=0.0, anti_windup="tracking")


def test_pid_clamping_stops_integrating_at_the_limit_and_takes_its_derivative_as_an_input() -> None:
    """anti_windup = clamping (Hopsan's SignalPID): v = 2 e + I + Kd de = 2.5 + I reaches upper = 3 at t = 0.5 s
    and the integral stops there; with derivative = input the derivative is de (no filter state)."""
    r = _pid_on_unit_step(Kp=2.0, Ki=1.0, Kd=1.0, anti_windup="clamping", derivative="input", upper=3.0)
    np.testing.assert_allclose(r["p.I"], np.minimum(r.t, 0.5), atol=1e-6)
    np.testing.assert_allclose(r["p.y"], np.minimum(2.5 + r.t, 3.0), atol=1e-6)
    assert set(c.PID("q", derivative="input").STATES) == {"I"}
    assert set(c.PID("q").STATES) == {"I", "e_f"} and "de" not in c.PID("q").INPUTS


def test_floor_ceil_round_comparisons_and_logic_are_hopsans() -> None:
    """Function's floor, ceil, round (half away from zero, as C's round), greater and smaller (1 or 0, strict),
    and and or (of u > 0.5 and u2 > 0.5), xor (one of them, not both), not (u <= 0.5), max and min, on a ramp
    from -2 to 2 against a constant 0.5."""
    s = hs.System("fn", t_end=4.0)
    s.add(c.Ramp("u", offset=-2.0, slope=1.0, t_start=0.0))
    s.add(c.Constant("k", value=0.5))
    for f in ("floor", "ceil", "round", "greater", "smaller", "and", "or", "xor", "not", "max", "min"):
        s.add(c.Function(f"f_{f}", function=f))  # "and", "or", "not" are keywords: no names
        s.connect("u.y", f"f_{f}.u")
        if f in ("greater", "smaller", "and", "or", "xor", "max", "min"):
            s.connect("k.y", f"f_{f}.u2")
    t = np.array([0.0, 0.3, 1.5, 1.75, 2.25, 2.5, 3.2, 3.5, 4.0])
    r = s.simulate(t_eval=t)
    u = t - 2.0
    np.testing.assert_array_equal(r["f_floor.y"], np.floor(u))
    np.testing.assert_array_equal(r["f_ceil.y"], np.ceil(u))
    np.testing.assert_array_equal(r["f_round.y"], np.sign(u) * np.floor(np.abs(u) + 0.5))
    np.testing.assert_array_equal(r["f_greater.y"], (u > 0.5).astype(float))
    np.testing.assert_array_equal(r["f_smaller.y"], (u < 0.5).astype(float))
    np.testing.assert_array_equal(r["f_and.y"], np.zeros_like(u))  # the constant 0.5 is not > 0.5: off
    np.testing.assert_array_equal(r["f_or.y"], (u > 0.5).astype(float))
    np.testing.assert_array_equal(r["f_xor.y"], (u > 0.5).astype(float))  # 0.5 is off: xor is u's
    np.testing.assert_array_equal(r["f_not.y"], (u <= 0.5).astype(float))
    np.testing.assert_array_equal(r["f_max.y"], np.maximum(u, 0.5))
    np.testing.assert_array_equal(r["f_min.y"], np.minimum(u, 0.5))


def test_latch_sets_resets_and_holds() -> None:
    """Latch (Hopsan's SignalSRlatch): set at 1 s, held after the set ends at 2 s, reset at 3 s (set again at
    3.5 s while reset: both on resets), held at 0 after 4 s; notQ = 1 - Q; Q follows within a few tau."""
    s = hs.System("latch", t_end=5.0)
    s.add(c.Pulse("set1", t_start=1.0, duration=1.0))
    s.add(c.Pulse("set2", t_start=3.5, duration=1.0))
    s.add(c.Sum("set", gain1=1.0, gain2=1.0))
    s.add(c.Pulse("reset", t_start=3.0, duration=1.0))
    s.add(c.Latch("l"))
    s.connect("set1.y", "set.u1")
    s.connect("set2.y", "set.u2")
    s.connect("set.y", "l.set")
    s.connect("reset.y", "l.reset")
    r = s.simulate(t_eval=[0.5, 1.5, 2.5, 3.25, 3.75, 4.25, 4.75])
    np.testing.assert_allclose(r["l.Q"], [0, 1, 1, 0, 0, 1, 1], atol=1e-9)
    np.testing.assert_allclose(r["l.notQ"], 1 - r["l.Q"])


def test_counter_counts_the_crossings_of_one_half_in_the_directions_asked() -> None:
    """Counter (Hopsan's SignalCounter) of sin(2 pi t), which crosses 0.5 upwards at k + 1/12 s and downwards at
    k + 5/12 s: the rising, falling and both counts at times between the edges; an input on from the start counts
    one rising edge, as Hopsan's (its previous value starts false)."""
    s = hs.System("counter", t_end=2.2)
    s.add(c.Sine("u", amplitude=1.0, frequency=1.0))
    s.add(c.Constant("on", value=1.0))
    for edges in ("both", "rising", "falling"):
        s.add(c.Counter(edges, edges=edges))
        s.connect("u.y", f"{edges}.u")
    s.add(c.Counter("start", edges="rising"))
    s.connect("on.y", "start.u")
    t = np.array([0.0, 0.05, 0.2, 0.5, 1.0, 1.2, 1.5, 2.0, 2.2])
    r = s.simulate(t_eval=t)
    rising = np.floor(t - 1 / 12) + 1
    falling = np.floor(t - 5 / 12) + 1
    np.testing.assert_allclose(r["rising.y"], rising, atol=1e-6)
    np.testing.assert_allclose(r["falling.y"], falling, atol=1e-6)
    np.testing.assert_allclose(r["both.y"], rising + falling, atol=1e-6)
    np.testing.assert_allclose(r["start.y"], (t > 0).astype(float), atol=1e-6)  # counted within a few tau


def test_hysteresis_is_the_play_operator_of_its_input() -> None:
    """Hysteresis (Hopsan's SignalHysteresis) of width 1 on a triangle 0 -> 2 -> 0: the output stays at 0 until
    the input is 0.5 ahead, follows at u - 0.5 up to 1.5, holds there while the input falls back through the band
    (to 1 at t = 3 s), then follows at u + 0.5; within the 1 us tracking lag."""
    s = hs.System("play", t_end=4.0)
    s.add(c.Ramp("up", slope=1.0, limit=2.0))
    s.add(c.Ramp("down", slope=-1.0, t_start=2.0, limit=2.0))
    s.add(c.Sum("u", gain1=1.0, gain2=1.0))
    s.add(c.Hysteresis("h", band=1.0))
    s.connect("up.y", "u.u1")
    s.connect("down.y", "u.u2")
    s.connect("u.y", "h.u")
    r = s.simulate(t_eval=[0.0, 0.25, 1.0, 2.0, 2.5, 3.0, 3.5, 4.0])
    np.testing.assert_allclose(r["h.y"], [0.0, 0.0, 0.5, 1.5, 1.5, 1.5, 1.0, 0.5], atol=1e-5)
