"""The centrifugal pumps (hydroservo.components.CentrifugalPump, CentrifugalPumpInertia; Hopsan's
HydraulicCentrifugalPump and HydraulicCentrifugalPumpJ) against closed forms: the flow where Euler's impeller
pressure meets the pump's losses, the torque, and the speed at which a drive's torque balances it."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

import hydroservo as hs
from hydroservo import components as c

RHO, D, B, KL, AP = 860.0, 0.3, 0.03, 0.1, 1e-3


def _circuit(pump: c.Component, p_out: float) -> hs.System:
    s = hs.System("centrifugal")
    s.add(pump)
    s.add(c.Tank("tank"))
    s.add(c.Tank("load", p=p_out))
    s.connect("tank.P", f"{pump.name}.P1")
    s.connect(f"{pump.name}.P2", "load.P")
    return s


def _flow(omega: float, dp: float, beta2: float, kcp: float, slip_density: float) -> tuple[float, float]:
    """The delivered flow and the impeller's: k Q_i² + c (Q_i + L) = ρ U2² − Δp with L = −Kcp Δp leaking back,
    k = kl ρ/(2 Ap²), c = ρ_s U2 cot β2/(π d b) (the turbulent law; the laminar part, below 430 Pa, is far off)."""
    u2 = omega * D / 2.0
    k = KL * RHO / (2.0 * AP**2)
    cc = slip_density * u2 / (np.pi * D * B * np.tan(beta2))
    leak = -kcp * dp
    q_i = (-cc + np.sqrt(cc**2 + 4.0 * k * (RHO * u2**2 - dp - cc * leak))) / (2.0 * k)
    return q_i + leak, q_i


@pytest.mark.parametrize(("slip", "beta2"), [("euler", 1.0), ("hopsan", 1.57)])
def test_the_flow_is_where_eulers_pressure_meets_the_losses_and_the_shaft_takes_the_power_over_the_speed(
    slip: str, beta2: float
) -> None:
    """At 126 rad/s against 2 bar: Q solves Euler's law through the losses (Hopsan's slip term has ρ² where
    Euler's has ρ: its blades nearly radial here, as in its test), the torque is B ω + (Δp + kl ρ Q²/(2 Ap²))
    Q_i/(ω + 0.001)."""
    pump = c.CentrifugalPump("pump", omegap=126.0, beta2=beta2, rho=RHO, d=D, b=B, kl=KL, Ap=AP, Kcp=2e-9, Bp=0.2,
                             slip=slip)
    r = _circuit(pump, 2e5).simulate(t_eval=[0.0, 0.01], method="cvodes")
    q, q_i = _flow(126.0, 2e5, beta2, 2e-9, RHO if slip == "euler" else RHO**2)
    assert r["pump.Q2"][-1] == pytest.approx(q, rel=1e-5) and r["pump.Q1"][-1] == r["pump.Q2"][-1]
    torque = 0.2 * 126.0 + (2e5 + KL * RHO * q**2 / (2.0 * AP**2)) * q_i / 126.001
    assert r["pump.torp"][-1] == pytest.approx(torque, rel=1e-5)
    assert r["pump.Pin"][-1] == pytest.approx(torque * 126.0, rel=1e-5)
    assert r["pump.Pout"][-1] == pytest.approx(2e5 * q, rel=1e-5)


def test_a_pump_at_rest_passes_nothing_and_a_pump_below_its_floor_draws_nothing() -> None:
    """At rest between equal pressures no flow; with ``inlet = "floor"`` and the inlet below p_floor, none either
    (the gate of :func:`~hydroservo.laws.displacement.floored_port_flow`), where it would deliver freely."""
    r = _circuit(c.CentrifugalPump("pump", omegap=0.0), 0.0).simulate(t_eval=[0.0, 0.01], method="cvodes")
    assert r["pump.Q2"][-1] == 0.0 and r["pump.torp"][-1] == 0.0
    free = _circuit(c.CentrifugalPump("pump", omegap=100.0), 0.0).simulate(t_eval=[0.0, 0.01], method="cvodes")
    assert free["pump.Q2"][-1] > 0.01
    floor = _circuit(c.CentrifugalPump("pump", omegap=100.0, inlet="floor", p_floor=1e5), 0.0)
    assert floor.simulate(t_eval=[0.0, 0.01], method="cvodes")["pump.Q2"][-1] == 0.0


def test_a_pump_turned_through_its_shaft_settles_where_the_drives_torque_balances_its_own() -> None:
    """CentrifugalPumpInertia with radial blades between equal pressures, turned by a torque of 100 N m: its
    impeller passes Q = Ap √(2/kl) U2 and gives the fluid ρ U2² Q, so it settles where 100 = Bp ω + ρ U2³ Ap
    √(2/kl)/(ω + 0.001); a drive's positive torque turns it forwards (its shaft counted into the pump)."""
    s = _circuit(c.CentrifugalPumpInertia("pump", beta2=np.pi / 2, rho=RHO, d=D, b=B, kl=KL, Ap=AP, Kcp=0.0,
                                          Bp=0.05, Jp=0.1), 0.0)
    s.add(c.TorqueSource("drive"))
    s.add(c.Constant("T", value=100.0))
    s.connect("drive.P", "pump.Pmr1")
    s.connect("T.y", "drive.u")
    r = s.simulate(t_eval=[0.0, 3.0], method="cvodes")

    def balance(w: float) -> float:
        u2 = w * D / 2.0
        return 0.05 * w + RHO * u2**3 * AP * np.sqrt(2.0 / KL) / (w + 0.001) - 100.0

    omega = brentq(balance, 1.0, 500.0)
    assert r["pump.omega"][-1] == pytest.approx(omega, rel=1e-5)
    assert r["pump.Q2"][-1] == pytest.approx(AP * np.sqrt(2.0 / KL) * omega * D / 2.0, rel=1e-5)
