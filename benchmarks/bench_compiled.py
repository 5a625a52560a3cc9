"""The compiled path (hydroservo.system.native) on the flight simulator: against CVODES at equal accuracy, in
batches on one and two threads, and what building a model costs at -O1 and -O2.

Run: ``python benchmarks/bench_compiled.py``

* Equal accuracy: the largest deviation of the plotted signals (y, p1, p2, xv) from CVODES at rtol 1e-11,
  relative to each signal's range, 1001 output times over the 2-s step; for each target (1e-3, 1e-4), the
  cheapest accuracy setting of each method that meets it (1e-1 ... 1e-6), its median time over repeats.
* Batch: 64 runs with the load varied, rodas3 (compiled, the default) and CVODES, on 1 and 2 threads, outputs not
  read.
* Build: sources generated and compiled into an empty cache folder, at -O1 and -O2, and the run time of each.
"""

from __future__ import annotations

import os
import tempfile
import time
import warnings

import numpy as np
from results import median_cpu

import hydroservo as hs
from hydroservo.system import native

ACCURACIES = (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6)
METHODS = ("cvodes", "rodas3", "ros23", "dopri5")



def equal_accuracy(repeat: int) -> dict[str, dict[float, tuple[float, float]]]:
    system = hs.load_model("flight-simulator")
    names = [n for panel in system.default_panels() for n in panel]
    ref = system.simulate(rtol=1e-11, atol=1e-13, max_steps=10_000_000, method="cvodes")
    found: dict[str, dict[float, tuple[float, float]]] = {}
    for method in METHODS:
        for accuracy in ACCURACIES:
            run = system.simulate(accuracy=accuracy, method=method)
            dev = max(float(np.max(np.abs(run[n] - ref[n])) / np.ptp(ref[n])) for n in names if np.ptp(ref[n]) > 0)
            seconds = median_cpu(lambda a=accuracy, m=method: system.simulate(accuracy=a, method=m), repeat)
            found.setdefault(method, {})[accuracy] = (seconds, dev)
    return found


def batch(repeat: int) -> dict[tuple[str, int], float]:
    system = hs.load_model("flight-simulator")
    loads = {"load.W": np.linspace(10_000.0, 16_000.0, 64)}
    found = {}
    for method in ("rodas3", "cvodes"):
        for threads in (1, 2):
            system.batch(loads, 2.0, threads=threads, method=method)
            found[method, threads] = median_cpu(
                lambda m=method, n=threads: system.batch(loads, 2.0, threads=n, method=m), repeat
            )
    return found


def build(repeat: int) -> dict[str, tuple[float, float]]:
    found = {}
    for flags in (("-O1",), ("-O2",)):
        with tempfile.TemporaryDirectory() as cache:
            os.environ["HYDROSERVO_CACHE"] = cache
            model = hs.load_model("flight-simulator").build()
            start = time.perf_counter()
            sources = native.model_sources(model, "hs_bench")
            library = native.compiled(sources, flags)
            seconds = time.perf_counter() - start
            functions = native.bind(library, "hs_bench")
            instance = functions["new"]()
            p = np.ascontiguousarray(hs.load_model("flight-simulator").parameter_vector())
            grid = np.linspace(0.0, 2.0, 1001)
            out = np.zeros((grid.size, model.nx))

            def run(c=functions, m=instance, p=p, grid=grid, out=out) -> None:
                c["set_parameters"](m, native.pointer(p))
                c["reset"](m)
                c["integrate"](m, 2, 1, 1e-7, 1e-9, 0.0, 10**6, grid.size, native.pointer(grid), native.pointer(out), None)

            found[" ".join(flags)] = (seconds, median_cpu(run, repeat))
            functions["free"](instance)
        del os.environ["HYDROSERVO_CACHE"]
    return found


def main(repeat: int = 7) -> dict:
    warnings.simplefilter("ignore", hs.ImplausibleResultWarning)
    acc = equal_accuracy(repeat)
    print("flight-simulator, 2 s, 1001 output times: median time [ms] and deviation of the plotted signals")
    print(f"{'accuracy':>9}" + "".join(f"{m:>22}" for m in METHODS))
    for accuracy in ACCURACIES:
        print(f"{accuracy:>9.0e}" + "".join(f"{acc[m][accuracy][0] * 1e3:>12.2f} {acc[m][accuracy][1]:>9.1e}" for m in METHODS))
    best = {}
    for target in (1e-3, 1e-4):
        for m in METHODS:
            meets = [(s, a) for a, (s, d) in acc[m].items() if d <= target]
            best[m, target] = min(meets) if meets else (float("nan"), float("nan"))
        base = best["cvodes", target][0]
        print(f"within {target:.0e}: " + ", ".join(
            f"{m} {best[m, target][0] * 1e3:.2f} ms (accuracy {best[m, target][1]:.0e}, {base / best[m, target][0]:.2f}x CVODES)"
            for m in METHODS))  # fmt: skip
    runs = batch(repeat=3)
    print("batch of 64 runs: " + ", ".join(f"{m} on {n} thread(s) {s * 1e3:.0f} ms" for (m, n), s in runs.items()))
    speedups = {m: runs[m, 1] / runs[m, 2] for m in ("rodas3", "cvodes")}
    print("CPU time on 1 thread over CPU time on 2 (the work; wall time is not measurable on a shared core): "
          + ", ".join(f"{m} {v:.2f}x" for m, v in speedups.items()))
    built = build(repeat)
    print("build into an empty cache, and ros23 at rtol 1e-7: " + ", ".join(
        f"{flags}: {b:.2f} s, run {r * 1e3:.2f} ms" for flags, (b, r) in built.items()))  # fmt: skip
    return {"accuracy": acc, "best": best, "batch": runs, "batch_speedup": speedups, "build": built}


if __name__ == "__main__":
    main()
