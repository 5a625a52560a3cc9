"""The pseudo-section laws of FerreiraND (hydroservo.laws.pseudo_section): closed forms and identities."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.data import parameter_set
from hydroservo.identification import fit_datasheet
from hydroservo.laws import pseudo_section as ps
from hydroservo.laws.orifice import turbulent_flow

DATASHEET = parameter_set("FerreiraND").table("datasheet")


def test_variable_structure_continuous_in_value_and_slope_at_x_t() -> None:
    for match in ("pressure-gain,leakage", "pressure-gain,flow-gain", "flow-gain,leakage"):
        p = fit_datasheet(DATASHEET, "variable", match).params
        xt, h = p["x_t"], 1e-7
        left = ps.variable_structure(np.array([xt - h, xt]), **p)
        right = ps.variable_structure(np.array([xt + 1e-15, xt + h]), **p)
        assert right[0] == pytest.approx(left[1], rel=1e-9)
        assert (right[1] - right[0]) / h == pytest.approx((left[1] - left[0]) / h, rel=1e-5)


def test_core_region_closed_forms(ferreira_published: dict[str, dict[str, float]]) -> None:
    """Eqs. 25, 28 and 30 in the exponential core follow from eqs. 9, 13, 27."""
    p = ferreira_published["variable"]
    x = np.linspace(-0.9, 0.9, 19) * p["x_t"]
    A_p, A_n = ps.pseudo_sections(x, "variable", p)
    P_s = 7e6
    np.testing.assert_allclose(ps.relative_load_pressure(A_p, A_n), np.tanh(p["k"] * x), atol=1e-14)
    np.testing.assert_allclose(
        ps.leakage_blocked(A_p, A_n, P_s), np.sqrt(2 * P_s) * p["gamma"] / np.sqrt(np.cosh(p["k"] * x)), rtol=1e-12
    )
    np.testing.assert_allclose(
        ps.load_flow_no_load(A_p, A_n, P_s), np.sqrt(P_s / 2) * 2 * p["gamma"] * np.sinh(p["k"] * x / 2), rtol=1e-12
    )


def test_eq23_holds_for_any_pseudo_sections() -> None:
    """K_q0 = q_lk0 K_p0 / 2 (eq. 23) for arbitrary positive sections of a matched symmetrical valve."""
    rng = np.random.default_rng(0)
    P_s = 1e7
    for _ in range(20):
        c = rng.uniform(0.1, 3.0, size=4)

        def A(x: np.ndarray) -> np.ndarray:
            return c[0] * np.exp(c[1] * x) + c[2] * x**2 + c[3] * np.log1p(np.exp(5 * x))  # noqa: B023

        h = 1e-6
        x = np.array([-h, 0.0, h])
        A_p, A_n = A(x), A(-x)
        K_q0 = np.diff(ps.load_flow_no_load(A_p, A_n, P_s)[[0, 2]])[0] / (2 * h)
        K_p0 = np.diff(ps.relative_load_pressure(A_p, A_n)[[0, 2]])[0] / (2 * h)
        q_lk0 = ps.leakage_blocked(A_p[1], A_n[1], P_s)
        assert K_q0 == pytest.approx(q_lk0 * K_p0 / 2, rel=1e-6)


def test_leakage_and_pressure_equations_agree(ferreira_published: dict[str, dict[str, float]]) -> None:
    """Eqs. 16, 17 and 27 give the same leakage; eq. 21 gives zero load flow at the blocked-port pressure."""
    p = ferreira_published["fixed"]
    x = np.linspace(-0.06, 0.06, 25)
    A_p, A_n = ps.pseudo_sections(x, "fixed", p)
    P_s = 7e6
    PL = ps.relative_load_pressure(A_p, A_n)
    q = ps.leakage_blocked(A_p, A_n, P_s)
    np.testing.assert_allclose(q, 2 * A_n * np.sqrt(P_s / 2 * (1 + PL)), rtol=1e-12)  # eq. 16
    np.testing.assert_allclose(q, 2 * A_p * np.sqrt(P_s / 2 * (1 - PL)), rtol=1e-12)  # eq. 17
    np.testing.assert_allclose(ps.load_flow(A_p, A_n, P_s, PL), 0.0, atol=1e-12 * np.max(q))
    # the four-orifice flows with blocked-port pressures: no flow out of the ports, supply = tank = leakage
    P1, P2 = P_s * (1 + PL) / 2, P_s * (1 - PL) / 2
    Q1, Q2, Qs, Qt = ps.matched_valve_flows(A_p, A_n, P_s, 0.0, P1, P2)
    np.testing.assert_allclose(Q1, 0.0, atol=1e-12 * np.max(q))
    np.testing.assert_allclose(Q2, 0.0, atol=1e-12 * np.max(q))
    np.testing.assert_allclose(Qs, q, rtol=1e-10)
    np.testing.assert_allclose(Qt, q, rtol=1e-10)


def test_sections_from_measurements_invert_the_model(ferreira_published: dict[str, dict[str, float]]) -> None:
    p = ferreira_published["variable"]
    x = np.linspace(-0.06, 0.06, 41)
    A_p, A_n = ps.pseudo_sections(x, "variable", p)
    P_s = 7e6
    PL = ps.relative_load_pressure(A_p, A_n)
    q = ps.leakage_blocked(A_p, A_n, P_s)
    Ap2, An2 = ps.sections_from_measurements(PL, q, P_s, max_abs_PL=0.6)
    ok = np.abs(PL) < 0.6
    np.testing.assert_allclose(Ap2[ok], A_p[ok], rtol=1e-10)
    np.testing.assert_allclose(An2[ok], A_n[ok], rtol=1e-10)
    assert np.all(np.isnan(Ap2[~ok])) and (~ok).any()


def test_general_case_reduces_to_matched() -> None:
    A = np.array([1e-8, 2e-8, 3e-8, 4e-8])
    got = ps.valve_flows(*A, 1e7, 0.0, 4e6, 5e6)
    q_s1, q_s2 = A[0] * np.sqrt(6e6), A[1] * np.sqrt(5e6)
    q_1t, q_2t = A[2] * np.sqrt(4e6), A[3] * np.sqrt(5e6)
    np.testing.assert_allclose(got, [q_s1 - q_1t, q_s2 - q_2t, q_s1 + q_s2, q_1t + q_2t])
    # reversed drop: the flow reverses (sign of eq. 1)
    assert turbulent_flow(1e-8, -4e6) == pytest.approx(-2e-5)
