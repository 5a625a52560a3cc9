r"""Torque motor of a two-stage servovalve: armature and flapper driven by the coil current.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

__all__ = ["armature_acceleration"]


def armature_acceleration(
    x_f: Any, v_f: Any, i: Any, x_v: Any, omega_n: Any, zeta_n: Any, K1: Any, Kf: Any, Kw: Any
) -> Any:
    r"""Flapper-tip acceleration of a force-feedback torque motor, [FlightSimulatorND] eq. (3-7).

    .. math:: \ddot x_f = -2\omega_n\zeta_n\dot x_f - \omega_n^2 x_f
              + \frac{K_1\omega_n^2}{K_f} I_s - \frac{K_w}{K_f}\omega_n^2 x_v

    The armature, flapper and flexure tube form a second-order system driven
    by the motor torque :math:`K_1 I_s` and pulled back by the feedback wire,
    whose force grows with the main-spool position :math:`x_v`; all
    stiffnesses are referred to the flapper tip as in eq. (3-6).

    Parameters
    ----------
    x_f : array_like
        Flapper displacement at the nozzles [m].
    v_f : array_like
        Flapper velocity [m/s].
    i : array_like
        Coil current :math:`I_s` [A].
    x_v : array_like
        Main-spool position [m].
    omega_n : array_like
        Natural frequency of the first stage [rad/s].
    zeta_n : array_like
        Damping ratio of the first stage [-].
    K1 : array_like
        Torque-motor gain [N*m/A].
    Kf : array_like
        Net stiffness of armature and flapper [N] (torque per flapper displacement).
    Kw : array_like
        Feedback-wire stiffness [N] (torque per spool displacement).

    Returns
    -------
    array_like
        :math:`\ddot x_f` [m/s^2].

    References
    ----------
    [FlightSimulatorND] eqs. (3-6), (3-7), after [Merritt1967].

    Examples
    --------
    In equilibrium the motor torque balances the feedback wire, K1 I = Kw x_v:

    >>> abs(float(armature_acceleration(0.0, 0.0, 0.01, 0.01 * 3.5 / 10.7, 4580.0, 0.4, 3.5, 400.0, 10.7))) < 1e-9
    True
    """
    wn2 = omega_n**2
    return -2.0 * omega_n * zeta_n * v_f - wn2 * x_f + K1 * wn2 / Kf * i - Kw / Kf * wn2 * x_v
