"""Speed of the engine on the [FlightSimulatorND] 2-second step response, against a plain SciPy baseline.

Run: ``python benchmarks/bench_flight_simulator.py``

Everything is timed in this process, on this machine; the figures are ratios
to the baseline run alongside, never absolute promises. Three comparisons:

1. the same relative tolerance (1e-6) for both; the baseline is the
   straightforward ``solve_ivp(method="LSODA")`` with a plain Python
   right-hand side in SI units and a scalar ``atol`` (1e-10, small enough for
   the spool position of ~1e-5 m);
2. the same, with the baseline given hand-tuned per-state absolute tolerances;
3. each solver at the loosest of rtol = 1e-3, 1e-4, 1e-5, 1e-6 whose ``y``
   stays within 1e-4 (relative to max |y|) of a tight reference solution.

Then 1000 runs with the load mass varied by +-20 %, batched over both cores (wall time). The single runs are
timed in CPU time, the least over repeats. Figures written to benchmarks/results/flight_simulator.json.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent))
import reference_flight_simulator as ref  # noqa: E402
from results import record  # noqa: E402

import hydroservo as hs  # noqa: E402


def best_of(fn, repeat: int) -> float:
    """The least CPU time [s] of ``fn()`` over ``repeat`` calls (both solvers run one thread in this process; CPU
    time is steadier than wall time on a shared machine)."""
    times = []
    for _ in range(repeat):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return min(times)


def main() -> dict[str, float]:
    P = ref.P
    s0 = np.zeros(10)
    s0[3] = P["W"] / P["A2"]
    t_eval = np.linspace(0.0, 2.0, 1001)
    tight_atol = np.array([1e-9, 1e-9, 1e-3, 1e-3, 1e-13, 1e-10, 1e-12, 1e-9, 1e-6, 1e-11])
    y_ref = solve_ivp(ref.rhs, (0, 2), s0, method="LSODA", t_eval=t_eval, rtol=1e-10, atol=tight_atol, args=(P, 2.0)).y[
        0
    ]
    scale = np.max(np.abs(y_ref))

    def lsoda(rtol: float, atol) -> tuple[float, np.ndarray]:
        def run():
            run.sol = solve_ivp(ref.rhs, (0, 2), s0, method="LSODA", t_eval=t_eval, rtol=rtol, atol=atol, args=(P, 2.0))

        t = best_of(run, 5)
        return t, run.sol.y[0]

    system = hs.load_model("flight-simulator")
    build_start = time.perf_counter()
    model = system.build()
    build = time.perf_counter() - build_start
    p = system.parameter_vector()

    def engine(rtol: float) -> tuple[float, np.ndarray]:
        model.simulate(2.0, p, rtol=rtol, atol=rtol * 1e-2, method="cvodes")  # creates the integrator once

        def run():
            run.res = model.simulate(2.0, p, rtol=rtol, atol=rtol * 1e-2, method="cvodes")

        t = best_of(run, 20)
        return t, -run.res["load.x"]

    out: dict[str, float] = {"build_s": build}
    print(f"model build (CasADi graph, once): {build * 1e3:.1f} ms")
    print("2-s step response of FlightSimulatorND, 1001 output times, best of several runs:")

    t_e, y_e = engine(1e-6)
    t_l, y_l = lsoda(1e-6, 1e-10)
    dev = np.max(np.abs(y_e - y_l)) / scale
    out.update(engine_s=t_e, lsoda_s=t_l, ratio_same_tol=t_l / t_e, deviation=dev)
    print(
        f"  [1] rtol 1e-6 both: engine {t_e * 1e3:.2f} ms, LSODA (scalar atol) {t_l * 1e3:.2f} ms, "
        f"ratio {t_l / t_e:.1f}x; largest deviation of y {dev:.2e} (relative to max |y|)"
    )
    t_l2, y_l2 = lsoda(1e-6, tight_atol * 1e4)
    out["ratio_tuned_baseline"] = t_l2 / t_e
    print(
        f"  [2] rtol 1e-6, baseline with per-state atol: LSODA {t_l2 * 1e3:.2f} ms, ratio {t_l2 / t_e:.1f}x; "
        f"deviation {np.max(np.abs(y_e - y_l2)) / scale:.2e}"
    )

    def loosest(fn) -> tuple[float, float, float]:
        for rtol in (1e-3, 1e-4, 1e-5, 1e-6):
            t, y = fn(rtol)
            err = np.max(np.abs(y - y_ref)) / scale
            if err < 1e-4:
                return rtol, t, err
        raise RuntimeError("no tolerance met the accuracy target")

    r_e, t_e3, err_e = loosest(engine)
    r_l, t_l3, err_l = loosest(lambda r: lsoda(r, r * 1e-4))
    out["ratio_equal_accuracy"] = t_l3 / t_e3
    print(
        f"  [3] equal accuracy (y within 1e-4 of a tight reference): engine rtol {r_e:g} {t_e3 * 1e3:.2f} ms "
        f"(error {err_e:.1e}), LSODA rtol {r_l:g} {t_l3 * 1e3:.2f} ms (error {err_l:.1e}), ratio {t_l3 / t_e3:.1f}x"
    )

    masses = system["load"].values["m"] * np.linspace(0.8, 1.2, 1000)
    system.batch({"load.m": masses}, t_end=2.0, n_points=201, method="cvodes")  # warm-up (creates the mapped integrator)
    start = time.perf_counter()
    batch = system.batch({"load.m": masses}, t_end=2.0, n_points=201, method="cvodes")
    y_end = batch["y"][:, -1]  # an output: computed on access, so inside the timing
    t_batch = time.perf_counter() - start
    out["batch_1000_s"] = t_batch
    print(
        f"1000 runs, load mass 0.8-1.2 x nominal, 2 s each, {batch.stats['threads']} threads: {t_batch:.2f} s "
        f"(final y {from_m(y_end.min()):.3f} to {from_m(y_end.max()):.3f} in)"
    )
    record("flight_simulator", out, script="benchmarks/bench_flight_simulator.py")
    return out


def from_m(v: float) -> float:
    return v / 0.0254


if __name__ == "__main__":
    main()
