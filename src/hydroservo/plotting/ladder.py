"""The fidelity ladder: every model's response at every step, and the Table 5.3 map of errors and classes."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.plotting import finish, pyplot

if TYPE_CHECKING:
    from hydroservo.analysis.ladder import LadderTable

__all__ = ["plot_ladder_responses", "plot_ladder_classes"]

#: Colours of the classes of [Efe2014] Table 5.3.
CLASS_COLOURS = {"accurate": "#8fd18f", "moderate": "#f5d76e", "inaccurate": "#f08c8c", "failed": "#bbbbbb"}


def plot_ladder_responses(
    ladder: LadderTable, *, unit: str = "", scale: float = 1.0, title: str = "", file: str | Path | None = None
) -> Any:
    """A panel per step: ``output`` against time for every model (times ``scale``: SI to ``unit``), the reference
    in black."""
    plt = pyplot(file)
    steps = ladder.steps
    ncol = 3 if len(steps) > 4 else min(2, len(steps))
    nrow = (len(steps) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 2.8 * nrow + 0.9), sharex=True, squeeze=False)
    names = list(ladder.runs)
    styles = {"nonlinear": "-", "linear": "--", "linear-feedback": "-.", "simplified": ":", "simplified-feedback": (0, (5, 1, 1, 1))}
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, (ax, step) in enumerate(zip(axes.ravel(), steps)):
        for i, name in enumerate(names):
            batch = ladder.runs[name]
            if k in batch.failed:
                continue
            kind = name.removeprefix("improved ")
            is_ref = name == ladder.reference
            ax.plot(batch.t, scale * batch[ladder.output][k], ls=styles.get(kind, "-"), lw=2.2 if is_ref else 1.1,
                    color="black" if is_ref else colors[i % len(colors)], label=name + (" (reference)" if is_ref else ""),
                    zorder=3 if is_ref else 2)
        ax.set_title(f"{100 * step:g} %", fontsize=9)
        ax.grid(True, alpha=0.3)
    for ax in axes.ravel()[len(steps):]:
        ax.set_visible(False)
    for ax in axes[:, 0]:
        ax.set_ylabel(f"{ladder.output}" + (f" [{unit}]" if unit else ""), fontsize=8)
    for ax in axes[-1]:
        ax.set_xlabel("t [s]")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=min(5, len(labels)), fontsize=7, frameon=False)
    fig.suptitle(title or f"model-fidelity ladder: {ladder.output} for each step of {ladder.parameter}", fontsize=10)
    fig.tight_layout(rect=(0, 0.04 + 0.025 * ((len(labels) + 4) // 5), 1, 1))
    if file is not None:
        fig.savefig(file, dpi=110)
        plt.close(fig)
    return fig


def plot_ladder_classes(ladder: LadderTable, *, title: str = "", file: str | Path | None = None) -> Any:
    """[Efe2014] Table 5.3 as a map: a cell per model and step, coloured by class, with the error in %."""
    plt = pyplot(file)
    table = ladder.table
    models = list(table.index)
    steps = ladder.steps
    fig, ax = plt.subplots(figsize=(1.25 * len(models) + 1.8, 0.5 * len(steps) + 1.9))
    for j, model in enumerate(models):
        for i, step in enumerate(steps):
            cls = str(table.loc[model, f"class {100 * step:g} %"])
            err = float(table.loc[model, f"error {100 * step:g} % [%]"])
            ax.add_patch(plt.Rectangle((j, i), 1, 1, color=CLASS_COLOURS.get(cls.split(" ")[0], "#dddddd"), ec="white"))
            text = "failed" if not np.isfinite(err) else f"{err:+.1f} %"
            if "implausible" in cls:
                text += "\n(implausible)"
            ax.text(j + 0.5, i + 0.5, text, ha="center", va="center", fontsize=7)
    ax.set_xlim(0, len(models))
    ax.set_ylim(len(steps), 0)
    ax.set_xticks(np.arange(len(models)) + 0.5, [m.replace(" ", "\n", 1) for m in models], fontsize=7)
    ax.set_yticks(np.arange(len(steps)) + 0.5, [f"{100 * s:g} %" for s in steps], fontsize=8)
    ax.set_ylabel("valve signal step")
    for name, colour in CLASS_COLOURS.items():
        ax.plot([], [], "s", color=colour, ms=9, label=name)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=4, fontsize=7, frameon=False)
    ax.set_title(title or f"steady-state displacement error against {ladder.reference} (Table 5.3 classes)", fontsize=9)
    return finish(fig, file, plt)
