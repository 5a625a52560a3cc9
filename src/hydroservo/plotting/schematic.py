"""Circuit diagrams of systems, with symbols after ISO 1219-1, laid out automatically.

:func:`draw` turns a :class:`~hydroservo.system.System` into a :class:`Schematic`: every component as its
symbol (4/3 directional valves with their centre position and actuation, servovalves, cylinders, pumps and
motors, relief, reducing, counterbalance and check valves, orifices, accumulators, tanks, pressure sources,
volumes, lines, masses with their springs; signal blocks as labelled boxes), with its name and its main
parameters in the units they were given in; oil lines solid, signal wires dashed with an arrow in their
direction, mechanical couplings (a cylinder's rod on its load) as a double line; a junction dot where three
or more ports meet. ``Schematic.save`` writes SVG, PNG or PDF; in a notebook a schematic shows itself.

The circuit is read from the system as it is connected: hydraulic links port to port (:attr:`System.links`,
grouped into nodes), and, in model files that wire the pressure and flow signals of two ports one by one
(``"valve.pA" = "cyl.pB"``), those pairs as the oil line they stand for.

Layout
------
The positions of the symbols and the routes of the lines come from `graphlay
<https://pypi.org/project/graphlay/>`_, a layered (Sugiyama) layout engine with orthogonal routing, written
in Rust and shipped as prebuilt wheels for Linux, macOS and Windows. It was chosen over the alternatives for
what a schematic needs: lines enter each symbol at its port (a valve's A and B on top, P and T below; a
cylinder's A and B on its body), given as fixed port positions on each node's sides, and run orthogonally,
as drawn by hand. Graphviz ``dot`` lays out as well but needs a system program a ``pip install`` cannot
bring, and its orthogonal routing ignores ports; grandalf (pure Python) has no orthogonal routing or ports.

Energy flows up the page, as ISO 1219-2 draws it: the engine lays out top to bottom along edges directed
from the actuators and loads to the control valves to the supply (pumps, tanks, relief valves); signals run
in their own direction, from the command to the valve they drive. Drawing happens in matplotlib (already a
dependency), which gives SVG with each component and each connection a group of its own
(``id="component:NAME"``, ``id="link:A.P--B.P"``, ``id="signal:A.y--B.u"``, ``id="mechanical:A--B"``), text as
text, and PNG and PDF from the same drawing.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.errors import ParameterError

if TYPE_CHECKING:
    from hydroservo.components.base import Component
    from hydroservo.system.system import System

__all__ = ["draw", "Schematic", "circuit", "Circuit", "Connection", "drawn", "missing", "FORMATS", "MAIN_PARAMETERS"]

#: What :meth:`Schematic.save` writes, by suffix.
FORMATS = ("svg", "png", "pdf")

#: The parameters shown beside a component's name, by type (the first found, at most three).
MAIN_PARAMETERS: dict[str, tuple[str, ...]] = {
    "Cylinder": ("A_A", "A_B", "x_max"),
    "Mass": ("m", "k_spring", "B"),
    "Pump": ("D", "omega"),
    "VariablePump": ("D", "omega", "p_c"),
    "Motor": ("D",),
    "ReliefValve": ("p_crack", "q_nom"),
    "PressureReducingValve": ("p_set",),
    "CounterbalanceValve": ("p_crack",),
    "CheckValve": ("p_crack",),
    "Orifice": ("d", "Cd"),
    "Accumulator": ("V0", "p0"),
    "Volume": ("V",),
    "Line": ("l", "d"),
    "Hose": ("l", "d"),
    "ConstantPressure": ("p",),
    "Tank": ("p",),
    "FourWayValve": ("xv_max", "c_v"),
    "StagedSlotValve": ("temperature",),
    "TwoStageServovalve": ("i_max",),
    "CatalogueServovalve": ("Q_N", "i_N"),
    "SpoolFirstOrder": ("tau",),
    "SpoolSecondOrder": ("omega_n", "zeta"),
    "SpoolRateLimited": ("omega_n", "zeta"),
    "ServoSolenoidValve": ("omega_n",),
    "TorqueMotor": ("omega_n",),
    "FlapperNozzleSpool": ("omega_h",),
    "Step": ("amplitude",),
    "Pulse": ("amplitude", "duration"),
    "Sine": ("amplitude", "frequency"),
    "Square": ("amplitude", "frequency"),
    "Ramp": ("slope",),
    "Gain": ("K",),
    "Transducer": ("G",),
    "Lag": ("K", "tau"),
    "PID": ("Kp", "Ki", "Kd"),
    "Amplifier": ("G_a",),
    "Saturation": ("lower", "upper"),
}

# -- the circuit as a graph ---------------------------------------------------------------------------
_MECHANICAL_SIGNALS = {"F", "x", "v", "T", "theta", "omega", "T_load", "m_oil", "m_add"}
_MECHANICAL_TYPES = {"Cylinder", "Mass", "Motor", "LoadPressureCylinder"}


@dataclass(frozen=True)
class Connection:
    """One line of the diagram: ``kind`` "link" (oil, between ports "comp.port"), "signal" (from an output to
    inputs, "comp.name") or "mechanical" (between two components); ``ends`` as the SVG id names them."""

    kind: str
    ends: tuple[str, ...]
    #: the signals a wire carries (for a signal or mechanical connection)
    carries: tuple[str, ...] = ()

    @property
    def ident(self) -> str:
        return f"{self.kind}:{'--'.join(self.ends)}"


@dataclass
class Circuit:
    """What a diagram shows: the components and the connections, read from a system."""

    components: dict[str, Component]
    connections: list[Connection]


def _port_of_signal(comp: Component, signal: str) -> str | None:
    for pname, port in comp.HYDRAULIC.items():
        if signal in (port.p, port.Q):
            return pname
    return None


def circuit(system: System) -> Circuit:
    """The components and connections of ``system`` (module notes): oil links (port to port, or as signal
    pairs), mechanical couplings and signal wires, each once."""
    comps = system.components
    connections: list[Connection] = []
    seen: set[tuple[str, ...]] = set()
    for node in system.nodes():
        ports = tuple(node.ports)
        connections.append(Connection("link", ports))
        seen.add(tuple(sorted(ports)))
    signals: dict[tuple[str, str, str], list[str]] = {}
    for target, source in system.connections.items():
        tc, ti = target.split(".", 1)
        sc, so = source.split(".", 1)
        tport, sport = _port_of_signal(comps[tc], ti), _port_of_signal(comps[sc], so)
        if tport is not None and sport is not None:  # a pressure or flow of one port fed by another's
            pair = tuple(sorted((f"{tc}.{tport}", f"{sc}.{sport}")))
            if pair not in seen:
                seen.add(pair)
                connections.append(Connection("link", pair))
            continue
        kinds = {type(comps[tc]).__name__, type(comps[sc]).__name__}
        if so in _MECHANICAL_SIGNALS and ti in _MECHANICAL_SIGNALS and kinds <= _MECHANICAL_TYPES and tc != sc:
            first, second = sorted((sc, tc))
            key = ("mechanical", first, second)
        else:
            key = ("signal", sc, tc)
        signals.setdefault(key, []).append(f"{so}->{ti}")
    for (kind, a, b), carried in signals.items():
        connections.append(Connection(kind, (a, b), tuple(carried)))
    return Circuit(dict(comps), connections)


# -- symbols --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Port:
    """Where a line meets a symbol: a side of its box and the position along it (0 to 1, left to right or top to
    bottom)."""

    side: str
    at: float = 0.5


@dataclass
class Shape:
    """A symbol: what draws it, its box [px], its ports, and where its label goes ("right", "top" or "inside")."""

    kind: str
    width: float
    height: float
    ports: dict[str, Port] = field(default_factory=dict)
    label: str = "right"


_VALVES_4 = {"FourWayValve", "PseudoSectionValve", "ServoSolenoidValve", "StagedSlotValve", "TwoStageServovalve",
             "CatalogueServovalve"}
_SERVO = {"TwoStageServovalve", "CatalogueServovalve"}
_SIGNAL_INPUTS = {"xv": "in", "u": "in", "i": "in", "xs": "in", "eps_cmd": "in"}


def shape_of(comp: Component) -> Shape:
    """The symbol of a component, from its type (a type without one: a labelled box with its ports)."""
    kind = type(comp).__name__
    hydraulic = list(comp.HYDRAULIC)
    if kind in _VALVES_4:
        return Shape("servovalve" if kind in _SERVO else "valve43", 120, 44, {
            "A": Port("top", (24 + 26 + 8) / 120), "B": Port("top", (24 + 26 + 18) / 120),
            "P": Port("bottom", (24 + 26 + 8) / 120), "T": Port("bottom", (24 + 26 + 18) / 120),
            "in": Port("left", 0.5),
        })
    if kind in ("Cylinder", "LoadPressureCylinder"):
        return Shape("cylinder", 140, 34, {"A": Port("bottom", 10 / 140), "B": Port("bottom", 100 / 140),
                                           "rod": Port("right", 0.5)}, label="top")
    if kind in ("Pump", "VariablePump"):
        return Shape("pump_variable" if kind == "VariablePump" else "pump", 40, 40,
                     {"P": Port("top"), "S": Port("bottom"), "in": Port("left")})
    if kind == "Motor":
        return Shape("motor", 40, 40, {"A": Port("top"), "B": Port("bottom"), "rod": Port("right")})
    if kind in ("ConstantPressure", "PressureTable"):
        return Shape("source", 34, 34, {"P": Port("top")})
    if kind == "Tank":
        return Shape("tank", 34, 16, {"P": Port("top")})
    if kind in ("ReliefValve", "PressureReducingValve"):
        return Shape("relief" if kind == "ReliefValve" else "reducing", 34, 40, {"A": Port("top"), "B": Port("bottom")})
    if kind == "CounterbalanceValve":
        return Shape("counterbalance", 46, 44, {"A": Port("bottom"), "B": Port("top"), "X": Port("left")})
    if kind == "CheckValve":
        return Shape("check", 22, 26, {"A": Port("bottom"), "B": Port("top")})
    if kind == "Orifice":
        return Shape("orifice", 18, 30, {"A": Port("top"), "B": Port("bottom")})
    if kind == "Accumulator":
        return Shape("accumulator", 26, 44, {"P": Port("bottom")})
    if kind == "Volume":
        return Shape("volume", 20, 20, {"P": Port("top")})
    if kind in ("Line", "Hose"):
        ports = {p: Port("top" if p == hydraulic[0] else "bottom") for p in hydraulic}
        return Shape("hose" if kind == "Hose" else "line", 14, 64, ports)
    if kind == "Mass":
        return Shape("mass", 64, 36, {"rod": Port("left"), "in": Port("top", 0.25), "out": Port("top", 0.55)})
    # signal blocks and anything else: a box; hydraulic ports on top and bottom
    ports = {"in": Port("left"), "out": Port("right")}
    for k, p in enumerate(hydraulic):
        ports[p] = Port("top" if k % 2 == 0 else "bottom", (k // 2 + 1) / (len(hydraulic) // 2 + 2))
    return Shape("block", 0, 0, ports, label="inside")


def _quantity(comp: Component, key: str) -> str | None:
    from hydroservo.units import si_unit

    if key not in comp.PARAMETERS:
        return None
    if key in comp.given:
        return _short(comp.given[key])
    value = comp.values[key]
    unit = si_unit(comp.PARAMETERS[key].unit)
    return f"{value:.4g} {unit}".strip() if unit not in ("", "-") else f"{value:.4g}"


def _short(text: str) -> str:
    """A value as given, its number to 4 significant digits ("9.978026887936429e-4 m^2/s" -> "0.0009978 m^2/s")."""
    from hydroservo.units import split_quantity

    try:
        number, unit = split_quantity(text)
    except Exception:  # noqa: BLE001 - an expression or anything else: shown as it is
        return text
    return f"{number:.4g} {unit}".strip()


def parameter_lines(comp: Component) -> list[str]:
    """The main parameters of a component as ``name = value unit`` (as given; SI where no unit was given)."""
    lines = []
    for key in MAIN_PARAMETERS.get(type(comp).__name__, ())[:3]:
        if key == "k_spring" and not comp.values.get(key):
            continue
        shown = _quantity(comp, key)
        if shown is not None:
            lines.append(f"{key} = {shown}")
    return lines


# -- layout -----------------------------------------------------------------------------------------------
_NAME_SIZE, _TEXT_SIZE = 10.0, 8.5
_ROD = 44.0  #: the length of rod between an actuator and the load riding on it [px]
_CHAR = 0.6  # width of a character in font sizes (a sans-serif font's average)
#: How far down the page a component sits, by type (energy flows up: supply at the bottom).
_LEVEL = {"Mass": 0, "Cylinder": 1, "Motor": 1, "LoadPressureCylinder": 1, "Tank": 9, "ConstantPressure": 8,
          "PressureTable": 8, "Pump": 8, "VariablePump": 8, "ReliefValve": 8, "Accumulator": 7,
          "PressureReducingValve": 6, "CounterbalanceValve": 3, "CheckValve": 5, "Orifice": 5, "Line": 6,
          "Hose": 6, "Volume": 5, **{k: 4 for k in _VALVES_4}}


@dataclass
class _Node:
    name: str
    comp: Component | None
    shape: Shape
    lines: list[str]  #: the label: name, then parameters
    width: float = 0.0
    height: float = 0.0
    x: float = 0.0  #: the box's centre [px]
    y: float = 0.0
    level: float | None = None  #: how far down the page (a junction: just above the lowest of its ports)
    carry: float = 0.0  #: width at the right of the box that holds the loads riding on this actuator [px]

    def __post_init__(self) -> None:
        s = self.shape
        text_w = max((len(line) * _CHAR * (_NAME_SIZE if k == 0 else _TEXT_SIZE) for k, line in enumerate(self.lines)),
                     default=0.0)
        text_h = 14 + 11 * (len(self.lines) - 1)
        if not self.lines:
            self.width, self.height = s.width, s.height
        elif s.label == "inside":
            s.width, s.height = max(60.0, text_w + 16), max(30.0, text_h + 10)
            self.width, self.height = s.width, s.height
        elif s.label == "top":
            self.width, self.height = max(s.width, text_w), s.height + text_h + 6
        else:
            self.width, self.height = s.width + 8 + text_w, max(s.height, text_h)

    @property
    def symbol_box(self) -> tuple[float, float, float, float]:
        """(left, top, width, height) of the symbol [px]."""
        s = self.shape
        left = self.x - self.width / 2
        if s.label == "top":
            own = self.width - self.carry
            return left + (own - s.width) / 2, self.y + self.height / 2 - s.height, s.width, s.height
        return left, self.y - s.height / 2, s.width, s.height

    def port_point(self, port: Port) -> tuple[float, float]:
        left, top, w, h = self.symbol_box
        return {
            "top": (left + port.at * w, top), "bottom": (left + port.at * w, top + h),
            "left": (left, top + port.at * h), "right": (left + w, top + port.at * h),
        }[port.side]

    def hint(self, port: Port) -> dict[str, Any]:
        """The port as graphlay takes it: a side of the node's box and a position on it, -1 to 1."""
        px, py = self.port_point(port)
        if port.side in ("top", "bottom"):
            t = (px - self.x) / (self.width / 2)
        else:
            t = (py - self.y) / (self.height / 2)
        return {"offset": {"side": port.side, "t": max(-0.98, min(0.98, t))}}


@dataclass
class _Edge:
    connection: Connection
    a: str  #: node names
    b: str
    pa: Port | None
    pb: Port | None
    points: list[tuple[float, float]] = field(default_factory=list)


def _level(node: _Node) -> float:
    if node.level is not None:
        return node.level
    if node.comp is None:
        return 5.0
    return float(_LEVEL.get(type(node.comp).__name__, 2))


def _graphlay_edges(nodes: dict[str, _Node], edges: list[_Edge], index: dict[str, int],
                    directed: bool) -> tuple[list[dict[str, Any]], list[bool]]:
    """The edges as graphlay takes them, and whether each was turned round (oil and rods run from the actuators
    down to the supply, so that the supply ends at the bottom of a top-to-bottom layout)."""
    out, turned = [], []
    for e in edges:
        a, b, pa, pb = e.a, e.b, e.pa, e.pb
        turn = directed and e.connection.kind != "signal" and _level(nodes[a]) > _level(nodes[b])
        if turn:
            a, b, pa, pb = b, a, pb, pa
        entry: dict[str, Any] = {"source": index[a], "target": index[b],
                                 "weight": 1.0 if e.connection.kind == "signal" else 3.0}
        if pa is not None:
            entry["source_port"] = nodes[a].hint(pa)
        if pb is not None:
            entry["target_port"] = nodes[b].hint(pb)
        out.append(entry)
        turned.append(turn)
    return out, turned


def _place(names: list[str], nodes: dict[str, _Node], edges: list[_Edge], direction: str) -> None:
    """Place ``names`` (their centres) with graphlay's layered layout of the edges among them; those edges get
    the engine's routes (oil and rods kept in their own direction)."""
    import graphlay

    index = {n: k for k, n in enumerate(names)}
    inner = [e for e in edges if e.a in index and e.b in index]
    routed, turned = _graphlay_edges(nodes, inner, index, direction == "topbottom")
    graph = {
        "nodes": [{"size": {"width": nodes[n].width, "height": nodes[n].height}, "shape": "box", "key": n} for n in names],
        "edges": routed,
    }
    options = {"direction": direction, "spacing": {"layer_gap": 46.0, "node_gap": 34.0, "port_gap": 10.0}}
    laid = graphlay.layout(graph, options=options)
    for name, placed in zip(names, laid.raw["nodes"], strict=True):
        nodes[name].x, nodes[name].y = placed["center"]["x"], placed["center"]["y"]
    for e, turn, route in zip(inner, turned, laid.raw["edges"], strict=True):
        points = [(p["x"], p["y"]) for p in route["points"]]
        e.points = points[::-1] if turn else points


def _channel(e: _Edge, nodes: dict[str, _Node], y: float) -> list[tuple[float, float]]:
    """A route from ``e``'s first port to its second along the horizontal channel at ``y``: out of each port along
    its side's normal, then to the channel, across and back."""
    if e.pa is None or e.pb is None:
        return []
    normal = {"top": (0.0, -1.0), "bottom": (0.0, 1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}

    def border(node: _Node, port: Port) -> tuple[float, float]:
        px, py = node.port_point(port)
        if port.side == "top":
            return px, node.y - node.height / 2
        if port.side == "bottom":
            return px, node.y + node.height / 2
        return (node.x - node.width / 2 if port.side == "left" else node.x + node.width / 2), py

    a, b = nodes[e.a], nodes[e.b]
    s0, t0 = border(a, e.pa), border(b, e.pb)
    (sx, sy), (tx, ty) = normal[e.pa.side], normal[e.pb.side]
    s1 = (s0[0] + 12 * sx, s0[1] + 12 * sy)
    t1 = (t0[0] + 12 * tx, t0[1] + 12 * ty)
    return [s0, s1, (s1[0], y), (t1[0], y), t1, t0]


def _channels(e: _Edge, nodes: dict[str, _Node], k: int) -> list[float]:
    """Heights of the channels a line may take: above and below every symbol, and in the gaps above and below
    the rows of its two ends (``k`` lines already taken shift each by a few pixels)."""
    top = min(n.y - n.height / 2 for n in nodes.values())
    bottom = max(n.y + n.height / 2 for n in nodes.values())
    a, b = nodes[e.a], nodes[e.b]
    shift = 6 * k
    return [top - 16 - shift, b.y - b.height / 2 - 12 - shift, a.y - a.height / 2 - 12 - shift,
            b.y + b.height / 2 + 12 + shift, a.y + a.height / 2 + 12 + shift, bottom + 16 + shift]


def _crossed(e: _Edge, nodes: dict[str, _Node]) -> bool:
    """Whether the edge's route runs through the box of a node other than its two ends."""
    for name, n in nodes.items():
        if name in (e.a, e.b):
            continue
        x0, x1 = n.x - n.width / 2 - 3, n.x + n.width / 2 + 3  # touching a symbol's box counts: lines keep clear
        y0, y1 = n.y - n.height / 2 - 3, n.y + n.height / 2 + 3
        for (ax, ay), (bx, by) in zip(e.points, e.points[1:]):
            if max(ax, bx) > x0 and min(ax, bx) < x1 and max(ay, by) > y0 and min(ay, by) < y1:
                return True
    return False


def _layout(nodes: dict[str, _Node], edges: list[_Edge], riders: dict[str, str]) -> tuple[float, float, float, float]:
    """Place the nodes and route every edge (module notes); returns the drawing's bounds (x0, y0, x1, y1).

    The circuit (everything with oil ports, the actuators and their loads) is laid out top to bottom; the
    signal blocks, left to right, to its left; a load that rides on one actuator's rod (``riders``: load ->
    actuator) sits at the end of that rod; then graphlay routes every line over those positions.
    """
    import graphlay

    blocks = [n for n, node in nodes.items() if node.shape.kind == "block"]
    # a source that only pushes on a load (an external force) is drawn beside that load, in the circuit
    loads = {n for n, node in nodes.items() if node.shape.kind in ("mass", "cylinder", "motor")}
    for b in list(blocks):
        into = [e.b for e in edges if e.a == b]
        if into and set(into) <= loads and not any(e.b == b for e in edges):
            blocks.remove(b)
    circuit_nodes = [n for n in nodes if n not in blocks and n not in riders]
    for load, actuator in riders.items():  # the actuator's box holds its load
        extra = nodes[load].width + _ROD
        nodes[actuator].carry += extra
        nodes[actuator].width += extra
        nodes[actuator].height = max(nodes[actuator].height, nodes[load].height)
    inside = [e for e in edges if e.a in circuit_nodes and e.b in circuit_nodes]
    if circuit_nodes:
        proxies = [_Edge(e.connection, riders.get(e.a, e.a), riders.get(e.b, e.b), None, None)
                   for e in edges if (e.a in riders or e.b in riders) and e.connection.kind == "signal"
                   and riders.get(e.a, e.a) in circuit_nodes and riders.get(e.b, e.b) in circuit_nodes]
        _place(circuit_nodes, nodes, inside + [p for p in proxies if p.a != p.b], "topbottom")
    for load, actuator in riders.items():
        a, m = nodes[actuator], nodes[load]
        left, top, w, h = a.symbol_box
        m.x = a.x + a.width / 2 - m.width / 2
        m.y = top + h / 2 - (m.symbol_box[1] + m.shape.height / 2 - m.y)
    if blocks:
        _place(blocks, nodes, edges, "leftright")
        if circuit_nodes:
            right = max(nodes[n].x + nodes[n].width / 2 for n in blocks)
            left = min(nodes[n].x - nodes[n].width / 2 for n in circuit_nodes)
            # the blocks' row at the height of what they drive, but never above the circuit's top
            driven = [nodes[e.b].y for e in edges if e.a in blocks and e.b not in blocks] or \
                [nodes[n].y for n in circuit_nodes]
            top = min(nodes[n].y - nodes[n].height / 2 for n in circuit_nodes)
            shift_y = min(driven) - sum(nodes[n].y for n in blocks) / len(blocks)
            shift_y = max(shift_y, top - min(nodes[n].y - nodes[n].height / 2 for n in blocks))
            for n in blocks:
                nodes[n].x += left - 60 - right
                nodes[n].y += shift_y
            for e in edges:
                if e.a in blocks and e.b in blocks:
                    e.points = [(x + left - 60 - right, y + shift_y) for x, y in e.points]
    # the lines the layered layouts did not route (between the blocks and the circuit, to a riding load, a
    # load's rod): routed over the places the symbols now have, the symbols as obstacles (riders within their
    # actuator's box: the actuator's box is cut back to its own part for this)
    for actuator in set(riders.values()):
        node = nodes[actuator]
        node.width -= node.carry
        node.x -= node.carry / 2
        node.carry = 0.0
    rest = [e for e in edges if not e.points]
    order = list(nodes)
    index = {n: k for k, n in enumerate(order)}
    if rest:
        routed_edges, _ = _graphlay_edges(nodes, rest, index, False)
        graph = {
            "nodes": [{"size": {"width": nodes[n].width, "height": nodes[n].height}, "shape": "box", "key": n,
                       "position": {"x": nodes[n].x, "y": nodes[n].y}} for n in order],
            "edges": routed_edges,
        }
        laid = graphlay.reroute(graph, options={"spacing": {"port_gap": 10.0}})
        for e, routed in zip(rest, laid.raw["edges"], strict=True):
            e.points = [(p["x"], p["y"]) for p in routed["points"]]
        channels = 0
        for k, e in enumerate(rest):  # a line routed through another symbol: routed again on its own, else
            if not _crossed(e, nodes):  # along a channel above (or below) every symbol
                continue
            alone = graphlay.reroute({"nodes": graph["nodes"], "edges": [routed_edges[k]]})
            points = [(p["x"], p["y"]) for p in alone.raw["edges"][0]["points"]]
            if not _crossed(_Edge(e.connection, e.a, e.b, e.pa, e.pb, points), nodes):
                e.points = points
                continue
            for y in _channels(e, nodes, channels):
                candidate = _channel(e, nodes, y)
                if candidate and not _crossed(_Edge(e.connection, e.a, e.b, e.pa, e.pb, candidate), nodes):
                    e.points = candidate
                    channels += 1
                    break
    xs = [nodes[n].x - nodes[n].width / 2 for n in order] + [nodes[n].x + nodes[n].width / 2 for n in order]
    ys = [nodes[n].y - nodes[n].height / 2 for n in order] + [nodes[n].y + nodes[n].height / 2 for n in order]
    for e in edges:
        xs += [p[0] for p in e.points]
        ys += [p[1] for p in e.points]
    return min(xs), min(ys), max(xs), max(ys)


# -- drawing ------------------------------------------------------------------------------------------------
_INK, _OIL, _SIGNAL, _FILL = "#1b1f24", "#1b1f24", "#0b5cad", "white"


class _Pen:
    """Draws into a matplotlib axes in layout coordinates (px, y down), grouping the artists of each element."""

    def __init__(self, ax: Any) -> None:
        self.ax = ax
        self.group: str | None = None
        self._count: dict[str, int] = {}

    def _tag(self, artist: Any) -> Any:
        """Give the artist its element's id: the element's own for the first, ``id/k`` for the next (ids are unique)."""
        if self.group is not None:
            k = self._count.get(self.group, 0)
            self._count[self.group] = k + 1
            artist.set_gid(self.group if k == 0 else f"{self.group}/{k}")
        return artist

    def line(self, pts: list[tuple[float, float]], lw: float = 1.2, color: str = _INK, dash: Any = None,
             z: float = 2.0) -> None:
        xs, ys = zip(*pts, strict=True)
        (artist,) = self.ax.plot(xs, ys, color=color, lw=lw, solid_capstyle="butt", zorder=z,
                                 linestyle=dash if dash is not None else "-")
        self._tag(artist)

    def poly(self, pts: list[tuple[float, float]], fill: str = _FILL, lw: float = 1.2, closed: bool = True,
             z: float = 3.0) -> None:
        from matplotlib.patches import Polygon

        self._tag(self.ax.add_patch(Polygon(pts, closed=closed, facecolor=fill, edgecolor=_INK, lw=lw, zorder=z)))

    def rect(self, x: float, y: float, w: float, h: float, fill: str = _FILL, lw: float = 1.2, z: float = 3.0,
             round_: float = 0.0) -> None:
        from matplotlib.patches import FancyBboxPatch, Rectangle

        patch: Any
        if round_:
            patch = FancyBboxPatch((x, y), w, h, boxstyle=f"round,pad=0,rounding_size={round_}", facecolor=fill,
                                   edgecolor=_INK, lw=lw, zorder=z)
        else:
            patch = Rectangle((x, y), w, h, facecolor=fill, edgecolor=_INK, lw=lw, zorder=z)
        self._tag(self.ax.add_patch(patch))

    def circle(self, x: float, y: float, r: float, fill: str = _FILL, lw: float = 1.2, z: float = 3.0) -> None:
        from matplotlib.patches import Circle

        self._tag(self.ax.add_patch(Circle((x, y), r, facecolor=fill, edgecolor=_INK, lw=lw, zorder=z)))

    def arrow(self, a: tuple[float, float], b: tuple[float, float], color: str = _INK, lw: float = 1.0,
              head: float = 5.0, z: float = 4.0) -> None:
        """A line from ``a`` to ``b`` with a filled head at ``b``."""
        dx, dy = b[0] - a[0], b[1] - a[1]
        n = math.hypot(dx, dy) or 1.0
        ux, uy = dx / n, dy / n
        base = (b[0] - head * ux, b[1] - head * uy)
        self.line([a, base], lw=lw, color=color, z=z)
        left = (base[0] - 0.45 * head * uy, base[1] + 0.45 * head * ux)
        right = (base[0] + 0.45 * head * uy, base[1] - 0.45 * head * ux)
        from matplotlib.patches import Polygon

        self._tag(self.ax.add_patch(Polygon([b, left, right], closed=True, facecolor=color, edgecolor=color, lw=0.5,
                                            zorder=z)))

    def spring(self, a: tuple[float, float], b: tuple[float, float], turns: int = 4, width: float = 5.0) -> None:
        dx, dy = b[0] - a[0], b[1] - a[1]
        n = math.hypot(dx, dy) or 1.0
        ux, uy, px, py = dx / n, dy / n, -dy / n, dx / n
        pts = [a]
        for k in range(1, 2 * turns):
            s = k / (2 * turns)
            side = width if k % 2 else -width
            pts.append((a[0] + s * dx + side * px, a[1] + s * dy + side * py))
        pts.append(b)
        del ux, uy
        self.line(pts, lw=1.0)

    def text(self, x: float, y: float, s: str, size: float = _TEXT_SIZE, weight: str = "normal", ha: str = "left",
             va: str = "center", color: str = _INK) -> None:
        self._tag(self.ax.text(x, y, s, fontsize=size * 0.75, fontweight=weight, ha=ha, va=va, color=color, zorder=6,
                               family="DejaVu Sans"))


def _valve43(pen: _Pen, left: float, top: float, w: float, h: float, comp: Component | None, servo: bool) -> None:
    s = 26.0
    x0, y0 = left + 24, top + (h - s) / 2
    for k in range(3):
        pen.rect(x0 + k * s, y0, s, s)
    # continuous positioning: two lines along the envelope
    for y in (y0 - 4, y0 + s + 4):
        pen.line([(x0, y), (x0 + 3 * s, y)], lw=0.8)
    # left square (a): P->A, B->T parallel; right square (b): P->B, A->T crossed
    xa, xb = x0 + 8, x0 + 18
    pen.arrow((xa, y0 + s), (xa, y0 + 1))
    pen.arrow((xb, y0 + 1), (xb, y0 + s))
    c = x0 + 2 * s
    pen.arrow((c + 8, y0 + s), (c + 18, y0 + 1))
    pen.arrow((c + 18, y0 + s), (c + 8, y0 + 1))
    # centre: closed (lapped) or open (underlapped) ports
    m = x0 + s
    underlapped = comp is not None and any(comp.values.get(k, 0.0) < 0 for k in ("x_PA", "x_AT", "x_PB", "x_BT"))
    for px in (m + 8, m + 18):
        if underlapped:
            pen.line([(px, y0), (px, y0 + s)], lw=1.0)
        else:
            pen.line([(px, y0), (px, y0 + 5)], lw=1.0)
            pen.line([(px - 3, y0 + 5), (px + 3, y0 + 5)], lw=1.0)
            pen.line([(px, y0 + s), (px, y0 + s - 5)], lw=1.0)
            pen.line([(px - 3, y0 + s - 5), (px + 3, y0 + s - 5)], lw=1.0)
    # actuation: a proportional solenoid (or a torque motor) on the left, a centring spring on the right
    if servo:
        pen.rect(left + 2, y0 + 4, 20, s - 8)
        pen.line([(left + 2, y0 + s / 2), (left + 22, y0 + s / 2)], lw=0.8)
        pen.arrow((left + 6, y0 + s - 3), (left + 18, y0 + 3), lw=0.8, head=3.5)
    else:
        pen.rect(left + 4, y0 + 5, 18, s - 10)
        pen.line([(left + 8, y0 + s - 5), (left + 18, y0 + 5)], lw=0.8)
        pen.line([(left + 12, y0 + s - 5), (left + 22, y0 + 5)], lw=0.8)
    pen.spring((x0 + 3 * s, y0 + s / 2), (left + w, y0 + s / 2), turns=3, width=4.0)


def _symbol(pen: _Pen, node: _Node) -> None:
    """Draw the node's symbol (ISO 1219-1) in its box."""
    kind, comp = node.shape.kind, node.comp
    left, top, w, h = node.symbol_box
    cx, cy = left + w / 2, top + h / 2
    if kind in ("valve43", "servovalve"):
        _valve43(pen, left, top, w, h, comp, kind == "servovalve")
    elif kind == "cylinder":
        body = w - 30
        pen.rect(left, top, body, h)
        piston = left + 0.38 * body
        pen.rect(piston - 2.5, top + 1, 5, h - 2, fill=_INK)
        pen.line([(piston, cy), (left + w, cy)], lw=3.0)
        double = comp is not None and abs(comp.values.get("A_A", 0.0) - comp.values.get("A_B", 1.0)) < 1e-12
        if double:
            pen.line([(left - 12, cy), (piston, cy)], lw=3.0)
    elif kind in ("pump", "pump_variable", "motor", "source"):
        r = min(w, h) / 2
        pen.circle(cx, cy, r)
        if kind == "motor":
            pen.poly([(cx, top + 0.55 * r), (cx - 0.35 * r, top + 1), (cx + 0.35 * r, top + 1)], fill=_INK)
        else:
            pen.poly([(cx, top + 1), (cx - 0.38 * r, top + 0.6 * r), (cx + 0.38 * r, top + 0.6 * r)], fill=_INK)
        if kind != "source":
            pen.line([(left - 10, cy), (cx - r, cy)], lw=1.0)
            pen.line([(left - 7, cy - 3), (left - 7, cy + 3)], lw=1.0)
        if kind == "pump_variable":
            pen.arrow((cx - 1.1 * r, cy + 1.1 * r), (cx + 1.1 * r, cy - 1.1 * r), lw=1.0, head=5)
        if comp is not None and type(comp).__name__ == "PressureTable":
            pen.text(cx, cy + 0.35 * r, "p(t)", size=7, ha="center")
    elif kind == "tank":
        pen.line([(left, top), (left, top + h), (left + w, top + h), (left + w, top)], lw=1.4)
    elif kind in ("relief", "reducing"):
        pen.rect(left + 4, top, w - 12, h)
        x = left + 4 + (w - 12) * 0.45
        if kind == "relief":
            pen.arrow((x - 4, top + 4), (x - 4, top + h - 3))
        else:
            pen.arrow((x, top + 4), (x, top + h - 3))
        pen.spring((left + w - 8, top + h / 2), (left + w, top + h / 2), turns=2, width=3.0)
        pilot_y = top + 2 if kind == "relief" else top + h - 2
        pen.line([(x, pilot_y), (left, pilot_y), (left, cy), (left + 4, cy)], lw=0.7, dash=(0, (3, 2)))
    elif kind == "counterbalance":
        pen.rect(left + 6, top, w - 18, h)
        pen.arrow((left + 14, top + h - 3), (left + 14, top + 4))
        pen.circle(left + 26, cy, 4)
        pen.spring((left + w - 12, cy), (left + w, cy), turns=2, width=3.0)
        pen.line([(left, cy), (left + 6, cy)], lw=0.7, dash=(0, (3, 2)))
    elif kind == "check":
        pen.line([(cx, top), (cx, top + 5)], lw=1.2)
        pen.line([(cx - 7, top + 9), (cx, top + 17), (cx + 7, top + 9)], lw=1.2)
        pen.circle(cx, top + 11, 4.5)
        pen.line([(cx, top + 17), (cx, top + h)], lw=1.2)
    elif kind == "orifice":
        pen.line([(cx, top), (cx, top + h)], lw=1.2)
        from matplotlib.patches import Arc

        for sign in (-1, 1):
            pen._tag(pen.ax.add_patch(Arc((cx + sign * 8, cy), 12, 16, theta1=90 if sign > 0 else -90,
                                          theta2=270 if sign > 0 else 90, color=_INK, lw=1.1, zorder=4)))
    elif kind == "accumulator":
        pen.rect(left, top, w, h - 6, round_=w / 2 - 1)
        pen.line([(left + 2, top + 0.42 * (h - 6)), (left + w - 2, top + 0.42 * (h - 6))], lw=1.0)
        pen.line([(cx, top + h - 6), (cx, top + h)], lw=1.2)
    elif kind == "volume":
        pen.circle(cx, cy, w / 2)
        pen.text(cx, cy, "V", size=8, ha="center")
    elif kind in ("line", "hose"):
        if kind == "hose":
            pen.line([(cx, top), (cx - 4, top + h * 0.3), (cx + 4, top + h * 0.7), (cx, top + h)], lw=1.6)
        else:
            pen.line([(cx - 3, top + 4), (cx - 3, top + h - 4)], lw=1.0)
            pen.line([(cx + 3, top + 4), (cx + 3, top + h - 4)], lw=1.0)
            pen.line([(cx, top), (cx, top + 4)], lw=1.2)
            pen.line([(cx, top + h - 4), (cx, top + h)], lw=1.2)
            pen.line([(cx - 6, top + 4), (cx + 6, top + 4)], lw=1.0)
            pen.line([(cx - 6, top + h - 4), (cx + 6, top + h - 4)], lw=1.0)
    elif kind == "mass":
        pen.rect(left, top, w - 18, h)
        pen.text(left + (w - 18) / 2, cy, "m", size=11, ha="center", weight="bold")
        spring = comp is not None and comp.values.get("k_spring", 0.0) > 0
        if spring:
            pen.spring((left + w - 18, cy), (left + w - 2, cy), turns=3, width=4.0)
            pen.line([(left + w - 2, top + 4), (left + w - 2, top + h - 4)], lw=1.4)
    else:  # a block
        pen.rect(left, top, w, h, round_=4.0, fill="#f4f8fc")


def _label(pen: _Pen, node: _Node) -> None:
    if not node.lines:
        return
    s = node.shape
    left, top, w, h = node.symbol_box
    if s.label == "inside":
        y = top + h / 2 - 5.5 * (len(node.lines) - 1)
        for k, line in enumerate(node.lines):
            pen.text(left + w / 2, y + 11 * k, line, size=_NAME_SIZE if k == 0 else _TEXT_SIZE,
                     weight="bold" if k == 0 else "normal", ha="center")
        return
    if s.label == "top":
        x, y0 = node.x - node.width / 2, node.y - node.height / 2 + 7
    else:
        x, y0 = left + w + 8, node.y - 5.5 * (len(node.lines) - 1)
    for k, line in enumerate(node.lines):
        pen.text(x, y0 + 11 * k, line, size=_NAME_SIZE if k == 0 else _TEXT_SIZE, weight="bold" if k == 0 else "normal",
                 color=_INK if k == 0 else "#3b4450")


def _route(e: _Edge, nodes: dict[str, _Node]) -> list[tuple[float, float]]:
    """The edge's points from the symbol's port to the other's: the engine's route, extended from each node's
    border to the port on the symbol where the label sits between them."""
    pts = list(e.points)
    for end, name, port in ((0, e.a, e.pa), (-1, e.b, e.pb)):
        if port is None or not pts:
            continue
        px, py = nodes[name].port_point(port)
        x, y = pts[end]
        if abs(px - x) > 0.5 or abs(py - y) > 0.5:
            if end == 0:
                pts.insert(0, (px, py))
            else:
                pts.append((px, py))
    return pts


def _turn_lines(found: Circuit, nodes: dict[str, _Node]) -> None:
    """A line's end toward the actuators on top: the end whose other ports sit higher up the page."""
    for name, node in nodes.items():
        if node.shape.kind not in ("line", "hose") or len(node.shape.ports) != 2:
            continue
        first, second = list(node.shape.ports)
        height: dict[str, list[float]] = {first: [], second: []}
        for conn in found.connections:
            if conn.kind != "link":
                continue
            ports = [e.split(".", 1) for e in conn.ends]
            for c, p in ports:
                if c == name and p in height:
                    height[p] += [_level(nodes[o]) for o, _ in ports if o != name]
        mean = {p: sum(v) / len(v) if v else 5.0 for p, v in height.items()}
        if mean[second] < mean[first]:
            node.shape.ports = {first: Port("bottom"), second: Port("top")}


def _riders(found: Circuit) -> dict[str, str]:
    """Loads that ride on one actuator's rod (a Mass coupled to exactly one cylinder or motor): load -> actuator."""
    partners: dict[str, set[str]] = {}
    for conn in found.connections:
        if conn.kind == "mechanical":
            a, b = conn.ends
            partners.setdefault(a, set()).add(b)
            partners.setdefault(b, set()).add(a)
    out = {}
    for name, others in partners.items():
        if type(found.components[name]).__name__ == "Mass" and len(others) == 1:
            (actuator,) = others
            if type(found.components[actuator]).__name__ != "Mass" and len(partners[actuator]) == 1:
                out[name] = actuator
    return out


@dataclass
class Schematic:
    """A system's circuit diagram (module notes): its SVG, what it drew, and writers."""

    name: str
    svg: str
    components: list[str]
    connections: list[str]  #: the ids of the connections drawn (``link:...``, ``signal:...``, ``mechanical:...``)
    figure: Any = field(repr=False, default=None)
    #: each component's box (symbol and label) as drawn: name -> (left, top, right, bottom) [px]
    boxes: dict[str, tuple[float, float, float, float]] = field(default_factory=dict, repr=False)

    def save(self, path: str | Path) -> Path:
        """Write the drawing as SVG, PNG or PDF, by the suffix of ``path``."""
        path = Path(path)
        suffix = path.suffix.lower().lstrip(".")
        if suffix not in FORMATS:
            raise ParameterError(
                f"schematic file {str(path)!r}: unknown format {suffix or '(no suffix)'!r}; expected .svg, .png or .pdf"
            )
        if suffix == "svg":
            path.write_text(self.svg, encoding="utf-8")
        else:
            self.figure.savefig(path, format=suffix, dpi=150)
        return path

    def _repr_svg_(self) -> str:
        return self.svg


def draw(system: System, *, parameters: bool = True, title: str | None = None) -> Schematic:
    """The circuit diagram of ``system`` (module notes): each component's symbol with its name and, with
    ``parameters``, its main parameters in the units they were given in."""
    import matplotlib
    from matplotlib.figure import Figure  # not pyplot: the backend in use (a notebook's) is never changed

    found = circuit(system)
    nodes: dict[str, _Node] = {}
    for name, comp in found.components.items():
        lines = [name] + (parameter_lines(comp) if parameters else [])
        if shape_of(comp).kind == "block":
            lines.insert(1, type(comp).__name__)
        nodes[name] = _Node(name, comp, shape_of(comp), lines)
    _turn_lines(found, nodes)
    edges: list[_Edge] = []
    junctions = 0
    for conn in found.connections:
        if conn.kind == "link":
            ends = [e.split(".", 1) for e in conn.ends]
            if len(ends) == 2:
                (ca, pa), (cb, pb) = ends
                edges.append(_Edge(conn, ca, cb, nodes[ca].shape.ports.get(pa), nodes[cb].shape.ports.get(pb)))
                continue
            volumes = [k for k, (c, _) in enumerate(ends) if nodes[c].shape.kind in ("volume", "accumulator")]
            if volumes:  # the node's volume joins the others itself
                vc, vp = ends[volumes[0]]
                for k, (c, p) in enumerate(ends):
                    if k != volumes[0]:
                        edges.append(_Edge(conn, vc, c, nodes[vc].shape.ports.get(vp), nodes[c].shape.ports.get(p)))
                continue
            junctions += 1
            hub = f"~junction{junctions}"
            nodes[hub] = _Node(hub, None, Shape("junction", 8, 8, {"any": Port("top")}, label="none"), [],
                               level=max(_level(nodes[c]) for c, _ in ends) - 0.5)
            for c, p in ends:
                edges.append(_Edge(conn, c, hub, nodes[c].shape.ports.get(p), None))
        elif conn.kind == "mechanical":
            a, b = conn.ends
            edges.append(_Edge(conn, a, b, nodes[a].shape.ports.get("rod"), nodes[b].shape.ports.get("rod")))
        else:
            a, b = conn.ends
            target_in = nodes[b].shape.ports.get("in")
            edges.append(_Edge(conn, a, b, nodes[a].shape.ports.get("out"), target_in))
    riders = _riders(found)
    x0, y0, x1, y1 = _layout(nodes, edges, riders)
    margin = 30.0
    x0, y0 = x0 - margin, y0 - margin - (26 if title else 0)
    x1, y1 = x1 + margin, y1 + margin
    width, height = x1 - x0, y1 - y0
    fig = Figure(figsize=(width / 100, height / 100), dpi=100)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y1, y0)
    ax.set_aspect("equal")
    ax.axis("off")
    pen = _Pen(ax)
    drawn_connections: list[str] = []
    for conn in found.connections:
        pen.group = conn.ident
        drawn_connections.append(conn.ident)
        for e in (e for e in edges if e.connection is conn):
            pts = _route(e, nodes)
            if len(pts) < 2:
                continue
            if conn.kind == "link":
                pen.line(pts, lw=1.6, color=_OIL, z=2)
            elif conn.kind == "mechanical":
                pen.line(pts, lw=4.0, color=_INK, z=1.5)
                pen.line(pts, lw=1.8, color="white", z=1.6)
            else:
                pen.line(pts[:-1] + [pts[-1]], lw=1.0, color=_SIGNAL, dash=(0, (4, 2.5)), z=2)
                pen.arrow(pts[-2], pts[-1], color=_SIGNAL, lw=0.01, head=6.0, z=2.5)
    for name, node in nodes.items():
        if node.comp is None:
            pen.group = f"junction:{name.lstrip('~')}"
            pen.circle(node.x, node.y, 3.2, fill=_OIL, lw=0.5, z=5)
            continue
        pen.group = f"component:{name}"
        _symbol(pen, node)
        _label(pen, node)
    if title:
        pen.group = "title"
        pen.text(x0 + margin, y0 + 16, title, size=13, weight="bold")
    buffer = io.StringIO()
    with matplotlib.rc_context({"svg.fonttype": "none", "svg.hashsalt": "hydroservo"}):
        fig.savefig(buffer, format="svg")
    boxes = {n: (node.x - node.width / 2, node.y - node.height / 2, node.x + node.width / 2, node.y + node.height / 2)
             for n, node in nodes.items() if node.comp is not None}
    return Schematic(system.name, buffer.getvalue(), list(found.components), drawn_connections, fig, boxes)


def drawn(svg: str) -> tuple[set[str], set[str]]:
    """The components and connections an SVG drawing holds, read from its elements' ids (not from pixels)."""
    import xml.etree.ElementTree as ET

    root = ET.fromstring(svg)
    ids = {el.get("id", "").split("/", 1)[0] for el in root.iter()}
    components = {i.split(":", 1)[1] for i in ids if i.startswith("component:")}
    connections = {i for i in ids if i.split(":", 1)[0] in ("link", "signal", "mechanical")}
    return components, connections


def missing(system: System, svg: str) -> list[str]:
    """What of ``system`` a drawing leaves out: components and connections without their element (empty: none)."""
    components, connections = drawn(svg)
    found = circuit(system)
    out = [f"component {c}" for c in found.components if c not in components]
    out += [f"connection {c.ident}" for c in found.connections if c.ident not in connections]
    return out

