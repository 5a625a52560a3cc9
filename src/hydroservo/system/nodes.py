"""Hydraulic and mechanical nodes: ports connected once, resolved into the signals the equations read.

A user connects hydraulic ports (:class:`~hydroservo.components.base.Hydraulic`)
as they draw them: ``connect("valve.A", "cyl.A")``; links that share a port
join into one node (``connect("pump.P", "relief.P")`` and
``connect("pump.P", "valve.P")`` make one supply node of three ports).

Each node needs exactly one **pressure port** (a volume, a cylinder chamber,
an accumulator, a line end, a pressure source): it gives the node's pressure,
and receives the sum of the flows of all the node's **flow ports** (valves,
orifices, pumps, relief valves), which read that pressure. This is the lumped
node of [Merritt1967] section 5.2 (continuity at a volume) and the C/Q
alternation of Hopsan's transmission-line method: a flow port between two
pressure ports, a pressure port between flow ports. A node without a pressure
port has no pressure (the engine asks for a volume there); a node with two has
two (the engine asks for a resistance between them).

Mechanical ports (:class:`~hydroservo.components.base.Mechanical`) join the
same way, with the roles of a rigid point: each node needs exactly one
**motion port** (a mass, a fixed point, a velocity source), which gives the
node's position and velocity and receives the sum of the forces of all its
**force ports** (a cylinder's rod, a spring, a damper, a force source), which
read that motion. Each port counts its signals in its own direction, outward
from its component or inward; two connected ports face each other, so a force
port's position is the motion port's times :math:`-s_f s_m` (``s`` = +1
outward, -1 inward), and its force reaches the motion port with that factor
too. Hopsan's mechanical nodes join one Q component (the mass) to one C
component (the spring, the cylinder), as a motion port to a force port.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from hydroservo.components.base import Component, Hydraulic, Mechanical
from hydroservo.errors import ModelError

__all__ = ["Node", "port_of", "port_signals", "port_kind", "nodes", "resolve"]


@dataclass(frozen=True)
class Node:
    """A set of connected ports ("comp.port"), hydraulic or mechanical, in the order they were first connected."""

    ports: tuple[str, ...]

    def __str__(self) -> str:
        return " – ".join(self.ports)


def port_of(components: Mapping[str, Component], ref: str) -> tuple[Component, Hydraulic | Mechanical] | None:
    """The component and the hydraulic or mechanical port named ``ref`` ("comp.port"), or None if ``ref`` names
    no port."""
    parts = ref.split(".")
    if len(parts) != 2 or parts[0] not in components:
        return None
    comp = components[parts[0]]
    port = comp.HYDRAULIC.get(parts[1]) or comp.MECHANICAL.get(parts[1])
    return None if port is None else (comp, port)


def port_signals(port: Hydraulic | Mechanical) -> tuple[str, ...]:
    """The signals a port bundles."""
    return (port.p, port.Q) if isinstance(port, Hydraulic) else (port.x, port.v, port.F)


def port_kind(port: Hydraulic | Mechanical) -> str:
    """"hydraulic", or the kind of a mechanical port ("translational", "rotational")."""
    return "hydraulic" if isinstance(port, Hydraulic) else port.kind


def is_motion_port(comp: Component, port: Mechanical) -> bool:
    """True if the component gives the port's motion (and takes its force)."""
    return port.x in comp.OUTPUTS


def is_pressure_port(comp: Component, port: Hydraulic) -> bool:
    """True if the component gives the port's pressure (and takes its flow)."""
    return port.p in comp.OUTPUTS


def nodes(links: Iterable[tuple[str, str]]) -> list[Node]:
    """The nodes that ``links`` (pairs of ports) form: ports joined directly or through other ports."""
    parent: dict[str, str] = {}

    def root(a: str) -> str:
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    order: list[str] = []
    for a, b in links:
        for x in (a, b):
            if x not in parent:
                parent[x] = x
                order.append(x)
        ra, rb = root(a), root(b)
        if ra != rb:
            parent[rb] = ra
    groups: dict[str, list[str]] = {}
    for x in order:
        groups.setdefault(root(x), []).append(x)
    return [Node(tuple(g)) for g in groups.values()]


def resolve(
    components: Mapping[str, Component], links: Iterable[tuple[str, str]]
) -> dict[str, list[tuple[float, str]]]:
    """The inputs that the hydraulic and mechanical nodes feed: "comp.input" -> terms (coefficient, "comp.output").

    A flow port's pressure input reads the node's pressure port; the pressure
    port's flow input is the sum of the flows the flow ports deliver into the
    node, each with the sign its port counts it by. A force port's position
    and velocity read the node's motion port; the motion port's force input is
    the sum of the forces of the force ports, each turned into its direction.

    Raises
    ------
    ModelError
        A node with no pressure (motion) port or with more than one, naming the
        node, the ports and what to add.
    """
    fed: dict[str, list[tuple[float, str]]] = {}
    for node in nodes(links):
        pressure: list[tuple[str, Component, Hydraulic]] = []
        flow: list[tuple[str, Component, Hydraulic]] = []
        for ref in node.ports:
            found = port_of(components, ref)
            assert found is not None  # links are checked when they are made
            comp, port = found
            if isinstance(port, Mechanical):
                break
            (pressure if is_pressure_port(comp, port) else flow).append((ref, comp, port))
        else:
            _hydraulic_node(node, pressure, flow, fed)
            continue
        _mechanical_node(components, node, fed)
    return fed


def _hydraulic_node(
    node: Node,
    pressure: list[tuple[str, Component, Hydraulic]],
    flow: list[tuple[str, Component, Hydraulic]],
    fed: dict[str, list[tuple[float, str]]],
) -> None:
        if not pressure:
            raise ModelError(
                f"hydraulic node {node}: every port there takes a pressure and gives a flow, so nothing sets the "
                f"node's pressure; connect a Volume there (e.g. Volume('v1', V='0.1 L') and connect 'v1.P' to "
                f"{node.ports[0]!r}), or a line or an accumulator, whose oil holds the pressure"
            )
        if len(pressure) > 1:
            names = ", ".join(ref for ref, _, _ in pressure)
            raise ModelError(
                f"hydraulic node {node}: {names} each set the node's pressure (each holds a volume of oil or is a "
                f"pressure source); connect them through a flow port (an Orifice, a Line with flow ends, a valve), "
                f"or give one volume for both"
            )
        ref, comp, port = pressure[0]
        cname = ref.split(".")[0]
        terms = []
        for fref, _, fport in flow:
            fname = fref.split(".")[0]
            fed[f"{fname}.{fport.p}"] = [(1.0, f"{cname}.{port.p}")]
            # flow into the pressure port = the flows the flow ports deliver into the node
            terms.append((-fport.sign * port.sign, f"{fname}.{fport.Q}"))
        fed[f"{cname}.{port.Q}"] = terms


def _mechanical_node(components: Mapping[str, Component], node: Node, fed: dict[str, list[tuple[float, str]]]) -> None:
    """Feed a mechanical node: the force ports read the motion port's position and velocity, and the motion
    port's force input sums their forces, each turned by -s_f s_m into the motion port's direction (a mass's two
    ends each have their own force input: F at end 2, F_P1 at end 1)."""
    motion: list[tuple[str, Mechanical]] = []
    force: list[tuple[str, Mechanical]] = []
    for ref in node.ports:
        found = port_of(components, ref)
        assert found is not None
        comp, port = found
        assert isinstance(port, Mechanical)
        (motion if is_motion_port(comp, port) else force).append((ref, port))
    if not motion:
        raise ModelError(
            f"mechanical node {node}: every port there takes a motion and gives a force, so nothing moves the "
            f"node; connect a mass there (Mass), or a fixed point (FixedPosition) or a velocity source"
        )
    if len(motion) > 1:
        names = ", ".join(ref for ref, _ in motion)
        raise ModelError(
            f"mechanical node {node}: {names} each set the node's motion (each is a mass, a fixed point or a motion "
            f"source); join them through a force port (a Spring, a Damper), or make them one mass"
        )
    mref, mport = motion[0]
    mname = mref.split(".")[0]
    terms = fed.setdefault(f"{mname}.{mport.F}", [])
    for fref, fport in force:
        fname = fref.split(".")[0]
        factor = -fport.sign * mport.sign
        fed[f"{fname}.{fport.x}"] = [(factor, f"{mname}.{mport.x}")]
        fed[f"{fname}.{fport.v}"] = [(factor, f"{mname}.{mport.v}")]
        terms.append((factor, f"{fname}.{fport.F}"))
