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
    """Bode plot of ``response`` (gain and phase against frequency, one colour per amplitude).

    ``others`` are drawn dashed in the same colours (e.g. models against data).
    """

    plt = pyplot(file)
    fig, (ax_g, ax_p) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    styles = ["-", "--", ":", "-."]
    for k, resp in enumerate([response, *others]):
        for i, a in enumerate(resp.amplitudes):
            kw: dict[str, Any] = {"color": colors[i % len(colors)]}
            if k == 0:  # the reference (data): one legend entry per amplitude
                kw["label"] = f"±{100 * a:g} %" + (f" {resp.label}" if resp.label else "")
                if others:
                    kw.update(marker="o", ms=3, ls="none")
            else:  # models: one line style each, one legend entry per model
                kw["ls"] = styles[(k - 1) % len(styles)]
                if i == 0:
                    kw["label"] = resp.label or f"model {k}"
            ax_g.plot(resp.frequencies, resp.gain_db[i], **kw)
            if np.any(np.isfinite(resp.phase_deg[i])):
                ax_p.plot(resp.frequencies, resp.phase_deg[i], **kw)
    ax_g.set_ylabel("gain [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    for ax in (ax_g, ax_p):
        ax.grid(True, alpha=0.4)
        if f_max:
            ax.axvline(f_max, color="0.6", lw=0.8)
    ax_g.legend(fontsize=8, ncol=2)
    if title:
        ax_g.set_title(title)
    return finish(fig, file, plt)
