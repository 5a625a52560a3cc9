"""Signal sources and control blocks.

Signal blocks carry the unit given as ``unit=`` when they are created
(``Step("vi", unit="V", amplitude="2 V")``); without it they are
dimensionless. Blocks whose physics fix a unit (the amplifier's current, a
transducer's input) declare it.
"""

from __future__ import annotations

import csv
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo import _math as m
from hydroservo.components.base import SIGNAL, Component, Output, Param, Port, State, register
from hydroservo.errors import ParameterError

__all__ = [
    "Step",
    "Ramp",
    "Sine",
    "Square",
    "Table",
    "Sum",
    "Gain",
    "Lag",
    "Saturation",
    "PID",
    "Amplifier",
    "Transducer",
]

_OUT = {"y": Output(SIGNAL, "signal")}


@register
class Step(Component):
    """Step: ``offset`` before ``t_step``, ``offset + amplitude`` from ``t_step`` on."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "step height"),
        "t_step": Param(0.0, "s", "time of the step", min=0.0),
        "offset": Param(0.0, SIGNAL, "value before the step"),
    }
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["offset"] + m.if_else(t >= p["t_step"], p["amplitude"], 0.0)}


@register
class Ramp(Component):
    """Ramp of ``slope`` per second from ``t_start`` on, limited to ``limit`` in magnitude of change."""

    PARAMETERS = {
        "slope": Param(1.0, SIGNAL + "/s", "rate of change"),
        "t_start": Param(0.0, "s", "start time", min=0.0),
        "limit": Param(1e30, SIGNAL, "largest change from the offset", min=0.0),
        "offset": Param(0.0, SIGNAL, "initial value"),
    }
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        change = p["slope"] * m.fmax(t - p["t_start"], 0.0)
        change = m.fmin(m.fmax(change, -p["limit"]), p["limit"])
        return {"y": p["offset"] + change}


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
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tau = t - p["t_start"]
        wave = p["amplitude"] * m.sin(2 * np.pi * p["frequency"] * tau + p["phase"])
        return {"y": p["offset"] + m.if_else(tau >= 0, wave, 0.0)}


@register
class Square(Component):
    """Square wave of ``amplitude`` about ``offset``, positive first half-period, from ``t_start`` on."""

    PARAMETERS = {
        "amplitude": Param(1.0, SIGNAL, "amplitude"),
        "frequency": Param(1.0, "Hz", "frequency", min=0.0, min_inclusive=False),
        "t_start": Param(0.0, "s", "start time", min=0.0),
        "offset": Param(0.0, SIGNAL, "offset"),
    }
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        tau = t - p["t_start"]
        phase = tau * p["frequency"]
        frac = phase - m.floor(phase)
        wave = m.if_else(frac < 0.5, p["amplitude"], -p["amplitude"])
        return {"y": p["offset"] + m.if_else(tau >= 0, wave, 0.0)}


@register
class Table(Component):
    """Signal from a time table, linear between points, held outside.

    Give ``times`` and ``values`` lists, or ``file``: a CSV whose first column
    is time in seconds and whose column ``column`` (default: the second) holds
    the values.
    """

    PARAMETERS = {"scale": Param(1.0, "", "factor applied to the values")}
    OUTPUTS = _OUT

    def __init__(
        self,
        name: str,
        times: Any = None,
        values: Any = None,
        file: str | Path | None = None,
        column: str | int = 1,
        **params: Any,
    ) -> None:
        super().__init__(name, **params)
        self.file = None if file is None else str(file)
        self.column = column
        if file is not None:
            times, values = _read_table(Path(file), column, name)
        if times is None or values is None:
            raise ParameterError(f"{name}: a Table needs times and values, or a CSV file")
        t = np.asarray(times, dtype=float).ravel()
        v = np.asarray(values, dtype=float).ravel()
        if t.size == 0 or t.size != v.size:
            raise ParameterError(
                f"{name}: times and values must be equally long and non-empty; got {t.size} and {v.size}"
            )
        if np.any(np.diff(t) <= 0):
            raise ParameterError(f"{name}.times: expected strictly increasing times [s]")
        self.times, self.table_values = t, v

    def config(self) -> dict[str, Any]:
        if self.file is not None:
            return {"file": self.file, "column": self.column}
        return {"times": self.times.tolist(), "values": self.table_values.tolist()}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["scale"] * m.interp(t, self.times, self.table_values)}


def _read_table(path: Path, column: str | int, name: str) -> tuple[np.ndarray, np.ndarray]:
    try:
        with path.open(newline="") as fh:
            rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    except OSError as exc:
        raise ParameterError(f"{name}.file: cannot read {str(path)!r}: {exc.strerror}") from None
    if not rows:
        raise ParameterError(f"{name}.file: {str(path)!r} is empty")
    header = rows[0]
    try:
        float(header[0])
        data, names = rows, None
    except ValueError:
        data, names = rows[1:], [h.strip() for h in header]
    if isinstance(column, str):
        if names is None or column not in names:
            raise ParameterError(f"{name}.column: {column!r} is not a column of {str(path)!r}; columns: {names}")
        col = names.index(column)
    else:
        col = int(column)
    try:
        arr = np.array([[float(r[0]), float(r[col])] for r in data])
    except (ValueError, IndexError):
        raise ParameterError(
            f"{name}.file: {str(path)!r} needs numbers in column 0 (time, s) and column {col}"
        ) from None
    return arr[:, 0], arr[:, 1]


@register
class Sum(Component):
    """``y = k1 u1 + k2 u2 + k3 u3`` (unconnected inputs are 0)."""

    PARAMETERS = {
        f"k{i}": Param(1.0 if i == 1 else -1.0 if i == 2 else 1.0, "", f"weight of input {i}") for i in (1, 2, 3)
    }
    INPUTS = {f"u{i}": Port(SIGNAL, f"input {i}", default=0.0) for i in (1, 2, 3)}
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["k1"] * u["u1"] + p["k2"] * u["u2"] + p["k3"] * u["u3"]}


@register
class Gain(Component):
    """``y = k u``."""

    PARAMETERS = {"k": Param(1.0, "", "gain")}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["k"] * u["u"]}


@register
class Lag(Component):
    r"""First-order lag :math:`T\dot y = K u - y` (an RC network has K = 1, T = RC)."""

    PARAMETERS = {
        "K": Param(1.0, "", "static gain"),
        "T": Param(0.1, "s", "time constant", min=0.0, min_inclusive=False),
        "y0": Param(0.0, SIGNAL, "initial output"),
    }
    STATES = {"y": State(SIGNAL, "output", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = _OUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["y"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": (p["K"] * u["u"] - x["y"]) / p["T"]}


@register
class Saturation(Component):
    """``y = min(max(u, lower), upper)``."""

    PARAMETERS = {"lower": Param(-1.0, SIGNAL, "lower limit"), "upper": Param(1.0, SIGNAL, "upper limit")}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = _OUT

    def check(self) -> None:
        if self.values["lower"] >= self.values["upper"]:
            raise ParameterError(
                f"{self.name}.lower = {self.values['lower']:g}: expected below upper = {self.values['upper']:g}"
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": m.fmin(m.fmax(u["u"], p["lower"]), p["upper"])}


@register
class PID(Component):
    r"""PID controller on the error ``e`` with filtered derivative and clamped output.

    :math:`y = \operatorname{sat}(K_p e + K_i \int e\,dt + K_d \dot e_f)`, where
    :math:`e_f` is ``e`` through a first-order filter of time constant ``T_f``.
    The integrator stops integrating while the output is saturated and the
    error would drive it further (conditional integration anti-windup).
    """

    PARAMETERS = {
        "Kp": Param(1.0, "", "proportional gain"),
        "Ki": Param(0.0, "1/s", "integral gain"),
        "Kd": Param(0.0, "s", "derivative gain"),
        "T_f": Param(1e-3, "s", "derivative filter time constant", min=0.0, min_inclusive=False),
        "lower": Param(-1e30, SIGNAL, "output lower limit"),
        "upper": Param(1e30, SIGNAL, "output upper limit"),
    }
    STATES = {
        "I": State(SIGNAL + "*s", "integral of the error", nominal=1.0),
        "e_f": State(SIGNAL, "filtered error (for the derivative)", nominal=1.0),
    }
    INPUTS = {"e": Port(SIGNAL, "error")}
    OUTPUTS = _OUT

    def _raw(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        deriv = (u["e"] - x["e_f"]) / p["T_f"]
        return p["Kp"] * u["e"] + p["Ki"] * x["I"] + p["Kd"] * deriv

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": m.fmin(m.fmax(self._raw(x, u, p), p["lower"]), p["upper"])}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        raw = self._raw(x, u, p)
        e = u["e"]
        windup = ((raw > p["upper"]) * (e * p["Ki"] > 0)) + ((raw < p["lower"]) * (e * p["Ki"] < 0))
        return {"I": m.if_else(windup > 0, 0.0, e), "e_f": (e - x["e_f"]) / p["T_f"]}


@register
class Amplifier(Component):
    r"""Servo amplifier: voltage to current, :math:`I = \operatorname{sat}(G_a E / R)`.

    Seed 003 eq. (3-37): :math:`I_s = 10^3 G_a E_o / R_v` in mA; the factor
    :math:`10^3` is the ampere-to-milliampere conversion (SI here, so it
    disappears). The body of the dissertation prints 10; the model summary of
    section 4.2 and pot P90 of Appendix D (0.65, reproduced only with 10^3)
    use 10^3.
    """

    PARAMETERS = {
        "G_a": Param(1.0, "", "forward gain", min=0.0),
        "R": Param(100.0, "ohm", "resistance of valve coil and circuit", min=0.0, min_inclusive=False),
        "I_max": Param(1.0, "A", "current limit", min=0.0, min_inclusive=False),
    }
    INPUTS = {"E": Port("V", "input voltage")}
    OUTPUTS = {"i": Output("A", "coil current")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        i = p["G_a"] * u["E"] / p["R"]
        return {"i": m.fmin(m.fmax(i, -p["I_max"]), p["I_max"])}


@register
class Transducer(Component):
    """Feedback transducer, ``y = G u`` (e.g. a potentiometer in V/m)."""

    PARAMETERS = {"G": Param(1.0, "V/m", "transducer gain")}
    INPUTS = {"u": Port("m", "measured quantity")}
    OUTPUTS = {"y": Output("V", "transducer signal")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["G"] * u["u"]}
