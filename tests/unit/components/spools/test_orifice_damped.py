"""The orifice-damped massless spool (hydroservo.components.spools.orifice_damped) against its closed forms."""

from __future__ import annotations

import numpy as np
import pytest

import hydroservo as hs
from hydroservo import components as c


def _rig(spool: c.SpoolOrificeDamped, p1: float, p2: float, p_c: float) -> hs.System:
    s = hs.System("poppet")
    s.add(spool)
    for name, p in (("s1", p1), ("s2", p2), ("sc", p_c)):
        s.add(c.Tank(name, p=p))
    s.connect("s1.P", f"{spool.name}.P1")
    s.connect("s2.P", f"{spool.name}.P2")
    s.connect("sc.P", f"{spool.name}.C")
    return s


def test_the_spool_moves_as_its_orifice_lets_the_chamber_oil_out_until_its_spring_balances() -> None:
    """At constant pressures the chamber's excess y = (A_1 p_1 + A_2 p_2 - F_0 - k x)/A_c - p_C falls as
    dy/dt = -(k/A_c) (K_d/A_c) sqrt(y): sqrt(y) = sqrt(y_0) - b c t/2 (b = k/A_c, c = K_d/A_c), the spool at
    rest once y = 0, where the spring balances (x = a/b); the orifice's flow A_c dx/dt leaves through C."""
    a_1, a_2, a_c, f_0, k, k_d = 5e-5, 3e-5, 8e-5, 100.0, 3e4, 5e-9
    spool = c.SpoolOrificeDamped("sp", A_1=a_1, A_2=a_2, A_c=a_c, F_0=f_0, k_s=k, K_d=k_d, p_tr=1e-3, x_max=0.01)
    p1, p2, p_c = 30e5, 20e5, 1e5
    a = (a_1 * p1 + a_2 * p2 - f_0) / a_c - p_c
    b, cc = k / a_c, k_d / a_c
    t_rest = 2 * np.sqrt(a) / (b * cc)
    t = np.array([0.1, 0.4, 0.8]) * t_rest
    r = _rig(spool, p1, p2, p_c).simulate(t_eval=[0.0, *t, 3 * t_rest], accuracy=1e-8)
    root = np.sqrt(a) - b * cc * t / 2
    np.testing.assert_allclose(r["sp.xv"][1:4], (a - root**2) / b, rtol=1e-5)
    np.testing.assert_allclose(r["sp.QC"][1:4], k_d * root, rtol=1e-4)
    assert r["sp.xv"][4] == pytest.approx(a / b, rel=1e-6)
    assert np.all(np.asarray(r["sp.Q1"]) == 0.0) and np.all(np.asarray(r["sp.Q2"]) == 0.0)


@pytest.mark.parametrize("damping_flow", ["port", "none"])
def test_without_a_spring_it_travels_at_a_constant_speed_to_its_stop_and_rests_there(damping_flow: str) -> None:
    """k = 0: dx/dt = K_d sqrt(p_1 A_1/A_c - p_C)/A_c (regularised: dp/(dp^2 + p_tr^2)^(1/4)) from x0 down to
    x_min, where it stays; the orifice's flow goes on at the stop (Hopsan's), or is taken from no port."""
    spool = c.SpoolOrificeDamped("sp", damping_flow=damping_flow, A_1=1e-4, A_c=1e-4, K_d=2e-8, p_tr=100.0,
                                 x_min=-0.01, x_max=0.01, x0=0.005)
    dp = 1e5 - 10e5
    speed = 2e-8 * dp / (dp**2 + 100.0**2) ** 0.25 / 1e-4
    t_stop = -0.015 / speed
    r = _rig(spool, 1e5, 0.0, 10e5).simulate(t_eval=[0.0, 0.5 * t_stop, 2 * t_stop], accuracy=1e-8)
    assert r["sp.xv"][1] == pytest.approx(0.005 + speed * 0.5 * t_stop, rel=1e-6)
    assert r["sp.xv"][2] == pytest.approx(-0.01, abs=1e-8)
    q = 2e-8 * dp / (dp**2 + 100.0**2) ** 0.25 if damping_flow == "port" else 0.0
    np.testing.assert_allclose(r["sp.QC"], [q, q, q], rtol=1e-9)
