"""The everyday parts against their laws worked by hand: orifice, check valve, pumps, motor, accumulator."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c

ABS = 101325.0  # the atmosphere, to make gauge pressures absolute [Pa]


def pump_orifice(restriction: c.Component, pump: c.Component | None = None) -> System:
    """A pump into a 1 L volume that drains to tank through ``restriction``."""
    s = System("pump-orifice", t_end=2.0)
    s.add(c.Tank("tank"))
    s.add(pump or c.Pump("pump", D="25 cm^3/rev", omega="1500 rpm"))
    s.add(c.Volume("v", V="1 L"))
    s.add(restriction)
    s.connect("tank.P", "pump.S")
    s.connect("pump.P", "v.P", f"{restriction.name}.A")
    s.connect(f"{restriction.name}.B", "tank.P")
    return s


def test_an_orifice_settles_where_its_turbulent_flow_equals_the_pumps():
    r = pump_orifice(c.Orifice("o", d="3 mm", Cd=0.6, rho=870.0)).simulate()
    q = 25e-6 * 1500 / 60  # 37.5 L/min
    area = np.pi * 0.003**2 / 4
    dp = 870.0 / 2 * (q / (0.6 * area)) ** 2  # Q = Cd A sqrt(2 dp / rho), by hand
    assert r["v.p"][-1] == pytest.approx(dp, rel=1e-4)  # the laminar regularisation is far below 80 bar


def test_an_orifice_is_laminar_below_its_transition():
    o = c.Orifice("o", d="1 mm", rho=870.0, nu=32e-6)
    s = System("s")
    s.add(o)
    s.add(c.ConstantPressure("a", p="10 Pa"))
    s.add(c.Tank("b"))
    s.connect("a.P", "o.A")
    s.connect("o.B", "b.P")
    q10 = s.simulate(t_end=0.001)["o.Q"][-1]
    q20 = s.simulate(t_end=0.001, params={"a.p": "20 Pa"})["o.Q"][-1]
    assert q20 / q10 == pytest.approx(2.0, rel=1e-3)  # proportional to the drop, not to its root



def test_a_blended_orifice_adds_its_laminar_and_turbulent_resistances() -> None:
    """Option law = "blend": Q = A dp / (k_lam^-n + (rho |dp| / 2)^(n/2) / Cd^n)^(1/n), checked at a drop where
    the two resistances are equal (Q = 2^(-1/n) of either law's), far below it (laminar, k_lam A dp) and far above
    (turbulent); d_back the bore of the back flow; the transition law's nu does not enter."""
    area, back = np.pi * 1e-3**2 / 4, np.pi * 0.5e-3**2 / 4
    for n in (2.0, 4.0):
        o = c.Orifice("o", law="blend", d="1 mm", d_back="0.5 mm", Cd=0.6, rho=870.0, k_lam=2e-5, n_blend=n, nu=1.0)

        def q(dp: float, o: c.Orifice = o) -> float:
            return float(o.output_equations(0.0, {}, {"pA": 1e5 + dp, "pB": 1e5}, o.values)["Q"])

        dp_eq = 2 * 0.6**2 / (870.0 * 2e-5**2)  # k_lam^-1 = sqrt(rho dp / 2) / Cd
        assert q(dp_eq) == pytest.approx(2e-5 * area * dp_eq * 2 ** (-1 / n), rel=1e-12)
        assert q(dp_eq * 1e-4) == pytest.approx(2e-5 * area * dp_eq * 1e-4, rel=1e-3 if n == 4 else 1e-2)
        turbulent = 0.6 * area * np.sqrt(2 * dp_eq * 1e4 / 870.0)
        assert q(dp_eq * 1e4) == pytest.approx(turbulent, rel=1e-3 if n == 4 else 1e-2)
        assert q(-dp_eq) == pytest.approx(-2e-5 * back * dp_eq * 2 ** (-1 / n), rel=1e-12)

def test_a_check_valve_holds_its_cracking_pressure_plus_what_its_opening_needs():
    cv = c.CheckValve("cv", d="5 mm", p_crack="10 bar", dp_open="5 bar", Cd=0.6, rho=870.0)
    r = pump_orifice(cv, c.Pump("pump", D="2 cm^3/rev", omega="1500 rpm")).simulate()
    p = r["v.p"][-1]
    assert 10e5 < p < 15e5
    # the static balance, by hand: Q = Cd s(dp) A sqrt(2 dp/rho), s the rounded ramp
    s_lin = (p - 10e5) / 5e5
    s = s_lin**2 * (3 - 2 * s_lin)
    q = 0.6 * s * np.pi * 0.005**2 / 4 * np.sqrt(2 * p / 870.0)
    assert q == pytest.approx(2e-6 * 1500 / 60, rel=1e-3)
    assert r["cv.s"][-1] == pytest.approx(s, rel=1e-9)


def test_a_check_valve_blocks_reverse_flow():
    s = System("reverse")
    s.add(c.CheckValve("cv"))
    s.add(c.Tank("a"))
    s.add(c.ConstantPressure("b", p="100 bar"))
    s.connect("a.P", "cv.A")
    s.connect("cv.B", "b.P")
    assert s.simulate(t_end=0.01)["cv.Q"][-1] == 0.0


def test_pump_leakage_and_torque():
    pump = c.Pump("pump", D="25 cm^3/rev", omega="1500 rpm", C_leak="1e-11 m^3/s/Pa")
    r = pump_orifice(c.Orifice("o", d="3 mm", Cd=0.6, rho=870.0), pump).simulate()
    p, q = r["v.p"][-1], r["pump.QP"][-1]
    assert q == pytest.approx(25e-6 * 1500 / 60 - 1e-11 * p, rel=1e-9)
    assert r["pump.T"][-1] == pytest.approx(25e-6 / (2 * np.pi) * p, rel=1e-9)


def test_a_compensated_pump_holds_its_setting_within_its_band():
    pump = c.VariablePump("pump", D="25 cm^3/rev", omega="1500 rpm", p_c="100 bar", dp_band="5 bar")
    r = pump_orifice(c.Orifice("o", d="1 mm", Cd=0.6, rho=870.0), pump).simulate(t_end=8.0)
    p, eps = r["v.p"][-1], r["pump.eps"][-1]
    assert 100e5 < p < 105e5 and 0 < eps < 1
    assert eps == pytest.approx((105e5 - p) / 5e5, rel=1e-6)  # on the compensator's line
    # delivering what the orifice takes, its laminar transition (4.5 bar for 1 mm at 32 cSt) included
    p_tr = 870.0 / 2 * (1000 * 32e-6 / 0.001) ** 2
    q = 0.6 * np.pi * 0.001**2 / 4 * np.sqrt(2 / 870.0) * p / (p**2 + p_tr**2) ** 0.25
    assert r["pump.QP"][-1] == pytest.approx(q, rel=1e-6)


def test_a_motor_runs_at_the_speed_where_its_torque_meets_friction_and_load():
    s = System("motor", t_end=5.0)
    s.add(c.ConstantPressure("supply", p="100 bar"))
    s.add(c.Tank("tank"))
    s.add(c.Motor("m", D="50 cm^3/rev", B_m=0.5, J=0.01, C_im="1e-12 m^3/s/Pa"))
    s.add(c.Step("load", unit="N*m", amplitude="20 N*m"))
    s.connect("supply.P", "m.A")
    s.connect("m.B", "tank.P")
    s.connect("load.y", "m.T_load")
    r = s.simulate()
    D = 50e-6 / (2 * np.pi)
    omega = (D * 100e5 - 20.0) / 0.5
    assert r["m.omega"][-1] == pytest.approx(omega, rel=1e-6)
    assert r["m.QA"][-1] == pytest.approx(D * omega + 1e-12 * 100e5, rel=1e-6)


@pytest.mark.parametrize("kappa", [1.0, 1.4])
def test_an_accumulator_stores_what_is_pumped_along_its_polytropic_law(kappa):
    s = System("charge", t_end=3.0)
    s.add(c.Tank("tank"))
    s.add(c.Pump("pump", D="10 cm^3/rev", omega="600 rpm"))  # 6 L/min
    s.add(c.Accumulator("acc", V0="1 L", p0="50 bar", kappa=kappa, p_init="50 bar"))
    s.connect("tank.P", "pump.S")
    s.connect("pump.P", "acc.P")
    r = s.simulate()
    stored = 1e-4 * r.t  # the pumped volume [m^3]; the port's oil takes less than 1e-7 m^3 of it
    np.testing.assert_allclose(r["acc.V_oil"], stored, atol=2e-6)
    p_gas = (50e5 + ABS) * (1e-3 / (1e-3 - 3e-4)) ** kappa - ABS  # p V^kappa constant, absolute
    assert r["acc.p"][-1] == pytest.approx(p_gas, rel=5e-3)


def test_an_empty_accumulator_is_only_the_oil_in_its_port():
    s = System("empty", t_end=0.05)
    s.add(c.Accumulator("acc", V0="1 L", p0="50 bar", V_dead="10 cm^3", beta_e=1.4e9, p_init="0 bar"))
    s.add(c.ConstantPressure("src", p="1 bar"))
    s.add(c.Orifice("o", d="1 mm"))
    s.connect("src.P", "o.A")
    s.connect("o.B", "acc.P")
    r = s.simulate()
    assert r["acc.V_oil"][-1] == 0.0 and r["acc.p"][-1] == pytest.approx(1e5, rel=1e-3)


@pytest.mark.parametrize("inlet", ["free", "floor"])
def test_a_pump_drawing_from_a_starved_volume_empties_it_or_takes_only_what_flows_in(inlet: str) -> None:
    # a 37.5 L/min pump draws from a 1 L volume fed from tank through a laminar orifice that passes at most
    # G (p_tank - p_floor) = 1e-9 * 101325 m^3/s (6.1 L/min); it delivers into a volume drained to tank
    s = System("starved", t_end=1.0)
    s.add(c.Tank("tank"))
    s.add(c.LaminarOrifice("feed", G_lam="1e-9 m^3/s/Pa"))
    s.add(c.Volume("suction", V="1 L", pressure_floor="cavity", p0=0.0))
    s.add(c.Pump("pump", D="25 cm^3/rev", omega="1500 rpm", inlet=inlet, p_floor="0 Pa_abs"))
    s.add(c.Volume("out", V="1 L"))
    s.add(c.LaminarOrifice("drain", G_lam="1e-10 m^3/s/Pa"))
    s.connect("tank.P", "feed.A", "drain.B")
    s.connect("feed.B", "suction.P", "pump.S")
    s.connect("pump.P", "out.P", "drain.A")
    r = s.simulate()
    fed = 1e-9 * ABS  # the feed's largest flow, the suction at vacuum [m^3/s]
    if inlet == "floor":  # Hopsan's clamp: the suction held at the floor, the pump passing what the feed gives
        assert r["suction.p"][-1] == pytest.approx(-ABS, abs=100.0)  # within p_reg of vacuum
        assert r["pump.QP"][-1] == pytest.approx(fed, rel=1e-3)
        assert r["out.p"][-1] == pytest.approx(fed / 1e-10, rel=1e-3)  # the drain passes what the pump delivers
    else:  # the displacement flow goes on: the suction holds a growing cavity, the outlet climbs past that
        assert r["pump.QP"][-1] == pytest.approx(25e-6 * 1500 / 60, rel=1e-3)
        assert r["suction.p"][-1] == pytest.approx(-ABS, abs=1.0)
        assert r["out.p"][-1] > 2 * fed / 1e-10


def test_an_orifice_whose_area_is_an_input_follows_the_signal() -> None:
    # Hopsan's turbulent orifice takes its area as an input (Pressure Relief Valve Characteristics steps it)
    s = System("area", t_end=1.0)
    s.add(c.ConstantPressure("a", p="100 bar"))
    s.add(c.Tank("b"))
    s.add(c.Orifice("o", d="1 mm", Cd=0.67, rho=890.0, lambda_crit=10.0, area="input"))
    s.add(c.Step("A", unit="m^2", offset="1e-6 m^2", amplitude="-7e-7 m^2", t_step=0.5))
    s.connect("a.P", "o.A")
    s.connect("o.B", "b.P")
    s.connect("A.y", "o.A_in")
    r = s.simulate(t_eval=[0.25, 0.75])
    root = np.sqrt(2 * 100e5 / 890.0)
    assert list(r["o.Q"]) == pytest.approx([0.67 * 1e-6 * root, 0.67 * 3e-7 * root], rel=1e-6)


def test_check_valve_seat_opens_fully_at_cracking() -> None:
    """Option opening = "seat" (Hopsan's check valves): no flow up to p_crack, the full bore's turbulent flow
    just above it, none backwards."""
    from hydroservo.laws.orifice import transition_pressure

    cv = c.CheckValve("cv", opening="seat", d="2 mm", p_crack="3 bar", Cd=0.6, rho=870.0)
    p_tr = transition_pressure(2e-3, 870.0, 32e-6, 1000.0)
    area = np.pi * 2e-3**2 / 4.0

    def q(dp: float) -> float:
        return float(cv.output_equations(0.0, {}, {"pA": 1e5 + dp, "pB": 1e5}, cv.values)["Q"])

    assert q(2.99e5) == 0.0 and q(-5e5) == 0.0
    for dp in (3.01e5, 50e5):
        assert q(dp) == pytest.approx(0.6 * area * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p_tr * p_tr) ** 0.25, rel=1e-12)


def test_a_piloted_check_valve_passes_both_ways_through_its_open_bore_while_its_pilot_is_above_half() -> None:
    """Option pilot = "open" (Hopsan's Hydraulic22DirectionalCheckValve): with open <= 0.5 the seat checks (no
    flow back, the bore d forward above p_crack); above 0.5 the bore d_open passes either way; the switch is an
    event."""
    from hydroservo.laws.orifice import transition_pressure

    cv = c.CheckValve("cv", opening="seat", pilot="open", d="2 mm", d_open="3 mm", p_crack="3 bar", Cd=0.6,
                      rho=870.0)

    def q(dp: float, pilot: float) -> float:
        return float(cv.output_equations(0.0, {}, {"pA": 1e5 + dp, "pB": 1e5, "open": pilot}, cv.values)["Q"])

    def law(d: float, dp: float) -> float:
        p_tr = transition_pressure(d, 870.0, 32e-6, 1000.0)
        return 0.6 * np.pi * d * d / 4.0 * np.sqrt(2.0 / 870.0) * dp / (dp * dp + p_tr * p_tr) ** 0.25

    assert q(-5e5, 0.5) == 0.0 and q(2.9e5, 0.2) == 0.0
    assert q(10e5, 0.5) == pytest.approx(law(2e-3, 10e5), rel=1e-12)
    assert q(-5e5, 0.51) == pytest.approx(law(3e-3, -5e5), rel=1e-12)
    assert q(2.9e5, 1.0) == pytest.approx(law(3e-3, 2.9e5), rel=1e-12)
    assert cv.switch_equations(0.0, {}, {"open": 0.7, "pA": 0.0, "pB": 0.0}, cv.values, {})["pilot"][0] == pytest.approx(0.2)
