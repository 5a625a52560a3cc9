"""What each ``accuracy`` costs and gives, on every built-in model, against a tight reference.

Run: ``python benchmarks/bench_accuracy.py [--methods=cvodes,rodas3,ros23,dopri5]``

For each built-in model (its own duration and 1001 output times), each method and
each accuracy from 1e-2 to 1e-6 (``rtol = accuracy / 100`` for CVODES and rodas3,
``/ 1000`` for ros23 and dopri5, ``atol = rtol / 100``: ``system.integration.tolerances``):
the largest deviation of its main signals (the ones its plot shows) from the same
model with CVODES at rtol 1e-11, relative to each signal's range; the steps; and the median wall
time of the run over repeats, as a ratio to CVODES at the default accuracy (1e-4).
A deviation above the accuracy asked for is marked ``!``.
"""

from __future__ import annotations

import statistics
import time
import warnings

import numpy as np

import hydroservo as hs
from hydroservo.system.integration import DEFAULT_ACCURACY

ACCURACIES = (1e-2, 1e-3, 1e-4, 1e-5, 1e-6)


def deviation(result: hs.Result, reference: hs.Result, names: list[str]) -> tuple[float, str]:
    worst, where = 0.0, ""
    for name in names:
        span = float(np.ptp(reference[name]))
        if span > 0:
            d = float(np.max(np.abs(result[name] - reference[name]))) / span
            if d > worst:
                worst, where = d, name
    return worst, where


def main(repeat: int = 5, methods: tuple[str, ...] = ("cvodes",)) -> dict[str, dict[float, float]]:
    """The deviations: ``found[model][accuracy]`` for CVODES, ``found["model method"][accuracy]`` for the others."""
    warnings.simplefilter("ignore", hs.ImplausibleResultWarning)  # Hopsan's servo is flagged as published
    found: dict[str, dict[float, float]] = {}
    print(f"{'model':<26}{'method':<8}{'accuracy':>10}{'deviation':>12}  {'(signal)':<16}{'steps':>8}{'time':>10}")
    for name in hs.available_models():
        system = hs.load_model(name)
        names = [n for panel in system.default_panels() for n in panel]
        reference = system.simulate(rtol=1e-11, atol=1e-13, max_steps=10_000_000, method="cvodes")
        times: dict[tuple[str, float], float] = {}
        rows = []
        for method in methods:
            for accuracy in ACCURACIES:
                runs = []
                try:
                    system.simulate(accuracy=accuracy, method=method)  # compiled methods: built before timing
                    for _ in range(repeat):
                        start = time.perf_counter()
                        result = system.simulate(accuracy=accuracy, method=method)
                        runs.append(time.perf_counter() - start)
                except hs.errors.SolverError as exc:
                    rows.append((method, accuracy, float("nan"), str(exc).split(": ", 1)[1][:90], 0))
                    continue
                times[method, accuracy] = statistics.median(runs)
                d, where = deviation(result, reference, names)
                found.setdefault(name if method == "cvodes" else f"{name} {method}", {})[accuracy] = d
                rows.append((method, accuracy, d, where, result.stats["nsteps"]))
        for method, accuracy, d, where, steps in rows:
            if d != d:  # the run failed: say why
                print(f"{name:<26}{method:<8}{accuracy:>10.0e}   failed: {where}")
                continue
            mark = "!" if d > accuracy else " "
            base = times.get(("cvodes", DEFAULT_ACCURACY))
            ratio = f"{times[method, accuracy] / base:>9.2f}x" if base else "        -"
            print(f"{name:<26}{method:<8}{accuracy:>10.0e}{d:>11.1e}{mark}  ({where:<14}){steps:>8}{ratio}")
    print(f"time: median wall time of the run over {repeat}, as a ratio to CVODES at the default accuracy (1e-4)")
    return found


if __name__ == "__main__":
    import sys

    chosen = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--methods=")), "cvodes,rodas3,ros23,dopri5")
    main(methods=tuple(chosen.split(",")))
