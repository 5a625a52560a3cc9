r"""Armature assembly of a flapper-nozzle servovalve: flexure tube, flapper bending, feedback spring, impact.

The armature and flapper turn about a pivot in the flexure tube; the flexure
tube and the flapper bend as beams under the flow force on the flapper
([GordicND] section 2.3, after Urata 1999). Flapper-tip displacement ``x`` is
positive towards the right nozzle (the left nozzle's gap is :math:`x_0 - x`);
the flow force :math:`F_h` is positive when it pushes the flapper back
towards the null from the left, as in eqs. (13)-(14).

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk

__all__ = [
    "pivot_distance",
    "flexure_torque",
    "flapper_flow_force",
    "flapper_tip",
    "flapper_inclination",
    "feedback_spring_force",
    "impact_torque",
]


def pivot_distance(l_fl: Any, l_t: Any) -> Any:
    r"""Distance from the nozzle axis to the armature's axis of rotation, :math:`l_a = l_{fl} - l_t/2` [m].

    The flexure tube bends so that the armature assembly turns about the
    middle of the tube.

    Parameters
    ----------
    l_fl : array_like
        Flapper length (nozzle axis to the tube's clamped end) [m].
    l_t : array_like
        Flexure tube length [m].

    Returns
    -------
    array_like
        :math:`l_a` [m].

    References
    ----------
    [GordicND] eq. (11).

    Examples
    --------
    Table 1 (13 mm flapper, 8.5 mm tube): 8.75 mm, as Table 1 lists for :math:`l_a`:

    >>> round(float(pivot_distance(13e-3, 8.5e-3)) * 1e3, 2)
    8.75
    """
    return l_fl - l_t / 2.0


def flexure_torque(theta: Any, B_t: Any, l_t: Any) -> Any:
    r"""Torque of the bent flexure tube on the armature, :math:`T_t = B_t\theta/l_t` [N*m].

    Parameters
    ----------
    theta : array_like
        Armature rotation [rad].
    B_t : array_like
        Bending rigidity of the flexure tube [N*m^2].
    l_t : array_like
        Flexure tube length [m].

    Returns
    -------
    array_like
        :math:`T_t` [N*m].

    References
    ----------
    [GordicND] eq. (12).

    Examples
    --------
    >>> round(float(flexure_torque(1e-3, 0.0302, 8.5e-3)) * 1e3, 3)  # mN*m for 1 mrad
    3.553
    """
    return B_t / l_t * theta


def flapper_flow_force(
    p_l: Any, p_r: Any, p_d: Any, x: Any, x0: Any, d_n: Any, K_nl: Any, K_nr: Any
) -> Any:
    r"""Flow force of the two nozzle jets on the flapper, [GordicND] eq. (13).

    .. math:: F_h = (p_l - p_r)\frac{\pi d_n^2}{4}
              + 8\pi\left[K_{nl}^2 (x_0 - x)^2 (p_l - p_d) - K_{nr}^2 (x_0 + x)^2 (p_r - p_d)\right]

    The static pressure on the nozzle faces, and the momentum of the jets
    leaving through the curtain areas :math:`\pi d_n (x_0 \mp x)` (flapper-tip
    velocity neglected).

    Parameters
    ----------
    p_l, p_r : array_like
        Left and right nozzle pressures [Pa].
    p_d : array_like
        Pressure in the drain compartment [Pa].
    x : array_like
        Flapper-tip displacement towards the right nozzle [m].
    x0 : array_like
        Gap between flapper tip and each nozzle at null [m].
    d_n : array_like
        Nozzle diameter [m].
    K_nl, K_nr : array_like
        Flow coefficients of the left and right flapper-nozzle restrictions [-].

    Returns
    -------
    array_like
        :math:`F_h` [N], positive from the left nozzle's side.

    References
    ----------
    [GordicND] eq. (13).

    Examples
    --------
    Centred flapper, equal nozzle pressures: the jets balance.

    >>> float(flapper_flow_force(70e5, 70e5, 5e5, 0.0, 38.5e-6, 0.28e-3, 0.65, 0.65))
    0.0
    """
    area = np.pi * d_n**2 / 4.0
    jets = K_nl**2 * (x0 - x) ** 2 * (p_l - p_d) - K_nr**2 * (x0 + x) ** 2 * (p_r - p_d)
    return (p_l - p_r) * area + 8.0 * np.pi * jets


def flapper_tip(theta: Any, F_h: Any, l_a: Any, l_fl: Any, B_fl: Any, l_t: Any, B_t: Any) -> Any:
    r"""Flapper-tip displacement with the flapper and the flexure tube bent by the flow force, [GordicND] eq. (14).

    .. math:: x = \theta l_a - F_h\left(\frac{l_{fl}^3}{3 B_{fl}} + \frac{l_t^3}{12 B_t}\right)

    The tip does not follow the armature rotation alone: the flow force bends
    the flapper (a cantilever) and the tube. Since :math:`F_h` depends on
    :math:`x` (eq. 13), eqs. (13)-(14) are implicit in :math:`x`.

    Parameters
    ----------
    theta : array_like
        Armature rotation [rad].
    F_h : array_like
        Flow force on the flapper (:func:`flapper_flow_force`) [N].
    l_a : array_like
        Pivot distance (:func:`pivot_distance`) [m].
    l_fl : array_like
        Flapper length [m].
    B_fl : array_like
        Bending rigidity of the flapper [N*m^2].
    l_t : array_like
        Flexure tube length [m].
    B_t : array_like
        Bending rigidity of the flexure tube [N*m^2].

    Returns
    -------
    array_like
        :math:`x` [m].

    References
    ----------
    [GordicND] eq. (14), after Urata (1999).

    Examples
    --------
    1 mrad of armature rotation and 0.1 N of flow force, Table 1 geometry (um):

    >>> round(float(flapper_tip(1e-3, 0.1, 8.75e-3, 13e-3, 0.0256, 8.5e-3, 0.0302)) * 1e6, 2)
    5.72
    """
    return theta * l_a - F_h * (l_fl**3 / (3.0 * B_fl) + l_t**3 / (12.0 * B_t))


def flapper_inclination(theta: Any, F_h: Any, l_fl: Any, B_fl: Any) -> Any:
    r"""Inclination of the flapper's free end, :math:`\varphi = \theta - F_h l_{fl}^2/(2 B_{fl})` [rad].

    Parameters
    ----------
    theta : array_like
        Armature rotation [rad].
    F_h : array_like
        Flow force on the flapper [N].
    l_fl : array_like
        Flapper length [m].
    B_fl : array_like
        Bending rigidity of the flapper [N*m^2].

    Returns
    -------
    array_like
        :math:`\varphi` [rad].

    References
    ----------
    [GordicND] eq. (18).

    Examples
    --------
    >>> round(float(flapper_inclination(1e-3, 0.1, 13e-3, 0.0256)) * 1e3, 4)  # mrad
    0.6699
    """
    return theta - F_h * l_fl**2 / (2.0 * B_fl)


def feedback_spring_force(y: Any, x: Any, phi: Any, l_f: Any, K_f: Any, z: Any) -> Any:
    r"""Force between the feedback spring's ball and the spool, with the ball's clearance, [GordicND] eqs. (16)-(17).

    .. math:: y_{ff} = x + l_f\varphi, \qquad
              F_f = \begin{cases} 0, & |y + y_{ff}| < z\\
                    K_f\,[y + y_{ff} - z\,\operatorname{sgn}(y + y_{ff})], & |y + y_{ff}| \ge z\end{cases}

    :math:`y_{ff}` is where the ball would be without the spool; the spring
    is deflected by :math:`y + y_{ff}` once the clearance :math:`2z` is taken
    up (a dead band, continuous in the force).

    Parameters
    ----------
    y : array_like
        Spool displacement [m].
    x : array_like
        Flapper-tip displacement [m].
    phi : array_like
        Inclination of the flapper's free end (:func:`flapper_inclination`) [rad].
    l_f : array_like
        Feedback spring length (flapper tip to ball) [m].
    K_f : array_like
        Feedback spring stiffness [N/m].
    z : array_like
        Half the ball's clearance [m].

    Returns
    -------
    array_like
        :math:`F_f` [N]; its torque on the armature is :math:`T_f = F_f l_f` (eq. 15).

    References
    ----------
    [GordicND] eqs. (15)-(17), after van Wel (1992).

    Examples
    --------
    Inside the clearance no force; beyond it the spring's:

    >>> float(feedback_spring_force(1e-6, 0.0, 0.0, 13.3e-3, 1962.0, 2e-6))
    0.0
    >>> round(float(feedback_spring_force(10e-6, 0.0, 0.0, 13.3e-3, 1962.0, 2e-6)) * 1e3, 3)  # mN
    15.696
    """
    s = y + x + l_f * phi
    return K_f * (s - bk.fmin(bk.fmax(s, -z), z))


def impact_torque(x: Any, x0: Any, k_i: Any, l_a: Any) -> Any:
    r"""Torque of the flapper pressing against a nozzle, :math:`T_i = k_i(|x| - x_0)\operatorname{sgn}(x)\,l_a` once :math:`|x| \ge x_0` [N*m].

    An elastic impact, as rough as the source says it is: it only keeps the
    armature from passing through the nozzle.

    Parameters
    ----------
    x : array_like
        Flapper-tip displacement [m].
    x0 : array_like
        Gap at null [m].
    k_i : array_like
        "Impact stiffness" (lateral rigidity of the nozzle tube) [N/m].
    l_a : array_like
        Pivot distance [m].

    Returns
    -------
    array_like
        :math:`T_i` [N*m], 0 while the flapper is free.

    References
    ----------
    [GordicND] eq. (19), after Vilenius and Vivaldo (1976).

    Examples
    --------
    1 um into the right nozzle with Table 1's stiffness:

    >>> round(float(impact_torque(39.5e-6, 38.5e-6, 3e7, 8.75e-3)), 4)  # N*m
    0.2625
    """
    return k_i * (x - bk.fmin(bk.fmax(x, -x0), x0)) * l_a
