"""Rotational mechanics and the motor's shaft: an inertia, torque and angular-velocity sources, each against its
closed form."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.errors import ImplausibleResultWarning, ModelError


def test_inertia_driven_by_a_torque_spins_up_to_torque_over_damping() -> None:
    """J dω/dt = T - B ω: ω = T/B (1 - exp(-B t / J)); the source at P1 twists its end outward from itself, so
    along +θ (the inertia's P1 counts along -θ), as Hopsan's torque on a Q component's node."""
    s = System("spin")
    s.add(c.RotationalInertia("j", J=0.5, B_rot=2.0))
    s.add(c.TorqueSource("t"))
    s.add(c.Constant("T", unit="N*m", value=4.0))
    s.connect("t.P", "j.P1")
    s.connect("T.y", "t.u")
    t = np.array([0.0, 0.1, 0.3, 1.0])
    r = s.simulate(t_eval=t, accuracy=1e-9)
    omega = 4.0 / 2.0 * (1.0 - np.exp(-2.0 / 0.5 * t))
    assert np.allclose(r["j.omega"], omega, atol=1e-6)
    theta = 4.0 / 2.0 * (t - 0.5 / 2.0 * (1.0 - np.exp(-2.0 / 0.5 * t)))
    assert np.allclose(r["j.theta"], theta, atol=1e-6)


def test_inertia_on_its_spring_oscillates_at_sqrt_k_over_j() -> None:
    s = System("torsion")
    s.add(c.RotationalInertia("j", J=0.02, k_rot=50.0, theta0=0.1))
    t = np.linspace(0.0, 0.5, 11)
    r = s.simulate(t_eval=t, accuracy=1e-9)
    assert np.allclose(r["j.theta"], 0.1 * np.cos(np.sqrt(50.0 / 0.02) * t), atol=1e-5)


def test_an_angular_velocity_source_integrates_its_signal_whatever_the_torque_on_it() -> None:
    """From 0.2 rad at 3 rad/s: 3.2 rad after 1 s, with a torque source of 50 N m twisting its port."""
    s = System("driven")
    s.add(c.AngularVelocitySource("w", theta0=0.2))
    s.add(c.Constant("u", unit="rad/s", value=3.0))
    s.add(c.TorqueSource("load"))
    s.add(c.Constant("T", unit="N*m", value=50.0))
    s.connect("u.y", "w.u")
    s.connect("T.y", "load.u")
    s.connect("w.P", "load.P")
    r = s.simulate(t_eval=[0.0, 1.0])
    assert r["w.x"][-1] == pytest.approx(3.2) and r["w.v"][-1] == pytest.approx(3.0)


def test_rotational_and_translational_ports_do_not_join() -> None:
    s = System("mixed")
    s.add(c.RotationalInertia("j"))
    s.add(c.ForceSource("f"))
    with pytest.raises(ModelError):
        s.connect("f.P", "j.P2")
        s.simulate(t_end=0.01)


def test_motor_shaft_loaded_by_a_torque_source_and_its_displacement_setting() -> None:
    """J dω/dt = ε D Δp - B ω - T: steady ω = (ε D Δp - T)/B; the flow in at A is ε D ω."""
    D = 50e-6 / (2.0 * np.pi)
    s = System("motor")
    s.add(c.Tank("a", p="100 bar"))
    s.add(c.Tank("b"))
    s.add(c.Motor("m", D="50 cm^3/rev", J=0.01, B_m=0.5))
    s.add(c.TorqueSource("load"))
    s.add(c.Constant("T", unit="N*m", value=20.0))
    s.add(c.Constant("eps", value=0.5))
    s.connect("a.P", "m.A")
    s.connect("m.B", "b.P")
    s.connect("load.P", "m.shaft")
    s.connect("T.y", "load.u")
    s.connect("eps.y", "m.eps")
    r = s.simulate(t_end=1.0)
    omega = (0.5 * D * 100e5 - 20.0) / 0.5
    assert r["m.omega"][-1] == pytest.approx(omega, rel=1e-6)
    assert r["m.QA"][-1] == pytest.approx(0.5 * D * omega, rel=1e-6)


def test_motor_with_a_floor_draws_no_port_below_it() -> None:
    """Turning at 100 rad/s (an inertia too large to slow) with A closed off by a volume, option floor holds A at
    its floor; free, it draws A far below vacuum."""
    def run(inlet: str) -> float:
        s = System("suck")
        s.add(c.Motor("m", D="50 cm^3/rev", J=1e9, inlet=inlet, p_floor="0 Pa_abs", omega0=100.0))
        s.add(c.Volume("v", V="0.1 L", beta_e=1e9))
        s.add(c.Tank("b"))
        s.connect("v.P", "m.A")
        s.connect("m.B", "b.P")
        return float(s.simulate(t_end=0.05)["v.p"][-1])

    assert run("floor") == pytest.approx(-101325.0, abs=200.0)
    with pytest.warns(ImplausibleResultWarning, match="below vacuum"):
        assert run("free") < -1e6


def test_an_inertia_on_a_torsional_spring_to_a_turning_source_oscillates_about_it() -> None:
    """A source turning at 2 rad/s drags an inertia through a torsional spring: relative to the source the inertia
    swings as (ω_s / ω_n) sin(ω_n t) with ω_n = √(k/J), the spring's torque k times the twist."""
    k, J, w = 200.0, 0.5, 2.0
    s = System("torsion_drive")
    s.add(c.AngularVelocitySource("src"))
    s.add(c.Constant("u", unit="rad/s", value=w))
    s.add(c.TorsionalSpring("k", k_rot=k))
    s.add(c.RotationalInertia("j", J=J))
    s.connect("u.y", "src.u")
    s.connect("src.P", "k.P1")
    s.connect("k.P2", "j.P1")
    t = np.linspace(0.0, 1.0, 21)
    r = s.simulate(t_eval=t, accuracy=1e-9)
    wn = np.sqrt(k / J)
    # the inertia's P1 faces the spring: its +θ is the source's direction, its angle lags the source's by the twist
    twist = w / wn * np.sin(wn * t)
    np.testing.assert_allclose(r["j.theta"], w * t - twist, atol=1e-6)
    np.testing.assert_allclose(r["k.F"], -k * twist, atol=1e-4)


def test_a_machine_between_pressures_drives_an_inertia_to_torque_balance() -> None:
    """J dω/dt = ε D Δp - B_m ω - B ω on a Machine turning an inertia through its shaft: ω → ε D Δp/(B_m + B); the
    flow in at A is ε D ω + C_im Δp. Reversed (ε = -1) it turns the other way."""
    D = 40e-6 / (2.0 * np.pi)
    for eps in (0.5, -1.0):
        s = System("machine")
        s.add(c.Tank("a", p="50 bar"))
        s.add(c.Tank("b"))
        s.add(c.Machine("m", D="40 cm^3/rev", C_im=1e-12, B_m=0.2))
        s.add(c.RotationalInertia("j", J=0.05, B_rot=0.3))
        s.add(c.Constant("eps", value=eps))
        s.connect("a.P", "m.A")
        s.connect("m.B", "b.P")
        s.connect("m.shaft", "j.P2")
        s.connect("eps.y", "m.eps")
        r = s.simulate(t_end=2.0)
        omega = eps * D * 50e5 / (0.2 + 0.3)
        # the inertia's P2 faces the shaft: it turns at minus the shaft's outward speed
        assert r["j.omega"][-1] == pytest.approx(-omega, rel=1e-6)
        assert r["m.QA"][-1] == pytest.approx(eps * D * omega + 1e-12 * 50e5, rel=1e-6)
        assert r["m.T"][-1] == pytest.approx(0.3 * omega, rel=1e-6)


def test_a_geared_torsional_spring_turns_its_load_at_the_ratio_and_passes_torque_over_it() -> None:
    """n_gear = ω1/ω2 = -2: a source at 3 rad/s moves end 1 outward at -3 rad/s, so end 2 (x1/n + x2 constant)
    at -1.5 rad/s outward; the damped inertia's P1 faces end 2, its +θ end 2's outward direction turned: ω = -1.5
    rad/s. Steady, end 2 holds the inertia's damping, F2 = B ω, and end 1's torque is end 2's over n."""
    s = System("gear")
    s.add(c.AngularVelocitySource("src"))
    s.add(c.Constant("u", unit="rad/s", value=3.0))
    s.add(c.TorsionalSpring("k", k_rot=5000.0, n_gear=-2.0))
    s.add(c.RotationalInertia("j", J=0.01, B_rot=0.4))
    s.connect("u.y", "src.u")
    s.connect("src.P", "k.P1")
    s.connect("k.P2", "j.P1")
    r = s.simulate(t_end=2.0)
    assert r["j.omega"][-1] == pytest.approx(-1.5, rel=1e-6)
    assert r["k.F2"][-1] == pytest.approx(0.4 * -1.5, rel=1e-6)
    assert r["k.F1"][-1] == pytest.approx(0.4 * -1.5 / -2.0, rel=1e-6)
    with pytest.raises(Exception, match="n_gear = 0"):
        c.TorsionalSpring("bad", n_gear=0.0).check()
