"""A vehicle driven at its wheels (Hopsan's MechanicVehicle1D), against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c


def _vehicle(torque: float, CdA: float) -> System:
    s = System("vehicle")
    s.add(c.Vehicle("car", M=10.0, r_wheel=0.5, c_r=0.02, CdA=CdA, rho_air=1.25, g=10.0, v_reg=1e-6))
    s.add(c.TorqueSource("drive"))
    s.add(c.Constant("T", unit="N*m", value=torque))
    s.connect("T.y", "drive.u")
    s.connect("drive.P", "car.P1")
    return s


def test_a_vehicle_accelerates_against_its_rolling_resistance_and_settles_at_its_drag_limited_speed() -> None:
    """A torque source twisting the wheels' shaft with 5 N m (its outward torque presses against the port's turning
    at -v/r: it drives the vehicle forward with 5/0.5 = 10 N) against rolling resistance c_r M g = 2 N: without
    drag v = 0.8 t; with drag the speed settles at √(2·8/(ρ CdA)); below the rolling resistance it stays."""
    t = np.array([0.0, 1.0, 2.0])
    r = _vehicle(5.0, 0.0).simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    np.testing.assert_allclose(r["car.v"], 0.8 * t, atol=1e-6)
    np.testing.assert_allclose(r["car.omega"], -0.8 * t / 0.5, atol=1e-6)
    r = _vehicle(5.0, 0.4).simulate(t_end=200.0, accuracy=1e-9, method="cvodes")
    assert r["car.v"][-1] == pytest.approx(math.sqrt(2 * 8.0 / (1.25 * 0.4)), rel=1e-5)
    assert r["car.F_d"][-1] == pytest.approx(8.0, rel=1e-5)
    r = _vehicle(0.5, 0.4).simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    assert np.max(np.abs(r["car.v"])) < 1e-5
