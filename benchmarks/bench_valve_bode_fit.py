"""Speed of the [FerreiraND] amplitude-dependent Bode fit (3 amplitudes x 30 frequencies).

Run: ``python benchmarks/bench_valve_bode_fit.py``

1. One evaluation of all 90 gains, two ways, in this process:
   * baseline: the straightforward method, every sine simulated by CVODES
     (rtol 1e-8) from rest through 40 periods, batched over both cores with
     ``System.batch``; the fundamental taken over the last 10 periods;
   * hydroservo: periodic orbit by shooting, fixed-step RK4, mapped over threads.
   Their largest gain difference is printed (it is the baseline's residual transient).
2. The complete fit of eq. (43) from a start 35-40 % away from the published
   values ([FerreiraND]: 1007 rad/s, 0.48, 125 1/s, 81184 1/s^2), then the delay.
   The issue's floor: under 20 s on a 2-core machine.

Times are CPU time of this process (all its threads: the baseline's batch on both cores is charged for both),
steadier than wall time on a shared machine. Figures are written to benchmarks/results/valve_bode_fit.json.
"""

from __future__ import annotations

import time

import numpy as np
from results import record

from hydroservo.analysis.frequency import PeriodicResponse
from hydroservo.identification import fit_spool_dynamics, spool_response
from hydroservo.identification.spool_dynamics import spool_system
from hydroservo.validation.ferreira import bode_grid, published_dynamics

PUBLISHED = published_dynamics()
AMPS, FREQS = bode_grid()


def baseline_gains(periods: int = 40, last: int = 10, points_per_period: int = 64) -> np.ndarray:
    system, out = spool_system("rate-limited")
    gains = np.empty((AMPS.size, FREQS.size))
    for j, f in enumerate(FREQS):  # one batch per frequency: the output grid is in periods
        t = np.linspace(0.0, periods / f, periods * points_per_period + 1)
        res = system.batch(
            {"u.amplitude": AMPS, "u.frequency": [f] * AMPS.size}, t_end=t[-1], t_eval=t, rtol=1e-8, atol=1e-10,
            method="cvodes",
        )
        if res.failed:  # a failed run is NaN: its gain would drop out of the comparison unseen
            raise RuntimeError(f"baseline at {f:g} Hz: {res.failed}")
        y = res[out]
        sel = t >= t[-1] - last / f - 1e-12
        tt = t[sel]
        for i, a in enumerate(AMPS):
            yy = y[i, sel]
            a1 = 2 * np.trapezoid(yy * np.sin(2 * np.pi * f * tt), tt) / (tt[-1] - tt[0])
            b1 = 2 * np.trapezoid(yy * np.cos(2 * np.pi * f * tt), tt) / (tt[-1] - tt[0])
            gains[i, j] = 20 * np.log10(np.hypot(a1, b1) / a)
    return gains


def engine_gains(engine: PeriodicResponse, p: np.ndarray) -> np.ndarray:
    H, _ = engine.response(engine.parameters(p, AMPS, FREQS))
    return 20 * np.log10(np.abs(H)).reshape(AMPS.size, FREQS.size)


def main() -> None:
    system, out = spool_system("rate-limited")
    t0 = time.process_time()
    engine = PeriodicResponse(system, "u", out)
    build = time.process_time() - t0
    p = system.parameter_vector(None)
    engine_gains(engine, p)  # warm-up (maps are built on first use)
    t0 = time.process_time()
    g_engine = engine_gains(engine, p)
    t_engine = time.process_time() - t0
    baseline_gains(periods=2)  # warm-up of the CVODES integrators
    t0 = time.process_time()
    g_base = baseline_gains()
    t_base = time.process_time() - t0
    print("one evaluation of 90 gains (3 amplitudes x 30 frequencies)")
    print(f"  baseline, CVODES through 40 periods, batched:  {t_base * 1e3:8.1f} ms")
    print(
        f"  hydroservo, periodic orbit by shooting:        {t_engine * 1e3:8.1f} ms   ({t_base / t_engine:.1f}x faster;"
        f" compile {build:.2f} s once)"
    )
    print(f"  largest gain difference: {np.max(np.abs(g_base - g_engine)):.2e} dB")

    data = spool_response(PUBLISHED, AMPS, FREQS, steps_per_period=512)
    start = {"omega_n": 1007 * 1.35, "zeta": 0.48 * 0.65, "L_v": 125 * 1.4, "L_a": 81184 * 0.6}
    t0 = time.process_time()
    fit = fit_spool_dynamics(data, "rate-limited", start)
    t_fit = time.process_time() - t0
    errs = ", ".join(f"{k} {100 * (fit.params[k] / v - 1):+.1e} %" for k, v in PUBLISHED.items())
    print(
        f"complete Bode fit (eq. 43 + delay) from 35-40 % away: {t_fit:.2f} s (floor: 20 s), "
        f"{fit.info['iterations']} evaluations"
    )
    print(f"  recovered: {errs}")
    record("valve_bode_fit", {
        "baseline_ms": t_base * 1e3, "engine_ms": t_engine * 1e3, "ratio": t_base / t_engine,
        "gain_difference_dB": float(np.max(np.abs(g_base - g_engine))), "fit_s": t_fit,
    })  # fmt: skip


if __name__ == "__main__":
    main()
