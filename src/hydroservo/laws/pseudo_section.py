r"""Semi-empirical proportional-valve laws: pseudo-sections [FerreiraND].

Ferreira, Gomes de Almeida & Quintas, *Semi-empirical model for a hydraulic
servo-solenoid valve*. Citation keys in brackets are those of
:mod:`hydroservo.references`.

A control orifice :math:`i \to j` passes :math:`q_{ij} = \operatorname{sign}(\Delta P_{ij})
A_{ij}(x_s)\sqrt{|\Delta P_{ij}|}` (eq. 1): the flow is always written as
turbulent and the laminar region near null is absorbed into the
*pseudo-section* :math:`A_{ij}` [m^3/s/Pa^0.5], a function of the normalised
spool position :math:`x_s \in [-1, 1]`. For a matched and symmetrical valve one
function suffices: :math:`A_{s1} = A_{2t} = A_p(x_s)`,
:math:`A_{s2} = A_{1t} = A_n(x_s) = A_p(-x_s)`.

All functions are pure and vectorised (NumPy arrays or CasADi expressions);
pressures are relative to tank [Pa], flows in m^3/s, pseudo-sections in
m^3/s/Pa^0.5 (the paper prints them in L/min/bar^0.5; 1 L/min/bar^0.5 =
5.2705e-8 m^3/s/Pa^0.5).

How the extracted text was read
-------------------------------
* Eq. (24): the exponential core is :math:`A_p = \gamma e^{k x_s/2}`,
  :math:`A_n = \gamma e^{-k x_s/2}` (the exponent's factor 1/2 is confirmed by
  eq. 25, :math:`P_L = \tanh(k x_s)`, and by the published numbers: with
  k = 36.5, gamma = 0.1149 and x_t = 3.858e-2 continuity gives alpha = 4.240 and
  beta = 6.88e-2, as printed).
* Eq. (29) prints as "q_lk0 = 2 P_s gamma" with the root lost:
  :math:`q_{lk0} = \gamma\sqrt{2P_s}` follows from eq. (28) at :math:`x_s = 0`
  and gives 1.360 L/min for the published gamma and P_s = 70 bar.
* Eq. (31): :math:`K_{q0} = k\gamma\sqrt{P_s/2}`; the flow gain is measured
  with the ports connected, every orifice seeing :math:`P_s/2`, which the paper
  sets to :math:`P_n` = 35 bar ("the pressure drop in each orifice was
  constrained to 35 bar"). So a datasheet's :math:`K_{q0}` is taken at a drop
  :math:`P_n` per metering edge, and :math:`Q_n = \sqrt{P_n}\,A_p(1)` (eqs. 32, 34).
* Eq. (33): :math:`A_n = k_1x + k_2 + \sqrt{k_3x^2 + k_4x + k_5}`,
  :math:`A_p = -k_1x + k_2 + \sqrt{k_3x^2 - k_4x + k_5}`, the radicand
  non-negative on [-1, 1]. Checked against the published k1..k5: they satisfy
  eqs. (34), (36), (37) and zero leakage and leakage slope at :math:`x_s = 1`
  to four digits.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.errors import ParameterError
from hydroservo.laws.four_way import bridge_flows
from hydroservo.laws.orifice import turbulent_flow

__all__ = [
    "STRUCTURES",
    "PARAMETER_NAMES",
    "PARAMETER_UNITS",
    "PRINTED_UNITS",
    "variable_structure",
    "fixed_structure",
    "pseudo_sections",
    "valve_flows",
    "matched_valve_flows",
    "load_flow_no_load",
    "relative_load_pressure",
    "leakage_blocked",
    "load_flow",
    "sections_from_measurements",
    "check_sections",
]

#: Pseudo-section families: the variable structure of eq. (24) and the fixed (hyperbolic) one of eq. (33).
STRUCTURES = ("variable", "fixed")

_A = "m^3/s/Pa^0.5"
_A2 = "m^6/s^2/Pa"
#: SI unit of every pseudo-section parameter.
PARAMETER_UNITS = {
    "k": "",
    "gamma": _A,
    "alpha": _A,
    "beta": _A,
    "x_t": "",
    "k1": _A,
    "k2": _A,
    "k3": _A2,
    "k4": _A2,
    "k5": _A2,
}

#: The units the paper prints them in.
PRINTED_UNITS = {k: {"": "", _A: "L/min/bar^0.5", _A2: "(L/min)^2/bar"}[u] for k, u in PARAMETER_UNITS.items()}

#: Parameter names of each structure, as in the paper.
#: How far the two branches of a variable-structure section may differ at x_t, as a fraction of the larger: the
#: rounding of printed parameters (the published KBSDG4V-3 set: 0.04 %), well short of a jump.
CONTINUITY = 0.05

PARAMETER_NAMES = {"variable": ("k", "gamma", "alpha", "beta", "x_t"), "fixed": ("k1", "k2", "k3", "k4", "k5")}


def variable_structure(x: Any, k: Any, gamma: Any, alpha: Any, beta: Any, x_t: Any) -> Any:
    r"""Opening pseudo-section :math:`A_p(x_s)` of variable structure, [FerreiraND] eq. (24b).

    .. math::
        A_p(x_s) = \begin{cases} \gamma\, e^{k x_s/2}, & -1 \le x_s \le x_t \\
                                 \alpha x_s + \beta, & x_t < x_s \le 1 \end{cases}

    The closing section is :math:`A_n(x_s) = A_p(-x_s)` (eq. 24a).

    Parameters
    ----------
    x : array_like
        Normalised spool position [-], in [-1, 1].
    k : array_like
        Relative pressure gain at null, :math:`K_{p0}` (eq. 26) [-].
    gamma : array_like
        Pseudo-section at null (eq. 29) [m^3/s/Pa^0.5].
    alpha, beta : array_like
        Slope and intercept of the linear outer part [m^3/s/Pa^0.5].
    x_t : array_like
        Transition point [-], in (0, 1).

    Returns
    -------
    A_p : array_like
        Pseudo-section [m^3/s/Pa^0.5].

    References
    ----------
    [FerreiraND] eqs. (24)-(29).

    Examples
    --------
    The KBSDG4V-3 of [FerreiraND] (section 5), in the paper's units L/min/bar^0.5:
    value and slope are continuous at the transition point.

    >>> p = dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=3.858e-2)
    >>> round(float(variable_structure(0.03858, **p)), 4), round(4.241 * 0.03858 + 6.877e-2, 4)
    (0.2323, 0.2324)
    """
    # exp of min(x, x_t): the same on the branch it is used in, and no overflow where NumPy evaluates it unused
    return bk.if_else(x <= x_t, gamma * bk.exp(k * bk.fmin(x, x_t) / 2.0), alpha * x + beta)


def fixed_structure(x: Any, k1: Any, k2: Any, k3: Any, k4: Any, k5: Any) -> Any:
    r"""Opening pseudo-section :math:`A_p(x_s)` of fixed (hyperbolic) structure, [FerreiraND] eq. (33b).

    .. math:: A_p(x_s) = -k_1 x_s + k_2 + \sqrt{k_3 x_s^2 - k_4 x_s + k_5}

    and :math:`A_n(x_s) = A_p(-x_s) = k_1x_s + k_2 + \sqrt{k_3x_s^2 + k_4x_s + k_5}`
    (eq. 33a). The hyperbola has two asymptotes: slope :math:`\sqrt{k_3} - k_1`
    when open, :math:`-(\sqrt{k_3} + k_1)` (about zero) when closed.

    Parameters
    ----------
    x : array_like
        Normalised spool position [-].
    k1, k2 : array_like
        Coefficients of the hyperbola [m^3/s/Pa^0.5].
    k3, k4, k5 : array_like
        Coefficients of the radicand [m^6/s^2/Pa]; the radicand must stay
        non-negative on [-1, 1].

    Returns
    -------
    A_p : array_like
        Pseudo-section [m^3/s/Pa^0.5].

    References
    ----------
    [FerreiraND] eqs. (33)-(37).

    Examples
    --------
    Published fixed-structure set ([FerreiraND] section 5, L/min/bar^0.5): nominal
    flow 25.5 L/min at 35 bar per edge (eq. 34).

    >>> p = dict(k1=-2.142, k2=5.818e-3, k3=4.604, k4=-5.554e-2, k5=1.534e-2)
    >>> round(float(fixed_structure(1.0, **p)) * 35**0.5, 2)
    25.5
    """
    return -k1 * x + k2 + bk.sqrt(bk.fmax(k3 * x * x - k4 * x + k5, 0.0))


_LAWS = {"variable": variable_structure, "fixed": fixed_structure}


def pseudo_sections(x: Any, structure: str, params: dict[str, Any]) -> tuple[Any, Any]:
    """Opening and closing pseudo-sections ``(A_p(x), A_n(x))`` of a matched, symmetrical valve.

    Parameters
    ----------
    x : array_like
        Normalised spool position [-].
    structure : {"variable", "fixed"}
        Eq. (24) or eq. (33) [-].
    params : dict
        The structure's parameters (:data:`PARAMETER_NAMES`) in the units of
        :data:`PARAMETER_UNITS` [SI].

    Returns
    -------
    (A_p, A_n) : tuple of array_like
        Opening and closing pseudo-sections [m^3/s/Pa^0.5], :math:`A_n(x) = A_p(-x)`.

    Raises
    ------
    ParameterError
        An unknown ``structure``.

    References
    ----------
    [FerreiraND] eqs. (2), (24), (33).

    Examples
    --------
    At null both sections are gamma (here in the paper's L/min/bar^0.5):

    >>> p = dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=3.858e-2)
    >>> [round(float(a), 4) for a in pseudo_sections(0.0, "variable", p)]
    [0.1149, 0.1149]
    """
    if structure not in _LAWS:
        raise ParameterError(f"structure = {structure!r}: expected one of {', '.join(STRUCTURES)}")
    law = _LAWS[structure]
    args = [params[n] for n in PARAMETER_NAMES[structure]]
    return law(x, *args), law(-x, *args)


def valve_flows(
    A_s1: Any, A_s2: Any, A_1t: Any, A_2t: Any, P_s: Any, P_t: Any, P_1: Any, P_2: Any, p_tr: Any = 0.0
) -> tuple[Any, Any, Any, Any]:
    r"""Flows of a five-port four-way valve with four pseudo-sections, [FerreiraND] eqs. (1)-(3).

    The general unmatched, asymmetrical case: every control section has its own
    pseudo-section (already evaluated at the spool position).

    Parameters
    ----------
    A_s1, A_s2, A_1t, A_2t : array_like
        Pseudo-sections supply->1, supply->2, 1->tank, 2->tank [m^3/s/Pa^0.5].
    P_s, P_t, P_1, P_2 : array_like
        Supply, tank and outlet-port pressures [Pa].
    p_tr : array_like
        Regularisation pressure of the root [Pa] (0: eq. 1 exactly).

    Returns
    -------
    Q_1, Q_2, Q_s, Q_t : array_like
        Flow out of port 1 and port 2, drawn from supply, returned to tank
        [m^3/s] (eq. 3).

    References
    ----------
    [FerreiraND] eqs. (1)-(3).

    Examples
    --------
    Ports at half supply: each port flow is :math:`(A_{s1} - A_{1t})\sqrt{P_s/2}`
    (unit sections and 2 Pa here, for round numbers):

    >>> [float(q) for q in valve_flows(3.0, 1.0, 1.0, 3.0, 2.0, 0.0, 1.0, 1.0)]
    [2.0, -2.0, 4.0, 4.0]
    """
    return bridge_flows(
        turbulent_flow(A_s1, P_s - P_1, p_tr),
        turbulent_flow(A_1t, P_1 - P_t, p_tr),
        turbulent_flow(A_s2, P_s - P_2, p_tr),
        turbulent_flow(A_2t, P_2 - P_t, p_tr),
    )


def matched_valve_flows(
    A_p: Any, A_n: Any, P_s: Any, P_t: Any, P_1: Any, P_2: Any, p_tr: Any = 0.0
) -> tuple[Any, Any, Any, Any]:
    r"""Flows of a matched, symmetrical valve, [FerreiraND] eqs. (2)-(3): :func:`valve_flows`
    with :math:`A_{s1} = A_{2t} = A_p` and :math:`A_{s2} = A_{1t} = A_n`.

    Parameters
    ----------
    A_p, A_n : array_like
        Opening and closing pseudo-sections at the spool position [m^3/s/Pa^0.5].
    P_s, P_t, P_1, P_2 : array_like
        Supply, tank and outlet-port pressures [Pa].
    p_tr : array_like
        Regularisation pressure of the root [Pa] (0: eq. 1 exactly).

    Returns
    -------
    Q_1, Q_2, Q_s, Q_t : array_like
        Flow out of port 1 and port 2, drawn from supply, returned to tank [m^3/s].

    References
    ----------
    [FerreiraND] eqs. (1)-(3).

    Examples
    --------
    >>> [float(q) for q in matched_valve_flows(3.0, 1.0, 2.0, 0.0, 1.0, 1.0)]
    [2.0, -2.0, 4.0, 4.0]
    """
    return valve_flows(A_p, A_n, A_n, A_p, P_s, P_t, P_1, P_2, p_tr)


def load_flow_no_load(A_p: Any, A_n: Any, P_s: Any) -> Any:
    r"""Load flow with the ports connected (:math:`P_L = 0`), [FerreiraND] eq. (9) [m^3/s].

    .. math:: Q_L = \sqrt{P_s/2}\,(A_p - A_n)

    Parameters
    ----------
    A_p, A_n : array_like
        Opening and closing pseudo-sections at the spool position [m^3/s/Pa^0.5].
    P_s : array_like
        Supply pressure [Pa].

    Returns
    -------
    array_like
        Load flow [m^3/s].

    References
    ----------
    [FerreiraND] eqs. (6)-(9).

    Examples
    --------
    The published fixed-structure KBSDG4V-3 at full stroke and 70 bar supply
    (paper units: L/min/bar^0.5, bar, L/min) passes its nominal 25.5 L/min:

    >>> p = dict(k1=-2.142, k2=5.818e-3, k3=4.604, k4=-5.554e-2, k5=1.534e-2)
    >>> A_p, A_n = pseudo_sections(1.0, "fixed", p)
    >>> round(float(load_flow_no_load(A_p, A_n, 70.0)), 2)
    25.5
    """
    return bk.sqrt(P_s / 2.0) * (A_p - A_n)


def relative_load_pressure(A_p: Any, A_n: Any) -> Any:
    r"""Relative load pressure with blocked ports, [FerreiraND] eq. (13) [-].

    .. math:: \bar P_L = \frac{A_p^2 - A_n^2}{A_p^2 + A_n^2}, \qquad \bar P_L = (P_1 - P_2)/P_s

    Parameters
    ----------
    A_p, A_n : array_like
        Opening and closing pseudo-sections at the spool position [m^3/s/Pa^0.5].

    Returns
    -------
    array_like
        :math:`\bar P_L` [-], in [-1, 1].

    References
    ----------
    [FerreiraND] eqs. (10)-(13), (25).

    Examples
    --------
    With the exponential core of the variable structure, :math:`\bar P_L = \tanh(k x_s)`
    (eq. 25); the KBSDG4V-3 (k = 36.5) at 1 % of stroke:

    >>> p = dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=3.858e-2)
    >>> A_p, A_n = pseudo_sections(0.01, "variable", p)
    >>> round(float(relative_load_pressure(A_p, A_n)), 4), round(float(np.tanh(0.365)), 4)
    (0.3496, 0.3496)
    """
    return (A_p**2 - A_n**2) / (A_p**2 + A_n**2)


def leakage_blocked(A_p: Any, A_n: Any, P_s: Any) -> Any:
    r"""Leakage (supply) flow with blocked ports, [FerreiraND] eq. (27) [m^3/s].

    .. math:: q_{lk} = \frac{2\sqrt{P_s}\,A_pA_n}{\sqrt{A_p^2 + A_n^2}}

    from eqs. (13), (16) and (17) with the pressures of eq. (11).

    Parameters
    ----------
    A_p, A_n : array_like
        Opening and closing pseudo-sections at the spool position [m^3/s/Pa^0.5].
    P_s : array_like
        Supply pressure [Pa].

    Returns
    -------
    array_like
        Leakage flow [m^3/s].

    References
    ----------
    [FerreiraND] eqs. (11)-(17), (27)-(29).

    Examples
    --------
    At null, :math:`q_{lk0} = \gamma\sqrt{2P_s}` (eq. 29): the KBSDG4V-3 leaks
    1.360 L/min at 70 bar (paper units: L/min/bar^0.5, bar, L/min):

    >>> round(float(leakage_blocked(0.1149, 0.1149, 70.0)), 3)
    1.36
    """
    return 2.0 * bk.sqrt(P_s) * A_p * A_n / bk.sqrt(A_p**2 + A_n**2)


def load_flow(A_p: Any, A_n: Any, P_s: Any, P_L: Any) -> Any:
    r"""Load flow at relative load pressure :math:`\bar P_L`, [FerreiraND] eq. (21) [m^3/s].

    .. math:: Q_L = A_p\sqrt{\tfrac{P_s}{2}(1 - \bar P_L)} - A_n\sqrt{\tfrac{P_s}{2}(1 + \bar P_L)}

    valid for :math:`|\bar P_L| \le 1` with the outlet flows equal (a
    symmetrical actuator, eq. 4: :math:`P_1 + P_2 = P_s`). Gives the
    pressure-flow family of a datasheet.

    Parameters
    ----------
    A_p, A_n : array_like
        Opening and closing pseudo-sections at the spool position [m^3/s/Pa^0.5].
    P_s : array_like
        Supply pressure [Pa].
    P_L : array_like
        Relative load pressure :math:`(P_1 - P_2)/P_s` [-], in [-1, 1].

    Returns
    -------
    array_like
        Load flow [m^3/s].

    References
    ----------
    [FerreiraND] eqs. (4), (11), (21).

    Examples
    --------
    The published fixed-structure KBSDG4V-3 at full stroke and 70 bar
    (paper units) at half the supply as load pressure:

    >>> p = dict(k1=-2.142, k2=5.818e-3, k3=4.604, k4=-5.554e-2, k5=1.534e-2)
    >>> A_p, A_n = pseudo_sections(1.0, "fixed", p)
    >>> round(float(load_flow(A_p, A_n, 70.0, 0.0)), 2), round(float(load_flow(A_p, A_n, 70.0, 0.5)), 2)
    (25.5, 18.03)
    """
    return A_p * bk.sqrt(P_s / 2.0 * (1.0 - P_L)) - A_n * bk.sqrt(P_s / 2.0 * (1.0 + P_L))


def sections_from_measurements(
    P_L: Any, q_lk: Any, P_s: float, max_abs_PL: float = 0.6
) -> tuple[np.ndarray, np.ndarray]:
    r"""Pseudo-sections from measured blocked-port curves, [FerreiraND] eqs. (16)-(17).

    .. math:: A_n = \frac{q_{lk}}{\sqrt{2P_s(1 + \bar P_L)}}, \qquad
              A_p = \frac{q_{lk}}{\sqrt{2P_s(1 - \bar P_L)}}

    These are the "real" sections of the paper's Fig. 3. Points with
    :math:`|\bar P_L| \ge` ``max_abs_PL`` are returned as NaN: there the
    measurement uncertainty of pressure and flow dominates (the paper uses 0.6).

    Parameters
    ----------
    P_L : array_like
        Relative load pressure :math:`(P_1 - P_2)/P_s` [-].
    q_lk : array_like
        Leakage flow [m^3/s].
    P_s : float
        Supply pressure of the measurement [Pa].
    max_abs_PL : float
        Confidence limit on :math:`|\bar P_L|` [-].

    Returns
    -------
    A_p, A_n : ndarray
        Opening and closing pseudo-sections [m^3/s/Pa^0.5]; NaN where
        :math:`|\bar P_L| \ge` ``max_abs_PL``.

    Raises
    ------
    ParameterError
        A non-positive ``P_s`` or a negative leakage flow.

    References
    ----------
    [FerreiraND] eqs. (16)-(17) and Fig. 3.

    Examples
    --------
    The blocked-port curves of a valve give its sections back
    (:func:`relative_load_pressure`, :func:`leakage_blocked`; paper units):

    >>> p = dict(k=36.5, gamma=0.1149, alpha=4.241, beta=6.877e-2, x_t=3.858e-2)
    >>> A_p, A_n = pseudo_sections(np.array([-0.01, 0.0, 0.01]), "variable", p)
    >>> P_L, q_lk = relative_load_pressure(A_p, A_n), leakage_blocked(A_p, A_n, 70.0)
    >>> bool(np.allclose(sections_from_measurements(P_L, q_lk, 70.0), (A_p, A_n)))
    True
    """
    P_L = np.asarray(P_L, dtype=float)
    q_lk = np.asarray(q_lk, dtype=float)
    if not P_s > 0:
        raise ParameterError(f"P_s = {P_s!r} Pa: expected a positive supply pressure")
    if np.any(q_lk < 0):
        raise ParameterError(f"q_lk: expected leakage flows >= 0; got minimum {q_lk.min():g} m^3/s")
    ok = np.abs(P_L) < max_abs_PL
    with np.errstate(invalid="ignore", divide="ignore"):
        A_n = np.where(ok, q_lk / np.sqrt(2.0 * P_s * (1.0 + P_L)), np.nan)
        A_p = np.where(ok, q_lk / np.sqrt(2.0 * P_s * (1.0 - P_L)), np.nan)
    return A_p, A_n


def check_sections(structure: str, params: Mapping[str, float]) -> None:
    """Raise ParameterError if a pseudo-section (or the fixed radicand) is negative on [-1, 1].

    Below 0.1 % of the largest section a negative value is taken as rounding of
    printed parameters (the published fixed set reaches -1e-4 of it at x_s = -1);
    components clip it to zero.

    Parameters
    ----------
    structure : {"variable", "fixed"}
        Eq. (24) or eq. (33) [-].
    params : mapping
        The structure's parameters (:data:`PARAMETER_NAMES`) in the units of
        :data:`PARAMETER_UNITS` [SI] (or any consistent units).

    Returns
    -------
    None
        Returns only when the sections are valid.

    Raises
    ------
    ParameterError
        A negative pseudo-section or radicand on [-1, 1], or a variable-structure
        parameter out of its range (eq. 24: k, gamma, alpha > 0, x_t in (0, 1)).

    References
    ----------
    [FerreiraND] eqs. (24), (33).

    Examples
    --------
    The published fixed set passes (paper units):

    >>> check_sections("fixed", dict(k1=-2.142, k2=5.818e-3, k3=4.604, k4=-5.554e-2, k5=1.534e-2))
    """
    x = np.linspace(-1.0, 1.0, 2001)
    if structure == "fixed":
        k3, k4, k5 = params["k3"], params["k4"], params["k5"]
        rad = np.minimum(k3 * x**2 - k4 * x + k5, k3 * x**2 + k4 * x + k5)
        scale = max(abs(k3), abs(k4), abs(k5))
        if np.min(rad) < -1e-9 * scale:
            i = int(np.argmin(rad))
            raise ParameterError(
                f"fixed-structure pseudo-section: radicand k3 x^2 - k4 x + k5 = {rad[i]:.3g} < 0 at x_s = {x[i]:+.3f}; "
                "expected >= 0 on [-1, 1] (eq. 33)"
            )
    else:
        if not 0.0 < params["x_t"] < 1.0:
            raise ParameterError(f"variable-structure x_t = {params['x_t']!r}: expected a transition point in (0, 1)")
        for key in ("k", "gamma", "alpha"):
            if not params[key] > 0:
                raise ParameterError(f"variable-structure {key} = {params[key]!r}: expected > 0 (eq. 24)")
        # x_t is where the two branches meet (eqs. 24, 27-31: identification.datasheet derives alpha, beta and
        # x_t from that): a section that jumps there is a flow that jumps with the spool, a discontinuity no
        # valve has and no solver steps across (k = 63, x_t = 0.91 jumps by a factor of 1e11)
        k, gamma, alpha, beta, x_t = (float(params[n]) for n in ("k", "gamma", "alpha", "beta", "x_t"))
        with np.errstate(over="ignore"):
            inner, outer = gamma * math.exp(min(k * x_t / 2.0, 700.0)), alpha * x_t + beta
        if not abs(inner - outer) <= CONTINUITY * max(abs(inner), abs(outer)):
            raise ParameterError(
                f"variable-structure pseudo-section: at the transition point x_t = {x_t:.4g} the inner branch "
                f"gamma exp(k x_t / 2) = {inner:.4g} (k = {k:.4g}, gamma = {gamma:.4g}) and the outer one "
                f"alpha x_t + beta = {outer:.4g} (alpha = {alpha:.4g}, beta = {beta:.4g}) differ by more than "
                f"{CONTINUITY:.0%}; expected a continuous section (eq. 24: x_t is where they meet; "
                "identification.fit_datasheet derives alpha, beta and x_t from k and gamma)"
            )
    A_p, _ = pseudo_sections(x, structure, dict(params))
    scale = float(np.max(np.abs(A_p)))
    # Below 0.1 % of the largest section a negative value is rounding (the published fixed set itself
    # reaches -1e-4 of it at x_s = -1); components clip it to zero.
    if np.min(A_p) < -1e-3 * scale:
        i = int(np.argmin(A_p))
        raise ParameterError(
            f"{structure}-structure pseudo-section A_p = {A_p[i]:.3g} m^3/s/Pa^0.5 < 0 at x_s = {x[i]:+.3f}; "
            "expected a non-negative section on [-1, 1]"
        )
