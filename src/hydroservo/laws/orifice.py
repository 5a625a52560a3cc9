r"""The turbulent orifice law and its regularisation at null: one law for every orifice in hydroservo.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.

Regularisation near zero pressure drop
--------------------------------------
The turbulent law :math:`Q = G\,\operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`
has an infinite slope at :math:`\Delta p = 0`, which is where implicit solvers
fail (their Newton iterations need the Jacobian). Physically the flow there is
laminar, proportional to :math:`\Delta p`. hydroservo has one way of making
every orifice law smooth at null: it replaces :math:`|\Delta p|` by

.. math:: |\Delta p|_{p_{tr}} = \sqrt{\Delta p^2 + p_{tr}^2} \qquad (:func:`smooth_abs`)

so that the pressure term of the turbulent law becomes

.. math:: \operatorname{sign}(\Delta p)\sqrt{|\Delta p|} \;\to\;
          \frac{\Delta p}{(\Delta p^2 + p_{tr}^2)^{1/4}} \qquad (:func:`signed_sqrt`)

which is odd, infinitely differentiable, strictly increasing in
:math:`\Delta p`, linear for :math:`|\Delta p| \ll p_{tr}` and within
:math:`p_{tr}^2/(4\Delta p^2)` of the turbulent law for
:math:`|\Delta p| \gg p_{tr}`. ``p_tr = 0`` (NumPy input only) is the law as
published. Each valve says what its ``p_tr`` means:

* a valve whose law is turbulent only (:class:`~hydroservo.components.FourWayValve`)
  takes the pressure drop at which the flow number of [MareAttarND] eq. (4),
  :math:`\lambda = (D_h/\nu)\sqrt{2|\Delta p|/\rho}`, reaches its critical value
  (:func:`transition_pressure`): the physical laminar region. The flow number
  rather than the Reynolds number needs no flow, so no algebraic loop (after
  [Beck1967]). Default critical value 1000, usual for sharp-edged spool orifices;
* a valve whose pseudo-sections already hold the laminar region
  (:class:`~hydroservo.components.PseudoSectionValve`) takes a small numerical
  ``p_tr`` (0.1 bar);
* a valve whose own law is laminar at small drops
  (:class:`~hydroservo.components.StagedSlotValve`, [MareAttarND] Table 1)
  applies :func:`smooth_abs` inside that law with ``p_tr`` of 1 Pa, which
  leaves its laminar slope exactly unchanged (see
  :func:`hydroservo.laws.staged_slot.slot_flow`).

Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from hydroservo import backend as bk
from hydroservo.errors import ParameterError

__all__ = [
    "DISCHARGE_COEFFICIENT",
    "flow_number",
    "transition_pressure",
    "smooth_abs",
    "smooth_sign",
    "signed_sqrt",
    "turbulent_flow",
    "orifice_flow",
    "blended_flow",
    "opening",
    "round_port_area",
    "round_port_width",
    "flow_coefficient_from_catalogue",
    "short_tube_discharge",
]

#: Theoretical discharge coefficient of a sharp-edged orifice, pi/(pi+2), [Efe2014] eq. (3.6).
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

    Returns
    -------
    array_like
        Flow number [-].

    References
    ----------
    [MareAttarND] eq. (4), after [Beck1967].

    Examples
    --------
    >>> round(float(flow_number(1e-3, 35e5, 870.0, 32e-6)))
    2803
    """
    return D_h / nu * bk.sqrt(2.0 / rho * bk.fabs(dp))


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

    Returns
    -------
    array_like
        Transition pressure drop [Pa].

    References
    ----------
    Inverse of [MareAttarND] eq. (4).

    Examples
    --------
    A 1 mm hydraulic diameter with an ISO VG 32 oil at 40 degC:

    >>> round(float(transition_pressure(1e-3, 870.0, 32e-6)) / 1e5, 2)
    4.45
    """
    return 0.5 * rho * (lambda_crit * nu / D_h) ** 2


def _exact(dp: Any, p_tr: Any) -> bool:
    """True when the law is to be evaluated as published: NumPy input and ``p_tr`` zero."""
    if bk.is_symbolic(dp, p_tr):
        return False
    if isinstance(p_tr, (int, float)):
        return p_tr == 0
    return bool(np.all(np.asarray(p_tr) == 0))


def smooth_abs(dp: Any, p_tr: Any = 0.0) -> Any:
    r"""The regularised magnitude of a pressure drop, :math:`\sqrt{\Delta p^2 + p_{tr}^2}` [Pa].

    The one regularisation of every orifice law in hydroservo (module notes).

    Parameters
    ----------
    dp : array_like
        Pressure drop [Pa].
    p_tr : array_like
        Transition pressure [Pa]; 0 gives :math:`|\Delta p|` exactly.

    Returns
    -------
    array_like
        [Pa].

    References
    ----------
    hydroservo's regularisation; the law it regularises: [Efe2014] eq. (3.5).

    Examples
    --------
    >>> float(smooth_abs(-3.0, 4.0)), float(smooth_abs(-3.0))
    (5.0, 3.0)
    """
    if _exact(dp, p_tr):
        return np.abs(dp)
    return bk.sqrt(dp * dp + p_tr**2)


def smooth_sign(dp: Any, p_tr: Any = 0.0) -> Any:
    r"""The regularised sign of a pressure drop, :math:`\Delta p/\sqrt{\Delta p^2 + p_{tr}^2}` [-].

    With :func:`smooth_abs`, the pair that replaces :math:`|\Delta p|` and
    :math:`\operatorname{sign}\Delta p` in a law (module notes); ``p_tr = 0``
    (NumPy input only) gives the sign exactly.

    Parameters
    ----------
    dp : array_like
        Pressure drop [Pa].
    p_tr : array_like
        Transition pressure [Pa].

    Returns
    -------
    array_like
        [-], in [-1, 1].

    References
    ----------
    hydroservo's regularisation; the law it regularises: [Efe2014] eq. (3.5).

    Examples
    --------
    >>> float(smooth_sign(-3.0, 4.0)), float(smooth_sign(-3.0))
    (-0.6, -1.0)
    """
    if _exact(dp, p_tr):
        return np.sign(dp)
    return dp / smooth_abs(dp, p_tr)


def signed_sqrt(dp: Any, p_tr: Any = 0.0) -> Any:
    r"""The pressure term of the turbulent law, :math:`\Delta p / (\Delta p^2 + p_{tr}^2)^{1/4}` [Pa^0.5].

    With ``p_tr = 0`` (NumPy input only) exactly
    :math:`\operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`; otherwise
    :math:`\sqrt{|\Delta p|_{p_{tr}}}\,\operatorname{sign}_{p_{tr}}\Delta p` of
    :func:`smooth_abs` and :func:`smooth_sign`, see the module notes.

    Parameters
    ----------
    dp : array_like
        Pressure drop [Pa].
    p_tr : array_like
        Transition pressure of the regularisation [Pa].

    Returns
    -------
    array_like
        [Pa^0.5].

    References
    ----------
    [Efe2014] eq. (3.5); regularisation: module notes.

    Examples
    --------
    >>> float(signed_sqrt(-4.0)), round(float(signed_sqrt(-4.0, 3.0)), 4)
    (-2.0, -1.7889)
    """
    if _exact(dp, p_tr):
        dp = np.asarray(dp, dtype=float)
        return np.sqrt(np.abs(dp)) * np.sign(dp)
    return dp / (dp**2 + p_tr**2) ** 0.25


def turbulent_flow(G: Any, dp: Any, p_tr: Any = 0.0) -> Any:
    r"""Turbulent flow through a section of conductance ``G``, :math:`Q = G\,\operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`.

    The conductance lumps the discharge coefficient, the area and the density:
    :math:`G = C_d A \sqrt{2/\rho}` for a sharp-edged orifice
    (:func:`orifice_flow`), the pseudo-section :math:`A_{ij}(x_s)` of
    [FerreiraND] eq. (1), :math:`c_v x` of a spool edge ([Efe2014] eq. 3.18).

    Parameters
    ----------
    G : array_like
        Turbulent conductance [m^3/s/Pa^0.5].
    dp : array_like
        Pressure drop, upstream minus downstream [Pa].
    p_tr : array_like
        Transition pressure of the regularisation [Pa] (module notes); 0 for
        the law as published (NumPy input only).

    Returns
    -------
    array_like
        Volume flow [m^3/s], positive from upstream to downstream.

    References
    ----------
    [FerreiraND] eq. (1); [Efe2014] eqs. (3.5), (3.18).

    Examples
    --------
    >>> round(float(turbulent_flow(1e-7, 25e5)) * 6e4, 3)  # L/min
    9.487
    """
    return G * signed_sqrt(dp, p_tr)


def laminar_flow(K_c: Any, dp: Any) -> Any:
    r"""Laminar flow through a restriction, proportional to the pressure drop: :math:`Q = K_c\,\Delta p`.

    The law of a capillary or a long narrow passage (Hagen-Poiseuille: :math:`K_c = \pi d^4/(128 \mu l)` for
    a round bore), and of Hopsan's HydraulicLaminarOrifice, whose pressure-flow coefficient :math:`K_c` is
    given directly.

    Parameters
    ----------
    K_c : array_like
        Pressure-flow coefficient [m^3/s/Pa].
    dp : array_like
        Pressure drop, upstream minus downstream [Pa].

    Returns
    -------
    array_like
        Volume flow [m^3/s], positive from upstream to downstream.

    References
    ----------
    [Merritt1967] (laminar flow through passages); [Hopsan2026] (HydraulicLaminarOrifice).

    Examples
    --------
    >>> round(float(laminar_flow(1e-11, 1e6)) * 6e4, 6)  # L/min
    0.6
    """
    return K_c * dp


def orifice_flow(A: Any, dp: Any, rho: Any, Cd: Any = DISCHARGE_COEFFICIENT, p_tr: Any = 0.0) -> Any:
    r"""Flow through a sharp-edged orifice, in the direction of the pressure drop.

    .. math:: Q = C_d A \sqrt{2/\rho}\; \frac{\Delta p}{(\Delta p^2 + p_{tr}^2)^{1/4}}

    With ``p_tr = 0`` this is the turbulent law of [Efe2014] eqs. (3.5) and
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
        Discharge coefficient [-], default pi/(pi+2) ([Efe2014] eq. 3.6).
    p_tr : array_like
        Laminar-turbulent transition pressure [Pa] (:func:`transition_pressure`);
        0 for the unregularised turbulent law (NumPy input only).

    Returns
    -------
    array_like
        Volume flow [m^3/s], positive from upstream to downstream.

    References
    ----------
    [Efe2014] eqs. (3.5), (3.6), (3.18); regularisation: module notes.

    Examples
    --------
    >>> q = orifice_flow(1e-5, 35e5, 870.0, Cd=0.611)
    >>> round(float(q) * 6e4, 3)  # L/min
    32.884
    """
    return turbulent_flow(Cd * A * bk.sqrt(2.0 / rho), dp, p_tr)


def blended_flow(A: Any, dp: Any, rho: Any, Cd: Any, k_lam: Any, n: Any = 2.0) -> Any:
    r"""Flow through an orifice whose laminar and turbulent resistances add as an :math:`n`-norm.

    .. math:: Q = \frac{A\,\Delta p}{\Big(R_{lam}^n + R_{turb}^n\Big)^{1/n}},\qquad
              R_{lam} = \frac{1}{k_{lam}},\quad R_{turb} = \frac{1}{C_d}\sqrt{\frac{\rho|\Delta p|}{2}}

    (resistances per unit of area, :math:`\Delta p/(Q/A)`). At small drops the laminar resistance dominates and
    :math:`Q = k_{lam} A\,\Delta p`; at large ones the turbulent law
    :math:`Q = C_d A\sqrt{2/\rho}\,\operatorname{sign}(\Delta p)\sqrt{|\Delta p|}` of :func:`orifice_flow`.
    The flow is odd, strictly increasing in :math:`\Delta p` and has the finite slope :math:`k_{lam} A` at null,
    so it needs no further regularisation. This is the law of Hopsan's orifices with geometric parameters
    ([Hopsan2026] Hydraulic/Restrictors/HydraulicOrificeG.hpp and Hydraulic/Special/HydraulicOrificeCheckValveG.hpp:
    :math:`n = 2`; Hydraulic/Special/HydraulicSlitOrifice.hpp: :math:`n = 4`), whose equation, solved by Newton
    iterations each step, is this algebraic flow; their laminar coefficient :math:`k_{lam}` follows from the
    hydraulic diameter, the length and the viscosity (see the importer, :mod:`hydroservo.io.hopsan_library`).

    Parameters
    ----------
    A : array_like
        Orifice area [m^2].
    dp : array_like
        Pressure drop, upstream minus downstream [Pa].
    rho : array_like
        Density [kg/m^3].
    Cd : array_like
        Turbulent discharge coefficient [-].
    k_lam : array_like
        Laminar flow per unit of area and of pressure drop [m/s/Pa], > 0.
    n : array_like
        Exponent of the resistances' sum [-], >= 1.

    Returns
    -------
    array_like
        Volume flow [m^3/s], positive from upstream to downstream.

    References
    ----------
    [Hopsan2026] Hydraulic/Restrictors/HydraulicOrificeG.hpp, Hydraulic/Special/HydraulicSlitOrifice.hpp.

    Examples
    --------
    Laminar at a small drop, turbulent at a large one (1 mm², C_d 0.611, k_lam 5e-4 m/s/Pa):

    >>> round(float(blended_flow(1e-6, 1.0, 870.0, 0.611, 5e-4)) / 5e-10, 3)
    1.0
    >>> q_turb = float(orifice_flow(1e-6, 1e8, 870.0, Cd=0.611))
    >>> round(float(blended_flow(1e-6, 1e8, 870.0, 0.611, 5e-4)) / q_turb, 4)
    1.0
    """
    r_turb_n = (rho * bk.fabs(dp) / (2.0 * Cd**2)) ** (n / 2.0)
    return A * dp / ((1.0 / k_lam) ** n + r_turb_n) ** (1.0 / n)


def opening(x: Any) -> Any:
    r"""Opening of a control edge, :math:`f(x) = x` for :math:`x \ge 0`, else 0 [m].

    Parameters
    ----------
    x : array_like
        Edge position, positive when open [m].

    Returns
    -------
    array_like
        Opening [m].

    References
    ----------
    [Efe2014] eq. (3.21).

    Examples
    --------
    >>> opening(np.array([-1e-4, 2e-4])).tolist()
    [0.0, 0.0002]
    """
    return bk.fmax(x, 0.0)


def round_port_area(x: Any, d: Any) -> Any:
    r"""Opened area of a round port of diameter :math:`d` that an edge has uncovered by :math:`x`: the circular
    segment of height :math:`x_1` = :math:`x` limited to :math:`[0, d]` [m^2].

    .. math:: A = \frac{d^2}{4}\arccos\left(1 - \frac{2 x_1}{d}\right)
              - \left(\frac{d}{2} - x_1\right)\sqrt{(d - x_1)\,x_1}

    0 while the edge covers the port, :math:`\pi d^2/4` once it has passed it; 0 for :math:`d \le 0` (no port).

    Parameters
    ----------
    x : array_like
        How far the edge has uncovered the port, the segment's height [m].
    d : array_like
        Diameter of the port [m].

    Returns
    -------
    array_like
        Opened area [m^2].

    References
    ----------
    [Hopsan2026] HopsanCore/src/ComponentUtilities/AuxiliarySimulationFunctions.cpp, ``segare`` (the area of a
    circular segment, elementary geometry), used by Signal/Non-Linearities/SignalSegare.hpp.

    Examples
    --------
    >>> round(float(round_port_area(0.05, 0.1)) / (np.pi * 0.1**2 / 8), 12)  # half the port
    1.0
    >>> float(round_port_area(-1.0, 0.1)), round(float(round_port_area(1.0, 0.1)), 8)
    (0.0, 0.00785398)
    """
    d_pos = bk.fmax(d, 1e-300)
    x1 = bk.clip(x, 0.0, d_pos)
    area = d_pos * d_pos / 4.0 * bk.acos(1.0 - 2.0 * x1 / d_pos) - (d_pos / 2.0 - x1) * bk.sqrt((d_pos - x1) * x1)
    return bk.if_else(d > 0.0, area, 0.0 * area)


def round_port_width(x: Any, d: Any) -> Any:
    r"""Width of the opening of a round port of diameter :math:`d` uncovered by :math:`x`, the chord
    :math:`2\sqrt{(d - x_1)\,x_1}` at the edge (:math:`x_1` = :math:`x` limited to :math:`[0, d]`): the
    derivative of :func:`round_port_area` with :math:`x` inside the port [m].

    Parameters
    ----------
    x : array_like
        How far the edge has uncovered the port, the segment's height [m].
    d : array_like
        Diameter of the port [m].

    Returns
    -------
    array_like
        Width of the opening at the edge [m]; 0 for :math:`d \le 0`.

    References
    ----------
    [Hopsan2026] HopsanCore/src/ComponentUtilities/AuxiliarySimulationFunctions.cpp, ``dxSegare``, used by
    Signal/Non-Linearities/SignalDxSegare.hpp.

    Examples
    --------
    >>> float(round_port_width(0.05, 0.1))  # the diameter, at the port's middle
    0.1
    >>> float(round_port_width(0.0, 0.1)), float(round_port_width(0.2, 0.1))
    (0.0, 0.0)
    """
    d_pos = bk.fmax(d, 1e-300)
    x1 = bk.clip(x, 0.0, d_pos)
    width = 2.0 * bk.sqrt(bk.fmax((d_pos - x1) * x1, 0.0))
    return bk.if_else(d > 0.0, width, 0.0 * width)


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
    float
        c_v [m^2/(s Pa^0.5)], such that one edge passes :math:`c_v x \sqrt{\Delta p}`.

    References
    ----------
    [Efe2014] eq. (3.9).

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


def short_tube_discharge(Re: Any, l_over_d: Any) -> Any:
    r"""Discharge coefficient of a short tube (a drilled orifice) against its Reynolds number, Lichtarowicz et al.

    .. math:: \frac{1}{C_d} = \frac{1}{C_{d,max}} + \frac{20}{Re}\left(1 + 2.25\,\frac{l}{d}\right),
              \qquad C_{d,max} = 0.827 - 0.0085\,\frac{l}{d}

    the correlation behind "Lichtarowicz's diagram" that [GordicND] reads
    its constant-orifice coefficients from (its Fig. 4-a, after McCloy and
    Martin 1973), with :math:`Re = (d/\nu)\sqrt{2\Delta p/\rho}`
    (eqs. 28-30: the flow number, :func:`flow_number`). Fitted for
    :math:`2 \le l/d \le 10`; shorter tubes are an extrapolation.

    Parameters
    ----------
    Re : array_like
        Reynolds number on the ideal jet velocity [-].
    l_over_d : array_like
        Length over diameter of the tube [-].

    Returns
    -------
    array_like
        :math:`C_d` [-].

    References
    ----------
    [Lichtarowicz1965], as reproduced in McCloy and Martin (1973) and used by [GordicND] Fig. 4-a.

    Examples
    --------
    The constant orifice of [GordicND] Table 1 (0.18 mm by 0.3 mm) at 70 bar, 14 cSt, 871 kg/m^3:

    >>> Re = float(flow_number(0.18e-3, 70e5, 871.0, 14e-6))
    >>> round(Re), round(float(short_tube_discharge(Re, 0.3 / 0.18)), 3)
    (1630, 0.776)
    """
    c_max = 0.827 - 0.0085 * l_over_d
    return 1.0 / (1.0 / c_max + 20.0 / Re * (1.0 + 2.25 * l_over_d))
