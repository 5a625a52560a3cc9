"""Relief, pressure-reducing and counterbalance valves against their law worked by hand."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from hydroservo import System
from hydroservo import components as c

P_NOM = 7e6


def static_K(over: float, dp: float, k_cs: float = 1e-8, k_cf: float = 1e-8) -> float:
    """Hopsan's steady opening, by hand: over/(sqrt(p_nom)/k_cs + dp/(k_cf sqrt(p_nom)))."""
    return over / (np.sqrt(P_NOM) / k_cs + max(dp, 0.0) / (k_cf * np.sqrt(P_NOM)))


def pumped(valve: c.Component, pump_flow: str = "30 L/min") -> System:
    """A pump into a 1 L volume relieved to tank by ``valve`` (A on the volume, B on tank)."""
    s = System("relief", t_end=1.0)
    s.add(c.Tank("tank"))
    s.add(c.Pump("pump", D=pump_flow.replace("L/min", "L/rev"), omega="1 rev/min"))
    s.add(c.Volume("v", V="1 L", p0="150 bar"))
    s.add(valve)
    s.connect("tank.P", "pump.S", f"{valve.name}.B")
    s.connect("pump.P", "v.P", f"{valve.name}.A")
    return s


def test_a_relief_valve_settles_on_its_static_characteristic():
    relief = c.ReliefValve("relief", p_crack="200 bar", q_nom="100 L/min", tau="5 ms")
    # tight: at 1.1 bar over the setting the flow moves 1e-5 for 1 Pa, and the default tolerance allows 20 Pa
    r = pumped(relief).simulate(accuracy=1e-7)
    p, q = r["v.p"][-1], r["relief.Q"][-1]
    assert q == pytest.approx(30 / 6e4, rel=1e-6)  # it passes the pump's flow
    # on the static characteristic Q = K(p) sqrt(dp), a little above the setting (the pressure override)
    assert q == pytest.approx(static_K(p - 200e5, p) * np.sqrt(p), rel=1e-4)
    assert 200e5 < p < 205e5
    assert r["pump.T"][-1] > 0 and not r.warnings


def test_a_relief_valve_is_closed_below_cracking_and_its_spool_lags():
    relief = c.ReliefValve("relief", p_crack="200 bar", tau="20 ms")
    r = pumped(relief, "0.1 L/min").simulate(t_end=0.2)
    assert np.all(r["relief.Q"][r["v.p"] < 200e5] == 0.0)
    # a pressure step over the setting: the flow coefficient rises as 1 - exp(-t/tau)
    s = System("lag", t_end=0.1)
    s.add(c.ConstantPressure("high", p="210 bar"))
    s.add(c.Tank("tank"))
    s.add(c.ReliefValve("relief", p_crack="200 bar", tau="20 ms", q_nom="1000 L/min"))
    s.connect("high.P", "relief.A")
    s.connect("relief.B", "tank.P")
    r = s.simulate(n_points=101)
    K_ss = static_K(10e5, 210e5)
    k = np.searchsorted(r.t, 0.02)
    assert r["relief.K"][k] == pytest.approx(K_ss * (1 - np.exp(-1.0)), rel=1e-3)


def test_a_pressure_reducing_valve_holds_its_outlet_near_the_setting():
    s = System("reducing", t_end=2.0)
    s.add(c.ConstantPressure("supply", p="200 bar"))
    s.add(c.Tank("tank"))
    s.add(c.PressureReducingValve("prv", p_set="50 bar", q_nom="60 L/min", tau="5 ms"))
    s.add(c.Volume("v", V="0.5 L"))
    s.add(c.Orifice("load", d="1.5 mm", Cd=0.6))
    s.connect("supply.P", "prv.A")
    s.connect("prv.B", "v.P", "load.A")
    s.connect("load.B", "tank.P")
    r = s.simulate(accuracy=1e-7)  # tight, as for the relief valve: the flow balance is checked to 1e-6
    p, q = r["v.p"][-1], r["prv.Q"][-1]
    assert 45e5 < p < 50e5
    assert q == pytest.approx(static_K(50e5 - p, 200e5 - p) * np.sqrt(200e5 - p), rel=1e-4)
    assert q == pytest.approx(r["load.Q"][-1], rel=1e-6)


def test_a_counterbalance_valve_holds_until_piloted_and_lets_oil_back_freely():
    def run(pilot: str, pA: str, pB: str) -> float:
        s = System("cbv", t_end=0.5)
        s.add(c.ConstantPressure("load", p=pA))
        s.add(c.ConstantPressure("valve_side", p=pB))
        s.add(c.ConstantPressure("pilot", p=pilot))
        s.add(c.CounterbalanceValve("cbv", p_crack="250 bar", r_p=4.0, tau="5 ms", q_nom="1000 L/min"))
        s.connect("load.P", "cbv.A")
        s.connect("valve_side.P", "cbv.B")
        s.connect("pilot.P", "cbv.X")
        return float(s.simulate()["cbv.Q"][-1])

    assert run("0 bar", "150 bar", "0 bar") == 0.0  # the load is held
    q = run("30 bar", "150 bar", "0 bar")  # 150 + 4 x 30 = 270 bar: 20 bar over the setting
    assert q == pytest.approx(static_K(20e5, 150e5) * np.sqrt(150e5), rel=1e-4)
    assert run("0 bar", "0 bar", "10 bar") < -1e-5  # lifting: free flow B to A through the check valve


def test_a_counterbalance_valve_piloted_against_its_drop_without_a_check_valve():
    """Options pilot = "drop" (the spring chamber drained to B: p_A - p_B + r_p p_X over the setting) and check =
    "none" (no free flow back: Hopsan's over-centre and counterbalance valves): held both ways while closed,
    metering either way once piloted open."""

    def run(pilot: str, pA: str, pB: str) -> float:
        s = System("cbv", t_end=0.5)
        s.add(c.ConstantPressure("load", p=pA))
        s.add(c.ConstantPressure("valve_side", p=pB))
        s.add(c.ConstantPressure("pilot", p=pilot))
        s.add(c.CounterbalanceValve("cbv", p_crack="250 bar", r_p=4.0, tau="5 ms", q_nom="1000 L/min",
                                    pilot="drop", check="none"))
        s.connect("load.P", "cbv.A")
        s.connect("valve_side.P", "cbv.B")
        s.connect("pilot.P", "cbv.X")
        return float(s.simulate()["cbv.Q"][-1])

    assert run("0 bar", "200 bar", "50 bar") == 0.0  # 150 bar over the valve: held
    q = run("30 bar", "200 bar", "50 bar")  # 150 + 4 x 30 = 270 bar: 20 bar over the setting
    assert q == pytest.approx(static_K(20e5, 150e5) * np.sqrt(150e5), rel=1e-4)
    assert run("0 bar", "0 bar", "10 bar") == 0.0  # no check valve: held backwards too
    q = run("66 bar", "0 bar", "10 bar")  # -10 + 264 = 254 bar: open, metering back from B to A
    assert q == pytest.approx(-static_K(4e5, -10e5) * np.sqrt(10e5), rel=1e-4)


def test_the_bounded_lag_is_continuous_non_increasing_and_hopsans_limit():
    """limited_lag_rate: Hopsan's clamped lag away from the bounds, continuous and non-increasing in K across
    them (so an implicit step always has one solution), and no wind-up outside them."""
    from hydroservo.laws.pressure_valve import STOP_RELAXATION, limited_lag_rate

    tau, K_max = 1e-3, 2.0
    K = np.linspace(-0.5, 2.5, 300_001)
    for target in (-1.0, 0.5, 3.0):
        rate = np.asarray(limited_lag_rate(K, target, tau, K_max), dtype=float)
        assert np.all(np.diff(rate) <= 1e-9)  # non-increasing
        assert np.max(np.abs(np.diff(rate))) < 1.1 * (K[1] - K[0]) / (STOP_RELAXATION * tau)  # Lipschitz: no jump
        inside = (K > 0.01) & (K < K_max - 0.01)
        assert rate[inside] == pytest.approx((target - K[inside]) / tau)
    # outside the bounds the rate never points further out
    assert np.all(np.asarray(limited_lag_rate(K[K < 0], -1.0, tau, K_max)) >= 0.0)
    assert np.all(np.asarray(limited_lag_rate(K[K > K_max], 3.0, tau, K_max)) <= 0.0)


def test_an_implicit_euler_step_onto_the_closed_bound_has_a_solution():
    """The measured defect: the clamped law (rate T/tau just above 0, zero on it) has no implicit-Euler solution
    for a predictor in (0, h|T|/tau); the bounded lag has exactly one, at 0 within the relaxation."""
    from scipy.optimize import brentq

    from hydroservo.laws.pressure_valve import limited_lag_rate

    tau, T, h, K_pred = 1e-3, -1.0, 1e-6, 1e-5  # K_pred < h|T|/tau = 1e-3

    def clamped(K: float) -> float:
        rate = (T - K) / tau
        return 0.0 if K <= 0.0 and rate < 0.0 else rate

    grid = np.linspace(-1e-3, 1e-3, 20_001)
    residual = np.array([K - K_pred - h * clamped(K) for K in grid])
    # negative on and below the bound, positive above it: it jumps over zero at K = 0 and has no root
    assert np.all(residual[grid <= 0.0] < 0.0) and np.all(residual[grid > 0.0] > 0.0)
    K = brentq(lambda K: K - K_pred - h * float(limited_lag_rate(K, T, tau, 2.0)), -1e-3, 1e-3, xtol=1e-15)
    assert 0.0 <= K < K_pred


@pytest.mark.parametrize("accuracy", [1e-5, 1e-6, 1e-8])
def test_hopsans_position_servo_runs_at_tight_accuracy(accuracy):
    """CVODES' Newton corrector failed on position-servo from accuracy 1e-5 (the relief valve's clamped spool,
    near t = 0.3 ms and 1 ms); now every accuracy to 1e-8 runs, and the piston's end position agrees with the
    default run's to its accuracy (1e-4 of the 0.7 m range)."""
    import warnings

    from hydroservo import load_model

    system = load_model("position-servo")
    with warnings.catch_warnings():  # the chamber's 55 MPa peak, as Hopsan's own result, is flagged
        warnings.simplefilter("ignore")
        tight = system.simulate(t_end="1.2 s", n_points=241, accuracy=accuracy)
        default = system.simulate(t_end="1.2 s", n_points=241)
    assert tight["load.x"][-1] == pytest.approx(default["load.x"][-1], abs=1e-4 * 0.7)


def _between(valve: c.Component, pA: str, pB: str, t_end: float) -> System:
    s = System("between", t_end=t_end)
    s.add(c.Tank("a", p=pA))
    s.add(c.Tank("b", p=pB))
    s.add(valve)
    s.connect("a.P", f"{valve.name}.A")
    s.connect("b.P", f"{valve.name}.B")
    return s


def test_a_balanced_spool_reaches_the_static_opening_with_the_time_constant_its_flow_forces_shorten():
    """spool = "balance": C_s tau dK/dt = over - (C_s + C_f dp) K between fixed pressures is a lag to the static
    opening over/(C_s + C_f dp) with time constant tau C_s/(C_s + C_f dp); pilot = "drop" sets the relief valve
    against p_A - p_B (here 210 - 20 - 180 = 10 bar over)."""
    k_cs, k_cf, tau = 1e-8, 2e-8, 0.02
    Cs, Cf = np.sqrt(P_NOM) / k_cs, 1.0 / (k_cf * np.sqrt(P_NOM))
    dp, over = 190e5, 10e5
    tau_eff = tau * Cs / (Cs + Cf * dp)
    valve = c.ReliefValve("rv", p_crack="180 bar", pilot="drop", spool="balance", k_cs=k_cs, k_cf=k_cf, tau=tau,
                          q_nom="1000 L/min")
    t = np.array([0.0, tau_eff, 3.0 * tau_eff, 20.0 * tau_eff])
    r = _between(valve, "210 bar", "20 bar", float(t[-1])).simulate(t_eval=t, accuracy=1e-8)
    K_ss = over / (Cs + Cf * dp)
    np.testing.assert_allclose(r["rv.K"], K_ss * (1.0 - np.exp(-t / tau_eff)), rtol=1e-5, atol=1e-15)
    assert tau_eff < 0.5 * tau  # the flow forces stiffen the spool
    # the default pilot reads the inlet alone: 210 - 180 = 30 bar over
    inlet = c.ReliefValve("rv", p_crack="180 bar", spool="balance", k_cs=k_cs, k_cf=k_cf, tau=tau, q_nom="1000 L/min")
    r = _between(inlet, "210 bar", "20 bar", float(t[-1])).simulate(t_eval=t, accuracy=1e-8)
    assert r["rv.K"][-1] == pytest.approx(30e5 / (Cs + Cf * dp), rel=1e-6)



def test_a_spool_with_mass_is_the_balanced_spools_second_order_response_and_stops_inelastically():
    """spool = "mass": tau_m K'' + K' = (over - (C_s + C_f dp) K)/(C_s tau) between fixed pressures, from rest at
    K = 0: K = K_ss (1 - (s2 e^(s1 t) - s1 e^(s2 t))/(s2 - s1)), s1, s2 the roots of tau_m s^2 + s + b
    (underdamped here: it overshoots); with the full opening below the overshoot, the spool stops there, its
    velocity lost, and leaves the stop from rest to settle at K_ss."""
    k_cs, k_cf, tau, tau_m = 1e-8, 2e-8, 0.02, 0.01
    Cs, Cf = np.sqrt(P_NOM) / k_cs, 1.0 / (k_cf * np.sqrt(P_NOM))
    dp, over = 190e5, 10e5
    b = (Cs + Cf * dp) / (Cs * tau)
    K_ss = over / (Cs + Cf * dp)
    s1, s2 = np.roots([tau_m, 1.0, b]).astype(complex)
    t = np.linspace(0.0, 0.05, 11)
    closed_form = K_ss * (1.0 - (s2 * np.exp(s1 * t) - s1 * np.exp(s2 * t)) / (s2 - s1)).real
    valve = c.ReliefValve("rv", p_crack="180 bar", pilot="drop", spool="mass", k_cs=k_cs, k_cf=k_cf, tau=tau,
                          tau_m=tau_m, q_nom="1000 L/min")
    r = _between(valve, "210 bar", "20 bar", float(t[-1])).simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["rv.K"], closed_form, rtol=1e-5, atol=1e-12 * K_ss)
    assert closed_form.max() > 1.15 * K_ss  # it overshoots
    # a full opening below the overshoot: the spool reaches it at t0, where its velocity is lost (an inelastic
    # stop, as Hopsan's clamp), and leaves it from rest: K_ss + (K_max - K_ss) (s2 e^(s1 t') - s1 e^(s2 t'))/(s2 - s1)
    K_max = 1.05 * K_ss

    def first(time: float) -> float:
        return float((K_ss * (1.0 - (s2 * np.exp(s1 * time) - s1 * np.exp(s2 * time)) / (s2 - s1))).real) - K_max

    t0 = brentq(first, 0.01, 0.03)
    valve = c.ReliefValve("rv", p_crack="180 bar", pilot="drop", spool="mass", k_cs=k_cs, k_cf=k_cf, tau=tau,
                          tau_m=tau_m, q_nom=K_max * np.sqrt(P_NOM))
    after = t0 + np.array([0.002, 0.005, 0.01])
    r = _between(valve, "210 bar", "20 bar", 1.0).simulate(t_eval=[0.0, *after, 1.0], accuracy=1e-8)
    from_rest = K_ss + (K_max - K_ss) * ((s2 * np.exp(s1 * (after - t0)) - s1 * np.exp(s2 * (after - t0))) / (s2 - s1)).real
    np.testing.assert_allclose(r["rv.K"][1:4], from_rest, rtol=1e-4)
    assert r["rv.K"][4] == pytest.approx(K_ss, rel=1e-6) and abs(r["rv.ds"][4]) < 1e-6

def test_a_balanced_reducing_valve_takes_the_drop_with_its_sign_and_stops_at_full_opening():
    """Hopsan's flow force 2 Cq w cos(phi) (p_1 - p_2) x takes the drop with its sign: with the outlet above the
    inlet the static opening over/(C_s + C_f dp) is larger than at dp = 0; an opening beyond q_nom/sqrt(p_nom)
    stops there."""
    k_cs, k_cf, tau = 1e-8, 1e-8, 0.01
    Cs, Cf = np.sqrt(P_NOM) / k_cs, 1.0 / (k_cf * np.sqrt(P_NOM))
    prv = c.PressureReducingValve("prv", p_set="50 bar", spool="balance", k_cs=k_cs, k_cf=k_cf, tau=tau,
                                  q_nom="1000 L/min")
    r = _between(prv, "38 bar", "40 bar", 0.5).simulate(accuracy=1e-8)
    assert r["prv.K"][-1] == pytest.approx(10e5 / (Cs - Cf * 2e5), rel=1e-6)
    assert r["prv.K"][-1] > 10e5 / Cs
    small = c.PressureReducingValve("prv", p_set="50 bar", spool="balance", k_cs=k_cs, k_cf=k_cf, tau=tau,
                                    q_nom="1 L/min")
    r = _between(small, "38 bar", "40 bar", 0.5).simulate(accuracy=1e-8)
    K_max = 1e-3 / 60.0 / np.sqrt(P_NOM)
    assert r["prv.K"][-1] == pytest.approx(K_max, rel=1e-4)
    assert r["prv.s"][-1] == pytest.approx(1.0, rel=1e-4)


def test_a_relief_valve_with_hysteresis_opens_half_the_band_above_its_setting_and_closes_half_below():
    """Hopsan's ValveHysteresis (p_h): a slow sine of pressure about the setting opens the valve once it is p_h/2
    above the setting and closes it once it is p_h/2 below, where without hysteresis both happen at the setting.
    The spool's lag (1 ms, against a 1 s period of 10 bar) shifts both points by about 0.06 bar (the sine's rate
    times tau), hence the 0.1 bar tolerance."""

    def edges(p_h: str) -> tuple[float, float]:
        s = System("hysteresis", t_end=1.0)
        s.add(c.Sine("sine", offset=200e5, amplitude=10e5, frequency="1 Hz"))
        s.add(c.PressureSource("supply"))
        s.add(c.Tank("tank"))
        s.add(c.ReliefValve("relief", p_crack="200 bar", tau="1 ms", p_h=p_h))
        s.connect("sine.y", "supply.u")
        s.connect("supply.P", "relief.A")
        s.connect("relief.B", "tank.P")
        r = s.simulate(n_points=20_001, accuracy=1e-8)
        is_open = r["relief.K"] > 1e-3 * 1e-3 / np.sqrt(P_NOM)  # above 0.1 % of full opening
        opens = np.flatnonzero(~is_open[:-1] & is_open[1:])[0]
        closes = np.flatnonzero(is_open[:-1] & ~is_open[1:])[0]
        return float(r["supply.p"][opens]), float(r["supply.p"][closes])

    up, down = edges("5 bar")
    assert up == pytest.approx(202.5e5, abs=0.1e5) and down == pytest.approx(197.5e5, abs=0.1e5)
    up0, down0 = edges("0 bar")
    assert up0 == pytest.approx(200e5, abs=0.1e5) and down0 == pytest.approx(200e5, abs=0.1e5)


def test_a_balanced_spool_refuses_a_hysteresis():
    s = System("balanced", t_end=0.1)
    s.add(c.ConstantPressure("high", p="210 bar"))
    s.add(c.Tank("tank"))
    s.add(c.ReliefValve("relief", spool="balance", p_h="5 bar"))
    s.connect("high.P", "relief.A")
    s.connect("relief.B", "tank.P")
    with pytest.raises(Exception, match=r"relief\.p_h = 500000 Pa: a hysteresis needs spool"):
        s.simulate()


def test_a_pressure_compensator_is_open_until_its_pilots_differ_by_the_setting_then_throttles() -> None:
    """PressureCompensatorValve: the closing K_c = over/(C_s + C_f Δp) of over = p_X - p_Y - p_ref, within
    [0, K_max], and the flow (K_max - K_c) √Δp (turbulent, regularised below p_tr); the pilots take no flow."""
    k_max = 1e-3 / np.sqrt(P_NOM)
    p_tr = 1e4
    for px, expected_open in ((60e5, 1.0), (71e5, None), (300e5, 0.0)):
        s = System("compensator")
        s.add(c.PressureCompensatorValve("v", p_ref=20e5, tau=0.01))
        for port, p in (("A", 100e5), ("B", 40e5), ("X", px), ("Y", 50e5)):
            s.add(c.Tank(f"s{port}", p=p))
            s.connect(f"v.{port}", f"s{port}.P")
        r = s.simulate(t_eval=[0.0, 0.3])
        k_c = min(max(static_K(px - 50e5 - 20e5, 60e5), 0.0), k_max)
        k = k_max - k_c
        if expected_open is not None:
            assert k / k_max == pytest.approx(expected_open)
        else:
            assert 0.1 < k / k_max < 0.9  # throttling
        assert float(r["v.s"][0]) == pytest.approx(1.0)  # open at rest
        assert float(r["v.s"][-1]) == pytest.approx(k / k_max, rel=1e-6, abs=1e-9)
        assert float(r["v.Q"][-1]) == pytest.approx(k * 60e5 / (60e5**2 + p_tr**2) ** 0.25, rel=1e-6, abs=1e-12)
        assert float(r["v.QX"][-1]) == 0.0


def test_relief_and_reducing_valves_piloted_from_ports_take_their_pilots_there() -> None:
    """Option pilot = ports of ReliefValve (over = p_X - p_Y - p_crack) and pilot = port of PressureReducingValve
    (over = p_set + p_X - p_B): the static opening of the lag spool, the pilots without flow."""
    k_max = 1e-3 / np.sqrt(P_NOM)
    for valve, pilots, over in (
        (c.ReliefValve("v", p_crack=10e5, pilot="ports"), {"X": 61e5, "Y": 50e5}, 61e5 - 50e5 - 10e5),
        (c.PressureReducingValve("v", p_set=10e5, pilot="port"), {"X": 30.5e5}, 10e5 + 30.5e5 - 40e5),
    ):
        s = System("piloted")
        s.add(valve)
        for port, p in {"A": 100e5, "B": 40e5, **pilots}.items():
            s.add(c.Tank(f"s{port}", p=p))
            s.connect(f"v.{port}", f"s{port}.P")
        r = s.simulate(t_eval=[0.0, 0.3])
        k = min(static_K(over, 60e5), k_max)
        assert 0.0 < k < k_max
        assert float(r["v.Q"][-1]) == pytest.approx(k * 60e5 / (60e5**2 + 1e8) ** 0.25, rel=1e-6)
        assert float(r["v.QX"][-1]) == 0.0
