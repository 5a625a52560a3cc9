"""The staged-slot valve component of MareAttarND (hydroservo.components.valves.staged_slot).

The valve is hydroservo's example aerospace geometry (the parameter set
``MareAttarND_example``; the paper publishes none): properties of the model, not published values.
"""

from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

import hydroservo as hs
from hydroservo.analysis.static_bench import Bench
from hydroservo.components import ConstantPressure, StagedSlotValve, Step
from hydroservo.errors import ParameterError


def to_pa(text: str) -> float:
    from hydroservo.units import to_si

    return to_si(text, "Pa")


def test_component_flows_are_the_bridge_law_and_differentiable_at_zero_drop(aerospace_valve: StagedSlotValve) -> None:
    valve = aerospace_valve
    s = hs.System("bridge")
    s.add(Step("x", unit="m", amplitude="10 um"))
    s.add(ConstantPressure("supply", p="3000 psi"))
    s.add(Step("pA", unit="Pa", amplitude="120 bar"))
    s.add(Step("pB", unit="Pa", amplitude="60 bar"))
    s.add(StagedSlotValve("valve", temperature="32 degC"))
    for src, dst in (("x.y", "valve.xv"), ("supply.p", "valve.pS"), ("pA.y", "valve.pA"), ("pB.y", "valve.pB")):
        s.connect(src, dst)
    res = s.simulate(t_end=1e-3, n_points=2)
    props = valve.fluid_properties(to_pa("3000 psi"), 0.0, 32.0)
    X, Ps, pA, pB = 10e-6, to_pa("3000 psi"), 120e5, 60e5
    qa, qb = valve.orifice_flow("a", X, Ps, pA, props), valve.orifice_flow("b", X, pA, 0.0, props)
    qc, qd = valve.orifice_flow("c", X, Ps, pB, props), valve.orifice_flow("d", X, pB, 0.0, props)
    assert res.get("valve.QA")[-1] == pytest.approx(qa - qb, rel=1e-9)
    assert res.get("valve.QS")[-1] == pytest.approx(qa + qc, rel=1e-9)
    assert res.get("valve.QT")[-1] == pytest.approx(qb + qd, rel=1e-9)
    # exact derivative at zero drop: finite, and the laminar slope of the unsmoothed law
    comp = s["valve"]
    u = {k: ca.SX.sym(k) for k in ("xv", "pS", "pT", "pA", "pB")}
    QA = comp.output_equations(0.0, {}, u, comp.values)["QA"]
    dQ = ca.Function("dQ", list(u.values()), [ca.jacobian(QA, u["pA"])])
    slope = float(dQ(0.0, 100e5, 0.0, 100e5, 0.0))
    assert np.isfinite(slope) and slope < 0
    h = 10.0 * comp.values["p_tr"]

    def q_A(pA: float) -> float:
        return float(valve.orifice_flow("a", 0.0, 100e5, pA, props) - valve.orifice_flow("b", 0.0, pA, 0.0, props))

    assert slope == pytest.approx((q_A(100e5 + h) - q_A(100e5 - h)) / (2 * h), rel=1e-3)


def test_mineral_oil_component_builds_symbolically() -> None:
    comp = StagedSlotValve("v", fluid="iso-vg46", temperature="40 degC")
    u = {k: ca.SX.sym(k) for k in ("xv", "pS", "pT", "pA", "pB")}
    T = ca.SX.sym("T")
    out = comp.output_equations(0.0, {}, u, {**comp.values, "temperature": T})
    f = ca.Function("f", [*u.values(), T], [out["QS"]])
    assert float(f(0.0, 200e5, 0.0, 100e5, 100e5, 40.0)) > 0


def test_valve_parameters_refuse_wrong_signs() -> None:
    with pytest.raises(ParameterError, match=r"X_a0H = .*expected ≤ 0"):
        StagedSlotValve("v", X_a0H="5 um")
    with pytest.raises(ParameterError, match=r"v\.c = .*expected > 0"):
        StagedSlotValve("v", c="-1 um")
    with pytest.raises(ParameterError, match="w_H .* < w_L"):
        StagedSlotValve("v", w_L="5 mm", w_H="4 mm").check()
    with pytest.raises(ParameterError, match="P_s > P_r"):
        Bench(P_s=1e5, X_n=1e-3, P_r=2e5)
