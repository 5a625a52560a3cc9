"""Sensitivity studies: response families one factor at a time, and bar charts of global indices."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.plotting import finish, pyplot

if TYPE_CHECKING:
    from hydroservo.analysis.sensitivity import GlobalStudy, OneAtATime
from hydroservo.units import si_unit

__all__ = ["plot_one_at_a_time", "plot_indices"]


def _scaled(values: np.ndarray, unit_si: str, unit: str | None) -> tuple[np.ndarray, str]:
    if not unit:
        return values, si_unit(unit_si)
    from hydroservo.units import from_si

    return np.asarray(values) * from_si(1.0, unit_si, unit), unit


def plot_one_at_a_time(
    study: OneAtATime,
    factor: str,
    signals: Sequence[str] | None = None,
    *,
    units: Mapping[str, str] | None = None,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """A panel per signal, a line per level of ``factor`` (colour: level order; failed levels left out)."""
    plt = pyplot(file)
    if factor not in study.levels:
        raise KeyError(f"factor {factor!r}: not in the study ({', '.join(study.levels)})")
    names = list(signals) if signals else list(study.units)[:4]
    fig, axes = plt.subplots(len(names), 1, sharex=True, figsize=(7.5, 1.9 * len(names) + 1.2), squeeze=False)
    levels = study.levels[factor]
    cmap = plt.get_cmap("viridis")
    colors = [cmap(x) for x in np.linspace(0.0, 0.9, max(len(levels), 2))]
    for ax, name in zip(axes[:, 0], names):
        shown = ""
        for k, level in enumerate(levels):
            if (factor, k) in study.failed:
                continue
            y, shown = _scaled(study.responses[factor][k][name], study.units[name], (units or {}).get(name))
            ax.plot(study.t, y, color=colors[k], lw=1.2, label=level)
        ax.set_ylabel(f"{name}\n[{shown}]", fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0, 0].legend(title=factor, fontsize=7, title_fontsize=7, loc="best")
    axes[-1, 0].set_xlabel("t [s]")
    failed = sum(1 for f, _ in study.failed if f == factor)
    note = f" ({failed} level(s) failed, not drawn)" if failed else ""
    fig.suptitle(title or f"{study.model}: influence of {factor}{note}", fontsize=10)
    return finish(fig, file, plt)


def plot_indices(study: GlobalStudy, *, title: str = "", file: str | Path | None = None) -> Any:
    """Sobol S1 and ST (or Morris mu* and sigma) per parameter with their confidence intervals, a panel per metric."""
    plt = pyplot(file)
    table = study.indices
    metrics = list(dict.fromkeys(table["metric"]))
    params = study.parameters
    ncol = 2 if len(metrics) > 1 else 1
    nrow = (len(metrics) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(5.2 * ncol, 0.45 * len(params) * nrow + 1.6 * nrow + 0.6), squeeze=False)
    y = np.arange(len(params))
    for ax, metric in zip(axes.ravel(), metrics):
        rows = table[table["metric"] == metric].set_index("parameter").loc[params]
        if study.method == "sobol":
            ax.barh(y - 0.2, rows["S1"], 0.4, xerr=rows["S1_conf"], label="first order S1", color="tab:blue", capsize=2)
            ax.barh(y + 0.2, rows["ST"], 0.4, xerr=rows["ST_conf"], label="total ST", color="tab:orange", capsize=2)
            ax.set_xlim(min(-0.05, float(np.nanmin((rows["S1"] - rows["S1_conf"]).to_numpy(), initial=0.0))),
                        max(1.05, float(np.nanmax((rows["ST"] + rows["ST_conf"]).to_numpy(), initial=1.0))))
            ax.axvline(0.0, color="0.4", lw=0.8)
        else:
            ax.barh(y - 0.2, rows["mu_star"], 0.4, xerr=rows["mu_star_conf"], label="μ*", color="tab:blue", capsize=2)
            ax.barh(y + 0.2, rows["sigma"], 0.4, label="σ", color="tab:orange")
        if rows.drop(columns=[c for c in rows.columns if c in ("metric",)]).isna().all(axis=None):
            ax.text(0.5, 0.5, "not estimated\n(failed runs)", transform=ax.transAxes, ha="center", va="center", color="tab:red")
        ax.set_yticks(y, params, fontsize=7)
        ax.invert_yaxis()
        ax.set_title(metric, fontsize=8)
        ax.grid(True, axis="x", alpha=0.3)
    for ax in axes.ravel()[len(metrics):]:
        ax.set_visible(False)
    axes[0, 0].legend(fontsize=7, loc="lower right")
    what = "Sobol indices" if study.method == "sobol" else "Morris screening"
    n = study.runs.stats["runs"]
    fig.suptitle(title or f"{what} ({n} runs, {100 * study.conf_level:g} % intervals)", fontsize=10)
    return finish(fig, file, plt)
