"""Amplitude-dependent Bode plots: gain and phase against frequency, one colour per amplitude."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from hydroservo.plotting import finish, pyplot


class FrequencyResponse(Protocol):
    """What the plot reads of a frequency response (:class:`hydroservo.analysis.FrequencyResponse` is one)."""

    amplitudes: np.ndarray
    frequencies: np.ndarray
    gain_db: np.ndarray
    phase_deg: np.ndarray
    label: str

__all__ = ["plot_bode"]


def plot_bode(
    response: FrequencyResponse,
    others: Sequence[FrequencyResponse] = (),
    *,
    title: str = "",
    file: str | Path | None = None,
    f_max: float | None = None,
) -> Any:
    """Bode plot of ``response`` (gain and phase against a logarithmic frequency axis, one colour per amplitude).

    ``others`` (e.g. models against data) are drawn in the same colours, one
    line style each; the data are then markers. The legend gives the colour of
    each amplitude and the style of each response.
    """

    plt = pyplot(file)
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    fig, (ax_g, ax_p) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    styles = ["-", "--", ":", "-."]
    handles: list[Any] = []
    for i, a in enumerate(response.amplitudes):  # a colour per amplitude
        kw: dict[str, Any] = {"color": colors[i % len(colors)]}
        kw.update(marker="o", ms=3, ls="none") if others else kw.update(ls="-")
        handles.append(Line2D([], [], label=f"±{100 * a:g} %", **kw))
    if others:  # a line style per model, drawn in grey in the legend: the colours are the amplitudes'
        handles.append(Line2D([], [], color="0.3", marker="o", ms=3, ls="none", label=response.label or "data"))
        handles += [
            Line2D([], [], color="0.3", ls=styles[k % len(styles)], label=resp.label or f"model {k + 1}")
            for k, resp in enumerate(others)
        ]
    for k, resp in enumerate([response, *others]):
        for i in range(len(resp.amplitudes)):
            kw = {"color": colors[i % len(colors)]}
            if k == 0 and others:
                kw.update(marker="o", ms=3, ls="none")
            elif k > 0:
                kw["ls"] = styles[(k - 1) % len(styles)]
            ax_g.plot(resp.frequencies, resp.gain_db[i], **kw)
            if np.any(np.isfinite(resp.phase_deg[i])):
                ax_p.plot(resp.frequencies, resp.phase_deg[i], **kw)
    ax_g.set_ylabel("gain [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    for ax in (ax_g, ax_p):
        ax.set_xscale("log")
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))  # 10, 20, 50, 100 Hz, ...
        ax.xaxis.set_major_formatter(FuncFormatter(lambda f, _: f"{f:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.grid(True, which="both", alpha=0.3)
        if f_max:
            ax.axvline(f_max, color="0.6", lw=0.8)
    ax_g.legend(handles=handles, fontsize=8, ncol=2, title="amplitude (of stroke)" if not others else None)
    if title:
        ax_g.set_title(title)
    return finish(fig, file, plt)
