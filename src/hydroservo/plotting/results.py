"""Plots of simulation results: signals against time."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO, Protocol

from hydroservo.plotting import axis_label, by_dimension, curve_label, finish, panel_units, pyplot
from hydroservo.units import si_unit

if TYPE_CHECKING:
    import numpy as np
    from matplotlib.figure import Figure

__all__ = ["plot_result"]


class Result(Protocol):
    """What the plot reads of a result (:class:`hydroservo.system.Result` is one)."""

    t: np.ndarray
    model: str
    units: dict[str, str]
    descriptions: dict[str, str]
    panels: list[list[str]]

    @property
    def names(self) -> list[str]: ...

    def get(self, name: str, unit: str | None = None) -> np.ndarray: ...


def plot_result(
    result: Result,
    *names: str | Sequence[str],
    units: dict[str, str] | None = None,
    title: str | None = None,
    file: str | Path | BinaryIO | None = None,
    show: bool | None = False,
) -> Figure:
    """Plot signals of ``result`` against time, one panel per argument.

    An argument may be a name or a list of names sharing a panel (same unit).
    Without arguments, the result's main signals (:attr:`Result.panels`: the
    model file's plots, else its aliases, else its states). ``units`` maps names
    to display units, e.g. ``{"y": "in"}``. Each curve is labelled with its
    name and description, each axis with the names and the unit. ``show``: as
    :func:`hydroservo.plotting.finish` (``None`` shows a figure that goes to no file).
    """
    plt = pyplot(file)
    chosen = names or result.panels or [[n] for n in result.names[:6]]
    panels = by_dimension([[n] if isinstance(n, str) else list(n) for n in chosen], result.units)
    labels = [[curve_label(n, result.descriptions) for n in panel] for panel in panels]
    # legends of many or long labels go beside the axes, the figure widened for them
    beside = any(len(panel) > 4 or max(map(len, panel)) > _LEGEND_CHARS for panel in labels)
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(11.0 if beside else 7.5, 1.9 + 1.6 * len(panels)),
                             squeeze=False)
    for ax, panel, named in zip(axes[:, 0], panels, labels):
        drawn = panel_units(result.units, panel, dict(units or {}))
        for n, unit, label in zip(panel, drawn, named):
            ax.plot(result.t, result.get(n, unit), label=label)
        shown = [si_unit(u) for u in drawn]
        ax.set_ylabel(axis_label(panel, result.descriptions, " / ".join(dict.fromkeys(shown)), drawn[0]), fontsize="small")
        if beside:
            ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="x-small", framealpha=0.8)
        else:
            ax.legend(loc="best", fontsize="small", framealpha=0.8)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("t [s]")
    fig.suptitle(title or result.model)
    return finish(fig, file, plt, show)


#: The longest curve label a legend inside the axes takes; past it (or past four curves), the legends go beside.
_LEGEND_CHARS = 48
