"""Accumulator with option inlet = "laminar" (Hopsan's HydraulicAckumulator) against its law solved by hand."""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo import System
from hydroservo import components as c
from hydroservo.units import VACUUM


def _charged_from(p_source: str, V_oil0: float = 0.0, t_end: float = 20.0) -> System:
    s = System("charge", t_end=t_end)
    s.add(c.Tank("supply", p=p_source))
    s.add(c.Accumulator("acc", inlet="laminar", V0="1 L", p0="100 bar", kappa=1.0, K_ca=1e-9, V_gmin="0.1 L"))
    s.connect("supply.P", "acc.P")
    s.initial["acc.V_oil"] = V_oil0
    return s


def test_a_laminar_inlet_charges_the_isothermal_gas_spring_as_its_closed_form():
    """kappa = 1: dV/dt = K (p_s - p_0 V_0/(V_0 - V)) (absolute), so with u = V_0 - V, a = p_0 V_0, b = p_s,
    K t = (V_0 - u)/b - (a/b^2) ln((a - b u)/(a - b V_0)); it settles where p_0 V_0 = p_s (V_0 - V)."""
    p0, ps, V0, K = 100e5 - VACUUM, 150e5 - VACUUM, 1e-3, 1e-9
    t = np.array([0.0, 0.01, 0.03, 0.1])  # the time constant is some 0.05 s
    r = _charged_from("150 bar", t_end=float(t[-1])).simulate(t_eval=t, accuracy=1e-9)
    u = V0 - r["acc.V_oil"]
    a, b = p0 * V0, ps
    t_of_u = ((V0 - u) / b - a / b**2 * np.log((a - b * u) / (a - b * V0))) / K
    np.testing.assert_allclose(t_of_u[1:], t[1:], rtol=1e-4)
    assert r["acc.Q"][0] == pytest.approx(K * (ps - p0), rel=1e-9)
    assert r["acc.p"][-1] == pytest.approx(p0 * V0 / u[-1] + VACUUM, rel=1e-9)
    assert r["acc.V_gas"][-1] == pytest.approx(u[-1], rel=1e-12)


def test_an_empty_laminar_accumulator_holds_its_pre_charge_and_passes_no_flow():
    """Below the pre-charge it empties to 0 and stays there: no flow out, the gas at p_0."""
    r = _charged_from("50 bar", V_oil0=1e-5, t_end=5.0).simulate(t_eval=[0.0, 5.0], accuracy=1e-9)
    assert r["acc.V_oil"][-1] == pytest.approx(0.0, abs=1e-12)
    assert r["acc.Q"][-1] == pytest.approx(0.0, abs=1e-15)
    assert r["acc.p"][-1] == pytest.approx(100e5, rel=1e-12)
    p_gas0 = (100e5 - VACUUM) * 1e-3 / (1e-3 - 1e-5) + VACUUM  # kappa = 1
    assert r["acc.Q"][0] == pytest.approx(1e-9 * (50e5 - p_gas0), rel=1e-9)
