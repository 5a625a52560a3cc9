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


def _piston(p_source: str, x0: float, t_end: float) -> System:
    s = System("piston", t_end=t_end)
    s.add(c.Tank("supply", p=p_source))
    s.add(c.Accumulator("acc", inlet="piston", V0="1 L", p0="100 bar", kappa=1.4, A_p="10 cm^2", m_p="2 kg",
                        B_p=20.0, V_gmin="0.001 L"))
    s.connect("supply.P", "acc.P")
    s.initial["acc.x_p"] = x0
    return s


def test_a_piston_accumulator_oscillates_about_its_gas_springs_equilibrium_at_its_linearised_frequency():
    """Hopsan's HydraulicPistonAckumulator: m x'' = A (p_s - p_g(x)) - B x'; p_g(x) = p_s at
    V_g = V_0 (p_0/p_s)^(1/kappa) (absolute); about it the gas spring's stiffness is A^2 kappa p_s/V_g, so
    a small excursion rings at sqrt(k/m - (B/2m)^2), decaying as exp(-B t/2m)."""
    p0, ps, V0, A, m, B, kappa = 100e5 - VACUUM, 150e5 - VACUUM, 1e-3, 1e-3, 2.0, 20.0, 1.4
    V_g = V0 * (p0 / ps) ** (1 / kappa)
    x_eq = (V0 - V_g) / A
    k = A * A * kappa * ps / V_g
    w_d = np.sqrt(k / m - (B / (2 * m)) ** 2)
    t = np.linspace(0.0, 0.2, 4001)
    r = _piston("150 bar", x_eq + 1e-4, float(t[-1])).simulate(t_eval=t, accuracy=1e-8)
    e = r["acc.x_p"] - x_eq
    up = t[1:][(e[:-1] < 0) & (e[1:] >= 0)]  # upward zero crossings: one per period
    assert np.mean(np.diff(up)) == pytest.approx(2 * np.pi / w_d, rel=1e-3)
    envelope = 1e-4 * np.exp(-B * t / (2 * m))
    assert np.max(np.abs(e[t > 0.15])) == pytest.approx(np.max(envelope[t > 0.15]), rel=0.05)
    assert r["acc.Q"][100] == pytest.approx(A * r["acc.v_p"][100], rel=1e-12)


def test_a_piston_accumulator_below_its_pre_charge_rests_on_its_stop():
    """Below the pre-charge the gas holds the piston on its stop at empty: it gives as a 1e9 N/m spring under the
    pressure difference on the piston, and the gas stays at its pre-charge within that give."""
    r = _piston("50 bar", 0.0, 0.5).simulate(t_eval=[0.0, 0.5], accuracy=1e-8)
    give = -1e-3 * (r["acc.p"][-1] - 50e5) / 1e9
    assert r["acc.x_p"][-1] == pytest.approx(give, rel=1e-6)
    assert -1e-5 < give < 0.0
    assert r["acc.p"][-1] == pytest.approx(100e5, rel=1e-5)
    assert abs(r["acc.Q"][-1]) < 1e-12
