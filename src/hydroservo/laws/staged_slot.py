r"""The staged-slot spool valve of [MareAttarND]: orifices open, closed and critical, laminar to turbulent.

Pure, vectorised functions (NumPy arrays; the unified model also takes CasADi
expressions), SI units. Flow number :math:`\lambda` as in eq. (4)
(:func:`hydroservo.laws.orifice.flow_number`). Equation numbers are those of
[MareAttarND]; citation keys in brackets are those of :mod:`hydroservo.references`.
The closed-orifice laws of earlier authors that the paper reviews (eqs. 7-11)
are in :mod:`hydroservo.laws.leakage`.

How the extracted text was read
-------------------------------
* Eq. (6) prints :math:`C_q = C_{q\infty}\tanh(\alpha\lambda/\lambda_t)` with
  :math:`\alpha` undefined; eqs. (18), (20) and Table 1 have no such factor and
  must reduce to eq. (6) for an open orifice, so :math:`\alpha = 1` here (an
  argument, for other conventions: AMESim uses 2 with its critical number).
* Eqs. (18), (20) and Table 1 print the argument of tanh as
  "λ_t / λ_t(1 + ...)" (and "λ_i/λ_i"): a lost subscript. The reading
  :math:`\lambda_i/(\lambda_t[1 + \tfrac12 K_g(|X_i| - X_i)])` is the only one
  for which eq. (18) tends to eq. (15), :math:`C_q \to D_h\lambda/(64|X|)`,
  at large closure with the :math:`K_g` of eq. (19); the tests check that limit.
* Table 1's :math:`K_g` uses the hydraulic diameter of the closed passage,
  :math:`D_h = 2wc/(w + c)` (eq. 13), a constant, as eq. (19) says.
* Eqs. (14) and (16) (Merritt's short orifice, [Merritt1967]) use :math:`Re = C_q\lambda`
  (eq. 5), so they are implicit in :math:`C_q`; :func:`short_orifice_coefficient`
  solves them.
* Eq. (11), :math:`K_g = c(w + c)/(48\delta_\lambda w)`, is the continuity
  constant of the laminar-gap law (eq. 10), with :math:`\delta_\lambda` the limit
  slope :math:`dC_q/d\lambda` at small flow numbers.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.errors import ParameterError
from hydroservo.laws.four_way import EDGES, bridge_flows
from hydroservo.laws.orifice import smooth_abs, smooth_sign

__all__ = [
    "discharge_coefficient_open",
    "short_orifice_coefficient",
    "continuity_constant",
    "discharge_coefficient",
    "orifice_geometry",
    "slot_flow",
    "BRIDGE",
    "BRIDGE_PARAMETERS",
    "staged_slot_orifice_flow",
    "staged_slot_valve_flows",
]


def discharge_coefficient_open(lam: Any, Cq_inf: Any, lambda_t: Any, alpha: Any = 1.0) -> Any:
    r"""Flow coefficient of an open orifice, laminar to turbulent, [MareAttarND] eq. (6) [-].

    :math:`C_q = C_{q\infty}\tanh(\alpha\lambda/\lambda_t)`.

    Parameters
    ----------
    lam : array_like
        Flow number (eq. 4) [-].
    Cq_inf : array_like
        Turbulent limit of the flow coefficient [-].
    lambda_t : array_like
        Transition flow number [-].
    alpha : array_like
        Shape factor [-] (1: the unified model of eq. 20; module notes).

    Returns
    -------
    array_like
        Flow coefficient :math:`C_q` [-].

    References
    ----------
    [MareAttarND] eq. (6).

    Examples
    --------
    At the transition flow number the coefficient is :math:`\tanh 1 = 76\,\%` of its turbulent limit:

    >>> round(float(discharge_coefficient_open(8.0, 0.65, 8.0)) / 0.65, 4)
    0.7616
    """
    return Cq_inf * bk.tanh(alpha * lam / lambda_t)


def short_orifice_coefficient(X: Any, D_h: Any, lam: Any) -> np.ndarray:
    r"""Flow coefficient of a closed orifice as Merritt's short orifice, [MareAttarND] eqs. (14), (16) [-].

    The passage of length :math:`|X|` and hydraulic diameter :math:`D_h`:

    .. math::
        C_q = \left(2.28 + \frac{64|X|}{D_h Re}\right)^{-1/2} \quad (D_h Re/|X| < 50), \qquad
        C_q = \left(13.74\sqrt{\frac{|X|}{D_h Re}} + 1.5\right)^{-1/2} \quad (D_h Re/|X| > 50)

    with :math:`Re = C_q\lambda` (eq. 5), solved for :math:`C_q` at each point.
    Limits: :math:`1/\sqrt{1.5} = 0.816` for small closure (eq. 17),
    :math:`D_h\lambda/(64|X|)` for large closure (eq. 15).

    Parameters
    ----------
    X : array_like
        Closure (length of the passage) [m], > 0.
    D_h : array_like
        Hydraulic diameter of the passage [m].
    lam : array_like
        Flow number [-], > 0.

    Returns
    -------
    ndarray
        Flow coefficient :math:`C_q` [-], the shape of the broadcast arguments.

    Raises
    ------
    ParameterError
        A closure, hydraulic diameter or flow number not positive.

    References
    ----------
    [MareAttarND] eqs. (5), (14)-(17), after [Merritt1967] (whom [MareAttarND] cite as Merritt, 1968).

    Examples
    --------
    The two limits: small closure (eq. 17) and large closure (eq. 15,
    :math:`D_h\lambda/(64|X|)` = 4.6875e-4 here):

    >>> cq = short_orifice_coefficient([1e-9, 1e-3], 3e-6, [1e3, 10.0])
    >>> round(float(cq[0]), 3), round(float(cq[1]), 7)
    (0.814, 0.0004687)
    """
    from scipy.optimize import brentq  # SciPy's optimiser is imported only where a closed orifice is solved

    X, D_h, lam = np.broadcast_arrays(np.asarray(X, float), np.asarray(D_h, float), np.asarray(lam, float))
    if np.any(X <= 0) or np.any(D_h <= 0) or np.any(lam <= 0):
        raise ParameterError("short_orifice_coefficient: expected closure X > 0 m, D_h > 0 m and flow number > 0")
    out = np.empty(X.shape)
    for idx in np.ndindex(X.shape):
        x, d, la = X[idx], D_h[idx], lam[idx]
        b = 64 * x / (d * la)
        cq = (-b + np.sqrt(b * b + 4 * 2.28)) / (2 * 2.28)  # eq. (14): 2.28 Cq^2 + b Cq - 1 = 0
        if d * cq * la / x > 50:  # the other regime, eq. (16)
            cq = brentq(_eq16, 1e-12, 1.0 / np.sqrt(1.5), args=(x / (d * la),), xtol=1e-15)
        out[idx] = cq
    return out


def _eq16(cq: float, x_over_dlam: float) -> float:
    """Residual of [MareAttarND] eq. (16) with Re = C_q lambda."""
    residual: float = cq**-2 - (13.74 * np.sqrt(x_over_dlam / cq) + 1.5)
    return residual


def continuity_constant(Cq_inf: Any, lambda_t: Any, w: Any, c: Any) -> Any:
    r"""Continuity constant of the closed-orifice coefficient, [MareAttarND] eq. (19) [1/m].

    :math:`K_g = 64C_{q\infty}/(D_h\lambda_t) = 32(w + c)C_{q\infty}/(wc\lambda_t)`, with
    :math:`D_h = 2wc/(w + c)` (eq. 13) the hydraulic diameter of the closed passage.

    Parameters
    ----------
    Cq_inf : array_like
        Turbulent limit of the flow coefficient [-].
    lambda_t : array_like
        Transition flow number [-].
    w : array_like
        Slot width [m].
    c : array_like
        Radial clearance [m].

    Returns
    -------
    array_like
        :math:`K_g` [1/m].

    References
    ----------
    [MareAttarND] eqs. (13), (19).

    Examples
    --------
    A 4 mm slot, 1.5 um clearance, :math:`C_{q\infty} = 0.65`, :math:`\lambda_t = 8`:

    >>> round(float(continuity_constant(0.65, 8.0, 4e-3, 1.5e-6)))
    1733983
    """
    return 32.0 * (w + c) * Cq_inf / (w * c * lambda_t)


def discharge_coefficient(X_i: Any, lam: Any, Cq_inf: Any, lambda_t: Any, K_g: Any) -> Any:
    r"""Unified flow coefficient, continuous through null, [MareAttarND] eq. (20) [-].

    .. math:: C_{qi} = C_{q\infty}\tanh\frac{\lambda_i}{\lambda_t\left[1 + \tfrac12K_g(|X_i| - X_i)\right]}

    Open (:math:`X_i > 0`): eq. (6); closed: eq. (18).

    Parameters
    ----------
    X_i : array_like
        Opening of orifice i [m] (negative: closure).
    lam : array_like
        Flow number of the orifice [-].
    Cq_inf, lambda_t : array_like
        Turbulent limit of the flow coefficient and transition flow number [-].
    K_g : array_like
        Continuity constant (eq. 19) [1/m].

    Returns
    -------
    array_like
        Flow coefficient :math:`C_{qi}` [-].

    References
    ----------
    [MareAttarND] eqs. (6), (18)-(20).

    Examples
    --------
    Open and critical orifices follow eq. (6); a closure of 1 um divides the
    argument of tanh by :math:`1 + K_g|X_i|`:

    >>> Kg = continuity_constant(0.65, 8.0, 4e-3, 1.5e-6)
    >>> [round(float(cq), 4) for cq in discharge_coefficient(np.array([1e-6, 0.0, -1e-6]), 8.0, 0.65, 8.0, Kg)]
    [0.495, 0.495, 0.2277]
    """
    return Cq_inf * bk.tanh(lam / (lambda_t * (1.0 + 0.5 * K_g * (bk.fabs(X_i) - X_i))))


def orifice_geometry(X_i: Any, r: Any, c: Any, n: Any, w: Any) -> tuple[Any, Any, Any]:
    r"""Typical length, area and hydraulic diameter of orifice i, [MareAttarND] Table 1.

    Open (:math:`X_i > 0`): :math:`X_{si} = \sqrt{X_i^2 + (2r + c)^2} - 2r` (the
    rounded edge of radius r and the clearance c, after [Lebrun1986]); closed or
    critical: :math:`X_{si} = c`. Then :math:`S_i = nwX_{si}` and
    :math:`D_{hi} = 2wX_{si}/(w + X_{si})`. Continuous in value and slope at
    :math:`X_i = 0`.

    Parameters
    ----------
    X_i : array_like
        Opening [m].
    r : array_like
        Rounded-edge radius [m].
    c : array_like
        Radial clearance [m].
    n : array_like
        Number of slots [-].
    w : array_like
        Slot width [m].

    Returns
    -------
    X_s, S, D_h : array_like
        Typical length [m], flow area [m^2] and hydraulic diameter [m].

    References
    ----------
    [MareAttarND] Table 1, eq. (13), Fig. 2, after [Lebrun1986].

    Examples
    --------
    Closed or critical the length is the clearance; opened 10 um it is
    :math:`\sqrt{X^2 + (2r + c)^2} - 2r`:

    >>> X_s, S, D_h = orifice_geometry(np.array([0.0, 1e-5]), 2e-6, 1.5e-6, 2, 4e-3)
    >>> [round(float(x) * 1e6, 3) for x in X_s]  # um
    [1.5, 7.413]
    """
    open_len = bk.sqrt(X_i * X_i + (2.0 * r + c) ** 2) - 2.0 * r
    X_s = bk.if_else(X_i > 0, open_len, c + 0.0 * X_i)
    return X_s, n * w * X_s, 2.0 * w * X_s / (w + X_s)


def slot_flow(
    X_i: Any,
    dp: Any,
    r: Any,
    c: Any,
    n: Any,
    w: Any,
    rho: Any,
    nu: Any,
    Cq_inf: Any,
    lambda_t: Any,
    p_tr: Any = 0.0,
) -> Any:
    r"""Flow through orifice i, the 9-parameter model of [MareAttarND] Table 1 [m^3/s].

    :math:`Q_i = C_{qi}S_i\sqrt{2|\Delta P_i|/\rho}\,\operatorname{sgn}\Delta P_i`, with the
    geometry of :func:`orifice_geometry`, the flow number of eq. (4) on
    :math:`D_{hi}`, and :math:`C_{qi}` of eq. (20) with :math:`K_g` of eq. (19).
    The opening is :math:`X_i = X_{i0} + \varepsilon X`; pass it already formed.

    Parameters
    ----------
    X_i : array_like
        Opening of the orifice [m] (negative when closed).
    dp : array_like
        Pressure drop across it [Pa].
    r, c, n, w : array_like
        Rounded-edge radius [m], clearance [m], slot number [-], slot width [m].
    rho : array_like
        Density [kg/m^3].
    nu : array_like
        Kinematic viscosity [m^2/s].
    Cq_inf, lambda_t : array_like
        Turbulent flow coefficient [-] and transition flow number [-].
    p_tr : array_like
        0 (default): the law as published. A positive value [Pa] replaces
        :math:`|\Delta P|` by :math:`\sqrt{\Delta P^2 + p_{tr}^2}` and
        :math:`\operatorname{sgn}\Delta P` by :math:`\Delta P/\sqrt{\Delta P^2 + p_{tr}^2}`
        (:func:`~hydroservo.laws.orifice.smooth_abs`, :func:`~hydroservo.laws.orifice.smooth_sign`:
        the one regularisation of every orifice law), so that exact derivatives
        exist at zero drop (in a simulated system).

    Returns
    -------
    array_like
        Flow through the orifice in the direction of the pressure drop [m^3/s].

    Notes
    -----
    For small drops the flow is laminar, :math:`Q \propto \Delta P` (the tanh
    is linear in :math:`\lambda \propto \sqrt{|\Delta P|}`), so the law has a
    finite slope at zero drop without regularisation; its exact derivative,
    though, is 0 * inf there. The regularisation leaves that laminar slope
    exactly as it is: in the laminar limit :math:`Q \propto \lambda\sqrt{|\Delta P|}
    \operatorname{sgn}\Delta P \propto |\Delta P|\operatorname{sgn}\Delta P`, which becomes
    :math:`\sqrt{\Delta P^2 + p_{tr}^2}\,\Delta P/\sqrt{\Delta P^2 + p_{tr}^2} = \Delta P`.

    References
    ----------
    [MareAttarND] Table 1, eqs. (4), (19), (20).

    Examples
    --------
    Two 4 mm slots at 100 bar, Skydrol-like density and viscosity: closed by
    1 um, critical, and open 0.1 mm (L/min):

    >>> q = slot_flow(np.array([-1e-6, 0.0, 1e-4]), 10e6, 2e-6, 1.5e-6, 2, 4e-3, 1000.0, 1e-5, 0.65, 8.0)
    >>> [round(float(x) * 6e4, 4) for x in q]
    [0.0635, 0.0662, 4.2425]
    """
    _, S, D_h = orifice_geometry(X_i, r, c, n, w)
    u = bk.sqrt(2.0 / rho * smooth_abs(dp, p_tr))
    lam = D_h / nu * u
    K_g = continuity_constant(Cq_inf, lambda_t, w, c)
    Cq = discharge_coefficient(X_i, lam, Cq_inf, lambda_t, K_g)
    return Cq * S * u * smooth_sign(dp, p_tr)


#: The four orifices of the Wheatstone bridge ([MareAttarND] Fig. 1) and the metering edge each is
#: (:data:`hydroservo.laws.four_way.EDGES`): a supply to port 1 (A), b port 1 to return, c supply to
#: port 2 (B), d port 2 to return.
BRIDGE: dict[str, str] = {"a": "PA", "b": "AT", "c": "PB", "d": "BT"}

#: Parameters of the staged-slot bridge: name -> (SI unit, description).
BRIDGE_PARAMETERS: dict[str, tuple[str, str]] = {
    **{f"X_{i}0": ("m", f"opening of orifice {i} at null, low-gain stage (> 0 underlap, < 0 overlap)") for i in BRIDGE},
    **{f"X_{i}0H": ("m", f"opening of orifice {i} at null, high-gain stage (<= 0: closed at null)") for i in BRIDGE},
    "w_L": ("m", "slot width of the low-gain stage"),
    "w_H": ("m", "slot width of the high-gain stage (>= w_L; = w_L: no staging)"),
    "r": ("m", "rounded-edge radius"),
    "c": ("m", "spool-bushing radial clearance"),
    "n": ("", "number of slots per orifice"),
    "Cq_inf": ("", "turbulent limit of the flow coefficient"),
    "lambda_tL": ("", "transition flow number, low-gain stage"),
    "lambda_tH": ("", "transition flow number, high-gain stage"),
}

#: Width given to the high-gain stage of an unstaged slot (w_H = w_L): its flow is 1e-12 of the low stage's.
_NO_STAGE_WIDTH = 1e-15


def staged_slot_orifice_flow(
    i: str,
    X: Any,
    p_up: Any,
    p_down: Any,
    params: Mapping[str, Any],
    rho: Any,
    nu: Any,
    p_tr: Any = 0.0,
) -> Any:
    r"""Flow through orifice ``i`` of a staged-slot bridge, [MareAttarND] Table 1 and Fig. 5 [m^3/s].

    Each metering edge opens a staged slot (Fig. 5): a narrow part of width
    :math:`w_L` from the edge, then a wide part of width :math:`w_H`. The
    uncovered area is that of two orifices in parallel: the low-gain one of
    width :math:`w_L` and opening :math:`X_{i0} + \varepsilon X`, and the
    high-gain one of width :math:`w_H - w_L` and opening
    :math:`X_{i0H} + \varepsilon X` (closed, :math:`X_{i0H} < 0`, until the
    edge reaches the step). Both follow the 9-parameter law of Table 1
    (:func:`slot_flow`) with the shared r, c, n, :math:`C_{q\infty}` and their
    own :math:`\lambda_t` (eqs. 21 and 23 identify :math:`\lambda_{tL}` and
    :math:`\lambda_{tH}` separately). The high stage's closed-orifice flow is the
    leakage through the clearance over the wide part, as physical as the low one.

    Parameters
    ----------
    i : str
        Orifice name [-]: "a", "b", "c" or "d" (:data:`BRIDGE`).
    X : array_like
        Valve opening (spool position from hydraulic null) [m].
    p_up, p_down : array_like
        Pressures upstream and downstream of the orifice [Pa].
    params : mapping
        :data:`BRIDGE_PARAMETERS` [SI units].
    rho : array_like
        Density [kg/m^3].
    nu : array_like
        Kinematic viscosity [m^2/s].
    p_tr : array_like
        Regularisation pressure [Pa], see :func:`slot_flow`.

    Returns
    -------
    array_like
        Flow from upstream to downstream [m^3/s].

    References
    ----------
    [MareAttarND] Table 1, Figs. 1 and 5, eqs. (21), (23).
    """
    eps = EDGES[BRIDGE[i]][2]
    dp = p_up - p_down
    common = (params["r"], params["c"], params["n"])
    low = slot_flow(
        params[f"X_{i}0"] + eps * X,
        dp,
        *common,
        params["w_L"],
        rho,
        nu,
        params["Cq_inf"],
        params["lambda_tL"],
        p_tr,
    )
    w_extra = bk.fmax(params["w_H"] - params["w_L"], _NO_STAGE_WIDTH)
    high = slot_flow(
        params[f"X_{i}0H"] + eps * X,
        dp,
        *common,
        w_extra,
        rho,
        nu,
        params["Cq_inf"],
        params["lambda_tH"],
        p_tr,
    )
    return low + high


def staged_slot_valve_flows(
    X: Any,
    p_S: Any,
    p_T: Any,
    p_A: Any,
    p_B: Any,
    params: Mapping[str, Any],
    rho: Any,
    nu: Any,
    p_tr: Any = 0.0,
) -> tuple[Any, Any, Any, Any]:
    r"""Port flows of the staged-slot four-way valve: :func:`staged_slot_orifice_flow` in the bridge.

    Parameters
    ----------
    X : array_like
        Valve opening [m].
    p_S, p_T, p_A, p_B : array_like
        Supply, return and use-port pressures [Pa].
    params : mapping
        :data:`BRIDGE_PARAMETERS` [SI units].
    rho : array_like
        Density [kg/m^3].
    nu : array_like
        Kinematic viscosity [m^2/s].
    p_tr : array_like
        Regularisation pressure [Pa].

    Returns
    -------
    (Q_A, Q_B, Q_S, Q_T) : tuple of array_like
        [m^3/s], as :func:`hydroservo.laws.four_way.bridge_flows`.

    References
    ----------
    [MareAttarND] Fig. 1 and Table 1.
    """
    nodes = {"S": p_S, "T": p_T, "A": p_A, "B": p_B}

    def q(i: str) -> Any:
        up, down, _ = EDGES[BRIDGE[i]]
        return staged_slot_orifice_flow(i, X, nodes[up], nodes[down], params, rho, nu, p_tr)

    return bridge_flows(q("a"), q("b"), q("c"), q("d"))
