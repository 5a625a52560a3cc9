"""Plots of the identification procedures on rig records: friction against speed, K(x_v) and H(x_v, d_f)."""

from __future__ import annotations

import textwrap
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.plotting import finish, pyplot

if TYPE_CHECKING:
    from hydroservo.identification.flow_coefficient import FlowCoefficientTables
    from hydroservo.identification.friction import FrictionPoints, StribeckFit

__all__ = ["plot_friction", "plot_flow_coefficient"]


def plot_friction(points: FrictionPoints, fit: StribeckFit, *, title: str = "", file: str | Path | None = None) -> Any:
    """Friction force against speed: the points from the records (with their spread) and the fitted law;
    the relative errors underneath ([Efe2014] Table 5.2's columns)."""
    plt = pyplot(file)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.0, 6.0), sharex=True, gridspec_kw={"height_ratios": [2.4, 1.0]})
    top.errorbar(points.velocity, points.force, yerr=points.spread, fmt="o", ms=4, color="0.3", capsize=3,
                 label="from the records (eq. 4.24), ± spread")
    lo, hi = float(np.min(points.velocity)), float(np.max(points.velocity))
    span = max(hi - lo, 1e-6)
    v = np.linspace(lo - 0.05 * span, hi + 0.05 * span, 600)
    v = v[np.abs(v) > 1e-4]
    top.plot(v[v > 0], fit.law(v[v > 0]), "-", color="C0", lw=1.5, label="Stribeck law fitted (eq. 3.47)")
    top.plot(v[v < 0], fit.law(v[v < 0]), "-", color="C0", lw=1.5)
    top.axhline(0, color="0.6", lw=0.6)
    top.axvline(0, color="0.6", lw=0.6)
    top.set_ylabel("friction force F_f [N]")
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    bottom.bar(fit.velocity, fit.relative_error, width=0.02 * span + 1e-4, color="C3")
    bottom.axhline(0, color="0.3", lw=0.8)
    bottom.set_ylabel("error [%]")
    bottom.set_xlabel("rod speed [m/s]")
    bottom.grid(True, alpha=0.3)
    fig.suptitle(textwrap.fill(title or "friction from rig records", 80), fontsize=10)
    return finish(fig, file, plt)


def plot_flow_coefficient(result: FlowCoefficientTables, *, title: str = "", file: str | Path | None = None) -> Any:
    """The samples' flow-coefficient ratio against the valve signal (opening and closing), the K table through
    the opening ones, and H(x_v, closing) ([Efe2014] Figs. 5.1-5.2)."""
    plt = pyplot(file)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.0, 6.4), sharex=True, gridspec_kw={"height_ratios": [2.0, 1.2]})
    o = result.opening
    top.plot(result.signal[o], result.ratio[o], ".", ms=3, color="C0", alpha=0.5, label="samples, opening")
    top.plot(result.signal[~o], result.ratio[~o], ".", ms=3, color="C1", alpha=0.5, label="samples, closing")
    t = result.tables
    top.plot(t["K_x"], t["K"], "-o", ms=3, color="C0", lw=1.5, label="K(x_v) (eq. 3.22)")
    top.set_ylabel("c_v,eff / c_v [-]")
    top.set_ylim(0, 1.6)
    top.grid(True, alpha=0.3)
    top.legend(fontsize=8)
    if "H_x" in t:
        bottom.plot(t["H_x"], t["H_closing"], "-o", ms=3, color="C1", label="H(x_v, closing)")
        bottom.plot(t["H_x"], t["H_opening"], "-", color="C0", lw=1.0, label="H(x_v, opening)")
        bottom.legend(fontsize=8)
    bottom.set_ylabel("H [-] (eq. 3.23)")
    bottom.set_xlabel("relative spool position x_v / x_v,max [-]")
    bottom.grid(True, alpha=0.3)
    fig.suptitle(textwrap.fill(title or "flow coefficient from rig records", 80), fontsize=10)
    return finish(fig, file, plt)
