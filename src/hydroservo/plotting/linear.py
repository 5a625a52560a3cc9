"""Linear models: pole map with the modes named, Bode plots of input-output pairs."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.plotting import finish, pyplot

if TYPE_CHECKING:
    from hydroservo.analysis.linear import LinearModel

__all__ = ["plot_poles", "plot_linear_bode"]


def plot_poles(lin: LinearModel, *, title: str = "", file: str | Path | None = None) -> Any:
    """The modes on a map of natural frequency (log) and damping ratio, each labelled with its main states;
    unstable modes in red. Poles at the origin (free integrators) are listed in the title, not drawn."""
    plt = pyplot(file)
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    modes = lin.modes()
    drawn = [m for m in modes if m.frequency > 0]
    free = [", ".join(m.main_states(0.5)[:1]) for m in modes if m.frequency == 0]
    for m in drawn:
        color = "tab:red" if m.eigenvalue.real > 0 else "tab:blue"
        marker = "o" if m.oscillatory else "s"
        ax.plot(m.frequency, m.damping, marker, color=color, ms=7)
        ax.annotate(", ".join(m.main_states(0.2)[:2]), (m.frequency, m.damping), textcoords="offset points",
                    xytext=(6, -10 if m.damping > 0.9 else 5), fontsize=7)
    ax.set_xscale("log")
    if drawn:
        fmin, fmax = min(m.frequency for m in drawn), max(m.frequency for m in drawn)
        ax.set_xlim(fmin / 3, fmax * 5)
    ax.set_ylim(min([-0.1] + [m.damping - 0.1 for m in drawn]), 1.12)
    ax.axhline(0.0, color="tab:red", lw=0.8, ls="--")
    ax.set_xlabel("natural frequency [Hz]")
    ax.set_ylabel("damping ratio [-]")
    ax.grid(True, which="both", alpha=0.3)
    ax.plot([], [], "o", color="tab:blue", label="oscillatory pair")
    ax.plot([], [], "s", color="tab:blue", label="real pole")
    ax.legend(fontsize=7, loc="lower right")
    extra = f" (pole at 0: {', '.join(free)})" if free else ""
    ax.set_title(title or f"{lin.name}: modes of the linear model{extra}", fontsize=10)
    return finish(fig, file, plt)


def plot_linear_bode(
    lin: LinearModel,
    frequencies: Sequence[float] | np.ndarray,
    pairs: Sequence[tuple[str, str]],
    *,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Gain (log axis, in the output's unit per the input's) and phase of each (input, output) pair, a row each."""
    from hydroservo.units import si_unit

    plt = pyplot(file)
    f = np.asarray(frequencies, dtype=float)
    fig, axes = plt.subplots(len(pairs), 2, sharex=True, figsize=(8.5, 1.9 * len(pairs) + 1.0), squeeze=False)
    for (inp, out), (ax_g, ax_p) in zip(pairs, axes):
        H = lin.transfer(f, inp, out)
        unit_in = si_unit(lin.units.get(inp, "")) or "1"
        unit_out = si_unit(lin.units.get(out, "")) or "1"
        if np.any(np.abs(H) > 0):
            ax_g.loglog(f, np.abs(H))
        else:
            ax_g.set_xscale("log")
            ax_g.text(0.5, 0.5, "no effect of this input", transform=ax_g.transAxes, ha="center", va="center")
        ax_g.set_ylabel(f"|{out}| / |{inp}|\n[{unit_out} per {unit_in}]", fontsize=8)
        ax_p.semilogx(f, np.degrees(np.unwrap(np.angle(H))))
        ax_p.set_ylabel("phase [deg]", fontsize=8)
        for ax in (ax_g, ax_p):
            ax.grid(True, which="both", alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("frequency [Hz]")
    fig.suptitle(title or f"{lin.name}: frequency response of the linear model", fontsize=10)
    return finish(fig, file, plt)
