"""Plots of simulation results: signals against time."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from hydroservo.plotting import finish, pyplot
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

    @property
    def names(self) -> list[str]: ...

    def get(self, name: str, unit: str | None = None) -> np.ndarray: ...


def plot_result(
    result: Result,
    *names: str | Sequence[str],
    units: dict[str, str] | None = None,
    title: str | None = None,
    file: str | Path | None = None,
) -> Figure:
    """Plot signals of ``result`` against time, one panel per argument.

    An argument may be a name or a list of names sharing a panel (same unit).
    ``units`` maps names to display units, e.g. ``{"y": "in"}``.
    """
    plt = pyplot(file)
    panels = [[n] if isinstance(n, str) else list(n) for n in (names or [[result.names[0]]])]
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(7.5, 1.9 + 1.6 * len(panels)), squeeze=False)
    for ax, panel in zip(axes[:, 0], panels):
        labels = []
        for n in panel:
            unit = (units or {}).get(n)
            shown = unit if unit else si_unit(result.units.get(n, ""))
            ax.plot(result.t, result.get(n, unit), label=n)
            labels.append(shown)
        ax.set_ylabel(f"{' / '.join(panel)} [{labels[0]}]" if len(panel) == 1 else f"[{labels[0]}]")
        if len(panel) > 1:
            ax.legend(loc="best", fontsize="small")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("t [s]")
    fig.suptitle(title or result.model)
    return finish(fig, file, plt)


