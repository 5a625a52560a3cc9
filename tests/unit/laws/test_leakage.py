"""Closed-orifice leakage laws that MareAttarND reviews (hydroservo.laws.leakage, eqs. 7-11).

Geometry of a plausible aerospace servovalve orifice (not the paper's, which is
not published): 2 slots of 2 mm, 2 um radial clearance, C_q_inf = 0.7, lambda_t = 100.
"""

from __future__ import annotations

import pytest

from hydroservo.laws import leakage

GEO = {"r": 5e-6, "c": 2e-6, "n": 2, "w": 2e-3}
FLOW = {"Cq_inf": 0.7, "lambda_t": 100.0}


def test_earlier_closed_orifice_laws() -> None:
    # Ellman eq. 7 at X = 0: k2 sqrt(dp); Eryilmaz eq. 8 at X = 0: k1 sqrt(dp) X0; leakage falls with closure
    assert leakage.ellman_flow(0.0, 4e6, 1.0, 1e-9) == pytest.approx(1e-9 * 2e3)
    assert leakage.ellman_flow(-1e-5, 4e6, 1e-6, 1e-9) > leakage.ellman_flow(1e-5, 4e6, 1e-6, 1e-9)
    assert leakage.eryilmaz_flow(0.0, 4e6, 1e-5, 1e-9, 0.5) == pytest.approx(1e-9 * 2e3 * 1e-5)  # k1 sqrt(dp) X0
    # laminar gap eq. 10 with the continuity constant of eq. 11
    K_g = leakage.laminar_gap_continuity(GEO["w"], GEO["c"], FLOW["Cq_inf"] / FLOW["lambda_t"])
    q0 = leakage.laminar_gap_flow(0.0, 1e6, 0.02, GEO["n"], GEO["w"], GEO["c"], K_g)
    assert q0 == pytest.approx(GEO["n"] * GEO["w"] * GEO["c"] ** 3 / (12 * 0.02 * K_g) * 1e6)
