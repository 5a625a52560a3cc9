"""Plots of the two-stage servovalve on its test bench ([GordicND])."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.plotting import finish, lpm, pyplot

__all__ = ["plot_static_bench", "plot_sensitivity"]


def plot_static_bench(bench: Any, *, title: str = "", file: str | Path | None = None) -> Any:
    """The flow-current characteristic with the rated line (left) and the flow drawn from supply (right).

    ``bench`` is a :class:`hydroservo.analysis.servovalve.StaticBench` (read by its attributes).
    """
    plt = pyplot(file)
    fig, (ax_q, ax_s) = plt.subplots(1, 2, figsize=(11, 4.5))
    i_ma = np.asarray(bench.currents) * 1e3
    ax_q.plot(i_ma, lpm(bench.flows), "o-", ms=3, label="no-load flow")
    ax_q.plot(i_ma, lpm(bench.rated_flow / bench.i_rated * np.asarray(bench.currents)), "k--", lw=0.8, label="rated line")
    ax_q.set_xlabel("current i [mA]")
    ax_q.set_ylabel("flow Q_SV [L/min]")
    ax_q.set_title(f"flow-current characteristic, {bench.p_s / 1e5:g} bar")
    ax_q.legend(loc="upper left", fontsize="small")
    ax_s.plot(i_ma, lpm(bench.supply_flows), "o-", ms=3, color="tab:red")
    ax_s.set_xlabel("current i [mA]")
    ax_s.set_ylabel("flow from supply [L/min]")
    ax_s.set_title("supply flow (internal leakage at null)")
    for ax in (ax_q, ax_s):
        ax.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_sensitivity(sens: Any, figures: Any, *, top: int = 8, title: str = "", file: str | Path | None = None) -> Any:
    """One bar chart per design figure: the ``top`` parameters by elasticity (d ln figure / d ln parameter).

    ``sens`` is a :class:`hydroservo.analysis.servovalve.Sensitivity`; ``figures`` maps a figure's key to its
    (description, unit, scale).
    """
    plt = pyplot(file)
    keys = list(sens.figures)
    cols = 3
    rows = (len(keys) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows))
    for ax, key in zip(np.ravel(axes), keys, strict=False):
        ranked = sens.ranked(key, top)[::-1]
        names = [n for n, _ in ranked]
        values = [e for _, e in ranked]
        ax.barh(names, values, color=["tab:blue" if e >= 0 else "tab:red" for e in values])
        description, unit, scale = figures[key]
        ax.set_title(f"{description}\n({sens.figures[key] * scale:.4g} {unit})", fontsize="small")
        ax.axvline(0.0, color="k", lw=0.6)
        ax.grid(True, axis="x", alpha=0.3)
        ax.tick_params(labelsize="small")
    for ax in np.ravel(axes)[len(keys) :]:
        ax.set_visible(False)
    fig.supxlabel("elasticity: % change of the figure per % change of the parameter", fontsize="small")
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)
