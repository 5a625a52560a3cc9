"""The static test bench of a staged-slot valve (hydroservo.analysis.static_bench): balance, symmetry, metrics.

The valve is hydroservo's example aerospace geometry (the parameter set
``MareAttarND_example``; the paper publishes none), so these tests check
properties of the model and the tools, not published values; the comparison
with the paper's Table 2 is in docs/validation.md.
"""

from __future__ import annotations

import numpy as np
import pytest

from hydroservo.analysis.static_bench import Bench, bench_curves, blocked_ports, flow_gain, table2_metrics
from hydroservo.components import StagedSlotValve


def symmetric(valve: StagedSlotValve, lap: float = 0.4e-6) -> StagedSlotValve:
    laps = {f"X_{i}0": lap for i in "abcd"} | {f"X_{i}0H": -100e-6 for i in "abcd"}
    return valve.replace(**laps)


@pytest.mark.parametrize("T", [-40.0, -15.0, 32.0])
def test_symmetric_valve_half_supply_at_null_and_symmetric_leakage(
    T: float, aerospace_valve: StagedSlotValve, aerospace_bench: Bench
) -> None:
    bench = aerospace_bench
    valve = symmetric(aerospace_valve)
    P1, P2, _ = blocked_ports(valve, T, bench, np.array([0.0]))
    assert P1[0] == pytest.approx(bench.P_s / 2, rel=1e-10) and P2[0] == pytest.approx(bench.P_s / 2, rel=1e-10)
    X = np.linspace(0.0, 0.0625, 101) * bench.X_n
    lk_pos, lk_neg = blocked_ports(valve, T, bench, X)[2], blocked_ports(valve, T, bench, -X)[2]
    np.testing.assert_allclose(lk_neg, lk_pos, rtol=1e-9)
    assert table2_metrics(valve, T, bench, 1e-3)["useport_null"] == pytest.approx(50.0, abs=1e-6)


def test_useport_pressure_below_half_supply_with_more_return_underlap(
    aerospace_valve: StagedSlotValve, aerospace_bench: Bench
) -> None:
    # MareAttarND section 3.3: a greater underlap on the return edges (b, d) lowers the null pressure. The example
    # valve gives 38 % of P_s at -15 degC; 45 % is a margin below the symmetric valve's exact 50 %, not a published
    # figure (the paper's valve measures 46.2 %, Table 2, with a geometry it does not publish)
    assert table2_metrics(aerospace_valve, -15.0, aerospace_bench, 1e-3)["useport_null"] < 45.0


def test_bench_solver_balances_every_opening_including_null(
    aerospace_valve: StagedSlotValve, aerospace_bench: Bench
) -> None:
    valve, bench = aerospace_valve, aerospace_bench
    X = np.concatenate([np.linspace(-1, 1, 401), [0.0, 1e-12, -1e-12]]) * bench.X_n
    props = valve.fluid_properties(bench.P_s, bench.P_r, -40.0)
    P1, P2, lk = blocked_ports(valve, -40.0, bench, X)
    assert np.all(np.isfinite(P1)) and np.all((P1 >= 0) & (P1 <= bench.P_s)) and np.all(lk > 0)
    qa, qb = valve.orifice_flow("a", X, bench.P_s, P1, props), valve.orifice_flow("b", X, P1, 0.0, props)
    # blocked port 1: what a brings, b takes (to 1e-5 of the flow where P1 sits within 2e-5 Pa of P_r)
    assert np.max(np.abs(qa - qb) / (qa + qb)) < 1e-5
    Q_L, Pc = flow_gain(valve, -40.0, bench, X)
    q = {i: valve.orifice_flow(i, X, *nodes, props) for i, nodes in (("a", (bench.P_s, Pc)), ("b", (Pc, 0.0)))}
    q |= {i: valve.orifice_flow(i, X, *nodes, props) for i, nodes in (("c", (bench.P_s, Pc)), ("d", (Pc, 0.0)))}
    assert np.max(np.abs(q["a"] + q["c"] - q["b"] - q["d"])) < 1e-9 * np.max(np.abs(Q_L))
    n = 401  # the sorted part: monotone characteristics
    assert np.all(np.diff(Q_L[:n]) > 0) and np.all(np.diff(P1[:n] - P2[:n]) >= 0)


def test_table2_metrics_follow_their_definitions(aerospace_valve: StagedSlotValve, aerospace_bench: Bench) -> None:
    valve, bench = aerospace_valve, aerospace_bench
    m = table2_metrics(valve, -15.0, bench)
    curves = bench_curves(valve, -15.0, bench, n=2001, zoom=0.1)
    Qn = float(flow_gain(valve, bench.T_rated, bench, np.array([bench.X_n]))[0][0])
    assert m["max_leakage"] == pytest.approx(np.max(curves.Q_lk) / Qn * 100, rel=1e-3)
    PL = (curves.P_1 - curves.P_2) / bench.P_s * 100
    x = curves.X_blocked / bench.X_n * 100
    span = np.interp(40.0, PL, x) - np.interp(-40.0, PL, x)
    assert m["pressure_gain_40"] == pytest.approx(80.0 / span, rel=1e-2)
    sel = (np.abs(curves.X_flow) >= 0.4 * bench.X_n) & (curves.X_flow > 0)
    slope = np.polyfit(curves.X_flow[sel] / bench.X_n * 100, curves.Q_L[sel] / Qn * 100, 1)[0]
    assert m["flow_gain_high"] == pytest.approx(slope, rel=2e-2)  # mean of the two polarities
