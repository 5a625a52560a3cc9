"""Hopsan models as hydroservo systems: each component of Hopsan's default library mapped to hydroservo's, with
Hopsan's law.

:func:`read_hopsan` reads a model file (:func:`hydroservo.io.hopsan.read_hmf`), maps every component through
:data:`LIBRARY` (Hopsan's type -> a function that builds the hydroservo components standing for it, with the
parameters in Hopsan's units and the names of its ports) and connects them as Hopsan does. Nothing is simulated
until the whole model is mapped: a model with a component that is not in :data:`LIBRARY`, or a setting of a
mapped one that is not supported (a parameter driven by a signal, unequal edges of a valve), is refused with one
message listing each of them with its path in the model.

Hopsan's port variables (``Mass#P2#Position``) become aliases of the imported system named with dots
(``Mass.P2.Position``), in SI as Hopsan logs them (pressures absolute), so that a result and Hopsan's compare
column by column. A Hopsan node joins one C component (a volume, a spring) to one Q component (a valve, a mass):
its pressure and force come from the C side (hydroservo's pressure and force ports), its flow, position and
velocity from the Q side (flow and motion ports), and every port of the node, sensors' included, is given them.

The laws: each mapping names the Hopsan component file it follows; docs/hopsan.md tabulates them with what
differs (Hopsan's transmission-line elements are mapped to the lumped law they discretise).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.components import base as cbase
from hydroservo.errors import ModelFileError
from hydroservo.io.hopsan import HopsanComponent, HopsanModel, read_hmf

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["read_hopsan", "HopsanImport", "LIBRARY", "safe_name"]

#: Hopsan's pressures are absolute; hydroservo's signals are gauge pressures (``p_atm`` in an alias).
ATMOSPHERE = 101325.0


@dataclass(frozen=True)
class Var:
    """A Hopsan node variable as ``coef * signal``, plus the atmosphere if ``absolute`` (Hopsan's pressures)."""

    coef: float
    signal: str
    absolute: bool = False

    @property
    def offset(self) -> float:
        return ATMOSPHERE if self.absolute else 0.0

    def expr(self) -> str:
        text = self.signal if self.coef == 1.0 else f"-{self.signal}" if self.coef == -1.0 else f"{self.coef!r}*{self.signal}"
        return f"{text} + p_atm" if self.absolute else text


@dataclass
class Mapped:
    """What one Hopsan component became: hydroservo components, and where its ports went.

    ``power``: Hopsan power port -> hydroservo port ("comp.port"); ``read``: Hopsan read port (a sensor's) ->
    (hydroservo input fed by the node's variable, variable name, its unit); ``inputs``/``outputs``: Hopsan signal
    ports -> hydroservo inputs/outputs; ``values``: Hopsan signal variables that are no port variable (a valve's
    ``xv``) -> Var.
    """

    components: list[cbase.Component] = field(default_factory=list)
    power: dict[str, str] = field(default_factory=dict)
    read: dict[str, tuple[str, str]] = field(default_factory=dict)
    inputs: dict[str, str] = field(default_factory=dict)
    outputs: dict[str, str] = field(default_factory=dict)
    values: dict[str, Var] = field(default_factory=dict)
    note: str = ""
    #: signals joining the components it became: (output, input)
    internal: list[tuple[str, str]] = field(default_factory=list)
    #: Hopsan ports that are multiports (each connection a node of its own, as a multiport volume's P1)
    multiports: frozenset[str] = frozenset()


class _Params:
    """A Hopsan component's parameters, read by Hopsan's names with their defaults (from its component file)."""

    def __init__(self, hc: HopsanComponent, where: str, problems: list[str]) -> None:
        self.hc, self.where, self.problems = hc, where, problems

    def __call__(self, name: str, default: float) -> float:
        for key in (f"{name}#Value", name):
            par = self.hc.parameters.get(key)
            if par is not None:
                if par.value is None or not math.isfinite(par.value):
                    self.problems.append(f"{self.where}: parameter {name} = {par.text!r} is not a number")
                    return default
                return par.value
        return default

    def start(self, port: str, variable: str, default: float = 0.0) -> float:
        """A port variable's start value (``P1#Pressure``)."""
        return self(f"{port}#{variable}", default)


Builder = Callable[[HopsanComponent, str, _Params], Mapped]


def safe_name(name: str) -> str:
    """A Hopsan name as a hydroservo component name: characters other than letters, digits and _ become _, and
    a name that starts with a digit gets a ``c_`` in front (``4_3_Servo_Valve`` -> ``c_4_3_Servo_Valve``)."""
    safe = re.sub(r"\W", "_", name, flags=re.ASCII)
    return f"c_{safe}" if not safe or safe[0].isdigit() else safe


def _abs(p: float) -> str:
    return f"{p!r} Pa_abs"


# -- hydraulic ------------------------------------------------------------------------------------------------


def _tank(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Tank

    return Mapped([Tank(n, p=_abs(par("p", 1e5)))], power={"P1": f"{n}.P"})


def _pressure_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Tank

    # a source of constant pressure that takes any flow: a tank at that pressure (Tank allows any pressure
    # above vacuum, ConstantPressure only above the atmosphere)
    return Mapped([Tank(n, p=_abs(par("p", 1e5)))], power={"P1": f"{n}.P"})


def _volume(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Volume

    comp = Volume(n, V=par("V", 1e-3), beta_e=par("Beta_e", 1e9), p0=_abs(par.start("P1", "Pressure", 1e5)))
    ports = {"P1": f"{n}.P", "P2": f"{n}.P"}  # HydraulicVolume's two ports and the multiport's one: one node
    return Mapped([comp], power=ports, multiports=frozenset({"P1"}) if hc.typename.endswith("MultiPort") else frozenset())


def _relief(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import ReliefValve

    comp = ReliefValve(
        n,
        p_crack=_abs(par("p_max", 2e7)),
        tau=par("tao", 0.01),
        k_cs=par("k_cs", 1e-8),
        k_cf=par("k_cf", 1e-8),
        q_nom=par("q_nom", 0.01),
        p_nom=7e6,  # Hopsan's fixed nominal pressure drop (HydraulicPressureReliefValve.hpp)
        p_tr=1e3,
    )
    # Hopsan's output xv (its spool's filtered position, in its own scaling) has no counterpart: not aliased
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _fixed_pump(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Pump

    comp = Pump(n, D=f"{par('D_p', 5e-5)!r} m^3/rev", omega=par("n_p", 50.0), C_leak=par("C_lp", 1e-11))
    return Mapped([comp], power={"P1": f"{n}.S", "P2": f"{n}.P"})


def _valve43(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import FourWayValve, Gain, SpoolSecondOrder

    problems = par.problems
    f = {edge: par(f"f_{edge}", 1.0) for edge in ("pa", "pb", "at", "bt")}
    if len(set(f.values())) > 1:
        problems.append(
            f"{par.where}: the edges' area fractions f_pa, f_pb, f_at, f_bt differ ({', '.join(f'{v:g}' for v in f.values())}); "
            "FourWayValve has one flow coefficient for all four edges"
        )
    rho = par("rho", 870.0)
    c_v = par("C_q", 0.67) * f["pa"] * math.pi * par("d", 0.01) * math.sqrt(2.0 / rho)
    x_vmax = par("x_vmax", 0.01)
    gain = Gain(f"{n}_stroke", input_unit="m", K=f"{1.0 / x_vmax!r} 1/m")
    spool = SpoolSecondOrder(f"{n}_spool", omega_n=par("omega_h", 100.0), zeta=par("delta_h", 1.0), xv_max=x_vmax)
    valve = FourWayValve(
        n,
        c_v=c_v,
        x_PA=par("x_pa", -1e-6),
        x_AT=par("x_at", -1e-6),
        x_PB=par("x_pb", -1e-6),
        x_BT=par("x_bt", -1e-6),
        rho=rho,
        D_h="1 mm",
        lambda_crit=10.0,  # turbulent down to about 40 Pa: Hopsan's orifices are turbulent to the null
    )
    return Mapped(
        [gain, spool, valve],
        power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A", "PB": f"{n}.B"},
        inputs={"in": f"{n}_stroke.u"},
        values={"xv": Var(1.0, f"{n}_spool.xv")},
        internal=[(f"{n}_stroke.y", f"{n}_spool.u"), (f"{n}_spool.xv", f"{n}.xv"), (f"{n}_spool.vv", f"{n}.vv")],
        note="a Gain (reference in m to a fraction of the stroke), a SpoolSecondOrder and a FourWayValve",
    )


def _cylinder_c(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Cylinder

    a1, a2, sl = par("A_1", 1e-3), par("A_2", 1e-3), par("s_l", 1.0)
    comp = Cylinder(
        n,
        A_A=a1,
        A_B=a2,
        V_A0=par("V_1", 3e-4),
        V_B0=par("V_2", 3e-4) + a2 * sl,  # Hopsan measures chamber 2 from the other end of the stroke
        beta_e=par("Beta_e", 1e9),
        B_p=par("B_p", 1e3),
        C_Li=par("c_leak", 0.0),
        x_min=0.0,
        x_max=sl,
        pressure_floor="cavity",
        p_floor="0 Pa_abs",
        pA0=_abs(par.start("P1", "Pressure", 1e5)),
        pB0=_abs(par.start("P2", "Pressure", 1e5)),
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P3": f"{n}.R"}, multiports=frozenset({"P1", "P2"}))


def _pressure_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _sensor(n, "Pressure", "Pa")


def _flow_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _sensor(n, "Flow", "m^3/s")


# -- mechanic -------------------------------------------------------------------------------------------------


def _mass(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Mass

    x_min, x_max = par("x_min", -1e300), par("x_max", 1e300)
    comp = Mass(
        n,
        m=par("m", 100.0),
        B=par("B", 10.0),
        k_spring=par("k", 0.0),
        incline=0.0,
        x0=par.start("P2", "Position"),
        v0=par.start("P2", "Velocity"),
    )
    if abs(x_min) < 1e299 or abs(x_max) < 1e299:  # Hopsan's inelastic stops, as stiff ones
        comp.set(x_min=max(x_min, -1e30), x_max=min(x_max, 1e30), k_stop=1e9, c_stop=1e6)
    if par.start("P1", "Position") + par.start("P2", "Position") != 0.0:
        par.problems.append(
            f"{par.where}: start positions of P1 and P2 that do not add up to zero (a mass of some length) are not "
            "supported yet"
        )
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _spring(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Spring

    # relaxed at its start positions (Hopsan's are inward, hydroservo's outward)
    e0 = -(par.start("P1", "Position") + par.start("P2", "Position"))
    return Mapped([Spring(n, k_spring=par("k", 100.0), e0=e0)], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _fixed_position(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import FixedPosition

    return Mapped([FixedPosition(n)], power={"Pm1": f"{n}.P"})


def _force_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import ForceSource

    return Mapped([ForceSource(n)], power={"P1": f"{n}.P"}, inputs={"F": f"{n}.u"})


def _position_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _sensor(n, "Position", "m")


def _velocity_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _sensor(n, "Velocity", "m/s")


def _force_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _sensor(n, "Force", "N")


def _sensor(n: str, variable: str, unit: str) -> Mapped:
    """A sensor: a Sum reading the node's variable (fed when the node is known), its output Hopsan's ``out``."""
    from hydroservo.components import Sum

    return Mapped([Sum(n, unit=unit, gain2=0.0)], read={"P1": (f"{n}.u1", variable)}, outputs={"out": f"{n}.y"})


# -- signal ---------------------------------------------------------------------------------------------------


def _step(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Step

    comp = Step(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), t_step=par("t_step", 1.0))
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _constant(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Constant

    return Mapped([Constant(n, value=par("y", 1.0))], outputs={"out": f"{n}.y"})


def _gain(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Gain

    return Mapped([Gain(n, K=par("k", 1.0))], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _sum_of_two(sign: float) -> Builder:
    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Sum

        return Mapped(
            [Sum(n, gain1=1.0, gain2=sign)], inputs={"in1": f"{n}.u1", "in2": f"{n}.u2"}, outputs={"out": f"{n}.y"}
        )

    return build


def _integrator(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Integrator

    return Mapped([Integrator(n, y0=par("out", 0.0))], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _sink(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return Mapped(note="dropped: a plot window; what it shows is logged at its sources")


#: Hopsan type -> the function that maps it (each follows the Hopsan component file of that name in
#: ``componentLibraries/defaultLibrary``).
LIBRARY: dict[str, Builder] = {
    "HydraulicTankC": _tank,
    "HydraulicPressureSourceC": _pressure_source,
    "HydraulicVolume": _volume,
    "HydraulicVolumeMultiPort": _volume,
    "HydraulicPressureReliefValve": _relief,
    "HydraulicFixedDisplacementPump": _fixed_pump,
    "Hydraulic43Valve": _valve43,
    "HydraulicCylinderC": _cylinder_c,
    "HydraulicPressureSensor": _pressure_sensor,
    "HydraulicFlowSensor": _flow_sensor,
    "MechanicTranslationalMass": _mass,
    "MechanicTranslationalSpring": _spring,
    "MechanicFixedPosition": _fixed_position,
    "MechanicForceTransformer": _force_source,
    "MechanicPositionSensor": _position_sensor,
    "MechanicVelocitySensor": _velocity_sensor,
    "MechanicForceSensor": _force_sensor,
    "SignalStep": _step,
    "SignalConstant": _constant,
    "SignalGain": _gain,
    "SignalAdd": _sum_of_two(1.0),
    "SignalSubtract": _sum_of_two(-1.0),
    "SignalIntegrator2": _integrator,
    "SignalSink": _sink,
}


@dataclass
class HopsanImport:
    """A Hopsan model imported: the system, and how each Hopsan component was mapped."""

    system: System
    model: HopsanModel
    mapping: list[tuple[str, str, str]]  #: (Hopsan path, Hopsan type, what it became)
    names: dict[str, str]  #: Hopsan path -> hydroservo component name


def read_hopsan(path: str | Path) -> System:
    """The Hopsan model file ``path`` as a hydroservo :class:`~hydroservo.system.system.System`.

    Raises
    ------
    ModelFileError
        The file cannot be read (:func:`~hydroservo.io.hopsan.read_hmf`), or it holds components or settings that
        are not supported: each is listed with its path in the model.
    """
    return import_hopsan(path).system


def import_hopsan(path: str | Path) -> HopsanImport:
    """The Hopsan model file ``path`` imported: the system and the mapping (see :func:`read_hopsan`)."""
    from hydroservo.components import Constant
    from hydroservo.system.nodes import port_of
    from hydroservo.system.system import System

    model = read_hmf(path)
    source = str(path)
    problems: list[str] = []
    unsupported = [c for c in model.components if c.typename not in LIBRARY]
    if unsupported:
        listed = "; ".join(f"{c.full_name} ({c.typename})" for c in unsupported)
        raise ModelFileError(
            f"{source}: {len(unsupported)} component(s) of types hydroservo does not map yet: {listed}. Supported: "
            f"{', '.join(sorted(LIBRARY))} (docs/hopsan.md)"
        )
    names: dict[str, str] = {}
    used: set[str] = set()
    mapped: dict[str, Mapped] = {}
    mapping: list[tuple[str, str, str]] = []
    for hc in model.components:
        name = safe_name("_".join((*hc.path, hc.name)))
        base, k = name, 1
        while name in used:
            k += 1
            name = f"{base}_{k}"
        used.add(name)
        names[hc.full_name] = name
        where = f"{source}: {hc.full_name} ({hc.typename})"
        try:
            m = LIBRARY[hc.typename](hc, name, _Params(hc, where, problems))
        except Exception as exc:  # a value out of a component's range: named with the Hopsan component
            problems.append(f"{where}: {exc}")
            continue
        mapped[hc.full_name] = m
        became = m.note or ", ".join(f"{type(c).__name__} {c.name}" for c in m.components)
        mapping.append((hc.full_name, hc.typename, became))
    if problems:
        raise ModelFileError("; ".join(problems))

    system = System(safe_name(model.name or Path(source).stem))
    system.description = model.description or f"imported from Hopsan model {Path(source).name}"
    system.source = source
    for m in mapped.values():
        for comp in m.components:
            system.add(comp)
    for m in mapped.values():
        for out, inp in m.internal:
            system.connect(out, inp)

    def ref(end: str) -> tuple[str, str]:
        comp, _, port = end.rpartition(".")
        return comp, port

    # group Hopsan's connections into nodes: power ports (and read ports) by union, signal links pairwise
    power_groups: list[list[tuple[str, str]]] = []
    signal_links: list[tuple[tuple[str, str], tuple[str, str]]] = []
    for connection in model.connections:
        ends = [ref(e) for e in connection]
        kinds = {_port_kind(mapped.get(c), p) for c, p in ends}
        if kinds <= {"power", "read"}:
            power_groups.append(ends)
        else:
            signal_links.extend(zip(ends, ends[1:], strict=False))
    power_groups = _union(power_groups, {(c, p) for c, m in mapped.items() for p in m.multiports})

    connected_inputs: set[tuple[str, str]] = set()
    for (ca, pa), (cb, pb) in signal_links:
        ka, kb = _port_kind(mapped.get(ca), pa), _port_kind(mapped.get(cb), pb)
        if {ka, kb} == {"output", "input"}:
            (co, po), (ci, pi) = ((ca, pa), (cb, pb)) if ka == "output" else ((cb, pb), (ca, pa))
            system.connect(mapped[co].outputs[po], mapped[ci].inputs[pi])
            connected_inputs.add((ci, pi))
        elif "none" not in (ka, kb) and "dropped" not in (ka, kb):
            problems.append(f"{source}: connection {ca}.{pa} – {cb}.{pb}: ports of kinds {ka} and {kb} do not join")

    aliases: dict[str, Var] = {}
    for node_ends in power_groups:
        refs = [mapped[c].power[p] for c, p in node_ends if _port_kind(mapped.get(c), p) == "power"]
        if len(set(refs)) > 1:
            system.connect(*dict.fromkeys(refs))
        node = _node_variables(system, refs, port_of)
        for c, p in node_ends:
            for var, value in node.items():
                if (var == "Flow" and p in mapped[c].multiports) or f"{c}.{p}.{var}" in aliases:
                    continue  # a multiport's flow is one per connection: Hopsan logs none of them by the port
                aliases[f"{c}.{p}.{var}"] = value
            read = mapped[c].read.get(p)
            if read is not None:
                target, variable = read
                if variable not in node:
                    problems.append(f"{source}: {c}.{p} reads {variable}, which the node it is joined to has not")
                    continue
                value = node[variable]
                comp = system[target.split(".")[0]]
                comp.set(gain1=value.coef, offset=value.offset)
                system.connect(value.signal, target)

    # Hopsan's signal inputs left unconnected take their start value: a constant where it is not 0
    for hc in model.components:
        m = mapped[hc.full_name]
        for port, target in m.inputs.items():
            if (hc.full_name, port) in connected_inputs:
                continue
            par = hc.parameters.get(f"{port}#Value")
            start = par.value if par is not None and par.value is not None else 0.0
            cname, iname = target.split(".")
            default = system[cname].INPUTS[iname].default
            if start != 0.0 or default is None:
                const = system.add(Constant(f"{cname}_{iname}", value=start))
                system.connect(f"{const.name}.y", target)
        for port, signal in m.outputs.items():
            aliases[f"{hc.full_name}.{port}.Value"] = Var(1.0, signal)
        for variable, value in m.values.items():
            aliases[f"{hc.full_name}.{variable}.Value"] = value
    if problems:
        raise ModelFileError("; ".join(problems))
    for name, value in aliases.items():
        unit = _unit_of(system, value)
        system.alias(name, value.expr(), unit, f"Hopsan's {name.replace('.', '#')}")
    system.meta.update(
        {
            "t_end": f"{model.stop - model.start!r} s",
            "hopsan_timestep": f"{model.timestep!r} s",
            "status": "imported",
        }
    )
    return HopsanImport(system, model, mapping, names)


def _port_kind(m: Mapped | None, port: str) -> str:
    if m is None:
        return "none"
    if port in m.power:
        return "power"
    if port in m.read:
        return "read"
    if port in m.inputs:
        return "input"
    if port in m.outputs:
        return "output"
    return "dropped" if not m.components else "none"


def _union(groups: list[list[tuple[str, str]]], multiports: set[tuple[str, str]]) -> list[list[tuple[str, str]]]:
    """Groups that share a port merged, unless the port is a multiport (each of its connections a node)."""
    merged: list[list[tuple[str, str]]] = []
    for group in groups:
        joined = [g for g in merged if (set(g) & set(group)) - multiports]
        new = list(dict.fromkeys([*group, *(e for g in joined for e in g)]))
        merged = [g for g in merged if g not in joined] + [new]
    return merged


def _node_variables(system: System, refs: list[str], port_of: Callable[..., Any]) -> dict[str, Var]:
    """Hopsan's variables of the node the hydroservo ports ``refs`` form: pressure (absolute) and flow, or
    position, velocity and force, each from the port that gives it."""
    from hydroservo.components.base import Hydraulic, Mechanical
    from hydroservo.system.nodes import is_motion_port, is_pressure_port

    out: dict[str, Var] = {}
    for r in dict.fromkeys(refs):
        comp, port = port_of(system.components, r)
        cname = r.split(".")[0]
        if isinstance(port, Hydraulic):
            if is_pressure_port(comp, port):
                out["Pressure"] = Var(1.0, f"{cname}.{port.p}", absolute=True)
            elif len(refs) == 2:  # a Hopsan node: its flow goes into the C component, out of this one
                out["Flow"] = Var(-port.sign, f"{cname}.{port.Q}")
        elif isinstance(port, Mechanical):
            if is_motion_port(comp, port):  # Hopsan's Q ports count outward
                out["Position"] = Var(port.sign, f"{cname}.{port.x}")
                out["Velocity"] = Var(port.sign, f"{cname}.{port.v}")
            else:  # the force pressing on the node
                out["Force"] = Var(port.sign, f"{cname}.{port.F}")
    return out


def _unit_of(system: System, value: Var) -> str:
    cname, sig = value.signal.split(".")
    comp = system.components[cname]
    spec = comp.OUTPUTS.get(sig) or comp.STATES.get(sig)
    return spec.unit if spec is not None and spec.unit not in ("@",) else ""
