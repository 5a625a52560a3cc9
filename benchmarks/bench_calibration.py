"""A five-parameter calibration of the robot arm with exact gradients, against the same fit with finite differences.

Run: ``python benchmarks/bench_calibration.py`` (``--repeat N``, default 5)

The problem (the issue's): the robot arm (Efe2014) on a 4-s, two-rate record of its valve-signal steps (the
example record ``arm_step``: chamber pressures at 40 Hz, rod position and valve signal at 200 Hz, with the
noise and resolution of Table 5.1's logger), five parameters fitted from the published model: the spool time
constant, the valve flow coefficient, the internal leakage, the viscous and the Coulomb friction
(``spool.tau``, ``valve.c_v``, ``cyl.C_Li``, ``load.B``, ``load.F_c0``), each sensor's noise given, the initial
states estimated with them (the default).

Timed, median over repeats, in this process: ``calibrate(...)`` with ``gradient="exact"`` (the residuals'
Jacobian from the sensitivity equations, integrated by CVODES with the states) and the baseline
``gradient="finite-differences"`` (SciPy's forward differences, step sqrt(rtol) in the fitted scale: one run
per parameter per Jacobian). Both start from the same point, run the same optimiser, the same integrator and
tolerances. Printed: the model evaluations of each (residual runs, and Jacobians: a finite-difference Jacobian
costs one residual run per column, which SciPy counts among its residual evaluations), the time, and the
largest difference of their results in standard errors. The first call of each builds and caches the
integrators: it is timed apart and left out of the median.

Times are CPU time of this process (steadier than wall time on a shared machine). Figures are ratios on this
machine, never absolute promises; written to benchmarks/results/calibration.json.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np
from results import record as write_results

from hydroservo.data import example_files
from hydroservo.identification.calibration import calibrate
from hydroservo.io.model_file import load_model
from hydroservo.io.records import read_record

FIT = ["spool.tau", "valve.c_v", "cyl.C_Li", "load.B", "load.F_c0"]
NOISE = {"cyl.pA": "0.05 bar", "cyl.pB": "0.05 bar", "load.x": "0.02 mm"}


def _record() -> Any:
    folder = Path(tempfile.mkdtemp(prefix="hydroservo-bench-"))
    names = ["arm_step-200Hz.csv", "arm_step-40Hz.csv"]
    files = example_files()
    for n in names:
        (folder / n).write_text(files[n], encoding="utf-8")
    return read_record([folder / n for n in names])


def run(gradient: str, record: Any) -> tuple[float, Any]:
    arm = load_model("robot-arm")
    start = time.process_time()
    cal = calibrate(arm, [record], FIT, inputs=["command.y"], noise=NOISE, gradient=gradient)
    return time.process_time() - start, cal


def main(repeat: int = 5) -> dict[str, float]:
    record = _record()
    out: dict[str, float] = {}
    results = {}
    for gradient in ("exact", "finite-differences"):
        first, _ = run(gradient, record)
        times = []
        for _ in range(repeat):
            seconds, cal = run(gradient, record)
            times.append(seconds)
        results[gradient] = cal
        out[f"{gradient} s"] = statistics.median(times)
        out[f"{gradient} first s"] = first
        out[f"{gradient} residual runs"] = cal.nfev
        out[f"{gradient} jacobians"] = cal.njev
        print(f"{gradient:>18}: median {statistics.median(times):.3f} s over {repeat} (first call {first:.3f} s), "
              f"{cal.nfev} residual runs, {cal.njev} Jacobians, converged {cal.success}")
    exact, fd = results["exact"], results["finite-differences"]
    shift = float(np.max(np.abs(exact.values - fd.values) / exact.stderr))
    out["ratio"] = out["finite-differences s"] / out["exact s"]
    out["shift in stderr"] = shift
    runs_fd = fd.nfev  # SciPy counts the difference runs among its residual evaluations
    runs_exact = exact.nfev + exact.njev
    print(f"exact gradients: {out['ratio']:.2f}x faster, {runs_exact} model runs (of which {exact.njev} with "
          f"sensitivities) against {runs_fd}; results differ by at most {shift:.2f} standard errors")
    for name in FIT:
        p = exact.parameter(name)
        print(f"  {name:<10} {p['value']:.5g} ± {p['stderr']:.2g} {p['unit']}")
    write_results("calibration", {
        "exact_s": out["exact s"], "fd_s": out["finite-differences s"], "ratio": out["ratio"],
        "exact_runs": exact.nfev, "exact_jacobians": exact.njev, "exact_model_runs": runs_exact, "fd_runs": runs_fd,
        "shift_stderr": shift,
    })  # fmt: skip
    return out


if __name__ == "__main__":
    repeat = 5
    if "--repeat" in sys.argv:
        repeat = int(sys.argv[sys.argv.index("--repeat") + 1])
    main(repeat)
