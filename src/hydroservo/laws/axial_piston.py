r"""The axial piston machine: the valve plate's port openings, the swash plate's piston strokes.

An in-line axial piston machine has N pistons in a cylinder block that turns with the shaft. Each piston's foot
slides on a swash plate tilted by :math:`\gamma`, so that at the block's angle :math:`\theta` a piston on the
pitch radius :math:`r` is pushed in and out by :math:`r\tan\gamma` about its mean position
(:func:`swash_plate_piston`); each cylinder bore meets the valve plate, whose two kidney-shaped ports (suction and
delivery) it passes in turn: the area through which the bore's oil reaches a port is a function of the angle
(:func:`valve_plate_opening`), with notches (V-grooves) that open it gradually before the kidney and round ends
after. Hopsan's valve plate, cylinder block and pump piston ([Hopsan2026] Hydraulic/MachineParts/) are these
laws.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units. Citation keys in brackets are those of
:mod:`hydroservo.references`.
"""

from __future__ import annotations

import math
from typing import Any

from hydroservo import backend as bk

__all__ = ["swash_plate_piston", "valve_plate_opening"]


def swash_plate_piston(theta: Any, omega: Any, r: Any, gamma: Any, phase: Any) -> tuple[Any, Any, Any]:
    r"""A piston on a swash plate: its stroke, its velocity and its arm on the block.

    .. math:: x = r\tan\gamma\,\sin a,\quad \dot x = -r\tan\gamma\,\cos a\;\omega,\quad
              \frac{\partial x}{\partial\theta} = -r\tan\gamma\,\cos a,\qquad a = -\theta - \varphi

    The block turns by :math:`\theta` at :math:`\omega = \dot\theta`; the piston at phase :math:`\varphi` (its
    place on the pitch circle and the plate's offset) is :math:`x` out of its mean position along its axis. A
    force :math:`F` pushing the piston along +x turns the block by the torque :math:`F\,\partial x/\partial\theta`
    (virtual work); the power the pistons take from the block is :math:`-\sum F\dot x`.

    Parameters
    ----------
    theta : array_like
        Angle of the cylinder block [rad].
    omega : array_like
        Its angular velocity [rad/s].
    r : array_like
        Pitch radius of the pistons on the swash plate [m].
    gamma : array_like
        Swash plate angle [rad].
    phase : array_like
        The piston's phase [rad]: the plate's offset plus 2π k/N for the k-th of N pistons.

    Returns
    -------
    tuple of array_like
        Stroke x [m], velocity [m/s] and arm ∂x/∂θ [m/rad].

    References
    ----------
    [Hopsan2026] Hydraulic/MachineParts/MechanicCylinderBlockWithSwashPlate.hpp (this law: its pistons at
    :math:`x_0 + r\tan\gamma\sin a` moving at :math:`-r\tan\gamma\cos a\,\omega` for the block's
    :math:`a = -\theta - \theta_{offset} - 2\pi i/N`, their forces turning it through :math:`r\tan\gamma\cos a`).

    Examples
    --------
    A quarter turn ahead of its mean position, a piston is at full stroke and at rest:

    >>> import math
    >>> x, v, arm = swash_plate_piston(0.0, 100.0, 0.05, math.atan(0.2), -math.pi / 2)
    >>> round(float(x), 6), round(float(v), 6), round(float(arm), 6)
    (0.01, -0.0, -0.0)
    """
    a = -theta - phase
    stroke = r * bk.tan(gamma)
    arm = -stroke * bk.cos(a)
    return stroke * bk.sin(a), arm * omega, arm


def _fmod(a: Any, b: float) -> Any:
    """C's fmod: ``a - b trunc(a/b)``, of the sign of ``a`` (Hopsan's ``fmod``)."""
    q = a / b
    return a - b * bk.sign(q) * bk.floor(bk.fabs(q))


def _segment(d: Any, r: Any) -> Any:
    """Hopsan's area of a round end of radius r uncovered as its chord's distance d runs from 2r to 0:
    2r² acos(d/2r) - d √(4r² - d²)/2 (d held within [0, 2r], where the law is used)."""
    d = bk.clip(d, 0.0, 2.0 * r)
    return 2.0 * r * r * bk.acos(d / (2.0 * r)) - 0.5 * d * bk.sqrt(bk.fmax(4.0 * r * r - d * d, 0.0))


def valve_plate_opening(
    theta: Any,
    start: Any,
    phi_P: Any,
    Delta_alpha: Any,
    alpha_f: Any,
    phi_1: Any,
    phi_2: Any,
    theta_1: Any,
    theta_2: Any,
    R_f: Any,
    periodic: bool = True,
) -> Any:
    r"""The area through which a cylinder bore reaches a kidney port of the valve plate [m^2].

    The bore passes the port as the block turns; :math:`x = R_f\,\operatorname{fmod}(\theta - \theta_s -
    \alpha_{min}, 2\pi)` is the arc it has travelled from where the port's first notch begins, with
    :math:`\alpha_{min} = \pi/2 - \varphi_P/2 - \varphi_1 - \Delta\alpha` (the port is centred on a quarter turn
    past its start :math:`\theta_s`), and the angles made arcs on the groove's centre line :math:`R_f`:
    :math:`g_1 = R_f\varphi_1`, :math:`g_2 = R_f\varphi_2` the notches before and after the kidney,
    :math:`r = R_f\Delta\alpha` its rounded ends, :math:`R = R_f\alpha_f` the bore's port, :math:`\phi =
    R_f\varphi_P` the groove. The area, with :math:`t = \tan\theta_1`, :math:`k = \tan(\theta_2/2)` and
    :math:`k_2 = \pi r^2/2`, :math:`k_3 = g_1^2t^2k`, :math:`k_5 = g_2^2\tan^2\theta_1\tan(\theta_2/2)`, is, the
    first of these ranges that holds :math:`x` counting:

    * :math:`[0, g_1]`: the first notch, :math:`\min(x^2 t k,\; x^2 t^2 k)`;
    * :math:`[g_1, g_1 + 2r]`: :math:`k_3` and the round end uncovered,
      :math:`2r^2\arccos(d/2r) - d\sqrt{4r^2 - d^2}/2`, :math:`d = 2r - x + g_1`;
    * :math:`[g_1 + 2r, R]`: :math:`k_3 + 2k_2 + 2r(x - g_1 - 2r)`;
    * :math:`[R, R + g_1]`: :math:`\min(y^2 t k,\; y^2 t^2 k) + 2k_2 + 2r(x - g_1 - 2r)`, :math:`y = g_1 + R - x`;
    * :math:`[R + g_1, g_1 + \phi]`: the bore fully open, :math:`2k_2 + 2r(R - 2r)`;
    * :math:`[g_1 + \phi, g_1 + \phi + g_2]`: :math:`2k_2 + 2r(R - 2r + \phi + g_1 - x) + \min(y^2 w_2/(2g_1),\;
      y^2 t^2 k)`, :math:`y = x - g_1 - \phi`, :math:`w_2 = 2g_2\tan\theta_1\tan(\theta_2/2)`;
    * :math:`[g_1 + \phi + g_2, g_1 + \phi + R - 2r]`: :math:`2k_2 + 2r(R - 2r + \phi + g_1 - x) + k_5`;
    * :math:`[g_1 + \phi + R - 2r, g_1 + \phi + R]`: the round end covered, the segment above with
      :math:`d = x - g_1 - \phi - R + 2r`, plus :math:`k_5`;
    * :math:`[g_1 + \phi + R, g_1 + \phi + R + g_2]`: :math:`\min(y^2 w_2/(2g_1),\; y^2 t^2 k)`,
      :math:`y = R + g_1 + \phi + g_2 - x`;

    and 0 elsewhere. This is Hopsan's law as its valve plate evaluates it, term for term: where its ranges overlap
    (the round ends longer than the bore's port, :math:`g_1 + 2r > R`) the first one counts, the notch after the
    kidney is scaled by :math:`g_1` and :math:`\theta_1` as written there, and the area is not continuous
    everywhere. The position along the groove is :math:`x = R_f\,((\theta - \theta_s - \alpha_{min}) \bmod 2\pi)`,
    :math:`\alpha_{min} = \pi/2 - \phi_P/2 - \phi_1 - \Delta\alpha`: the plate is the same every turn. With
    ``periodic`` false the angle is measured as Hopsan's plate measures it, which is not a rotation: before the
    bore first reaches the notch (:math:`\theta - \theta_s - \alpha_{min} < 0`) the port is closed, and a
    negative :math:`\theta` counts as :math:`2\pi - \operatorname{fmod}(|\theta| - \theta_s - \alpha_{min},
    2\pi)`; a block starting at 0 leaves some bores shut to both kidneys for most of its first turn.

    Parameters
    ----------
    theta : array_like
        Angle of the cylinder block relative to the plate [rad].
    start : array_like
        Where this bore's port begins, its place on the block [rad] (2π k/N for the k-th of N bores; π further
        for the second kidney).
    phi_P : array_like
        Length of the kidney (groove) [rad].
    Delta_alpha : array_like
        Length of its rounded ends [rad].
    alpha_f : array_like
        Length of the bore's port [rad].
    phi_1, phi_2 : array_like
        Lengths of the notches (pre-compression grooves) before and after the kidney [rad].
    theta_1, theta_2 : array_like
        The notches' angles: their slope and their V's opening [rad].
    R_f : array_like
        Radius of the groove's centre line [m].
    periodic : bool
        The same plate every turn (default), or Hopsan's measure of the angle (not periodic: above) [-].

    Returns
    -------
    array_like
        Opening area [m^2].

    References
    ----------
    [Hopsan2026] Hydraulic/MachineParts/HydraulicValvePlate.hpp (``groove``, this law).

    Examples
    --------
    A bore in the middle of the kidney is open by its full port, 2k₂ + 2r(R - 2r) = 2rR - (4 - π)r²:

    >>> import math
    >>> deg = math.pi / 180
    >>> a = valve_plate_opening(90 * deg, 0.0, 128 * deg, 8 * deg, 30 * deg, 20 * deg, 20 * deg, 6 * deg,
    ...                         90 * deg, 0.03)
    >>> r, R = 0.03 * 8 * deg, 0.03 * 30 * deg
    >>> round(float(a) * 1e6, 3), round((2 * r * R - (4 - math.pi) * r * r) * 1e6, 3)
    (116.533, 116.533)
    """
    two_pi = 2.0 * math.pi
    min_angle = math.pi / 2 - phi_P / 2.0 - phi_1 - Delta_alpha
    ahead = theta - start - min_angle
    if periodic:
        turned = ahead - two_pi * bk.floor(ahead / two_pi)
    else:
        backwards = two_pi - _fmod(bk.fabs(theta) - start - min_angle, two_pi)
        turned = bk.if_else(theta < 0, backwards, bk.if_else(ahead < 0, -1.0, _fmod(ahead, two_pi)))
    x = turned * R_f
    phi, r, R, g1, g2 = phi_P * R_f, Delta_alpha * R_f, alpha_f * R_f, phi_1 * R_f, phi_2 * R_f
    t1, k1 = bk.tan(theta_1), bk.tan(theta_2 / 2.0)
    slope = t1 * t1 * k1
    w1 = 2.0 * g1 * t1 * k1
    w2 = 2.0 * g2 * t1 * k1
    k2 = r * r * math.pi / 2.0
    k3 = g1 * g1 * slope
    k5 = g2 * g2 * slope

    def notch(y: Any, w: Any) -> Any:
        return bk.fmin(y * y / g1 * w / 2.0, y * y * slope)

    ranges = [
        (0.0, g1, notch(x, w1)),
        (g1, g1 + 2.0 * r, k3 + _segment(2.0 * r - x + g1, r)),
        (g1 + 2.0 * r, R, k3 + k2 + (x - g1 - 2.0 * r) * 2.0 * r + k2),
        (R, R + g1, notch(g1 + R - x, w1) + k2 + (x - g1 - 2.0 * r) * 2.0 * r + k2),
        (R + g1, g1 + phi, k2 + (R - 2.0 * r) * 2.0 * r + k2),
        (g1 + phi, g1 + phi + g2, k2 + (R - 2.0 * r + phi + g1 - x) * 2.0 * r + k2 + notch(x - g1 - phi, w2)),
        (g1 + phi + g2, g1 + phi + R - 2.0 * r, k2 + (R - 2.0 * r + phi + g1 - x) * 2.0 * r + k2 + k5),
        (g1 + phi + R - 2.0 * r, g1 + phi + R, _segment(x - g1 - phi - R + 2.0 * r, r) + k5),
        (g1 + phi + R, g1 + phi + R + g2, notch(R - x + g1 + phi + g2, w2)),
    ]
    area: Any = 0.0
    for lo, hi, value in reversed(ranges):  # the first range that holds x counts, as Hopsan's if-else chain
        area = bk.if_else(x >= lo, bk.if_else(x <= hi, value, area), area)
    return area
