"""Warm API calls against the bare integrator call they wrap, in this process.

Run: ``python benchmarks/bench_warm.py [--quick]``

On the built-in ``flight-simulator`` (its 2-s step, 1001 output times, the
default tolerances):

* the bare CVODES call: the model's own CasADi integrator called with the
  scaled initial state and the parameter vector, nothing else;
* ``Model.simulate`` (checks, integration, statistics, plausibility);
* ``System.simulate`` then reading the output ``y`` (what a user's script does);
* ``load_model`` again (the compiled model found by its structure) and ``build``;
* a batch of 1000 runs (the load varied), its integration time against the
  whole call plus reading ``y`` of every run.

Medians over repeats, each figure beside its baseline as a ratio. The issue's
targets (issue 14): a warm simulate plus reading ``y`` within 1.5x the bare
call; the batch with its outputs within 1.2x its integration.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import hydroservo as hs
from hydroservo.system.integration import SolverSettings


def median_ms(fn: Callable[[], Any], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times) * 1e3


def paired(fn: Callable[[], Any], base: Callable[[], Any], repeat: int) -> tuple[float, float]:
    """``fn``'s median time [ms] and the median of its time over ``base``'s, the two run in turn ``repeat``
    times: a machine that slows down for a while slows both sides of a pair, not the ratio."""
    times, ratios = [], []
    for _ in range(repeat):
        start = time.perf_counter()
        base()
        middle = time.perf_counter()
        fn()
        end = time.perf_counter()
        times.append(end - middle)
        ratios.append((end - middle) / (middle - start))
    return statistics.median(times) * 1e3, statistics.median(ratios)


def main(quick: bool = False) -> dict[str, float]:
    repeat, runs = (15, 200) if quick else (60, 1000)
    system = hs.load_model("flight-simulator")
    model = system.build()
    p = system.parameter_vector()
    system.simulate(method="cvodes")["y"]  # warm: integrator and output functions built once
    grid = np.linspace(0.0, system.t_end, 1001)
    integ = model._integrator(grid, SolverSettings())
    z0 = np.asarray(model.x0(p), dtype=float).ravel() / model.nominal

    def call() -> Any:
        return integ(x0=z0, p=p)

    bare = median_ms(call, repeat)
    rows = [
        ("bare CVODES call (the baseline)", (bare, 1.0)),
        ("Model.simulate", paired(lambda: model.simulate(system.t_end, p, method="cvodes"), call, repeat)),
        ("System.simulate", paired(lambda: system.simulate(method="cvodes"), call, repeat)),
        ("System.simulate, then result['y']", paired(lambda: system.simulate(method="cvodes")["y"], call, repeat)),
        ("load_model (warm)", paired(lambda: hs.load_model("flight-simulator"), call, repeat)),
        ("load_model + build (warm)", paired(lambda: hs.load_model("flight-simulator").build(), call, repeat)),
    ]
    print(f"flight-simulator, 2-s step, 1001 output times, medians of {repeat} (each call in turn with the bare one):")
    for label, (ms, ratio) in rows:
        print(f"  {label:<40} {ms:8.3f} ms   {ratio:5.2f}x the bare call")

    masses = np.linspace(0.8, 1.2, runs) * system.components["load"].values["m"]
    batch_repeat = 3 if quick else 5
    integration, total = [], []
    for _ in range(batch_repeat):
        start = time.perf_counter()
        batch = system.batch({"load.m": masses}, n_points=1001, threads=2, method="cvodes")
        batch["y"]
        total.append(time.perf_counter() - start)
        integration.append(batch.stats["wall_time_s"])
    t_int, t_all = statistics.median(integration), statistics.median(total)
    print(
        f"  batch of {runs} runs (load.m +-20 %, 2 threads), medians of {batch_repeat}: integration {t_int:.2f} s, "
        f"the whole call and reading y of every run {t_all:.2f} s: {t_all / t_int:.2f}x the integration"
    )
    return {"bare_ms": bare, "simulate_y_ratio": rows[3][1][1], "batch_ratio": t_all / t_int, "batch_runs": runs}


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
