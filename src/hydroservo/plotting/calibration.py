"""Calibration plots: each compared signal, measured against model, with its residuals underneath."""

from __future__ import annotations

import textwrap
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.plotting import finish, pyplot
from hydroservo.units import si_unit

if TYPE_CHECKING:
    from hydroservo.identification.calibration import Experiment

__all__ = ["plot_fit"]


def plot_fit(
    experiment: Experiment,
    trace: Mapping[str, np.ndarray],
    *,
    title: str = "",
    file: str | Path | None = None,
    units: Mapping[str, str] | None = None,
) -> Any:
    """One column per compared signal: measured samples (dots) and the model (line) above, residuals below.

    Signals are shown in ``units`` (signal -> unit), else in the unit of the record's column.
    """
    plt = pyplot(file)
    names = experiment.measured
    ncol = len(names)
    fig, axes = plt.subplots(2, ncol, figsize=(max(4.0 * ncol, 6.0), 5.2), sharex=True, squeeze=False,
                             gridspec_kw={"height_ratios": [2.2, 1.0]})
    for k, name in enumerate(names):
        factor, label = experiment.shown(name, (units or {}).get(name))
        t = experiment.grid[experiment.index[name]]
        meas = experiment.values[name] * factor
        model = trace[name] * factor
        top, bottom = axes[0, k], axes[1, k]
        top.plot(t, meas, ".", ms=2.5, color="0.45", label="measured", zorder=2)
        top.plot(experiment.grid, model, "-", lw=1.4, color="C0", label="model", zorder=3)
        top.set_title(name, fontsize=9)
        top.set_ylabel(f"{name} [{si_unit(label)}]", fontsize=8)
        top.grid(True, alpha=0.3)
        residual = model[experiment.index[name]] - meas
        bottom.plot(t, residual, ".", ms=2.0, color="C3")
        bottom.axhline(0.0, color="0.3", lw=0.8)
        rms = float(np.sqrt(np.mean(residual**2)))
        bottom.set_ylabel(f"residual [{si_unit(label)}]", fontsize=8)
        bottom.set_xlabel("t [s]")
        bottom.set_title(f"RMS {rms:.3g} {si_unit(label)}", fontsize=8)
        bottom.grid(True, alpha=0.3)
    axes[0, 0].legend(fontsize=8, loc="best")
    fig.suptitle(textwrap.fill(title or f"calibration: {experiment.name}", 110), fontsize=10)
    return finish(fig, file, plt)
