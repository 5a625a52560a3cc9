"""The parts added for Hopsan's library: laminar orifice, flow source, driven sources, soft step, integrator,
a pump's displacement setting, a fixed point away from 0, a velocity source, a mass with a length.

Each against its closed form."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c


def test_laminar_orifice_between_two_sources_and_its_driven_coefficient() -> None:
    s = System("orifice")
    s.add(c.Tank("high", p="100 bar"))
    s.add(c.Tank("low"))
    s.add(c.LaminarOrifice("o", G_lam=2e-11))
    s.add(c.Step("dk", unit="m^3/s/Pa", amplitude=1e-11, t_step=0.5))
    s.connect("high.P", "o.A")
    s.connect("o.B", "low.P")
    s.connect("dk.y", "o.u")
    r = s.simulate(t_eval=[0.25, 0.75])
    assert r["o.Q"][0] == pytest.approx(2e-11 * 100e5) and r["o.Q"][1] == pytest.approx(3e-11 * 100e5)


def test_flow_source_fills_a_volume() -> None:
    """dp/dt = beta q / V: 1e-4 m^3/s into 1 L at 1e9 Pa gives 1e8 Pa/s."""
    s = System("fill")
    s.add(c.FlowSource("q", q=1e-4))
    s.add(c.Volume("v", V="1 L", beta_e=1e9))
    s.connect("q.P", "v.P")
    r = s.simulate(t_eval=[0.0, 0.01])
    assert r["v.p"][1] == pytest.approx(1e6, rel=1e-6)


def test_a_pressure_source_follows_its_signal() -> None:
    s = System("driven")
    s.add(c.PressureSource("t", p0="1 bar"))
    s.add(c.Constant("u", unit="Pa", value=2e5))
    s.add(c.Volume("v"))
    s.add(c.LaminarOrifice("o"))
    s.connect("t.P", "o.A")
    s.connect("o.B", "v.P")
    s.connect("u.y", "t.u")
    assert s.simulate(t_end=0.01)["t.p"][-1] == pytest.approx(3e5)


def test_soft_step_is_half_a_cosine() -> None:
    s = System("soft")
    s.add(c.SoftStep("y", amplitude=2.0, offset=1.0, t_start=1.0, t_end=3.0))
    s.add(c.Integrator("i"))
    s.connect("y.y", "i.u")
    t = np.array([0.0, 0.5, 1.5, 2.0, 4.0])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    expected = 1.0 + 1.0 * (1.0 - np.cos(np.pi * np.clip((t - 1.0) / 2.0, 0.0, 1.0)))
    assert np.allclose(r["y.y"], expected)
    # its integral over 0-4 s: 1 before the step, 4 during it (the cosine's part integrates to 0), 3 after
    assert r["i.y"][-1] == pytest.approx(8.0, rel=1e-6)
    with pytest.raises(Exception, match="t_end"):
        c.SoftStep("bad", t_start=2.0, t_end=1.0).check()


def test_pump_displacement_setting_scales_its_flow() -> None:
    s = System("pump")
    s.add(c.Tank("t"))
    s.add(c.Tank("out", p="10 bar"))
    s.add(c.Pump("p", D="10 cm^3/rev", omega="1500 rpm"))
    s.add(c.Constant("eps", value=0.4))
    s.connect("t.P", "p.S")
    s.connect("p.P", "out.P")
    s.connect("eps.y", "p.eps")
    q = s.simulate(t_end=0.01)["p.QP"][-1]
    assert q == pytest.approx(0.4 * 10e-6 * 1500 / 60)


def test_a_pump_driven_at_a_speed_signal_delivers_d_omega_less_its_leakage_backwards_too() -> None:
    """Option speed = input: Q_P = D ω_in - C_leak (p_P - p_S), ω_in a ramp from -10 to 10 rad/s (backwards,
    the pump delivers from P to S); the parameter omega is not used."""
    s = System("pump")
    s.add(c.Tank("t"))
    s.add(c.Tank("out", p="10 bar"))
    s.add(c.Pump("p", D="50 cm^3/rev", omega="1500 rpm", C_leak=1e-12, speed="input"))
    s.add(c.Ramp("n", unit="rad/s", offset=-10.0, slope=2.0, t_start=0.0))
    s.connect("t.P", "p.S")
    s.connect("p.P", "out.P")
    s.connect("n.y", "p.omega_in")
    r = s.simulate(t_eval=[0.0, 2.5, 5.0, 10.0])
    omega = np.array([-10.0, -5.0, 0.0, 10.0])
    np.testing.assert_allclose(r["p.QP"], 50e-6 / (2 * np.pi) * omega - 1e-12 * 10e5, rtol=1e-9, atol=1e-15)


def test_mass_length_places_end_1_and_a_fixed_point_holds_its_position() -> None:
    """A mass whose end 1 sits at length - x, held by a spring to a fixed point at 0.1 m: relaxed at the start
    positions, the spring holds it there; 10 N along +x moves it by 10 N / k."""
    s = System("held")
    s.add(c.Mass("m", m=1.0, B=100.0, x0=0.02, length=0.05))
    # the spring's ends face the mass's end 1 and the point: outward displacements -(0.05 - 0.02) and -0.1
    s.add(c.Spring("k", k_spring=1000.0, e0=-(0.03 + 0.1)))
    s.add(c.FixedPosition("g", x0=0.1))
    s.add(c.Step("push", unit="N", amplitude=10.0, t_step=1.0))
    s.connect("m.P1", "k.P1")
    s.connect("k.P2", "g.P")
    s.connect("push.y", "m.F_ext")
    r = s.simulate(t_eval=[0.0, 0.9, 6.0], accuracy=1e-8)
    assert np.allclose(r["m.x_P1"], 0.05 - r["m.x"])
    assert r["m.x"][1] == pytest.approx(0.02, abs=1e-12)  # relaxed: nothing moves before the push
    assert r["m.x"][2] == pytest.approx(0.02 + 10.0 / 1000.0, rel=1e-6)


def test_velocity_source_moves_its_node() -> None:
    s = System("driven mass")
    s.add(c.VelocitySource("src", x0=0.01))
    s.add(c.Constant("v", unit="m/s", value=0.2))
    s.add(c.Spring("k", k_spring=500.0, e0=-0.01))
    s.add(c.FixedPosition("g"))
    s.connect("v.y", "src.u")
    s.connect("src.P", "k.P1")
    s.connect("k.P2", "g.P")
    r = s.simulate(t_eval=[0.0, 1.0])
    assert r["src.x"][1] == pytest.approx(0.21)
    assert r["k.F"][1] == pytest.approx(500.0 * (-0.21 + 0.01))  # compressed by 0.2 m: tension -100 N


def test_a_spring_with_slack_pulls_but_never_pushes() -> None:
    """Spring with option slack = "slack": tension k max(x1 + x2 - e0, 0). A velocity source at -0.1 m moving at
    0.2 m/s (e0 = 0, end 2 fixed at 0) stretches it by 0.1 - 0.2 t (its end 1 faces the source): pulling with
    k (0.1 - 0.2 t) until t = 0.5 s, then slack (no force); the plain spring then pushes."""
    r = {}
    for slack in ("slack", "none"):
        s = System(f"rope {slack}")
        s.add(c.VelocitySource("src", x0=-0.1))
        s.add(c.Constant("v", unit="m/s", value=0.2))
        s.add(c.Spring("k", k_spring=500.0, slack=slack))
        s.add(c.FixedPosition("g"))
        s.connect("v.y", "src.u")
        s.connect("src.P", "k.P1")
        s.connect("k.P2", "g.P")
        r[slack] = s.simulate(t_eval=[0.0, 0.25, 0.5, 1.0])
    assert list(r["slack"]["k.F"]) == pytest.approx([50.0, 25.0, 0.0, 0.0], abs=1e-9)
    assert list(r["slack"]["k.F1"]) == pytest.approx([-50.0, -25.0, 0.0, 0.0], abs=1e-9)
    assert list(r["none"]["k.F"]) == pytest.approx([50.0, 25.0, 0.0, -50.0], abs=1e-9)


def test_arithmetic_blocks() -> None:
    s = System("math")
    s.add(c.Constant("a", value=-3.0))
    s.add(c.Constant("b", value=2.0))
    s.add(c.Product("mul"))
    s.add(c.Quotient("div"))
    s.add(c.Absolute("abs"))
    s.add(c.Power("pow", n=3.0))
    s.add(c.Integrator("i"))
    for block in ("mul", "div"):
        s.connect("a.y", f"{block}.u1")
        s.connect("b.y", f"{block}.u2")
    s.connect("a.y", "abs.u")
    s.connect("a.y", "pow.u")
    s.connect("pow.y", "i.u")
    r = s.simulate(t_eval=[0.0, 1.0])
    assert (r["mul.y"][-1], r["div.y"][-1], r["abs.y"][-1], r["pow.y"][-1]) == pytest.approx((-6.0, -1.5, 3.0, 27.0))


def test_volume_with_a_cavity_holds_its_floor_and_refills_it_first() -> None:
    """Drawn from at 1e-5 m^3/s for 1 s, a 1 L volume at 1e9 Pa loses 1e7 Pa of pressure state: from 2 bar
    absolute its port holds 0 Pa absolute while the state goes 9.8 MPa below, a cavity of 9.8 cm^3 (V dp / beta);
    the same flow back refills it before the pressure rises."""
    s = System("cavity")
    s.add(c.Volume("v", V="1 L", beta_e=1e9, p0="2 bar_abs", pressure_floor="cavity", p_floor="0 Pa_abs"))
    s.add(c.FlowSource("q", q=0.0))
    s.add(c.Pulse("draw", unit="m^3/s", amplitude=-1e-5, t_start=0.0, duration=1.0))
    s.add(c.Pulse("fill", unit="m^3/s", amplitude=1e-5, t_start=1.0, duration=0.9))
    s.add(c.Sum("flow", unit="m^3/s", gain2=1.0))
    s.connect("draw.y", "flow.u1")
    s.connect("fill.y", "flow.u2")
    s.connect("flow.y", "q.u")
    s.connect("q.P", "v.P")
    r = s.simulate(t_eval=[0.0, 1.0, 1.95, 2.5], accuracy=1e-8)
    assert r["v.p"][1] == pytest.approx(-101325.0)
    assert r["v.V_cav"][1] == pytest.approx(1e-3 * (1e7 - 2e5) / 1e9, rel=1e-6)
    # refilled for 0.9 s: 0.9e7 Pa of the 0.98e7 below the floor; still 0.8 cm^3 of cavity, still at the floor
    assert r["v.p"][2] == pytest.approx(-101325.0) and r["v.V_cav"][2] == pytest.approx(1e-3 * 0.8e6 / 1e9, rel=1e-4)


def test_a_velocity_source_takes_its_position_from_an_input_with_option_position_input() -> None:
    """Hopsan's velocity transformer with its position input connected: the position is the input, whatever the
    velocity (here 0.3 m held while moving at 0.2 m/s), so a spring to a fixed point is stretched by it alone."""
    s = System("positioned")
    s.add(c.VelocitySource("src", position="input"))
    s.add(c.Constant("v", unit="m/s", value=0.2))
    s.add(c.Constant("x", unit="m", value=0.3))
    s.add(c.Spring("k", k_spring=500.0))
    s.add(c.FixedPosition("g"))
    s.connect("v.y", "src.u")
    s.connect("x.y", "src.x_in")
    s.connect("src.P", "k.P1")
    s.connect("k.P2", "g.P")
    assert "x" not in s["src"].STATES
    r = s.simulate(t_eval=[0.0, 1.0])
    assert list(r["src.x"]) == pytest.approx([0.3, 0.3]) and list(r["src.v"]) == pytest.approx([0.2, 0.2])
    assert r["k.F"][1] == pytest.approx(-500.0 * 0.3)


def test_a_mass_with_coulomb_friction_sticks_below_its_static_force_and_slides_against_the_kinetic_one() -> None:
    """The Stribeck law as Hopsan's Coulomb friction (F_c0 = f_k, F_s0 = f_s - f_k, small v_reg and c_s): a
    force of 40 N on a 10 kg mass with f_s = 50 N leaves it (nearly) at rest; 80 N against f_k = 45 N and
    b = 10 N s/m gives v = (80 - 45)/10 (1 - exp(-t b/m)) from rest."""
    s = System("friction", t_end=2.0)
    for name, force in (("stuck", 40.0), ("sliding", 80.0)):
        s.add(c.Mass(name, m=10.0, B=10.0, F_c0=45.0, F_s0=5.0, v_reg=1e-5, c_s=1e-3, incline=0.0))
        s.add(c.Constant(f"F_{name}", unit="N", value=force))
        s.connect(f"F_{name}.y", f"{name}.F_ext")
    t = np.array([0.0, 0.5, 1.0, 2.0])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    assert np.max(np.abs(r["stuck.x"])) < 1e-4 and np.max(np.abs(r["stuck.v"])) < 2e-5
    np.testing.assert_allclose(r["sliding.v"], 3.5 * (1.0 - np.exp(-t)), atol=2e-3)


def test_a_force_source_behind_a_damper_drives_a_mass_to_its_terminal_velocity() -> None:
    """ForceSource with its input B (Hopsan's MechanicTranslationalCSource, in_z = B): F = u - B v, so a mass m
    it pushes with u from rest moves at (u/B)(1 - exp(-B t/m)); with B unconnected (0) the force is u whatever
    the motion."""
    u, b, m = 20.0, 5.0, 2.0
    s = System("damped push")
    s.add(c.ForceSource("f"))
    s.add(c.Constant("U", unit="N", value=u))
    s.add(c.Constant("Bc", unit="N*s/m", value=b))
    s.add(c.Mass("m", m=m, B=0.0, incline=0.0))
    s.connect("U.y", "f.u")
    s.connect("Bc.y", "f.B")
    s.connect("f.P", "m.P1")  # pushes end 1 in: the mass moves along +x
    t = np.array([0.0, 0.3, 1.0, 3.0])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["m.v"], u / b * (1.0 - np.exp(-b * t / m)), atol=1e-6)
    np.testing.assert_allclose(r["f.F"], u * np.exp(-b * t / m), atol=1e-5)  # the damper takes B v of it


def test_a_rigid_link_between_two_springs_sits_where_their_forces_balance() -> None:
    """RigidLink (Hopsan's MechanicTranslationalLosslessConnector): massless, so the springs k1 and k2 on either
    side carry one force; pulled at V by a velocity source through k1, with k2 to a fixed point, its end 2 moves
    at k1 V/(k1 + k2) (its end 1 back at the same rate, from its length) and both springs carry the tension
    k1 k2 V t/(k1 + k2)."""
    k1, k2, vel = 3000.0, 1000.0, 0.2
    s = System("series springs")
    s.add(c.VelocitySource("pull"))
    s.add(c.Constant("V", unit="m/s", value=-vel))  # the source's port moving inward: spring a's end outward
    s.add(c.Spring("a", k_spring=k1))
    s.add(c.RigidLink("link", length=0.3, x0=0.0))
    s.add(c.Spring("b", k_spring=k2, e0=-0.3))  # relaxed at the start: the link's end 1 at 0.3 m outward
    s.add(c.FixedPosition("g"))
    s.connect("V.y", "pull.u")
    s.connect("pull.P", "a.P1")
    s.connect("a.P2", "link.P2")
    s.connect("link.P1", "b.P1")
    s.connect("b.P2", "g.P")
    t = np.array([0.0, 0.5, 1.0])
    r = s.simulate(t_eval=t, accuracy=1e-8)
    np.testing.assert_allclose(r["link.x"], k1 / (k1 + k2) * vel * t, atol=1e-9)
    np.testing.assert_allclose(r["link.v"][1:], k1 / (k1 + k2) * vel, rtol=1e-6)
    np.testing.assert_allclose(r["link.x_P1"], 0.3 - k1 / (k1 + k2) * vel * t, atol=1e-9)
    np.testing.assert_allclose(r["a.F"], r["b.F"], atol=1e-6)  # one force through both
    np.testing.assert_allclose(r["a.F"], k1 * k2 / (k1 + k2) * vel * t, rtol=1e-6, atol=1e-9)


def test_a_pressure_source_behind_a_resistance_loses_z_q() -> None:
    """PressureSource with option impedance = "input" (Hopsan's HydraulicCSource, its wave variable and impedance
    inputs): p = u - Z Q. Into a laminar orifice G to a tank, Q = G p, so p = u/(1 + Z G), whatever Z does: here
    Z steps from 1e9 to 3e9 Pa s/m³ at 0.5 s (p from u/2 to u/4)."""
    s = System("behind a resistance")
    s.add(c.PressureSource("src", impedance="input"))
    s.add(c.Constant("U", unit="Pa", value=1e6))
    s.add(c.Step("Zc", unit="Pa*s/m^3", offset=1e9, amplitude=2e9, t_step=0.5))
    s.add(c.LaminarOrifice("o", G_lam=1e-9))
    s.add(c.Tank("t"))
    s.connect("U.y", "src.u")
    s.connect("Zc.y", "src.Z")
    s.connect("src.P", "o.A")
    s.connect("o.B", "t.P")
    r = s.simulate(t_eval=[0.0, 0.25, 0.75, 1.0])
    np.testing.assert_allclose(r["src.p"], [5e5, 5e5, 2.5e5, 2.5e5], rtol=1e-9)
    np.testing.assert_allclose(r["o.Q"], 1e-9 * r["src.p"], rtol=1e-9)
    assert "Z" not in c.PressureSource("ideal").INPUTS  # an ideal source by default
