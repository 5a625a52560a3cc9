"""Plots of parameter studies: a family of responses, and metrics against a parameter."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO, Protocol

import numpy as np

from hydroservo.plotting import finish, pyplot
from hydroservo.units import si_unit

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

__all__ = ["plot_family", "plot_metrics"]


class Batch(Protocol):
    """What the plot reads of a batch (:class:`hydroservo.system.BatchResult` is one)."""

    t: np.ndarray
    model: str
    units: dict[str, str]
    params: dict[str, np.ndarray]
    param_units: dict[str, str]
    varied: list[str]
    failed: dict[int, str]
    warnings: dict[int, list[Any]]

    def get(self, name: str, unit: str | None = None) -> np.ndarray: ...

    def __len__(self) -> int: ...


def plot_family(
    batch: Batch,
    signal: str,
    *,
    unit: str | None = None,
    color_by: str | None = None,
    title: str | None = None,
    file: str | Path | BinaryIO | None = None,
) -> Figure:
    """``signal`` of every run that did not fail, coloured by ``color_by`` (default: the first varied
    parameter) with a colour bar; implausible runs dashed."""
    plt = pyplot(file)
    from matplotlib import colors as mcolors

    key = color_by or (batch.varied[0] if batch.varied else None)
    values = batch.get(signal, unit)
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    runs = [k for k in range(len(batch)) if k not in batch.failed]
    cmap = plt.get_cmap("viridis")
    norm = None
    if key is not None:
        c = batch.params[key][runs] if runs else np.zeros(0)
        norm = mcolors.Normalize(vmin=float(np.min(c)) if c.size else 0.0, vmax=float(np.max(c)) if c.size else 1.0)
    for k in runs:
        color = cmap(norm(batch.params[key][k])) if key is not None and norm is not None else "C0"
        ax.plot(batch.t, values[k], color=color, lw=1.0, ls="--" if k in batch.warnings else "-")
    if key is not None and norm is not None:
        bar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax)
        bar.set_label(f"{key} [{si_unit(batch.param_units.get(key, ''))}]")
    shown = si_unit(unit or batch.units.get(signal, ""))
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"{signal} [{shown}]")
    ax.grid(True, alpha=0.3)
    notes = []
    if batch.failed:
        notes.append(f"{len(batch.failed)} failed run(s) not drawn")
    if batch.warnings:
        notes.append(f"{len(batch.warnings)} implausible run(s) dashed")
    head = title or f"{batch.model}: {signal}, {len(runs)} runs" + (f" over {', '.join(batch.varied)}" if batch.varied else "")
    ax.set_title(head + (f"\n({'; '.join(notes)})" if notes else ""), fontsize=10)
    return finish(fig, file, plt)


def plot_metrics(
    table: pd.DataFrame,
    x: str,
    metrics: list[str] | None = None,
    *,
    title: str = "",
    file: str | Path | None = None,
) -> Figure:
    """Metrics of a study table (:func:`hydroservo.analysis.study.metrics_table`) against column ``x``,
    one panel per metric; columns are matched by their start (``"load.m"`` finds ``"load.m [kg]"``).
    Runs that failed are left out, implausible ones drawn hollow."""
    plt = pyplot(file)

    def column(start: str) -> str:
        found = [c for c in table.columns if c == start or c.startswith(start + " ")]
        if not found:
            raise KeyError(f"no column {start!r}; columns: {', '.join(map(str, table.columns))}")
        return str(found[0])

    xc = column(x)
    chosen = [column(m) for m in metrics] if metrics else [c for c in table.columns if "_time [" in c or "overshoot" in c]
    ok = table[table["status"] != "failed"] if "status" in table else table
    fig, axes = plt.subplots(len(chosen), 1, sharex=True, figsize=(7, 1.8 + 1.7 * len(chosen)), squeeze=False)
    for ax, name in zip(axes[:, 0], chosen):
        plausible = ok["status"] == "ok" if "status" in ok else np.ones(len(ok), bool)
        ax.plot(ok[xc][plausible], ok[name][plausible], "o", ms=4, color="C0", label="runs")
        if (~plausible).any():
            ax.plot(ok[xc][~plausible], ok[name][~plausible], "o", ms=4, mfc="none", color="C3", label="implausible")
            ax.legend(fontsize="small")
        ax.set_ylabel(name, fontsize=9)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(xc)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)
