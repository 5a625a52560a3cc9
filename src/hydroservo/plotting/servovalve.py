"""Plots of the two-stage servovalve on its test bench ([GordicND])."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.plotting import finish, lpm, pyplot

__all__ = ["plot_static_bench"]


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
