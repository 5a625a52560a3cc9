"""The servovalve bench report of [GordicND]'s Table 1 valve: hydroservo against plain SciPy, in this process.

Run: ``python benchmarks/bench_servovalve.py`` (``--quick``: one repeat, nothing written; ``--report``: also
times hydroservo's whole bench report)

The baseline is ``reference_servovalve.py``: the same equations as
:class:`hydroservo.components.TwoStageServovalve` (quasi-static first stage,
bent flapper) written out with NumPy, the flapper tip solved by Brent's method
at every call, integrated by ``solve_ivp(method="BDF")`` with a finite-difference
Jacobian, equilibria by ``scipy.optimize.root``. Each bench test is run the
same way by both (same currents, durations, output grids, tolerances rtol 1e-6)
and timed as the median of repeats; the ratio is SciPy's time over
hydroservo's. The frequency response is compared on a subset (±5 and ±25 %
at 5, 50 and 200 Hz) because plain SciPy, simulating periods until the
fundamental repeats, takes minutes per amplitude; hydroservo's whole report
is timed on its own. The flows are compared too: both must agree.

Figures are ratios on this machine (2 cores), never absolute promises; written to
benchmarks/results/servovalve_speed.json (not with ``--quick``). Times are wall time (medians): both sides
run one thread in this process, so the machine's load slows both alike.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import root

sys.path.insert(0, str(Path(__file__).resolve().parent))
import reference_servovalve as ref  # noqa: E402
from results import record  # noqa: E402

from hydroservo.analysis import servovalve_bench as sb  # noqa: E402

P_S, P_0, RATED = 210e5, 1e5, 0.01
ATOL = np.array([1e-11, 1e-8, 1e-12, 1e-9, 1e-2, 1e-1, 1e-1])  # theta, omega, y, v, p_d, p_A, p_B (SI)


def median_time(fn: Callable[[], Any], repeat: int) -> tuple[float, Any]:
    times, out = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out


def _simulate(current: Callable[[float], float], grid: np.ndarray, s0: np.ndarray, load: Any = None) -> np.ndarray:
    n = s0.size
    sol = solve_ivp(ref.rhs, (grid[0], grid[-1]), s0, method="BDF", t_eval=grid, rtol=1e-6, atol=ATOL[:n],
                    args=(current, P_S, P_0, load))
    if sol.status != 0:
        raise RuntimeError(sol.message)
    return sol.y


def _no_load(Y: np.ndarray) -> np.ndarray:
    return np.array([ref.flows(Y[:, k], P_S, P_0)[0] for k in range(Y.shape[1])])


def scipy_static(points: int = 41) -> np.ndarray:
    """At rest (omega = v = 0): the torque, the spool's force and the drain's flow balanced, by ``root`` on
    (theta, y, p_d), each side solved from its largest current down (from null outwards, hybr stops on a
    spurious point inside the null's dead band at 0.5 mA), every solution checked."""
    half = np.linspace(RATED / (points // 2), RATED, points // 2)
    currents = np.concatenate([-half[::-1], [0.0], half])
    flows = np.zeros(currents.size)
    p = ref.P
    unknown = np.array([1e-3, 1e-4, 1e6])  # theta [rad], y [m], p_d [Pa]
    balance = np.array([p["J_a"] / 1e-3, p["m_s"], p["V_d"] / p["beta_e"] / 1e-7])  # to mN m, N, 0.1 mm^3/s

    def residual(z: np.ndarray, i: float) -> np.ndarray:
        theta, y, p_d = z * unknown
        rates = ref.rhs(0.0, np.array([theta, 0.0, y, 0.0, p_d]), lambda t: i, P_S, P_0, None)
        return rates[[1, 3, 4]] * balance

    for side in (1.0, -1.0):
        guess = np.array([0.0, 0.0, 17e5]) / unknown
        for k in sorted((k for k, i in enumerate(currents) if i * side >= 0), key=lambda k: -abs(currents[k])):
            sol = root(residual, guess, args=(currents[k],), method="hybr", options={"xtol": 1e-12})
            if not sol.success or np.max(np.abs(residual(sol.x, currents[k]))) > 1e-6:
                raise RuntimeError(f"SciPy: no equilibrium at {currents[k] * 1e3:g} mA: {sol.message}")
            guess = sol.x
            theta, y, p_d = sol.x * unknown
            flows[k] = ref.flows(np.array([theta, 0.0, y, 0.0, p_d]), P_S, P_0)[0]
    return flows


def scipy_steps() -> list[np.ndarray]:
    out = []
    grid = np.linspace(0.0, 0.2, 4001)
    for frac in (0.05, 0.10, 0.25):
        amp = frac * RATED
        Y = _simulate(lambda t, amp=amp: amp if (t % 0.1) < 0.05 else -amp, grid, np.array([0, 0, 0, 0, 16e5 + P_0]))
        out.append(_no_load(Y[:, 2000:3001]))
    return out


def scipy_hysteresis() -> np.ndarray:
    f = 1 / 16
    grid = np.linspace(0.0, 1.25 / f, 5001)
    Y = _simulate(lambda t: RATED * np.sin(2 * np.pi * f * t), grid, np.array([0, 0, 0, 0, 16e5 + P_0]))
    return _no_load(Y[:, grid >= 0.25 / f - 1e-9])


def scipy_blocked() -> np.ndarray:
    load = (1e-6, 1.4e9)
    s0 = np.array([0, 0, 0, 0, 16e5 + P_0, (P_S + P_0) / 2, (P_S + P_0) / 2])
    out = []
    for f, span in ((0.5, 0.01), (0.1, 0.01), (0.5, 1.0)):
        grid = np.linspace(0.0, 1.25 / f, 10001 if span < 1 else 4001)
        Y = _simulate(lambda t, f=f, span=span: span * RATED * np.sin(2 * np.pi * f * t), grid, s0, load)
        out.append(Y[5] - Y[6])
    return out[0]


def scipy_bode(amplitudes: tuple[float, ...], frequencies: tuple[float, ...], tol: float = 2e-3) -> np.ndarray:
    """Plain periods until the fundamental of the last one differs from the one before by less than ``tol``."""
    H = np.zeros((len(amplitudes), len(frequencies)), dtype=complex)
    for a, amp in enumerate(amplitudes):
        for j, f in enumerate(frequencies):
            T, n = 1 / f, 128
            s = np.array([0, 0, 0, 0, 16e5 + P_0])
            previous = None
            for k in range(30):
                grid = np.linspace(k * T, (k + 1) * T, n + 1)
                Y = _simulate(lambda t, amp=amp, f=f: amp * RATED * np.sin(2 * np.pi * f * t), grid, s)
                s = Y[:, -1]
                q = _no_load(Y[:, :-1])
                t = grid[:-1]
                h = 2 / n * (np.sum(q * np.sin(2 * np.pi * f * t)) + 1j * np.sum(q * np.cos(2 * np.pi * f * t)))
                if previous is not None and abs(h - previous) <= tol * abs(h):
                    break
                previous = h
            H[a, j] = h / (amp * RATED)
    return H


#: the figures' keys of each test (benchmarks/results/servovalve_speed.json)
KEYS = {"static (41 currents at rest)": "static", "square waves 5/10/25 %": "steps", "hysteresis (1/16 Hz)": "hysteresis",
        "blocked ports (3 sweeps)": "blocked", "frequency response, subset": "bode"}  # fmt: skip


def main(quick: bool = False) -> dict[str, float]:
    repeat = 1 if quick else 3
    out: dict[str, float] = {}
    print(f"servovalve bench, Table 1, {P_S / 1e5:g} bar; median of {repeat} (hydroservo) against plain SciPy")
    rows = [
        ("static (41 currents at rest)", lambda: sb.static_tests(points=41), scipy_static,
         lambda e, s: np.max(np.abs(e.flows - s)) * 6e4),
        ("square waves 5/10/25 %", lambda: sb.step_tests(), scipy_steps,
         lambda e, s: max(np.max(np.abs(st.flow - q)) for st, q in zip(e, s, strict=True)) * 6e4),
        ("hysteresis (1/16 Hz)", lambda: sb.hysteresis_test(), scipy_hysteresis,
         lambda e, s: np.max(np.abs(e.flows - s)) * 6e4),
        ("blocked ports (3 sweeps)", lambda: sb.blocked_tests(), scipy_blocked, None),
    ]
    amps, freqs = (0.05, 0.25), (5.0, 50.0, 200.0)
    rows.append(
        ("frequency response, subset", lambda: sb.frequency_test(amplitudes=amps, frequencies=freqs),
         lambda: scipy_bode(amps, freqs), None)
    )
    total_e = total_s = 0.0
    figures: dict[str, float] = {}
    for name, engine, scipy, compare in rows:
        t_e, res_e = median_time(engine, repeat)
        t_s, res_s = median_time(scipy, 1 if quick else 2)
        total_e, total_s = total_e + t_e, total_s + t_s
        diff = "" if compare is None else f", flows differ by at most {compare(res_e, res_s):.1e} L/min"
        print(f"  {name:<30} hydroservo {t_e:7.2f} s   SciPy {t_s:8.2f} s   ratio {t_s / t_e:6.1f}x{diff}")
        out[name] = t_s / t_e
        key = KEYS[name]
        figures[f"{key}_ratio"], figures[f"{key}_hydroservo_s"], figures[f"{key}_scipy_s"] = t_s / t_e, t_e, t_s
        if compare is not None:
            figures[f"{key}_flow_difference_L_min"] = compare(res_e, res_s)
    print(f"  {'all of the above':<30} hydroservo {total_e:7.2f} s   SciPy {total_s:8.2f} s   ratio {total_s / total_e:6.1f}x")
    out["total"] = total_s / total_e
    figures["total_ratio"], figures["total_hydroservo_s"], figures["total_scipy_s"] = total_s / total_e, total_e, total_s
    if "--report" in sys.argv:
        t_r, report = median_time(lambda: sb.bench_report(), 1)
        out["report_s"] = figures["report_s"] = t_r
        print(f"hydroservo's whole report (static, blocked, steps, hysteresis, threshold, Bode at 5/25/100 % x 19 frequencies): {t_r:.1f} s")
    if not quick:
        record("servovalve_speed", figures)
    return out


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
