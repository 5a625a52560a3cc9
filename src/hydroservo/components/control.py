"""Control blocks: sums, gains, lags, saturations, PID, the servo amplifier and feedback transducers.

Blocks carry the unit given as ``unit=`` when they are created; without it
they are dimensionless. Blocks whose physics fix a unit (the amplifier's
current, a transducer's input) declare it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import SIGNAL, Component, Option, Output, Param, Port, State, register
from hydroservo.components.signals import SIGNAL_OUTPUT
from hydroservo.errors import ParameterError, UnitError
from hydroservo.laws.orifice import round_port_area, round_port_width
from hydroservo.laws.pressure_valve import valve_hysteresis
from hydroservo.units import coherent_unit, is_absolute_pressure

__all__ = [
    "Sum", "Product", "Quotient", "Absolute", "Power", "Function", "Gain", "Lag", "TransferFunction", "Integrator",
    "Saturation", "DeadZone", "RateLimiter", "Hysteresis", "Latch", "Counter", "Selector", "PID", "Amplifier",
    "Transducer",
]


@register
class Sum(Component):
    """``y = gain1 u1 + gain2 u2 + gain3 u3 + offset`` (unconnected inputs are 0); by default ``u1 - u2 + u3``."""

    RENAMED = {"k1": "gain1", "k2": "gain2", "k3": "gain3"}
    PARAMETERS = {
        **{f"gain{i}": Param(-1.0 if i == 2 else 1.0, "", f"weight of input {i}") for i in (1, 2, 3)},
        "offset": Param(0.0, SIGNAL, "added to the weighted inputs"),
    }
    INPUTS = {f"u{i}": Port(SIGNAL, f"input {i}", default=0.0) for i in (1, 2, 3)}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p["gain1"] * u["u1"] + p["gain2"] * u["u2"] + p["gain3"] * u["u3"] + p["offset"]}


@register
class Product(Component):
    """``y = u1 u2`` of dimensionless signals (an input left unconnected is 1).

    ``unit`` names the product's unit where the factors carry theirs (a torque times a speed: ``unit="W"``)."""

    INPUTS = {"u1": Port("", "factor 1", default=1.0), "u2": Port("", "factor 2", default=1.0)}
    OUTPUTS = {"y": Output(SIGNAL, "product")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": u["u1"] * u["u2"]}


@register
class Quotient(Component):
    """``y = u1 / u2`` of dimensionless signals (a zero divisor gives a non-finite result, which the run reports)."""

    INPUTS = {"u1": Port("", "dividend", default=0.0), "u2": Port("", "divisor", default=1.0)}
    OUTPUTS = {"y": Output("", "quotient")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": u["u1"] / u["u2"]}


@register
class Absolute(Component):
    """``y = |u|``."""

    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.fabs(u["u"])}


@register
class Power(Component):
    """``y = |u|^n`` of a dimensionless signal (Hopsan's SignalPower, [Hopsan2026], takes the magnitude)."""

    PARAMETERS = {"n": Param(2.0, "", "exponent")}
    INPUTS = {"u": Port("", "input")}
    OUTPUTS = {"y": Output("", "|u|^n")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.fabs(u["u"]) ** p["n"]}


#: The functions of :class:`Function` (its option ``function``).
FUNCTIONS = (
    "sqrt", "exp", "log", "log10", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh",
    "square", "sign", "floor", "ceil", "round", "greater", "smaller", "and", "or", "xor", "not", "max", "min",
    "round_port_area", "round_port_width",
)


@register
class Function(Component):
    r"""``y = f(u)`` of a dimensionless signal, ``f`` the function named by option ``function``: Hopsan's math
    blocks ([Hopsan2026] Signal/MathFunctions/SignalSqrt.hpp and the others of that folder;
    Signal/Arithmetics/SignalSquare.hpp and SignalSign.hpp).

    Outside its domain a function gives Hopsan's value and ``error = 1`` (0 inside): :math:`\sqrt{u}` of
    :math:`u < 0` is 0; :math:`\ln u` and :math:`\log_{10} u` of :math:`u \le 0` are 0; :math:`\arcsin` and
    :math:`\arccos` of :math:`|u| > 1` are those of :math:`\pm 1`. The other functions have no domain to leave
    (``error`` is 0). ``atan2`` is the angle of the point ``(u2, u)`` in :math:`(-\pi, \pi]` (Hopsan's inY is
    ``u``, inX ``u2``); ``sign`` is 1 for :math:`u \ge 0` and -1 below, as Hopsan's (not 0 at 0); ``square`` is
    :math:`u^2`. ``floor``, ``ceil`` and ``round`` (half away from zero, C's ``round``) are Hopsan's
    SignalFloor, SignalCeil and SignalRound (Signal/MathFunctions/). The comparisons and logic of Hopsan's
    Signal/Logic/ read two signals and give 1 or 0: ``greater`` :math:`u > u_2` and ``smaller`` :math:`u < u_2`
    (SignalGreaterThan, SignalSmallerThan: ``in`` and ``x_limit``), ``and`` and ``or`` of :math:`u > 0.5` and
    :math:`u_2 > 0.5` (SignalAnd, SignalOr: Hopsan's doubleToBool), ``xor`` of the two (SignalXor) and ``not``
    1 where :math:`u \le 0.5`, else 0 (SignalNot, which reads ``u`` only). ``max`` and ``min`` are
    :math:`\max(u, u_2)` and :math:`\min(u, u_2)` (two inputs of Hopsan's SignalMax and SignalMin,
    Signal/Arithmetics/SignalMax.hpp and SignalMin.hpp). ``round_port_area`` and ``round_port_width`` are the
    opened area and width of a round port of diameter ``u2`` uncovered by ``u``
    (:func:`~hydroservo.laws.orifice.round_port_area`, :func:`~hydroservo.laws.orifice.round_port_width`;
    Hopsan's SignalSegare and SignalDxSegare, Signal/Non-Linearities/, with ``x`` and ``diameter``), 0 and
    ``error = 1`` for a diameter of 0 or less. Where the output or the error jumps or has a
    kink (the domain's edges, the sign's and atan2's jumps at :math:`u = 0`, the tangent's poles, the integers
    or half-integers where floor, ceil and round step, the comparisons' and logic's switching, the crossing of
    ``u`` and ``u2`` of max and min, the port's edges :math:`u = 0` and :math:`u = u_2`), a switch event.
    """

    INPUTS = {
        "u": Port("", "argument"),
        "u2": Port("", "second argument (atan2: the x of the point (u2, u))", default=1.0),
    }
    OUTPUTS = {
        "y": Output("", "f(u)"),
        "error": Output("", "1 where u is outside the function's domain (y is then Hopsan's value there), else 0"),
    }
    OPTIONS = {"function": Option("sqrt", FUNCTIONS, "the function")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        a, f = u["u"], self.option("function")
        error = 0.0 * a
        if f == "sqrt":
            error = bk.if_else(a < 0.0, 1.0, 0.0)
            y = bk.sqrt(bk.fmax(a, 0.0))
        elif f in ("log", "log10"):
            error = bk.if_else(a <= 0.0, 1.0, 0.0)
            law = bk.log if f == "log" else bk.log10
            y = bk.if_else(a <= 0.0, 0.0, law(bk.fmax(a, 1e-300)))
        elif f in ("asin", "acos"):
            error = bk.if_else(bk.fabs(a) > 1.0, 1.0, 0.0)
            y = (bk.asin if f == "asin" else bk.acos)(bk.clip(a, -1.0, 1.0))
        elif f == "atan2":
            y = bk.atan2(a, u["u2"])
        elif f == "square":
            y = a * a
        elif f == "sign":
            y = bk.if_else(a >= 0.0, 1.0, -1.0)
        elif f in ("floor", "ceil"):
            y = bk.floor(a) if f == "floor" else -bk.floor(-a)
        elif f == "round":
            y = bk.if_else(a >= 0.0, bk.floor(a + 0.5), -bk.floor(0.5 - a))
        elif f in ("greater", "smaller"):
            y = bk.if_else(a > u["u2"] if f == "greater" else a < u["u2"], 1.0, 0.0)
        elif f in ("and", "or"):
            both = (a > 0.5) * (u["u2"] > 0.5) if f == "and" else (a > 0.5) + (u["u2"] > 0.5)
            y = bk.if_else(both > 0, 1.0, 0.0)
        elif f == "xor":
            y = bk.fabs(bk.if_else(a > 0.5, 1.0, 0.0) - bk.if_else(u["u2"] > 0.5, 1.0, 0.0))
        elif f == "not":
            y = bk.if_else(a > 0.5, 0.0, 1.0)
        elif f in ("max", "min"):
            y = bk.fmax(a, u["u2"]) if f == "max" else bk.fmin(a, u["u2"])
        elif f in ("round_port_area", "round_port_width"):
            error = bk.if_else(u["u2"] <= 0.0, 1.0, 0.0)
            y = (round_port_area if f == "round_port_area" else round_port_width)(a, u["u2"])
        else:
            y = getattr(bk, f)(a)
        return {"y": y, "error": error}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        a, f = u["u"], self.option("function")
        if f in ("sqrt", "log", "log10", "sign", "atan2"):
            return {"zero": (a, 1.0)}
        if f in ("asin", "acos"):
            return {"upper": (a - 1.0, 1.0), "lower": (a + 1.0, 1.0)}
        if f == "tan":
            return {"pole": (bk.cos(a), 1.0)}
        if f in ("floor", "ceil"):  # the sine of pi u changes sign at each integer
            return {"step": (bk.sin(math.pi * a), 1.0)}
        if f == "round":
            return {"step": (bk.cos(math.pi * a), 1.0)}
        if f in ("greater", "smaller"):
            return {"switch": (a - u["u2"], 1.0)}
        if f in ("and", "or", "xor"):
            return {"switch1": (a - 0.5, 1.0), "switch2": (u["u2"] - 0.5, 1.0)}
        if f == "not":
            return {"switch": (a - 0.5, 1.0)}
        if f in ("max", "min"):
            return {"kink": (a - u["u2"], 1.0)}
        if f in ("round_port_area", "round_port_width"):
            return {"closed": (a, 1.0), "open": (a - u["u2"], 1.0)}
        return {}


def _bound(unit: str, y: str) -> str:
    """A declared unit with the block's signal unit ``y`` (SI) in place of its placeholder, as
    :meth:`Component._bind_signal_unit` binds the declarations (for those an option adds later)."""
    if SIGNAL not in unit:
        return unit
    if y == "":
        return unit.replace(SIGNAL + "/", "1/").replace(SIGNAL + "*", "").replace(SIGNAL, "")
    return unit.replace(SIGNAL, y if y.isidentifier() else f"({y})")


#: Placeholder unit of a gain's input (``input_unit``); the output keeps ``SIGNAL`` (``unit``).
INPUT_SIGNAL = "@in"


class _Gain(Component):
    """A gain ``y = K u`` between two units: ``input_unit`` in, ``unit`` out, the gain in unit/input_unit."""

    #: the name of the gain parameter, and the units taken when none are given
    GAIN = "K"
    DEFAULT_UNITS: tuple[str | None, str | None] = (None, None)

    def __init__(self, name: str, unit: str | None = None, input_unit: str | None = None, **values: Any) -> None:
        default_out, default_in = self.DEFAULT_UNITS
        unit = default_out if unit is None else unit
        self.input_unit = (default_in if input_unit is None else input_unit) if default_in is not None or input_unit is not None else unit
        try:
            super().__init__(name, unit, **values)
        except ParameterError as exc:
            if self.GAIN in values and f"{name}.{self.GAIN}" in str(exc) and "dimension" in str(exc):
                raise ParameterError(
                    f"{exc}; the gain is in unit/input_unit: give both, e.g. "
                    f"{type(self).__name__}({name!r}, unit='V', input_unit='m', {self.GAIN}='20 V/m')"
                ) from None
            raise

    def _bind_signal_unit(self, unit: str) -> None:
        try:
            given = coherent_unit(self.input_unit or "")
        except UnitError:
            raise ParameterError(f"{self.name}.input_unit = {self.input_unit!r}: not a unit") from None
        if is_absolute_pressure(self.input_unit or ""):
            raise ParameterError(
                f"{self.name}.input_unit = {self.input_unit!r}: an absolute pressure is a value, not a signal's unit; "
                "use 'bar' or 'Pa' (signals are gauge pressures)"
            )
        if given == coherent_unit(unit):  # one unit through: the gain is a pure number
            self.PARAMETERS = {  # type: ignore[misc]
                k: replace(v, unit="") if k == self.GAIN else v for k, v in self.PARAMETERS.items()
            }

        def sub(u: str) -> str:
            if u == INPUT_SIGNAL:
                return given
            return u.replace(INPUT_SIGNAL, f"({given})" if given else "1")

        self.PARAMETERS = {k: replace(v, unit=sub(v.unit)) for k, v in self.PARAMETERS.items()}  # type: ignore[misc]
        self.INPUTS = {k: replace(v, unit=sub(v.unit)) for k, v in self.INPUTS.items()}  # type: ignore[misc]
        super()._bind_signal_unit(unit)

    def config(self) -> dict[str, Any]:
        """``input_unit`` when it is not the one the constructor would take without it (model files)."""
        default_in = self.DEFAULT_UNITS[1] if self.DEFAULT_UNITS[1] is not None else self.unit
        return {} if self.input_unit is None or self.input_unit == default_in else {"input_unit": self.input_unit}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": p[self.GAIN] * u["u"]}


@register
class Gain(_Gain):
    """``y = K u``; ``K`` is in unit/input_unit.

    With only ``unit`` given, input and output share it and ``K`` is a pure
    number (``Gain("g", unit="V", K=2)``). To turn one quantity into another,
    give both: ``Gain("k", unit="V", input_unit="m", K="20 V/m")``; the
    connections are then checked in both units.
    """

    RENAMED = {"k": "K"}
    PARAMETERS = {"K": Param(1.0, SIGNAL + "/" + INPUT_SIGNAL, "gain (unit/input_unit)")}
    INPUTS = {"u": Port(INPUT_SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT


@register
class Lag(Component):
    r"""First-order lag :math:`\tau\dot y = K u - y` (an RC network has K = 1, tau = RC)."""

    RENAMED = {"T": "tau"}
    PARAMETERS = {
        "K": Param(1.0, "", "static gain"),
        "tau": Param(0.1, "s", "time constant", min=0.0, min_inclusive=False),
        "y0": Param(0.0, SIGNAL, "initial output"),
    }
    STATES = {"y": State(SIGNAL, "output", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["y"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": (p["K"] * u["u"] - x["y"]) / p["tau"]}


@register
class TransferFunction(Component):
    r"""A transfer function of first or second order,
    :math:`G(s) = (a_2 s^2 + a_1 s + a_0) / (b_2 s^2 + b_1 s + b_0)` (``a_2 = b_2 = 0`` for option ``order = "1"``).

    The continuous law of Hopsan's filters and transfer functions (SignalFirstOrderFilter, SignalHP1Filter,
    SignalLP2Filter, SignalFirstOrderTransferFunction, SignalSecondOrderTransferFunction, [Hopsan2026]
    Signal/Filters/SignalFirstOrderTransferFunction.hpp and the others of that folder), which Hopsan discretises
    by the bilinear transform at its time step. A first-order lag :math:`K/(\tau s + 1)` is :class:`Lag`.

    Realised as :math:`y = d\,u + x_1` with :math:`d = a_n/b_n` (the direct part) and, for the second order,
    :math:`\dot x_1 = x_2 + c_1 u`, :math:`\dot x_2 = -\beta_0 x_1 - \beta_1 x_2 + (c_0 - \beta_1 c_1) u`
    (:math:`\beta_i = b_i/b_2`, :math:`c_i = a_i/b_2 - d\beta_i`); for the first,
    :math:`\dot x_1 = (a_0/b_1 - d\,b_0/b_1) u - (b_0/b_1) x_1`. The states start at :math:`x_1 = y_0`,
    :math:`x_2 = 0`: the output at :math:`y_0 + d\,u(0)`, its strictly proper part at rest with the input at 0,
    as Hopsan's filters start from their output's start value. The coefficients make a dimensionless gain: the output is in the input's unit.
    """

    PARAMETERS = {
        "a0": Param(1.0, "", "numerator coefficient of s^0"),
        "a1": Param(0.0, "s", "numerator coefficient of s^1"),
        "a2": Param(0.0, "s^2", "numerator coefficient of s^2 (order 2)"),
        "b0": Param(1.0, "", "denominator coefficient of s^0"),
        "b1": Param(0.1, "s", "denominator coefficient of s^1"),
        "b2": Param(0.0, "s^2", "denominator coefficient of s^2 (order 2)"),
        "y0": Param(0.0, SIGNAL, "initial output of the strictly proper part (the output with the input at 0)"),
    }
    STATES = {"x1": State(SIGNAL, "output less the direct part d u", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT
    OPTIONS = {"order": Option("1", ("1", "2"), "order of the denominator")}

    def options_changed(self) -> None:
        """The second order has a second state: the rate of x1 less its direct part c1 u."""
        cls = type(self)
        self.STATES = dict(cls.STATES)  # type: ignore[misc]
        if self.option("order") == "2":
            self.STATES["x2"] = State(SIGNAL + "/s", "rate of x1 less its direct part c1 u", nominal=1.0)
        # in the block's unit, as _bind_signal_unit gave the declarations (a run's messages name the states' units)
        y = self.OUTPUTS["y"].unit
        self.STATES = {k: replace(v, unit=_bound(v.unit, y)) for k, v in self.STATES.items()}  # type: ignore[misc]

    def check(self) -> None:
        v = self.values
        if self.option("order") == "1":
            if v["b1"] == 0.0:
                raise ParameterError(f"{self.name}.b1 = 0: a first-order transfer function needs b1 other than 0")
            if v["a2"] != 0.0 or v["b2"] != 0.0:
                raise ParameterError(
                    f"{self.name}: a2 = {v['a2']:g}, b2 = {v['b2']:g} with order = '1': expected 0, or order = '2'"
                )
        elif v["b2"] == 0.0:
            raise ParameterError(f"{self.name}.b2 = 0: a second-order transfer function needs b2 other than 0")

    def _direct(self, p: Mapping[str, Any]) -> Any:
        return p["a2"] / p["b2"] if self.option("order") == "2" else p["a1"] / p["b1"]

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": self._direct(p) * u["u"] + x["x1"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        d = self._direct(p)
        if self.option("order") == "1":
            beta0 = p["b0"] / p["b1"]
            return {"x1": (p["a0"] / p["b1"] - d * beta0) * u["u"] - beta0 * x["x1"]}
        beta0, beta1 = p["b0"] / p["b2"], p["b1"] / p["b2"]
        c0, c1 = p["a0"] / p["b2"] - d * beta0, p["a1"] / p["b2"] - d * beta1
        return {
            "x1": x["x2"] + c1 * u["u"],
            "x2": -beta0 * x["x1"] - beta1 * x["x2"] + (c0 - beta1 * c1) * u["u"],
        }


@register
class Integrator(Component):
    r"""Integrator :math:`\dot y = u`, from ``y0``, without limits (Hopsan's SignalIntegrator2, [Hopsan2026])."""

    PARAMETERS = {"y0": Param(0.0, SIGNAL, "initial output")}
    STATES = {"y": State(SIGNAL, "output", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL + "/s", "input (the output's rate)")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["y"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": u["u"]}


@register
class Saturation(Component):
    """``y = min(max(u, lower), upper)``."""

    PARAMETERS = {"lower": Param(-1.0, SIGNAL, "lower limit"), "upper": Param(1.0, SIGNAL, "upper limit")}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def check(self) -> None:
        if self.values["lower"] >= self.values["upper"]:
            raise ParameterError(
                f"{self.name}.lower = {self.values['lower']:g}: expected below upper = {self.values['upper']:g}"
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.fmin(bk.fmax(u["u"], p["lower"]), p["upper"])}


@register
class DeadZone(Component):
    """``y = u - u_dstart`` below ``u_dstart``, 0 between the two, ``u - u_dend`` above ``u_dend`` (Hopsan's
    SignalDeadZone, [Hopsan2026] Signal/Non-Linearities/SignalDeadZone.hpp, and its names). Continuous, with a
    kink at each edge (a switch event)."""

    PARAMETERS = {
        "u_dstart": Param(-1.0, SIGNAL, "start of the dead zone"),
        "u_dend": Param(1.0, SIGNAL, "end of the dead zone"),
    }
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def check(self) -> None:
        if self.values["u_dstart"] > self.values["u_dend"]:
            raise ParameterError(
                f"{self.name}.u_dstart = {self.values['u_dstart']:g}: expected at most u_dend = {self.values['u_dend']:g}"
            )

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.fmin(u["u"] - p["u_dstart"], 0.0) + bk.fmax(u["u"] - p["u_dend"], 0.0)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"start": (u["u"] - p["u_dstart"], 1.0), "end": (u["u"] - p["u_dend"], 1.0)}


def tracking_time(what: str) -> Param:
    """The time constant ``tau`` with which a block follows Hopsan's step-by-step update of its output (a rate
    limiter's, a hysteresis', a latch's, a counter's): the update's limit as the step vanishes is a jump or a
    kink, which an ODE follows within a few ``tau``. 1 µs by default, far below a servo loop's time scales and
    stiff only for an explicit solver."""
    return Param(1e-6, "s", f"time constant with which {what}", min=0.0, min_inclusive=False)


@register
class RateLimiter(Component):
    r"""The input with its rate limited: the output follows ``u``, but rises at most at ``c_up`` and falls at
    most at ``|c_down|`` (Hopsan's SignalRateLimiter, [Hopsan2026] Signal/Non-Linearities/SignalRateLimiter.hpp).

    Hopsan's block steps its output by ``c Ts`` towards the input, or onto it when the input is nearer than
    that: as the step vanishes, the output follows the input while the input's rate stays within the limits,
    and ramps at the limit otherwise. Here that law is an ODE,
    :math:`\dot y = \min(\max((u - y)/\tau, c_{down}), c_{up})`: the output tracks the input with the time
    constant ``tau`` (a lag of :math:`\tau \dot u` while following; the output's rate settles onto the input's
    within a few ``tau`` after catching up), and ramps at the limit when the input is further than
    :math:`\tau |c|` away. ``tau`` is 1 µs by default: far below the time scales of a servo loop (a 0.25 Hz sine
    of amplitude 1 is followed within 2e-6), and stiff only for an explicit solver. The two switches of the rate
    are switch events. The output starts at ``y0`` (Hopsan's starts at the input's start value).
    """

    PARAMETERS = {
        "c_up": Param(1.0, SIGNAL + "/s", "largest rate of rise", min=0.0),
        "c_down": Param(-1.0, SIGNAL + "/s", "largest rate of fall (negative, as Hopsan's)", max=0.0),
        "tau": tracking_time("the output tracks the input within the limits"),
        "y0": Param(0.0, SIGNAL, "initial output"),
    }
    STATES = {"y": State(SIGNAL, "output", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["y"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.clip((u["u"] - x["y"]) / p["tau"], p["c_down"], p["c_up"])}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        rate = (u["u"] - x["y"]) / p["tau"]
        return {"up": (rate - p["c_up"], 1.0), "down": (rate - p["c_down"], 1.0)}


@register
class Hysteresis(Component):
    r"""Hysteresis (backlash, play): the output stays put while the input moves within half the ``band`` of it,
    and is dragged along at that distance beyond (Hopsan's SignalHysteresis, [Hopsan2026]
    Signal/Non-Linearities/SignalHysteresis.hpp).

    Hopsan's step sets the output to its previous value held within :math:`u \pm y_h/2` (ValveHysteresis'
    ``getValue``, :func:`hydroservo.laws.pressure_valve.valve_hysteresis`): as the step vanishes, the output
    is that play operator of the input. Here that law is an ODE, :math:`\dot y = (\min(\max(y, u - y_h/2),
    u + y_h/2) - y)/\tau`: the output follows the band's edge within a few ``tau`` (1 µs by default, as
    :class:`RateLimiter`'s tracking) and holds exactly inside it. The band's edges reached are switch events. The
    output starts at ``y0`` (Hopsan's at the input's start value).
    """

    PARAMETERS = {
        "band": Param(1.0, SIGNAL, "width of the hysteresis band (y_h)", min=0.0),
        "tau": tracking_time("the output follows the band"),
        "y0": Param(0.0, SIGNAL, "initial output"),
    }
    STATES = {"y": State(SIGNAL, "output", initial="y0", nominal=1.0)}
    INPUTS = {"u": Port(SIGNAL, "input")}
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["y"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": (valve_hysteresis(u["u"], x["y"], 0.5 * p["band"]) - x["y"]) / p["tau"]}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        gap = u["u"] - x["y"]
        return {"upper": (gap - 0.5 * p["band"], 1.0), "lower": (gap + 0.5 * p["band"], 1.0)}


@register
class Latch(Component):
    r"""A set-reset latch: ``Q`` goes to 1 while ``set`` holds and ``reset`` does not, to 0 while ``reset`` holds
    and ``set`` does not (or both), and keeps its value while neither does; ``notQ`` = 1 - ``Q`` (Hopsan's
    SignalSRlatch, [Hopsan2026] Signal/Logic/SignalSRlatch.hpp).

    Hopsan's step sets :math:`Q_n = f(S, R, Q_{n-1})` with
    :math:`f = \lfloor \lfloor S(1 - \lfloor R \rceil) \rceil - \lfloor R(1 - \lfloor S \rceil) \rceil
    + \lfloor Q \lfloor (1 - \lfloor R \rceil)(1 - \lfloor S \rceil) \rceil \rceil \rceil`,
    :math:`\lfloor\cdot\rceil` limiting to [0, 1]; as the step vanishes, :math:`Q` takes the value
    :math:`Q = f(S, R, Q)` at once where the inputs change, and keeps it while they hold. Here that law is an ODE,
    :math:`\dot Q = (f(S, R, Q) - Q)/\tau`: ``Q`` follows within a few ``tau`` (1 µs by default, as
    :class:`RateLimiter`'s tracking), and holds exactly while neither input is set (:math:`f = Q`). Inputs are
    read as Hopsan's formula reads them (not thresholded): 0 and 1 are off and on.
    """

    PARAMETERS = {
        "tau": tracking_time("Q follows the latch's law"),
        "Q0": Param(0.0, "", "initial state", min=0.0, max=1.0),
    }
    STATES = {"Q": State("", "the latch's state", initial="Q0", nominal=1.0)}
    INPUTS = {"set": Port("", "set condition (1: on)", default=0.0), "reset": Port("", "reset condition (1: on)", default=0.0)}
    OUTPUTS = {"Q": Output("", "state"), "notQ": Output("", "1 - state")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"Q": x["Q"], "notQ": 1.0 - x["Q"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        def lim(v: Any) -> Any:
            return bk.clip(v, 0.0, 1.0)

        S, R, Q = u["set"], u["reset"], x["Q"]
        law = lim(lim(S * (1.0 - lim(R))) - lim(R * (1.0 - lim(S))) + lim(Q * lim((1.0 - lim(R)) * (1.0 - lim(S)))))
        return {"Q": (law - Q) / p["tau"]}


@register
class Counter(Component):
    r"""Counts the edges of a logic signal: how often ``u`` has crossed 0.5 upwards (option ``edges = "rising"``),
    downwards (``"falling"``) or either way (``"both"``), from 0 (Hopsan's SignalCounter, [Hopsan2026]
    Signal/Logic/SignalCounter.hpp).

    Hopsan's step reads :math:`b_n = u_n > 0.5` (doubleToBool) and adds 1 where :math:`b_n \ne b_{n-1}` in a
    direction counted, from :math:`b_{-1}` false: as the step vanishes the output is the number of those
    crossings of 0.5 up to :math:`t` (an input above 0.5 at the start is a rising edge, as Hopsan's). Here that law
    is an ODE: the state ``b`` follows the logic value, :math:`\dot b = ([u > 0.5] - b)/\tau`, and the count
    grows by its rate in the directions counted, :math:`\dot n = \max(\dot b, 0)` (rising),
    :math:`\max(-\dot b, 0)` (falling) or :math:`|\dot b|` (both): over an edge ``b`` moves monotonically from
    0 to 1 (1 to 0), which adds exactly 1 once it has settled, within a few ``tau`` (1 µs by default, as
    :class:`Latch`'s). The crossings of 0.5 are switch events.
    """

    PARAMETERS = {
        "tau": tracking_time("b follows the input's logic value"),
    }
    STATES = {
        "b": State("", "the input's logic value, followed (Hopsan's previous value, false at the start)", nominal=1.0),
        "n": State("", "the count", nominal=1.0),
    }
    INPUTS = {"u": Port("", "logic signal (on above 0.5)")}
    OUTPUTS = {"y": Output("", "the count of edges")}
    OPTIONS = {"edges": Option("both", ("both", "rising", "falling"), "which crossings of 0.5 are counted")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": x["n"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        rate = (bk.if_else(u["u"] > 0.5, 1.0, 0.0) - x["b"]) / p["tau"]
        edges = self.option("edges")
        count = bk.fabs(rate) if edges == "both" else bk.fmax(rate if edges == "rising" else -rate, 0.0)
        return {"b": rate, "n": count}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        return {"edge": (u["u"] - 0.5, 1.0)}


@register
class Selector(Component):
    """One of up to four inputs, chosen by ``route``: ``u1`` while ``route < limit12``, ``u2`` while
    ``route < limit23``, ``u3`` while ``route < limit34``, else ``u4`` (Hopsan's SignalDualRoute,
    SignalTripleRoute and SignalQuadRoute, [Hopsan2026] Signal/SignalRouting/SignalQuadRoute.hpp). Unconnected
    inputs are 0; a limit of 1e300 leaves the inputs after it unused."""

    PARAMETERS = {
        "limit12": Param(0.5, "", "route value from which u2 is chosen"),
        "limit23": Param(1.5, "", "route value from which u3 is chosen"),
        "limit34": Param(2.5, "", "route value from which u4 is chosen"),
    }
    INPUTS = {
        **{f"u{i}": Port(SIGNAL, f"input {i}", default=0.0) for i in (1, 2, 3, 4)},
        "route": Port("", "which input: compared with the limits"),
    }
    OUTPUTS = SIGNAL_OUTPUT

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        r = u["route"]
        y = bk.if_else(r < p["limit34"], u["u3"], u["u4"])
        y = bk.if_else(r < p["limit23"], u["u2"], y)
        return {"y": bk.if_else(r < p["limit12"], u["u1"], y)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        r = u["route"]
        return {"limit12": (r - p["limit12"], 1.0), "limit23": (r - p["limit23"], 1.0), "limit34": (r - p["limit34"], 1.0)}


@register
class PID(Component):
    r"""PID controller on the error ``e`` with filtered derivative and clamped output.

    :math:`y = \operatorname{sat}(v)`, :math:`v = K_p e + K_i I + K_d \dot e_f`, where
    :math:`e_f` is ``e`` through a first-order filter of time constant ``T_f``,
    :math:`\dot I = e` and :math:`\operatorname{sat}` limits to [``lower``, ``upper``].
    With option ``derivative = "input"`` the derivative is the input ``de`` instead,
    :math:`v = K_p e + K_i I + K_d\,de` (no filter: the derivative of ``e``, or of what it
    is made of, given by the model).

    The integrator's anti-windup is the option ``anti_windup``:

    * ``conditional`` (default): the integrator stops while the output is saturated and the
      error would drive it further;
    * ``clamping``: the integrator stops whenever the output is saturated,
      :math:`\dot I = e` only while ``lower`` < v < ``upper``: Hopsan's SignalPID and
      SignalPIlead ([Hopsan2026] Signal/Control/SignalPID.hpp, SignalPIlead.hpp, whose
      integrator's input ``Ierr`` is the error times ``dxLimit`` of the limited output: 1
      inside the limits, 1e-9 at them, a numerical remnant of 0);
    * ``tracking`` (back-calculation): :math:`K_i \dot I = K_i e + (\operatorname{sat_t}(v) - v)/T_t`,
      :math:`\operatorname{sat_t}` limiting to [``track_lower``, ``track_upper``], so that the
      integral part is pulled back with the time constant ``T_t`` while :math:`v` is outside
      them (the output is still limited to [``lower``, ``upper``]): Hopsan's SignalPID2
      ([Hopsan2026] Signal/Control/SignalPID2.hpp, whose explicit step
      :math:`I \mathrel{+}= T_s/T_t (U_{max} - v)` is that law's Euler step). Needs ``Ki`` > 0.

    The switches of the anti-windup are switch events.
    """

    PARAMETERS = {
        "Kp": Param(1.0, "", "proportional gain"),
        "Ki": Param(0.0, "1/s", "integral gain"),
        "Kd": Param(0.0, "s", "derivative gain"),
        "T_f": Param(1e-3, "s", "derivative filter time constant", min=0.0, min_inclusive=False),
        "lower": Param(-1e30, SIGNAL, "output lower limit"),
        "upper": Param(1e30, SIGNAL, "output upper limit"),
        "T_t": Param(1.0, "s", "tracking time constant (anti_windup = tracking)", min=0.0, min_inclusive=False),
        "track_lower": Param(-1e30, SIGNAL, "lower limit the integral tracks (anti_windup = tracking)"),
        "track_upper": Param(1e30, SIGNAL, "upper limit the integral tracks (anti_windup = tracking)"),
    }
    STATES = {
        "I": State(SIGNAL + "*s", "integral of the error", nominal=1.0),
        "e_f": State(SIGNAL, "filtered error (for the derivative)", nominal=1.0),
    }
    INPUTS = {"e": Port(SIGNAL, "error")}
    OUTPUTS = SIGNAL_OUTPUT
    OPTIONS = {
        "anti_windup": Option(
            "conditional", ("conditional", "clamping", "tracking"), "how the integrator stops winding up at the limits"
        ),
        "derivative": Option("filtered", ("filtered", "input"), "the derivative: e through the filter T_f, or input de"),
    }

    def options_changed(self) -> None:
        """With the derivative an input, the input ``de`` and no filter state."""
        cls = type(self)
        if self.option("derivative") == "input":
            self.STATES = {"I": cls.STATES["I"]}  # type: ignore[misc]
            self.INPUTS = {**cls.INPUTS, "de": Port(SIGNAL + "/s", "derivative of the error (derivative = input)")}  # type: ignore[misc]
        else:
            self.STATES, self.INPUTS = dict(cls.STATES), dict(cls.INPUTS)  # type: ignore[misc]
        # the block's unit, as _bind_signal_unit gave the declarations
        self.STATES = {k: replace(v, unit=self._unit(v.unit)) for k, v in self.STATES.items()}  # type: ignore[misc]
        self.INPUTS = {k: replace(v, unit=self._unit(v.unit)) for k, v in self.INPUTS.items()}  # type: ignore[misc]

    def _unit(self, unit: str) -> str:
        return _bound(unit, self.OUTPUTS["y"].unit)

    def check(self) -> None:
        if self.option("anti_windup") == "tracking" and self.values["Ki"] <= 0.0:
            raise ParameterError(f"{self.name}.Ki = {self.values['Ki']:g} 1/s: anti_windup = tracking needs Ki > 0")

    def _raw(self, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        deriv = u["de"] if self.option("derivative") == "input" else (u["e"] - x["e_f"]) / p["T_f"]
        return p["Kp"] * u["e"] + p["Ki"] * x["I"] + p["Kd"] * deriv

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"y": bk.fmin(bk.fmax(self._raw(x, u, p), p["lower"]), p["upper"])}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        raw = self._raw(x, u, p)
        e = u["e"]
        mode = self.option("anti_windup")
        if mode == "tracking":
            rate = e + (bk.fmin(bk.fmax(raw, p["track_lower"]), p["track_upper"]) - raw) / (p["Ki"] * p["T_t"])
        elif mode == "clamping":
            rate = bk.if_else((raw > p["lower"]) * (raw < p["upper"]) > 0, e, 0.0)
        else:
            windup = ((raw > p["upper"]) * (e * p["Ki"] > 0)) + ((raw < p["lower"]) * (e * p["Ki"] < 0))
            rate = bk.if_else(windup > 0, 0.0, e)
        rates = {"I": rate}
        if self.option("derivative") != "input":
            rates["e_f"] = (e - x["e_f"]) / p["T_f"]
        return rates

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        if self.option("anti_windup") == "conditional":
            return {}
        raw = self._raw(x, u, p)
        lo, hi = ("track_lower", "track_upper") if self.option("anti_windup") == "tracking" else ("lower", "upper")
        return {"lower": (raw - p[lo], 1.0), "upper": (raw - p[hi], 1.0)}


@register
class Amplifier(Component):
    r"""Servo amplifier: voltage to current, :math:`I = \operatorname{sat}(G_a E / R)`.

    [FlightSimulatorND] eq. (3-37): :math:`I_s = 10^3 G_a E_o / R_v` in mA; the factor
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
        return {"i": bk.fmin(bk.fmax(i, -p["I_max"]), p["I_max"])}


@register
class Transducer(_Gain):
    """Feedback transducer, ``y = G u``: by default a position in metres to volts (a potentiometer in V/m).

    ``unit`` and ``input_unit`` make it any other sensor: a pressure
    transducer is ``Transducer("pt", unit="V", input_unit="bar", G="0.04 V/bar")``
    (or ``unit="mA"`` for a current loop).
    """

    GAIN = "G"
    DEFAULT_UNITS = ("V", "m")
    PARAMETERS = {"G": Param(1.0, SIGNAL + "/" + INPUT_SIGNAL, "transducer gain (unit/input_unit)")}
    INPUTS = {"u": Port(INPUT_SIGNAL, "measured quantity")}
    OUTPUTS = {"y": Output(SIGNAL, "transducer signal")}
