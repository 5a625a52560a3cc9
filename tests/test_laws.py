"""Published laws against analytic values and the seeds' own numbers."""

from __future__ import annotations

import warnings

import casadi as ca
import numpy as np
import pytest

from hydroservo.errors import ParameterError
from hydroservo.laws import fluid as fluids
from hydroservo.laws import four_way, orifice
from hydroservo.laws.friction import stribeck

BAR = 1e5


# -- Stribeck friction, seed 001 Table 5.2 -------------------------------------
# Simulated column of Table 5.2 with c_s = 0.01, F_v = 280, F_c0 = 78, F_s0 = 5.
# The table prints two decimals, so the tolerance is half a unit in the last place.
TABLE_5_2 = [(0.165, 124.20), (0.123, 112.44), (0.078, 99.84), (0.048, 91.48), (0.022, 84.71), (0.01, 82.64)]


@pytest.mark.parametrize(("v", "force"), TABLE_5_2)
def test_stribeck_reproduces_table_5_2(v: float, force: float) -> None:
    assert stribeck(v, 280.0, 78.0, 5.0, 0.01) == pytest.approx(force, abs=0.005)


def test_stribeck_is_odd_and_smoothing_converges() -> None:
    v = np.linspace(-0.2, 0.2, 41)
    exact = stribeck(v, 280.0, 78.0, 5.0, 0.01)
    np.testing.assert_allclose(exact, -stribeck(-v, 280.0, 78.0, 5.0, 0.01))
    smooth = stribeck(v, 280.0, 78.0, 5.0, 0.01, v_reg=1e-5)
    mask = np.abs(v) > 1e-3
    np.testing.assert_allclose(smooth[mask], exact[mask], rtol=1e-12)


# -- bulk modulus ----------------------------------------------------------------
def test_lee_bulk_modulus_values() -> None:
    # E'(p) = 0.5 * 18000 bar * log10(90 p/280 bar + 3), seed 001 eq. 3.2 (log restored)
    assert fluids.bulk_modulus_lee(0.0) == pytest.approx(0.5 * 18000 * BAR * np.log10(3.0))
    assert fluids.bulk_modulus_lee(280 * BAR) == pytest.approx(0.5 * 18000 * BAR * np.log10(93.0))
    p = np.linspace(0, 300 * BAR, 50)
    assert np.all(np.diff(fluids.bulk_modulus_lee(p)) > 0)


@pytest.mark.parametrize("T", [20.0, 50.0, 90.0])
def test_eggerth_at_table_temperatures(T: float) -> None:
    k1, k2, lam = fluids.EGGERTH_TABLE[T]
    p = 150 * BAR
    expected = 1.0 / (k1 + k2 * (p / (10 * BAR)) ** (-lam))
    assert fluids.bulk_modulus_eggerth(p, temperature=T) == pytest.approx(expected, rel=1e-14)


def test_eggerth_interpolates_and_refuses_extrapolation() -> None:
    k1, k2, lam = fluids.eggerth_coefficients(35.0)
    assert k1 == pytest.approx((4.943e-10 + 5.469e-10) / 2)
    assert lam == pytest.approx((1.480 + 1.258) / 2)
    e = [fluids.bulk_modulus_eggerth(200 * BAR, temperature=T) for T in (20.0, 35.0, 50.0)]
    assert e[0] > e[1] > e[2]  # stiffer when colder (Fig. 3.1)
    with pytest.raises(ParameterError, match="temperature: 120"):
        fluids.eggerth_coefficients(120.0)


def test_wave_speed_and_line_length() -> None:
    c = fluids.wave_speed(1.6e9, 870.0)
    assert c == pytest.approx(np.sqrt(1.6e9 / 870.0))
    assert fluids.max_line_length(c, 100.0) == pytest.approx(c / 1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert fluids.check_line_length(0.5, c, 100.0)
    with pytest.warns(UserWarning, match="exceeds c/\\(10 f_max\\)"):
        assert not fluids.check_line_length(2.0, c, 100.0)


def test_density_linear() -> None:
    assert fluids.density_linear(1.5e7, 870.0, 1.5e9) == pytest.approx(870.0 * 1.01)


# -- orifice law -------------------------------------------------------------------
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


def test_four_way_valve_critical_centre_and_overlap() -> None:
    args = dict(p_S=200e5, p_T=0.0, p_A=80e5, p_B=60e5, c_v=2e-7)
    QA, QB, QS, QT = four_way.four_way_valve_flows(0.0, **args)
    assert QA == 0 and QB == 0 and QS == 0 and QT == 0
    QA, QB, QS, QT = four_way.four_way_valve_flows(3e-4, **args)
    assert QA == pytest.approx(2e-7 * 3e-4 * np.sqrt(120e5))
    assert QB == pytest.approx(-2e-7 * 3e-4 * np.sqrt(60e5))
    assert QS == pytest.approx(QA) and QT == pytest.approx(-QB)
    # overlap: dead band of x_o, then the same law shifted (seed 001 eqs. 3.19-3.21)
    over = dict(args, x_PA=1e-4, x_AT=1e-4, x_PB=1e-4, x_BT=1e-4)
    assert four_way.four_way_valve_flows(0.9e-4, **over)[0] == 0
    assert four_way.four_way_valve_flows(4e-4, **over)[0] == pytest.approx(QA)
    # underlap: both edges open at null, supply leaks to tank through the bridge
    under = dict(args, x_PA=-5e-5, x_AT=-5e-5, x_PB=-5e-5, x_BT=-5e-5)
    _, _, QS0, QT0 = four_way.four_way_valve_flows(0.0, **under)
    assert QS0 > 0 and QT0 > 0
    # reverse flow when a port is above supply (seed 003 eq. 3-18a)
    assert four_way.four_way_valve_flows(3e-4, **dict(args, p_A=250e5))[0] < 0
