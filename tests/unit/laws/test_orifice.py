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
