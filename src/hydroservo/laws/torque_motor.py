r"""Torque motor of a two-stage servovalve: armature and flapper driven by the coil current.

Two descriptions: the second-order armature of [FlightSimulatorND]
(:func:`armature_acceleration`, stiffnesses referred to the flapper tip), and
the electromagnetic torque of [GordicND] from the motor's geometry and magnet
(:func:`electromagnetic_torque`, eq. 4), its linearisation at null
(:func:`torque_gain`, :func:`magnetic_spring`, eqs. 5-6) and the magnetic
reluctance constant (:func:`reluctance_constant`, eqs. 7-9).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "MU_0",
    "armature_acceleration",
    "electromagnetic_torque",
    "torque_gain",
    "magnetic_spring",
    "reluctance_constant",
]

#: Magnetic permeability of vacuum [H/m].
MU_0 = 4e-7 * 3.141592653589793


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


def electromagnetic_torque(
    theta: Any, i: Any, r: Any, A_p: Any, x_p0: Any, M_m: Any, N: Any, k_c: Any = 1.0, k_r: Any = 0.0
) -> Any:
    r"""Torque of the electromagnetic forces on the armature, [GordicND] eq. (4).

    .. math:: T_e = \frac{r\mu_0 A_p}{x_{p0}^2}\left(M_m + k_c N\frac{r\theta}{x_{p0}}i\right)
              \frac{M_m\frac{r\theta}{x_{p0}} + k_c N (1 + k_r) i}
                   {\left[1 - \left(\frac{r\theta}{x_{p0}}\right)^2 + k_r\right]^2}

    for serial, parallel and push-pull coils alike (``k_c``): the magnet's
    flux and the coils' meet in the four air gaps, whose lengths change by
    :math:`\pm r\theta`. At null it is linear in ``i`` and ``theta`` with the
    slopes of :func:`torque_gain` and :func:`magnetic_spring`; away from it the
    gain grows with :math:`\theta` and the torque with :math:`i\theta`.

    Parameters
    ----------
    theta : array_like
        Armature rotation [rad].
    i : array_like
        Coil current :math:`i^*` (the total current, or the difference of the
        two coils' in push-pull) [A].
    r : array_like
        Distance from the armature pivot to the centre of a pole face [m].
    A_p : array_like
        Area of an air gap (pole face) [m^2].
    x_p0 : array_like
        Length of each air gap at null [m].
    M_m : array_like
        Magnetomotive force of the permanent magnet [A].
    N : array_like
        Turns of each coil [-].
    k_c : array_like
        Coil connection coefficient: 1 parallel, 2 serial or push-pull [-].
    k_r : array_like
        Magnetic reluctance constant (:func:`reluctance_constant`) [-].

    Returns
    -------
    array_like
        Torque on the armature [N*m].

    References
    ----------
    [GordicND] eq. (4), after Urata (2000); [Merritt1967] without ``k_r``.

    Examples
    --------
    The Table 1 motor of [GordicND] at 10 mA, armature at null (= :func:`torque_gain` times 10 mA):

    >>> round(float(electromagnetic_torque(0.0, 0.01, 14.5e-3, 9e-6, 0.45e-3, 586.0, 3625, 1.0, 0.465)) * 1e3, 3)
    11.743
    """
    g = r * theta / x_p0
    return (
        r * MU_0 * A_p / x_p0**2
        * (M_m + k_c * N * g * i)
        * (M_m * g + k_c * N * (1.0 + k_r) * i)
        / (1.0 - g**2 + k_r) ** 2
    )


def torque_gain(r: Any, A_p: Any, x_p0: Any, M_m: Any, N: Any, k_c: Any = 1.0, k_r: Any = 0.0) -> Any:
    r"""Torque-motor gain at null, :math:`K_i = \dfrac{k_c N r \mu_0 A_p M_m}{x_{p0}^2 (1 + k_r)}` [N*m/A].

    Parameters
    ----------
    r, A_p, x_p0, M_m, N, k_c, k_r : array_like
        As in :func:`electromagnetic_torque` [m, m^2, m, A, -, -, -].

    Returns
    -------
    array_like
        :math:`K_i = \partial T_e/\partial i` at :math:`i = \theta = 0` [N*m/A].

    References
    ----------
    [GordicND] eq. (5).

    Examples
    --------
    >>> round(float(torque_gain(14.5e-3, 9e-6, 0.45e-3, 586.0, 3625, 1.0, 0.465)), 4)
    1.1743
    """
    return k_c * N * r * MU_0 * A_p * M_m / (x_p0**2 * (1.0 + k_r))


def magnetic_spring(r: Any, A_p: Any, x_p0: Any, M_m: Any, k_r: Any = 0.0) -> Any:
    r"""Electromagnetic spring constant at null, :math:`K_m = \dfrac{r^2 \mu_0 A_p M_m^2}{x_{p0}^3 (1 + k_r)^2}` [N*m/rad].

    The torque grows with the rotation (:math:`T_e = K_i i + K_m\theta`, eq. 3):
    a negative stiffness that the flexure tube must overcome.

    Parameters
    ----------
    r, A_p, x_p0, M_m, k_r : array_like
        As in :func:`electromagnetic_torque` [m, m^2, m, A, -].

    Returns
    -------
    array_like
        :math:`K_m = \partial T_e/\partial\theta` at :math:`i = \theta = 0` [N*m/rad].

    References
    ----------
    [GordicND] eq. (6).

    Examples
    --------
    >>> round(float(magnetic_spring(14.5e-3, 9e-6, 0.45e-3, 586.0, 0.465)), 3)
    4.175
    """
    return r**2 * MU_0 * A_p * M_m**2 / (x_p0**3 * (1.0 + k_r) ** 2)


def reluctance_constant(l_m: Any, A_m: Any, mu_m: Any, k_m: Any, k_l: Any, x_p0: Any, A_p: Any) -> Any:
    r"""Magnetic reluctance constant, :math:`k_r = \dfrac{R_{mm}}{R_{mp0}}\dfrac{1}{k_l}` [-].

    With the magnet's reluctance :math:`R_{mm} = \dfrac{l_m}{A_m\mu_m}\dfrac{1}{k_m}`
    (eq. 8) and an air gap's at null :math:`R_{mp0} = \dfrac{x_{p0}}{\mu_0 A_p}`
    (eq. 9). Eq. (7) as extracted reads :math:`1/k_1`; the only constant of
    that name in the nomenclature is the leakage-flux constant :math:`k_l`.

    Parameters
    ----------
    l_m : array_like
        Length of the permanent magnet [m].
    A_m : array_like
        Cross-section of the permanent magnet [m^2].
    mu_m : array_like
        Permeability of the permanent magnet [H/m].
    k_m : array_like
        Constant of the non-uniform field in the magnet [-].
    k_l : array_like
        Constant of the leakage flux in the air gaps [-].
    x_p0, A_p : array_like
        Air gap length at null [m] and area [m^2].

    Returns
    -------
    array_like
        :math:`k_r` [-].

    References
    ----------
    [GordicND] eqs. (7)-(9), after Urata (2000).

    Examples
    --------
    Table 1 with the magnet's relative permeability 5 (``mu_m = 5 mu_0``):

    >>> round(float(reluctance_constant(10.9e-3, 154.68e-6, 5 * MU_0, 2.42, 0.27, 0.45e-3, 9e-6)), 3)
    0.431
    """
    R_mm = l_m / (A_m * mu_m) / k_m
    R_mp0 = x_p0 / (MU_0 * A_p)
    return R_mm / R_mp0 / k_l
