"""MareAttarND orifice laws: limits of the closed-orifice coefficient (eqs. 15, 17), continuity through null (eq. 20).

Geometry of a plausible aerospace servovalve orifice (not the paper's, which is
not published): 2 slots of 2 mm, 2 um radial clearance, 5 um edge radius,
C_q_inf = 0.7, lambda_t = 100, Skydrol-like 1000 kg/m^3 and 20 cSt.
"""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.errors import ParameterError
from hydroservo.laws import staged_slot as so

GEO = {"r": 5e-6, "c": 2e-6, "n": 2, "w": 2e-3}
FLUID = {"rho": 1000.0, "nu": 2e-5}
FLOW = {"Cq_inf": 0.7, "lambda_t": 100.0}


def test_short_orifice_limits() -> None:
    # eq. 17: small closure -> 1/sqrt(1.5); at X/(D_h lambda) = 1e-8 C_q is 5e-4 below the limit, hence 1e-3
    assert so.short_orifice_coefficient(1e-9, 1e-5, 1e4) == pytest.approx(1 / np.sqrt(1.5), rel=1e-3)
    # eq. 15: large closure -> D_h lambda / (64 |X|); within 6e-6 at X/(D_h lambda) = 10 and 100, 1e-3 is loose
    lam = np.array([1.0, 10.0])
    np.testing.assert_allclose(so.short_orifice_coefficient(1e-3, 1e-5, lam), 1e-5 * lam / 64e-3, rtol=1e-3)
    # implicit in Re = C_q lambda: the solution satisfies eq. 14 (Merritt's 2.28) to the solver's precision
    cq = float(so.short_orifice_coefficient(1e-4, 1e-5, 20.0)[()])
    assert cq**-2 == pytest.approx(2.28 + 64 * 1e-4 / (1e-5 * cq * 20.0), rel=1e-9)
    with pytest.raises(ParameterError, match="closure X > 0"):
        so.short_orifice_coefficient(0.0, 1e-5, 10.0)


def test_unified_coefficient_tends_to_eq15_and_reduces_to_eq6() -> None:
    K_g = so.continuity_constant(FLOW["Cq_inf"], FLOW["lambda_t"], GEO["w"], GEO["c"])
    D_h = 2 * GEO["w"] * GEO["c"] / (GEO["w"] + GEO["c"])
    assert K_g == pytest.approx(64 * FLOW["Cq_inf"] / (D_h * FLOW["lambda_t"]))  # the two forms of eq. 19
    X = -np.array([1e-4, 1e-3, 1e-2])
    cq = so.discharge_coefficient(X, 5.0, FLOW["Cq_inf"], FLOW["lambda_t"], K_g)
    err = np.abs(cq / (D_h * 5.0 / (64 * np.abs(X))) - 1)  # eq. 15, closer as |X| grows
    assert err[1] < 1e-2 and err[2] < 1e-3 and np.all(np.diff(err) < 0)
    lam = np.array([1.0, 100.0, 1e4])
    np.testing.assert_allclose(
        so.discharge_coefficient(1e-5, lam, FLOW["Cq_inf"], FLOW["lambda_t"], K_g),
        so.discharge_coefficient_open(lam, FLOW["Cq_inf"], FLOW["lambda_t"]),
    )


def test_flow_is_continuous_through_null() -> None:
    """C_q S (and so Q) has the same value from both sides of the critical opening (eq. 20's purpose)."""
    h = 1e-12
    q = so.slot_flow(np.array([-h, 0.0, h]), 7e6, **GEO, **FLUID, **FLOW)
    assert q[0] == pytest.approx(q[1], rel=1e-6) and q[2] == pytest.approx(q[1], rel=1e-6)
    # the geometry is C1 at null (Table 1: the rounded-edge length starts with zero slope) ...
    Xs = so.orifice_geometry(np.array([-1e-9, 0.0, 1e-9]), GEO["r"], GEO["c"], GEO["n"], GEO["w"])[0]
    assert (Xs[2] - Xs[1]) / 1e-9 < 1e-3 and Xs[0] == Xs[1]
    # ... and the flow increases monotonically with the opening through null
    X = np.linspace(-2e-5, 2e-5, 81)
    assert np.all(np.diff(so.slot_flow(X, 7e6, **GEO, **FLUID, **FLOW)) > 0)


def test_laminar_at_small_drops_and_odd_in_drop() -> None:
    dp = np.array([1.0, 2.0, 4.0])
    q = so.slot_flow(-1e-5, dp, **GEO, **FLUID, **FLOW)
    np.testing.assert_allclose(q / q[0], dp, rtol=1e-4)  # tanh linear in lambda ~ sqrt(dp): Q ~ dp
    assert so.slot_flow(1e-5, -3e6, **GEO, **FLUID, **FLOW) == pytest.approx(
        -so.slot_flow(1e-5, 3e6, **GEO, **FLUID, **FLOW)
    )
