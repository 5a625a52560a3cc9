"""The speed suite: every figure of the README's speed table, each beside its baseline, in one run.

Run: ``python benchmarks/suite.py`` (prints the tables), ``--readme`` (also writes them into README.md between
its ``speed-table``, ``realtime-rows`` and ``hopsan-table`` markers, and docs/engine.md's and docs/realtime.md's
tables), ``--parts rows,realtime,hopsan`` (some of them; Hopsan's figures need ``HOPSAN_ROOT``, its build by
``../shared/tools/hopsan/build_hopsan.sh``). Takes a few minutes on an idle machine.

Each row is a ratio to a baseline measured in the same run on the same machine
(medians over repeats), never an absolute promise, or a whole command's CPU and wall time. Every figure is
also written to benchmarks/results/<bench>.json with the date and the machine, and the table quotes each after
a marker naming its key (benchmarks/results.py; tests/integration/test_claims.py holds the pages to them).
"""

from __future__ import annotations

import os
import platform
import re
import sys
from pathlib import Path

import bench_accuracy
import bench_cli
import bench_compiled
import bench_flight_simulator
import bench_growth
import bench_hopsan
import bench_realtime
import bench_startup
import bench_warm
from results import load, mark, record

from hydroservo.errors import ParameterError

README = Path(__file__).resolve().parents[1] / "README.md"
ENGINE = README.parent / "docs" / "engine.md"
REALTIME = README.parent / "docs" / "realtime.md"
START, END = "<!-- speed-table:start -->", "<!-- speed-table:end -->"
SCRIPT = "benchmarks/suite.py"
#: The step of the real-time rows [s]: the C stepper's runs of bench_realtime.CASES at it, and CVODES's.
REALTIME_STEP = 1e-4


def rows() -> list[tuple[str, str, str]]:
    """(what, hydroservo, baseline) rows of the table, measured now; each bench's figures written to
    benchmarks/results/<bench>.json and quoted after their markers."""
    out: list[tuple[str, str, str]] = []
    start = bench_startup.main(7)
    base = start["baseline: python -c pass"]
    fig = {"import_s": start["import hydroservo"] - base,
           "first_use_s": start["import hydroservo; first use of hs.System"] - base,
           "version_s": start["hydroservo --version"] - base, "help_s": start["hydroservo --help"] - base}  # fmt: skip
    record("startup", fig, script=SCRIPT)
    out.append(("`import hydroservo`", f"{mark('startup.import_s', fig['import_s'], '.3f')} s CPU", "over a bare interpreter"))
    cli = bench_cli.main(5)
    for model in ("position_servo", "flight_simulator"):
        out.append((
            f"`hydroservo simulate {model.replace('_', '-')} --json`, end to end, compiled model in the cache "
            "(CPU time, then wall time; medians)",
            f"{mark(f'cli.{model}_warm_cpu_s', cli[f'{model}_warm_cpu_s'], '.2f')} s CPU, "
            f"{mark(f'cli.{model}_warm_wall_s', cli[f'{model}_warm_wall_s'], '.2f')} s wall",
            "one process",
        ))  # fmt: skip
    out.append((
        "`hydroservo simulate position-servo --json`, first run of the model: it compiles the model's C code",
        f"{mark('cli.position_servo_first_cpu_s', cli['position_servo_first_cpu_s'], '.1f')} s CPU, "
        f"{mark('cli.position_servo_first_wall_s', cli['position_servo_first_wall_s'], '.1f')} s wall",
        "one process, empty cache",
    ))  # fmt: skip
    fs = bench_flight_simulator.main()
    record("flight_simulator", {k: v for k, v in fs.items() if isinstance(v, (int, float))}, script=SCRIPT)
    out.append((
        "flight-simulator 2-s step, CVODES vs SciPy LSODA (Python right-hand side), equal accuracy",
        f"{mark('flight_simulator.ratio_equal_accuracy', fs['ratio_equal_accuracy'], '.1f')}x faster",
        "`solve_ivp(method='LSODA')`",
    ))  # fmt: skip
    warm = bench_warm.main()
    record("warm", warm, script=SCRIPT)
    out.append((
        "warm `System.simulate(method=\"cvodes\")` + reading `y`",
        f"{mark('warm.simulate_y_ratio', warm['simulate_y_ratio'], '.2f')}x", "the bare CVODES call",
    ))  # fmt: skip
    out.append((
        f"batch of {warm['batch_runs']:.0f} runs (load varied, 2 threads) with their outputs read",
        f"{mark('warm.batch_ratio', warm['batch_ratio'], '.2f')}x", "its integration time",
    ))  # fmt: skip
    comp = bench_compiled.main(repeat=5)
    fig = {}
    for target in (1e-3, 1e-4):
        best = min(comp["best"][m, target] + (m,) for m in ("rodas3", "ros23", "dopri5"))
        (ours, a, method), (base, b) = best, comp["best"]["cvodes", target]
        key = f"ratio_{target:.0e}"
        fig[key] = base / ours
        out.append((
            f"flight-simulator within {target:g} of range: compiled {method} (accuracy {a:g}) vs CVODES ({b:g}), "
            "each at its cheapest accuracy meeting it",
            f"{mark(f'compiled.{key}', fig[key], '.2f')}x faster", "CVODES (CasADi, interpreted model)",
        ))  # fmt: skip
    for m, v in comp["batch_speedup"].items():
        fig[f"batch_speedup_{m}"] = v
    record("compiled", fig, script=SCRIPT)
    out.append((
        "batch of 64 flight-simulator runs, compiled rodas3: CPU time on 1 thread over CPU time on 2 (the work the threads add; "
        "what they save in wall time cannot be measured here, where a session gets about half a core)",
        f"{mark('compiled.batch_speedup_rodas3', fig['batch_speedup_rodas3'], '.2f')}x", "1 thread",
    ))  # fmt: skip
    acc = bench_accuracy.main(repeat=3, methods=("rodas3",))
    fig = {}
    for key, devs in sorted(acc.items()):
        if 1e-4 not in devs:
            continue
        model = key.split()[0]
        name = f"{model.replace('-', '_')}_1e-4"
        fig[name] = devs[1e-4]
        mark_ = " (above it: docs/engine.md, \"Accuracy\", says which signals)" if devs[1e-4] > 1e-4 else ""
        out.append((
            f"default (rodas3 at accuracy 1e-4), `{model}`: largest deviation of its plotted signals",
            f"{mark(f'accuracy.{name}', devs[1e-4], '.0e')}{mark_}", "of each signal's range, vs CVODES at rtol 1e-11",
        ))  # fmt: skip
    record("accuracy", fig, script=SCRIPT)
    growth = bench_growth.main(repeat=3)
    (b1, r1, s1), (b24, r24, s24) = growth[1], growth[24]
    fig = {"build_per_loop_24": b24 / 24 / b1, "run_per_step_loop_24": r24 / s24 / 24 / (r1 / s1)}
    record("growth", fig, script=SCRIPT)
    out.append((
        "24 actuator loops in one model (240 states): build time per loop; run time per step and loop",
        f"{mark('growth.build_per_loop_24', fig['build_per_loop_24'], '.2f')}x; "
        f"{mark('growth.run_per_step_loop_24', fig['run_per_step_loop_24'], '.2f')}x", "one loop",
    ))  # fmt: skip
    return out


def table(found: list[tuple[str, str, str]]) -> str:
    load = f"; load average {os.getloadavg()[0]:.0f} on {os.cpu_count()} cores" if hasattr(os, "getloadavg") else ""
    head = (f"Measured by `python benchmarks/suite.py --readme` ({platform.machine()}, {sys.version.split()[0]}{load}: "
            "other processes' load inflates wall times most, CPU times less, ratios least):\n\n")  # fmt: skip
    lines = ["| what | hydroservo | against |", "|---|---|---|"]
    lines += [f"| {a} | {b} | {c} |" for a, b, c in found]
    return head + "\n".join(lines) + "\n"


def realtime(hopsan_us_per_step: float | None = None) -> str:
    """The real-time section: the exported C stepper (rk4, bdf2) on each model of bench_realtime.CASES, CVODES
    one step at a time from Python beside it, Hopsan's measured figure; or why it was skipped (no C compiler, or
    the stepper failed to build). Every run of CASES is measured and written to results/realtime.json; the table
    shows those at REALTIME_STEP."""
    try:
        version = bench_realtime.compiler_version()
        figures = [bench_realtime.measure(name, t_end, names, runs, with_output=True)
                   for name, t_end, names, runs in bench_realtime.CASES]  # fmt: skip
    except (ParameterError, OSError) as exc:  # no compiler, or the stepper did not build or load
        reason = str(exc).splitlines()[0].rstrip(".")
        print(f"real-time rows skipped: {reason}\n")
        return f"Real-time rows skipped in this run: {reason}.\n"
    fig: dict[str, float | None] = {}
    for f in figures:
        model = f["model"].replace("-", "_")
        for run in f["runs"]:
            key = f"{model}_{run['method']}_{run['h']:.0e}"
            fig[f"{key}_us"] = run["us_per_step"]
            fig[f"{key}_real_time"] = run["real_time"]
            fig[f"{key}_dev"] = max(run["deviation"].values())
            fig[f"{key}_us_recorded"] = run.get("us_per_step_recorded")
        fig[f"{model}_cvodes_us"] = f["cvodes_per_step_us"]
        fig[f"{model}_cvodes_output_us"] = f.get("cvodes_output_us")
        fig[f"{model}_cvodes_real_time"] = f["cvodes_h"] / f["cvodes_per_step_us"] * 1e6
    record("realtime", fig, script=SCRIPT)
    global REALTIME_DOC
    REALTIME_DOC = realtime_doc(figures, version)
    lines = [
        f"| model | solver, step h = {REALTIME_STEP * 1e3:g} ms | µs per step | × real time | deviation from CVODES (of signal range) | measured or quoted |",
        "|---|---|---:|---:|---:|---|",
    ]
    signals = []
    for f in figures:
        model = f"`{f['model']}`"
        slug = f["model"].replace("-", "_")
        signals.append(f"{model}: {', '.join(f'`{s}`' for s in f['signals'])}")
        for run in f["runs"]:
            if run["h"] != REALTIME_STEP:
                continue
            key = f"realtime.{slug}_{run['method']}_{run['h']:.0e}"
            lines.append(
                f"| {model} | exported C stepper, {run['method']} | {mark(key + '_us', run['us_per_step'], '.2f')} "
                f"| {mark(key + '_real_time', run['real_time'], '.0f')} | {mark(key + '_dev', fig[key[9:] + '_dev'], '.0e')} "
                "| measured here |"
            )
        lines.append(
            f"| {model} | baseline: CVODES one step at a time from Python "
            f"| {mark(f'realtime.{slug}_cvodes_us', f['cvodes_per_step_us'], '.0f')} "
            f"| {mark(f'realtime.{slug}_cvodes_real_time', fig[f'{slug}_cvodes_real_time'], '.1f')} | – | measured here |"
        )
    if hopsan_us_per_step is not None and hopsan_us_per_step == hopsan_us_per_step:
        lines.append(
            f"| Position Servo example (Hopsan) | Hopsan's compiled fixed-step solver "
            f"| {mark('hopsan.step_hopsan_us', hopsan_us_per_step, '.2f')} | – | – | measured here (`bench_hopsan.py`, below) |"
        )
    else:
        lines.append("| Position Servo example (Hopsan) | Hopsan's compiled fixed-step solver | not measured (no Hopsan "
                     "build at hand) | – | – | – |")  # fmt: skip
    head = (
        f"Real time, `python benchmarks/bench_realtime.py`'s measurements ({version}, -O2): the C code of "
        "`hydroservo export-c` compiled and run in this process (`hydroservo.codegen.c.CStepper`, the whole run in "
        "one call into C, nothing recorded; CPU time, medians over repeats), beside CVODES called from Python once per "
        "step "
        "as a real-time loop in Python would. Deviation: the largest |C − CVODES| over the run on the main signals "
        f"({'; '.join(signals)}), relative to each signal's range, against CVODES at rtol 1e-10.\n\n"
    )
    return head + "\n".join(lines) + "\n"


#: docs/realtime.md's table, made by the last :func:`realtime`
REALTIME_DOC = ""


def realtime_doc(figures: list[dict], version: str) -> str:
    """docs/realtime.md's tables: every run of bench_realtime.CASES, and the baselines per step."""
    lines = [
        f"Measured by `python benchmarks/suite.py --readme` ({version}, -O2; CPU time, medians over repeats). "
        "Deviation: the "
        "largest |C - CVODES| over the run on the main signals, relative to each signal's range, against CVODES at "
        "rtol 1e-10 on a 1 ms grid.",
        "",
        "| model | method | step | µs per step | × real time | µs per step with every output recorded | "
        "largest deviation from CVODES (of range) |",
        "|---|---|---|---|---|---|---|",
    ]
    for f in figures:
        slug = f["model"].replace("-", "_")
        for k, run in enumerate(f["runs"]):
            key = f"realtime.{slug}_{run['method']}_{run['h']:.0e}"
            name = f"`{f['model']}` ({f['t_end']:g} s; {', '.join(f['signals'])})" if k == 0 else ""
            lines.append(
                f"| {name} | {run['method']} | {run['h'] * 1e3:g} ms | {mark(key + '_us', run['us_per_step'], '.2f')} "
                f"| {mark(key + '_real_time', run['real_time'], '.0f')} "
                f"| {mark(key + '_us_recorded', run.get('us_per_step_recorded'), '.2f')} "
                f"| {mark(key + '_dev', max(run['deviation'].values()), '.1e')} |"
            )
    lines += ["", "Beside them, per step of 0.1 ms:", "", "| | " + " | ".join(f["model"] for f in figures) + " |",
              "|---|" + "---|" * len(figures)]  # fmt: skip
    cells = []
    for f in figures:
        slug = f["model"].replace("-", "_")
        cells.append(f"{mark(f'realtime.{slug}_cvodes_us', f['cvodes_per_step_us'], '.0f')} µs: "
                     f"{mark(f'realtime.{slug}_cvodes_real_time', f['cvodes_h'] / f['cvodes_per_step_us'] * 1e6, '.1f')} × real time")  # fmt: skip
    lines.append("| CVODES from Python, one CasADi integrator call per step (what a real-time loop in Python would do) | "
                 + " | ".join(cells) + " |")  # fmt: skip
    cells = []
    for f in figures:
        slug = f["model"].replace("-", "_")
        cells.append(f"{mark(f'realtime.{slug}_cvodes_output_us', f.get('cvodes_output_us'), '.1f')} µs")
    lines.append("| CVODES, one `System.simulate` run with an output every 0.1 ms (offline: its own steps, outputs "
                 "interpolated) | " + " | ".join(cells) + " |")  # fmt: skip
    return "\n".join(lines) + "\n"


def hopsan(found: dict) -> str:
    """The comparison with Hopsan on its Position Servo example (``bench_hopsan.measure``): at its defaults, at
    equal accuracy, per step and per process; Hopsan's figures only when HOPSAN_ROOT names its build."""
    fig = bench_hopsan.figures(found)
    record("hopsan", fig, script="benchmarks/bench_hopsan.py")

    def m(key: str, spec: str) -> str:
        return mark(f"hopsan.{key}", fig.get(key), spec)

    if not found["measured_hopsan"]:
        return ("Against Hopsan on its own Position Servo example (`python benchmarks/bench_hopsan.py --hopsan "
                "HOPSAN_ROOT`): not measured in this run (no Hopsan build at hand).\n")  # fmt: skip
    lines = ["| target (each tool against its own converged result) | Hopsan | hydroservo | ratio (Hopsan's time over hydroservo's) |",
             "|---|---|---|---|"]  # fmt: skip
    for label, (a, b) in found["best"].items():
        key = bench_hopsan.slug(label)
        ta = f"{m(key + '_hopsan_ms', '.1f')} ms ({a[1]})" if a else "not reached by Ts 1e-6"
        tb = f"{m(key + '_hydroservo_ms', '.1f')} ms ({b[1]})" if b else "not reached"
        ratio = f"{m(key + '_ratio', '.2f')}x" if a and b else "–"
        lines.append(f"| {label} | {ta} | {tb} | {ratio} |")
    lines.append(f"| one step (hydroservo: exported rk4) | {m('step_hopsan_us', '.3f')} µs | {m('step_rk4_us', '.3f')} µs | – |")
    lines.append(
        "| whole process, CPU time (Hopsan: `hopsancli` at its default; hydroservo: `export-c --main` simulator at "
        f"accuracy 1e-3) | {m('process_hopsancli_s', '.3f')} s | {m('process_standalone_s', '.3f')} s | "
        f"{m('process_ratio', '.2f')}x |"
    )
    lines.append(
        f"| each at its defaults (Hopsan: Ts 1e-4, x within {m('hopsan_default_x_dev', '.1e')}; hydroservo: rodas3 "
        f"at accuracy 1e-4, x within {m('default_hydroservo_x_dev', '.0e')}) | {m('default_hopsan_ms', '.1f')} ms | "
        f"{m('default_hydroservo_ms', '.1f')} ms | {m('default_ratio', '.2f')}x |"
    )
    head = (
        "Against Hopsan on its own Position Servo example (`python benchmarks/bench_hopsan.py`; Hopsan built from "
        "source and measured here; one 3-s run in process, CPU time): hydroservo's fastest setting that meets "
        "each target (dopri5, ros23 and rodas3 compiled, or CVODES) against Hopsan's largest step that does; the "
        "two then timed again in turn, 5 rounds of 3 runs each, medians of each tool's time and of the rounds' "
        f"ratios. hydroservo's default, rodas3 at accuracy 1e-4 (CVODES before 0.6: {m('cvodes_1e-4_ms', '.0f')} "
        f"ms), takes {m('default_hydroservo_ms', '.0f')} ms in process; as a command, see the first rows of the "
        "table above: it holds every signal to about 1e-4, which Hopsan's default does not attempt (docs/engine.md, "
        "\"Compiled solvers\").\n\n"
    )
    return head + "\n".join(lines) + "\n"


def write_block(page: Path, start: str, end: str, text: str) -> None:
    found = page.read_text(encoding="utf-8")
    if start not in found or end not in found:
        raise SystemExit(f"{page}: no {start} ... {end} block to write the table into")
    block = f"{start}\n{text}{end}"
    page.write_text(re.sub(re.escape(start) + ".*?" + re.escape(end), lambda _: block, found, flags=re.S), encoding="utf-8")
    print(f"wrote the table into {page}")


#: the parts of the suite, each written into its own block of README.md
PARTS = ("rows", "realtime", "hopsan")


def main(write: bool, parts: tuple[str, ...] = PARTS) -> None:
    if "rows" in parts:
        text = table(rows())
        print(text)
        if write:
            write_block(README, START, END, text)
    if "realtime" in parts:
        try:
            step = load("hopsan")["figures"].get("step_hopsan_us")
        except OSError:
            step = None
        text = realtime(step)
        print(text)
        if write:
            write_block(README, "<!-- realtime-rows:start -->", "<!-- realtime-rows:end -->", text)
            if REALTIME_DOC:
                write_block(REALTIME, "<!-- realtime-table:start -->", "<!-- realtime-table:end -->", REALTIME_DOC)
    if "hopsan" in parts:
        text = hopsan(bench_hopsan.measure(repeat=5, hopsan=os.environ.get("HOPSAN_ROOT")))
        print(text)
        if write:
            write_block(README, "<!-- hopsan-table:start -->", "<!-- hopsan-table:end -->", text)
            write_block(ENGINE, "<!-- hopsan-table:start -->", "<!-- hopsan-table:end -->", text.split("\n\n", 1)[1])


if __name__ == "__main__":
    chosen = PARTS
    if "--parts" in sys.argv:
        chosen = tuple(sys.argv[sys.argv.index("--parts") + 1].split(","))
        unknown = set(chosen) - set(PARTS)
        if unknown:
            raise SystemExit(f"--parts {','.join(sorted(unknown))}: expected some of {','.join(PARTS)}")
    main("--readme" in sys.argv, chosen)
