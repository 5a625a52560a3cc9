"""The four-chamber cylinder (hydroservo.components.FourChamberCylinder, Hopsan's HydraulicFourChamberPiston)
against closed forms: the chambers' pressures as the piston moves, the force, a chamber filled through its port,
the leakage between two chambers, and the floor a chamber holds at."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c

AREAS = {"A_1": 1e-3, "A_2": 5e-4, "A_3": 2e-4, "A_4": 1e-4}
BETA = 1e9


def _cylinder(drive: c.Component, **values: object) -> hs.System:
    """The cylinder (dead volumes 1 L, stroke 1 m, no leakage unless given) with each port fed by a flow source
    ``q1`` ... ``q4`` (0 unless set) and its rod joined to ``drive`` (outward to outward: x is minus the drive's)."""
    s = hs.System("four")
    s.add(c.FourChamberCylinder("cyl", **{**AREAS, "s_l": 1.0, "Beta_e": BETA, "B_p": 100.0, "k_stop": 0.0,
                                          "c_stop": 0.0, **{f"V_{i}": 1e-3 for i in (1, 2, 3, 4)},
                                          **{f"c_leak{i}{j}": 0.0 for i, j in ((1, 2), (1, 3), (1, 4), (2, 3),
                                                                              (2, 4), (3, 4))}, **values}))
    s.add(drive)
    s.connect("cyl.P5", f"{drive.name}.P")
    for i in (1, 2, 3, 4):
        s.add(c.FlowSource(f"q{i}", q=0.0))
        s.connect(f"q{i}.P", f"cyl.P{i}")
    return s


def _volumes(x: float) -> np.ndarray:
    """Chambers 1 and 3 grow with x, 2 and 4 with the stroke left."""
    return np.array([1e-3 + 1e-3 * x, 1e-3 + 5e-4 * (1.0 - x), 1e-3 + 2e-4 * x, 1e-3 + 1e-4 * (1.0 - x)])


def test_closed_chambers_follow_their_volumes_and_press_on_the_piston() -> None:
    """The rod driven out at 1 mm/s from x = 0.2 m, every chamber closed at 50 bar: p_i = p_0 − β ln(V_i/V_i0),
    and F = A_1 p_1 − A_2 p_2 + A_3 p_3 − A_4 p_4 − B_p v."""
    s = _cylinder(c.VelocitySource("drive", x0=-0.2), **{f"p{i}_0": 50e5 for i in (1, 2, 3, 4)})
    s.add(c.Constant("u", value=-1e-3))
    s.connect("u.y", "drive.u")
    r = s.simulate(t_eval=[0.0, 0.1], accuracy=1e-10, method="cvodes")
    p = 50e5 - BETA * np.log(_volumes(0.2001) / _volumes(0.2))
    np.testing.assert_allclose([r[f"cyl.p{i}"][-1] for i in (1, 2, 3, 4)], p, rtol=1e-7)
    np.testing.assert_allclose([r[f"cyl.V{i}"][-1] for i in (1, 2, 3, 4)], _volumes(0.2001), rtol=1e-12)
    force = 1e-3 * p[0] - 5e-4 * p[1] + 2e-4 * p[2] - 1e-4 * p[3] - 100.0 * 1e-3
    assert r["cyl.F"][-1] == pytest.approx(force, rel=1e-7)


def test_a_chamber_fills_through_its_port_and_leaks_into_the_next() -> None:
    """The rod held at x = 0.3 m: 1e-5 m³/s into chamber 3 raises it at β Q/V_3; chambers 1 and 2 at 10 and 0 bar
    joined by c_leak12 equalise as e^(−c β (1/V_1 + 1/V_2) t)."""
    s = _cylinder(c.FixedPosition("fix", x0=-0.3), c_leak12=1e-12, p1_0=10e5)
    s["q3"].set(q=1e-5)
    r = s.simulate(t_eval=[0.0, 0.05, 0.1], accuracy=1e-10, method="cvodes")
    v = _volumes(0.3)
    np.testing.assert_allclose(r["cyl.p3"], BETA * 1e-5 / v[2] * r.t, rtol=1e-7, atol=1e-3)
    rate = 1e-12 * BETA * (1.0 / v[0] + 1.0 / v[1])
    np.testing.assert_allclose(r["cyl.p1"] - r["cyl.p2"], 10e5 * np.exp(-rate * r.t), rtol=1e-7)
    assert r["cyl.p4"][-1] == 0.0


def test_a_chamber_drawn_below_its_floor_holds_there_and_rises_as_soon_as_the_piston_returns() -> None:
    """Chamber 1 (at 0 bar) expanded at 10 mm/s for 0.05 s falls to p_floor and holds there, keeping no cavity (Hopsan
    floors its chambers' waves at every step): brought back, it rises at once, to p_floor + β ln(V_max/V)."""
    s = _cylinder(c.VelocitySource("drive", x0=-0.2))
    s.add(c.Step("u", offset=-0.01, amplitude=0.02, t_step=0.05))
    s.connect("u.y", "drive.u")
    r = s.simulate(t_eval=[0.0, 0.05, 0.1], accuracy=1e-10, method="cvodes")
    floor = s["cyl"].values["p_floor"]
    assert r["cyl.p1"][1] == pytest.approx(floor)
    v = _volumes(0.2005)[0], _volumes(0.2)[0]
    assert r["cyl.p1"][2] == pytest.approx(floor + BETA * np.log(v[0] / v[1]), rel=1e-6)
