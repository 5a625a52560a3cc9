r"""The four-way valve as a bridge of four metering edges: one assembly for every four-way valve.

Every four-way valve in hydroservo, whatever the law of its edges, is the
Wheatstone bridge of [MareAttarND] Fig. 1: supply S to port A (edge PA, the
paper's orifice a), A to tank T (AT, b), S to B (PB, c), B to T (BT, d).
:func:`bridge_flows` turns the four edge flows into the port flows;
:func:`four_way_valve_flows` is the bridge with sharp-edged spool edges and
per-edge laps ([Efe2014] eqs. 3.18-3.23), each edge's flow :func:`edge_flow`; the
three-way valve (:func:`three_way_valve_flows`: supply, tank and one use port)
is the A half of the bridge, with the same edge law; the pseudo-section valve
(:func:`hydroservo.laws.pseudo_section.valve_flows`) and the staged-slot valve
(:func:`hydroservo.laws.staged_slot.staged_slot_valve_flows`) use the same assembly.

Pure, vectorised functions (NumPy arrays or CasADi expressions), SI units.
Citation keys in brackets are those of :mod:`hydroservo.references`.
"""

from __future__ import annotations

from typing import Any

from hydroservo import backend as bk
from hydroservo.laws.orifice import opening, turbulent_flow

__all__ = ["EDGES", "bridge_flows", "edge_flow", "four_way_valve_flows", "three_way_valve_flows", "valve_coefficients"]

#: The four metering edges: name -> (upstream node, downstream node, +1 if the edge opens with positive spool travel).
#: Nodes: S supply, T tank (the paper's return R), A and B the use ports (the paper's 1 and 2).
EDGES: dict[str, tuple[str, str, int]] = {
    "PA": ("S", "A", +1),
    "AT": ("A", "T", -1),
    "PB": ("S", "B", -1),
    "BT": ("B", "T", +1),
}


def bridge_flows(q_PA: Any, q_AT: Any, q_PB: Any, q_BT: Any) -> tuple[Any, Any, Any, Any]:
    r"""Port flows of a four-way valve from the flows through its four metering edges.

    .. math:: Q_A = q_{PA} - q_{AT}, \quad Q_B = q_{PB} - q_{BT}, \quad
              Q_S = q_{PA} + q_{PB}, \quad Q_T = q_{AT} + q_{BT}

    Parameters
    ----------
    q_PA, q_AT, q_PB, q_BT : array_like
        Flow through each edge in the direction of :data:`EDGES` [m^3/s].

    Returns
    -------
    (Q_A, Q_B, Q_S, Q_T) : tuple of array_like
        Flows out of the valve into lines A and B, into the valve from
        supply, and out of the valve to tank [m^3/s].

    References
    ----------
    [MareAttarND] Fig. 1; [FerreiraND] eq. (3); [Efe2014] eqs. (3.19)-(3.20).

    Examples
    --------
    >>> bridge_flows(3.0, 1.0, 0.5, 2.0)
    (2.0, -1.5, 3.5, 3.0)
    """
    return q_PA - q_AT, q_PB - q_BT, q_PA + q_PB, q_AT + q_BT


def edge_flow(c_v: Any, x: Any, dp: Any, p_tr: Any = 0.0, G_leak: Any = 0.0) -> Any:
    r"""Flow through one sharp metering edge of a spool valve, :math:`q = c_v f(x)\,g(\Delta p) + G_{leak}\,\Delta p`.

    :math:`f` is the edge's opening (:func:`~hydroservo.laws.orifice.opening`, 0 while the edge is covered) and
    :math:`g(\Delta p) = \operatorname{sign}(\Delta p)\sqrt{|\Delta p|}` regularised below ``p_tr``
    (:func:`~hydroservo.laws.orifice.turbulent_flow`). Every spool valve of hydroservo with sharp edges (four-,
    three- and two-way) is made of it.

    Parameters
    ----------
    c_v : array_like
        Flow coefficient of the edge [m^2/s/Pa^0.5]: :math:`C_d\,w\sqrt{2/\rho}` for an area gradient ``w``
        (:math:`\pi d` for a full annulus of spool diameter d).
    x : array_like
        Edge position [m]: the spool position less the edge's overlap, positive when open.
    dp : array_like
        Pressure drop across the edge, upstream minus downstream [Pa].
    p_tr : array_like
        Transition pressure of the regularisation [Pa]; 0 for the law as published (NumPy input only).
    G_leak : array_like
        Laminar clearance leakage conductance of the edge [m^3/s/Pa].

    Returns
    -------
    array_like
        Flow from upstream to downstream [m^3/s].

    References
    ----------
    [Efe2014] eqs. (3.18), (3.21).

    Examples
    --------
    An edge opened 0.1 mm under 100 bar, :math:`c_v` = 1e-3 m^2/s/Pa^0.5 (3.16e-4 m^3/s):

    >>> round(float(edge_flow(1e-3, 1e-4, 100e5)), 7), float(edge_flow(1e-3, -1e-4, 100e5))
    (0.0003162, 0.0)
    """
    return turbulent_flow(c_v * opening(x), dp, p_tr) + G_leak * dp


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
    r"""Flows of a four-way spool valve with sharp edges and per-edge overlap.

    .. math::
        Q_A &= c_v f(x_v - x_{PA})\,g(p_S - p_A) - c_v f(-x_v - x_{AT})\,g(p_A - p_T)\\
        Q_B &= c_v f(-x_v - x_{PB})\,g(p_S - p_B) - c_v f(x_v - x_{BT})\,g(p_B - p_T)

    with :math:`g(\Delta p) = \operatorname{sign}(\Delta p)\sqrt{|\Delta p|}`
    regularised by :func:`~hydroservo.laws.orifice.signed_sqrt` and :math:`f` of
    :func:`~hydroservo.laws.orifice.opening`, assembled by :func:`bridge_flows`.
    Positive ``x_v`` connects P to A and B to T.

    Parameters
    ----------
    x_v : array_like
        Spool position [m].
    p_S, p_T, p_A, p_B : array_like
        Supply, tank and port pressures [Pa].
    c_v : array_like
        Flow coefficient [m^2/s/Pa^0.5]
        (:func:`~hydroservo.laws.orifice.flow_coefficient_from_catalogue`).
    x_PA, x_AT, x_PB, x_BT : array_like
        Overlap of each control edge [m]; negative for underlap. Equal values
        give [Efe2014] eqs. (3.19)-(3.20) with :math:`x_o`; zero gives the
        critical-centre valve of [FlightSimulatorND] eqs. (3-18), (3-20),
        (3-22), (3-23).
    p_tr : array_like
        Transition pressure of the regularisation [Pa].
    G_leak : array_like
        Laminar leakage conductance of each edge [m^3/s/Pa], in parallel with
        the orifice (radial clearance leakage).
    K : array_like
        Flow-coefficient compensation :math:`K(x_v)H(x_v,d_f)` [-],
        [Efe2014] eqs. (3.22)-(3.23).

    Returns
    -------
    (Q_A, Q_B, Q_S, Q_T) : tuple of array_like
        Flows out of the valve into lines A and B, into the valve from
        supply, and out of the valve to tank [m^3/s].

    References
    ----------
    [Efe2014] eqs. (3.18)-(3.23); [FlightSimulatorND] eqs. (3-18), (3-20), (3-22), (3-23).

    Examples
    --------
    Critical-centre valve opened 0.25 mm, port A at 100 bar, port B at 50 bar,
    210 bar supply: A receives :math:`c_v x\sqrt{110\,\mathrm{bar}}`, B returns
    :math:`c_v x\sqrt{50\,\mathrm{bar}}` (L/min):

    >>> QA, QB, QS, QT = four_way_valve_flows(2.5e-4, 210e5, 0.0, 100e5, 50e5, 3.5e-4)
    >>> round(float(QA) * 6e4, 2), round(float(QB) * 6e4, 2)
    (17.41, -11.74)
    """
    cvk = c_v * K
    q_PA = edge_flow(cvk, x_v - x_PA, p_S - p_A, p_tr, G_leak)
    q_AT = edge_flow(cvk, -x_v - x_AT, p_A - p_T, p_tr, G_leak)
    q_PB = edge_flow(cvk, -x_v - x_PB, p_S - p_B, p_tr, G_leak)
    q_BT = edge_flow(cvk, x_v - x_BT, p_B - p_T, p_tr, G_leak)
    return bridge_flows(q_PA, q_AT, q_PB, q_BT)


def three_way_valve_flows(
    x_v: Any,
    p_S: Any,
    p_T: Any,
    p_A: Any,
    c_PA: Any,
    c_AT: Any,
    x_PA: Any = 0.0,
    x_AT: Any = 0.0,
    p_tr: Any = 0.0,
) -> tuple[Any, Any, Any]:
    r"""Flows of a three-way spool valve (supply, tank, one use port A): the A half of the four-way bridge.

    .. math::
        q_{PA} = c_{PA} f(x_v - x_{PA})\,g(p_S - p_A), \quad q_{AT} = c_{AT} f(-x_v - x_{AT})\,g(p_A - p_T)

    each edge by :func:`edge_flow`, and :math:`Q_A = q_{PA} - q_{AT}`, :math:`Q_S = q_{PA}`,
    :math:`Q_T = q_{AT}` (:func:`bridge_flows` with B's edges closed). Positive ``x_v`` connects P to A; each
    edge has its own coefficient (a fraction of the circumference may be cut for one edge only).

    Parameters
    ----------
    x_v : array_like
        Spool position [m].
    p_S, p_T, p_A : array_like
        Supply, tank and use-port pressures [Pa].
    c_PA, c_AT : array_like
        Flow coefficients of edges P-A and A-T [m^2/s/Pa^0.5].
    x_PA, x_AT : array_like
        Overlap of each edge [m]; negative for underlap.
    p_tr : array_like
        Transition pressure of the regularisation [Pa].

    Returns
    -------
    (Q_A, Q_S, Q_T) : tuple of array_like
        Flow out of the valve into line A, into the valve from supply, out of the valve to tank [m^3/s].

    References
    ----------
    [Efe2014] eqs. (3.18)-(3.21) (the edges of port A).

    Examples
    --------
    Opened 0.25 mm towards A, A at 100 bar, 210 bar supply: A receives :math:`c_v x\sqrt{110\,\mathrm{bar}}`
    (L/min), and nothing goes to tank:

    >>> QA, QS, QT = three_way_valve_flows(2.5e-4, 210e5, 0.0, 100e5, 3.5e-4, 3.5e-4)
    >>> round(float(QA) * 6e4, 2), float(QT)
    (17.41, 0.0)
    """
    q_PA = edge_flow(c_PA, x_v - x_PA, p_S - p_A, p_tr)
    q_AT = edge_flow(c_AT, -x_v - x_AT, p_A - p_T, p_tr)
    return q_PA - q_AT, q_PA, q_AT


def valve_coefficients(
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
) -> dict[str, Any]:
    r"""Valve sensitivity coefficients of the sharp-edged four-way valve at an operating point.

    The derivatives of the turbulent flows of :func:`four_way_valve_flows`
    (without regularisation or leakage) into ports A and B, [Efe2014] eqs.
    4.8-4.12, in general form: every edge contributes while it is open, with
    its opening :math:`f(x) = \max(x, 0)` of eq. 3.21 (the thesis writes
    :math:`x_{v0}` in eqs. 4.10-4.11, which is the opening only for a
    zero-lapped valve), and with the sign of its pressure drop (a load that
    overruns the supply reverses an edge's flow, eq. 3.18):

    .. math::
        K_{Qx,A} &= \frac{\partial Q_A}{\partial x_v}
                  = c_v\,[x_v > x_{PA}]\,\mathrm{sgn}(p_S - p_A)\sqrt{|p_S - p_A|}
                   + c_v\,[-x_v > x_{AT}]\,\mathrm{sgn}(p_A - p_T)\sqrt{|p_A - p_T|}\\
        K_{Qp,A} &= \frac{\partial Q_A}{\partial p_A}
                  = -\frac{c_v f(x_v - x_{PA})}{2\sqrt{|p_S - p_A|}}
                   - \frac{c_v f(-x_v - x_{AT})}{2\sqrt{|p_A - p_T|}}\\
        K_{px} &= K_{Qx}/K_{Qp}

    and the same for B with its edges (``K_Qx_B`` is negative: positive spool
    travel empties B). With the spool inside its overlap every coefficient
    is 0 and :math:`K_{px}` is undefined (NaN); the thesis's cases leave that
    band out. :math:`K_{Qp}` is :math:`-K_c` of [Merritt1967] and
    :math:`K_{px}` is :math:`-K_p`.

    Parameters
    ----------
    x_v : array_like
        Spool position [m].
    p_S, p_T, p_A, p_B : array_like
        Supply, tank and port pressures [Pa].
    c_v : array_like
        Flow coefficient per edge [m^2/s/Pa^0.5], with any compensation
        :math:`K(x_v)H(x_v,d_f)` applied at the point (eqs. 3.22-3.23; the
        derivative of the tables is not part of eqs. 4.8-4.11).
    x_PA, x_AT, x_PB, x_BT : array_like
        Overlap of each edge [m] (negative: underlap).

    Returns
    -------
    dict
        ``K_Qx_A``, ``K_Qx_B`` [m^2/s]; ``K_Qp_A``, ``K_Qp_B`` [m^3/(s Pa)];
        ``K_px_A``, ``K_px_B`` [Pa/m].

    References
    ----------
    [Efe2014] eqs. (4.8)-(4.12); [Merritt1967] section 5.3.

    Examples
    --------
    Critical-centre valve 0.25 mm open, 30 bar supply, A at 20 bar, B at 5 bar:
    :math:`K_{Qx,A} = c_v\sqrt{10\,\mathrm{bar}}`, :math:`K_{Qp,A} = -c_v x_v/(2\sqrt{10\,\mathrm{bar}})`,
    so :math:`K_{px,A} = -2(p_S - p_A)/x_v` = -8e9 Pa/m:

    >>> k = valve_coefficients(2.5e-4, 30e5, 0.0, 20e5, 5e5, 1e-5)
    >>> round(float(k["K_Qx_A"]), 6), round(float(k["K_px_A"]) / 1e9, 9)
    (0.01, -8.0)
    """
    drops = {"SA": p_S - p_A, "AT": p_A - p_T, "SB": p_S - p_B, "BT": p_B - p_T}
    root = {k: bk.sqrt(bk.fabs(d)) for k, d in drops.items()}
    signed = {k: bk.if_else(d >= 0, 1.0, -1.0) * root[k] for k, d in drops.items()}
    o_PA, o_AT, o_PB, o_BT = opening(x_v - x_PA), opening(-x_v - x_AT), opening(-x_v - x_PB), opening(x_v - x_BT)
    on = {k: bk.if_else(o > 0, 1.0, 0.0) for k, o in (("PA", o_PA), ("AT", o_AT), ("PB", o_PB), ("BT", o_BT))}
    K_Qx_A = c_v * (on["PA"] * signed["SA"] + on["AT"] * signed["AT"])
    K_Qx_B = -c_v * (on["PB"] * signed["SB"] + on["BT"] * signed["BT"])
    K_Qp_A = -c_v * (o_PA / (2 * bk.fmax(root["SA"], 1e-300)) + o_AT / (2 * bk.fmax(root["AT"], 1e-300)))
    K_Qp_B = -c_v * (o_PB / (2 * bk.fmax(root["SB"], 1e-300)) + o_BT / (2 * bk.fmax(root["BT"], 1e-300)))
    nan = float("nan")
    return {
        "K_Qx_A": K_Qx_A,
        "K_Qx_B": K_Qx_B,
        "K_Qp_A": K_Qp_A,
        "K_Qp_B": K_Qp_B,
        "K_px_A": bk.if_else(K_Qp_A != 0, K_Qx_A / bk.if_else(K_Qp_A != 0, K_Qp_A, 1.0), nan),
        "K_px_B": bk.if_else(K_Qp_B != 0, K_Qx_B / bk.if_else(K_Qp_B != 0, K_Qp_B, 1.0), nan),
    }
