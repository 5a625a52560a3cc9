"""What each ``accuracy`` costs and gives, on every built-in model, against a tight reference.

Run: ``python benchmarks/bench_accuracy.py [--methods=cvodes,rodas3,ros23,dopri5]``

For each built-in model (its own duration and 1001 output times), each method and
each accuracy from 1e-2 to 1e-6 (``rtol = accuracy / 100`` for CVODES and rodas3,
``/ 1000`` for ros23 and dopri5, ``atol = rtol / 100``: ``system.integration.tolerances``):
the largest deviation of its main signals (the ones its plot shows) from the same
model with CVODES at rtol 1e-11, relative to each signal's range; the steps; and the median CPU
time of the run over repeats, as a ratio to CVODES at the default accuracy (1e-4). With all four methods it
writes benchmarks/results/accuracy_table.json and prints docs/engine.md's table (``--write``: into it).
A deviation above the accuracy asked for is marked ``!``.
"""

from __future__ import annotations

import statistics
import time
import warnings

import numpy as np
from results import mark, record

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


#: the figures of the last :func:`main`: ``<model>_<method>_<accuracy>`` (deviation) and ``<model>_<method>_time``
#: (CPU time at the default accuracy over CVODES's)
FIGURES: dict[str, float | None] = {}


def main(repeat: int = 5, methods: tuple[str, ...] = ("cvodes",)) -> dict[str, dict[float, float]]:
    """The deviations: ``found[model][accuracy]`` for CVODES, ``found["model method"][accuracy]`` for the others."""
    FIGURES.clear()
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
                        start = time.process_time()
                        result = system.simulate(accuracy=accuracy, method=method)
                        runs.append(time.process_time() - start)
                except hs.errors.SolverError as exc:
                    rows.append((method, accuracy, float("nan"), str(exc).split(": ", 1)[1][:90], 0))
                    FIGURES[f"{name}_{method}_{accuracy:.0e}"] = None
                    continue
                times[method, accuracy] = statistics.median(runs)
                d, where = deviation(result, reference, names)
                found.setdefault(name if method == "cvodes" else f"{name} {method}", {})[accuracy] = d
                FIGURES[f"{name}_{method}_{accuracy:.0e}"] = d
                rows.append((method, accuracy, d, where, result.stats["nsteps"]))
        for method, accuracy, d, where, steps in rows:
            if d != d:  # the run failed: say why
                print(f"{name:<26}{method:<8}{accuracy:>10.0e}   failed: {where}")
                continue
            mark = "!" if d > accuracy else " "
            base = times.get(("cvodes", DEFAULT_ACCURACY))
            ratio = f"{times[method, accuracy] / base:>9.2f}x" if base else "        -"
            if accuracy == DEFAULT_ACCURACY and base:
                FIGURES[f"{name}_{method}_time"] = times[method, accuracy] / base
            print(f"{name:<26}{method:<8}{accuracy:>10.0e}{d:>11.1e}{mark}  ({where:<14}){steps:>8}{ratio}")
    print(f"time: median CPU time of the run over {repeat}, as a ratio to CVODES at the default accuracy (1e-4)")
    return found


def table(methods: tuple[str, ...]) -> str:
    """docs/engine.md's table of the last :func:`main`, every figure after its marker (accuracy_table.json)."""
    lines = ["| model | method | " + " | ".join(f"{a:.0e}" + (" (default)" if a == DEFAULT_ACCURACY else "")
                                              for a in ACCURACIES) + " | time at 1e-4 |",  # fmt: skip
             "|---|---|" + "---|" * len(ACCURACIES) + "---|"]  # fmt: skip
    for name in hs.available_models():
        for k, method in enumerate(methods):
            cells = []
            for a in ACCURACIES:
                d = FIGURES.get(f"{name}_{method}_{a:.0e}")
                cell = mark(f"accuracy_table.{name}_{method}_{a:.0e}", d, ".1e")
                cells.append(cell + (" (!)" if d is not None and d > a else ""))
            label = f"**{method}** (default)" if method == "rodas3" else method
            time_ = mark(f"accuracy_table.{name}_{method}_time", FIGURES.get(f"{name}_{method}_time"), ".2f")
            lines.append(f"| {name if k == 0 else ''} | {label} | " + " | ".join(cells) + f" | {time_} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    import re
    import sys
    from pathlib import Path

    chosen = next((a.split("=", 1)[1] for a in sys.argv[1:] if a.startswith("--methods=")), "rodas3,cvodes,ros23,dopri5")
    methods = tuple(chosen.split(","))
    main(repeat=3, methods=methods)
    if set(methods) == {"rodas3", "cvodes", "ros23", "dopri5"}:
        record("accuracy_table", FIGURES)
        text = table(methods)
        print(text)
        if "--write" in sys.argv:  # into docs/engine.md's accuracy-table block
            page = Path(__file__).resolve().parents[1] / "docs" / "engine.md"
            start, end = "<!-- accuracy-table:start -->", "<!-- accuracy-table:end -->"
            found = page.read_text(encoding="utf-8")
            block = f"{start}\n{text}{end}"
            page.write_text(re.sub(re.escape(start) + ".*?" + re.escape(end), lambda _: block, found, flags=re.S),
                            encoding="utf-8")  # fmt: skip
            print(f"wrote the table into {page}")
