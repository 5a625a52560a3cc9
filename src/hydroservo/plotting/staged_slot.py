"""Plots of the staged-slot valve on its test bench: the analogues of [MareAttarND] Figs. 3-4 and 6-8."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.analysis.static_bench import Bench, BenchCurves
from hydroservo.laws.staged_slot import continuity_constant, discharge_coefficient
from hydroservo.plotting import finish, lpm, pyplot

__all__ = ["plot_bench_characteristics", "plot_pressure_flow_family", "plot_discharge_coefficient"]

_T_COLORS = ("tab:blue", "tab:green", "tab:red", "tab:purple", "tab:orange", "tab:brown")


def plot_bench_characteristics(
    curves: Sequence[BenchCurves],
    *,
    measured: BenchCurves | None = None,
    title: str = "",
    file: str | Path | None = None,
) -> Any:
    """Flow gain, pressure gain and leakage ([MareAttarND] Figs. 6-8), one colour per temperature.

    Openings in % of X_n; ``measured`` curves (one temperature) as markers.
    """
    plt = pyplot(file)
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    (ax_q, ax_p), (ax_pl, ax_lk) = axes

    def draw(c: BenchCurves, lab: str, style: dict[str, Any], p1: str, p2: str, p2_label: str | None) -> None:
        """One set of curves; ``p1``/``p2`` are the formats of P_1 and P_2 (line styles or markers)."""
        span = c.bench.P_s - c.bench.P_r

        def pct(X: Any) -> Any:
            return np.asarray(X) / c.bench.X_n * 100.0

        if c.X_flow is not None and c.Q_L is not None:
            ax_q.plot(pct(c.X_flow), lpm(c.Q_L), p1, label=lab, **style)
        if c.X_blocked is not None and c.P_1 is not None and c.P_2 is not None:
            ax_p.plot(pct(c.X_blocked), c.P_1 / 1e5, p1, label=f"P_1, {lab}" if p2_label else lab, **style)
            ax_p.plot(pct(c.X_blocked), c.P_2 / 1e5, p2, label=p2_label, **style)
            ax_pl.plot(pct(c.X_blocked), (c.P_1 - c.P_2) / span * 100, p1, label=lab, **style)
        if c.X_leak is not None and c.Q_lk is not None:
            ax_lk.plot(pct(c.X_leak), lpm(c.Q_lk), p1, label=lab, **style)

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
    return finish(fig, file, plt)


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
    plt = pyplot(file)
    fig, ax = plt.subplots(figsize=(8.5, 4.5))
    for x, q in zip(openings, Q_L, strict=True):
        ax.plot(P_L / 1e5, lpm(q), label=f"X = {x / bench.X_n * 100:g} % X_n")
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel("load pressure P_L = P_1 - P_2 [bar]")
    ax.set_ylabel("load flow Q_L [L/min]")
    ax.set_title(title or "Pressure-flow characteristics")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.0, 0.5))
    return finish(fig, file, plt)


def plot_discharge_coefficient(params: Mapping[str, float], *, title: str = "", file: str | Path | None = None) -> Any:
    """Flow coefficient of eq. (20) against flow number and closure ([MareAttarND] Figs. 3 and 4), low-gain stage."""
    plt = pyplot(file)
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
    return finish(fig, file, plt)
