"""The staged-slot valve of MareAttarND on a test bench, its component, identification and CLI.

The valve is hydroservo's example aerospace geometry (the parameter set
``MareAttarND_example``; the paper publishes none), so these tests check
properties of the model and the tools, not published values; the comparison
with the paper's Table 2 is in docs/validation.md.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

import hydroservo as hs
from hydroservo.analysis.static_bench import (
    Bench,
    bench_curves,
    blocked_ports,
    flow_gain,
    table2_metrics,
    temperature_table,
)
from hydroservo.cli import main
from hydroservo.components import ConstantPressure, StagedSlotValve, Step
from hydroservo.data import example_files
from hydroservo.errors import ParameterError
from hydroservo.identification.staged_slot import LOW_GAIN, identify_staged_slot, noisy_curves
from hydroservo.io import (
    read_bench_curves,
    read_model,
    read_staged_slot_valve,
    staged_slot_valve_toml,
    write_bench_curves,
)

VALVE, _BENCH = read_staged_slot_valve("aerospace-example")
assert _BENCH is not None
BENCH: Bench = _BENCH
#: The start of the identification: every fitted parameter 30-40 % away from the truth.
START_FACTORS = {
    "X_a0": 1.3,
    "X_b0": 0.7,
    "X_c0": 1.35,
    "X_d0": 0.65,
    "r": 0.7,
    "c": 1.3,
    "Cq_inf": 0.7,
    "lambda_tL": 1.4,
    "X_a0H": 1.3,
    "X_b0H": 0.7,
    "X_c0H": 0.7,
    "X_d0H": 1.3,
    "lambda_tH": 0.65,
}


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def symmetric(lap: float = 0.4e-6) -> StagedSlotValve:
    laps = {f"X_{i}0": lap for i in "abcd"} | {f"X_{i}0H": -100e-6 for i in "abcd"}
    return VALVE.replace(**laps)


@pytest.mark.parametrize("T", [-40.0, -15.0, 32.0])
def test_symmetric_valve_half_supply_at_null_and_symmetric_leakage(T: float) -> None:
    valve = symmetric()
    P1, P2, _ = blocked_ports(valve, T, BENCH, np.array([0.0]))
    assert P1[0] == pytest.approx(BENCH.P_s / 2, rel=1e-10) and P2[0] == pytest.approx(BENCH.P_s / 2, rel=1e-10)
    X = np.linspace(0.0, 0.0625, 101) * BENCH.X_n
    lk_pos, lk_neg = blocked_ports(valve, T, BENCH, X)[2], blocked_ports(valve, T, BENCH, -X)[2]
    np.testing.assert_allclose(lk_neg, lk_pos, rtol=1e-9)
    assert table2_metrics(valve, T, BENCH, 1e-3)["useport_null"] == pytest.approx(50.0, abs=1e-6)


def test_useport_pressure_below_half_supply_with_more_return_underlap() -> None:
    # seed 002 section 3.3: a greater underlap on the return edges (b, d) lowers the null pressure
    assert table2_metrics(VALVE, -15.0, BENCH, 1e-3)["useport_null"] < 45.0


def test_bench_solver_balances_every_opening_including_null() -> None:
    X = np.concatenate([np.linspace(-1, 1, 401), [0.0, 1e-12, -1e-12]]) * BENCH.X_n
    props = VALVE.fluid_properties(BENCH.P_s, BENCH.P_r, -40.0)
    P1, P2, lk = blocked_ports(VALVE, -40.0, BENCH, X)
    assert np.all(np.isfinite(P1)) and np.all((P1 >= 0) & (P1 <= BENCH.P_s)) and np.all(lk > 0)
    qa, qb = VALVE.orifice_flow("a", X, BENCH.P_s, P1, props), VALVE.orifice_flow("b", X, P1, 0.0, props)
    # blocked port 1: what a brings, b takes (to 1e-5 of the flow where P1 sits within 2e-5 Pa of P_r)
    assert np.max(np.abs(qa - qb) / (qa + qb)) < 1e-5
    Q_L, Pc = flow_gain(VALVE, -40.0, BENCH, X)
    q = {i: VALVE.orifice_flow(i, X, *nodes, props) for i, nodes in (("a", (BENCH.P_s, Pc)), ("b", (Pc, 0.0)))}
    q |= {i: VALVE.orifice_flow(i, X, *nodes, props) for i, nodes in (("c", (BENCH.P_s, Pc)), ("d", (Pc, 0.0)))}
    assert np.max(np.abs(q["a"] + q["c"] - q["b"] - q["d"])) < 1e-9 * np.max(np.abs(Q_L))
    n = 401  # the sorted part: monotone characteristics
    assert np.all(np.diff(Q_L[:n]) > 0) and np.all(np.diff(P1[:n] - P2[:n]) >= 0)


def test_table2_metrics_follow_their_definitions() -> None:
    m = table2_metrics(VALVE, -15.0, BENCH)
    curves = bench_curves(VALVE, -15.0, BENCH, n=2001, zoom=0.1)
    Qn = float(flow_gain(VALVE, BENCH.T_rated, BENCH, np.array([BENCH.X_n]))[0][0])
    assert m["max_leakage"] == pytest.approx(np.max(curves.Q_lk) / Qn * 100, rel=1e-3)
    PL = (curves.P_1 - curves.P_2) / BENCH.P_s * 100
    x = curves.X_blocked / BENCH.X_n * 100
    span = np.interp(40.0, PL, x) - np.interp(-40.0, PL, x)
    assert m["pressure_gain_40"] == pytest.approx(80.0 / span, rel=1e-2)
    sel = (np.abs(curves.X_flow) >= 0.4 * BENCH.X_n) & (curves.X_flow > 0)
    slope = np.polyfit(curves.X_flow[sel] / BENCH.X_n * 100, curves.Q_L[sel] / Qn * 100, 1)[0]
    assert m["flow_gain_high"] == pytest.approx(slope, rel=2e-2)  # mean of the two polarities


def test_component_flows_are_the_bridge_law_and_differentiable_at_zero_drop() -> None:
    s = hs.System("bridge")
    s.add(Step("x", unit="m", amplitude="10 um"))
    s.add(ConstantPressure("supply", p="3000 psi"))
    s.add(Step("pA", unit="Pa", amplitude="120 bar"))
    s.add(Step("pB", unit="Pa", amplitude="60 bar"))
    s.add(StagedSlotValve("valve", temperature="32 degC"))
    for src, dst in (("x.y", "valve.xv"), ("supply.p", "valve.pS"), ("pA.y", "valve.pA"), ("pB.y", "valve.pB")):
        s.connect(src, dst)
    res = s.simulate(t_end=1e-3, n_points=2)
    props = VALVE.fluid_properties(to_pa("3000 psi"), 0.0, 32.0)
    X, Ps, pA, pB = 10e-6, to_pa("3000 psi"), 120e5, 60e5
    qa, qb = VALVE.orifice_flow("a", X, Ps, pA, props), VALVE.orifice_flow("b", X, pA, 0.0, props)
    qc, qd = VALVE.orifice_flow("c", X, Ps, pB, props), VALVE.orifice_flow("d", X, pB, 0.0, props)
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
        return float(VALVE.orifice_flow("a", 0.0, 100e5, pA, props) - VALVE.orifice_flow("b", 0.0, pA, 0.0, props))

    assert slope == pytest.approx((q_A(100e5 + h) - q_A(100e5 - h)) / (2 * h), rel=1e-3)


def to_pa(text: str) -> float:
    from hydroservo.units import to_si

    return to_si(text, "Pa")


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


def _start() -> StagedSlotValve:
    return VALVE.replace(**{k: VALVE.values[k] * f for k, f in START_FACTORS.items()})


def test_identification_round_trip_without_noise() -> None:
    """From 30-40 % away, exact data: every identifiable parameter within 0.1 %.

    The high-gain laps are fitted per pair (a with d, b with c: not separable
    from the flow-gain curve; see hydroservo.identification.bridge), so the
    pair's mean is what must come back.
    """
    res = identify_staged_slot(bench_curves(VALVE, -15.0, BENCH), _start())
    for name in LOW_GAIN:
        assert res.valve.values[name] == pytest.approx(VALVE.values[name], rel=1e-3), name
    for a, b in (("X_a0H", "X_d0H"), ("X_b0H", "X_c0H")):
        mean = 0.5 * (VALVE.values[a] + VALVE.values[b])
        assert res.valve.values[a] == res.valve.values[b] == pytest.approx(mean, rel=1e-3)
    assert res.valve.values["lambda_tH"] == pytest.approx(VALVE.values["lambda_tH"], rel=1e-3)
    assert max(abs(v) for v in res.errors.values()) < 2e-3


def test_identification_with_one_percent_noise_predicts_other_temperatures() -> None:
    """1 % noise on every reading (seed 002's flow-meter accuracy).

    Tolerances: 2 % (the issue's floor) for c, C_q_inf and lambda_tL; for the laps and r, 3 standard
    deviations of the 20-repetition study in docs/validation.md (8 nm and 2 % there); for the predicted
    metrics, 3 % (3 standard deviations of the worst one, the high flow gain at -40 degC: 1.0 %).
    """
    data = noisy_curves(bench_curves(VALVE, -15.0, BENCH), 0.01, seed=7)
    res = identify_staged_slot(data, _start())
    p, true = res.valve.values, VALVE.values
    for name in ("c", "Cq_inf", "lambda_tL"):
        assert p[name] == pytest.approx(true[name], rel=0.02), name
    for i in "abcd":
        assert p[f"X_{i}0"] == pytest.approx(true[f"X_{i}0"], abs=25e-9), i  # 25 nm
    assert p["r"] == pytest.approx(true["r"], rel=0.06)
    pred, ref = (temperature_table(v, BENCH, [-15.0, -40.0, 32.0]) for v in (res.valve, VALVE))
    for T in (-40.0, 32.0):
        for key, value in ref["metrics"][T].items():
            assert pred["metrics"][T][key] == pytest.approx(value, rel=0.03), (T, key)


def test_bench_curve_files_round_trip_and_bad_files(tmp_path: Path) -> None:
    curves = bench_curves(VALVE, -15.0, BENCH, n=41)
    paths = write_bench_curves(curves, tmp_path)
    back = read_bench_curves(paths)
    assert back.temperature == -15.0 and back.bench.P_s == pytest.approx(BENCH.P_s)
    np.testing.assert_allclose(back.P_1, curves.P_1, rtol=1e-12, atol=1e-6)
    np.testing.assert_allclose(back.Q_lk, curves.Q_lk, rtol=1e-12)
    bad = tmp_path / "bad.csv"
    bad.write_text(paths[0].read_text().replace("# temperature = -15.0 degC\n", ""))
    with pytest.raises(ParameterError, match="missing '# temperature"):
        read_bench_curves([bad])
    bad.write_text(paths[0].read_text().replace("Q_L [L/min]", "Q_L"))
    with pytest.raises(ParameterError, match=r"expected a unit in brackets"):
        read_bench_curves([bad])
    other = tmp_path / "other.csv"
    other.write_text(paths[1].read_text().replace("temperature = -15.0", "temperature = 20"))
    with pytest.raises(ParameterError, match="one temperature"):
        read_bench_curves([paths[0], other])


def test_characteristics_and_identify_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(
        capsys, "valve", "characteristics", "aerospace-example", "--temperature", "-15,-40", "--points", "101",
        "--out", str(tmp_path / "ch"), "--json",
    )  # fmt: skip
    assert code == 0
    data = json.loads(out)
    assert set(data["metrics"]) == {"-15", "-40"} and data["reference_degC"] == -15
    assert data["change_from_reference"]["-40"]["max_leakage"] < 0  # colder: less leakage
    for f in data["files"].values():
        assert Path(f).stat().st_size > 0
    start = tmp_path / "start.toml"
    start.write_text(staged_slot_valve_toml(_start(), None))
    code, out, _ = run(
        capsys, "valve", "identify", data["files"]["T-15_flow_gain"], data["files"]["T-15_blocked_ports"],
        "--start", str(start), "--predict", "-40", "--out", str(tmp_path / "id"), "--json",
    )  # fmt: skip
    assert code == 0
    res = json.loads(out)
    assert res["identified"]["c"] == pytest.approx(VALVE.values["c"], rel=1e-3)
    comp, bench = read_staged_slot_valve(res["files"]["parameters"])
    assert comp.values["Cq_inf"] == pytest.approx(VALVE.values["Cq_inf"], rel=1e-3)
    assert bench.P_s == pytest.approx(BENCH.P_s, rel=1e-14)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["valve", "characteristics", "aerospace-example", "--temperature", "-80", "--strict"], r"temperature -80"),
        (["valve", "characteristics", "nothing.toml"], r"cannot read|not found|No such"),
        (["valve", "characteristics", "aerospace-example", "--temperature", "20 degC"], r"bare numbers in degC"),
        (["valve", "identify", "missing.csv", "--start", "aerospace-example"], r"missing\.csv"),
    ],
)
def test_spool_cli_bad_input_exits_2(
    argv: list[str], message: str, capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.startswith("hydroservo: error:")
    assert re.search(message, err), err


def test_wrong_sign_lap_in_a_parameter_file_exits_2(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "v.toml"
    path.write_text(staged_slot_valve_toml(VALVE.replace(check=False, X_b0H=3e-6), BENCH))
    code, _, err = run(capsys, "valve", "characteristics", str(path), "--out", str(tmp_path))
    assert code == 2 and "X_b0H" in err and "expected ≤ 0" in err
    curves = tmp_path / "c.csv"
    curves.write_text("# temperature = -15 degC\n# P_s = 200 bar\n# X_n = 0.4 mm\nX [um], P_1 [bar]\n0, 100\n")
    code, _, err = run(capsys, "valve", "identify", str(curves), "--start", "aerospace-example")
    assert code == 2 and "P_1 and P_2" in err


def test_example_model_file_simulates_the_valve_in_a_circuit(tmp_path: Path) -> None:
    path = tmp_path / "model.toml"
    path.write_text(example_files()["staged_slot_valve_cylinder.toml"])
    system = read_model(path)
    res = system.simulate(n_points=301)
    A_A = system["cyl"].values["A_A"]
    v_end, QA_end = res.get("load.v")[-1], res.get("valve.QA")[-1]
    assert v_end > 0 and v_end * A_A == pytest.approx(QA_end, rel=1e-3)  # steady: the valve's flow moves the piston
    assert res.get("valve.QS")[0] > 0  # leakage at null before the step
