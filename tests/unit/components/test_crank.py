"""A crank (Hopsan's MechanicJLink): a link on a rotating inertia moving a translational port, against closed
forms."""

from __future__ import annotations

import numpy as np

from hydroservo import System
from hydroservo import components as c


def test_a_crank_turned_by_a_torque_moves_its_link_end_along_r_sin_theta_and_a_force_there_turns_it_back() -> None:
    """Turned by 2 N m against B_rot = 4: ω = 0.5 (1 - exp(-4 t/J)), x = x_link - r sin θ, v = -r cos θ ω. A
    force source pushing on the link's end with 10 N (F1 = -10 N outward) at θ = 0 turns it as J ω' = 10 r."""
    s = System("crank")
    s.add(c.Crank("k", J=0.5, B_rot=4.0, r_link=0.2, x_link=0.3))
    s.add(c.TorqueSource("t"))
    s.add(c.Constant("T", unit="N*m", value=2.0))
    s.connect("T.y", "t.u")
    s.connect("t.P", "k.P2")
    t = np.array([0.0, 0.1, 0.5])
    r = s.simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    omega = -0.5 * (1.0 - np.exp(-8.0 * t))  # the source's outward torque presses against the port's turning
    theta = -0.5 * (t - (1.0 - np.exp(-8.0 * t)) / 8.0)
    np.testing.assert_allclose(r["k.omega"], omega, atol=1e-7)
    np.testing.assert_allclose(r["k.x"], 0.3 - 0.2 * np.sin(theta), atol=1e-7)
    np.testing.assert_allclose(r["k.v"], -0.2 * np.cos(theta) * omega, atol=1e-7)
    s = System("pushed")
    s.add(c.Crank("k", J=0.5, B_rot=0.0, r_link=0.2))
    s.add(c.ForceSource("f"))
    s.add(c.Constant("F", unit="N", value=10.0))
    s.connect("F.y", "f.u")
    s.connect("f.P", "k.P1")
    r = s.simulate(t_eval=[0.0, 1e-3], accuracy=1e-10, method="cvodes")
    assert abs(r["k.omega"][1] - 10.0 * 0.2 / 0.5 * 1e-3) < 1e-8


def test_a_rack_on_its_pinion_moves_as_r_theta_and_a_force_on_the_rack_turns_it_through_r() -> None:
    """Option link = "rack" (Hopsan's MechanicRackAndPinion): a force of 10 N on the rack (r 0.2 m, J 0.5 kg m²,
    B_rot 4 N m s/rad) turns the pinion as J ω' = 10 r - B ω: ω = 0.5 (1 - exp(-8 t)), the rack at
    x = x_link - r θ far beyond where the crank's sin θ would differ, moving at -r ω."""
    s = System("rack")
    s.add(c.Crank("k", J=0.5, B_rot=4.0, r_link=0.2, x_link=0.3, link="rack"))
    s.add(c.ForceSource("f"))
    s.add(c.Constant("F", unit="N", value=10.0))
    s.connect("F.y", "f.u")
    s.connect("f.P", "k.P1")
    t = np.array([0.0, 0.1, 0.5, 5.0])
    r = s.simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    omega = 0.5 * (1.0 - np.exp(-8.0 * t))
    theta = 0.5 * (t - (1.0 - np.exp(-8.0 * t)) / 8.0)
    np.testing.assert_allclose(r["k.omega"], omega, atol=1e-7)
    np.testing.assert_allclose(r["k.x"], 0.3 - 0.2 * theta, atol=1e-7)
    np.testing.assert_allclose(r["k.v"], -0.2 * omega, atol=1e-7)
