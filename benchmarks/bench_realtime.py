"""Real time from the exported C stepper (hydroservo.codegen.c): microseconds per step, the multiple of real
time, and the deviation from CVODES, for the flight-simulator and the servo-solenoid circuit.

Run: ``python benchmarks/bench_realtime.py`` (``--stability`` also searches the longest stable rk4 step
of each model, about a minute more).

Everything is timed in this process, on this machine:

Times are CPU time of this process (the stepper and CVODES run in it, one thread), medians over repeats.

* the C stepper: the loop of ``CStepper.advance`` (one call into C for the whole run, nothing recorded),
  the median over repeats of the whole run from a reset, divided by the number of steps; and the same
  with every state and output written after every step (``CStepper.run``);
* the baselines: CVODES (hydroservo's engine, through CasADi) driven from Python one step at a time, as a
  real-time loop in Python would: one integrator call per step h, its start time a parameter; and one
  ``Model.simulate`` run with an output at every step h;
* Hopsan's compiled solver, 0.5 us per step: a quoted figure, not measured here.

Deviation: the largest |C - CVODES| over the run on each main signal, relative to that signal's range
over the run, against CVODES at rtol 1e-10 (about 1e-9 of range) on a 1 ms grid.
"""

from __future__ import annotations

import argparse
import platform
import subprocess

import casadi as ca
import numpy as np
from results import median_cpu

import hydroservo as hs
from hydroservo.codegen.c import CStepper, compiler
from hydroservo.errors import SolverError

#: model, duration [s], main signals, (method, step [s]) to time.
CASES = [
    ("flight-simulator", 2.0, ("y", "p1", "p2", "xv"), [("rk4", 1e-4), ("bdf2", 1e-4), ("bdf2", 1e-3)]),
    (
        "servo-solenoid-cylinder",
        0.4,
        ("x_mm", "cyl.pA", "cyl.pB", "xs"),
        [("rk4", 1e-4), ("bdf2", 1e-4), ("bdf2", 5e-4)],
    ),
]

#: Hopsan's compiled fixed-step solver: quoted, not measured here.
HOPSAN_US_PER_STEP = 0.5


def reference(system: hs.System, t_end: float) -> hs.Result:
    return system.simulate(t_end, t_eval=np.linspace(0.0, t_end, round(t_end / 1e-3) + 1), rtol=1e-10, atol=1e-12, method="cvodes")


def deviations(times: np.ndarray, values: np.ndarray, signals: list[str], ref: hs.Result, names) -> dict[str, float]:
    """Largest |C - CVODES| on each signal at the reference's times (within the run), relative to its range."""
    inside = ref.t <= times[-1] + 1e-12
    out = {}
    for name in names:
        c = np.interp(ref.t[inside], times, values[:, signals.index(name)])
        out[name] = float(np.max(np.abs(c - ref[name][inside])) / np.ptp(ref[name]))
    return out


def c_stepper(system: hs.System, t_end: float, method: str, h: float, ref: hs.Result, names) -> dict:
    stepper = CStepper(system, step=h, method=method)
    n = round(t_end / h)
    t, values = stepper.run(t_end)
    row = {"deviation": deviations(t, values, stepper.signals, ref, names), **stepper.statistics()}

    def loop() -> None:
        stepper.reset()
        stepper.advance(n)

    def recorded() -> None:
        stepper.reset()
        stepper.run(t_end)

    row["us_per_step"] = median_cpu(loop, 15) / n * 1e6
    row["us_per_step_recorded"] = median_cpu(recorded, 5) / n * 1e6
    return row


def cvodes_per_step(system: hs.System, h: float, frames: int = 400) -> float:
    """Microseconds for one step of h by CVODES called from Python: an integrator from t0 to t0 + h per call."""
    model = system.build()
    p = system.parameter_vector()
    t, t0 = ca.SX.sym("t"), ca.SX.sym("t0")
    z, pp = ca.SX.sym("z", model.nx), ca.SX.sym("p", model.np)
    nominal = ca.DM(model.nominal)
    dae = {"x": z, "t": t, "p": ca.vertcat(pp, t0), "ode": model.f(t0 + t, z * nominal, pp) / nominal}
    step = ca.integrator("frame", "cvodes", dae, 0.0, h, {"abstol": 1e-8, "reltol": 1e-6})
    z0 = np.asarray(model.x0(p), dtype=float).ravel() / model.nominal

    def loop() -> None:
        state = z0
        for k in range(frames):
            state = step(x0=state, p=np.append(p, k * h))["xf"]

    return median_cpu(loop, 5) / frames * 1e6


def cvodes_with_output_every_step(system: hs.System, t_end: float, h: float) -> float:
    """Microseconds per step of h for one System.simulate run with an output at every step."""
    grid = np.linspace(0.0, t_end, round(t_end / h) + 1)
    system.simulate(t_end, t_eval=grid, method="cvodes")
    return median_cpu(lambda: system.simulate(t_end, t_eval=grid, method="cvodes"), 5) / (grid.size - 1) * 1e6


def rk4_stability_limit(
    system: hs.System, t_end: float, ref: hs.Result, names, lo: float, hi: float
) -> tuple[float, float]:
    """The longest stable rk4 step between lo (stable) and hi (not), to 2 %: stable means the run is not
    refused and stays within 5 % of range of CVODES on the main signals. (An unstable mode grows without
    bound, or into a limit cycle the saturations bound; a step that no longer divides a source's jump time
    costs at most about 1e-2 there: neither is mistaken for the other.)"""

    def stable(h: float) -> bool:
        stepper = CStepper(system, step=h, method="rk4")
        try:
            t, values = stepper.run(h * np.ceil(t_end / h - 1e-9))
        except SolverError:
            return False
        return max(deviations(t, values, stepper.signals, ref, names).values()) < 0.05

    while hi / lo > 1.02:
        mid = float(np.sqrt(lo * hi))
        lo, hi = (mid, hi) if stable(mid) else (lo, mid)
    return lo, hi


def compiler_version() -> str:
    """The first line of the C compiler's ``--version`` (raises ParameterError if there is no compiler)."""
    done = subprocess.run([*compiler(), "--version"], capture_output=True, text=True)
    return (done.stdout.splitlines() or ["unknown C compiler"])[0]


def measure(name: str, t_end: float, names, runs, *, with_output: bool = True, stability: bool = False) -> dict:
    """The figures of one model, as data: ``runs`` ((method, step) pairs) of the C stepper, each a dict with
    ``method``, ``h``, ``us_per_step``, ``real_time`` (multiple of real time), ``us_per_step_recorded``,
    ``deviation`` (per signal of ``names``) and the stepper's statistics; ``cvodes_h``, ``cvodes_per_step_us``
    (CVODES one integrator call per step from Python); ``cvodes_output_us`` (one run with an output at every
    step) if ``with_output``; ``rk4_stable`` ((stable, not stable) steps) if ``stability``."""
    system = hs.load_model(name)
    ref = reference(system, t_end)
    out: dict = {"model": name, "t_end": t_end, "signals": tuple(names), "runs": []}
    for method, h in runs:
        row = c_stepper(system, t_end, method, h, ref, names)
        out["runs"].append({"method": method, "h": h, "real_time": h / row["us_per_step"] * 1e6, **row})
    h = 1e-4
    out["cvodes_h"] = h
    out["cvodes_per_step_us"] = cvodes_per_step(system, h)
    if with_output:
        out["cvodes_output_us"] = cvodes_with_output_every_step(system, t_end, h)
    if stability:
        out["rk4_stable"] = rk4_stability_limit(system, t_end, ref, names, 1e-4, 2e-3)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stability", action="store_true", help="also search the longest stable rk4 step")
    args = parser.parse_args()
    print(f"{platform.processor() or platform.machine()}, {compiler_version()}, -O2")
    print(f"Hopsan's compiled solver: {HOPSAN_US_PER_STEP} us per step (quoted, not measured here)\n")
    header = (f"{'model':<24} {'method':<6} {'h [s]':>7} {'us/step':>8} {'x real time':>11} {'us/step rec.':>12} "
              f"{'Newton it./step':>15} {'Jacobians':>9}  deviation from CVODES (of range)")  # fmt: skip
    for name, t_end, names, runs in CASES:
        fig = measure(name, t_end, names, runs, stability=args.stability)
        print(header)
        for row in fig["runs"]:
            method, h = row["method"], row["h"]
            iterations = f"{row['iterations'] / row['steps']:.2f}" if method == "bdf2" else "-"
            jacobians = str(row["jacobians"]) if method == "bdf2" else "-"
            deviation = ", ".join(f"{k} {v:.1e}" for k, v in row["deviation"].items())
            print(f"{name:<24} {method:<6} {h:>7.0e} {row['us_per_step']:>8.3f} {row['real_time']:>11.0f} "
                  f"{row['us_per_step_recorded']:>12.3f} {iterations:>15} {jacobians:>9}  {deviation}")  # fmt: skip
        h, per_call, per_output = fig["cvodes_h"], fig["cvodes_per_step_us"], fig["cvodes_output_us"]
        print(f"{name:<24} CVODES from Python, one integrator call per step of {h:g} s: {per_call:.1f} us "
              f"({h / per_call * 1e6:.1f} x real time)")  # fmt: skip
        print(f"{name:<24} CVODES, one run with an output every {h:g} s: {per_output:.2f} us per step "
              f"({h / per_output * 1e6:.0f} x real time)")  # fmt: skip
        if args.stability:
            lo, hi = fig["rk4_stable"]
            print(f"{name:<24} rk4: stable at {lo:.3g} s, not at {hi:.3g} s")
        print()


if __name__ == "__main__":
    main()
