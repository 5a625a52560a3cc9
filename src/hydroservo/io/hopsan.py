"""Hopsan model files (``.hmf``) read into a plain structure: the first step of importing a Hopsan model.

:func:`read_hmf` reads what a Hopsan model file declares, with nothing of Hopsan's laws yet: the components
(type, name, path through the subsystems, parameters with their units and values evaluated), the connections
between their ports with the subsystems flattened (a connection through a subsystem's port joins the ports on
either side), the system parameters, and the simulation settings (start, stop, time step). Mapping the
components to hydroservo's, with Hopsan's laws, comes on top of this (issue 26).

An ``.hmf`` comes from someone else, so it is read defensively:

* XML through defusedxml, which refuses entity declarations (no billion laughs) and external entities or DTDs
  (nothing fetched, no file read), on top of expat;
* only a regular file, of at most the cap of model files (:data:`hydroservo.io.files.CAPS`, 20 MB unless
  ``HYDROSERVO_MAX_MODEL_MB`` says otherwise), read by :func:`hydroservo.io.files.read_bytes`; an encoding its
  XML declaration names that cannot be read is refused; at most :data:`MAX_DEPTH` levels of subsystems,
  :data:`MAX_COMPONENTS` components;
* parameter values evaluated by a bounded grammar (:func:`evaluate`: numbers, names of system parameters, ``+``,
  ``-``, ``*``, ``/``, ``^``, parentheses; at most 200 characters and 20 levels deep), never by ``eval``;
* every refusal a :class:`~hydroservo.errors.ModelFileError` naming the file, the component's path and the
  parameter, with what was expected.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from hydroservo.errors import ModelFileError, shorten
from hydroservo.io.files import plain_float, read_bytes

if TYPE_CHECKING:
    from xml.etree.ElementTree import Element

__all__ = [
    "HopsanModel",
    "HopsanComponent",
    "HopsanParameter",
    "read_hmf",
    "evaluate",
    "MAX_DEPTH",
    "MAX_COMPONENTS",
]

#: The deepest nesting of subsystems read.
MAX_DEPTH = 32
#: The most components read (all subsystems together).
MAX_COMPONENTS = 20_000
#: Joins a subsystem path inside the reader: no character a Hopsan name may hold (names hold "/": "4/3 Valve").
_SEP = "\x1f"
#: The longest parameter expression read [characters], and its deepest nesting.
MAX_EXPRESSION = 200
MAX_NESTING = 20


@dataclass
class HopsanParameter:
    """One parameter as the file gives it: the text of its value, its unit as Hopsan writes it, and the value
    evaluated (None if the text is no number and no expression of system parameters, such as a text parameter)."""

    name: str
    text: str
    unit: str
    value: float | None


@dataclass
class HopsanComponent:
    """One component: Hopsan's type (``Hydraulic43Valve``), its name, and the path of subsystems it sits in."""

    typename: str
    name: str
    path: tuple[str, ...]  #: the subsystems it sits in, outermost first (empty at the top level)
    parameters: dict[str, HopsanParameter] = field(default_factory=dict)
    cqs: str = ""  #: Hopsan's C, Q or S type (its transmission-line role)

    @property
    def full_name(self) -> str:
        """The path and the name joined by dots (``Servo1.Gain``)."""
        return ".".join((*self.path, self.name))


@dataclass
class HopsanModel:
    """What a Hopsan model file declares, subsystems flattened."""

    name: str
    source: str
    start: float  #: [s]
    stop: float  #: [s]
    timestep: float  #: [s]
    parameters: dict[str, HopsanParameter]  #: the top-level system parameters
    components: list[HopsanComponent]
    #: the ports joined, each group a tuple of ``component.port`` by full name: a connection between two
    #: components is a pair; a subsystem's port joins every port connected to it, inside and outside
    connections: list[tuple[str, ...]]
    description: str = ""

    def component(self, full_name: str) -> HopsanComponent:
        """The component of this full name (``Servo1.Gain``)."""
        for comp in self.components:
            if comp.full_name == full_name:
                return comp
        raise KeyError(full_name)

    def types(self) -> dict[str, int]:
        """How many components of each Hopsan type the model holds."""
        found: dict[str, int] = {}
        for comp in self.components:
            found[comp.typename] = found.get(comp.typename, 0) + 1
        return dict(sorted(found.items()))


# -- parameter expressions ---------------------------------------------------------------------------------------

_TOKEN = re.compile(r"\s*(?:(?P<number>(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)|(?P<name>[A-Za-z_][\w.]*)|(?P<op>[-+*/^()]))")


def evaluate(text: str, names: dict[str, float], *, what: str = "value") -> float:
    """The value of a Hopsan parameter expression: numbers, names of system parameters (``names``), ``+``,
    ``-``, ``*``, ``/``, ``^`` (power, right-associative), unary signs and parentheses; nothing else is read,
    and nothing is executed.

    Raises
    ------
    ValueError
        With what is wrong: an unknown name, a character or a function the grammar does not read, a text
        longer than :data:`MAX_EXPRESSION` or nested deeper than :data:`MAX_NESTING`, a result that is not finite.

    Examples
    --------
    >>> evaluate("2*Cyl_A1 + 1e-4", {"Cyl_A1": 0.001})
    0.0021
    >>> evaluate("-(2^3)^2/4", {})
    -16.0
    """
    if len(text) > MAX_EXPRESSION:
        raise ValueError(f"{what}: {len(text)} characters; expected an expression of at most {MAX_EXPRESSION}")
    tokens: list[tuple[str, str]] = []
    k = 0
    stripped = text.rstrip()
    while k < len(stripped):
        match = _TOKEN.match(stripped, k)
        if match is None or match.end() == k:
            raise ValueError(
                f"{what}: {shorten(text)!r}: cannot read {stripped[k:k + 10]!r}; expected numbers, system parameters, "
                "+ - * / ^ and parentheses"
            )
        kind = match.lastgroup or ""
        tokens.append((kind, match.group(kind)))
        k = match.end()
    if not tokens:
        raise ValueError(f"{what}: empty; expected a number or an expression")
    position = 0

    def peek() -> tuple[str, str]:
        return tokens[position] if position < len(tokens) else ("end", "")

    def take() -> tuple[str, str]:
        nonlocal position
        token = peek()
        position += 1
        return token

    def expression(depth: int) -> float:
        value = term(depth)
        while peek() in (("op", "+"), ("op", "-")):
            op = take()[1]
            value = value + term(depth) if op == "+" else value - term(depth)
        return value

    def term(depth: int) -> float:
        value = unary(depth)
        while peek() in (("op", "*"), ("op", "/")):
            op = take()[1]
            right = unary(depth)
            if op == "/" and right == 0.0:
                raise ValueError(f"{what}: {shorten(text)!r}: division by zero")
            value = value * right if op == "*" else value / right
        return value

    def unary(depth: int) -> float:  # a sign binds looser than a power: -A^2 = -(A^2)
        if peek() in (("op", "-"), ("op", "+")):
            sign = -1.0 if take()[1] == "-" else 1.0
            return sign * unary(depth)
        return power(depth)

    def power(depth: int) -> float:
        base = atom(depth)
        if peek() == ("op", "^"):
            take()
            exponent = unary(depth)  # right-associative, signed: 2^3^2 = 2^9, 2^-1 = 0.5
            try:
                raised = base**exponent
            except (OverflowError, ZeroDivisionError):
                raise ValueError(f"{what}: {shorten(text)!r}: the power is not finite") from None
            if isinstance(raised, complex):
                raise ValueError(f"{what}: {shorten(text)!r}: a negative number to a fractional power")
            return float(raised)
        return base

    def atom(depth: int) -> float:
        if depth > MAX_NESTING:
            raise ValueError(f"{what}: {shorten(text)!r}: nested more than {MAX_NESTING} deep")
        kind, value = take()
        if kind == "number":
            return float(value)
        if kind == "name":
            if peek() == ("op", "("):
                raise ValueError(f"{what}: {shorten(text)!r}: function {value}() is not read; expected arithmetic only")
            if value not in names:
                known = ", ".join(sorted(names)) or "none"
                raise ValueError(f"{what}: {shorten(text)!r}: no system parameter {value!r} (known: {known})")
            return names[value]
        if (kind, value) == ("op", "("):
            inner = expression(depth + 1)
            if take() != ("op", ")"):
                raise ValueError(f"{what}: {shorten(text)!r}: a parenthesis is not closed")
            return inner
        raise ValueError(f"{what}: {shorten(text)!r}: expected a number, a name or '(' where {value or 'the end'!r} is")

    result = expression(0)
    if position != len(tokens):
        raise ValueError(f"{what}: {shorten(text)!r}: unexpected {tokens[position][1]!r}")
    if not math.isfinite(result):
        raise ValueError(f"{what}: {shorten(text)!r} is not finite")
    return result


# -- the file ------------------------------------------------------------------------------------------------------


_DECLARED_ENCODING = re.compile(rb"""^\s*<\?xml[^>]*?\bencoding\s*=\s*["']([^"']{0,60})["']""")


def _parse(path: Path) -> Element:
    """The root element of ``path``, parsed by defusedxml (no entities, no DTD, nothing fetched)."""
    from defusedxml import DefusedXmlException
    from defusedxml.ElementTree import ParseError, fromstring

    data = read_bytes(path, "Hopsan model", ModelFileError, kind="model")
    try:
        root = fromstring(data, forbid_dtd=True, forbid_entities=True, forbid_external=True)
    except DefusedXmlException as exc:
        raise ModelFileError(
            f"Hopsan model {str(path)!r}: refused ({type(exc).__name__}: {exc}); expected a plain .hmf file "
            "without a DTD or entities"
        ) from None
    except ParseError as exc:
        raise ModelFileError(f"Hopsan model {str(path)!r}: not well-formed XML ({exc}); expected an .hmf file") from None
    except (LookupError, ValueError, UnicodeError) as exc:  # expat asks Python's codecs for an encoding it lacks
        declared = _DECLARED_ENCODING.match(data)
        named = f"the encoding {declared.group(1).decode('ascii', 'replace')!r}" if declared else "its encoding"
        raise ModelFileError(
            f"Hopsan model {str(path)!r}: its XML declaration names {named}, which cannot be read ({shorten(str(exc), 120)}); "
            "expected UTF-8, as Hopsan writes (or ISO-8859-1, US-ASCII, UTF-16)"
        ) from None
    if root.tag != "hopsanmodelfile":
        raise ModelFileError(f"Hopsan model {str(path)!r}: root element <{shorten(root.tag)}>; expected <hopsanmodelfile>")
    return root


def _float(text: str | None, where: str, what: str, default: float) -> float:
    if text is None or not text.strip():
        return default
    try:
        value = plain_float(text)
    except ValueError:
        raise ModelFileError(f"{where}: {what} = {shorten(text)!r}; expected a number") from None
    if not math.isfinite(value):
        raise ModelFileError(f"{where}: {what} = {shorten(text)!r}; expected a finite number")
    return value


class _Reader:
    """Walks the systems of a file: components, parameters in scope, connections through subsystem ports."""

    def __init__(self, source: str, old_names: bool = False) -> None:
        self.source = source
        #: a file of Hopsan before 0.6 names port variables P1::Pressure; Hopsan's loader reads them as P1#Pressure
        self.old_names = old_names
        self.components: list[HopsanComponent] = []
        # port graph: "path/comp.port" <-> "path/comp.port"; a subsystem's port is "path/sub.port" seen from
        # outside and "path/sub/port.P" seen from inside (a systemport's own port), joined below
        self.edges: list[tuple[str, str]] = []
        self.system_ports: list[str] = []

    def where(self, path: tuple[str, ...], name: str = "") -> str:
        inside = ".".join((*path, name)) if name else ".".join(path) or "the top-level system"
        return f"Hopsan model {self.source!r}, {inside}"

    def parameters(self, element: Element | None, scope: dict[str, float], path: tuple[str, ...], owner: str) -> dict[str, HopsanParameter]:
        found: dict[str, HopsanParameter] = {}
        if element is None:
            return found
        for item in element.findall("parameter"):
            name = item.get("name") or ""
            if self.old_names:
                name = _renamed_old_parameter(name)
            text = item.get("value") or ""
            unit = item.get("unit") or ""
            if not name:
                raise ModelFileError(f"{self.where(path, owner)}: a parameter without a name; expected name=\"...\"")
            kind = (item.get("type") or "double").lower()
            value: float | None = None
            if text.strip().lower().lstrip("+-") in ("nan", "inf"):  # Hopsan writes an unset value so
                value = float(text.strip().lower().replace("+", ""))
            elif kind == "bool" or text.strip().lower() in ("true", "false"):
                value = 1.0 if text.strip().lower() in ("true", "1") else 0.0
            elif kind in ("double", "integer", "int"):
                try:
                    value = evaluate(text, scope, what=f"{name} = {shorten(text)!r}")
                except ValueError as exc:
                    raise ModelFileError(f"{self.where(path, owner)}: parameter {exc}") from None
            found[name] = HopsanParameter(name, text, unit, value)
        return found

    def system(self, element: Element, path: tuple[str, ...], scope: dict[str, float]) -> dict[str, HopsanParameter]:
        if len(path) > MAX_DEPTH:
            raise ModelFileError(f"{self.where(path)}: subsystems nested more than {MAX_DEPTH} deep")
        own = self.parameters(element.find("parameters"), scope, path, "")
        inner = {**scope, **{k: p.value for k, p in own.items() if p.value is not None}}
        objects = element.find("objects")
        here: set[str] = set()  # the names a connection of this system may name
        for child in list(objects) if objects is not None else []:
            name = child.get("name") or ""
            here.add(name)
            if child.tag in ("component", "system") and not name:
                raise ModelFileError(f"{self.where(path)}: a <{child.tag}> without a name")
            if child.tag == "component":
                if len(self.components) >= MAX_COMPONENTS:
                    raise ModelFileError(f"{self.where(path)}: more than {MAX_COMPONENTS} components")
                typename = child.get("typename") or ""
                if not typename:
                    raise ModelFileError(f"{self.where(path, name)}: a component without a typename")
                params = self.parameters(child.find("parameters"), inner, path, name)
                self.components.append(HopsanComponent(typename, name, path, params, child.get("cqstype") or ""))
            elif child.tag == "system":
                self.system(child, (*path, name), inner)
            elif child.tag == "systemport":
                self.system_ports.append(_SEP.join((*path, name)))
        connections = element.find("connections")
        for link in list(connections) if connections is not None else []:
            if link.tag != "connect":
                continue
            ends = [link.get(k) for k in ("startcomponent", "startport", "endcomponent", "endport")]
            if not all(ends):
                raise ModelFileError(f"{self.where(path)}: a <connect> without its start and end component and port")
            a, pa, b, pb = (e or "" for e in ends)
            for named in (a, b):
                if named not in here:
                    raise ModelFileError(
                        f"{self.where(path)}: a <connect> of {a}.{pa} and {b}.{pb} names {named!r}, which is no "
                        "component, subsystem or port of this system"
                    )
            self.edges.append((self.node(path, a, pa), self.node(path, b, pb)))
        return own

    def node(self, path: tuple[str, ...], component: str, port: str) -> str:
        """A port as a node of the graph: a systemport of this system stands for itself, whatever port is named."""
        here = _SEP.join((*path, component))
        return here if here in self.system_ports else f"{here}.{port}"

    def flattened(self) -> list[tuple[str, ...]]:
        """The connections between component ports, through the subsystems: a port outside (``sub.port``) and
        the systemport inside (``sub`` _SEP ``port``) are one junction, and the component ports on either side of it form
        one group. Connections between two components stay pairs (a signal sink's one port may read several
        signals: it is no junction of them)."""
        names = {_SEP.join((*c.path, c.name)) for c in self.components}

        def is_component_port(end: str) -> bool:
            return end.rsplit(".", 1)[0] in names

        parent: dict[str, str] = {}

        def find(x: str) -> str:
            while parent.get(x, x) != x:
                x = parent[x] = parent.get(parent[x], parent[x])
            return x

        def union(a: str, b: str) -> None:
            parent[find(a)] = find(b)

        for port in self.system_ports:  # path, sub, Port joined by _SEP inside is "path...sub.Port" outside
            head, _, name = port.rpartition(_SEP)
            union(port, f"{head}.{name}" if head else port)
        pairs: list[tuple[str, ...]] = []
        attached: dict[str, list[str]] = {}
        for a, b in self.edges:
            if is_component_port(a) and is_component_port(b):
                pairs.append((a, b))
            elif is_component_port(a) or is_component_port(b):
                comp, junction = (a, b) if is_component_port(a) else (b, a)
                attached.setdefault(find(junction), []).append(comp)
            else:
                union(a, b)
        groups: dict[str, list[str]] = {}
        for junction, ports in attached.items():
            groups.setdefault(find(junction), []).extend(ports)
        pairs += [tuple(dict.fromkeys(ports)) for ports in groups.values() if len(set(ports)) > 1]
        return [tuple(port.replace(_SEP, ".") for port in group) for group in pairs]


#: node variables Hopsan renamed after 0.6 (HmfLoader.cpp, updateOldModelFileParameter)
_OLD_NODE_VARIABLES = {"Angular Velocity": "AngularVelocity", "Equivalent Inertia": "EquivalentInertia",
                       "CharImp": "CharImpedance"}


def _renamed_old_parameter(name: str) -> str:
    """A parameter's name in a file of Hopsan before 0.6 as Hopsan's loader renames it (HmfLoader.cpp,
    updateOldModelFileParameter): ``P1::Pressure`` is ``P1#Pressure``, the node variables renamed since
    (``P1#CharImp`` is ``P1#CharImpedance``), and in a name with characters other than letters, digits and
    ``_``, commas and dots dropped and spaces made ``_`` (``omega_p,1`` is ``omega_p1``)."""
    name = name.replace("::", "#")
    if "#" in name:
        head, _, variable = name.rpartition("#")
        name = f"{head}#{_OLD_NODE_VARIABLES.get(variable, variable)}"
    if re.search(r"[^A-Za-z0-9_]", name):
        name = "std_dev" if name == "sigma^2" else name.replace(",", "").replace(".", "").replace(" ", "_")
    return name


def _names_port_variables_with_colons(core_version: str) -> bool:
    """Whether a file written by Hopsan core ``core_version`` names port variables ``P1::Pressure``: before 0.6.0
    and the 0.6.x snapshots, as Hopsan's loader decides (HopsanCore/src/CoreUtilities/HmfLoader.cpp,
    updateOldModelFileParameter, which renames them ``P1#Pressure``)."""
    if "0.6.x_r" in core_version:
        return True
    numbers = re.findall(r"\d+", core_version.split("_")[0])
    return bool(numbers) and tuple(int(n) for n in numbers[:3]) < (0, 6, 0)


def read_hmf(path: str | Path) -> HopsanModel:
    """Read a Hopsan model file: its components, connections (subsystems flattened), system parameters and
    simulation settings (module notes).

    Raises
    ------
    ModelFileError
        For a file that is missing, too large, not well-formed, holds a DTD or entities, or declares
        something malformed (the message names the component's path and the parameter).
    """
    path = Path(path)
    root = _parse(path)
    top = root.find("system")
    if top is None:
        raise ModelFileError(f"Hopsan model {str(path)!r}: no <system>; expected the model's top-level system")
    reader = _Reader(str(path), _names_port_variables_with_colons(root.get("hopsancoreversion") or ""))
    try:
        own = reader.system(top, (), {})
    except RecursionError:
        raise ModelFileError(f"Hopsan model {str(path)!r}: nested too deep to read") from None
    settings = top.find("simulationtime")
    where = f"Hopsan model {str(path)!r}, <simulationtime>"
    start = _float(settings.get("start") if settings is not None else None, where, "start", 0.0)
    stop = _float(settings.get("stop") if settings is not None else None, where, "stop", 10.0)
    step = _float(settings.get("timestep") if settings is not None else None, where, "timestep", 1e-3)
    if not stop > start or not step > 0:
        raise ModelFileError(f"{where}: start {start:g} s, stop {stop:g} s, step {step:g} s; expected stop > start and step > 0")
    info = root.find("info")
    description = (info.findtext("description") or "").strip() if info is not None else ""
    return HopsanModel(
        name=top.get("name") or path.stem,
        source=str(path),
        start=start,
        stop=stop,
        timestep=step,
        parameters=own,
        components=reader.components,
        connections=reader.flattened(),
        description=description,
    )
