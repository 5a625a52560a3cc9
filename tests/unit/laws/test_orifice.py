"""The orifice law (hydroservo.laws.orifice): turbulent, regularised, transition pressure, catalogue coefficient."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from hydroservo.errors import ParameterError
from hydroservo.laws import orifice


def test_unregularised_law_is_turbulent_law() -> None:
    dp = np.array([-50e5, -1e5, 0.0, 2e5, 70e5])
    q = orifice.orifice_flow(1e-5, dp, 870.0, Cd=0.6)
    np.testing.assert_allclose(q, 0.6 * 1e-5 * np.sqrt(2 * np.abs(dp) / 870.0) * np.sign(dp))


def test_regularised_law_approaches_turbulent_law() -> None:
    p_tr = 1e5
    dp = np.geomspace(3e5, 3e7, 20)
    reg = orifice.orifice_flow(1e-5, dp, 870.0, 0.6, p_tr)
    turb = orifice.orifice_flow(1e-5, dp, 870.0, 0.6)
    rel = np.abs(reg / turb - 1.0)
    # exact bound of the relative deviation: 1 - (1 + (p_tr/dp)^2)^(-1/4) <= (p_tr/dp)^2 / 4
    assert np.all(rel <= (p_tr / dp) ** 2 / 4 * (1 + 1e-12))
    assert rel[-1] < 1e-5


def test_regularised_law_is_smooth_odd_and_increasing() -> None:
    dp = ca.SX.sym("dp")
    q = orifice.orifice_flow(1e-5, dp, 870.0, 0.6, 2e5)
    f = ca.Function("f", [dp], [q, ca.jacobian(q, dp)])
    grid = np.concatenate([np.linspace(-5e6, 5e6, 2001), [0.0, 1e-9, -1e-9]])
    vals, slopes = (np.asarray(v).ravel() for v in f.map(grid.size)(grid))
    assert np.all(np.isfinite(slopes))
    assert np.all(slopes > 0)  # strictly increasing, finite slope at null
    np.testing.assert_allclose(np.asarray(f(-grid[:5])[0]).ravel(), -vals[:5])
    # linear (laminar) at small drops, slope Cd A sqrt(2/rho) / sqrt(p_tr)
    assert float(f(0.0)[1]) == pytest.approx(0.6 * 1e-5 * np.sqrt(2 / 870.0) / np.sqrt(2e5))


def test_transition_pressure_is_inverse_of_flow_number() -> None:
    p_tr = orifice.transition_pressure(0.8e-3, 850.0, 20e-6, 1000.0)
    assert orifice.flow_number(0.8e-3, p_tr, 850.0, 20e-6) == pytest.approx(1000.0)


def test_catalogue_flow_coefficient() -> None:
    cv = orifice.flow_coefficient_from_catalogue(40 / 60000, 35e5, 1e-3)
    q = cv * 1e-3 * np.sqrt(35e5)
    assert q == pytest.approx(40 / 60000)
    with pytest.raises(ParameterError, match="x_max"):
        orifice.flow_coefficient_from_catalogue(1e-3, 35e5, 0.0)


def test_a_round_ports_area_is_the_circular_segment_and_its_width_the_derivative() -> None:
    """round_port_area against the segment's area from its central angle, (d^2/8)(phi - sin phi) with
    cos(phi/2) = 1 - 2x/d; its numerical derivative is round_port_width; the small-opening limit
    (4/3) sqrt(d x) x; closed below 0, the whole circle beyond d; NumPy and CasADi alike."""
    d = 0.012
    x = np.linspace(0.0, d, 41)[1:-1]
    phi = 2.0 * np.arccos(1.0 - 2.0 * x / d)
    np.testing.assert_allclose(orifice.round_port_area(x, d), d * d / 8.0 * (phi - np.sin(phi)), rtol=1e-9)
    dx = 1e-9
    slope = (orifice.round_port_area(x + dx, d) - orifice.round_port_area(x - dx, d)) / (2 * dx)
    np.testing.assert_allclose(slope, orifice.round_port_width(x, d), rtol=1e-5)
    small = np.array([1e-7, 1e-6])
    np.testing.assert_allclose(orifice.round_port_area(small, d), 4.0 / 3.0 * np.sqrt(d * small) * small, rtol=1e-3)
    outside = np.array([-1.0, 0.0, d, 1.0])
    np.testing.assert_allclose(orifice.round_port_area(outside, d), [0.0, 0.0, np.pi * d * d / 4, np.pi * d * d / 4])
    np.testing.assert_allclose(orifice.round_port_width(outside, d), 0.0, atol=0.0)
    xs = ca.SX.sym("x")
    area = ca.Function("a", [xs], [orifice.round_port_area(xs, d)])
    width = ca.Function("w", [xs], [orifice.round_port_width(xs, d)])
    assert float(area(0.3 * d)) == pytest.approx(float(orifice.round_port_area(0.3 * d, d)), rel=1e-14)
    assert float(width(0.3 * d)) == pytest.approx(float(orifice.round_port_width(0.3 * d, d)), rel=1e-14)
