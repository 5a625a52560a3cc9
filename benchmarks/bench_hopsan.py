"""hydroservo against Hopsan on Hopsan's own "Position Servo" example (3 s): at each tool's defaults, at equal
accuracy, per step and per process.

Run: ``python benchmarks/bench_hopsan.py [--hopsan HOPSAN_ROOT] [--repeat N]``

Accuracy: each tool's deviation from its own converged solution, relative to the signal's range over the run,
on the 601 times of the reference (every 5 ms), so that the small difference between the two models (0.0004 %
of range, docs/hopsan.md) does not count against either:

* hydroservo: against itself with CVODES at accuracy 1e-8 (rtol 1e-10);
* Hopsan: against its converged result (Richardson extrapolation of its fixed-step scheme, shipped in
  ``data/reference/hopsan_position_servo.csv``, itself uncertain to about 5e-4 of range: a Hopsan deviation
  below that cannot be told from the reference's own error).

Targets: the piston position within 3e-2 of its range (about Hopsan's default step of 0.1 ms), 1e-3 and 1e-4;
and every signal compared (position, velocity, chamber pressure) within 1e-3. For each, the cheapest setting
that meets it: hydroservo over methods (dopri5, ros23 compiled; CVODES) and accuracies; Hopsan over its
fixed step; then the two cheapest settings of each target timed again in turn (rounds of Hopsan then hydroservo),
the published ratio being the median of the rounds' ratios. In-process times are CPU-time medians over repeats
(steadier than wall time on a shared machine; both tools run one thread), in process (Hopsan: ``hopsan_bench``, built by
``../shared/tools/hopsan/build_hopsan.sh``: its ``simulate`` call, the model loaded and initialised outside
it; hydroservo: ``System.simulate`` on the model built, the compiled solvers from the cache) and per process
(``hopsancli`` and ``hydroservo simulate --json``, and the standalone simulator of ``export-c --main``: the
CPU time of each whole process, its children included).

Without Hopsan (no ``--hopsan`` and no ``HOPSAN_ROOT``) its figures are quoted from docs/engine.md (measured
on this machine type, 2 cores, with the same programs).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np
from results import median_cpu, record

import hydroservo as hs
from hydroservo.codegen.c import CStepper, export_c
from hydroservo.data import reference_text

#: Hopsan's figures when it is not at hand: docs/engine.md, measured with hopsan_bench on this machine type
#: (2 cores, 2026-11-26, Hopsan at commit 0c3995e): its simulate call [s] at each step, and the deviation of x
#: from its converged result.
QUOTED_HOPSAN = {1e-4: (5.31e-3, 3.1e-2), 3e-5: (17.2e-3, 6.9e-3), 1e-5: (49.3e-3, 2.1e-3), 3e-6: (168e-3, 5.9e-4),
                 1e-6: (496e-3, 2.0e-4)}  # fmt: skip

HYDROSERVO = [(m, a, e) for m in ("dopri5", "ros23", "rodas3", "cvodes") for a in (1e-1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5)
              for e in ((True, False) if m != "cvodes" else (True,))]  # fmt: skip
HOPSAN_STEPS = (1e-4, 3e-5, 1e-5, 3e-6, 1e-6)
TARGETS = [("x within 3e-2", ("x",), 3e-2), ("x within 1e-3", ("x",), 1e-3), ("x within 1e-4", ("x",), 1e-4),
           ("x, v, pA within 1e-3", ("x", "v", "pA"), 1e-3)]  # fmt: skip



def reference() -> dict[str, np.ndarray]:
    import io

    data = np.genfromtxt(io.StringIO(reference_text("hopsan_position_servo.csv")), delimiter=",", skip_header=1)
    return {"t": data[:, 0], "x": data[:, 1], "v": data[:, 2], "pA": data[:, 3]}


def deviations(signals: dict[str, np.ndarray], converged: dict[str, np.ndarray]) -> dict[str, float]:
    return {k: float(np.max(np.abs(signals[k] - converged[k])) / np.ptp(converged[k])) for k in ("x", "v", "pA")}



def hydroservo_signals(result: hs.Result) -> dict[str, np.ndarray]:
    return {"x": result["load.x"], "v": result["load.v"], "pA": result["cyl.pA"]}


def hydroservo_runs(repeat: int) -> list[tuple[str, float, float, dict[str, float]]]:
    system = hs.load_model("position-servo")
    grid = reference()["t"]
    converged = hydroservo_signals(system.simulate(t_eval=grid, accuracy=1e-8, method="cvodes"))
    rows = []
    for method, accuracy, events in HYDROSERVO:
        try:  # the first run builds the compiled model (or finds it in the cache)
            result = system.simulate(t_eval=grid, accuracy=accuracy, method=method, events=events)
        except hs.errors.SolverError:
            continue
        seconds = median_cpu(
            lambda a=accuracy, m=method, e=events: system.simulate(t_eval=grid, accuracy=a, method=m, events=e), repeat
        )
        label = method if events or method == "cvodes" else f"{method} no events"
        rows.append((label, accuracy, seconds, deviations(hydroservo_signals(result), converged)))
    return rows


def hopsan_runs(root: Path, repeat: int) -> list[tuple[float, float, float, dict[str, float]]]:
    bench = root / "bench" / "hopsan_bench"
    model = root / "PositionServo.hmf"
    library = root / "install" / "componentLibraries" / "defaultLibrary" / "libdefaultcomponentlibrary.so"
    ref = reference()
    converged = {k: ref[k] for k in ("x", "v", "pA")}
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for ts in HOPSAN_STEPS:
            out = Path(folder) / "run.csv"
            done = subprocess.run([str(bench), str(model), repr(ts), "3", "601", str(repeat), str(out), str(library)],
                                  capture_output=True, text=True, timeout=3600)  # fmt: skip
            if done.returncode != 0:
                print(f"hopsan_bench at Ts {ts:g} failed: {done.stderr.strip()[:200]}")
                continue
            sims = [float(line.split()[9]) for line in done.stdout.splitlines() if line.startswith("rep ")]  # sim_cpu
            header = out.read_text().splitlines()[0].split(",")
            data = np.loadtxt(out, delimiter=",", skiprows=1)
            t = data[:, 0]
            signals = {
                "x": np.interp(ref["t"], t, data[:, header.index("Mass.P2.Position")]),
                "v": np.interp(ref["t"], t, data[:, header.index("Mass.P2.Velocity")]),
                "pA": np.interp(ref["t"], t, data[:, header.index("4_3_Servo_Valve.PA.Pressure")]),
            }
            rows.append((ts, statistics.median(sims), 3.0 / ts, deviations(signals, converged)))
    return rows


def per_step(repeat: int) -> float:
    """The compiled fixed-step rk4's cost of one step [s] on position-servo (one call into C for 30 000 steps)."""
    stepper = CStepper(hs.load_model("position-servo"), step=1e-6)
    steps = 30_000

    def run() -> None:
        stepper.reset()
        stepper.advance(steps)

    return median_cpu(run, repeat) / steps


def process_cpu(argv: list[str], env: dict[str, str] | None = None) -> float:
    """The CPU time [s] of one whole process (user + system, its children included)."""
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"{' '.join(argv)} failed")
    return usage.ru_utime + usage.ru_stime


def median_process(fn, repeat: int) -> float:
    """The median over ``repeat`` calls of ``fn()``, which returns a time."""
    return statistics.median(fn() for _ in range(repeat))


def per_process(repeat: int, hopsan: Path | None) -> dict[str, float]:
    found = {}
    with tempfile.TemporaryDirectory() as folder:
        export = export_c(hs.load_model("position-servo"), Path(folder) / "c", step=1e-4, main=True, build=True)
        for accuracy in ("1e-2", "1e-3"):
            found[f"standalone simulator, accuracy {accuracy}"] = median_process(
                lambda a=accuracy: process_cpu(
                    [str(export.executable), "--method", "dopri5", "--accuracy", a, "--points", "601"]
                ),
                repeat,
            )
        # as installed by pip: the modules' bytecode compiled (into a folder of this run's, by a first run, which
        # also finds or builds the compiled model), whatever PYTHONDONTWRITEBYTECODE says here
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = str(Path(folder) / "pycache")
        command = [sys.executable, "-m", "hydroservo", "simulate", "position-servo", "--json"]
        for args in ([], ["--method", "dopri5", "--accuracy", "1e-2"]):
            subprocess.run([*command, *args], capture_output=True, check=True, env=env)
        found["hydroservo simulate --json (its defaults: rodas3 compiled, accuracy 1e-4)"] = median_process(
            lambda: process_cpu(command, env), repeat
        )
        found["hydroservo simulate --json --method dopri5 --accuracy 1e-2"] = median_process(
            lambda: process_cpu([*command, "--method", "dopri5", "--accuracy", "1e-2"], env), repeat
        )
    if hopsan is not None:
        cli = hopsan / "install" / "bin" / "hopsancli"
        model = hopsan / "PositionServo.hmf"
        found["hopsancli (Ts 1e-4, its default)"] = median_process(
            lambda: process_cpu([str(cli), "-m", str(model), "-s", "hmf"]), repeat
        )
    return found


def cheapest(rows, signals: tuple[str, ...], bound: float):
    """The (time, label) of the cheapest row whose deviation on ``signals`` is at most ``bound``, or None."""
    return min(((seconds, label) for label, seconds, dev in rows if max(dev[k] for k in signals) <= bound),
               default=None)  # fmt: skip


def setting(label: str) -> tuple[str, float, bool]:
    """(method, accuracy, events) of a hydroservo row's label ("dopri5 no events 1e-01")."""
    words = label.split()
    return words[0], float(words[-1]), "no" not in words


def paired(root: Path, ts: float, ours: str, repeat: int, each: int = 3) -> tuple[float, float, float]:
    """Hopsan at step ``ts`` and hydroservo at the setting labelled ``ours``, in turn, ``repeat`` rounds of
    ``each`` runs: the medians of Hopsan's CPU time, of hydroservo's and of the ratio round by round (the pairing
    keeps the ratio meaningful when the machine's load drifts)."""
    bench = root / "bench" / "hopsan_bench"
    model = root / "PositionServo.hmf"
    library = root / "install" / "componentLibraries" / "defaultLibrary" / "libdefaultcomponentlibrary.so"
    system = hs.load_model("position-servo")
    grid = reference()["t"]
    method, accuracy, events = setting(ours)
    system.simulate(t_eval=grid, accuracy=accuracy, method=method, events=events)
    theirs_s, ours_s, ratios = [], [], []
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "run.csv"
        for _ in range(repeat):
            done = subprocess.run([str(bench), str(model), repr(ts), "3", "601", str(each), str(out), str(library)],
                                  capture_output=True, text=True, timeout=3600, check=True)  # fmt: skip
            a = statistics.median(float(line.split()[9]) for line in done.stdout.splitlines() if line.startswith("rep "))
            b = median_cpu(lambda: system.simulate(t_eval=grid, accuracy=accuracy, method=method, events=events), each)
            theirs_s.append(a)
            ours_s.append(b)
            ratios.append(a / b)
    return statistics.median(theirs_s), statistics.median(ours_s), statistics.median(ratios)


#: the figures' keys of each target (benchmarks/results/hopsan.json)
SLUGS = {"x within 3e-2": "x_3e-2", "x within 1e-3": "x_1e-3", "x within 1e-4": "x_1e-4", "x, v, pA within 1e-3": "xvp_1e-3"}


def slug(label: str) -> str:
    return SLUGS.get(label, "hopsan_default")


def measure(repeat: int = 7, hopsan: str | None = None) -> dict:
    """Every figure: the runs of both tools, the cheapest setting per target (then timed again, the two tools in
    turn), per step, per process."""
    warnings.simplefilter("ignore", hs.ImplausibleResultWarning)  # the 55 MPa peak, in Hopsan's result too
    root = Path(hopsan) if hopsan and (Path(hopsan) / "bench" / "hopsan_bench").exists() else None
    ours = [(f"{m} {a:.0e}", s, d) for m, a, s, d in hydroservo_runs(repeat)]
    if root is not None:
        theirs_runs = hopsan_runs(root, repeat)
        theirs = [(f"Ts {ts:.0e}", s, d) for ts, s, _, d in theirs_runs]
        fine = next(((s, n) for ts, s, n, _ in theirs_runs if ts == 1e-6), None)
        hopsan_step = fine[0] / fine[1] if fine else float("nan")
    else:
        theirs_runs = []
        theirs = [(f"Ts {ts:.0e} (quoted)", s, {"x": dx, "v": float("nan"), "pA": float("nan")})
                  for ts, (s, dx) in QUOTED_HOPSAN.items()]  # fmt: skip
        hopsan_step = float("nan")
    default_hopsan = theirs[0] if theirs else None
    # Hopsan's default: the deviation its default step gives, and the cheapest hydroservo run within it
    targets = list(TARGETS)
    if default_hopsan is not None:
        targets.insert(0, (f"x within Hopsan's default ({default_hopsan[2]['x']:.1e})", ("x",), default_hopsan[2]["x"]))
    best = {label: (cheapest(theirs, sig, bound), cheapest(ours, sig, bound)) for label, sig, bound in targets}
    pairs = {}
    if root is not None:
        for label, (a, b) in best.items():
            if a and b:
                pairs[label] = paired(root, float(a[1].split()[1]), b[1], repeat)
    return {
        "hydroservo": ours,
        "hopsan": theirs,
        "hopsan_runs": theirs_runs,
        "measured_hopsan": root is not None,
        "best": best,
        "paired": pairs,
        "per_step": {"hydroservo rk4": per_step(repeat), "hopsan": hopsan_step},
        "per_process": per_process(repeat, root),
    }


def figures(found: dict) -> dict[str, float | None]:
    """The published figures of a :func:`measure` (benchmarks/results/hopsan.json): per target, each tool's
    CPU time [ms] and the ratio, from the paired rounds (None: a tool does not reach the target)."""
    out: dict[str, float | None] = {"measured_hopsan": float(found["measured_hopsan"])}
    for label, (a, b) in found["best"].items():
        key = slug(label)
        pair = found["paired"].get(label)
        out[f"{key}_hopsan_ms"] = pair[0] * 1e3 if pair else (a[0] * 1e3 if a else None)
        out[f"{key}_hydroservo_ms"] = pair[1] * 1e3 if pair else (b[0] * 1e3 if b else None)
        out[f"{key}_ratio"] = pair[2] if pair else None
        if key == "hopsan_default":
            out["hopsan_default_x_dev"] = found["hopsan"][0][2]["x"]
            out["hopsan_default_pA_dev"] = found["hopsan"][0][2]["pA"]
    step = found["per_step"]
    out["step_hopsan_us"] = step["hopsan"] * 1e6
    out["step_rk4_us"] = step["hydroservo rk4"] * 1e6
    process = found["per_process"]
    theirs = process.get("hopsancli (Ts 1e-4, its default)")
    ours = process["standalone simulator, accuracy 1e-3"]
    out["process_hopsancli_s"] = theirs
    out["process_standalone_s"] = ours
    out["process_ratio"] = theirs / ours if theirs else None
    out["process_cli_default_s"] = process["hydroservo simulate --json (its defaults: rodas3 compiled, accuracy 1e-4)"]
    out["process_cli_dopri5_s"] = process["hydroservo simulate --json --method dopri5 --accuracy 1e-2"]
    default, default_dev = next((s, d) for label, s, d in found["hydroservo"] if label == "rodas3 1e-04")
    out["default_hydroservo_ms"] = default * 1e3
    out["default_hydroservo_x_dev"] = default_dev["x"]
    out["default_hydroservo_pA_dev"] = default_dev["pA"]
    out["cvodes_1e-4_ms"] = next(s for label, s, _ in found["hydroservo"] if label == "cvodes 1e-04") * 1e3
    if found["hopsan"]:
        out["default_hopsan_ms"] = found["hopsan"][0][1] * 1e3
        out["default_ratio"] = found["hopsan"][0][1] / default
    if not found["measured_hopsan"]:  # Hopsan's side quoted, not measured: no figure of it, nor a ratio, is written
        for key in out:
            if key != "measured_hopsan" and ("hopsan" in key or "ratio" in key):
                out[key] = None
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--hopsan", default=os.environ.get("HOPSAN_ROOT"), help="HOPSAN_ROOT of build_hopsan.sh")
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    found = measure(args.repeat, args.hopsan)
    print("hydroservo, in process (System.simulate on the built model), position-servo 3 s, 601 output times:")
    print(f"{'setting':<26}{'time [ms]':>11}{'x dev':>10}{'v dev':>10}{'pA dev':>10}")
    for label, seconds, dev in found["hydroservo"]:
        print(f"{label:<26}{seconds * 1e3:>11.2f}{dev['x']:>10.1e}{dev['v']:>10.1e}{dev['pA']:>10.1e}")
    print("\nHopsan, in process (hopsan_bench: its simulate call)" + ("" if found["measured_hopsan"] else ", quoted"))
    for label, seconds, dev in found["hopsan"]:
        print(f"{label:<14}{seconds * 1e3:>11.2f}{dev['x']:>10.1e}{dev['v']:>10.1e}{dev['pA']:>10.1e}")
    print("\nThe cheapest setting meeting each target (deviation from each tool's own converged result):")
    print(f"{'target':<36}{'Hopsan':>26}{'hydroservo':>30}{'ratio':>9}")
    for label, (a, b) in found["best"].items():
        ta = f"{a[0] * 1e3:.2f} ms ({a[1]})" if a else "not reached"
        tb = f"{b[0] * 1e3:.2f} ms ({b[1]})" if b else "not reached"
        ratio = f"{a[0] / b[0]:.1f}x" if a and b else "-"
        print(f"{label:<36}{ta:>26}{tb:>30}{ratio:>9}")
    steps = found["per_step"]
    print(f"\nper step: compiled rk4 {steps['hydroservo rk4'] * 1e6:.3f} us; Hopsan {steps['hopsan'] * 1e6:.3f} us")
    print("\nper process (CPU time, median):")
    for label, seconds in found["per_process"].items():
        print(f"  {label:<60}{seconds:>8.3f} s")
    print("\nthe cheapest settings again, the two tools in turn (CPU time, medians; ratio round by round):")
    for label, (a, b, r) in found["paired"].items():
        print(f"  {label:<36}Hopsan {a * 1e3:8.2f} ms   hydroservo {b * 1e3:8.2f} ms   ratio {r:6.2f}")
    print(f"\nmachine: {os.cpu_count()} cores; hydroservo {hs.__version__}")
    record("hopsan", figures(found), script="benchmarks/bench_hopsan.py")


if __name__ == "__main__":
    main()
