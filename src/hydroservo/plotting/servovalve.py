"""Plots of the two-stage servovalve on its test bench ([GordicND])."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from hydroservo.identification.servovalve_catalogue import catalogue_response
from hydroservo.plotting import finish, lpm, pyplot

if TYPE_CHECKING:
    from hydroservo.analysis.servovalve_bench import Bode, Report, StaticTests
    from hydroservo.analysis.servovalve_design import DesignStudy
    from hydroservo.identification.servovalve_catalogue import CatalogueFit

__all__ = ["plot_static_bench", "plot_sensitivity", "plot_flow_current", "plot_steps", "plot_bench_bode", "plot_blocked", "plot_catalogue_fits"]


def plot_static_bench(bench: StaticTests, *, title: str = "", file: str | Path | None = None) -> Any:
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


def plot_sensitivity(sens: DesignStudy, figures: dict[str, Any], *, top: int = 8, title: str = "", file: str | Path | None = None) -> Any:
    """One bar chart per design figure: the ``top`` parameters by elasticity (d ln figure / d ln parameter).

    ``sens`` is a :class:`hydroservo.analysis.servovalve.Sensitivity`; ``figures`` maps a figure's key to its
    (description, unit, scale).
    """
    plt = pyplot(file)
    keys = list(sens.figures)
    cols = min(3, len(keys))
    rows = (len(keys) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.2 * rows))
    for ax, key in zip(np.ravel(axes), keys, strict=False):
        ranked = sens.ranked(key, top)[::-1]
        names = [n for n, _ in ranked]
        values = [e for _, e in ranked]
        ax.barh(names, values, color=["tab:blue" if e >= 0 else "tab:red" for e in values])
        description, unit, scale = figures[key]
        ax.set_title(f"{description}\n({sens.figures[key] * scale:.4g} {unit})", fontsize="small")
        ax.axvline(0.0, color="k", lw=0.6)
        ax.grid(True, axis="x", alpha=0.3)
        ax.tick_params(labelsize="small")
    for ax in np.ravel(axes)[len(keys) :]:
        ax.set_visible(False)
    fig.supxlabel("elasticity: % change of the figure per % change of the parameter", fontsize="small")
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_flow_current(report: Report, *, title: str = "", file: str | Path | None = None) -> Any:
    """The flow-current characteristic at rest (points) with the slow-sine loop (line): whole range (left) and
    within 10 % of rated current of null (right), where hysteresis and the null show.

    ``report`` is a :class:`hydroservo.analysis.servovalve_bench.Report` (read by its attributes).
    """
    plt = pyplot(file)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    st, hy = report.static, report.hysteresis
    for ax in axes:
        if st is not None:
            i_ma = np.asarray(st.currents) * 1e3
            ax.plot(i_ma, lpm(st.flows), "o", ms=3, label="at rest (trim)")
            ax.plot(i_ma, lpm(st.rated_flow / st.i_rated * np.asarray(st.currents)), "k--", lw=0.8, label="rated line")
        if hy is not None:
            ax.plot(np.asarray(hy.currents) * 1e3, lpm(hy.flows), "-", lw=1.0, color="tab:orange",
                    label=f"sine {hy.frequency:.3g} Hz: hysteresis {hy.hysteresis * 100:.2f} %")
        ax.set_xlabel("current i [mA]")
        ax.set_ylabel("no-load flow [L/min]")
        ax.grid(True, alpha=0.3)
    axes[0].set_title(f"flow-current characteristic, {report.p_s / 1e5:g} bar")
    axes[0].legend(loc="upper left", fontsize="small")
    zoom = 0.1 * report.i_rated * 1e3
    axes[1].set_xlim(-zoom, zoom)
    largest = st.rated_flow if st is not None else float(np.max(np.abs(hy.flows))) if hy is not None else 1.0
    q_zoom = 0.15 * abs(largest) * 6e4
    axes[1].set_ylim(-q_zoom, q_zoom)
    axes[1].set_title("near null")
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_steps(report: Report, *, title: str = "", file: str | Path | None = None) -> Any:
    """The square-wave tests ([GordicND] Fig. 9): the flow (left) and the flapper tip against the nozzle gap (right)."""
    plt = pyplot(file)
    fig, (ax_q, ax_x) = plt.subplots(1, 2, figsize=(11, 4.5))
    x0 = None
    for st in report.steps or []:
        t_ms = np.asarray(st.t) * 1e3
        label = f"+-{st.fraction * 100:g} %: rise {st.rise_time * 1e3:.2f} ms, overshoot {st.overshoot:.1f} %"
        line = ax_q.plot(t_ms, lpm(st.flow), label=label)[0]
        ax_x.plot(t_ms, np.asarray(st.flapper) * 1e6, color=line.get_color(),
                  label=f"+-{st.fraction * 100:g} %" + (": reaches a nozzle" if st.reaches_nozzle else ""))
        x0 = st.x_0
    if x0 is not None and np.isfinite(x0):
        ax_x.axhline(x0 * 1e6, color="k", lw=0.8, ls="--", label="nozzle")
        ax_x.axhline(-x0 * 1e6, color="k", lw=0.8, ls="--")
    ax_q.set_xlabel("time from the rising step [ms]")
    ax_q.set_ylabel("no-load flow [L/min]")
    ax_q.set_title("square wave between -i and +i")
    ax_x.set_xlabel("time from the rising step [ms]")
    ax_x.set_ylabel("flapper tip x [um]")
    ax_x.set_title("flapper tip")
    for ax in (ax_q, ax_x):
        ax.grid(True, alpha=0.3)
        ax.legend(loc="lower right", fontsize="small")
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_bench_bode(report: Report, *, title: str = "", file: str | Path | None = None) -> Any:
    """Amplitude ratio and phase of the no-load flow against current, one line per amplitude."""
    plt = pyplot(file)
    bode = report.bode
    assert bode is not None, "the report has no frequency response"
    fig, (ax_g, ax_p) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for k, amp in enumerate(bode.amplitudes):
        label = f"+-{amp * 100:g} %"
        if np.isfinite(bode.f_3db[k]):
            label += f": -3 dB at {bode.f_3db[k]:.0f} Hz"
        if np.isfinite(bode.f_90[k]):
            label += f", -90 deg at {bode.f_90[k]:.0f} Hz"
        line = ax_g.semilogx(bode.frequencies, bode.gain_db[k], "o-", ms=3, label=label)[0]
        ax_p.semilogx(bode.frequencies, bode.phase_deg[k], "o-", ms=3, color=line.get_color())
    ax_g.axhline(-3.0, color="k", lw=0.6, ls="--")
    ax_p.axhline(-90.0, color="k", lw=0.6, ls="--")
    return _finish_bode(fig, ax_g, ax_p, "no-load flow against current (relative to the lowest frequency)", title, file, plt)


def plot_blocked(report: Report, *, title: str = "", file: str | Path | None = None) -> Any:
    """Ports blocked: load pressure through null (left) and internal leakage over the whole range (right)."""
    plt = pyplot(file)
    bl = report.blocked
    assert bl is not None, "the report has no blocked-port test"
    fig, (ax, ax_l) = plt.subplots(1, 2, figsize=(11, 4.5))
    ax.plot(np.asarray(bl.currents) * 1e3, np.asarray(bl.load_pressure) / 1e5, "-", lw=1.0)
    ax.set_xlabel("current i [mA]")
    ax.set_ylabel("load pressure p_A - p_B [bar]")
    gain = bl.pressure_gain_40 * bl.i_rated / 100 / 1e5
    note = "" if bl.resolved else " (a jump: at least)"
    ax.set_title(f"load pressure, {bl.frequency:g} Hz sweep\n{gain:.3g} bar/% rated current{note}", fontsize="medium")
    ax_l.plot(np.asarray(bl.leak_currents) * 1e3, lpm(bl.leak_flows), "-", color="tab:purple")
    ax_l.set_xlabel("current i [mA]")
    ax_l.set_ylabel("flow from supply [L/min]")
    ax_l.set_ylim(bottom=0.0)
    ax_l.set_title("internal leakage")
    for a in (ax, ax_l):
        a.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)


def plot_catalogue_fits(bode: Bode, fits: list[CatalogueFit], *, amplitude: int = 0, title: str = "", file: str | Path | None = None) -> Any:
    """The servovalve's frequency response (points) and the catalogue models fitted to it (lines).

    ``bode`` is a :class:`hydroservo.analysis.servovalve_bench.Bode`, ``fits`` a sequence of
    :class:`hydroservo.identification.servovalve_catalogue.CatalogueFit`.
    """
    plt = pyplot(file)
    fig, (ax_g, ax_p) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    f = np.asarray(bode.frequencies)
    label = f"physical model, +-{bode.amplitudes[amplitude] * 100:g} %"
    ax_g.semilogx(f, bode.gain_db[amplitude], "ko", ms=4, label=label)
    ax_p.semilogx(f, bode.phase_deg[amplitude], "ko", ms=4)
    for fit in fits:
        fine = np.geomspace(f[0], f[-1], 200)
        H = catalogue_response(fit.order, fit.params, fine) / abs(catalogue_response(fit.order, fit.params, fine[:1])[0])
        text = f"order {fit.order}: within {fit.gain_error_db:.2f} dB, {fit.phase_error_deg:.1f} deg"
        line = ax_g.semilogx(fine, 20 * np.log10(np.abs(H)), "-", label=text)[0]
        ax_p.semilogx(fine, np.degrees(np.unwrap(np.angle(H))), "-", color=line.get_color())
    return _finish_bode(fig, ax_g, ax_p, "catalogue models fitted to the small-signal response", title, file, plt)


def _finish_bode(fig: Any, ax_g: Any, ax_p: Any, heading: str, title: str, file: str | Path | None, plt: Any) -> Any:
    """Label, grid and finish the gain and phase axes of a servovalve Bode plot."""
    ax_g.set_ylabel("amplitude ratio [dB]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel("frequency [Hz]")
    ax_g.set_title(heading)
    ax_g.legend(loc="lower left", fontsize="small")
    for ax in (ax_g, ax_p):
        ax.grid(True, which="both", alpha=0.3)
    if title:
        fig.suptitle(title)
    return finish(fig, file, plt)
