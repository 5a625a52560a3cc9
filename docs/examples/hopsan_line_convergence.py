"""Hopsan's transmission lines as lumped ladders: how close they come as their segments multiply
=============================================================================================

HydraulicLineTest (Hopsan's component test of its lines) imported with 10 to 200 segments per line and with the
import's default (5 T/Ts: 200 for the lossless line, 47 for the hose), each run
against Hopsan's converged result (the reference of ``hydroservo validate hopsan-examples``): per line, the
largest, the root-mean-square and the median deviation of its traces (the pressure at the flow source and the
flow into the orifice), in per cent of range, the largest deviation of the pressure's plateaus (its mean over
the middle 40 % of each interval between two of the reference's wavefronts: the level the waves settle to,
with the ladder's ringing averaged out), and the run's time. Prints the table docs/hopsan.md shows and
draws docs/img/hopsan_line_convergence.png (the lossless line's and the hose's pressure at the flow source
beside Hopsan's).

Run: ``python docs/examples/hopsan_line_convergence.py``.
"""

import os
import time
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from hydroservo.io import read_hopsan
from hydroservo.validation.hopsan_examples import MODELS, _reference, errors

NAME = "hydraulic-line-test"
#: segments of each line; None: the import's default (5 T/Ts: 200, the most, for the line, 47 for the hose)
SEGMENTS = (10, 25, 50, 100, 200, None)
#: per line, the traces compared: the pressure at the flow source and the flow at the orifice's end
LINES = {
    "HydraulicTLMlossless": ("Q_type_Flow_Source.P1.Pressure", "Flow_Rate_Transducer.P1.Flow"),
    "HydraulicHose": ("Pressure_Transducer_1.P1.Pressure", "Flow_Rate_Transducer_1.P1.Flow"),
}
DRAWN = (50, None)


def plateaus(t_ref: np.ndarray, y_ref: np.ndarray, t: np.ndarray, y: np.ndarray) -> float:
    """The largest deviation of the mean over the middle 40 % of each interval between two wavefronts of the
    reference (a change of more than a fifth of its range from one sample to the next), % of its range."""
    span = float(np.ptp(y_ref))
    fronts = np.flatnonzero(np.abs(np.diff(y_ref)) > 0.2 * span)
    worst = 0.0
    for a, b in zip(fronts[:-1], fronts[1:], strict=True):
        t0, t1 = t_ref[a + 1], t_ref[b]
        lo, hi = t0 + 0.3 * (t1 - t0), t1 - 0.3 * (t1 - t0)
        in_ref, in_run = (t_ref >= lo) & (t_ref <= hi), (t >= lo) & (t <= hi)
        if in_ref.any() and in_run.any():
            worst = max(worst, abs(float(np.mean(y[in_run]) - np.mean(y_ref[in_ref]))))
    return 100.0 * worst / span


def main() -> None:
    source = Path(os.environ.get("HOPSAN_SOURCE", "../hopsan")) / "Models" / MODELS[NAME].path
    header, ref = _reference(NAME)
    columns = [c.split(" [")[0] for c in header]
    runs = {}
    fine = np.linspace(0.0, float(ref[-1, 0]), 20001)
    print("| segments | line | largest | RMS | median | plateaus | run |")
    print("|---|---|---|---|---|---|---|")
    for n in SEGMENTS:
        system = read_hopsan(source, line_segments=n)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            started = time.perf_counter()
            err = errors(NAME, system)
            seconds = time.perf_counter() - started
            result = system.simulate(t_eval=fine, max_steps=10**6)
        if n in DRAWN:
            runs[n] = result
        for line, traces in LINES.items():
            e = np.concatenate([err[t] for t in traces])
            y_ref = ref[:, columns.index(traces[0])]
            plateau = plateaus(ref[:, 0], y_ref, fine, result[traces[0]])
            print(f"| {n or 'default'} | {line} | {e.max():.1f} % | {np.sqrt(np.mean(e**2)):.2f} % | {np.median(e):.3f} % "
                  f"| {plateau:.2f} % | {seconds:.1f} s |")
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for ax, (line, (pressure, _)) in zip(axes, LINES.items(), strict=True):
        ax.plot(ref[:, 0], ref[:, columns.index(pressure)] / 1e6, "k", lw=1.2, label="Hopsan, converged")
        for n, result in runs.items():
            label = f"{n} segments" if n else "the import's default segments"
            ax.plot(result.t, result[pressure] / 1e6, lw=0.7, label=f"hydroservo, {label}")
        ax.set_title(f"{line}: pressure at the flow source")
        ax.set_ylabel("MPa (absolute)")
        ax.legend(loc="lower right", fontsize=8)
    axes[-1].set_xlabel("t [s]")
    fig.tight_layout()
    out = Path(__file__).resolve().parents[1] / "img" / "hopsan_line_convergence.png"
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
