"""Two masses that slide on each other (Hopsan's MechanicM2load1D), against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c


def _pair(f2: float, f3: float, friction: float) -> System:
    s = System("pair")
    s.add(c.MassPair("p", m1=2.0, m2=3.0, F_c0=friction, v_reg=1e-6, c_s=1e-3))
    for name, force, port in (("f2", f2, "P2"), ("f3", f3, "P3")):
        s.add(c.ForceSource(name))
        s.add(c.Constant(f"{name}_u", unit="N", value=force))
        s.connect(f"{name}_u.y", f"{name}.u")
        s.connect(f"{name}.P", f"p.{port}")
    return s


def test_a_force_between_the_masses_moves_them_apart_about_their_still_centre_of_gravity() -> None:
    """A force source pushing on P3 (inward: F3 = -6 N outward): μ ẍ3 = F3 with μ = m1 m2/(m1 + m2) = 1.2 kg,
    x3 = F3 t²/(2μ); the centre of gravity stays, so mass 1 moves by m2/(m1 + m2) x3 and mass 2 by
    -m1/(m1 + m2) x3 (end 1 counted outward, along -x)."""
    t = np.array([0.0, 0.5, 1.0])
    r = _pair(0.0, 6.0, 0.0).simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    x3 = -6.0 * t**2 / (2 * 1.2)
    np.testing.assert_allclose(r["p.x3"], x3, atol=1e-8)
    np.testing.assert_allclose(r["p.xt"], 0.0, atol=1e-10)
    np.testing.assert_allclose(r["p.x1"], -0.6 * x3, atol=1e-8)
    np.testing.assert_allclose(r["p.x2"], -0.4 * x3, atol=1e-8)


def test_a_force_on_one_end_carries_both_masses_while_the_friction_between_them_holds() -> None:
    """A force source pushing on end 2 with 10 N (F2 = -10 N outward): the pair accelerates at F2/(m1 + m2) =
    -2 m/s²; mass 1 needs m1·2 = 4 N from the friction between them: held by 5 N, they move as one; with 3 N,
    mass 1 lags against it: μ ẍ3 = -(m1 F2)/(m1 + m2) - F_c0 = 4 - 3 N."""
    t = np.array([0.0, 0.5, 1.0])
    held = _pair(10.0, 0.0, 5.0).simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    np.testing.assert_allclose(held["p.x2"], -(t**2), atol=1e-6)
    assert np.max(np.abs(held["p.v3"])) < 1e-5
    slides = _pair(10.0, 0.0, 3.0).simulate(t_eval=t, accuracy=1e-9, method="cvodes")
    assert slides["p.x3"][-1] == pytest.approx(1.0 / 1.2 / 2.0, rel=1e-3)
