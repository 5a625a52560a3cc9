r"""Components replaced by their linearisation about an operating point: the rungs of a fidelity ladder.

[Efe2014] derives from the nonlinear drive (eqs. 4.1-4.4) a *linearised*
model (section 4.3, eqs. 4.5-4.14: the valve's flows by their tangent at the
operating point :math:`P_0`, the chambers' volumes and bulk moduli frozen
there) and a *simplified* one in the load pressure (section 4.4, eqs.
4.15-4.23), each also with *parameter feedback* (sections 4.3.3, 4.4.1: the
coefficients re-evaluated from the current state as the run goes). In general
form, for any component:

* :class:`Linearized` replaces the component's outputs and state rates
  :math:`g(z)`, :math:`z` its states and inputs, by
  :math:`g(z_a) + J(\zeta)(z - z_a)`, with :math:`J = \partial g/\partial z`
  evaluated at :math:`\zeta = z_0` (``coefficients = "frozen"``) or at the
  current :math:`\zeta = z` (``"feedback"``). The anchor :math:`z_a` is the
  operating point :math:`z_0`, except for the inputs named ``null``, taken
  at zero, whose coefficient is the secant from zero rather than the
  tangent: for a valve's spool position the linearised valve is
  :math:`Q = Q(0, p_0) + \bar K_{Qx} x_v + K_{Qp}(p - p_0)` with
  :math:`\bar K_{Qx} = (Q(x_{v0}, p_0) - Q(0, p_0))/x_{v0}`, the form of
  [Efe2014] eqs. 4.6-4.13 (and of [Merritt1967]'s :math:`Q_L = K_q x_v - K_c p_L`).
  It passes through the valve's null, so a shut valve passes no operating
  flow, and through the operating point. For a zero-lapped valve the secant
  is the tangent :math:`K_{Qx}` of eq. 4.8 (the flow is proportional to the
  opening); for an overlapped one it is the effective gain
  :math:`c_v (x_{v0} - x_o)/x_{v0}\,\sqrt{\Delta p}`. With the plain tangent
  an overlapped valve linearised at an opening would pass
  :math:`-c_v x_o\sqrt{\Delta p}` when shut, and with the tangent through
  the null it would overstate the flow at the operating point by
  :math:`x_o/(x_{v0} - x_o)`. For a cylinder at a steady
  operating point the net flow into each chamber is zero, so the frozen
  tangent of :math:`\dot p = (E'(p)/V(x))\,N` is exactly
  :math:`(E'_0/V_0)\,\Delta N`: eq. 4.13's frozen volumes and bulk moduli.
  With feedback the tangent differs from Efe's update (current :math:`E'/V`
  times the flow's tangent) by :math:`N\,\partial(E'/V)/\partial z\cdot\Delta z`,
  which vanishes where the pressures are steady.
* :class:`LoadPressureCylinder` is a linearised cylinder with one state, the
  load pressure :math:`p_L = p_A - \alpha p_B` (eq. 4.17), its chamber
  pressures reconstructed by eqs. 4.15-4.16,
  :math:`\Delta p_A = \Delta p_L/(1 + \alpha^3)`,
  :math:`\Delta p_B = -\alpha^2\Delta p_L/(1 + \alpha^3)`, and
  :math:`\dot p_L = \dot p_A - \alpha\dot p_B` (eq. 4.18) from the
  linearised chamber equations. With the valve linearised too this is eq.
  4.19 with the coefficients of eqs. 4.20-4.22 (re-derived:
  docs/robot_arm.md).

The inner component keeps its parameters (they stay symbolic: a batch may
vary them), ports and signals; only its equations change.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping
from typing import Any

import casadi as ca

from hydroservo.components.base import REGISTRY, Component, Option, State, register
from hydroservo.errors import ModelError, ParameterError

__all__ = ["Linearized", "LoadPressureCylinder"]

MODES = ("frozen", "feedback")


def _inner(inner: Component | Mapping[str, Any], name: str) -> Component:
    """The wrapped component: an instance (copied), or a table ``{type, parameters, options, config}``."""
    if isinstance(inner, Component):
        return copy.deepcopy(inner)
    spec = dict(inner)
    cls = REGISTRY.resolve(str(spec.pop("type", "")))
    if cls is None:
        raise ParameterError(f"{name}.inner: expected a component table with a known 'type'")
    return cls(name, **spec)


class _Taylor(Component):
    """Shared machinery: the inner component's equations expanded about ``point`` (its states and inputs, SI)."""

    OPTIONS = {"coefficients": Option("frozen", MODES, "coefficients at the operating point, or from the current state")}

    def __init__(
        self, name: str, inner: Component | Mapping[str, Any], point: Mapping[str, float], null: Any = (), **values: Any
    ) -> None:
        self.inner = _inner(inner, name)
        if self.inner.ALGEBRAIC:
            raise ModelError(f"{name}: {type(self.inner).__name__} has algebraic unknowns; it cannot be linearised alone")
        # the inner's declarations, as this instance's own
        self.PARAMETERS = dict(self.inner.PARAMETERS)  # type: ignore[misc]
        self.INPUTS = dict(self.inner.INPUTS)  # type: ignore[misc]
        self.OUTPUTS = dict(self.inner.OUTPUTS)  # type: ignore[misc]
        self.HYDRAULIC = dict(self.inner.HYDRAULIC)  # type: ignore[misc]
        self.STATES = dict(self.inner.STATES)  # type: ignore[misc]
        # the physical bounds stay watched: a linear model that drives a piston through its stop is flagged
        self.LIMITS = dict(self.inner.LIMITS)  # type: ignore[misc]
        super().__init__(name)
        self.values = dict(self.inner.values)  # the inner's values, then any given here (a model file's edits)
        self.given = dict(self.inner.given)
        self.explicit = set(self.inner.explicit)
        self.set(**values)
        wanted = [*self.inner.STATES, *self.inner.INPUTS]
        missing = [k for k in wanted if k not in point]
        if missing:
            raise ParameterError(f"{name}.point: no operating value for {', '.join(missing)}")
        self.point = {k: float(point[k]) for k in wanted}
        unknown = [k for k in null if k not in self.inner.INPUTS]
        if unknown:
            raise ParameterError(f"{name}.null: {', '.join(unknown)} is not an input of {type(self.inner).__name__}")
        #: Inputs expanded about zero rather than the point (a valve's spool: the linearised valve of eqs. 4.6-4.13)
        self.null = tuple(null)

    def config(self) -> dict[str, Any]:
        inner = {"type": type(self.inner).__name__, **self.inner.given, **self.inner.option_values, **self.inner.config()}
        for k in self.inner.explicit:
            inner.setdefault(k, self.inner.values[k])
        return {"inner": inner, "point": dict(self.point), **({"null": list(self.null)} if self.null else {})}

    def structure_key(self) -> tuple[Any, ...]:
        return (type(self.inner).__name__, tuple(sorted(self.inner.option_values.items())), tuple(sorted(self.point.items())),
                self.null, self.inner.structure_key())

    def _equations(self, t: Any) -> tuple[dict[str, Any], dict[str, Any], dict[str, Any], dict[str, Any]]:
        """The inner's outputs and rates on symbols of its states and inputs: (xs, us, outputs, rates)."""
        xs = {k: ca.SX.sym(f"x_{k}") for k in self.inner.STATES}
        us = {k: ca.SX.sym(f"u_{k}") for k in self.inner.INPUTS}
        y = self.inner.output_equations(t, xs, us, self._p)
        d = self.inner.state_equations(t, xs, us, self._p, y) if self.inner.STATES else {}
        return xs, us, {k: ca.SX(v) for k, v in y.items()}, {k: ca.SX(v) for k, v in d.items()}

    def expand(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], which: str) -> dict[str, Any]:
        """The inner's outputs (``which = "y"``) or state rates (``"d"``), expanded about the point.

        ``x`` may hold values of the inner's states. An input is read only if
        the expanded expressions depend on it: an output that depends on a
        state alone (a chamber's pressure) does not read the flows into it, so
        no algebraic loop appears where the inner component has none.
        """
        self._p = p
        xs, us, y, d = self._equations(t)
        exprs = y if which == "y" else d
        if not exprs:
            return {}
        g = ca.vertcat(*exprs.values())
        needed = [k for k in us if ca.depends_on(g, us[k])]
        z = ca.vertcat(*xs.values(), *[us[k] for k in needed])
        z0 = ca.DM([self.point[k] for k in [*xs, *needed]])
        # the anchor: the point, with the null inputs at zero; the coefficients stay those of the point
        za = ca.DM([0.0 if k in self.null else self.point[k] for k in [*xs, *needed]])
        zc = ca.vertcat(*[ca.SX(x[k]) for k in xs], *[ca.SX(u[k]) for k in needed])
        rest = [k for k in us if k not in needed]  # inputs the expressions do not read: their values do not matter
        if rest:
            g = ca.substitute(g, ca.vertcat(*[us[k] for k in rest]), ca.DM([self.point[k] for k in rest]))
        if z.numel() == 0:
            return dict(zip(exprs, ca.vertsplit(g)))
        J = ca.jacobian(g, z)
        ga = ca.substitute(g, z, za)
        at = z0 if self.option("coefficients") == "frozen" else zc
        Jat = ca.substitute(J, z, at)
        names = [*xs, *needed]
        cols = []
        for i, k in enumerate(names):
            col = Jat[:, i]
            if k in self.null:  # the secant from the null: the flow at the opening over the opening
                zero = ca.vertcat(*[0.0 if j == i else at[j] for j in range(len(names))])
                secant = (ca.substitute(g, z, at) - ca.substitute(g, z, zero)) / ca.if_else(at[i] != 0, at[i], 1.0)
                col = ca.if_else(ca.fabs(at[i]) > 1e-12 * max(1.0, abs(self.point[k])), secant, col)
            cols.append(col)
        lin = ga + ca.mtimes(ca.horzcat(*cols), zc - za)
        return dict(zip(exprs, ca.vertsplit(lin)))


@register
class Linearized(_Taylor):
    """A component replaced by its first-order expansion about an operating point (module notes).

    ``inner`` is the component (or its table in a model file); ``point`` its
    states and inputs there, SI. Option ``coefficients``: ``frozen`` (the
    linearised model, [Efe2014] section 4.3) or ``feedback`` (with parameter
    feedback, section 4.3.3).
    """

    def output_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        return self.expand(t, x, u, p, "y")

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        return self.expand(t, x, u, p, "d")


@register
class LoadPressureCylinder(_Taylor):
    """A cylinder reduced to its load pressure about an operating point, [Efe2014] eqs. 4.15-4.23 (module notes).

    One state ``pL`` (:math:`p_A - \\alpha p_B`, :math:`\\alpha = A_B/A_A`); the
    outputs are the cylinder's, with the chamber pressures of eqs. 4.15-4.16.
    """

    def __init__(self, name: str, inner: Component | Mapping[str, Any], point: Mapping[str, float], **values: Any) -> None:
        super().__init__(name, inner, point, **values)
        if set(self.inner.STATES) != {"pA", "pB"} or not {"A_A", "A_B"} <= set(self.inner.PARAMETERS):
            raise ModelError(f"{name}: a load-pressure model needs a cylinder (states pA, pB; areas A_A, A_B)")
        self.STATES = {"pL": State("Pa", "load pressure p_A - alpha p_B (eq. 4.17)", initial=0.0, nominal=1e7)}  # type: ignore[misc]

    def _alpha(self, p: Mapping[str, Any]) -> Any:
        return p["A_B"] / p["A_A"]

    def chambers(self, pL: Any, p: Mapping[str, Any]) -> dict[str, Any]:
        """The chamber pressures of eqs. 4.15-4.16 about the point."""
        a = self._alpha(p)
        dpL = pL - (self.point["pA"] - a * self.point["pB"])
        return {"pA": self.point["pA"] + dpL / (1 + a**3), "pB": self.point["pB"] - a**2 * dpL / (1 + a**3)}

    def output_equations(self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]) -> dict[str, Any]:
        return self.expand(t, self.chambers(x["pL"], p), u, p, "y")

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        rates = self.expand(t, self.chambers(x["pL"], p), u, p, "d")
        return {"pL": rates["pA"] - self._alpha(p) * rates["pB"]}
