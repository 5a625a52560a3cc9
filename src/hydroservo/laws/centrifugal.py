r"""Centrifugal pumps: the impeller's theoretical pressure (Euler's pump equation), the flow it drives through the
pump's losses, and the torque that takes.

An impeller of outlet diameter :math:`d` and outlet width :math:`b` turning at :math:`\omega` moves its outlet at
:math:`U_2 = \omega d/2`; the flow :math:`Q` leaves it radially at :math:`c_{m2} = Q/(\pi d b)` along blades at the
outlet angle :math:`\beta_2`, so its whirl is :math:`c_{u2} = U_2 - c_{m2}\cot\beta_2`, and with no whirl at the
inlet the pressure it gives the fluid is Euler's :math:`\Delta p_{th} = \rho U_2 c_{u2}`
(:func:`theoretical_pressure`). The pump's losses are a turbulent loss of :math:`k_l` dynamic heads at the outlet
area :math:`A_p`, so the flow is that of an orifice across which :math:`\Delta p_{th}` less the pressure the pump
delivers against acts (:func:`impeller_flow`), and the shaft takes the power given to the fluid over its speed
(:func:`shaft_torque`). These are the laws of Hopsan's centrifugal pumps ([Hopsan2026]
HydroDynamicComponents/HydraulicCentrifugalPump.hpp, HydraulicCentrifugalPumpJ.hpp, and the Mathematica
notebooks beside them that generate their code).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.laws.orifice import turbulent_flow

__all__ = [
    "LOSS_VELOCITY_SQUARED",
    "SPEED_REGULARISATION",
    "theoretical_pressure",
    "loss_transition_pressure",
    "impeller_flow",
    "hydraulic_power",
    "shaft_torque",
]

#: The square of the loss velocity below which Hopsan's pumps make their loss laminar, 10 m²/s² (the ``x0`` of
#: its signedSquareL in HydraulicCentrifugalPump.hpp): a transition pressure of :math:`k_l\rho/2` times it.
LOSS_VELOCITY_SQUARED = 10.0

#: The speed added to :math:`|\omega|` where the torque divides the power by the speed, 0.001 rad/s (Hopsan's),
#: so that a pump at rest takes a finite torque.
SPEED_REGULARISATION = 1e-3


def theoretical_pressure(omega: Any, Q: Any, d: Any, b: Any, beta2: Any, rho: Any, slip_density: Any = None) -> Any:
    r"""The pressure an impeller gives the fluid, Euler's pump equation for a radial inlet [Pa].

    .. math:: \Delta p_{th} = \rho\,U_2^2 - \rho_s\,U_2\,\frac{Q\cot\beta_2}{\pi d b}, \qquad U_2 = \frac{\omega d}{2}

    with :math:`\rho_s = \rho` (Euler). Hopsan's pumps write the second term with :math:`\rho^2` in place of
    :math:`\rho` (their notebooks' :math:`(U_2^2 - \rho U_2 Q/(\pi d b\tan\beta_2))\rho`, a density too many, which
    their numbers take in kg/m³): give ``slip_density`` :math:`\rho^2 \cdot 1\,\mathrm{m^3/kg}` for their law.

    Parameters
    ----------
    omega : array_like
        Impeller speed [rad/s].
    Q : array_like
        Flow through the impeller [m^3/s].
    d : array_like
        Impeller outlet diameter [m].
    b : array_like
        Impeller outlet width [m].
    beta2 : array_like
        Blade angle at the outlet [rad] (π/2: radial blades, no slip term).
    rho : array_like
        Density [kg/m^3].
    slip_density : array_like, optional
        The density of the second term [kg/m^3]; None: ``rho`` (Euler's).

    Returns
    -------
    array_like
        Pressure rise of the ideal impeller [Pa].

    References
    ----------
    Euler's pump equation, as [Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp writes it (with
    its :math:`\rho^2`: ``slip_density``).

    Examples
    --------
    Radial blades: :math:`\rho U_2^2`, 860 kg/m³ at 18.9 m/s:

    >>> round(float(theoretical_pressure(126.0, 0.08, 0.3, 0.03, np.pi / 2, 860.0)))
    307201
    """
    u2 = 0.5 * omega * d
    rho_s = rho if slip_density is None else slip_density
    return rho * u2 * u2 - rho_s * u2 * Q / (np.pi * d * b * bk.tan(beta2))


def loss_transition_pressure(kl: Any, rho: Any) -> Any:
    r"""The pressure drop below which a pump's loss is laminar, :math:`k_l \rho\, v_t^2/2` [Pa], with Hopsan's
    :math:`v_t^2` of :data:`LOSS_VELOCITY_SQUARED`.

    Parameters
    ----------
    kl : array_like
        Loss coefficient: dynamic heads lost at the outlet area [-].
    rho : array_like
        Density [kg/m^3].

    Returns
    -------
    array_like
        Transition pressure of :func:`hydroservo.laws.orifice.signed_sqrt` [Pa].

    References
    ----------
    [Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp (signedSquareL of the loss velocity squared
    with x0 = 10).

    Examples
    --------
    >>> float(loss_transition_pressure(0.1, 860.0))
    430.0
    """
    return 0.5 * kl * rho * LOSS_VELOCITY_SQUARED


def impeller_flow(dp_th: Any, dp: Any, Ap: Any, kl: Any, rho: Any, p_tr: Any = 0.0) -> Any:
    r"""The flow an impeller drives against the pressure rise ``dp`` through its losses [m^3/s].

    .. math:: Q = A_p\sqrt{\frac{2}{k_l\rho}}\;\operatorname{sign}(\Delta p_{th} - \Delta p)\sqrt{|\Delta p_{th} -
              \Delta p|}

    (the pressure the impeller gives, less what the pump delivers against, lost as :math:`k_l` dynamic heads
    :math:`\rho Q^2/(2A_p^2)`): the turbulent law of :func:`hydroservo.laws.orifice.turbulent_flow`, regularised
    below ``p_tr`` (:func:`loss_transition_pressure` for Hopsan's law). Since :math:`\Delta p_{th}` falls with
    :math:`Q` (:func:`theoretical_pressure`), a pump's flow solves :math:`Q = f(\Delta p_{th}(Q))`.

    Parameters
    ----------
    dp_th : array_like
        Theoretical pressure of the impeller [Pa].
    dp : array_like
        Pressure rise across the pump, outlet minus inlet [Pa].
    Ap : array_like
        Outlet flow area [m^2].
    kl : array_like
        Loss coefficient [-].
    rho : array_like
        Density [kg/m^3].
    p_tr : array_like
        Transition pressure of the regularisation [Pa]; 0 for the law as written (NumPy input only).

    Returns
    -------
    array_like
        Flow from inlet to outlet [m^3/s].

    References
    ----------
    [Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp (``Ap signedSquareL(2 (p1 - p2 + Δp_th)/(kl
    ρ), 10)``).

    Examples
    --------
    1 bar of loss through 10 cm² with kl = 0.1 at 860 kg/m³, about 48 L/s:

    >>> round(float(impeller_flow(3e5, 2e5, 1e-3, 0.1, 860.0)), 5)
    0.04822
    """
    return turbulent_flow(Ap * bk.sqrt(2.0 / (kl * rho)), dp_th - dp, p_tr)


def hydraulic_power(dp: Any, Q: Any, Q_i: Any, Ap: Any, kl: Any, rho: Any) -> Any:
    r"""The power a pump gives the fluid: the pressure rise and the loss at its delivery times the impeller's
    flow [W].

    .. math:: P = \left(\Delta p + \frac{k_l\rho\,Q^2}{2A_p^2}\right) Q_i

    Parameters
    ----------
    dp : array_like
        Pressure rise across the pump, outlet minus inlet [Pa].
    Q : array_like
        Flow delivered [m^3/s].
    Q_i : array_like
        Flow through the impeller (delivered plus leaked back) [m^3/s].
    Ap : array_like
        Outlet flow area [m^2].
    kl : array_like
        Loss coefficient [-].
    rho : array_like
        Density [kg/m^3].

    Returns
    -------
    array_like
        Power [W].

    References
    ----------
    [Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPumpJ.hpp (its notebook's power balance
    ``(p2 + kl q2² ρ/(2 Ap²) - p1)(q2e - Kcp (p1 - p2))``).

    Examples
    --------
    >>> round(float(hydraulic_power(2e5, 0.05, 0.05, 1e-3, 0.1, 860.0)))
    15375
    """
    return (dp + 0.5 * kl * rho * Q * Q / (Ap * Ap)) * Q_i


def shaft_torque(power: Any, omega: Any, B: Any = 0.0, omega_reg: Any = SPEED_REGULARISATION) -> Any:
    r"""The torque a pump's shaft takes: its viscous friction and the power it gives the fluid over its speed
    [N m].

    .. math:: T = B\,\omega + \frac{P}{|\omega| + \omega_{reg}}

    Parameters
    ----------
    power : array_like
        Power given to the fluid [W] (:func:`hydraulic_power`).
    omega : array_like
        Shaft speed [rad/s].
    B : array_like
        Viscous friction coefficient [N m s/rad].
    omega_reg : array_like
        Speed that keeps the torque finite at rest [rad/s] (Hopsan's 0.001).

    Returns
    -------
    array_like
        Torque [N m], along the speed.

    References
    ----------
    [Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp (``torp``), HydraulicCentrifugalPumpJ.hpp.

    Examples
    --------
    >>> round(float(shaft_torque(22073.0, 126.0)), 2)
    175.18
    """
    return B * omega + power / (bk.fabs(omega) + omega_reg)
