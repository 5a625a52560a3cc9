r"""Servo-solenoid (high-performance proportional) valve of [FerreiraND]: pseudo-sections and spool dynamics.

Two decoupled blocks in series ([FerreiraND] section 2): the spool dynamics of
the valve with its controller card (:class:`~hydroservo.components.SpoolRateLimited`,
Fig. 11), and the static flow model with pseudo-sections
(:class:`PseudoSectionValve`, eqs. 1-3, 24, 33; the laws are
:mod:`hydroservo.laws.pseudo_section`). :class:`ServoSolenoidValve` is both in
one component, input :math:`u \in [-1, 1]`.

The same component is what a datasheet fit returns
(:func:`hydroservo.identification.fit_datasheet`): its :meth:`~PseudoSectionValve.sections`
and :meth:`~PseudoSectionValve.characteristics` evaluate the laws with its values.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.components.base import Component, FromSet, Option, Param, Port, register
from hydroservo.components.spools.rate_limited import SpoolRateLimited
from hydroservo.components.valves.ports import FLOW_OUTPUTS, HYDRAULIC_PORTS, PRESSURE_PORTS
from hydroservo.errors import ParameterError
from hydroservo.laws import pseudo_section as ps

__all__ = ["PseudoSectionValve", "ServoSolenoidValve"]


def _variable(key: str) -> FromSet:
    return FromSet("FerreiraND", "variable", key)


def _fixed(key: str) -> FromSet:
    return FromSet("FerreiraND", "fixed", key)


_A = ps.PARAMETER_UNITS["gamma"]
_A2 = ps.PARAMETER_UNITS["k3"]
_SECTION_PARAMS = {
    "k": Param(
        _variable("k"), "", "variable structure: relative pressure gain at null (eq. 26)", min=0.0, min_inclusive=False
    ),
    "gamma": Param(_variable("gamma"), _A, "variable structure: section at null (eq. 29)", min=0.0),
    "alpha": Param(_variable("alpha"), _A, "variable structure: slope of the outer part", min=0.0),
    "beta": Param(_variable("beta"), _A, "variable structure: intercept of the outer part"),
    "x_t": Param(
        _variable("x_t"),
        "",
        "variable structure: transition point",
        min=0.0,
        max=1.0,
        min_inclusive=False,
        max_inclusive=False,
    ),
    "k1": Param(_fixed("k1"), _A, "fixed structure k1 (eq. 33)"),
    "k2": Param(_fixed("k2"), _A, "fixed structure k2"),
    "k3": Param(_fixed("k3"), _A2, "fixed structure k3", min=0.0),
    "k4": Param(_fixed("k4"), _A2, "fixed structure k4"),
    "k5": Param(_fixed("k5"), _A2, "fixed structure k5", min=0.0),
    "p_tr": Param(1e4, "Pa", "regularisation pressure of the square root (numerical only)", min=0.0),
}
_STRUCTURE = Option("variable", ps.STRUCTURES, "pseudo-section family: eq. (24) variable or eq. (33) fixed")


def _section_flows(xs: Any, u: Mapping[str, Any], p: Mapping[str, Any], structure: str) -> dict[str, Any]:
    x = bk.clip(xs, -1.0, 1.0)
    params = {n: p[n] for n in ps.PARAMETER_NAMES[structure]}
    A_p, A_n = ps.pseudo_sections(x, structure, params)
    A_p, A_n = bk.fmax(A_p, 0.0), bk.fmax(A_n, 0.0)  # rounding-level negatives (see check_sections)
    QA, QB, QS, QT = ps.matched_valve_flows(A_p, A_n, u["pS"], u["pT"], u["pA"], u["pB"], p["p_tr"])
    return {"QA": QA, "QB": QB, "QS": QS, "QT": QT}


class _Sections(Component):
    """What a pseudo-section valve knows about itself, evaluated with its own values (NumPy)."""

    @property
    def structure(self) -> str:
        """The pseudo-section family in use, ``"variable"`` or ``"fixed"``."""
        return self.option("structure")

    def section_parameters(self) -> dict[str, float]:
        """The parameters of the structure in use (SI)."""
        return {n: self.values[n] for n in ps.PARAMETER_NAMES[self.structure]}

    def sections(self, x: Any) -> tuple[np.ndarray, np.ndarray]:
        """Opening and closing pseudo-sections ``(A_p(x), A_n(x))`` at normalised positions ``x`` [m^3/s/Pa^0.5]."""
        return ps.pseudo_sections(np.asarray(x, dtype=float), self.structure, self.section_parameters())

    def characteristics(self, P_n: float, P_s: float) -> dict[str, float]:
        """Static characteristics computed from the laws (SI).

        ``Q_n`` = :math:`\\sqrt{P_n}A_p(1)` (eqs. 32, 34), ``Q_L1`` the load flow at
        full opening with connected ports at :math:`2P_n` supply (eq. 9),
        ``K_q0`` the slope of eq. (9) at null with :math:`P_s = 2P_n`, ``K_p0`` the
        slope of eq. (13) at null, ``q_lk0`` eq. (27) at null and :math:`P_s`.
        Slopes by central differences of step 1e-6.
        """
        h = 1e-6
        A_p, A_n = self.sections(np.array([-h, 0.0, h, 1.0]))
        QL = ps.load_flow_no_load(A_p, A_n, 2.0 * P_n)
        PL = ps.relative_load_pressure(A_p, A_n)
        return {
            "Q_n": float(math.sqrt(P_n) * A_p[3]),
            "Q_L1": float(QL[3]),
            "K_q0": float((QL[2] - QL[0]) / (2 * h)),
            "K_p0": float((PL[2] - PL[0]) / (2 * h)),
            "q_lk0": float(ps.leakage_blocked(A_p[1], A_n[1], P_s)),
        }

    def blocked_ports(self, x: Any, P_s: float) -> tuple[np.ndarray, np.ndarray]:
        """With blocked ports at supply ``P_s`` [Pa]: the relative load pressure [-] (eq. 13) and the leakage
        [m^3/s] (eq. 27) at normalised positions ``x`` (the curves of [FerreiraND] Figs. 4 and 7)."""
        A_p, A_n = self.sections(x)
        return np.asarray(ps.relative_load_pressure(A_p, A_n)), np.asarray(ps.leakage_blocked(A_p, A_n, P_s))

    def no_load_flow(self, x: Any, P_n: float) -> np.ndarray:
        """With connected ports (no load) and ``P_n`` [Pa] per edge: the load flow [m^3/s] at normalised positions
        ``x`` (eq. 9; [FerreiraND] Figs. 5-6, 8-9)."""
        A_p, A_n = self.sections(x)
        return np.asarray(ps.load_flow_no_load(A_p, A_n, 2.0 * P_n))

    def pressure_flow(self, x: float, P_L: Any, P_s: float) -> np.ndarray:
        """At normalised position ``x``: the load flow [m^3/s] against relative load pressures ``P_L`` [-] at
        supply ``P_s`` [Pa] (eq. 21), the datasheet's family."""
        A_p, A_n = self.sections(np.array([x]))
        return np.asarray(ps.load_flow(A_p[0], A_n[0], P_s, np.asarray(P_L, dtype=float)))

    def check_sections(self) -> None:
        """Raise ParameterError if a pseudo-section (or the fixed radicand) is negative on [-1, 1]."""
        try:
            ps.check_sections(self.structure, self.section_parameters())
        except ParameterError as exc:
            raise ParameterError(f"{self.name}: {exc}") from None


@register
class PseudoSectionValve(_Sections):
    """Matched, symmetrical four-way valve with pseudo-sections ([FerreiraND] eqs. 1-3, 24, 33).

    Input: the normalised spool position ``xs`` (clipped to [-1, 1]); port A
    is the paper's port 1 (opened to supply for ``xs > 0``). Parameters of both
    structures are declared; option ``structure`` selects which are used.
    Defaults: the published KBSDG4V-3 sets (parameter set ``FerreiraND``). Fit
    your own with :func:`hydroservo.identification.fit_datasheet`.

    The square root of eq. (1) is regularised below ``p_tr`` (default 0.1 bar,
    :mod:`hydroservo.laws.orifice`) only so that implicit solvers have a finite
    Jacobian at zero drop; the laminar region is in the pseudo-sections, as in
    the paper.
    """

    PARAMETERS = dict(_SECTION_PARAMS)
    INPUTS = {"xs": Port("", "normalised spool position, -1 to 1"), **PRESSURE_PORTS}
    OUTPUTS = dict(FLOW_OUTPUTS)
    HYDRAULIC = dict(HYDRAULIC_PORTS)
    OPTIONS = {"structure": _STRUCTURE}

    def check(self) -> None:
        self.check_sections()

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return _section_flows(u["xs"], u, p, self.option("structure"))


@register
class ServoSolenoidValve(_Sections, SpoolRateLimited):
    """Complete servo-solenoid valve of [FerreiraND]: :class:`SpoolRateLimited` then :class:`PseudoSectionValve`.

    Input the normalised command ``u`` in [-1, 1] and the port pressures;
    outputs the four flows and the spool position ``xs``. Defaults: the
    published KBSDG4V-3 (variable structure).
    """

    PARAMETERS = {**SpoolRateLimited.PARAMETERS, **_SECTION_PARAMS}
    INPUTS = {**SpoolRateLimited.INPUTS, **PRESSURE_PORTS}
    OUTPUTS = {**SpoolRateLimited.OUTPUTS, **FLOW_OUTPUTS}
    HYDRAULIC = dict(HYDRAULIC_PORTS)
    OPTIONS = {**SpoolRateLimited.OPTIONS, "structure": _STRUCTURE}

    def check(self) -> None:
        super().check()
        self.check_sections()

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        out = super().output_equations(t, x, u, p)
        return {**out, **_section_flows(out["xs"], u, p, self.option("structure"))}
