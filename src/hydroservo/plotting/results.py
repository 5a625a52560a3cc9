"""Plots of simulation results: signals against time."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, BinaryIO, Protocol

from hydroservo.plotting import finish, panel_units, pyplot
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
    panels = [[n] if isinstance(n, str) else list(n) for n in chosen]
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(7.5, 1.9 + 1.6 * len(panels)), squeeze=False)
    for ax, panel in zip(axes[:, 0], panels):
        drawn = panel_units(result.units, panel, dict(units or {}))
        for n, unit in zip(panel, drawn):
            described = result.descriptions.get(n, "")
            ax.plot(result.t, result.get(n, unit), label=f"{n}: {described}" if described and described != n else n)
        shown = [si_unit(u) for u in drawn]
        ax.set_ylabel(_axis_label(panel, result.descriptions, " / ".join(dict.fromkeys(shown))))
        ax.legend(loc="best", fontsize="small", framealpha=0.8)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("t [s]")
    fig.suptitle(title or result.model)
    return finish(fig, file, plt, show)


#: The longest list of names an axis is labelled with; past it, what the signals are (the legend names them).
_LABEL_CHARS = 40


def _axis_label(panel: list[str], descriptions: dict[str, str], unit: str) -> str:
    """``"p1, p2 [Pa]"``; for a panel whose names would not fit beside the axis, what its signals have in common
    (``"pressure [Pa]"``) or how many they are, and a long single name broken over lines."""
    import textwrap

    names = ", ".join(panel)
    if len(panel) > 1 and len(names) > _LABEL_CHARS:
        described = {descriptions.get(n, "") for n in panel}
        names = described.pop() if len(described) == 1 and "" not in described else f"{len(panel)} signals"
    return textwrap.fill(f"{names} [{unit}]", _LABEL_CHARS)
