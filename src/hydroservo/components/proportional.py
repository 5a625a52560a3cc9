r"""Servo-solenoid (high-performance proportional) valve of seed 000.

Two decoupled blocks in series (seed 000 section 2): the spool dynamics of the
valve with its controller card (:class:`SpoolRateLimited`, Fig. 11), and the
static flow model with pseudo-sections (:class:`PseudoSectionValve`, eqs. 1-3,
24, 33). :class:`ServoSolenoidValve` is both in one component, input
:math:`u \in [-1, 1]`.

Spool dynamics (Fig. 11, re-derived)
------------------------------------
The figure is a second-order loop drawn with its velocity and acceleration as
signals, so that each can be limited:

.. math::
    v_d = \frac{\omega_n}{2\xi}(u - s), \quad
    v_l = \frac{2L_v}{\pi}\arctan\frac{\pi v_d}{2L_v}, \quad
    \dot v = \operatorname{sat}_{L_a}\bigl(2\xi\omega_n (v_l - v)\bigr), \quad
    \dot s = v

Without limits this is :math:`\ddot s = \omega_n^2(u - s) - 2\xi\omega_n\dot s`.
Both limiters have unit gain at the origin, as the paper requires: the
velocity limiter is the arctangent shape bounded by :math:`\pm L_v` (the
paper's best choice, "in action from small velocities"), the acceleration
limiter a hard saturation at :math:`\pm L_a`. The spool position then passes
a pure delay :math:`\Delta t` (section 6.2).

A pure delay is not an ordinary differential equation; in a system it is
replaced by its (2, 2) Padé approximant (option ``delay = "pade2"``, the
default; ``"pade1"`` or ``"none"`` also). Its gain is exactly one; its phase,
:math:`-2\arctan\frac{\omega\Delta t/2}{1 - (\omega\Delta t)^2/12}`, is within
0.06 deg of the delay's at 200 Hz and 0.4 deg at 300 Hz for the published 0.76 ms. Frequency-response
analysis (:mod:`hydroservo.analysis.frequency`) applies the delay exactly, as
a phase :math:`-\omega\Delta t`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import _math as m
from hydroservo import pseudo_sections as ps
from hydroservo.components.base import Component, Option, Output, Param, Port, State, register
from hydroservo.errors import ParameterError
from hydroservo.parameters.ferreira_000 import DYNAMICS, FIXED, VARIABLE
from hydroservo.units import to_si

__all__ = ["SpoolRateLimited", "PseudoSectionValve", "ServoSolenoidValve", "rate_limited_spool"]


def rate_limited_spool(u: Any, s: Any, v: Any, omega_n: Any, zeta: Any, L_v: Any, L_a: Any) -> Any:
    r"""Spool acceleration of seed 000 Fig. 11 [1/s^2] (see the module docstring).

    Parameters
    ----------
    u : array_like
        Normalised command [-].
    s, v : array_like
        Normalised spool position [-] and velocity [1/s].
    omega_n : array_like
        Natural angular frequency [rad/s].
    zeta : array_like
        Damping ratio (the paper's :math:`\xi`) [-].
    L_v : array_like
        Velocity limit [1/s].
    L_a : array_like
        Acceleration limit [1/s^2].
    """
    v_d = omega_n / (2.0 * zeta) * (u - s)
    v_l = 2.0 * L_v / np.pi * m.atan(np.pi * v_d / (2.0 * L_v))
    return m.fmin(m.fmax(2.0 * zeta * omega_n * (v_l - v), -L_a), L_a)


def _si(values: Mapping[str, Any], units: Mapping[str, str]) -> dict[str, float]:
    return {k: to_si(v, units[k], what=k) for k, v in values.items()}


_DYN = _si(DYNAMICS, {"omega_n": "rad/s", "zeta": "", "L_v": "1/s", "L_a": "1/s^2", "delay": "s"})
_VAR = _si(VARIABLE, ps.PARAMETER_UNITS)
_FIX = _si(FIXED, ps.PARAMETER_UNITS)

_DELAY_STATES = {
    "none": {},
    "pade1": {"w1": State("", "Padé (1,1) state of the delay", initial="s0", nominal=1.0)},
    "pade2": {
        "w1": State("", "Padé (2,2) state of the delay", initial="s0", nominal=1.0),
        "w2": State("1/s", "Padé (2,2) state of the delay (rate)", nominal=100.0),
    },
}


@register
class SpoolRateLimited(Component):
    """Spool position of a servo-solenoid valve with its card: seed 000 Fig. 11, then a delay.

    Defaults: the KBSDG4V-3 fit of seed 000 section 6 (omega_n = 1007 rad/s,
    xi = 0.48, L_v = 125 1/s, L_a = 81184 1/s^2, delay 0.7625 ms). The command
    is saturated to [-1, 1] and the delivered position clipped to the stroke.
    """

    PARAMETERS = {
        "omega_n": Param(_DYN["omega_n"], "rad/s", "natural angular frequency", min=0.0, min_inclusive=False),
        "zeta": Param(_DYN["zeta"], "", "damping ratio (xi in seed 000)", min=0.0, min_inclusive=False),
        "L_v": Param(_DYN["L_v"], "1/s", "velocity limit (arctangent limiter)", min=0.0, min_inclusive=False),
        "L_a": Param(_DYN["L_a"], "1/s^2", "acceleration limit (hard saturation)", min=0.0, min_inclusive=False),
        "delay": Param(_DYN["delay"], "s", "pure delay of the spool position", min=0.0),
        "s0": Param(0.0, "", "initial normalised spool position", min=-1.0, max=1.0),
    }
    STATES = {
        "s": State("", "normalised spool position before the delay", initial="s0", nominal=1.0),
        "v": State("1/s", "normalised spool velocity", nominal=100.0),
        **_DELAY_STATES["pade2"],
    }
    INPUTS = {"u": Port("", "normalised command, -1 to 1")}
    OUTPUTS = {"xs": Output("", "normalised spool position, delayed"), "vs": Output("1/s", "spool velocity")}
    OPTIONS = {
        "delay_model": Option("pade2", ("pade2", "pade1", "none"), "how the pure delay is approximated in time"),
    }

    def set_option(self, key: str, value: Any) -> None:
        super().set_option(key, value)
        if key == "delay_model":
            base = {k: v for k, v in self.STATES.items() if not k.startswith("w")}
            self.STATES = {**base, **_DELAY_STATES[str(value)]}  # type: ignore[misc]

    def check(self) -> None:
        if self.option("delay_model") != "none" and self.values["delay"] <= 0:
            raise ParameterError(
                f"{self.name}.delay = {self.values['delay']:g} s with delay_model = "
                f"{self.option('delay_model')!r}: expected a positive delay, or delay_model = 'none'"
            )

    def _delayed(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        mode = self.option("delay_model")
        if mode == "none":
            return x["s"]
        if mode == "pade1":
            return 2.0 * x["w1"] - x["s"]
        return x["s"] - p["delay"] * x["w2"]  # s - 2a w', a = delay/2

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xs": m.fmin(m.fmax(self._delayed(x, p), -1.0), 1.0), "vs": x["v"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        cmd = m.fmin(m.fmax(u["u"], -1.0), 1.0)
        acc = rate_limited_spool(cmd, x["s"], x["v"], p["omega_n"], p["zeta"], p["L_v"], p["L_a"])
        der = {"s": x["v"], "v": acc}
        mode = self.option("delay_model")
        a = p["delay"] / 2.0
        if mode == "pade1":  # (1 - a s)/(1 + a s)
            der["w1"] = (x["s"] - x["w1"]) / a
        elif mode == "pade2":  # (1 - a s + b s^2)/(1 + a s + b s^2), b = delay^2/12
            b = p["delay"] ** 2 / 12.0
            der["w1"] = x["w2"]
            der["w2"] = (x["s"] - x["w1"] - a * x["w2"]) / b
        return der


_SECTION_PARAMS = {
    "k": Param(
        _VAR["k"], "", "variable structure: relative pressure gain at null (eq. 26)", min=0.0, min_inclusive=False
    ),
    "gamma": Param(_VAR["gamma"], "m^3/s/Pa^0.5", "variable structure: section at null (eq. 29)", min=0.0),
    "alpha": Param(_VAR["alpha"], "m^3/s/Pa^0.5", "variable structure: slope of the outer part", min=0.0),
    "beta": Param(_VAR["beta"], "m^3/s/Pa^0.5", "variable structure: intercept of the outer part"),
    "x_t": Param(
        _VAR["x_t"],
        "",
        "variable structure: transition point",
        min=0.0,
        max=1.0,
        min_inclusive=False,
        max_inclusive=False,
    ),
    "k1": Param(_FIX["k1"], "m^3/s/Pa^0.5", "fixed structure k1 (eq. 33)"),
    "k2": Param(_FIX["k2"], "m^3/s/Pa^0.5", "fixed structure k2"),
    "k3": Param(_FIX["k3"], "m^6/s^2/Pa", "fixed structure k3", min=0.0),
    "k4": Param(_FIX["k4"], "m^6/s^2/Pa", "fixed structure k4"),
    "k5": Param(_FIX["k5"], "m^6/s^2/Pa", "fixed structure k5", min=0.0),
    "p_tr": Param(1e4, "Pa", "regularisation pressure of the square root (numerical only)", min=0.0),
}
_PRESSURE_PORTS = {
    "pS": Port("Pa", "supply pressure"),
    "pT": Port("Pa", "tank pressure", default=0.0),
    "pA": Port("Pa", "pressure in line A (port 1)"),
    "pB": Port("Pa", "pressure in line B (port 2)"),
}
_FLOW_OUTPUTS = {
    "QA": Output("m^3/s", "flow out of port A (port 1) into line A"),
    "QB": Output("m^3/s", "flow out of port B (port 2) into line B"),
    "QS": Output("m^3/s", "flow drawn from supply"),
    "QT": Output("m^3/s", "flow returned to tank"),
}
_STRUCTURE = Option("variable", ps.STRUCTURES, "pseudo-section family: eq. (24) variable or eq. (33) fixed")


def _section_flows(xs: Any, u: Mapping[str, Any], p: Mapping[str, Any], structure: str) -> dict[str, Any]:
    x = m.fmin(m.fmax(xs, -1.0), 1.0)
    params = {n: p[n] for n in ps.PARAMETER_NAMES[structure]}
    A_p, A_n = ps.pseudo_sections(x, structure, params)
    A_p, A_n = m.fmax(A_p, 0.0), m.fmax(A_n, 0.0)  # rounding-level negatives (see check_sections)
    QA, QB, QS, QT = ps.matched_valve_flows(A_p, A_n, u["pS"], u["pT"], u["pA"], u["pB"], p["p_tr"])
    return {"QA": QA, "QB": QB, "QS": QS, "QT": QT}


def _check_structure(comp: Component) -> None:
    structure = comp.option("structure")
    params = {n: comp.values[n] for n in ps.PARAMETER_NAMES[structure]}
    try:
        ps.check_sections(structure, params)
    except ParameterError as exc:
        raise ParameterError(f"{comp.name}: {exc}") from None


@register
class PseudoSectionValve(Component):
    """Matched, symmetrical four-way valve with pseudo-sections (seed 000 eqs. 1-3, 24, 33).

    Input: the normalised spool position ``xs`` (clipped to [-1, 1]); port A
    is the paper's port 1 (opened to supply for ``xs > 0``). Parameters of both
    structures are declared; option ``structure`` selects which are used.
    Defaults: the published KBSDG4V-3 sets. Fit your own with
    :func:`hydroservo.identification.fit_datasheet`.

    The square root of eq. (1) is regularised below ``p_tr`` (default 0.1 bar)
    only so that implicit solvers have a finite Jacobian at zero drop; the
    laminar region is in the pseudo-sections, as in the paper.
    """

    PARAMETERS = dict(_SECTION_PARAMS)
    INPUTS = {"xs": Port("", "normalised spool position, -1 to 1"), **_PRESSURE_PORTS}
    OUTPUTS = dict(_FLOW_OUTPUTS)
    OPTIONS = {"structure": _STRUCTURE}

    def check(self) -> None:
        _check_structure(self)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return _section_flows(u["xs"], u, p, self.option("structure"))


@register
class ServoSolenoidValve(SpoolRateLimited):
    """Complete servo-solenoid valve of seed 000: :class:`SpoolRateLimited` then :class:`PseudoSectionValve`.

    Input the normalised command ``u`` in [-1, 1] and the port pressures;
    outputs the four flows and the spool position ``xs``. Defaults: the
    published KBSDG4V-3 (variable structure).
    """

    PARAMETERS = {**SpoolRateLimited.PARAMETERS, **_SECTION_PARAMS}
    INPUTS = {**SpoolRateLimited.INPUTS, **_PRESSURE_PORTS}
    OUTPUTS = {**SpoolRateLimited.OUTPUTS, **_FLOW_OUTPUTS}
    OPTIONS = {**SpoolRateLimited.OPTIONS, "structure": _STRUCTURE}

    def check(self) -> None:
        super().check()
        _check_structure(self)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out = super().output_equations(t, x, u, p)
        return {**out, **_section_flows(out["xs"], u, p, self.option("structure"))}
