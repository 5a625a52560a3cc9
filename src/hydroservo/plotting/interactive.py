"""Interactive figures for reports: plotly figures (zoom, pan, each value with its unit on hover).

Each function takes the library's result objects and returns the figure as plotly's JSON form, a dict with
``data`` (the traces) and ``layout``, which :class:`hydroservo.io.html.Figure` carries into a page and
plotly.js draws there. The figures are written in plotly's documented figure schema directly: no law is
evaluated here, and no plotting library is imported (the page's JavaScript is plotly.js, shipped by the
``plotly`` package).

Numbers are rounded to 7 significant digits (far below what a plot or a hover shows) to keep pages small;
a trace of more than :data:`MAX_POINTS` points keeps, in each of :data:`MAX_POINTS`/2 bins, its smallest and
largest value, so that no peak is hidden.

=======================  ==================================================================
function                 figure
=======================  ==================================================================
:func:`result_figure`    signals of a run against time, a panel per group, one shared time axis
:func:`bode_figure`      gain and phase against frequency, a trace per amplitude
:func:`xy_figure`        curves y(x): static characteristics
:func:`bar_figure`       horizontal bars with error bars: sensitivity indices
=======================  ==================================================================
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from hydroservo.analysis.frequency import FrequencyResponse
    from hydroservo.system.result import Result

__all__ = ["result_figure", "bode_figure", "xy_figure", "bar_figure", "MAX_POINTS", "COLORS"]

#: Largest number of points of a trace (more are thinned keeping each bin's extremes).
MAX_POINTS = 4000
#: The colours of the traces (colour-blind safe: Okabe and Ito).
COLORS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442")
_FONT = {"family": "system-ui, -apple-system, 'Segoe UI', Roboto, Helvetica, Arial, sans-serif", "size": 12}


def _numbers(values: Any) -> list[float | None]:
    """A list of floats rounded to 7 significant digits; NaN and infinities as None (a gap)."""
    a = np.asarray(values, dtype=float).ravel()
    out: list[float | None] = []
    for v in a.tolist():
        out.append(float(f"{v:.7g}") if np.isfinite(v) else None)
    return out


def _thin(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """At most :data:`MAX_POINTS` points: each bin's first, smallest and largest value (in time order)."""
    n = x.size
    if n <= MAX_POINTS:
        return x, y
    bins = MAX_POINTS // 2
    edges = np.linspace(0, n, bins + 1).astype(int)
    keep: list[int] = []
    for a, b in zip(edges[:-1], edges[1:], strict=True):
        if b <= a:
            continue
        seg = y[a:b]
        finite = np.isfinite(seg)
        picks = {a}
        if finite.any():
            idx = np.flatnonzero(finite)
            picks |= {a + int(idx[np.argmin(seg[idx])]), a + int(idx[np.argmax(seg[idx])])}
        keep += sorted(picks)
    keep.append(n - 1)
    k = np.unique(np.array(keep))
    return x[k], y[k]


def _layout(title: str, rows: int, height_per_row: int = 210) -> dict[str, Any]:
    return {
        "title": {"text": title, "x": 0.01, "xanchor": "left", "font": {"size": 15}},
        "font": _FONT,
        "height": 90 + height_per_row * rows,
        "margin": {"l": 70, "r": 20, "t": 50, "b": 45},
        "paper_bgcolor": "white",
        "plot_bgcolor": "white",
        "hovermode": "x unified",
        "legend": {"orientation": "h", "y": -0.08 if rows > 1 else -0.18, "x": 0, "font": {"size": 11}},
    }


def _axis(title: str, **extra: Any) -> dict[str, Any]:
    return {"title": {"text": title}, "showgrid": True, "gridcolor": "#e6e6e6", "zeroline": False,
            "linecolor": "#888", "mirror": True, "ticks": "outside", **extra}


def result_figure(
    result: Result,
    panels: Sequence[Sequence[str]] | None = None,
    units: Mapping[str, str] | None = None,
    title: str = "",
) -> dict[str, Any]:
    """Signals of ``result`` against time: a panel per group of ``panels`` (default the result's own, else its
    first six signals), in ``units`` where given (else SI), every panel on one time axis (zoom one, zoom all).

    Hovering shows every signal of the panel at that time, each with its unit.
    """
    from hydroservo.plotting import axis_label, by_dimension, panel_units
    from hydroservo.units import si_unit

    units = units or {}
    chosen = by_dimension([list(p) for p in (panels or result.panels or [[n] for n in result.names[:6]])], result.units)
    data: list[dict[str, Any]] = []
    layout = _layout(title or result.model, len(chosen))
    layout["grid"] = {"rows": len(chosen), "columns": 1, "pattern": "coupled", "roworder": "top to bottom",
                      "ygap": 0.12}
    t = np.asarray(result.t, dtype=float)
    color = 0
    for row, panel in enumerate(chosen, start=1):
        yaxis = "y" if row == 1 else f"y{row}"
        shown_units = []
        drawn_units = panel_units(result.units, panel, dict(units))
        for name, drawn in zip(panel, drawn_units):
            unit = si_unit(drawn)
            shown_units.append(unit)
            x, y = _thin(t, np.asarray(result.get(name, drawn), dtype=float))
            described = result.descriptions.get(name, "")
            label = f"{name} [{unit}]"
            data.append({
                "type": "scatter", "mode": "lines", "name": label, "x": _numbers(x), "y": _numbers(y),
                "xaxis": "x", "yaxis": yaxis, "line": {"color": COLORS[color % len(COLORS)], "width": 1.6},
                "legendgroup": f"panel{row}",
                "hovertemplate": f"%{{y:.5g}} {unit}" + (f" ({described})" if described and described != name else "")
                + f"<extra>{name}</extra>",
            })
            color += 1
        distinct = list(dict.fromkeys(shown_units))
        label = axis_label(panel, result.descriptions, ", ".join(distinct), drawn_units[0])
        layout["yaxis" if row == 1 else f"yaxis{row}"] = _axis(label.replace("\n", "<br>"))
    layout["xaxis"] = _axis("t [s]")
    return {"data": data, "layout": layout}


def bode_figure(responses: FrequencyResponse | Sequence[FrequencyResponse], title: str = "",
                input_unit: str = "", output_unit: str = "") -> dict[str, Any]:
    """Gain [dB] and phase [deg] against frequency [Hz] (log axis), a trace per response and amplitude; the
    later responses dashed (a model beside data). Units name what the gain is a ratio of, for the axis title."""
    from hydroservo.analysis.frequency import FrequencyResponse

    items = [responses] if isinstance(responses, FrequencyResponse) else list(responses)
    data: list[dict[str, Any]] = []
    for k, resp in enumerate(items):
        for i, a in enumerate(resp.amplitudes):
            label = (resp.label + " " if resp.label else "") + (f"{a:g}" if len(resp.amplitudes) > 1 else "")
            style = {"color": COLORS[i % len(COLORS)], "width": 1.8, "dash": "solid" if k == 0 else "dash"}
            common = {"type": "scatter", "mode": "lines+markers" if k == 0 and resp.frequencies.size < 60 else "lines",
                      "x": _numbers(resp.frequencies), "line": style, "legendgroup": f"{k}-{i}",
                      "name": label.strip() or f"response {k + 1}"}
            data.append({**common, "y": _numbers(resp.gain_db[i]), "xaxis": "x", "yaxis": "y",
                         "hovertemplate": "%{y:.4g} dB at %{x:.4g} Hz<extra>%{fullData.name}</extra>"})
            data.append({**common, "y": _numbers(resp.phase_deg[i]), "xaxis": "x", "yaxis": "y2", "showlegend": False,
                         "hovertemplate": "%{y:.4g} deg at %{x:.4g} Hz<extra>%{fullData.name}</extra>"})
    layout = _layout(title or "frequency response", 2, 230)
    layout["hovermode"] = "closest"
    layout["grid"] = {"rows": 2, "columns": 1, "pattern": "coupled", "roworder": "top to bottom", "ygap": 0.1}
    ratio = f" ({output_unit}/{input_unit})" if output_unit or input_unit else ""
    layout["xaxis"] = _axis("f [Hz]", type="log")
    layout["yaxis"] = _axis(f"gain{ratio} [dB]")
    layout["yaxis2"] = _axis("phase [deg]")
    return {"data": data, "layout": layout}


def xy_figure(
    curves: Sequence[tuple[Any, Any, str]],
    x_label: str,
    y_label: str,
    title: str = "",
    markers: Sequence[tuple[Any, Any, str]] = (),
    marker_size: int = 6,
) -> dict[str, Any]:
    """Curves ``(x, y, name)`` (lines) and measured points ``markers`` (``(x, y, name)``) on one pair of axes;
    ``x_label`` and ``y_label`` carry the units (``"i [mA]"``). Many markers (a record's samples) read better
    small (``marker_size``), and are drawn in grey behind the curves."""
    data: list[dict[str, Any]] = []
    for k, (x, y, name) in enumerate(curves):
        data.append({"type": "scatter", "mode": "lines", "name": name, "x": _numbers(x), "y": _numbers(y),
                     "line": {"color": COLORS[k % len(COLORS)], "width": 1.8},
                     "hovertemplate": f"{y_label} %{{y:.5g}}<br>{x_label} %{{x:.5g}}<extra>{name}</extra>"})
    for k, (x, y, name) in enumerate(markers):
        marker = ({"color": COLORS[k % len(COLORS)], "size": marker_size, "symbol": "circle-open"} if marker_size >= 5
                  else {"color": "#8a8f96", "size": marker_size, "symbol": "circle"})
        data.insert(k, {"type": "scatter", "mode": "markers", "name": name, "x": _numbers(x), "y": _numbers(y),
                     "marker": marker,
                     "hovertemplate": f"{y_label} %{{y:.5g}}<br>{x_label} %{{x:.5g}}<extra>{name}</extra>"})
    layout = _layout(title, 1, 360)
    layout["hovermode"] = "closest"
    layout["xaxis"] = _axis(x_label)
    layout["yaxis"] = _axis(y_label)
    return {"data": data, "layout": layout}


def bar_figure(
    groups: Mapping[str, Sequence[tuple[str, float, float | None]]],
    value_label: str,
    title: str = "",
) -> dict[str, Any]:
    """Horizontal bars, a panel per group (a metric): ``(label, value, error or None)`` each, largest on top,
    with error bars (confidence half-widths) where given."""
    names = list(groups)
    data: list[dict[str, Any]] = []
    layout = _layout(title, max(len(names), 1), 60)
    layout["hovermode"] = "closest"
    layout["showlegend"] = False
    layout["grid"] = {"rows": max(len(names), 1), "columns": 1, "pattern": "independent",
                      "roworder": "top to bottom", "ygap": 0.55}
    annotations: list[dict[str, Any]] = []
    for row, name in enumerate(names, start=1):
        bars = sorted(groups[name], key=lambda b: abs(b[1]) if np.isfinite(b[1]) else -1.0)
        suffix = "" if row == 1 else str(row)
        errors = [b[2] for b in bars]
        bar: dict[str, Any] = {
            "type": "bar", "orientation": "h", "name": name, "y": [b[0] for b in bars], "x": _numbers([b[1] for b in bars]),
            "xaxis": f"x{suffix}", "yaxis": f"y{suffix}", "marker": {"color": COLORS[(row - 1) % len(COLORS)]},
            "hovertemplate": f"%{{y}}: %{{x:.4g}}<extra>{name}</extra>",
        }
        if any(e is not None for e in errors):
            bar["error_x"] = {"type": "data", "array": _numbers([np.nan if e is None else e for e in errors]),
                              "visible": True, "color": "#444"}
        data.append(bar)
        layout[f"xaxis{suffix}"] = _axis(value_label if row == len(names) else "")
        layout[f"yaxis{suffix}"] = _axis("", automargin=True)
        annotations.append({"text": f"<b>{name}</b>", "xref": f"x{suffix} domain", "yref": f"y{suffix} domain",
                            "x": 0, "y": 1.0, "xanchor": "left", "yanchor": "bottom", "showarrow": False,
                            "font": {"size": 12}})
    layout["annotations"] = annotations
    layout["height"] = 90 + sum(70 + 22 * len(groups[n]) for n in names)
    return {"data": data, "layout": layout}
