"""The rotational inertia's Stribeck friction (Hopsan's MechanicRotationalInertiaWithCoulombFriction), against its
closed form."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c


def _spun(torque: float) -> System:
    s = System("friction")
    s.add(c.RotationalInertia("j", J=0.5, B_rot=2.0, T_c0=5.0, T_s0=3.0, omega_s=1e-3, omega_reg=1e-6))
    s.add(c.TorqueSource("t"))
    s.add(c.Constant("T", unit="N*m", value=torque))
    s.connect("t.P", "j.P1")
    s.connect("T.y", "t.u")
    return s


def test_an_inertia_with_coulomb_friction_sticks_below_its_static_torque_and_slides_against_the_kinetic_one() -> None:
    """Twisted by 7 N m, below T_c0 + T_s0 = 8 N m, it stays (creeping at omega_reg atanh(7/8)); by 10 N m it turns
    against T_c0 = 5 N m and B_rot = 2 N m s/rad: J ω' = 10 - 5 - 2 ω, ω = 2.5 (1 - exp(-4 t)) once past the
    Stribeck region (a few omega_s)."""
    t = np.array([0.0, 0.25, 0.5, 1.0])
    stuck = _spun(7.0).simulate(t_eval=t, accuracy=1e-8, method="cvodes")
    assert np.max(np.abs(stuck["j.omega"])) < 1e-5
    turns = _spun(10.0).simulate(t_eval=t, accuracy=1e-8, method="cvodes")
    np.testing.assert_allclose(turns["j.omega"][1:], 2.5 * (1.0 - np.exp(-4.0 * t[1:])), rtol=2e-3)
    assert turns["j.omega"][-1] == pytest.approx(2.5 * (1.0 - np.exp(-4.0)), rel=2e-4)
