"""Plots of a pseudo-section valve: the analogues of [FerreiraND] Figs. 2-9."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.components.valves.pseudo_section import PseudoSectionValve
from hydroservo.plotting import finish, lpm, pyplot
from hydroservo.units import from_si

__all__ = ["plot_pseudo_sections", "plot_null_characteristics", "plot_load_flow", "plot_pressure_flow"]

_SEC = "L/min/bar^0.5"
_SI = "m^3/s/Pa^0.5"
_K = from_si(1.0, _SI, _SEC)  # SI pseudo-section -> L/min/bar^0.5


def plot_pseudo_sections(
    valve: PseudoSectionValve,
    *,
    measured: Mapping[str, np.ndarray] | None = None,
    zoom: float = 0.06,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """A_p and A_n over the full stroke (Fig. 2) and near null (Fig. 3) [L/min/bar^0.5].

    ``measured`` may hold ``x_s``, ``A_p``, ``A_n`` (SI) computed from measured
    curves (:meth:`hydroservo.identification.datasheet.PseudoSectionFit.measured_sections`).
    """
    plt = pyplot(file)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, lim in zip(axes, (1.0, zoom)):
        x = np.linspace(-lim, lim, 801)
        A_p, A_n = valve.sections(x)
        ax.plot(x, _K * A_p, label="A_p = A_s1 = A_2t")
        ax.plot(x, _K * A_n, label="A_n = A_s2 = A_1t")
        if measured is not None and lim == zoom:
            xm = np.asarray(measured["x_s"])
            ax.plot(xm, _K * np.asarray(measured["A_p"]), "o", ms=3, label="A_p from curves (eq. 17)")
            ax.plot(xm, _K * np.asarray(measured["A_n"]), "s", ms=3, label="A_n from curves (eq. 16)")
        if lim < 1:
            top = float(_K * np.max(valve.sections(np.array([lim]))[0]))
            ax.set_ylim(0, 1.1 * top)
        ax.set_xlabel("x_s [-]")
        ax.set_ylabel(f"pseudo-section [{_SEC}]")
        ax.grid(True, alpha=0.4)
        ax.set_title(f"{valve.structure} structure, x_s in [-{lim:g}, {lim:g}]")
    axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_null_characteristics(
    valve: PseudoSectionValve,
    P_s: float,
    *,
    measured: Mapping[str, np.ndarray] | None = None,
    zoom: float = 0.06,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Relative load pressure (eq. 13) and leakage (eq. 27) with blocked ports near null (Figs. 4, 7).

    ``measured`` may hold ``x_s``, ``P_L`` [-] and ``q_lk`` [m^3/s].
    """
    plt = pyplot(file)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    x = np.linspace(-zoom, zoom, 801)
    P_L, q_lk = valve.blocked_ports(x, P_s)
    ax.plot(x, P_L, label="P_L [-] (model)")
    ax.plot(x, lpm(q_lk), label="q_lk [L/min] (model)")
    if measured is not None:
        ax.plot(measured["x_s"], measured["P_L"], "o", ms=3, label="P_L measured")
        ax.plot(measured["x_s"], lpm(measured["q_lk"]), "s", ms=3, label="q_lk measured")
    ax.set_xlabel("x_s [-]")
    ax.set_ylabel("q_lk [L/min], P_L [-]")
    ax.set_title(title or f"Blocked ports at P_s = {P_s / 1e5:g} bar")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    return finish(fig, file, plt)


def plot_load_flow(
    valve: PseudoSectionValve,
    P_n: float,
    *,
    measured: Mapping[str, np.ndarray] | None = None,
    zoom: float = 0.06,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Load flow with connected ports (eq. 9, P_n per edge) near null and over the stroke (Figs. 5-6, 8-9).

    ``measured`` may hold ``x_s`` and ``Q_L`` [m^3/s].
    """
    plt = pyplot(file)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, lim in zip(axes, (zoom, 1.0)):
        x = np.linspace(-lim, lim, 801)
        ax.plot(x, lpm(valve.no_load_flow(x, P_n)), label="Q_L (model)")
        if measured is not None and "Q_L" in measured:
            xm = np.asarray(measured["x_s"])
            sel = np.abs(xm) <= lim
            ax.plot(xm[sel], lpm(np.asarray(measured["Q_L"])[sel]), "o", ms=3, label="Q_L measured")
        ax.set_xlabel("x_s [-]")
        ax.set_ylabel("Q_L [L/min]")
        ax.set_title(f"P_L = 0, {P_n / 1e5:g} bar per edge, x_s in [-{lim:g}, {lim:g}]")
        ax.grid(True, alpha=0.4)
    axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_pressure_flow(
    valve: PseudoSectionValve,
    P_s: float,
    *,
    openings: tuple[float, ...] = (0.02, 0.05, 0.1, 0.25, 0.5, 0.75, 1.0),
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Load flow against relative load pressure at several openings (eq. 21): the datasheet family."""
    plt = pyplot(file)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    PL = np.linspace(-1.0, 1.0, 401)
    for xs in openings:
        ax.plot(PL, lpm(valve.pressure_flow(xs, PL, P_s)), label=f"x_s = {100 * xs:g} %")
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set_xlabel("P_L = (P_1 - P_2)/P_s [-]")
    ax.set_ylabel("Q_L [L/min]")
    ax.set_title(title or f"Pressure-flow characteristics at P_s = {P_s / 1e5:g} bar")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    return finish(fig, file, plt)
