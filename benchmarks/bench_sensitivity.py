"""A Sobol study of the robot arm on 2 threads, timed against the same runs one by one, in this process.

Run: ``python benchmarks/bench_sensitivity.py`` (``--quick``: n = 128, 1024 runs, one repeat)

The study: :func:`hydroservo.analysis.sensitivity.sobol` on the built-in
``robot-arm`` example, six parameters (flow coefficient, spool response time,
supply level, mass, internal leakage, external force; the ranges of
docs/robot_arm.md), base sample n = 1024, so n (d + 2) = 8192 runs of 1.5 s,
301 output points, the model's own metrics, ``threads=2`` (the CI machine's
cores). Timed: the whole ``sobol()`` call (sampling, runs, analysis) and the
runs alone (``runs.stats``), median over repeats.

The baseline: the same design points (read from the study's table, SI) run
one at a time through the public API, ``System.simulate(params=..., n_points=301)``
in a Python loop, and each result reduced to the same metrics. Running all
8192 that way takes minutes, so an evenly spaced subset is timed (median over
repeats) and the per-run time extrapolated to the whole design; the printout
says so. The same subset also goes through ``run_design`` on one thread, to
tell the gain of batching from that of the second thread. The baseline's
metrics must equal the study's for those points (to solver tolerance): the
largest relative difference is printed.

Figures are ratios on this machine, never absolute promises.
"""

from __future__ import annotations

import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import hydroservo as hs
from hydroservo.analysis.campaign import run_design
from hydroservo.analysis.metrics import describe, parse_metric
from hydroservo.analysis.sensitivity import sobol

RANGES: dict[str, tuple[Any, Any]] = {
    "valve.c_v": (1.0e-4, 2.0e-4),  # m^2/s/Pa^0.5
    "spool.tau": ("20 ms", "40 ms"),
    "supply.scale": (0.8333, 1.1667),  # 25 to 35 bar
    "load.m": ("15 kg", "35 kg"),
    "cyl.C_Li": (0.5e-13, 2e-13),  # m^3/s/Pa
    "force.amplitude": ("-200 N", "200 N"),
}
THREADS = 2
N_POINTS = 301  # run_design's output grid; the baseline asks for the same


def median_time(fn: Callable[[], Any], repeat: int) -> tuple[float, list[float], Any]:
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), times, out


def one_by_one(arm: Any, keys: list[str], points: np.ndarray, metrics: list[Any]) -> np.ndarray:
    """Each point simulated on its own through ``System.simulate``, reduced to ``metrics`` (runs x metrics)."""
    out = np.full((points.shape[0], len(metrics)), np.nan)
    for k, row in enumerate(points):
        result = arm.simulate(params=dict(zip(keys, row.tolist(), strict=True)), n_points=N_POINTS)
        out[k] = [m(result.t, {name: result[name] for name in m.signals}) for m in metrics]
    return out


def main(quick: bool = False) -> dict[str, float]:
    n, repeat, subset = (128, 1, 64) if quick else (1024, 3, 256)
    arm = hs.load_model("robot-arm")
    model = arm.build()
    missing = [name for name in RANGES if name not in arm.parameter_names()]
    if missing:
        raise SystemExit(f"robot-arm has no parameter {', '.join(missing)}")
    metrics = [parse_metric(text, model.units, arm.t_end) for text in arm.metrics]
    arm.simulate(n_points=N_POINTS)  # warm up the integrator
    runs = n * (len(RANGES) + 2)
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"robot-arm Sobol study: {len(RANGES)} parameters, n = {n}, {runs} runs of {arm.t_end:g} s, "
          f"{N_POINTS} output points; threads = {THREADS}, cpu count {os.cpu_count()} ({usable} usable)")

    # -- the study ------------------------------------------------------------------------------------
    walls, rates, totals = [], [], []
    study = None
    for _ in range(repeat):
        start = time.perf_counter()
        study = sobol(arm, RANGES, n, threads=THREADS, n_points=N_POINTS)
        totals.append(time.perf_counter() - start)
        walls.append(study.runs.stats["wall_time_s"])
        rates.append(study.runs.stats["runs_per_s"])
    assert study is not None
    stats = study.runs.stats
    t_study, w_study, r_study = statistics.median(totals), statistics.median(walls), statistics.median(rates)
    print(f"  study (sobol, {THREADS} threads, chunks of {stats['chunk']}), median of {repeat}: "
          f"sobol() {t_study:.1f} s [{', '.join(f'{t:.1f}' for t in totals)}], runs {w_study:.1f} s, "
          f"{r_study:.0f} runs/s, {stats['failed']} failed, {stats['implausible']} implausible")

    # -- the same points one by one (a subset, extrapolated) --------------------------------------------
    table = study.runs.table
    keys = study.runs.parameters
    points = table.iloc[:, : len(keys)].to_numpy(dtype=float)  # SI: "name [unit]" columns in the order of keys
    pick = np.unique(np.linspace(0, runs - 1, subset).round().astype(int))
    t_one, times_one, Y_one = median_time(lambda: one_by_one(arm, keys, points[pick], metrics), repeat)
    per_run = t_one / pick.size
    print(f"  one by one (System.simulate + metrics, a Python loop): {pick.size} of the {runs} points, evenly "
          f"spaced, median of {repeat}: {t_one:.2f} s [{', '.join(f'{t:.2f}' for t in times_one)}], "
          f"{per_run * 1e3:.2f} ms/run, {1 / per_run:.0f} runs/s")
    print(f"    extrapolated to all {runs} runs (not run): {per_run * runs:.1f} s")
    design = {k: points[pick, j] for j, k in enumerate(keys)}
    t_batch1, _, _ = median_time(
        lambda: run_design(arm, design, metrics, t_end=arm.t_end, n_points=N_POINTS, threads=1), repeat
    )
    print(f"  the same {pick.size} points through run_design on 1 thread, median of {repeat}: {t_batch1:.2f} s, "
          f"{t_batch1 / pick.size * 1e3:.2f} ms/run, {pick.size / t_batch1:.0f} runs/s")
    ratio = per_run * runs / w_study
    print(f"  ratio one by one (extrapolated) / study's runs: {ratio:.2f}x   "
          f"(/ whole sobol() call: {per_run * runs / t_study:.2f}x; batching alone, 1 thread: "
          f"{t_one / t_batch1:.2f}x; the 2nd thread: {t_batch1 / pick.size * runs / w_study:.2f}x)")

    # -- the same numbers -------------------------------------------------------------------------------
    Y_study = study.runs.values()[pick]
    rel = np.abs(Y_one - Y_study) / np.maximum(np.abs(Y_study), np.finfo(float).tiny)
    largest = float(np.nanmax(rel)) if np.isfinite(rel).any() else float("nan")
    where = "every metric equal"
    if largest > 0:
        k, j = np.unravel_index(int(np.nanargmax(rel)), rel.shape)
        where = f"{describe(metrics[j])}, run {int(pick[k])}"
    print(f"  metrics one by one vs the study's on those {pick.size} points: largest relative difference "
          f"{largest:.2e} ({where}); {int((~np.isfinite(rel)).sum())} NaN")

    # -- the indices, for a glance ----------------------------------------------------------------------
    short = [k.split(".")[-1] for k in keys]
    print(f"  total indices S_T (metric x parameter), n = {n}:")
    print(f"    {'':<34}" + "".join(f"{s:>11}" for s in short))
    ST = study.indices.pivot(index="metric", columns="parameter", values="ST")
    for m in metrics:
        name = describe(m)
        print(f"    {name:<34}" + "".join(f"{ST.loc[name, k]:>11.3f}" for k in keys))
    for note in study.notes:
        print(f"  note: {note}")
    return {"study_s": w_study, "sobol_s": t_study, "runs_per_s": r_study, "one_by_one_ms": per_run * 1e3,
            "ratio": ratio, "max_rel_diff": largest}


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
