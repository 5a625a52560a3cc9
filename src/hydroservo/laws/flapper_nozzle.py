r"""Flapper-nozzle pilot stage of a two-stage servovalve driving the main spool.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.

Re-derivation of [FlightSimulatorND] eq. (3-16)
-----------------------------------------------
The extraction dropped the derivative dots. From eqs. (3-9) to (3-12) without
flow forces, :math:`A_v P_{Lv} = M_v s^2 x_v` and
:math:`P_{Lv}(K_{ce} + V_v s/4\beta) = K_2 x_f - A_v s x_v`, hence

.. math:: x_v\left(\frac{s^3}{\omega_h^2} + \frac{2\delta_h}{\omega_h}s^2 + s\right)
          = \frac{K_2}{A_v} x_f,
          \quad \omega_h^2 = \frac{4\beta A_v^2}{M_v V_v},
          \quad \delta_h = \frac{\omega_h K_{ce} M_v}{2A_v^2}

(eq. 3-14 with D = E = 0), i.e.
:math:`\dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v`.
The analog pot values of Appendix D confirm each coefficient: P101 =
:math:`K_2\omega_h^2/(10^{10}A_v)` = 0.6375, P38 = :math:`2\delta_h\omega_h/10^4` = 0.388,
P15 = :math:`\omega_h^2/10^7` = 0.376. The spool is an integrator of flapper
displacement: it stops only when :math:`x_f = 0`, which the torque motor
reaches when :math:`K_1 I_s = K_w x_v` (section 5.2.1).
"""

from __future__ import annotations

from typing import Any

__all__ = ["spool_jerk"]


def spool_jerk(x_f: Any, v_v: Any, a_v: Any, K2: Any, Av: Any, omega_h: Any, delta_h: Any) -> Any:
    r"""Main-spool jerk driven by the flapper-nozzle flow, [FlightSimulatorND] eq. (3-16) re-derived.

    .. math:: \dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v

    Flow forces (terms D and E of eq. 3-15) are left out, as in the
    dissertation's final model (its Appendix A found them negligible).

    Parameters
    ----------
    x_f : array_like
        Flapper displacement [m].
    v_v : array_like
        Spool velocity [m/s].
    a_v : array_like
        Spool acceleration [m/s^2].
    K2 : array_like
        Flapper-nozzle flow gain [m^2/s].
    Av : array_like
        Spool end area [m^2].
    omega_h : array_like
        Natural frequency of the spool stage [rad/s].
    delta_h : array_like
        Damping ratio of the spool stage [-].

    Returns
    -------
    array_like
        :math:`\dddot x_v` [m/s^3].

    References
    ----------
    [FlightSimulatorND] eqs. (3-9)-(3-16) and Appendix D.

    Examples
    --------
    With the flapper centred and the spool at rest nothing moves:

    >>> float(spool_jerk(0.0, 0.0, 0.0, 0.12, 7.1e-5, 1940.0, 1.0))
    0.0
    """
    wh2 = omega_h**2
    return K2 / Av * wh2 * x_f - 2.0 * delta_h * omega_h * a_v - wh2 * v_v
