"""The first-principles servovalve's laws ([GordicND]) against hand-computed values and their own derivations."""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest
from scipy.optimize import brentq

from hydroservo.laws import armature, flapper_nozzle, orifice, torque_motor

TM = {"r": 14.5e-3, "A_p": 9e-6, "x_p0": 0.45e-3, "M_m": 586.0}  # Table 1


def test_the_linearised_torque_motor_is_the_slope_of_eq_4_at_null():
    theta, i = ca.SX.sym("theta"), ca.SX.sym("i")
    T = torque_motor.electromagnetic_torque(theta, i, N=3625, k_c=1.0, k_r=0.465, **TM)
    grad = ca.Function("g", [theta, i], [ca.jacobian(T, ca.vertcat(theta, i))])(0.0, 0.0).full().ravel()
    assert grad[1] == pytest.approx(float(torque_motor.torque_gain(N=3625, k_c=1.0, k_r=0.465, **TM)), rel=1e-12)
    assert grad[0] == pytest.approx(float(torque_motor.magnetic_spring(k_r=0.465, **TM)), rel=1e-12)
    # by hand, eq. 5: k_c N r mu_0 A_p M_m / (x_p0^2 (1 + k_r))
    K_i = 3625 * 14.5e-3 * 4e-7 * np.pi * 9e-6 * 586.0 / (0.45e-3**2 * 1.465)
    assert grad[1] == pytest.approx(K_i, rel=1e-12) and K_i == pytest.approx(1.1743, abs=1e-4)


def test_the_torque_grows_faster_than_linear_away_from_null():
    lin = torque_motor.torque_gain(N=3625, k_r=0.465, **TM) * 0.01 + torque_motor.magnetic_spring(k_r=0.465, **TM) * 2e-3
    full = torque_motor.electromagnetic_torque(2e-3, 0.01, N=3625, k_r=0.465, **TM)
    assert full > lin  # the i*theta term and the narrowing gap


def test_reluctance_constant_by_hand():
    R_mm = 10.9e-3 / (154.68e-6 * 5 * 4e-7 * np.pi) / 2.42
    R_mp0 = 0.45e-3 / (4e-7 * np.pi * 9e-6)
    k_r = torque_motor.reluctance_constant(10.9e-3, 154.68e-6, 5 * torque_motor.MU_0, 2.42, 0.27, 0.45e-3, 9e-6)
    assert float(k_r) == pytest.approx(R_mm / R_mp0 / 0.27, rel=1e-12)


@pytest.mark.parametrize("d", [0.0, 1e-7, -1e-7, 3e-7])
def test_closed_form_nozzle_pressures_solve_the_flow_balance(d):
    p_s, p_d, a, b, c = 210e5, 12e5, 3.1e-10, 2.6e-10, 3.7e-10
    p_l, p_r = flapper_nozzle.nozzle_pressures(p_s, p_d, a, b, c, d)
    left = brentq(lambda p: a * np.sqrt(p_s - p) - b * np.sqrt(p - p_d) - d, p_d, p_s, xtol=1e-6)
    right = brentq(lambda p: a * np.sqrt(p_s - p) + d - c * np.sqrt(p - p_d), p_d, p_s, xtol=1e-6)
    assert float(p_l) == pytest.approx(left, rel=1e-9) and float(p_r) == pytest.approx(right, rel=1e-9)


def test_the_null_gap_passes_equal_flows_through_orifice_and_nozzle():
    a = flapper_nozzle.orifice_conductance(0.78, 0.18e-3, 871.0)
    x0 = flapper_nozzle.null_gap(140e5, 70e5, 12e5, a, 0.611, 0.28e-3, 871.0)
    b = flapper_nozzle.nozzle_conductance(0.611, 0.28e-3, x0, 871.0)
    assert float(a * np.sqrt(70e5)) == pytest.approx(float(b * np.sqrt(58e5)), rel=1e-12)
    p_l, _ = flapper_nozzle.nozzle_pressures(140e5, 12e5, a, b, b, 0.0)
    assert float(p_l) == pytest.approx(70e5, rel=1e-12)


def test_flapper_bending_and_tip_by_hand():
    F_h, theta = 0.1, 1e-3
    compliance = 0.013**3 / (3 * 0.0256) + 0.0085**3 / (12 * 0.0302)
    assert float(armature.flapper_tip(theta, F_h, 8.75e-3, 13e-3, 0.0256, 8.5e-3, 0.0302)) == pytest.approx(
        theta * 8.75e-3 - F_h * compliance, rel=1e-12
    )
    assert float(armature.flapper_inclination(theta, F_h, 13e-3, 0.0256)) == pytest.approx(
        theta - F_h * 0.013**2 / (2 * 0.0256), rel=1e-12
    )


def test_the_feedback_spring_has_a_dead_band_and_is_continuous():
    s = np.linspace(-10e-6, 10e-6, 2001)
    F = armature.feedback_spring_force(s, 0.0, 0.0, 13.3e-3, 1962.0, 2e-6)
    assert np.all(F[np.abs(s) < 2e-6] == 0.0)
    expected = np.where(np.abs(s) >= 2e-6, 1962.0 * (s - 2e-6 * np.sign(s)), 0.0)  # eq. 16 as printed
    np.testing.assert_allclose(F, expected, atol=1e-15)


def test_impact_only_beyond_the_gap():
    x = np.array([-40e-6, -38e-6, 0.0, 38e-6, 40e-6])
    T = armature.impact_torque(x, 38.5e-6, 3e7, 8.75e-3)
    np.testing.assert_allclose(T, [-3e7 * 1.5e-6 * 8.75e-3, 0, 0, 0, 3e7 * 1.5e-6 * 8.75e-3], rtol=1e-9, atol=1e-18)


def test_lichtarowicz_limits():
    # high Reynolds: C_d,max; low: the viscous term dominates and C_d falls
    assert float(orifice.short_tube_discharge(1e9, 2.0)) == pytest.approx(0.827 - 0.017, rel=1e-6)
    assert float(orifice.short_tube_discharge(10.0, 2.0)) < 0.1
