"""Signal sources: steps, ramps, sines, square waves, pulse trains, staircases and time tables.

Signal blocks carry the unit given as ``unit=`` when they are created
(``Step("vi", unit="V", amplitude="2 V")``); without it they are
dimensionless.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import SIGNAL, Component, Option, Output, Param, Port, register
from hydroservo.errors import ParameterError

__all__ = [
    "Constant", "Step", "SoftStep", "DecayingStep", "Pulse", "PulseWave", "Staircase", "Ramp", "Sine", "Square", "Table",
    "Table2D", "SIGNAL_OUTPUT",
]

#: The output of every signal block.
SIGNAL_OUTPUT = {"y": Output(SIGNAL, "signal")}


@register
class Constant(Component):
    """A constant signal ``y = value``."""

    PARAMETERS = {"value": Param(0.0, SIGNAL, "the value")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["value"] + 0.0 * t}


@register
class Step(Component):
    """Step: ``offset`` before ``t_step``, ``offset + amplitude`` from ``t_step`` on."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "step height"),
        "t_step": Param(0.0, "s", "time of the step", min=0.0),
        "offset": Param(0.0, SIGNAL, "value before the step"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["offset"] + bk.if_else(t >= p["t_step"], p["amplitude"], 0.0)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"step": (t - p["t_step"], 1e-3)}


@register
class SoftStep(Component):
    r"""A step eased by half a cosine: ``offset`` before ``t_start``,
    :math:`offset + \tfrac{A}{2}(1 - \cos(\pi (t - t_{start})/(t_{end} - t_{start})))` until ``t_end``,
    ``offset + amplitude`` after (Hopsan's SignalSoftStep, [Hopsan2026])."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "step height"),
        "t_start": Param(1.0, "s", "start of the step", min=0.0),
        "t_end": Param(2.0, "s", "end of the step", min=0.0),
        "offset": Param(0.0, SIGNAL, "value before the step"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def check(self) -> None:
        if self.values["t_end"] <= self.values["t_start"]:
            raise ParameterError(
                f"{self.name}.t_end = {self.values['t_end']:g} s: expected after t_start = {self.values['t_start']:g} s"
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        phase = bk.fmin(bk.fmax((t - p["t_start"]) / (p["t_end"] - p["t_start"]), 0.0), 1.0)
        return {"y": p["offset"] + 0.5 * p["amplitude"] * (1.0 - bk.cos(np.pi * phase))}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"start": (t - p["t_start"], 1e-3), "end": (t - p["t_end"], 1e-3)}


@register
class Pulse(Component):
    """Pulse: ``offset + amplitude`` from ``t_start`` for ``duration``, ``offset`` before and after.

    A valve-signal step that ends: the open-loop steps of [Efe2014] section 5.2
    move the arm by the valve held open for a while, then closed.
    """

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "pulse height"),
        "t_start": Param(0.0, "s", "time the pulse starts", min=0.0),
        "duration": Param(1.0, "s", "how long it lasts", min=0.0),
        "offset": Param(0.0, SIGNAL, "value outside the pulse"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        on = bk.if_else(t >= p["t_start"], 1.0, 0.0) * bk.if_else(t < p["t_start"] + p["duration"], 1.0, 0.0)
        return {"y": p["offset"] + p["amplitude"] * on}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"start": (t - p["t_start"], 1e-3), "end": (t - p["t_start"] - p["duration"], 1e-3)}


@register
class DecayingStep(Component):
    r"""A step that decays back: ``offset`` before ``t_step``, :math:`offset + A e^{-(t - t_{step})/\tau}` from it
    on (Hopsan's SignalStepExponentialDelay, [Hopsan2026] Signal/Sources&Sinks/SignalStepExponentialDelay.hpp)."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "height of the step"),
        "tau": Param(1.0, "s", "time constant of the decay", min=0.0, min_inclusive=False),
        "t_step": Param(1.0, "s", "time of the step", min=0.0),
        "offset": Param(0.0, SIGNAL, "value before the step, and approached after it"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        since = bk.fmax(t - p["t_step"], 0.0)
        return {"y": p["offset"] + bk.if_else(t >= p["t_step"], p["amplitude"] * bk.exp(-since / p["tau"]), 0.0)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"step": (t - p["t_step"], 1e-3)}


@register
class PulseWave(Component):
    """Periodic pulses: ``offset + amplitude`` for the first ``duty`` of each ``period`` from ``t_start`` on,
    ``offset`` for the rest of it and before ``t_start`` (Hopsan's SignalPulseWave, [Hopsan2026]
    Signal/Sources&Sinks/SignalPulseWave.hpp). :class:`Square` is the wave about its offset."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "height of the pulses"),
        "period": Param(1.0, "s", "period", min=0.0, min_inclusive=False),
        "duty": Param(0.5, "", "fraction of each period at offset + amplitude", min=0.0, max=1.0),
        "t_start": Param(0.0, "s", "start of the first pulse", min=0.0),
        "offset": Param(0.0, SIGNAL, "value between the pulses"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        phase = (t - p["t_start"]) / p["period"]
        on = bk.if_else(t > p["t_start"], 1.0, 0.0) * bk.if_else(phase - bk.floor(phase) < p["duty"], 1.0, 0.0)
        return {"y": p["offset"] + p["amplitude"] * on}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        # each pulse's rise (whole periods from t_start) and fall (duty into the period): sines of slope 1 there,
        # so that an edge is located in time as closely as a step's
        phase = (t - p["t_start"]) / p["period"]
        scale = p["period"] / np.pi
        return {
            "start": (t - p["t_start"], 1e-3),
            "rise": (scale * bk.sin(np.pi * phase), 1e-3),
            "fall": (scale * bk.sin(np.pi * (phase - p["duty"])), 1e-3),
        }


@register
class Staircase(Component):
    """Steps of ``height`` every ``width`` from ``t_start``: ``height * floor((t - t_start) / width)``, 0 before
    (Hopsan's SignalStaircase, [Hopsan2026] Signal/Sources&Sinks/SignalStaircase.hpp)."""

    PARAMETERS = {
        "height": Param(1.0, SIGNAL, "height of each step"),
        "width": Param(1.0, "s", "time between steps", min=0.0, min_inclusive=False),
        "t_start": Param(0.0, "s", "start time (the first step is one width later)", min=0.0),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["height"] * bk.floor(bk.fmax(t - p["t_start"], 0.0) / p["width"])}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        # each step, whole widths after t_start: a sine of slope 1 there, located in time as closely as a step
        edge = p["width"] / np.pi * bk.sin(np.pi * (t - p["t_start"]) / p["width"])
        return {"start": (t - p["t_start"], 1e-3), "step": (edge, 1e-3)}


@register
class Ramp(Component):
    """Ramp of ``slope`` per second from ``t_start`` on, limited to ``limit`` in magnitude of change."""

    PARAMETERS = {
        "slope": Param(1.0, SIGNAL + "/s", "rate of change"),
        "t_start": Param(0.0, "s", "start time", min=0.0),
        "limit": Param(1e30, SIGNAL, "largest change from the offset", min=0.0),
        "offset": Param(0.0, SIGNAL, "initial value"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        change = p["slope"] * bk.fmax(t - p["t_start"], 0.0)
        change = bk.fmin(bk.fmax(change, -p["limit"]), p["limit"])
        return {"y": p["offset"] + change}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        # the start, and the change reaching its limit (never, at the default limit)
        return {"start": (t - p["t_start"], 1e-3), "limit": (bk.fabs(p["slope"]) * (t - p["t_start"]) - p["limit"], 1.0)}


@register
class Sine(Component):
    """``offset + amplitude * sin(2 pi f (t - t_start) + phase)`` from ``t_start`` on."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "amplitude"),
        "frequency": Param(1.0, "Hz", "frequency", min=0.0),
        "phase": Param(0.0, "rad", "phase at t_start"),
        "t_start": Param(0.0, "s", "start time", min=0.0),
        "offset": Param(0.0, SIGNAL, "offset"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tau = t - p["t_start"]
        wave = p["amplitude"] * bk.sin(2 * np.pi * p["frequency"] * tau + p["phase"])
        return {"y": p["offset"] + bk.if_else(tau >= 0, wave, 0.0)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"start": (t - p["t_start"], 1e-3)}


@register
class Square(Component):
    """Square wave of ``amplitude`` about ``offset``, positive first half-period, from ``t_start`` on."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "amplitude"),
        "frequency": Param(1.0, "Hz", "frequency", min=0.0, min_inclusive=False),
        "t_start": Param(0.0, "s", "start time", min=0.0),
        "offset": Param(0.0, SIGNAL, "offset"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tau = t - p["t_start"]
        phase = tau * p["frequency"]
        frac = phase - bk.floor(phase)
        wave = bk.if_else(frac < 0.5, p["amplitude"], -p["amplitude"])
        return {"y": p["offset"] + bk.if_else(tau >= 0, wave, 0.0)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        # the start, and each edge: the sine of the same frequency changes sign where the square wave jumps
        return {"start": (t - p["t_start"], 1e-3), "edge": (bk.sin(2 * np.pi * p["frequency"] * (t - p["t_start"])), 1.0)}


@register
class Table(Component):
    r"""Signal from a time table, linear between points, held outside.

    ``times`` [s] and ``values`` (the block's unit) are equally long lists. To
    take them from a CSV file use :func:`hydroservo.io.read_time_table`; a model
    file names the file with ``file = "record.csv"`` (and ``column``), and
    ``source`` keeps that name so that the model file can be written again.

    With option ``index = "input"`` the table is a lookup table of its input
    ``u`` rather than of time: ``times`` then holds the breakpoints of ``u`` (in
    ``u``'s SI unit, strictly increasing) and :math:`y = scale \cdot f(u)`, ``f``
    linear between the breakpoints and held at the first and last value outside
    them: Hopsan's Signal1DLookupTable ([Hopsan2026]
    Signal/Non-Linearities/Signal1DLookupTable.hpp, its LookupTable1D's
    interpolation). The output has a kink at each breakpoint.
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the values")}
    OUTPUTS = SIGNAL_OUTPUT
    OPTIONS = {
        "index": Option("time", ("time", "input"), "what the table is indexed by: time, or the input u (a lookup table)")
    }

    def __init__(
        self,
        name: str,
        times: Any = None,
        values: Any = None,
        source: Mapping[str, Any] | None = None,
        **params: Any,
    ) -> None:
        super().__init__(name, **params)
        self.source = None if source is None else dict(source)
        if times is None or values is None:
            raise ParameterError(f"{name}: a Table needs times and values (hydroservo.io.read_time_table reads a CSV)")
        t = np.asarray(times, dtype=float).ravel()
        v = np.asarray(values, dtype=float).ravel()
        if t.size == 0 or t.size != v.size:
            raise ParameterError(
                f"{name}: times and values must be equally long and non-empty; got {t.size} and {v.size}"
            )
        if np.any(np.diff(t) <= 0):
            what = "breakpoints of the input u (index = input)" if self.option("index") == "input" else "times [s]"
            raise ParameterError(f"{name}.times: expected strictly increasing {what}")
        self.times, self.table_values = t, v

    def config(self) -> dict[str, Any]:
        if self.source is not None:
            return dict(self.source)
        return {"times": self.times.tolist(), "values": self.table_values.tolist()}

    def options_changed(self) -> None:
        """A lookup table (``index = "input"``) reads its input ``u``; a time table has none."""
        by_input = self.option("index") == "input"
        self.INPUTS = {"u": Port("", "the table's index (option index = input)")} if by_input else {}  # type: ignore[misc]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        index = u["u"] if self.option("index") == "input" else t
        return {"y": p["scale"] * bk.interp(index, self.times, self.table_values)}


@register
class Table2D(Component):
    r"""A lookup table of two inputs, bilinear between its breakpoints and held at its edges outside them: Hopsan's
    Signal2DLookupTable ([Hopsan2026] Signal/Non-Linearities/Signal2DLookupTable.hpp, its LookupTable2D's
    interpolation).

    ``rows`` (the breakpoints of input ``row``) and ``cols`` (of ``col``) are strictly increasing; ``values`` is
    the matrix of ``len(rows)`` by ``len(cols)`` values, :math:`V_{ij}` at (rows_i, cols_j). Each input is first
    held within its breakpoints; then, as Hopsan's, the table is interpolated along ``row`` in the two columns
    about ``col`` and between them along ``col``: :math:`y = \sum_j h_j(c)\, f_j(r)` with :math:`f_j` column
    j interpolated in r and :math:`h_j` the piecewise-linear hat of breakpoint j. A table read from a file keeps
    its name in ``source`` so that a model file can be written again.
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the values")}
    INPUTS = {"row": Port("", "the first index (along rows)"), "col": Port("", "the second index (along cols)")}
    OUTPUTS = SIGNAL_OUTPUT

    def __init__(
        self,
        name: str,
        rows: Any = None,
        cols: Any = None,
        values: Any = None,
        source: Mapping[str, Any] | None = None,
        **params: Any,
    ) -> None:
        super().__init__(name, **params)
        self.source = None if source is None else dict(source)
        if rows is None or cols is None or values is None:
            raise ParameterError(f"{name}: a Table2D needs rows, cols and values")
        r = np.asarray(rows, dtype=float).ravel()
        c = np.asarray(cols, dtype=float).ravel()
        v = np.asarray(values, dtype=float)
        if r.size < 2 or c.size < 2 or v.shape != (r.size, c.size):
            raise ParameterError(
                f"{name}: expected at least two rows and two cols and values of {r.size} by {c.size}; got values of "
                f"shape {v.shape}"
            )
        for what, index in (("rows", r), ("cols", c)):
            if np.any(np.diff(index) <= 0) or not np.all(np.isfinite(index)):
                raise ParameterError(f"{name}.{what}: expected strictly increasing breakpoints")
        if not np.all(np.isfinite(v)):
            raise ParameterError(f"{name}.values: expected finite numbers")
        self.rows, self.cols, self.table_values = r, c, v

    def config(self) -> dict[str, Any]:
        if self.source is not None:
            return dict(self.source)
        return {"rows": self.rows.tolist(), "cols": self.cols.tolist(), "values": self.table_values.tolist()}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        unit = np.eye(self.cols.size)
        y = 0.0
        for j in range(self.cols.size):
            y = y + bk.interp(u["col"], self.cols, unit[j]) * bk.interp(u["row"], self.rows, self.table_values[:, j])
        return {"y": p["scale"] * y}


@register
class Table3D(Component):
    r"""A lookup table of three inputs, trilinear between its breakpoints and held at its edges outside them:
    Hopsan's Signal3DLookupTable ([Hopsan2026] Signal/Non-Linearities/Signal3DLookupTable.hpp, its
    LookupTable3D's interpolation), Table2D's law with a third index.

    ``rows``, ``cols`` and ``planes`` (the breakpoints of inputs ``row``, ``col`` and ``plane``) are strictly
    increasing; ``values`` is the array of ``len(rows)`` by ``len(cols)`` by ``len(planes)`` values,
    :math:`V_{ijk}` at (rows_i, cols_j, planes_k). Each input is first held within its breakpoints; then
    :math:`y = \sum_{jk} h_j(c)\, h_k(q)\, f_{jk}(r)`, :math:`f_{jk}` the line (j, k) interpolated in r and
    :math:`h` the piecewise-linear hats of the breakpoints (multilinear interpolation, whatever the order of the
    axes).
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the values")}
    INPUTS = {
        "row": Port("", "the first index (along rows)"),
        "col": Port("", "the second index (along cols)"),
        "plane": Port("", "the third index (along planes)"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def __init__(
        self, name: str, rows: Any = None, cols: Any = None, planes: Any = None, values: Any = None, **params: Any
    ) -> None:
        super().__init__(name, **params)
        if rows is None or cols is None or planes is None or values is None:
            raise ParameterError(f"{name}: a Table3D needs rows, cols, planes and values")
        axes = [np.asarray(a, dtype=float).ravel() for a in (rows, cols, planes)]
        v = np.asarray(values, dtype=float)
        shape = tuple(a.size for a in axes)
        if min(shape) < 2 or v.shape != shape:
            raise ParameterError(
                f"{name}: expected at least two rows, cols and planes and values of {shape[0]} by {shape[1]} by "
                f"{shape[2]}; got values of shape {v.shape}"
            )
        for what, index in zip(("rows", "cols", "planes"), axes, strict=True):
            if np.any(np.diff(index) <= 0) or not np.all(np.isfinite(index)):
                raise ParameterError(f"{name}.{what}: expected strictly increasing breakpoints")
        if not np.all(np.isfinite(v)):
            raise ParameterError(f"{name}.values: expected finite numbers")
        self.rows, self.cols, self.planes = axes
        self.table_values = v

    def config(self) -> dict[str, Any]:
        return {"rows": self.rows.tolist(), "cols": self.cols.tolist(), "planes": self.planes.tolist(),
                "values": self.table_values.tolist()}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        hat_c, hat_q = np.eye(self.cols.size), np.eye(self.planes.size)
        y = 0.0
        for k in range(self.planes.size):
            weight_k = bk.interp(u["plane"], self.planes, hat_q[k])
            for j in range(self.cols.size):
                line = bk.interp(u["row"], self.rows, self.table_values[:, j, k])
                y = y + weight_k * bk.interp(u["col"], self.cols, hat_c[j]) * line
        return {"y": p["scale"] * y}
