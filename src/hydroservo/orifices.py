"""Orifice and spool-valve flow laws.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.

Regularisation near zero pressure drop
--------------------------------------
The turbulent orifice law :math:`Q \\propto \\operatorname{sign}(\\Delta p)\\sqrt{|\\Delta p|}`
has an infinite slope at :math:`\\Delta p = 0`, which is where implicit solvers
fail (their Newton iterations need the Jacobian). Physically the flow there is
laminar, proportional to :math:`\\Delta p`. hydroservo blends the two with

.. math:: Q = C_d A \\sqrt{2/\rho}\\; \frac{\\Delta p}{(\\Delta p^2 + p_{tr}^2)^{1/4}}

which is odd, smooth (infinitely differentiable), strictly increasing in
:math:`\\Delta p`, linear for :math:`|\\Delta p| \\ll p_{tr}` and within
:math:`p_{tr}^2/(4\\Delta p^2)` of the turbulent law for :math:`|\\Delta p| \\gg p_{tr}`.
The transition pressure :math:`p_{tr}` is not a numerical constant: it is the
pressure drop at which the flow number of seed 002 eq. (4),
:math:`\\lambda = (D_h/\nu)\\sqrt{2|\\Delta p|/\rho}`, reaches its critical value
:math:`\\lambda_{crit}` (:func:`transition_pressure`). The flow number rather than the
Reynolds number is used because it needs no flow, so no algebraic loop
(seed 002, after Beck 1967). Default :math:`\\lambda_{crit} = 1000`, the usual
value for sharp-edged spool orifices (it is also AMESim's default critical flow
number).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import _math as m
from hydroservo.errors import ParameterError

__all__ = [
    "DISCHARGE_COEFFICIENT",
    "flow_number",
    "transition_pressure",
    "signed_sqrt",
    "orifice_flow",
    "opening",
    "flow_coefficient_from_catalogue",
    "four_way_valve_flows",
]

#: Theoretical discharge coefficient of a sharp-edged orifice, pi/(pi+2), seed 001 eq. (3.6).
DISCHARGE_COEFFICIENT = float(np.pi / (np.pi + 2.0))


def flow_number(D_h: Any, dp: Any, rho: Any, nu: Any) -> Any:
    r"""Flow number :math:`\lambda = \frac{D_h}{\nu}\sqrt{\frac{2}{\rho}|\Delta p|}` [-].

    Parameters
    ----------
    D_h : array_like
        Hydraulic diameter of the orifice [m].
    dp : array_like
        Pressure drop [Pa].
    rho : array_like
        Density [kg/m^3].
    nu : array_like
        Kinematic viscosity [m^2/s].

    References
    ----------
    Seed 002 (Maré & Attar) eq. (4), after Beck (1967).
    """
    return D_h / nu * m.sqrt(2.0 / rho * m.fabs(dp))


def transition_pressure(D_h: Any, rho: Any, nu: Any, lambda_crit: Any = 1000.0) -> Any:
    r"""Pressure drop at which the flow number reaches ``lambda_crit`` [Pa].

    .. math:: \Delta p_{tr} = \frac{\rho}{2}\left(\frac{\lambda_{crit}\,\nu}{D_h}\right)^2

    Parameters
    ----------
    D_h : array_like
        Hydraulic diameter [m]; for a spool port of width much larger than its
        opening ``x``, :math:`D_h = 2x`.
    rho : array_like
        Density [kg/m^3].
    nu : array_like
        Kinematic viscosity [m^2/s].
    lambda_crit : array_like
        Critical flow number [-], default 1000.

    References
    ----------
    Inverse of seed 002 eq. (4).

    Examples
    --------
    A 1 mm hydraulic diameter with an ISO VG 32 oil at 40 degC:

    >>> round(float(transition_pressure(1e-3, 870.0, 32e-6)) / 1e5, 2)
    4.45
    """
    return 0.5 * rho * (lambda_crit * nu / D_h) ** 2


def signed_sqrt(dp: Any, p_tr: Any = 0.0) -> Any:
    r"""The pressure term of the orifice law, :math:`\Delta p / (\Delta p^2 + p_{tr}^2)^{1/4}` [Pa^0.5].

    With ``p_tr = 0`` (NumPy input only) exactly
    :math:`\operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`; see the module notes.
    """
    if not m.is_symbolic(dp, p_tr) and np.all(np.asarray(p_tr) == 0):
        dp = np.asarray(dp, dtype=float)
        return np.sqrt(np.abs(dp)) * np.sign(dp)
    return dp / (dp**2 + p_tr**2) ** 0.25


def orifice_flow(A: Any, dp: Any, rho: Any, Cd: Any = DISCHARGE_COEFFICIENT, p_tr: Any = 0.0) -> Any:
    r"""Flow through an orifice, in the direction of the pressure drop.

    .. math:: Q = C_d A \sqrt{2/\rho}\; \frac{\Delta p}{(\Delta p^2 + p_{tr}^2)^{1/4}}

    With ``p_tr = 0`` this is the turbulent law of seed 001 eqs. (3.5) and
    (3.18), :math:`Q = C_d A\sqrt{2|\Delta p|/\rho}\,\operatorname{sign}(\Delta p)`.

    Parameters
    ----------
    A : array_like
        Orifice area [m^2].
    dp : array_like
        Pressure drop, upstream minus downstream [Pa].
    rho : array_like
        Density [kg/m^3].
    Cd : array_like
        Discharge coefficient [-], default pi/(pi+2) (seed 001 eq. 3.6).
    p_tr : array_like
        Laminar-turbulent transition pressure [Pa] (:func:`transition_pressure`);
        0 for the unregularised turbulent law (NumPy input only).

    Returns
    -------
    Volume flow [m^3/s], positive from upstream to downstream.

    References
    ----------
    Seed 001 (Efe 2014) eqs. (3.5), (3.18); regularisation: module notes.

    Examples
    --------
    >>> q = orifice_flow(1e-5, 35e5, 870.0, Cd=0.611)
    >>> round(float(q) * 6e4, 3)  # L/min
    32.884
    """
    return Cd * A * m.sqrt(2.0 / rho) * signed_sqrt(dp, p_tr)


def opening(x: Any) -> Any:
    r"""Opening of a control edge, :math:`f(x) = x` for :math:`x \ge 0`, else 0 [m].

    References
    ----------
    Seed 001 eq. (3.21).
    """
    return m.fmax(x, 0.0)


def flow_coefficient_from_catalogue(Q_N: float, dp_N: float, x_max: float) -> float:
    r"""Valve flow coefficient from catalogue data, :math:`c_v = \frac{Q_N}{\sqrt{\Delta p_N}\,x_{v,max}}`.

    Parameters
    ----------
    Q_N : float
        Nominal flow [m^3/s].
    dp_N : float
        Nominal pressure drop [Pa] *per control edge* at which ``Q_N`` is
        rated. Catalogues often rate at 70 bar across the valve, i.e. 35 bar
        per edge: pass 35 bar then.
    x_max : float
        Maximum spool stroke [m].

    Returns
    -------
    c_v [m^2/(s Pa^0.5)], such that one edge passes :math:`c_v x \sqrt{\Delta p}`.

    References
    ----------
    Seed 001 eq. (3.9).

    Examples
    --------
    >>> cv = flow_coefficient_from_catalogue(40 / 6e4, 35e5, 1e-3)
    >>> round(cv * 1e4, 4)
    3.5635
    """
    for name, val in (("Q_N", Q_N), ("dp_N", dp_N), ("x_max", x_max)):
        if not val > 0:
            raise ParameterError(f"{name}: {val!r}; expected a positive value")
    return float(Q_N / (np.sqrt(dp_N) * x_max))


def four_way_valve_flows(
    x_v: Any,
    p_S: Any,
    p_T: Any,
    p_A: Any,
    p_B: Any,
    c_v: Any,
    x_PA: Any = 0.0,
    x_AT: Any = 0.0,
    x_PB: Any = 0.0,
    x_BT: Any = 0.0,
    p_tr: Any = 0.0,
    G_leak: Any = 0.0,
    K: Any = 1.0,
) -> tuple[Any, Any, Any, Any]:
    r"""Flows of a four-way spool valve with per-edge overlap.

    .. math::
        Q_A &= c_v f(x_v - x_{PA})\,g(p_S - p_A) - c_v f(-x_v - x_{AT})\,g(p_A - p_T)\\
        Q_B &= c_v f(-x_v - x_{PB})\,g(p_S - p_B) - c_v f(x_v - x_{BT})\,g(p_B - p_T)

    with :math:`g(\Delta p) = \operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`
    regularised by :func:`signed_sqrt` and :math:`f` of :func:`opening`.
    Positive ``x_v`` connects P to A and B to T.

    Parameters
    ----------
    x_v : array_like
        Spool position [m].
    p_S, p_T, p_A, p_B : array_like
        Supply, tank and port pressures [Pa].
    c_v : array_like
        Flow coefficient [m^2/(s Pa^0.5)] (:func:`flow_coefficient_from_catalogue`).
    x_PA, x_AT, x_PB, x_BT : array_like
        Overlap of each control edge [m]; negative for underlap. Equal values
        give seed 001 eqs. (3.19)-(3.20) with :math:`x_o`; zero gives the
        critical-centre valve of seed 003 eqs. (3-18), (3-20), (3-22), (3-23).
    p_tr : array_like
        Transition pressure of the regularisation [Pa].
    G_leak : array_like
        Laminar leakage conductance of each edge [m^3/(s Pa)], in parallel with
        the orifice (radial clearance leakage).
    K : array_like
        Flow-coefficient compensation :math:`K(x_v)H(x_v,d_f)` [-], seed 001
        eqs. (3.22)-(3.23).

    Returns
    -------
    (Q_A, Q_B, Q_S, Q_T) [m^3/s]: flows out of the valve into lines A and B,
    into the valve from supply, and out of the valve to tank.

    References
    ----------
    Seed 001 eqs. (3.18)-(3.23); seed 003 eqs. (3-18), (3-20), (3-22), (3-23).
    """

    cvk = c_v * K
    q_PA = cvk * opening(x_v - x_PA) * signed_sqrt(p_S - p_A, p_tr) + G_leak * (p_S - p_A)
    q_AT = cvk * opening(-x_v - x_AT) * signed_sqrt(p_A - p_T, p_tr) + G_leak * (p_A - p_T)
    q_PB = cvk * opening(-x_v - x_PB) * signed_sqrt(p_S - p_B, p_tr) + G_leak * (p_S - p_B)
    q_BT = cvk * opening(x_v - x_BT) * signed_sqrt(p_B - p_T, p_tr) + G_leak * (p_B - p_T)
    return q_PA - q_AT, q_PB - q_BT, q_PA + q_PB, q_AT + q_BT
