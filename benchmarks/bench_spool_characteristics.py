"""Speed of the [MareAttarND] test-bench characteristics: one valve, one temperature, every test.

Run: ``python benchmarks/bench_spool_characteristics.py``

The valve is hydroservo's example aerospace servovalve (Skydrol, -15 degC).
"Every test" is what ``hydroservo valve characteristics`` computes per
temperature: the flow-gain curve (401 openings over +-X_n), the pressure-gain
and leakage curves (401 openings over +-6.25 % X_n), and the six Table-2
metrics (with their own root searches: pressure null, +-40 % P_s crossings,
leakage maximum, flow-gain slopes). The issue's floor: under 1 s.

Baseline, in this process: the same curves solved the straightforward way,
one opening at a time with SciPy's ``brentq`` on the same orifice laws (same
bracket, same tolerance). Their largest differences are printed.

Times are CPU time of this process (steadier than wall time on a shared machine), each a single run after a
warm-up. Figures are written to benchmarks/results/spool_characteristics.json.
"""

from __future__ import annotations

import time

import numpy as np
from results import record
from scipy.optimize import brentq

from hydroservo.analysis.static_bench import Bench, bench_curves, table2_metrics
from hydroservo.components import StagedSlotValve
from hydroservo.io import read_staged_slot_valve

T = -15.0


def baseline_curves(valve: StagedSlotValve, bench: Bench, n: int = 401) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Q_L (connected), P_1 and leakage (blocked), one scalar brentq per opening and test."""
    props = valve.fluid_properties(bench.P_s, bench.P_r, T)
    Ps, Pr, tol = bench.P_s, bench.P_r, 1e-12 * (bench.P_s - bench.P_r)
    span = Ps - Pr

    def f(i: str, x: float, up: float, down: float) -> float:
        return float(valve.orifice_flow(i, np.array(x), up, down, props))

    Q_L, P1, leak = np.empty(n), np.empty(n), np.empty(n)
    for k, x in enumerate(np.linspace(-1.0, 1.0, n) * bench.X_n):
        p = brentq(
            lambda p, x=x: f("a", x, Ps, p) + f("c", x, Ps, p) - f("b", x, p, Pr) - f("d", x, p, Pr),
            Pr - 0.01 * span,
            Ps + 0.01 * span,
            xtol=tol,
        )
        Q_L[k] = f("a", x, Ps, p) - f("b", x, p, Pr)
    for k, x in enumerate(np.linspace(-0.0625, 0.0625, n) * bench.X_n):
        p1 = brentq(lambda p, x=x: f("a", x, Ps, p) - f("b", x, p, Pr), Pr, Ps, xtol=tol)
        p2 = brentq(lambda p, x=x: f("c", x, Ps, p) - f("d", x, p, Pr), Pr, Ps, xtol=tol)
        P1[k], leak[k] = p1, f("a", x, Ps, p1) + f("c", x, Ps, p2)
    return Q_L, P1, leak


def main() -> None:
    valve, bench = read_staged_slot_valve("aerospace-example")
    assert bench is not None
    bench_curves(valve, T, bench)  # warm-up
    t0 = time.process_time()
    curves = bench_curves(valve, T, bench)
    t_curves = time.process_time() - t0
    t0 = time.process_time()
    metrics = table2_metrics(valve, T, bench)
    t_metrics = time.process_time() - t0
    t0 = time.process_time()
    Q_L, P1, leak = baseline_curves(valve, bench)
    t_base = time.process_time() - t0
    print(f"one valve at {T:g} degC, 401 openings per test")
    print(f"  baseline, brentq per opening, the three curves:   {t_base * 1e3:8.1f} ms")
    print(
        f"  hydroservo, vectorised bracketing, three curves:  {t_curves * 1e3:8.1f} ms   ({t_base / t_curves:.0f}x faster)"
    )
    print(f"  hydroservo, the six Table-2 metrics:              {t_metrics * 1e3:8.1f} ms")
    print(
        f"  every test (curves and metrics):                  {(t_curves + t_metrics) * 1e3:8.1f} ms   (floor: 1000 ms)"
    )
    print(
        "  largest differences from the baseline: "
        f"Q_L {np.max(np.abs(Q_L - curves.Q_L)) / np.max(np.abs(Q_L)):.1e} of full scale, "
        f"P_1 {np.max(np.abs(P1 - curves.P_1)):.1e} Pa, "
        f"leakage {np.max(np.abs(leak / curves.Q_lk - 1)):.1e} relative"
    )
    print("  metrics: " + ", ".join(f"{k} {v:.4g}" for k, v in metrics.items()))
    record("spool_characteristics", {
        "baseline_ms": t_base * 1e3, "curves_ms": t_curves * 1e3, "ratio": t_base / t_curves,
        "every_test_s": t_curves + t_metrics,
        "Q_L_difference": float(np.max(np.abs(Q_L - curves.Q_L)) / np.max(np.abs(Q_L))),
    })  # fmt: skip


if __name__ == "__main__":
    main()
