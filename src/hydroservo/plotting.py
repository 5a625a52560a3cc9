"""Plots of valve characteristics (the analogues of seed 000 Figs. 2-9 and seed 002 Figs. 3-4, 6-8).

Every function draws into a new figure, saves it when ``file`` is given
(without needing a display) and returns the figure.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo import pseudo_sections as ps
from hydroservo.identification.datasheet import PseudoSectionModel
from hydroservo.units import from_si

if TYPE_CHECKING:
    from hydroservo.analysis.bench import Bench, BenchCurves

__all__ = [
    "plot_pseudo_sections",
    "plot_null_characteristics",
    "plot_load_flow",
    "plot_pressure_flow",
    "plot_bench_characteristics",
    "plot_pressure_flow_family",
    "plot_discharge_coefficient",
]

_SEC = "L/min/bar^0.5"
_SI = "m^3/s/Pa^0.5"
_K = from_si(1.0, _SI, _SEC)  # SI pseudo-section -> L/min/bar^0.5


def _plt(file: str | Path | None) -> Any:
    import matplotlib

    if file is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _finish(fig: Any, file: str | Path | None, plt: Any) -> Any:
    fig.tight_layout()
    if file is not None:
        fig.savefig(file, dpi=110)
        plt.close(fig)
    return fig


def _lpm(q: Any) -> Any:
    return np.asarray(q) * 6e4


def plot_pseudo_sections(
    model: PseudoSectionModel,
    *,
    measured: Mapping[str, np.ndarray] | None = None,
    zoom: float = 0.06,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """A_p and A_n over the full stroke (Fig. 2) and near null (Fig. 3) [L/min/bar^0.5].

    ``measured`` may hold ``x_s``, ``A_p``, ``A_n`` (SI) computed from measured
    curves with :func:`hydroservo.pseudo_sections.sections_from_measurements`.
    """
    plt = _plt(file)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, lim in zip(axes, (1.0, zoom)):
        x = np.linspace(-lim, lim, 801)
        A_p, A_n = model.sections(x)
        ax.plot(x, _K * A_p, label="A_p = A_s1 = A_2t")
        ax.plot(x, _K * A_n, label="A_n = A_s2 = A_1t")
        if measured is not None and lim == zoom:
            xm = np.asarray(measured["x_s"])
            ax.plot(xm, _K * np.asarray(measured["A_p"]), "o", ms=3, label="A_p from curves (eq. 17)")
            ax.plot(xm, _K * np.asarray(measured["A_n"]), "s", ms=3, label="A_n from curves (eq. 16)")
        if lim < 1:
            top = float(_K * np.max(model.sections(np.array([lim]))[0]))
            ax.set_ylim(0, 1.1 * top)
        ax.set_xlabel("x_s [-]")
        ax.set_ylabel(f"pseudo-section [{_SEC}]")
        ax.grid(True, alpha=0.4)
        ax.set_title(f"{model.structure} structure, x_s in [-{lim:g}, {lim:g}]")
    axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return _finish(fig, file, plt)


def plot_null_characteristics(
    model: PseudoSectionModel,
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
    plt = _plt(file)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    x = np.linspace(-zoom, zoom, 801)
    A_p, A_n = model.sections(x)
    ax.plot(x, ps.relative_load_pressure(A_p, A_n), label="P_L [-] (model)")
    ax.plot(x, _lpm(ps.leakage_blocked(A_p, A_n, P_s)), label="q_lk [L/min] (model)")
    if measured is not None:
        ax.plot(measured["x_s"], measured["P_L"], "o", ms=3, label="P_L measured")
        ax.plot(measured["x_s"], _lpm(measured["q_lk"]), "s", ms=3, label="q_lk measured")
    ax.set_xlabel("x_s [-]")
    ax.set_ylabel("q_lk [L/min], P_L [-]")
    ax.set_title(title or f"Blocked ports at P_s = {P_s / 1e5:g} bar")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    return _finish(fig, file, plt)


def plot_load_flow(
    model: PseudoSectionModel,
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
    plt = _plt(file)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, lim in zip(axes, (zoom, 1.0)):
        x = np.linspace(-lim, lim, 801)
        A_p, A_n = model.sections(x)
        ax.plot(x, _lpm(ps.load_flow_no_load(A_p, A_n, 2 * P_n)), label="Q_L (model)")
        if measured is not None and "Q_L" in measured:
            xm = np.asarray(measured["x_s"])
            sel = np.abs(xm) <= lim
            ax.plot(xm[sel], _lpm(np.asarray(measured["Q_L"])[sel]), "o", ms=3, label="Q_L measured")
        ax.set_xlabel("x_s [-]")
        ax.set_ylabel("Q_L [L/min]")
        ax.set_title(f"P_L = 0, {P_n / 1e5:g} bar per edge, x_s in [-{lim:g}, {lim:g}]")
        ax.grid(True, alpha=0.4)
    axes[0].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return _finish(fig, file, plt)


def plot_pressure_flow(
    model: PseudoSectionModel,
    P_s: float,
    *,
    openings: tuple[float, ...] = (0.02, 0.05, 0.1, 0.25, 0.5, 0.75, 1.0),
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Load flow against relative load pressure at several openings (eq. 21): the datasheet family."""
    plt = _plt(file)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    PL = np.linspace(-1.0, 1.0, 401)
    for xs in openings:
        A_p, A_n = model.sections(np.array([xs]))
        ax.plot(PL, _lpm(ps.load_flow(A_p[0], A_n[0], P_s, PL)), label=f"x_s = {100 * xs:g} %")
    ax.axhline(0, color="0.5", lw=0.8)
    ax.set_xlabel("P_L = (P_1 - P_2)/P_s [-]")
    ax.set_ylabel("Q_L [L/min]")
    ax.set_title(title or f"Pressure-flow characteristics at P_s = {P_s / 1e5:g} bar")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    return _finish(fig, file, plt)


# -- seed 002: test-bench characteristics of a spool valve ---------------------------------------
_T_COLORS = ("tab:blue", "tab:green", "tab:red", "tab:purple", "tab:orange", "tab:brown")


def plot_bench_characteristics(
    curves: Sequence[BenchCurves],
    *,
    measured: BenchCurves | None = None,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Flow gain, pressure gain and leakage (seed 002 Figs. 6-8), one colour per temperature.

    Openings in % of X_n; ``measured`` curves (one temperature) as markers.
    """
    plt = _plt(file)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    (ax_q, ax_p), (ax_pl, ax_lk) = axes

    def draw(c: BenchCurves, lab: str, style: dict[str, Any], p1: str, p2: str, p2_label: str | None) -> None:
        """One set of curves; ``p1``/``p2`` are the formats of P_1 and P_2 (line styles or markers)."""
        span = c.bench.P_s - c.bench.P_r

        def pct(X: Any) -> Any:
            return np.asarray(X) / c.bench.X_n * 100.0

        if c.X_flow is not None and c.Q_L is not None:
            ax_q.plot(pct(c.X_flow), _lpm(c.Q_L), p1, label=lab, **style)
        if c.X_blocked is not None and c.P_1 is not None and c.P_2 is not None:
            ax_p.plot(pct(c.X_blocked), c.P_1 / 1e5, p1, label=f"P_1, {lab}" if p2_label else lab, **style)
            ax_p.plot(pct(c.X_blocked), c.P_2 / 1e5, p2, label=p2_label, **style)
            ax_pl.plot(pct(c.X_blocked), (c.P_1 - c.P_2) / span * 100, p1, label=lab, **style)
        if c.X_leak is not None and c.Q_lk is not None:
            ax_lk.plot(pct(c.X_leak), _lpm(c.Q_lk), p1, label=lab, **style)

    for k, c in enumerate(curves):
        lab = f"{c.temperature:g} °C"
        draw(c, lab, {"color": _T_COLORS[k % len(_T_COLORS)], "zorder": 3}, "-", "--", f"P_2, {lab}")
    if measured is not None:
        style = {"ms": 2.5, "color": "k", "alpha": 0.45, "ls": "none"}
        draw(measured, f"measured, {measured.temperature:g} °C", style, "o", "s", None)
    labels = (
        (ax_q, "Flow gain (use ports connected)", "Q_L [L/min]"),
        (ax_p, "Pressure gain (use ports blocked)", "P_1, P_2 [bar]"),
        (ax_pl, "Load pressure (use ports blocked)", "P_L = P_1 - P_2 [% P_s]"),
        (ax_lk, "Leakage (use ports blocked)", "supply flow [L/min]"),
    )
    for ax, ttl, ylab in labels:
        ax.set_title(ttl, fontsize=10)
        ax.set_xlabel("opening X [% X_n]")
        ax.set_ylabel(ylab)
        ax.grid(True, alpha=0.4)
        ax.legend(fontsize=7)
    if title:
        fig.suptitle(title)
    return _finish(fig, file, plt)


def plot_pressure_flow_family(
    P_L: np.ndarray,
    Q_L: np.ndarray,
    openings: Sequence[float],
    bench: Bench,
    *,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Load flow against load pressure at fixed openings (the pressure-flow family)."""
    plt = _plt(file)
    fig, ax = plt.subplots(figsize=(8.5, 4.5))
    for x, q in zip(openings, Q_L, strict=True):
        ax.plot(P_L / 1e5, _lpm(q), label=f"X = {x / bench.X_n * 100:g} % X_n")
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel("load pressure P_L = P_1 - P_2 [bar]")
    ax.set_ylabel("load flow Q_L [L/min]")
    ax.set_title(title or "Pressure-flow characteristics")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.0, 0.5))
    return _finish(fig, file, plt)


def plot_discharge_coefficient(params: Mapping[str, float], *, title: str = "", file: str | Path | None = None) -> Any:
    """Flow coefficient of eq. (20) against flow number and closure (seed 002 Figs. 3 and 4), low-gain stage."""
    from hydroservo.spool_orifices import continuity_constant, discharge_coefficient

    plt = _plt(file)
    Cq, lt, w, c = params["Cq_inf"], params["lambda_tL"], params["w_L"], params["c"]
    K_g = continuity_constant(Cq, lt, w, c)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    lam = np.logspace(-1, 4, 300)
    for closure in (0.0, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0):
        ax1.semilogx(lam, discharge_coefficient(-closure * 1e-6, lam, Cq, lt, K_g), label=f"|X_i| = {closure:g} µm")
    ax1.set_xlabel("flow number λ [-]")
    ax1.set_ylabel("C_q [-]")
    ax1.set_title("Closed orifice (Fig. 3 analogue)", fontsize=10)
    ax1.grid(True, which="both", alpha=0.4)
    ax1.legend(fontsize=7)
    X = np.linspace(-10.0, 10.0, 201)
    L, XX = np.meshgrid(np.log10(lam), X)
    cs = ax2.contourf(XX, L, discharge_coefficient(XX * 1e-6, 10**L, Cq, lt, K_g), levels=20, cmap="viridis")
    fig.colorbar(cs, ax=ax2, label="C_q [-]")
    ax2.set_xlabel("orifice opening X_i [µm] (< 0: closed)")
    ax2.set_ylabel("log10 flow number λ [-]")
    ax2.set_title("Continuity through null (Fig. 4 analogue)", fontsize=10)
    fig.suptitle(title or f"Eq. (20): C_q∞ = {Cq:g}, λ_t = {lt:g}, K_g = {K_g:.3g} 1/m")
    return _finish(fig, file, plt)
