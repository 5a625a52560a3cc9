"""The speed suite: every figure of the README's speed table, each beside its baseline, in one run.

Run: ``python benchmarks/suite.py`` (prints the table), ``--readme`` (also writes
it into README.md between its ``speed-table`` markers). Takes a few minutes.

Each row is a ratio to a baseline measured in the same run on the same machine
(medians over repeats), never an absolute promise. Figures from other tools
are quoted, with their source, and marked so.
"""

from __future__ import annotations

import platform
import re
import sys
from pathlib import Path

import bench_accuracy
import bench_compiled
import bench_flight_simulator
import bench_growth
import bench_hopsan
import bench_realtime
import bench_startup
import bench_warm

from hydroservo.errors import ParameterError

README = Path(__file__).resolve().parents[1] / "README.md"
START, END = "<!-- speed-table:start -->", "<!-- speed-table:end -->"
#: The step of the real-time rows [s]: the C stepper's runs of bench_realtime.CASES at it, and CVODES's.
REALTIME_STEP = 1e-4


def rows() -> list[tuple[str, str, str]]:
    """(what, hydroservo, baseline) rows of the table, measured now."""
    out: list[tuple[str, str, str]] = []
    start = bench_startup.main(7)
    base = start["baseline: python -c pass"]
    out.append(("`import hydroservo`", f"{start['import hydroservo'] - base:.3f} s", "over a bare interpreter"))
    run = start["hydroservo simulate flight-simulator --json"]
    out.append(("`hydroservo simulate flight-simulator --json`, end to end", f"{run:.2f} s", "one process, cold"))
    fs = bench_flight_simulator.main()
    out.append((
        "flight-simulator 2-s step, CVODES vs SciPy LSODA (Python right-hand side), equal accuracy",
        f"{fs['ratio_equal_accuracy']:.1f}x faster", "`solve_ivp(method='LSODA')`",
    ))  # fmt: skip
    warm = bench_warm.main()
    out.append((
        "warm `System.simulate(method=\"cvodes\")` + reading `y`", f"{warm['simulate_y_ratio']:.2f}x",
        "the bare CVODES call",
    ))  # fmt: skip
    out.append((
        f"batch of {warm['batch_runs']:.0f} runs (load varied, 2 threads) with their outputs read",
        f"{warm['batch_ratio']:.2f}x", "its integration time",
    ))  # fmt: skip
    comp = bench_compiled.main(repeat=5)
    for target in (1e-3, 1e-4):
        best = min(comp["best"][m, target] + (m,) for m in ("rodas3", "ros23", "dopri5"))
        (ours, a, method), (base, b) = best, comp["best"]["cvodes", target]
        out.append((
            f"flight-simulator within {target:g} of range: compiled {method} (accuracy {a:g}) vs CVODES ({b:g}), "
            "each at its cheapest accuracy meeting it",
            f"{base / ours:.2f}x faster", "CVODES (CasADi, interpreted model)",
        ))  # fmt: skip
    out.append((
        "batch of 64 flight-simulator runs, compiled rodas3, 2 threads",
        f"{comp['batch_speedup']['rodas3']:.2f}x faster", "1 thread",
    ))  # fmt: skip
    acc = bench_accuracy.main(repeat=3, methods=("rodas3",))
    for key, devs in sorted(acc.items()):
        if 1e-4 not in devs:
            continue
        model = key.split()[0]
        mark = " (above it: docs/engine.md, \"Accuracy\", says which signals)" if devs[1e-4] > 1e-4 else ""
        out.append((
            f"default (rodas3 at accuracy 1e-4), `{model}`: largest deviation of its plotted signals",
            f"{devs[1e-4]:.0e}{mark}", "of each signal's range, vs CVODES at rtol 1e-11",
        ))  # fmt: skip
    growth = bench_growth.main(repeat=3)
    (b1, r1, s1), (b24, r24, s24) = growth[1], growth[24]
    out.append((
        "24 actuator loops in one model (240 states): build time per loop; run time per step and loop",
        f"{b24 / 24 / b1:.2f}x; {r24 / s24 / 24 / (r1 / s1):.2f}x", "one loop",
    ))  # fmt: skip
    return out


def table(found: list[tuple[str, str, str]]) -> str:
    head = f"Measured by `python benchmarks/suite.py --readme` ({platform.machine()}, {sys.version.split()[0]}):\n\n"
    lines = ["| what | hydroservo | against |", "|---|---|---|"]
    lines += [f"| {a} | {b} | {c} |" for a, b, c in found]
    return head + "\n".join(lines) + "\n"


def realtime(hopsan_us_per_step: float | None = None) -> str:
    """The real-time section: the exported C stepper (rk4, bdf2) on each model of bench_realtime.CASES, CVODES
    one step at a time from Python beside it, Hopsan's quoted figure; or why it was skipped (no C compiler, or
    the stepper failed to build)."""
    try:
        version = bench_realtime.compiler_version()
        figures = [
            bench_realtime.measure(
                name, t_end, names, [(m, h) for m, h in runs if h == REALTIME_STEP], with_output=False
            )
            for name, t_end, names, runs in bench_realtime.CASES
        ]
    except (ParameterError, OSError) as exc:  # no compiler, or the stepper did not build or load
        reason = str(exc).splitlines()[0].rstrip(".")
        print(f"real-time rows skipped: {reason}\n")
        return f"Real-time rows skipped in this run: {reason}.\n"
    lines = [
        f"| model | solver, step h = {REALTIME_STEP * 1e3:g} ms | µs per step | × real time | deviation from CVODES (of signal range) | measured or quoted |",
        "|---|---|---:|---:|---:|---|",
    ]
    signals = []
    for fig in figures:
        model = f"`{fig['model']}`"
        signals.append(f"{model}: {', '.join(f'`{s}`' for s in fig['signals'])}")
        for run in fig["runs"]:
            lines.append(
                f"| {model} | exported C stepper, {run['method']} | {run['us_per_step']:.2f} | {run['real_time']:.0f} "
                f"| {max(run['deviation'].values()):.0e} | measured here |"
            )
        per_step = fig["cvodes_per_step_us"]
        lines.append(
            f"| {model} | baseline: CVODES one step at a time from Python | {per_step:.0f} "
            f"| {fig['cvodes_h'] / per_step * 1e6:.1f} | – | measured here |"
        )
    if hopsan_us_per_step is not None and hopsan_us_per_step == hopsan_us_per_step:
        lines.append(
            f"| Position Servo example (Hopsan) | Hopsan's compiled fixed-step solver | {hopsan_us_per_step:.2f} "
            "| – | – | measured here (`bench_hopsan.py`, below) |"
        )
    else:
        lines.append(
            f"| Position Servo example (Hopsan) | Hopsan compiled solver, 2-core machine | {bench_realtime.HOPSAN_US_PER_STEP} "
            "| – | – | quoted, not measured here |"
        )
    head = (
        f"Real time, `python benchmarks/bench_realtime.py`'s measurements ({version}, -O2): the C code of "
        "`hydroservo export-c` compiled and run in this process (`hydroservo.codegen.c.CStepper`, the whole run in "
        "one call into C, nothing recorded; medians over repeats), beside CVODES called from Python once per step "
        "as a real-time loop in Python would. Deviation: the largest |C − CVODES| over the run on the main signals "
        f"({'; '.join(signals)}), relative to each signal's range, against CVODES at rtol 1e-10.\n\n"
    )
    return head + "\n".join(lines) + "\n"


def hopsan(found: dict) -> str:
    """The comparison with Hopsan on its Position Servo example (``bench_hopsan.measure``): at its defaults, at
    equal accuracy, per step and per process; Hopsan measured when HOPSAN_ROOT names its build, else quoted."""
    source = "measured here" if found["measured_hopsan"] else "quoted from docs/engine.md"
    lines = ["| target (each tool against its own converged result) | Hopsan | hydroservo | ratio |", "|---|---|---|---|"]
    for label, (a, b) in found["best"].items():
        ta = f"{a[0] * 1e3:.1f} ms ({a[1]})" if a else "not reached by Ts 1e-6"
        tb = f"{b[0] * 1e3:.1f} ms ({b[1]})" if b else "not reached"
        ratio = f"{a[0] / b[0]:.1f}x faster" if a and b else "–"
        lines.append(f"| {label} | {ta} | {tb} | {ratio} |")
    step = found["per_step"]
    hopsan_step = f"{step['hopsan'] * 1e6:.3f} µs" if step["hopsan"] == step["hopsan"] else "0.165 µs (quoted)"
    lines.append(f"| one step (hydroservo: exported rk4) | {hopsan_step} | {step['hydroservo rk4'] * 1e6:.3f} µs | – |")
    process = found["per_process"]
    theirs = process.get("hopsancli (Ts 1e-4, its default)")
    ours = process["standalone simulator, accuracy 1e-3"]
    lines.append(
        f"| whole process (Hopsan: `hopsancli` at its default; hydroservo: `export-c --main` simulator at accuracy "
        f"1e-3) | {f'{theirs:.3f} s' if theirs else '0.015 s (quoted)'} | {ours:.3f} s | "
        f"{f'{theirs / ours:.1f}x faster' if theirs else '–'} |"
    )
    default, default_dev = next((s, d) for label, s, d in found["hydroservo"] if label == "rodas3 1e-04")
    cvodes = next(s for label, s, _ in found["hydroservo"] if label == "cvodes 1e-04")
    hopsan_default = found["hopsan"][0] if found["hopsan"] else None
    if hopsan_default is not None:
        lines.append(
            f"| each at its defaults (Hopsan: Ts 1e-4, x within {hopsan_default[2]['x']:.1e}; hydroservo: rodas3 "
            f"at accuracy 1e-4, x within {default_dev['x']:.0e}) | {hopsan_default[1] * 1e3:.1f} ms | "
            f"{default * 1e3:.1f} ms | {hopsan_default[1] / default:.2f}x |"
        )
    cli = process["hydroservo simulate --json (its defaults: rodas3 compiled, accuracy 1e-4)"]
    head = (
        "Against Hopsan on its own Position Servo example (`python benchmarks/bench_hopsan.py`; Hopsan "
        f"{source}; in-process times of one 3-s run, medians of 5): hydroservo's fastest setting that meets "
        f"each target (dopri5, ros23 and rodas3 compiled, or CVODES). Its default, rodas3 at accuracy 1e-4 "
        f"(CVODES before 0.6: {cvodes * 1e3:.0f} ms), takes {default * 1e3:.0f} ms in process and {cli:.2f} s as a "
        "command: it holds every signal to about 1e-4, which Hopsan's default does not attempt (docs/engine.md, "
        "\"Compiled solvers\").\n\n"
    )
    return head + "\n".join(lines) + "\n"


def main(write: bool) -> None:
    import os

    against_hopsan = bench_hopsan.measure(repeat=5, hopsan=os.environ.get("HOPSAN_ROOT"))
    text = (
        table(rows())
        + "\n"
        + realtime(against_hopsan["per_step"]["hopsan"] * 1e6)
        + "\n"
        + hopsan(against_hopsan)
    )
    print(text)
    if write:
        readme = README.read_text(encoding="utf-8")
        if START not in readme or END not in readme:
            raise SystemExit(f"{README}: no {START} ... {END} block to write the table into")
        block = f"{START}\n{text}{END}"
        README.write_text(re.sub(re.escape(START) + ".*?" + re.escape(END), lambda _: block, readme, flags=re.S))
        print(f"wrote the table into {README}")


if __name__ == "__main__":
    main("--readme" in sys.argv)
