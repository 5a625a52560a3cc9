"""The wall with a free end (Hopsan's MechanicFreeLengthWall): a unilateral contact, against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.laws.stops import contact_residual


def _ball(h: float, k: float = 1e4, m: float = 1.0, g: float = 10.0) -> System:
    """A mass pushed by g m towards a spring whose free end is h above a wall (no damping anywhere)."""
    s = System("ball")
    s.add(c.Mass("m", m=m, B=0.0, incline=0.0, x0=0.0, length=0.0))
    s.add(c.Spring("k", k_spring=k, e0=-h))  # relaxed at the start: the end at h, the mass's end 2 at 0
    s.add(c.Wall("w", x0=h))
    s.add(c.ForceSource("g"))
    s.add(c.Constant("G", value=m * g))
    s.connect("G.y", "g.u")
    s.connect("g.P", "m.P1")  # pushes end 1 in: the mass moves along +x, towards the wall
    s.connect("m.P2", "k.P2")
    s.connect("k.P1", "w.P")
    return s


def test_a_ball_falls_freely_onto_the_wall_and_bounces_back_elastically() -> None:
    """Free fall for t_1 = √(2h/g) (the spring's free end moves with the mass and takes no force); then a
    spring contact of ω = √(k/m) about the static compression mg/k, which lets go after
    (π + 2 atan(g/(ω v_1)))/ω with the impact speed v_1 = √(2gh) reversed."""
    h, k, m, g = 0.05, 1e4, 1.0, 10.0
    t1, v1, w = math.sqrt(2 * h / g), math.sqrt(2 * g * h), math.sqrt(k / m)
    t2 = t1 + (math.pi + 2 * math.atan(g / (w * v1))) / w
    t = np.array([0.5 * t1, 0.5 * (t1 + t2), t2 + 0.02])
    r = _ball(h, k, m, g).simulate(t_eval=np.concatenate([[0.0], t]), accuracy=1e-8, method="cvodes")
    x, v, end = r["m.x"][1:], r["m.v"][1:], r["w.x"][1:]
    assert x[0] == pytest.approx(0.5 * g * (0.5 * t1) ** 2, rel=1e-6)
    assert end[0] == pytest.approx(h - x[0], rel=1e-6) and r["w.v"][1] == pytest.approx(-g * 0.5 * t1, rel=1e-4)
    assert r["k.F"][1] == pytest.approx(0.0, abs=1e-9)  # free: no force through the spring
    assert end[1] == pytest.approx(0.0, abs=1e-9) and r["w.v"][2] == pytest.approx(0.0, abs=1e-4)  # held
    assert -r["k.F"][2] == pytest.approx(k * (x[1] - h), rel=1e-6)  # compressed by what passed the wall
    # after the contact: the impact speed reversed, the parabola back up
    tf = t[2] - t2
    assert v[2] == pytest.approx(-v1 + g * tf, rel=1e-5)
    assert r["k.F"][3] == pytest.approx(0.0, abs=1e-9)


def test_a_damped_free_end_pushed_is_a_spring_and_damper_in_series() -> None:
    """Away from the wall, B v = F: a spring k pushed at V onto a free end on a damper B takes the force
    B V (1 - exp(-k t/B)) (Maxwell's element), and its end moves towards the wall at F/B."""
    k, b, vel = 1e3, 10.0, 0.2
    s = System("maxwell")
    s.add(c.VelocitySource("pull"))
    s.add(c.Constant("V", unit="m/s", value=vel))
    s.add(c.Spring("k", k_spring=k))
    s.add(c.Wall("w", B=b, x_stop=-1.0))  # the wall 1 m away: the end stays free
    s.connect("V.y", "pull.u")
    s.connect("pull.P", "k.P2")
    s.connect("k.P1", "w.P")
    t = np.array([0.005, 0.01, 0.05])
    r = s.simulate(t_eval=np.concatenate([[0.0], t]), accuracy=1e-8, method="cvodes")
    assert -r["k.F"][1:] == pytest.approx(b * vel * (1 - np.exp(-k * t / b)), rel=1e-4)  # a compression
    assert -r["w.v"][-1] == pytest.approx(vel * (1 - math.exp(-k * t[-1] / b)), rel=1e-4)
    assert r["w.x"][-1] > -1.0  # not yet at the wall


def test_the_contact_residual_vanishes_where_signorinis_conditions_hold() -> None:
    assert float(contact_residual(0.1, 0.0, 1e-6)) == 0.0
    assert float(contact_residual(0.0, 10.0, 1e-6)) == 0.0
    assert float(contact_residual(0.1, 10.0, 1e-6)) > 0.0  # away, yet pushed: not a solution
    assert float(contact_residual(-0.1, 0.0, 1e-6)) < 0.0  # through the wall
