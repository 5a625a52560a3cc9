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
from hydroservo.errors import ModelError, ModelFileError
from hydroservo.io.hopsan import HopsanComponent, HopsanModel, HopsanParameter, read_hmf

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["read_hopsan", "HopsanImport", "LIBRARY", "REFUSED", "safe_name"]

#: Hopsan's pressures are absolute; hydroservo's signals are gauge pressures (``p_atm`` in an alias).
ATMOSPHERE = 101325.0


@dataclass(frozen=True)
class Var:
    """A Hopsan node variable as ``coef * signal``, plus the atmosphere if ``absolute`` (Hopsan's pressures)."""

    coef: float
    signal: str
    absolute: bool = False
    text: str | None = None  # the expression itself, where a factor has a unit (the component's parameters)
    unit: str | None = None  # the variable's unit, with ``text`` (else the signal's)

    @property
    def offset(self) -> float:
        return ATMOSPHERE if self.absolute else 0.0

    def expr(self) -> str:
        if self.text is not None:
            return f"{self.text} + p_atm" if self.absolute else self.text
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
    #: Hopsan multi-input port (a sum's "in") -> the hydroservo inputs it fills, in the order it is connected
    multi: dict[str, list[str]] = field(default_factory=dict)
    #: initial values of states ("comp.state" -> value, SI) taken from Hopsan's start values
    initial: dict[str, float] = field(default_factory=dict)
    #: signals (or ports) joining the components it became: (output, input), (port, port)
    internal: list[tuple[str, str]] = field(default_factory=list)
    #: parameters or states that start at (a function of) the value of an input at the start ("comp.y0" ->
    #: ("comp.u", f)), as Hopsan's blocks that take their input's value when the model is initialised (a rate
    #: limiter's output, a directional valve's spool)
    start_from_input: dict[str, tuple[str, Callable[[float], float]]] = field(default_factory=dict)
    #: Hopsan power port -> the output giving Hopsan's flow there (out of the component), where more than one of
    #: its hydroservo components join at the port (a valve's centre edge beside its spool's): the node's flow
    flow: dict[str, str] = field(default_factory=dict)
    #: further variables a read port reads (a power sensor's pressure and flow), as ``read``'s entries
    read_also: dict[str, list[tuple[str, str]]] = field(default_factory=dict)
    #: Hopsan ports left unmapped on purpose -> why (named when a block reads one; a scope showing one is dropped)
    unmapped: dict[str, str] = field(default_factory=dict)


class _Params:
    """A Hopsan component's parameters, read by Hopsan's names with their defaults (from its component file)."""

    def __init__(
        self,
        hc: HopsanComponent,
        where: str,
        problems: list[str],
        node_start: dict[str, dict[str, float]] | None = None,
        driven: frozenset[str] = frozenset(),
        fan_in: dict[str, int] | None = None,
    ) -> None:
        self.hc, self.where, self.problems = hc, where, problems
        #: how many signals Hopsan connects to each of the component's ports (a multiport sum's inputs)
        self.fan_in = fan_in or {}
        self.node_start = node_start or {}
        #: Hopsan's start time: hydroservo's runs start at 0, so Hopsan's times are shifted by it (``time``)
        self.t0 = 0.0
        #: the component's ports Hopsan connects to something (its signal inputs among them are driven)
        self.driven = driven
        #: the model file's folder: the files a component names (a lookup table's CSV) are read from it
        self.folder: Path | None = None
        #: Hopsan's time step [s] and the import's segments of a line (None: from the line's delay and the step)
        self.timestep = 0.0
        self.line_segments: int | None = None

    def __call__(self, name: str, default: float) -> float:
        for key in (f"{name}#Value", name):
            par = self.hc.parameters.get(key)
            if par is not None:
                if par.value is None or not math.isfinite(par.value):
                    self.problems.append(f"{self.where}: parameter {name} = {par.text!r} is not a number")
                    return default
                return par.value
        return default

    def text(self, name: str, default: str = "") -> str:
        """A text parameter (a file name, a separator) as the file gives it."""
        par = self.hc.parameters.get(name)
        return default if par is None else par.text

    def time(self, name: str, default: float) -> float:
        """A time parameter on hydroservo's clock, which starts at 0 where Hopsan's starts at its start time."""
        return self(name, default) - self.t0

    def source_time(self, name: str, default: float) -> float:
        """A source's start or step time on hydroservo's clock (:meth:`time`); one before the run's start is
        refused (a problem is noted) and 0 returned."""
        t = self.time(name, default)
        if t < 0.0:
            self.problems.append(f"{self.where}: {name} = {t + self.t0:g} s, before the run's start, is not supported")
        return max(t, 0.0)

    def start(self, port: str, variable: str, default: float = 0.0) -> float:
        """A port variable's start value (``P1#Pressure``): the node's, which the component that owns it gives
        (Hopsan's C components write the start values of their nodes, its Q components read them), else this
        component's own."""
        value = self.node_start.get(port, {}).get(variable)
        return value if value is not None else self(f"{port}#{variable}", default)


Builder = Callable[[HopsanComponent, str, _Params], Mapped]

#: Hopsan's C components among the mapped types (they own the start values of their nodes)
C_TYPES = frozenset({
    "HydraulicTankC", "HydraulicMultiTankC", "HydraulicPressureSourceC", "HydraulicMultiPressureSourceC",
    "HydraulicVolume", "HydraulicVolumeMultiPort", "HydraulicCylinderC", "MechanicTranslationalSpring",
    "MechanicForceTransformer", "MechanicTorqueTransformer", "MechanicTorsionalSpring", "MechanicRotShaft",
    "MechanicRotShaftG", "MechanicGearShaft", "HydraulicMachineC", "HydraulicSpringLoadedPistonC", "MechanicMotor",
    "MechanicSpring", "MechanicTranslationalSpringWithSlack", "HydraulicFourChamberPiston", "HydraulicTLMlossless",
    "HydraulicHose", "HydraulicPumpPiston", "HydraulicCSource", "MechanicTranslationalCSource", "HydraulicPiston",
    "HydraulicFuelTankG",
})

#: Hopsan's multiports, by type: each connection to one is a node of its own (Hopsan gives each its own flow)
MULTIPORTS: dict[str, frozenset[str]] = {
    "HydraulicVolumeMultiPort": frozenset({"P1"}),
    "HydraulicMultiTankC": frozenset({"MP"}),
    "HydraulicMultiPressureSourceC": frozenset({"MP"}),
    "HydraulicCylinderC": frozenset({"P1", "P2"}),
    "HydraulicSpringLoadedPistonC": frozenset({"P1", "P2"}),
    "HydraulicFourChamberPiston": frozenset({"P1", "P2", "P3", "P4"}),
    "MechanicMultiPortTranslationalMass": frozenset({"P1", "P2"}),
    "MechanicTranslationalMassWithCoulombFrictionAndMultiPorts": frozenset({"P1", "P2"}),
    "MechanicFixedPositionMultiPort": frozenset({"Pm1"}),
    "MechanicRotationalInertiaMultiPort": frozenset({"P1", "P2"}),
}

#: Hopsan's multiports whose connections are each a port of their own in hydroservo's component (a valve plate's
#: bores), in the order Hopsan connects them, which is its order of their subports: the k-th is ``PORT#k``
SUBPORTS: dict[str, frozenset[str]] = {
    "HydraulicValvePlate": frozenset({"P1"}),
    "MechanicCylinderBlockWithSwashPlate": frozenset({"P1"}),
    "MechanicSwashPlate": frozenset({"P1"}),
}

#: Hopsan's mechanical multiports whose connections each keep their node's start position (an offset from the
#: first one's): hydroservo's one port has one, so the connections' start positions and velocities must agree
#: (the builder reads them as the port's start values; :data:`STARTS_DIFFER` marks ones that do not)
SHARED_STARTS = frozenset({
    "MechanicMultiPortTranslationalMass", "MechanicTranslationalMassWithCoulombFrictionAndMultiPorts",
    "MechanicFixedPositionMultiPort", "MechanicRotationalInertiaMultiPort",
})
STARTS_DIFFER = "StartsDiffer"


#: The longest name an imported component is given [characters]: what a mapping adds to it (``_spool``, ``_2``)
#: stays within the longest component name (:data:`hydroservo.components.base.MAX_NAME`).
LONGEST_NAME = cbase.MAX_NAME - 24


def _plain_name(name: str) -> str:
    safe = re.sub(r"\W", "_", name, flags=re.ASCII)
    return f"c_{safe}" if not safe or safe[0].isdigit() else safe


def _shortened(name: str, longest: int) -> str:
    """``name`` if it is at most ``longest`` characters, else its start and a digest of the whole (two long names
    that differ only at their ends stay apart)."""
    import hashlib

    if len(name) <= longest:
        return name
    return f"{name[:longest - 9]}_{hashlib.sha256(name.encode('utf-8', 'surrogatepass')).hexdigest()[:8]}"


def safe_name(name: str) -> str:
    """A Hopsan name as a hydroservo component name, valid by the model file's rule
    (:func:`hydroservo.components.base.name_problem`): characters other than letters, digits and _ become _, a
    name that starts with a digit gets a ``c_`` in front (``4_3_Servo_Valve`` -> ``c_4_3_Servo_Valve``), a Python
    keyword a ``_`` behind (``class`` -> ``class_``), and a name longer than :data:`LONGEST_NAME` is cut, with a
    digest of the whole behind.

    >>> safe_name("4_3 Servo-Valve"), safe_name("class"), len(safe_name("M" * 10000))
    ('c_4_3_Servo_Valve', 'class_', 76)
    """
    import keyword

    safe = _shortened(_plain_name(name), LONGEST_NAME)
    return f"{safe}_" if keyword.iskeyword(safe) else safe


def _abs(p: float) -> str:
    return f"{p!r} Pa_abs"


# -- hydraulic ------------------------------------------------------------------------------------------------


def _tank(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return _source(n, par("p", 1e5), hc, par)


def _source(n: str, p_abs: float, hc: HopsanComponent, par: _Params) -> Mapped:
    """A tank or a C-type pressure source: a Tank at Hopsan's absolute pressure, or a PressureSource following
    the signal that drives it (Hopsan's absolute pressure)."""
    from hydroservo.components import PressureSource, Tank

    port = "MP" if "Multi" in hc.typename else "P1"
    if "p" in par.driven:
        return Mapped([PressureSource(n, p0="0 Pa_abs")], power={port: f"{n}.P"}, inputs={"p": f"{n}.u"})
    return Mapped([Tank(n, p=_abs(p_abs))], power={port: f"{n}.P"})


def _pressure_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # a source of constant pressure that takes any flow: a tank at that pressure (Tank allows any pressure
    # above vacuum, ConstantPressure only above the atmosphere)
    return _source(n, par("p", 1e5), hc, par)


#: the conductance through which a Q-type pressure source holds the C component joined to it [m^3/s/Pa]
Q_SOURCE_CONDUCTANCE = 1e-2


def _pressure_source_q(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sources&Sinks/HydraulicPressureSourceQ.hpp: a Q component that writes p = in to its
    node and the flow q = (in - c)/Zc that brings the C component joined to it (a volume, a cylinder's chamber)
    to that pressure within one step: in the limit an ideal pressure source joined to a capacitance, whose
    pressure it sets, and which takes whatever flow that needs. hydroservo's node has one pressure port, the C
    component's; the source is a pressure source (a PressureSource following the signal ``p``, absolute, or a
    Tank at a constant ``p``) behind a LaminarOrifice of conductance ``Q_SOURCE_CONDUCTANCE`` (1e-2 m³/s/Pa): the
    capacitance follows the source's pressure with the time constant V/(β_e G) (0.03 ns for 0.3 L at 1e9 Pa) and
    stands below it by q/G (0.1 Pa for a flow of 1 L/s). The orifice, named as the source, gives the node's flow;
    its pressure is the C component's. (On HydraulicSpringLoadedPistonC.hmf, whose sources deliver up to 17 L/s,
    G = 1e-6, 1e-3 and 1e-2 m³/s/Pa put the constant source's pressure 170 %, 1.7 % and 0.17 % of its scale, 1 %
    of its value, off Hopsan's.)"""
    from hydroservo.components import LaminarOrifice

    source = _source(f"{n}_p", par("p", 1e5), hc, par)
    path = LaminarOrifice(n, G_lam=Q_SOURCE_CONDUCTANCE)
    return Mapped(
        [*source.components, path],
        power={"P1": f"{n}.B"},
        inputs=source.inputs,
        internal=[(source.power["P1"], f"{n}.A")],
        note=f"{type(source.components[0]).__name__} {n}_p behind LaminarOrifice {n} (G = {Q_SOURCE_CONDUCTANCE:g} m³/s/Pa)",
    )


def _volume(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Volume

    comp = Volume(
        n,
        V=par("V", 1e-3),
        beta_e=par("Beta_e", 1e9),
        p0=_abs(par.start("P1", "Pressure", 1e5)),
        pressure_floor="cavity",  # Hopsan's volumes cavitate at 0 Pa absolute: the ports see max(p, 0)
        p_floor="0 Pa_abs",
    )
    ports = {"P1": f"{n}.P", "P2": f"{n}.P"}  # HydraulicVolume's two ports and the multiport's one: one node
    return Mapped([comp], power=ports)


def _spool_valve_parameters(par: _Params) -> dict[str, Any] | None:
    """The spool of Hopsan's HydraulicPressureReliefValve family (relief, reducing, drop, controlled valves): its
    lag, characteristics and hysteresis; None (problems noted) for a negative hysteresis."""
    if par("p_h", 5e5) < 0.0:
        par.problems.append(f"{par.where}: hysteresis p_h = {par('p_h', 5e5):g} Pa; expected 0 or more")
        return None
    return {
        "tau": par("tao", 0.01),
        "k_cs": par("k_cs", 1e-8),
        "k_cf": par("k_cf", 1e-8),
        "q_nom": par("q_nom", 0.001),
        "p_nom": par("p_nom", 7e6),  # a constant 7 MPa in all but HydraulicPressureControlledValve, a parameter there
        "p_tr": 1e3,
        "p_h": par("p_h", 5e5),  # Hopsan's ValveHysteresis, its default 5 bar
    }


def _relief(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import ReliefValve

    spool = _spool_valve_parameters(par)
    if spool is None:
        return Mapped()
    comp = ReliefValve(n, p_crack=_abs(par("p_max", 2e7)), **spool)
    # Hopsan's output xv (its spool's filtered position, in its own scaling) has no counterpart: not aliased
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _pressure_drop_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureDropValve.hpp: the relief valve's law
    set on the drop, ``xs = (p1 - p2 - p_ref)/b1``: ReliefValve with ``pilot = "drop"``, ``p_crack = p_ref``."""
    from hydroservo.components import ReliefValve

    spool = _spool_valve_parameters(par)
    if spool is None:
        return Mapped()
    comp = ReliefValve(n, p_crack=par("p_ref", 2e6), pilot="drop", **spool)
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _reducing_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureReducingValve.hpp: the relief valve's
    law piloted by the outlet, ``xs = (p_ref - p2)/b1``: PressureReducingValve with ``p_set = p_ref`` (absolute)."""
    from hydroservo.components import PressureReducingValve

    spool = _spool_valve_parameters(par)
    if spool is None:
        return Mapped()
    comp = PressureReducingValve(n, p_set=_abs(par("p_ref", 2e6)), **spool)
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _pressure_controlled_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureControlledValve.hpp: the relief valve's
    law piloted by two lines, ``xs = (p_open - p_ref - p_close)/b1``, the pilots taking no flow: ReliefValve with
    ``pilot = "ports"``, its X the opening pilot P_OPEN, its Y the closing one P_CLOSE, ``p_crack = p_ref`` (a
    difference of pressures). Hopsan's b1 = C_s + C_f (p1 - p2) is not floored at a reverse drop there (it vanishes
    at p2 - p1 = C_s/C_f, 7 MPa with its defaults); hydroservo's is, as for every pressure-control valve. Its output
    x0 has no counterpart: not aliased."""
    from hydroservo.components import ReliefValve

    spool = _spool_valve_parameters(par)
    if spool is None:
        return Mapped()
    comp = ReliefValve(n, p_crack=par("p_ref", 2e6), pilot="ports", **spool)
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P_OPEN": f"{n}.X", "P_CLOSE": f"{n}.Y"})


def _compensating(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicPressureCompensatingValve.hpp: a normally open
    valve from P1 to P2 whose spool the pilot P_OPEN pushes closed against the spring pref and the pilot P_CLOSE,
    x_s = X0max - (p_open - pref - p_close)/b_1 with b_1 = C_s + C_f (p1 - p2), its hysteresis p_h and its lag tao
    (limited to [0, X0max], starting open): the relief valve's spool inverted, a PressureCompensatorValve (its X
    P_OPEN, its Y P_CLOSE; pref a difference of pressures, not absolute). Its xv (the filtered coefficient) is the
    valve's s times q_nom/√p_nom. Where the drop p1 - p2 is negative Hopsan's b_1 falls below C_s (and vanishes at
    p1 - p2 = -C_s/C_f); hydroservo takes the flow forces for a positive drop only, as for the relief valve."""
    from hydroservo.components import PressureCompensatorValve

    if par("p_h", 5e5) < 0.0:
        par.problems.append(f"{par.where}: hysteresis p_h = {par('p_h', 5e5):g} Pa; expected 0 or more")
        return Mapped()
    q_nom, p_nom = par("q_nom", 0.001), 7e6  # Hopsan's fixed nominal pressure drop
    comp = PressureCompensatorValve(
        n,
        p_ref=par("p_ref", 2e6),
        tau=par("tao", 0.01),
        k_cs=par("k_cs", 1e-8),
        k_cf=par("k_cf", 1e-8),
        q_nom=q_nom,
        p_nom=p_nom,
        p_tr=1e3,
        p_h=par("p_h", 5e5),
    )
    return Mapped(
        [comp],
        power={"P1": f"{n}.A", "P2": f"{n}.B", "P_OPEN": f"{n}.X", "P_CLOSE": f"{n}.Y"},
        values={"xv": Var(1.0, f"{n}.s", text=f"{n}.q_nom/sqrt({n}.p_nom)*{n}.s", unit="m^3/s/Pa^0.5")},
    )


def _pressure_valve_g(reducing: bool, counterbalance: bool = False, ported: bool = False, mass: bool = False) -> Builder:
    """[Hopsan2026] Hydraulic/Special/HydraulicPressureReliefValveG.hpp and HydraulicPressureReducingValveG.hpp:
    a massless spool of diameter Dv, damped by Bv, pushed by the pilot on its area A_v = π Dv²/4 (relief:
    p_1 - p_2 - pref; reducing: pref - p_2) against its spring ks and the steady flow force 2 Cq w cos φ (p_1 - p_2)
    x_v, its opening x_v in [0, Xvmax] (Hopsan limits the bilinear transform of B_v ẋ_v = A_v Δp_over - k_e x_v,
    the law it stands for, and its memory: no wind-up), the flow Cq w x_v √(2/ρ) signedSquareL(p_1 - p_2, p0) with
    w = π Dv frac sin φ. That is ReliefValve or PressureReducingValve with ``spool = "balance"``
    (:func:`hydroservo.laws.pressure_valve.spool_balance_rate`): K = Cq w √(2/ρ) x_v, C_s = ks/(Cq w √(2/ρ) A_v),
    C_f = 2 cos φ/(√(2/ρ) A_v), tau = Bv/ks, K at most Cq w √(2/ρ) Xvmax, p_tr = p0 (signedSquareL is
    hydroservo's regularised turbulent law exactly). The relief valve's setting is a drop (``pilot = "drop"``), the
    reducing valve's an absolute pressure. π where Hopsan writes 3.14159 and 0.785398 (1e-6 apart); visc is
    unused, as in Hopsan. Its output xv is the valve's opening s times Xvmax.

    ``counterbalance``: [Hopsan2026] Hydraulic/Special/HydraulicCounterBalanceValveG.hpp, the relief valve's spool
    with the pilot P3 on the fraction kappa of its area, p_1 - p_2 + kappa p_3 - pref (p_3 absolute, no flow), and
    no check valve: a CounterbalanceValve with ``pilot = "drop"``, ``check = "none"``, r_p = kappa, p_crack =
    pref - kappa p_atm (the gauge setting of Hopsan's absolute pilot); its own defaults (Dv 0.03 m, Bv 100 N s/m,
    Xvmax 0.03 m, phi 0.03 rad, ks 100 N/m, pref 1e6 Pa).

    ``ported``: the same spool piloted from other ports, Special/HydraulicPressureControlValveG.hpp (relief:
    Δp_over = p3 - p4 - pref, a ReliefValve with ``pilot = "ports"``, P3 its X, P4 its Y) and
    HydraulicPressureCompensatingValveG.hpp (reducing: Δp_over = pref + p3 - p2, a PressureReducingValve with
    ``pilot = "port"``, P3 its X); pref is then a difference of pressures. Their flow forces take |p1 - p2|, the
    relief and reducing G valves' the drop with its sign, as hydroservo's does: the two differ only for a flow
    from P2 to P1.

    ``mass``: [Hopsan2026] Hydraulic/Special/HydraulicPressureRelief2ValveG.hpp, the relief valve's spool with mass
    Mv, A_v/(Mv s² + Bv s + k_e) clamped to [0, Xvmax] with its memory (inelastic stops), its whole circumference
    open (w = π Dv sin φ, no frac): ``spool = "mass"``, tau_m = Mv/Bv; its own defaults (Xvmax 0.03 m); outputs
    xv = s Xvmax and dxv = ds Xvmax (0 at a stop, as Hopsan's dxLimit)."""
    if mass:
        defaults = {"Dv": 0.01, "phi": 1.17, "ks": 1e4, "Bv": 1000.0, "Xvmax": 0.03, "pref": 1e7}
    elif counterbalance:
        defaults = {"Dv": 0.03, "phi": 0.03, "ks": 100.0, "Bv": 100.0, "Xvmax": 0.03, "pref": 1e6}
    elif reducing and ported:  # the compensating valve's own defaults
        defaults = {"Dv": 0.03, "phi": 1.17, "ks": 1e4, "Bv": 1000.0, "Xvmax": 0.01, "pref": 1e6}
    else:
        defaults = {"Dv": 0.01, "phi": 1.17, "ks": 1e4, "Bv": 1000.0, "Xvmax": 0.002, "pref": 1e6 if ported else 1e7}

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import CounterbalanceValve, PressureReducingValve, ReliefValve

        rho, dv, phi = par("rho", 870.0), par("Dv", defaults["Dv"]), par("phi", defaults["phi"])
        frac = 1.0 if mass else par("frac", 0.1)
        ks, bv = par("ks", defaults["ks"]), par("Bv", defaults["Bv"])
        x_vmax, cq = par("Xvmax", defaults["Xvmax"]), par("Cq", 0.67)
        before = len(par.problems)
        for name, value in (("rho", rho), ("Dv", dv), ("frac", frac), ("ks", ks), ("Bv", bv), ("Xvmax", x_vmax),
                            ("Cq", cq), ("p0", par("p0", 1e5)), *((("Mv", par("Mv", 0.03)),) if mass else ())):
            if value <= 0.0:
                par.problems.append(f"{par.where}: {name} = {value:g}; only a value above 0 is supported")
        if not 0.0 < phi < math.pi / 2:
            par.problems.append(
                f"{par.where}: stream angle phi = {phi:g} rad; only an angle in (0, π/2) is supported (a jet that "
                "opens the valve and a flow force that closes it)"
            )
        if len(par.problems) > before:
            return Mapped()
        root = math.sqrt(2.0 / rho)
        c = cq * math.pi * dv * frac * math.sin(phi) * root  # K per metre of opening
        area = math.pi * dv * dv / 4.0
        p_nom = 7e6  # any nominal drop: the characteristics below are scaled by it
        c_s = ks / (c * area)
        c_f = 2.0 * math.cos(phi) / (root * area)
        spool: dict[str, Any] = {
            "spool": "balance",
            "tau": bv / ks,
            "k_cs": math.sqrt(p_nom) / c_s,
            "k_cf": 1.0 / (c_f * math.sqrt(p_nom)),
            "q_nom": c * x_vmax * math.sqrt(p_nom),
            "p_nom": p_nom,
            "p_tr": par("p0", 1e5),
        }
        if mass:
            spool.update(spool="mass", tau_m=par("Mv", 0.03) / bv)
        comp: cbase.Component
        power = {"P1": f"{n}.A", "P2": f"{n}.B"}
        if counterbalance:
            kappa = par("kappa", 0.1)
            if kappa < 0.0:
                par.problems.append(f"{par.where}: kappa = {kappa:g}; an area fraction of 0 or more is supported")
            comp = CounterbalanceValve(n, p_crack=par("pref", defaults["pref"]) - kappa * ATMOSPHERE, r_p=max(kappa, 0.0),
                                       pilot="drop", check="none", **spool)
            power["P3"] = f"{n}.X"
        elif ported:
            power.update({"P3": f"{n}.X"} if reducing else {"P3": f"{n}.X", "P4": f"{n}.Y"})
            if reducing:
                comp = PressureReducingValve(n, p_set=par("pref", defaults["pref"]), pilot="port", **spool)
            else:
                comp = ReliefValve(n, p_crack=par("pref", defaults["pref"]), pilot="ports", **spool)
        elif reducing:
            comp = PressureReducingValve(n, p_set=_abs(par("pref", defaults["pref"])), **spool)
        else:
            comp = ReliefValve(n, p_crack=par("pref", defaults["pref"]), pilot="drop", **spool)
        values = {"xv": Var(x_vmax, f"{n}.s")}
        if mass:  # Hopsan's outputs: its spool's position and velocity
            values["dxv"] = Var(x_vmax, f"{n}.ds")
        return Mapped(
            [comp],
            power=power,
            values=values,
            initial={f"{n}.K": c * min(max(par("xv", 0.0), 0.0), x_vmax)},
        )

    return build


def _over_center(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/PressureControlValves/HydraulicOverCenterValve.hpp: HydraulicPressureReliefValve's
    spool (its static opening (p_1 - p_ref + a_ratio p_control)/(C_s + C_f (p_1 - p_2)) through the hysteresis p_h
    and the lag tao, limited to [0, q_nom/√p_nom]; the flow that coefficient times √(p_1 - p_2), either way),
    piloted by P_CONTROL (absolute, no flow) on a_ratio times its area: a CounterbalanceValve with ``check =
    "none"`` (Hopsan's has no check valve), r_p = a_ratio, p_crack = p_ref - (1 + a_ratio) p_atm (the gauge setting
    of Hopsan's sum of absolute pressures), its own p_nom; P_CONTROL the pilot port X. Its output xv (the flow
    coefficient, Hopsan's x0) is the valve's K."""
    from hydroservo.components import CounterbalanceValve

    ratio, p_h = par("a_ratio", 5.0), par("p_h", 5e5)
    if ratio < 0.0 or p_h < 0.0:
        par.problems.append(f"{par.where}: a_ratio = {ratio:g}, p_h = {p_h:g} Pa; values of 0 or more are supported")
        return Mapped()
    comp = CounterbalanceValve(
        n,
        p_crack=par("p_ref", 2e6) - (1.0 + ratio) * ATMOSPHERE,
        r_p=ratio,
        check="none",
        tau=par("tao", 0.01),
        k_cs=par("k_cs", 1e-8),
        k_cf=par("k_cf", 1e-8),
        q_nom=par("q_nom", 0.001),
        p_nom=par("p_nom", 7e6),
        p_tr=1e3,  # as the relief valve's
        p_h=p_h,
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P_CONTROL": f"{n}.X"},
                  values={"xv": Var(1.0, f"{n}.K")})


def _accumulator(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Volumes&Lines/HydraulicAckumulator.hpp: a Q-type gas accumulator whose state of charge
    x = xmp follows V0 ẋ = Kca (p_1 - pa), limited to [0, 1] (its trapezoidal rule and limit stand for that ODE
    held at its bounds), pa = p0 (1/limit(1 - x, 0.1, 1))^kappa (absolute), q into it V0 ẋ: Accumulator with
    ``inlet = "laminar"``, K_ca = Kca, V_gmin = 0.1 V0, V_oil starting at xmp V0. Its outputs pa (absolute), Va
    (V0 (1 - x)), xmp and vmp (ẋ) are the Accumulator's p, V_gas, V_oil/V0 and Q/V0."""
    from hydroservo.components import Accumulator

    v0, kappa = par("V0", 1e-3), par("kappa", 1.2)
    if v0 <= 0.0 or par("Kca", 1e-8) <= 0.0:
        par.problems.append(f"{par.where}: V0 and Kca above 0 are supported")
        return Mapped()
    if not 1.0 <= kappa <= 1.67:
        par.problems.append(f"{par.where}: kappa = {kappa:g}; a polytropic exponent in [1, 1.67] is supported")
        return Mapped()
    comp = Accumulator(
        n, inlet="laminar", V0=v0, K_ca=par("Kca", 1e-8), kappa=kappa, p0=_abs(par("p0", 1e7)), V_gmin=0.1 * v0
    )
    return Mapped(
        [comp],
        power={"P1": f"{n}.P"},
        values={
            "pa": Var(1.0, f"{n}.p", absolute=True),
            "Va": Var(1.0, f"{n}.V_gas"),
            "xmp": Var(1.0, f"{n}.V_oil", text=f"{n}.V_oil/{n}.V0", unit=""),
            "vmp": Var(1.0, f"{n}.Q", text=f"{n}.Q/{n}.V0", unit="1/s"),
        },
        initial={f"{n}.V_oil": min(max(par("xmp", 0.0), 0.0), 1.0) * v0},
    )


def _piston_accumulator(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Volumes&Lines/HydraulicPistonAckumulator.hpp: a piston of area Ap and mass ML, damped
    by Bp, between the oil at P1 and a gas pre-charged to p0 in the stroke SL: ML ẍ = Ap (p_1 - pa) - Bp ẋ, x in
    [0, SL] (Hopsan's bilinear transforms of it, the position clamped and the velocity zeroed at the ends: inelastic
    stops), pa = p0 (SL/limit(SL - x, 0.001 SL, SL))^kappa (absolute), q into it Ap ẋ: Accumulator with
    ``inlet = "piston"``, V0 = Ap SL, V_gmin = 0.001 V0, stiff end stops for the inelastic ones: 1e11 N/m rather
    than the default 1e9, since a piston held on its stop by the pre-charge (1e4 N in Hopsan's test) sinks 10 µm
    into a 1e9 N/m stop, and the oil that takes (1e-8 m³ there) shifts the instant it breaks away by some 0.5 ms,
    and with it the phase of the piston's lightly damped oscillation on the oil (flows 12 % of range off on
    Hopsan's test; 0.41 % at 1e11 N/m). Its outputs pa (absolute), Va, xmp and vmp are the Accumulator's p,
    V_gas, V_oil/Ap and Q/Ap."""
    from hydroservo.components import Accumulator

    ap, sl, ml, kappa = par("Ap", 1e-3), par("SL", 0.5), par("ML", 1.0), par("kappa", 1.2)
    if ap <= 0.0 or sl <= 0.0 or ml <= 0.0 or par("Bp", 10.0) < 0.0:
        par.problems.append(f"{par.where}: Ap, SL and ML above 0 and Bp at least 0 are supported")
        return Mapped()
    if not 1.0 <= kappa <= 1.67:
        par.problems.append(f"{par.where}: kappa = {kappa:g}; a polytropic exponent in [1, 1.67] is supported")
        return Mapped()
    v0 = ap * sl
    comp = Accumulator(
        n, inlet="piston", V0=v0, A_p=ap, m_p=ml, B_p=par("Bp", 10.0), kappa=kappa, p0=_abs(par("p0", 1e7)),
        V_gmin=0.001 * v0, k_stop=1e11, c_stop=1e6,
    )
    return Mapped(
        [comp],
        power={"P1": f"{n}.P"},
        values={
            "pa": Var(1.0, f"{n}.p", absolute=True),
            "Va": Var(1.0, f"{n}.V_gas"),
            "xmp": Var(1.0, f"{n}.V_oil", text=f"{n}.V_oil/{n}.A_p", unit="m"),
            "vmp": Var(1.0, f"{n}.Q", text=f"{n}.Q/{n}.A_p", unit="m/s"),
        },
        initial={f"{n}.x_p": min(max(par("xmp", 0.0), 0.0), sl), f"{n}.v_p": par("vmp", 0.0)},
    )


def _fixed_pump(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementPump.hpp: q = D_p n_p/2π - C_lp (p_2 - p_1),
    no port drawn below 0 Pa absolute: a Pump with ``inlet = "floor"``; its speed n_p [rad/s] driven by a signal
    (``speed = "input"``, the signal into ``omega_in``; a negative speed pumps backwards, as Hopsan's)."""
    from hydroservo.components import Pump

    driven = "n_p" in par.driven
    comp = Pump(n, D=f"{par('D_p', 5e-5)!r} m^3/rev", omega=0.0 if driven else par("n_p", 250.0),
                C_leak=par("C_lp", 1e-12), inlet="floor", p_floor=_abs(0.0), speed="input" if driven else "constant")
    return Mapped([comp], power={"P1": f"{n}.S", "P2": f"{n}.P"}, inputs={"n_p": f"{n}.omega_in"} if driven else {})


def _edge_coefficient(par: _Params, f: float, rho: float, d: str = "d", c_q: str = "C_q") -> float:
    """Hopsan's flow coefficient of a spool edge, C_q f π d √(2/ρ) [m^2/s/Pa^0.5] (Kc = c_v times the opening)."""
    return par(c_q, 0.67) * f * math.pi * par(d, 0.01) * math.sqrt(2.0 / rho)


def _equal_fractions(par: _Params, names: tuple[str, ...]) -> float:
    """The edges' common fraction of the circumference; unequal ones are refused (FourWayValve has one c_v)."""
    f = [par(name, 1.0) for name in names]
    if len(set(f)) > 1:
        par.problems.append(
            f"{par.where}: the edges' area fractions {', '.join(names)} differ ({', '.join(f'{v:g}' for v in f)}); "
            "FourWayValve has one flow coefficient for all four edges"
        )
    return f[0]


@dataclass
class _Spool:
    """A Hopsan valve's spool as hydroservo blocks: what drives SpoolSecondOrder ``{n}_spool``, and its outputs."""

    components: list[cbase.Component]
    inputs: dict[str, str]
    internal: list[tuple[str, str]]
    initial: dict[str, float]


def _spool(n: str, par: _Params, x_vmax: float, command: str, start: float = 0.0, delta_h: float = 1.0) -> _Spool:
    """Hopsan's spool of the flow-control and directional valves ([Hopsan2026] Hydraulic/Valves/FlowControlValves/
    Hydraulic43Valve.hpp and its siblings): a second-order filter 1/(s²/ω_h² + 2δ_h s/ω_h + 1) of the desired
    position ``in`` [m], its output limited to the stroke; the continuous law is SpoolSecondOrder (ω_n = omega_h,
    ζ = delta_h) on the fraction of the stroke x_v/x_vmax.

    ``command``: "symmetric", ``in`` limited to ±x_vmax (SpoolSecondOrder saturates its command to ±1);
    "one-sided", ``in`` limited to [0, x_vmax] (a Saturation in front); "on-off", the spool driven to x_vmax
    while ``in`` > 0.5 and to 0 otherwise (Hopsan's doubleToBool; a Selector between 0 and a Constant 1). The
    one-sided and on-off spools are limited to [0, x_vmax] in Hopsan, SpoolSecondOrder to ±x_vmax: the same
    spool while it cannot overshoot its command, that is for delta_h >= 1 (its impulse response is then never
    negative, so a command within [0, 1] keeps it within [0, 1]); a smaller delta_h is refused.
    """
    from hydroservo.components import Constant, Gain, Saturation, Selector, SpoolSecondOrder

    omega, delta = par("omega_h", 100.0), par("delta_h", delta_h)
    if command != "symmetric" and delta < 1.0:
        par.problems.append(
            f"{par.where}: delta_h = {delta:g} < 1: Hopsan limits this spool to [0, x_vmax], SpoolSecondOrder to "
            "±x_vmax, and the two differ once the spool overshoots; set delta_h >= 1"
        )
    spool = SpoolSecondOrder(f"{n}_spool", omega_n=omega, zeta=delta, xv_max=x_vmax)
    low = -1.0 if command == "symmetric" else 0.0
    initial = {f"{n}_spool.s": min(max(start / x_vmax, low), 1.0)}
    if command == "on-off":
        # u1 (closed) is left at 0; route == 0.5 is closed, as in Hopsan (in > 0.5 opens)
        sel = Selector(f"{n}_on", limit12=math.nextafter(0.5, math.inf), limit23=1e300, limit34=1e300)
        one = Constant(f"{n}_open", value=1.0)
        return _Spool(
            [sel, one, spool], {"in": f"{n}_on.route"}, [(f"{n}_open.y", f"{n}_on.u2"), (f"{n}_on.y", f"{n}_spool.u")],
            initial,
        )
    gain = Gain(f"{n}_stroke", input_unit="m", K=f"{1.0 / x_vmax!r} 1/m")
    if command == "symmetric":
        return _Spool([gain, spool], {"in": f"{n}_stroke.u"}, [(f"{n}_stroke.y", f"{n}_spool.u")], initial)
    limit = Saturation(f"{n}_in", unit="m", lower=0.0, upper=x_vmax)
    return _Spool(
        [limit, gain, spool], {"in": f"{n}_in.u"},
        [(f"{n}_in.y", f"{n}_stroke.u"), (f"{n}_stroke.y", f"{n}_spool.u")], initial,
    )


_NOTE = {
    "symmetric": "a Gain (reference in m to a fraction of the stroke), a SpoolSecondOrder and a {valve}",
    "one-sided": "a Saturation (reference limited to [0, x_vmax]), a Gain, a SpoolSecondOrder and a {valve}",
    "on-off": "a Selector (open while in > 0.5), a SpoolSecondOrder and a {valve}",
}


def _valve43(hc: HopsanComponent, n: str, par: _Params, delta_h: float = 1.0) -> Mapped:
    from hydroservo.components import FourWayValve

    rho = par("rho", 870.0)
    c_v = _edge_coefficient(par, _equal_fractions(par, ("f_pa", "f_pb", "f_at", "f_bt")), rho)
    x_vmax = par("x_vmax", 0.01)
    # Hopsan's start value of the spool's position; delta_h: the component file's default damping
    spool = _spool(n, par, x_vmax, "symmetric", par("xv", 0.0), delta_h)
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
        [*spool.components, valve],
        power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A", "PB": f"{n}.B"},
        inputs=spool.inputs,
        values={"xv": Var(1.0, f"{n}_spool.xv")},
        initial=spool.initial,
        internal=[*spool.internal, (f"{n}_spool.xv", f"{n}.xv"), (f"{n}_spool.vv", f"{n}.vv")],
        note=_NOTE["symmetric"].format(valve="FourWayValve"),
    )


def _open_centre_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/FlowControlValves/HydraulicOpenCenterValve.hpp: the 4/3 valve (Hydraulic43Valve's
    spool and edges P-A, P-B, A-T, B-T, :func:`_valve43`) and a centre edge from C1 to C2, open at rest, whose
    opening is x_vmax - limit(|x_v| - x_cc, 0, x_vmax) (closed from |x_v| = x_vmax + x_cc on; a negative x_cc
    closes it before the end of the stroke), its flow coefficient C_q f_cc π d √(2/ρ), turbulent as the other edges.
    That opening is x_vmax + x_cc - s with s = limit(|x_v|, x_cc, x_cc + x_vmax): an Absolute, a Saturation and a
    Gain of -1 give -s to a TwoWayValve ``{n}_centre`` of overlap x_AB = -(x_vmax + x_cc), whose opening
    -s + x_vmax + x_cc is Hopsan's (never below 0, so the edge's own clamp never acts)."""
    from hydroservo.components import Absolute, Gain, Saturation, TwoWayValve

    rho, x_vmax, x_cc = par("rho", 870.0), par("x_vmax", 0.01), par("x_cc", -1e-6)
    if x_vmax <= 0.0:
        par.problems.append(f"{par.where}: x_vmax = {x_vmax:g} m; only a stroke above 0 is supported")
        return Mapped()
    m = _valve43(hc, n, par)
    centre = TwoWayValve(
        f"{n}_centre", c_v=_edge_coefficient(par, par("f_cc", 1.0), rho), x_AB=-(x_vmax + x_cc), rho=rho, D_h="1 mm",
        lambda_crit=10.0,
    )
    blocks: list[cbase.Component] = [
        Absolute(f"{n}_abs", unit="m"),
        Saturation(f"{n}_cc", unit="m", lower=x_cc, upper=x_cc + x_vmax),
        Gain(f"{n}_flip", unit="m", input_unit="m", K=-1.0),
    ]
    m.components += [*blocks, centre]
    m.power.update({"PC1": f"{n}_centre.A", "PC2": f"{n}_centre.B"})
    m.internal += [(f"{n}_spool.xv", f"{n}_abs.u"), (f"{n}_abs.y", f"{n}_cc.u"), (f"{n}_cc.y", f"{n}_flip.u"),
                   (f"{n}_flip.y", f"{n}_centre.xv")]
    m.note = (m.note + "; the centre edge C1-C2: an Absolute, a Saturation and a Gain (its opening from the "
              "spool's) and a TwoWayValve")
    return m


def _valve43_neutral(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic43ValveNeutralSupplyToTank.hpp and
    Hydraulic43ValveNeutralToTank.hpp: the 4/3 valve (Hydraulic43Valve's spool and edges P-A, P-B, A-T, B-T,
    :func:`_valve43`) whose centre position connects ports: an opening x_c = max(x_vmax - |x_v|/p_c, 0) (p_c, the
    fraction of the stroke over which the centre is open) of flow coefficient C_q f_c π d √(2/ρ), turbulent as the
    other edges. NeutralSupplyToTank: that edge from P to T (Hopsan's fifth turbulent flow q_pt); NeutralToTank:
    one such edge from A to T and one from B to T (Hopsan adds K_c to the A-T and B-T coefficients, two parallel
    turbulent orifices of the same pressure drop). Each centre edge is a TwoWayValve (``{n}_centre``, or
    ``{n}_centre_a`` and ``{n}_centre_b``) of overlap x_AB = -x_vmax on -|x_v|/p_c (an Absolute and a Gain of
    -1/p_c); its own clamp at 0 is Hopsan's max. Hopsan's flow at a port two edges meet is their sum, a Sum
    ``{n}_Q<port>``. Hopsan's default delta_h is 1 for the first, 10 for the second. p_c <= 0 and x_vmax <= 0 are
    refused."""
    from hydroservo.components import Absolute, Gain, Sum, TwoWayValve

    rho, x_vmax, p_c = par("rho", 870.0), par("x_vmax", 0.01), par("p_c", 0.02)
    if x_vmax <= 0.0 or p_c <= 0.0:
        par.problems.append(
            f"{par.where}: x_vmax = {x_vmax:g} m, p_c = {p_c:g}; only a stroke and a centre fraction above 0 are "
            "supported"
        )
        return Mapped()
    supply = hc.typename == "Hydraulic43ValveNeutralSupplyToTank"
    m = _valve43(hc, n, par, delta_h=1.0 if supply else 10.0)
    c_v = _edge_coefficient(par, par("f_c", 0.1), rho)
    m.components += [Absolute(f"{n}_abs", unit="m"), Gain(f"{n}_centre_x", unit="m", input_unit="m", K=-1.0 / p_c)]
    m.internal += [(f"{n}_spool.xv", f"{n}_abs.u"), (f"{n}_abs.y", f"{n}_centre_x.u")]
    edges = {"": ("P", "T")} if supply else {"_a": ("A", "T"), "_b": ("B", "T")}
    # Hopsan's flow at each port (out of the valve): the FourWayValve's and the centre edges' there, summed
    flows: dict[str, list[tuple[float, str]]] = {"P": [(-1.0, f"{n}.QS")], "T": [(1.0, f"{n}.QT")],
                                                  "A": [(1.0, f"{n}.QA")], "B": [(1.0, f"{n}.QB")]}
    for suffix, (a, b) in edges.items():
        edge = f"{n}_centre{suffix}"
        m.components.append(
            TwoWayValve(edge, c_v=c_v, x_AB=-x_vmax, rho=rho, D_h="1 mm", lambda_crit=10.0)
        )
        m.internal += [(f"{n}_centre_x.y", f"{edge}.xv"), (f"{n}.{a}", f"{edge}.A"), (f"{n}.{b}", f"{edge}.B")]
        flows[a].append((-1.0, f"{edge}.Q"))
        flows[b].append((1.0, f"{edge}.Q"))
    for port, terms in flows.items():
        if len(terms) > 1:
            total = f"{n}_Q{port}"
            m.components.append(Sum(total, unit="m^3/s", **{f"gain{i}": g for i, (g, _) in enumerate(terms, 1)}))
            m.internal += [(q, f"{total}.u{i}") for i, (_, q) in enumerate(terms, 1)]
            m.flow[f"P{port}"] = f"{total}.y"
    m.note += (
        "; the centre " + ("edge P-T" if supply else "edges A-T and B-T")
        + ": an Absolute and a Gain (the opening from the spool's) and " + ("a TwoWayValve" if supply else "two TwoWayValves")
    )
    return m


def _valve43_load_sensing(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic43LoadSensingValve.hpp: the 4/3 valve (its spool
    and edges as Hydraulic43Valve's) with a port PL to which it writes the pressure of A while x_v >= 0 and of B
    otherwise, taking that node's flow (p_load - c_L)/Z_c,L from neither A nor B (an ideal connection, in the limit
    of a vanishing step p_L = p_A or p_B): the FourWayValve with ``load_sensing = "port"``, its port L a stiff
    laminar passage G_L from the loaded port's pressure."""
    m = _valve43(hc, n, par)
    m.components[-1].set(load_sensing="port")
    m.power["PL"] = f"{n}.L"
    m.note = m.note.replace("a FourWayValve", "a FourWayValve with a load-sensing port")
    return m


def _valve42(command: str, all_edges: bool) -> Builder:
    """Hopsan's 4/2 valves ([Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic42Valve.hpp,
    Hydraulic42Valve2.hpp, Hydraulic/Valves/DirectionalValves/Hydraulic42DirectionalValve.hpp): a spool in
    [0, x_vmax] whose edges P-A and B-T open as x_v, and (Hydraulic42Valve2, the directional valve) P-B and A-T as
    x_vmax - x_v. A FourWayValve on that spool with laps x_PA = x_BT = 0 and x_PB = x_AT = -x_vmax (FourWayValve
    opens P-B and A-T as -x_v - lap), or, for Hydraulic42Valve, whose P-B and A-T never open, x_PB = x_AT = +x_vmax
    (covered over the whole stroke)."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import FourWayValve

        rho = par("rho", 870.0)
        fractions = ("f_pa", "f_pb", "f_at", "f_bt") if all_edges else ("f_pa", "f_bt")
        c_v = _edge_coefficient(par, _equal_fractions(par, fractions), rho)
        x_vmax = par("x_vmax", 0.01)
        # Hopsan's filter starts at its output's start value (the directional valve: at its input's, the value
        # driving it at the start if a signal does, limited to the stroke)
        start = par("in", 0.0) if command == "on-off" else par("xv", 0.0)
        spool = _spool(n, par, x_vmax, command, start)
        follows = {}
        if command == "on-off" and "in" in par.driven:
            follows = {f"{n}_spool.s": (spool.inputs["in"], lambda v: min(max(v, 0.0), x_vmax) / x_vmax)}
        other = -x_vmax if all_edges else x_vmax
        valve = FourWayValve(
            n, c_v=c_v, x_PA=0.0, x_BT=0.0, x_PB=other, x_AT=other, rho=rho, D_h="1 mm", lambda_crit=10.0
        )
        return Mapped(
            [*spool.components, valve],
            power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A", "PB": f"{n}.B"},
            inputs=spool.inputs,
            values={"xv": Var(1.0, f"{n}_spool.xv")},
            initial=spool.initial,
            internal=[*spool.internal, (f"{n}_spool.xv", f"{n}.xv"), (f"{n}_spool.vv", f"{n}.vv")],
            note=_NOTE[command].format(valve="FourWayValve"),
            start_from_input=follows,
        )

    return build


def _valve33(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic33Valve.hpp: P-A opens as x_v - x_pa, A-T as
    -x_v - x_at, each edge with its fraction of the circumference; the spool as the 4/3 valve's."""
    from hydroservo.components import ThreeWayValve

    rho = par("rho", 870.0)
    x_vmax = par("x_vmax", 0.01)
    spool = _spool(n, par, x_vmax, "symmetric", par("xv", 0.0))
    valve = ThreeWayValve(
        n,
        c_PA=_edge_coefficient(par, par("f_pa", 1.0), rho),
        c_AT=_edge_coefficient(par, par("f_at", 1.0), rho),
        x_PA=par("x_pa", -1e-6),
        x_AT=par("x_at", -1e-6),
        rho=rho,
        D_h="1 mm",
        lambda_crit=10.0,
    )
    return Mapped(
        [*spool.components, valve],
        power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A"},
        inputs=spool.inputs,
        values={"xv": Var(1.0, f"{n}_spool.xv")},
        initial=spool.initial,
        internal=[*spool.internal, (f"{n}_spool.xv", f"{n}.xv")],
        note=_NOTE["symmetric"].format(valve="ThreeWayValve"),
    )


def _valve32_directional(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/DirectionalValves/Hydraulic32DirectionalValve.hpp: an on/off spool in
    [0, x_vmax]; P-A opens as x_v, A-T as x_vmax - x_v: a ThreeWayValve with x_PA = 0 and x_AT = -x_vmax."""
    from hydroservo.components import ThreeWayValve

    rho = par("rho", 870.0)
    x_vmax = par("x_vmax", 0.01)
    c_v = _edge_coefficient(par, par("f", 1.0), rho)
    spool = _spool(n, par, x_vmax, "on-off", par("xv", 0.0))
    valve = ThreeWayValve(n, c_PA=c_v, c_AT=c_v, x_PA=0.0, x_AT=-x_vmax, rho=rho, D_h="1 mm", lambda_crit=10.0)
    return Mapped(
        [*spool.components, valve],
        power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A"},
        inputs=spool.inputs,
        values={"xv": Var(1.0, f"{n}_spool.xv")},
        initial=spool.initial,
        internal=[*spool.internal, (f"{n}_spool.xv", f"{n}.xv")],
        note=_NOTE["on-off"].format(valve="ThreeWayValve"),
    )


def _valve22(command: str, ports: tuple[str, str]) -> Builder:
    """Hopsan's 2/2 valves ([Hopsan2026] Hydraulic/Valves/FlowControlValves/Hydraulic22Valve.hpp, ports PP and PA,
    the desired position ``in`` limited to [0, x_vmax]; Hydraulic/Valves/DirectionalValves/
    Hydraulic22DirectionalValve.hpp, ports P1 and P2, on/off): one edge that opens as the spool x_v in
    [0, x_vmax], a TwoWayValve with x_AB = 0."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import TwoWayValve

        rho = par("rho", 870.0)
        x_vmax = par("x_vmax", 0.01)
        spool = _spool(n, par, x_vmax, command, par("xv", 0.0))
        valve = TwoWayValve(
            n, c_v=_edge_coefficient(par, par("f", 1.0), rho), x_AB=0.0, rho=rho, D_h="1 mm", lambda_crit=10.0
        )
        return Mapped(
            [*spool.components, valve],
            power={ports[0]: f"{n}.A", ports[1]: f"{n}.B"},
            inputs=spool.inputs,
            values={"xv": Var(1.0, f"{n}_spool.xv")},
            initial=spool.initial,
            internal=[*spool.internal, (f"{n}_spool.xv", f"{n}.xv")],
            note=_NOTE[command].format(valve="TwoWayValve"),
        )

    return build


def _pressure_controlled(kind: str) -> Builder:
    """Hopsan's pressure-controlled valves ([Hopsan2026] Hydraulic/Valves/PressureControlled/
    HydraulicPressureControlled22Valve.hpp, ...22Valve2, ...42Valve, ...42Valve2, ...42Valve3): the spool of the
    one-sided 2/2 and 4/2 valves (its second-order filter, limited to [0, x_vmax], starting at 0 as Hopsan's
    filter does whatever the file's x_v), commanded by the pilot pressure at PC (absolute, as Hopsan's Fs_min and
    Fs_max), x_vmax·limit((p_C - Fs_min)/(Fs_max - Fs_min), 0, 1). PC takes no flow: a Sum reads its node (as a
    sensor does), a Sum takes Fs_min off, a Gain scales to metres. The edges (turbulent, as the 2/2 and 4/2
    valves'):

    * 22Valve (default closed): PP-PA opens as x_v, a TwoWayValve with x_AB = 0;
    * 22Valve2 (default open): PP-PA opens as x_vmax - x_v, a TwoWayValve on -x_v (a Gain of -1) with
      x_AB = -x_vmax;
    * 42Valve: P-A and B-T open as x_v, P-B and A-T never (Hydraulic42Valve's FourWayValve);
    * 42Valve2: P-A and B-T open as x_vmax - x_v, P-B and A-T never: a FourWayValve with Hopsan's PA on its B
      and PB on its A, whose P-B and A-T open as x_vmax - x_v (laps -x_vmax), P-A and B-T covered (+x_vmax);
    * 42Valve3: P-A and B-T as x_vmax - x_v, P-B and A-T as x_v: Hydraulic42Valve2's FourWayValve with PA and
      PB swapped.

    Fs_max <= Fs_min, unequal fractions of the edges used and delta_h < 1 (a spool that overshoots) are refused."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import FourWayValve, Gain, Sum, TwoWayValve

        rho, x_vmax = par("rho", 870.0), par("x_vmax", 0.01)
        fs_min, fs_max = par("Fs_min", 1e5), par("Fs_max", 1e6)
        if fs_max <= fs_min:
            par.problems.append(
                f"{par.where}: Fs_max = {fs_max:g} Pa is not above Fs_min = {fs_min:g} Pa; the spool opens between them"
            )
            fs_max = fs_min + 1.0
        spool = _spool(n, par, x_vmax, "one-sided", 0.0)  # Hopsan's filter starts at 0
        pilot = Sum(f"{n}_pilot", unit="Pa", gain2=0.0)  # the node's pressure, absolute (set as a sensor's)
        over = Sum(f"{n}_over", unit="Pa", gain2=0.0, offset=-fs_min)
        command = Gain(f"{n}_cmd", unit="m", input_unit="Pa", K=f"{x_vmax / (fs_max - fs_min)!r} m/Pa")
        blocks: list[cbase.Component] = [pilot, over, command, *spool.components]
        internal = [(f"{n}_pilot.y", f"{n}_over.u1"), (f"{n}_over.y", f"{n}_cmd.u"),
                    (f"{n}_cmd.y", spool.inputs["in"]), *spool.internal]
        power: dict[str, str]
        valve: cbase.Component
        if kind.startswith("22"):
            c_v = _edge_coefficient(par, par("f_pa", 1.0), rho)
            if kind == "22":
                valve = TwoWayValve(n, c_v=c_v, x_AB=0.0, rho=rho, D_h="1 mm", lambda_crit=10.0)
                internal.append((f"{n}_spool.xv", f"{n}.xv"))
            else:
                valve = TwoWayValve(n, c_v=c_v, x_AB=-x_vmax, rho=rho, D_h="1 mm", lambda_crit=10.0)
                flip = Gain(f"{n}_flip", unit="m", input_unit="m", K=-1.0)
                blocks.append(flip)
                internal += [(f"{n}_spool.xv", f"{n}_flip.u"), (f"{n}_flip.y", f"{n}.xv")]
            power = {"PP": f"{n}.A", "PA": f"{n}.B"}
        else:
            fractions = ("f_pa", "f_pb", "f_at", "f_bt") if kind == "42-3" else ("f_pa", "f_bt")
            c_v = _edge_coefficient(par, _equal_fractions(par, fractions), rho)
            laps = {"42": (0.0, x_vmax), "42-2": (x_vmax, -x_vmax), "42-3": (0.0, -x_vmax)}[kind]
            valve = FourWayValve(n, c_v=c_v, x_PA=laps[0], x_BT=laps[0], x_PB=laps[1], x_AT=laps[1], rho=rho,
                                 D_h="1 mm", lambda_crit=10.0)
            a, b = ("A", "B") if kind == "42" else ("B", "A")  # 42Valve2 and 42Valve3: Hopsan's PA on B
            power = {"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.{a}", "PB": f"{n}.{b}"}
            internal += [(f"{n}_spool.xv", f"{n}.xv"), (f"{n}_spool.vv", f"{n}.vv")]
        return Mapped(
            [*blocks, valve],
            power=power,
            read={"PC": (f"{n}_pilot.u1", "Pressure")},
            values={"x_v": Var(1.0, f"{n}_spool.xv")},
            initial=spool.initial,
            internal=internal,
            note="a Sum reading the pilot PC, a Sum and a Gain to the spool's command, "
            + _NOTE["one-sided"].format(valve="TwoWayValve" if kind.startswith("22") else "FourWayValve"),
        )

    return build


def _valve33_edges(par: _Params, rho: float, x0: float, plam: float) -> dict[str, Any]:
    """The edges of Hopsan's HydraulicValve33 and HydraulicPressureControlValve33 as a ThreeWayValve's: P-A
    opening as Xap0 + xv and A-T as Xap0 - xv, each C_q √(2/ρ) π Fr Sd wide, turbulent above the laminar onset
    plam (the transition pressure of D_h)."""
    nu, lambda_crit = 32e-6, 1000.0
    return {
        "c_PA": _edge_coefficient(par, par("Frap", 1.0), rho, d="Sd", c_q="Cq"),
        "c_AT": _edge_coefficient(par, par("Frat", 1.0), rho, d="Sd", c_q="Cq"),
        "x_PA": -x0,
        "x_AT": -x0,
        "rho": rho,
        "nu": nu,
        "lambda_crit": lambda_crit,
        "D_h": lambda_crit * nu * math.sqrt(rho / (2.0 * plam)),  # transition_pressure(D_h) = plam
    }


def _valve33_special(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicValve33.hpp: a 3/3 valve whose spool position xv [m] is its input
    (no spool dynamics). Its edges' conductances are Ks π Fr Sd limit(Xap0 ± xv, 0, X0 + Xvmax) with
    Ks = Cq √(2/ρ), and the flows Ks·signedSquareL(Δp, plam) = Δp/(Δp² + plam²)^(1/4) (Hopsan's equation system,
    solved by Newton iterations each step, stands for these algebraic flows): a ThreeWayValve with the overlaps
    -Xap0 (Xap0 is an underlap), the transition pressure plam (D_h chosen so that p_tr = plam) and xv limited to
    ±Xvmax (a Saturation: the upper limits of the openings). Hopsan's A-T edge opens as Xap0 - xv, not Xat0 - xv
    (Xat0 enters only its upper limit): a valve with Xat0 different from Xap0 is refused."""
    from hydroservo.components import Saturation, ThreeWayValve

    rho = par("rho", 870.0)
    x0, x_vmax, plam = par("Xap0", 0.0), par("Xvmax", 0.01), par("plam", 1e4)
    if par("Xat0", 0.0) != x0:
        par.problems.append(
            f"{par.where}: Xat0 = {par('Xat0', 0.0):g} m differs from Xap0 = {x0:g} m: Hopsan's A-T edge opens as "
            "Xap0 - xv with its limit at Xat0 + Xvmax, which a ThreeWayValve of one underlap per edge does not have"
        )
    if plam <= 0.0:
        par.problems.append(f"{par.where}: plam = {plam:g} Pa; a turbulence onset pressure above 0 is supported")
        plam = 1e4
    valve = ThreeWayValve(n, **_valve33_edges(par, rho, x0, plam))
    limit = Saturation(f"{n}_xv", unit="m", lower=-x_vmax, upper=x_vmax)
    return Mapped(
        [limit, valve],
        power={"Pp": f"{n}.P", "Pt": f"{n}.T", "Pa": f"{n}.A"},
        inputs={"xv": f"{n}_xv.u"},
        internal=[(f"{n}_xv.y", f"{n}.xv")],
        note="a Saturation (xv limited to ±Xvmax) and a ThreeWayValve",
    )


def _valve416(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/HydraulicValve416.hpp: a 4/3 valve whose four edges each have a spool position of
    their own as input (xvpa, xvta, xvpb, xvtb [m], no spool dynamics), each edge's conductance Ks π Fr Sd
    limit(X0 + xv, 0, X0 + Xvmax) with Ks = Cq √(2/ρ) and its flow Ks·signedSquareL(Δp, plam) (Hopsan's
    equation system, solved by Newton iterations each step, stands for these algebraic flows): four TwoWayValves
    (``{n}_pa``, ``{n}_ta``, ``{n}_pb``, ``{n}_tb``: P to A, A to T, P to B, B to T), each behind a Saturation of
    its input to at most Xvmax, with the overlap −X0 (X0 is an underlap) and the transition pressure plam
    (HydraulicValve33's edges, :func:`_valve33_edges`). Each of Hopsan's ports joins two edges: its flow, out of
    the valve, is a Sum of theirs (``{n}_qp`` ...). π where Hopsan writes 3.14159 (8e-7 apart)."""
    from hydroservo.components import Saturation, Sum, TwoWayValve

    rho, x_vmax, plam = par("rho", 870.0), par("Xvmax", 0.01), par("plam", 1e4)
    if plam <= 0.0:
        par.problems.append(f"{par.where}: plam = {plam:g} Pa; a turbulence onset pressure above 0 is supported")
        plam = 1e4
    comps: list[cbase.Component] = []
    internal: list[tuple[str, str]] = []
    inputs: dict[str, str] = {}
    # edge -> (its ports A, B on Hopsan's ports, its fraction, underlap and input)
    edges = {"pa": ("Pp", "Pa"), "ta": ("Pa", "Pt"), "pb": ("Pp", "Pb"), "tb": ("Pb", "Pt")}
    for edge in edges:
        fraction, underlap = par(f"Fr{edge}", 1.0), par(f"X{edge}0", 0.0)
        laws = _valve33_edges(par, rho, underlap, plam)
        comps.append(Saturation(f"{n}_x{edge}", unit="m", lower=-1e30, upper=x_vmax))
        comps.append(TwoWayValve(f"{n}_{edge}", c_v=_edge_coefficient(par, fraction, rho, d="Sd", c_q="Cq"),
                                 x_AB=-underlap, **{k: laws[k] for k in ("rho", "nu", "lambda_crit", "D_h")}))
        internal.append((f"{n}_x{edge}.y", f"{n}_{edge}.xv"))
        inputs[f"xv{edge}"] = f"{n}_x{edge}.u"
    power: dict[str, str] = {}
    flow: dict[str, str] = {}
    for port in ("Pp", "Pt", "Pa", "Pb"):
        ends = [(f"{n}_{edge}.{'AB'[ab.index(port)]}", 1.0 if ab.index(port) == 1 else -1.0)
                for edge, ab in edges.items() if port in ab]
        power[port] = ends[0][0]
        internal.append((ends[0][0], ends[1][0]))
        total = f"{n}_q{port[1]}"
        comps.append(Sum(total, unit="m^3/s", gain1=ends[0][1], gain2=ends[1][1]))
        for k, (end, _) in enumerate(ends, start=1):
            internal.append((f"{end.split('.')[0]}.Q", f"{total}.u{k}"))
        flow[port] = f"{total}.y"
    return Mapped(comps, power=power, inputs=inputs, internal=internal, flow=flow,
                  note="four TwoWayValves, one per edge, each behind a Saturation of its spool position")

def _pressure_control_valve33(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/HydraulicPressureControlValve33.hpp: a 3/3 valve (P1 supply, P2 tank, P3 the
    controlled line) whose massless spool, damped by Bv, is pushed by the pilot pressure at P4 against the setting
    pref (absolute) on its area Av = π Sd²/4 and held by its spring ks and the steady flow forces of its open edges:
    Bv ẋv = Av (p4 - pref) - (ks + k_f) xv, xv in [Xvmin, Xvmax] (Hopsan's bilinear transform of it, clamped with
    its memory), k_f = 2 Cq π Sd Fr cos φ |Δp| per edge. Its edges as HydraulicValve33's: Cq √(2/ρ) π Fr Sd
    limit(Xap0 ± xv, ...) signedSquareL(Δp, plam), P-A opening as Xap0 + xv and A-T as Xap0 - xv (Xat0 enters
    only A-T's upper limit, which a spool within [Xvmin, Xvmax] does not reach unless Xvmin < Xat0 - Xap0 - Xvmax,
    refused). Hopsan switches A-T's flow force on only below xv = -Xat0, where that edge has opened by
    Xap0 + Xat0 (P-A's as soon as it opens): ``x_ATf`` = Xap0 + Xat0. A ThreeWayPressureValve
    (:class:`~hydroservo.components.valves.ThreeWayPressureValve`), the laminar onset plam as its transition pressure;
    its output xv is Hopsan's. π where Hopsan writes 3.14159, 0.785398 and 6.28319 (1e-6 apart)."""
    from hydroservo.components import ThreeWayPressureValve

    rho, sd, x0, x_at0 = par("rho", 870.0), par("Sd", 0.01), par("Xap0", 0.0), par("Xat0", 0.0)
    x_min, x_max, plam, phi = par("Xvmin", -0.01), par("Xvmax", 0.01), par("plam", 1e4), par("phi", 0.03)
    before = len(par.problems)
    for name, value in (("rho", rho), ("Sd", sd), ("plam", plam), ("Bv", par("Bv", 100.0))):
        if value <= 0.0:
            par.problems.append(f"{par.where}: {name} = {value:g}; only a value above 0 is supported")
    if par("ks", 100.0) < 0.0:
        par.problems.append(f"{par.where}: ks = {par('ks', 100.0):g} N/m; only a spring of at least 0 is supported")
    if not 0.0 <= phi <= math.pi / 2:
        par.problems.append(f"{par.where}: stream angle phi = {phi:g} rad; only an angle in [0, π/2] is supported")
    if x_min >= x_max:
        par.problems.append(f"{par.where}: Xvmin = {x_min:g} m is not below Xvmax = {x_max:g} m")
    elif x_min < x_at0 - x0 - x_max:
        par.problems.append(
            f"{par.where}: Xvmin = {x_min:g} m lets A-T open past its limit Xat0 + Xvmax = {x_at0 + x_max:g} m, "
            "which a ThreeWayValve's edge does not have"
        )
    if len(par.problems) > before:
        return Mapped()
    valve = ThreeWayPressureValve(
        n,
        **_valve33_edges(par, rho, x0, plam),
        A_v=math.pi * sd * sd / 4.0,
        p_ref=_abs(par("pref", 1e6)),
        k_s=par("ks", 100.0),
        B_v=par("Bv", 100.0),
        phi=phi,
        x_min=x_min,
        x_max=x_max,
        x_ATf=x0 + x_at0,
    )
    return Mapped(
        [valve],
        power={"P1": f"{n}.P", "P2": f"{n}.T", "P3": f"{n}.A", "P4": f"{n}.X"},
        values={"xv": Var(1.0, f"{n}.xv")},
        initial={f"{n}.x_v": min(max(par("xv", 0.0), x_min), x_max)},
        note="a ThreeWayPressureValve",
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
        C_Li=par("c_leak", 1e-11),
        x_min=0.0,
        x_max=sl,
        pressure_floor="cavity",
        p_floor="0 Pa_abs",
        p_amb="0 Pa_abs",  # Hopsan's piston force is that of absolute pressures: no atmosphere on the rod
        pA0=_abs(par.start("P1", "Pressure", 1e5)),
        pB0=_abs(par.start("P2", "Pressure", 1e5)),
    )
    use_sl = hc.parameters.get("use_sl")
    if use_sl is not None and use_sl.text.strip().lower() in ("false", "0"):
        comp.set(k_stop=0.0, c_stop=0.0)  # Hopsan's end stops switched off
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P3": f"{n}.R"})


def _four_chamber_piston(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/LinearActuators/HydraulicFourChamberPiston.hpp: four transmission-line chambers on one
    piston, in the limit of a vanishing step a FourChamberCylinder (Hopsan's names and dead volumes; its position
    from the retracted end, Hopsan's −x5) with its chambers floored at 0 Pa absolute, the force of absolute
    pressures (``p_amb`` 0 Pa absolute), its stroke limit as stiff stops (none with use_sl false); each chamber
    starts at its port's start pressure."""
    from hydroservo.components import FourChamberCylinder

    values: dict[str, Any] = {f"A_{i}": par(f"A_{i}", 0.001) for i in (1, 2, 3, 4)}
    values.update({f"V_{i}": par(f"V_{i}", 0.0003) for i in (1, 2, 3, 4)})
    values.update({f"c_leak{i}{j}": par(f"c_leak{i}{j}", 1e-11 if f"{i}{j}" in ("12", "14", "34") else 0.0)
                   for i, j in ((1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4))})
    values.update({f"p{i}_0": _abs(par.start(f"P{i}", "Pressure", 1e5)) for i in (1, 2, 3, 4)})
    comp = FourChamberCylinder(n, s_l=par("s_l", 1.0), B_p=par("B_p", 1000.0), Beta_e=par("Beta_e", 1e9),
                               p_floor=_abs(0.0), p_amb=_abs(0.0), **values)
    use_sl = hc.parameters.get("use_sl")
    if use_sl is not None and use_sl.text.strip().lower() in ("false", "0"):
        comp.set(k_stop=0.0, c_stop=0.0)  # Hopsan's end stops switched off
    return Mapped([comp], power={**{f"P{i}": f"{n}.P{i}" for i in (1, 2, 3, 4)}, "P5": f"{n}.P5"})

def _cylinder_q(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/LinearActuators/HydraulicCylinderQ.hpp: a Q-type piston with its load, between the
    C components joined to P1 and P2 (the chambers' volumes): its transfer functions 1/(m_l s² + (B_l + B_p) s +
    k_l) from the force A_1 p_1 - A_2 p_2 - f_3 to the position x_3, limited to [0, s_l] (the velocity zeroed
    there: inelastic stops), and q_1 = -A_1 v_3, q_2 = A_2 v_3 (Hopsan's flows count out of the component), are in
    the limit m_l ẍ = A_1 p_1 - A_2 p_2 - F_3 - (B_l + B_p) ẋ - k_l x: :func:`_q_piston`."""
    sl, m = par("s_l", 0.01), par("m_l", 0.05)
    if sl <= 0.0 or m <= 0.0:
        par.problems.append(f"{par.where}: s_l = {sl:g} m, m_l = {m:g} kg; only values above 0 are supported")
        return Mapped()
    return _q_piston(n, par, par("A_1", 1e-4), par("A_2", 1e-4), par("B_p", 0.0), m, par("B_l", 0.0),
                     par("k_l", 100.0), 0.0, sl, 0.0, "P3")


def _piston_mload(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicPistonMload.hpp: HydraulicCylinderQ's law with internal leakage and
    stops of their own, from its equation system: mL ẍ = A1 p_1 - A2 p_2 - f_mp - (bL + bp) ẋ, x limited to
    [xmin, xmax] (the velocity zeroed there), q_1 = -A1 ẋ - Cip (p_1 - p_2), q_2 = A2 ẋ + Cip (p_1 - p_2):
    :func:`_q_piston` with C_Li = Cip, no spring; its port Pmp. Its dry friction fc and bfc are declared but enter
    none of its equations, nor SL (the stops are xmin, xmax): they are not used here either."""
    m, x_min, x_max = par("mL", 1000.0), par("xmin", 0.0), par("xmax", 0.5)
    if m <= 0.0 or x_max <= x_min or par("Cip", 0.0) < 0.0:
        par.problems.append(f"{par.where}: mL = {m:g} kg, xmin = {x_min:g} m, xmax = {x_max:g} m, Cip = "
                            f"{par('Cip', 0.0):g}; expected mL > 0, xmin < xmax and Cip >= 0")
        return Mapped()
    return _q_piston(n, par, par("A1", 1e-3), par("A2", 1e-3), par("bp", 0.0), m, par("bL", 0.0), 0.0, x_min,
                     x_max, par("Cip", 0.0), "Pmp")


def _q_piston(n: str, par: _Params, a1: float, a2: float, bp: float, m: float, bl: float, kl: float, x_min: float,
              x_max: float, c_leak: float, port: str) -> Mapped:
    """Hopsan's Q-type pistons: a Cylinder with ``chambers = "ports"`` (its ports read the pressures of the volumes
    joined to them; B_p, internal leakage) pushing a Mass ``{n}_load`` (m, B_l, k_l towards x = 0), whose end 2 is
    ``port``, with stiff stops at x_min and x_max (1e9 N/m) damped critically for m, 2 √(1e9 N/m m): a stop that
    does not bounce, as Hopsan's inelastic one (the masses' 1e6 N s/m on HydraulicCylinderQ's default m_l of
    0.05 kg makes a mode of 2e7 1/s that switches on and off at the stop's edge, and the solver's steps collapse
    there). The pressures it reads are those of the volumes, at least 0 Pa absolute with their cavity law, as
    Hopsan's cavitation check floors them."""
    from hydroservo.components import Cylinder, Mass

    cyl = Cylinder(n, A_A=a1, A_B=a2, B_p=bp, C_Li=c_leak, chambers="ports", x_min=x_min, x_max=x_max, k_stop=0.0,
                   c_stop=0.0, p_amb="0 Pa_abs")
    load = Mass(f"{n}_load", m=m, B=bl, k_spring=kl, incline=0.0, x0=par.start(port, "Position"),
                v0=par.start(port, "Velocity"), x_min=x_min, x_max=x_max, k_stop=1e9,
                c_stop=2.0 * math.sqrt(1e9 * m))  # critically damped: no bounce, as Hopsan's inelastic stops
    return Mapped(
        [cyl, load],
        power={"P1": f"{n}.A", "P2": f"{n}.B", port: f"{n}_load.P2"},
        internal=[(f"{n}.R", f"{n}_load.P1")],
        note=f"Cylinder {n} (chambers = ports) pushing Mass {n}_load",
    )


def _spring_loaded_piston(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/LinearActuators/HydraulicSpringLoadedPistonC.hpp: HydraulicCylinderC's chambers
    and piston (the same volumes, leakage and stops) with the constant spring force F_s taken off the force at P3
    (its wave variable c3 - F_s): the cylinder of HydraulicCylinderC's mapping with ``F_s``. Its chambers' wave
    variables are floored at 0 (not its cylinder's cavity: no deficit to refill), so a chamber at 0 Pa absolute
    loses no more pressure: ``pressure_floor = "check-valve"`` at 0 Pa absolute, the leakage between the floored
    pressures."""
    m = _cylinder_c(hc, n, par)
    m.components[0].set(pressure_floor="check-valve", F_s=par("F_s", 1000.0))
    m.note = f"Cylinder {n} with F_s, pressure_floor = check-valve"
    return m


def _piston_mkload(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicPistonMkload.hpp: a Q-type piston (no oil of its own: its ports take
    the pressures of the volumes they join) carrying a load of mass mL on a spring kL to x = 0, damped by bL + bp,
    with dry friction fc, its position limited to [xmin, xmax]: mL ẍ = A1 p1 - A2 p2 - f_mp - (bL + bp) ẋ - kL x -
    F_f, the flows into the piston A1 ẋ + Cip (p1 - p2) at P1 and -A2 ẋ - Cip (p1 - p2) at P2 (Hopsan's equation
    system, solved by Newton iterations each step with the bilinear transform of the mass, stands for these laws).
    Its friction limit(bfc mL ẋ/Ts, -fc, fc) is a viscous slope that grows without bound as the step Ts vanishes:
    dry friction that holds the load until the force on it passes fc, and opposes the motion with fc after, the
    Stribeck law with F_c0 = fc, F_s0 = 0 as its velocity scale vanishes (v_reg = 1e-5 m/s, as the mass with
    Coulomb friction); the factor bfc drops out (bfc = 0 is no friction). A Cylinder with ``chambers = "ports"``
    (A_A = A1, A_B = A2, C_Li = Cip, B_p = bp, end stops at xmin and xmax for Hopsan's inelastic ones, of 1e11 N/m
    rather than the default 1e9: on Pressure Controlled Pump the pump's pressure holds the piston on its stop with
    2 kN, 2 µm into a 1e9 N/m stop, which delays its break-away and made its velocity 4.4 % of range off Hopsan's,
    0.01 % at 1e11 N/m; the force of absolute pressures, p_amb 0 Pa_abs) pushing a Mass ``{n}_load`` (m = mL, B = bL, k_spring = kL) at
    its end P1, the port Pmp its end P2 (both at x: length 0). The stroke SL enters none of Hopsan's equations and is not used."""
    from hydroservo.components import Cylinder, Mass

    a1, a2, x_min, x_max = par("A1", 1e-3), par("A2", 1e-3), par("xmin", 0.0), par("xmax", 0.5)
    fc, bfc = par("fc", 10.0), par("bfc", 1.0)
    before = len(par.problems)
    for name, value in (("A1", a1), ("A2", a2), ("mL", par("mL", 1000.0))):
        if value <= 0.0:
            par.problems.append(f"{par.where}: {name} = {value:g}; only a value above 0 is supported")
    for name, value in (("Cip", par("Cip", 0.0)), ("bp", par("bp", 0.0)), ("bL", par("bL", 0.0)),
                        ("kL", par("kL", 0.0)), ("fc", fc)):
        if value < 0.0:
            par.problems.append(f"{par.where}: {name} = {value:g}; only a value of at least 0 is supported")
    if x_min >= x_max:
        par.problems.append(f"{par.where}: xmin = {x_min:g} m is not below xmax = {x_max:g} m")
    if len(par.problems) > before:
        return Mapped()
    piston = Cylinder(
        n, chambers="ports", A_A=a1, A_B=a2, C_Li=par("Cip", 0.0), B_p=par("bp", 0.0), x_min=x_min, x_max=x_max,
        p_amb="0 Pa_abs", k_stop=1e11, c_stop=1e6,
    )
    load = Mass(
        f"{n}_load", m=par("mL", 1000.0), B=par("bL", 0.0), k_spring=par("kL", 0.0), incline=0.0,
        F_c0=fc if bfc > 0.0 else 0.0, v_reg=1e-5,
        x0=min(max(par.start("Pmp", "Position"), x_min), x_max), v0=par.start("Pmp", "Velocity"),
    )
    return Mapped(
        [piston, load],
        power={"P1": f"{n}.A", "P2": f"{n}.B", "Pmp": f"{n}_load.P2"},
        internal=[(f"{n}.R", f"{n}_load.P1")],  # the rod faces the load's end 1: at x (length 0), pushing +x
        note="a Cylinder (chambers = ports) and a Mass",
    )


def _flow_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import FlowSource

    # Hopsan's q is an input: the flow, or, driven by a signal, the signal (added to q = 0)
    if "q" in par.driven:
        return Mapped([FlowSource(n, q=0.0)], power={"P1": f"{n}.P"}, inputs={"q": f"{n}.u"})
    return Mapped([FlowSource(n, q=par("q", 1e-3))], power={"P1": f"{n}.P"})


def _laminar_orifice(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import LaminarOrifice

    # Hopsan's Kc is an input: the coefficient, or, driven by a signal, the signal (added to G_lam = 0)
    ports = {"P1": f"{n}.A", "P2": f"{n}.B"}
    if "Kc" in par.driven:
        return Mapped([LaminarOrifice(n, G_lam=0.0)], power=ports, inputs={"Kc": f"{n}.u"})
    return Mapped([LaminarOrifice(n, G_lam=abs(par("Kc", 1e-11)))], power=ports)


def _turbulent_orifice(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Orifice

    area = abs(par("A", 1e-5))
    # Hopsan's A is an input: the area, or, driven by a signal, the signal (option area = input)
    driven = "A" in par.driven
    comp = Orifice(
        n,
        d=math.sqrt(4.0 * area / math.pi) if area > 0 else 1e-3,  # driven: the transition's diameter only
        Cd=par("C_q", 0.67),
        rho=par("rho", 870.0),
        lambda_crit=10.0,  # turbulent down to a few Pa, as Hopsan's
        area="input" if driven else "bore",
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"}, inputs={"A": f"{n}.A_in"} if driven else {})


#: Hopsan's check valves' coefficient K_s = C_d A √(2/ρ) as a bore at these C_d and ρ (only their product with A
#: matters), turbulent down to some 50 Pa (lambda_crit 10), as Hopsan's turbulent law without regularisation
_CHECK_CD, _CHECK_RHO = 0.67, 870.0


def _check_bore(k_s: float) -> dict[str, Any]:
    area = abs(k_s) / (_CHECK_CD * math.sqrt(2.0 / _CHECK_RHO))
    return {"d": math.sqrt(4.0 * area / math.pi), "Cd": _CHECK_CD, "rho": _CHECK_RHO, "lambda_crit": 10.0}


def _check_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Restrictors/HydraulicCheckValve.hpp: q = K_s √(p_1 - p_2) while p_1 > p_2, none
    otherwise: a CheckValve with option opening = "seat" at p_crack 0 (no spring), its bore from K_s
    (:func:`_check_bore`). HydraulicCheckValvePreLoaded.hpp: the same, open while p_1 > p_2 + F_s (p_crack = F_s,
    a drop)."""
    from hydroservo.components import CheckValve

    preload = par("F_s", 0.0) if hc.typename == "HydraulicCheckValvePreLoaded" else 0.0
    if preload < 0.0:
        par.problems.append(f"{par.where}: pre-load F_s = {preload:g} Pa; expected 0 or more")
        return Mapped()
    comp = CheckValve(n, opening="seat", p_crack=preload, **_check_bore(par("K_s", 5e-7)))
    # Hopsan's output x (1 open, 0 closed, for its animation) is the CheckValve's s: not aliased
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _shuttle_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/HydraulicShuttleValve.hpp: P3 joined without resistance to the inlet of higher
    pressure (Hopsan's flow (c_in - c_3)/(Zc_in + Zc_3), an ideal connection of the two nodes, p_3 = max(p_1, p_2)
    in the limit of a vanishing step), the other inlet shut: a ShuttleValve, whose open seat is a laminar
    conductance G_open large enough that P3 follows within G_open's drop. Its output out (-1: P1 open, 1: P2) is
    the ShuttleValve's."""
    from hydroservo.components import ShuttleValve

    return Mapped([ShuttleValve(n)], power={"P1": f"{n}.P1", "P2": f"{n}.P2", "P3": f"{n}.P3"},
                  outputs={"out": f"{n}.out"})


def _check_valve_with_orifice(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Restrictors/HydraulicCheckValveWithOrifice.hpp: q = K_s √(p_1 - p_2) forwards and
    K_r √ backwards (turbulent both ways): an Orifice of the smaller coefficient beside a seat CheckValve of the
    difference, facing the way of the larger (``{n}_orifice`` and ``{n}``); the flows at P1 and P2 their sum
    (``{n}_Q1``, ``{n}_Q2``)."""
    from hydroservo.components import CheckValve, Orifice, Sum

    k_s, k_r = abs(par("K_s", 5e-7)), abs(par("K_r", 5e-9))
    forward = k_s >= k_r
    check = CheckValve(n, opening="seat", p_crack=0.0, **_check_bore(abs(k_s - k_r)))
    bore = _check_bore(min(k_s, k_r))
    orifice = Orifice(f"{n}_orifice", d=bore["d"], Cd=_CHECK_CD, rho=_CHECK_RHO, lambda_crit=10.0)
    a, b = ("A", "B") if forward else ("B", "A")
    sign = 1.0 if forward else -1.0  # the check valve's Q runs from P1 to P2, or back
    flows = [Sum(f"{n}_Q1", unit="m^3/s", gain1=-sign, gain2=-1.0), Sum(f"{n}_Q2", unit="m^3/s", gain1=sign, gain2=1.0)]
    return Mapped(
        [check, orifice, *flows],
        power={"P1": f"{n}.{a}", "P2": f"{n}.{b}"},
        internal=[(f"{n}.{a}", f"{n}_orifice.A"), (f"{n}.{b}", f"{n}_orifice.B"), (f"{n}.Q", f"{n}_Q1.u1"),
                  (f"{n}_orifice.Q", f"{n}_Q1.u2"), (f"{n}.Q", f"{n}_Q2.u1"), (f"{n}_orifice.Q", f"{n}_Q2.u2")],
        flow={"P1": f"{n}_Q1.y", "P2": f"{n}_Q2.y"},  # Hopsan's flows out of the component: the two summed
    )


def _pilot_check_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Restrictors/HydraulicPilotControlledCheckValve.hpp: open while p_1 + φ p_pilot - p_2
    > p_f, then q = K_s √(p_1 - p_2) both ways, the pilot taking no flow: a PilotCheckValve with option opening =
    "seat", r_p = φ, its bore from K_s as the check valve's. HydraulicPilotClosableCheckValve.hpp: open while
    p_1 > p_2 + p_pilot, r_p = -1 and p_f = 0. Hopsan's conditions read absolute pressures: in hydroservo's gauge
    pressures the cracking pressure is p_f - r_p p_atm (the atmosphere once on each side of the drop cancels)."""
    from hydroservo.components import PilotCheckValve

    if hc.typename == "HydraulicPilotClosableCheckValve":
        phi, p_f = -1.0, 0.0
    else:
        phi, p_f = par("phi", 3.5), par("p_f", 1e5)
    comp = PilotCheckValve(n, opening="seat", p_crack=p_f - phi * 101325.0, r_p=phi, **_check_bore(par("K_s", 5e-7)))
    # Hopsan's output x (1 open, 0 closed) is the valve's s: not aliased
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P_PILOT": f"{n}.X"})


def _directional_check_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/DirectionalValves/Hydraulic22DirectionalCheckValve.hpp: an on/off spool (the
    second-order filter of the 4/3 valve's, driven to 1 while ``in`` > 0.5 and to 0 otherwise, limited to [0, 1],
    starting at ``out``); while it is above 0.5 the valve passes Kv_open √|p_1 - p_2| both ways, otherwise it
    checks: Kv_check √(p_1 - p_2) once p_1 - p_2 exceeds F_s (a seat that opens fully there), none back. A
    CheckValve with ``opening = "seat"``, p_crack = F_s and ``pilot = "open"``, its bores from Kv_check and
    Kv_open (K = C_d A √(2/ρ), C_d 0.67, ρ 870 kg/m³: only the product matters), turbulent to some 50 Pa
    (lambda_crit 10), its pilot the spool's position (SpoolSecondOrder with a stroke of 1 m: x_v is the fraction;
    delta_h < 1 refused, as the other on/off valves'). Output ``out``: the spool's position."""
    from hydroservo.components import CheckValve, Gain

    k_open, k_check = par("Kv_open", 5e-7), par("Kv_check", 5e-7)
    if k_open <= 0.0 or k_check <= 0.0:
        par.problems.append(f"{par.where}: Kv_open = {k_open:g}, Kv_check = {k_check:g}; only values above 0 are supported")
        return Mapped()
    spool = _spool(n, par, 1.0, "on-off", par("out", 0.0))  # Hopsan's filter starts at out (not at its input)
    pilot = Gain(f"{n}_pilot", input_unit="m", K="1 1/m")  # the spool's position as the fraction of its stroke
    valve = CheckValve(n, opening="seat", pilot="open", p_crack=par("F_s", 0.0), d_open=_check_bore(k_open)["d"],
                       **_check_bore(k_check))
    return Mapped(
        [*spool.components, pilot, valve],
        power={"P1": f"{n}.A", "P2": f"{n}.B"},
        inputs=spool.inputs,
        outputs={"out": f"{n}_pilot.y"},
        initial=spool.initial,
        internal=[*spool.internal, (f"{n}_spool.xv", f"{n}_pilot.u"), (f"{n}_pilot.y", f"{n}.open")],
        note="a Selector (open while in > 0.5), a SpoolSecondOrder, a Gain and a CheckValve (pilot = open)",
    )


# -- Hopsan's orifices with geometric parameters, its poppet and 3/3 shuttle valves ---------------------------


def _geometric_orifice_inputs(par: _Params, names: tuple[str, ...]) -> bool:
    """Whether the parameters ``names`` of a geometric orifice are all above 0 (a problem noted for each that is
    not: Hopsan's law divides by them)."""
    bad = [f"{name} = {par(name, 1.0):g}" for name in names if not par(name, 1.0) > 0.0]
    if bad:
        par.problems.append(f"{par.where}: {', '.join(bad)}; only values above 0 are supported")
    return not bad


def _orifice_g(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Restrictors/HydraulicOrificeG.hpp (ports P1, P2) and
    Hydraulic/Special/HydraulicOrificeCheckValveG.hpp (ports Pp, Pc): Hopsan's equation, solved by Newton
    iterations each step, is the algebraic flow q = 2 Δp/√((C_dt² L² μ² + 2 δ⁴ d_h⁴ ρ|Δp|)/(A_o² C_dt² δ⁴ d_h⁴))
    with L = d_h + 32 δ² l_o (3 - s_f), i.e. Δp/√(R_lam² + R_turb²): the laminar resistance L μ/(2 A_o δ² d_h²)
    and the turbulent √(ρ|Δp|/2)/(C_dt A_o) added in quadrature. An Orifice with ``law = "blend"`` (n_blend = 2),
    k_lam = 2 δ² d_h²/(L μ), its bore of area A_o, C_d = C_dt. The check valve's law is the same with s_f = 0
    and the area A_b for flow from Pp to Pc, A_o back (``d_back``); its dhb enters no equation of Hopsan's. The
    outputs Ro, DRL and Cd (Reynolds number, discharge coefficient) are not aliased."""
    from hydroservo.components import Orifice

    check = hc.typename == "HydraulicOrificeCheckValveG"
    d_h, ell = par("dh", 0.3 if check else 0.0025), par("lo", 0.001)
    delta, mu = par("del", 0.02 if check else 0.157), par("visc", 0.12)
    a_o, c_d = par("Ao", 0.0003 if check else 1e-7), par("Cdt", 0.67 if check else 0.611)
    a_b = par("Ab", 0.0001)
    shape = 0.0 if check else par("sf", 0.0)
    names = ("Ao", "Ab", "dh", "del", "visc", "Cdt") if check else ("Ao", "dh", "del", "visc", "Cdt")
    big_l = d_h + 32.0 * delta**2 * ell * (3.0 - shape)
    ok = _geometric_orifice_inputs(par, names)
    if c_d > 1.0:
        par.problems.append(f"{par.where}: Cdt = {c_d:g}; a discharge coefficient in (0, 1] is supported")
        ok = False
    if big_l <= 0.0:
        par.problems.append(f"{par.where}: dh + 32 del^2 lo (3 - sf) = {big_l:g} m is not above 0")
        ok = False
    if not ok:
        return Mapped()
    bore = math.sqrt(4.0 * (a_b if check else a_o) / math.pi)
    comp = Orifice(
        n,
        law="blend",
        d=bore,
        d_back=math.sqrt(4.0 * a_o / math.pi) if check else 0.0,
        Cd=c_d,
        rho=par("rho", 870.0),
        k_lam=2.0 * delta**2 * d_h**2 / (big_l * mu),
        n_blend=2.0,
    )
    ports = ("Pp", "Pc") if check else ("P1", "P2")
    return Mapped([comp], power={ports[0]: f"{n}.A", ports[1]: f"{n}.B"})


def _slit_orifice(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicSlitOrifice.hpp: Hopsan's equation, solved by Newton iterations
    each step, is the algebraic flow q = 8 Δp/((1024 A_o⁸ δ⁸ Δp² ρ² + C_d⁴ μ⁴ S_o⁴ M²)/(A_o¹² C_d⁴ δ⁸))^(1/4)
    with M = A_o² + 64 δ⁴ l_o² (3 - s_f)² S_o² (its sum of three terms in μ⁴ is S_o⁴ M²), i.e.
    Δp/(R_lam⁴ + R_turb⁴)^(1/4): the laminar resistance μ S_o √M/(8 A_o³ δ²) and the turbulent √(ρ|Δp|/2)/(C_d A_o)
    added as a 4-norm. An Orifice with ``law = "blend"``, n_blend = 4, k_lam = 8 A_o² δ²/(μ S_o √M), its bore of
    area A_o. The height b enters only Hopsan's output DRL; the outputs Ro, DRL and Cde are not aliased."""
    from hydroservo.components import Orifice

    a_o, s_o, ell = par("Ao", 1e-7), par("So", 0.002), par("lo", 0.001)
    delta, mu, c_d = par("del", 0.157), par("visc", 0.12), par("Cd", 0.611)
    if not _geometric_orifice_inputs(par, ("Ao", "So", "del", "visc", "Cd")):
        return Mapped()
    if c_d > 1.0:
        par.problems.append(f"{par.where}: Cd = {c_d:g}; a discharge coefficient in (0, 1] is supported")
        return Mapped()
    big_m = a_o**2 + 64.0 * delta**4 * ell**2 * (3.0 - par("sf", 0.0)) ** 2 * s_o**2
    comp = Orifice(
        n,
        law="blend",
        d=math.sqrt(4.0 * a_o / math.pi),
        Cd=c_d,
        rho=par("rho", 870.0),
        k_lam=8.0 * a_o**2 * delta**2 / (mu * s_o * math.sqrt(big_m)),
        n_blend=4.0,
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"})


def _poppet_valve(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/Hydraulic22PoppetValve.hpp: a massless poppet x in [0, x_vmax] (its limited
    integrator, starting at xv_out) whose seat opens PS to PN as C_q π d_1 f x √(2/ρ) √Δp, pushed open by p_N on
    A_N = π d_1²/4 and p_S on A_S = π d_2²/4 - A_N, held by its spring F_0 + k x; its spring chamber (A_C = π d_2²/4)
    at p_c = (A_N p_N + A_S p_S - F_0 - k x)/A_C drains to PC through the damping orifice d_d,
    q_C = C_q π d_d²/4 √(2/ρ) √(p_c - p_C), and A_C ẋ = q_C. A SpoolOrificeDamped ``{n}_poppet`` (its ports 1 and 2
    on PN and PS, C on PC; the orifice's law regularised below 100 Pa) and a TwoWayValve ``{n}`` (PS its A, PN its
    B, x_AB = 0, turbulent to some 40 Pa as Hopsan's other valves). A_N + A_S = A_C, so the atmosphere cancels in
    the poppet's balance. Output xv_out the poppet's position. x_vmax or d_d not above 0 refused."""
    from hydroservo.components import SpoolOrificeDamped, TwoWayValve

    rho, c_q = par("rho", 870.0), par("C_q", 0.67)
    d_1, d_2, x_vmax, d_d = par("d_1", 10e-3), par("d_2", 10e-3), par("x_vmax", 0.01), par("d_d", 0.1e-3)
    if not (x_vmax > 0.0 and d_d > 0.0 and d_2 > 0.0 and rho > 0.0):
        par.problems.append(f"{par.where}: x_vmax = {x_vmax:g} m, d_d = {d_d:g} m, d_2 = {d_2:g} m, rho = {rho:g} "
                            "kg/m^3; only values above 0 are supported")
        return Mapped()
    a_n, a_c = math.pi * d_1**2 / 4.0, math.pi * d_2**2 / 4.0
    poppet = SpoolOrificeDamped(
        f"{n}_poppet", A_1=a_n, A_2=a_c - a_n, A_c=a_c, F_0=par("F_0", 100.0), k_s=par("k", 1e4),
        K_d=c_q * math.pi * d_d**2 / 4.0 * math.sqrt(2.0 / rho), x_min=0.0, x_max=x_vmax,
        x0=min(max(par("xv_out", 0.0), 0.0), x_vmax),
    )
    valve = TwoWayValve(n, c_v=_edge_coefficient(par, par("f", 1.0), rho, d="d_1"), x_AB=0.0, rho=rho, D_h="1 mm",
                        lambda_crit=10.0)
    return Mapped(
        [poppet, valve],
        power={"PS": f"{n}.A", "PN": f"{n}.B", "PC": f"{n}_poppet.C"},
        outputs={"xv_out": f"{n}_poppet.xv"},
        internal=[(f"{n}.B", f"{n}_poppet.P1"), (f"{n}.A", f"{n}_poppet.P2"), (f"{n}_poppet.xv", f"{n}.xv")],
        note="a SpoolOrificeDamped (the poppet) and a TwoWayValve (its seat)",
    )


def _shuttle_valve33(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Valves/Hydraulic33ShuttleValve.hpp: a massless spool x_v in [-x_vmax, x_vmax]
    (starting at xv_out) between two end chambers, fed from PP through the damping orifice d_1 and drained to PT
    through d_2 (K_i = C_q π d_i²/4 √(2/ρ)): the chambers at p = (K_1² p_P + K_2² p_T)/(K_1² + K_2²), where the
    two flows are equal, and A ẋ_v = K_1 √(p_P - p), A = π d²/4: the two orifices in series, K_1 K_2/√(K_1² + K_2²)
    √(p_P - p_T). Its edges P-A open as -x_v - x_pa and A-T as x_v - x_at, C_q f π d √(2/ρ) wide. A
    SpoolOrificeDamped ``{n}_spool`` (A_1 = A_c = A, port 1 on PP, C on PT, ``damping_flow = "none"``: Hopsan counts
    the chambers' oil at no port), a Gain of -1 and a ThreeWayValve ``{n}`` on -x_v (its P-A opening as
    -x_v - x_pa, A-T as x_v - x_at; turbulent to some 40 Pa). Hopsan reads the previous step's pressures for the
    spool, the same as the step vanishes. Output xv_out the spool's position. x_vmax, d_1, d_2 or d not above 0
    refused."""
    from hydroservo.components import Gain, SpoolOrificeDamped, ThreeWayValve

    rho, c_q, d = par("rho", 870.0), par("C_q", 0.67), par("d", 0.01)
    x_vmax, d_1, d_2 = par("x_vmax", 0.01), par("d_1", 1e-3), par("d_2", 1e-3)
    if not (x_vmax > 0.0 and d_1 > 0.0 and d_2 > 0.0 and d > 0.0 and rho > 0.0):
        par.problems.append(f"{par.where}: x_vmax = {x_vmax:g} m, d_1 = {d_1:g} m, d_2 = {d_2:g} m, d = {d:g} m, "
                            f"rho = {rho:g} kg/m^3; only values above 0 are supported")
        return Mapped()
    k_1, k_2 = (c_q * math.pi * di**2 / 4.0 * math.sqrt(2.0 / rho) for di in (d_1, d_2))
    area = math.pi * d**2 / 4.0
    spool = SpoolOrificeDamped(
        f"{n}_spool", damping_flow="none", A_1=area, A_2=0.0, A_c=area, F_0=0.0, k_s=0.0,
        K_d=k_1 * k_2 / math.sqrt(k_1**2 + k_2**2), x_min=-x_vmax, x_max=x_vmax,
        x0=min(max(par("xv_out", 0.0), -x_vmax), x_vmax),
    )
    flip = Gain(f"{n}_flip", unit="m", input_unit="m", K=-1.0)
    valve = ThreeWayValve(
        n, c_PA=_edge_coefficient(par, par("f_pa", 1.0), rho), c_AT=_edge_coefficient(par, par("f_at", 1.0), rho),
        x_PA=par("x_pa", -1e-6), x_AT=par("x_at", -1e-6), rho=rho, D_h="1 mm", lambda_crit=10.0,
    )
    return Mapped(
        [spool, flip, valve],
        power={"PP": f"{n}.P", "PT": f"{n}.T", "PA": f"{n}.A"},
        outputs={"xv_out": f"{n}_spool.xv"},
        internal=[(f"{n}.P", f"{n}_spool.P1"), (f"{n}.T", f"{n}_spool.C"), (f"{n}_spool.xv", f"{n}_flip.u"),
                  (f"{n}_flip.y", f"{n}.xv")],
        note="a SpoolOrificeDamped (damping_flow = none), a Gain of -1 and a ThreeWayValve",
    )


def _special_four_way(n: str, par: _Params, overlap: bool, sd: float = 0.01, lap: float = 0.0) -> Mapped:
    """The four edges of Hopsan's Special 4/3 valves (HydraulicValve43, HydraulicValve43LS, HydraulicValve63OC)
    as a FourWayValve behind a Saturation of the spool position xv [m] to ±Xvmax: edge conductances
    Ks π Fr Sd times P-A's limit(±Xap0 + xv, 0, ±Xap0 + Xvmax), A-T's limit(±Xap0 - xv, 0, ±Xat0 + Xvmax), P-B's
    limit(±Xap0 - xv, 0, ±Xbp0 + Xvmax) and B-T's limit(±Xap0 + xv, 0, ±Xbt0 + Xvmax) (+ for HydraulicValve43,
    whose Xap0 is an underlap: laps -Xap0; - with ``overlap``: laps +Xap0), Ks = Cq √(2/ρ), the flows
    Ks·signedSquareL(Δp, plam) = Ks Δp/(Δp² + plam²)^(1/4) (their equation systems, solved by Newton iterations
    each step, stand for these algebraic flows): the transition pressure plam exactly (D_h chosen so), the
    saturated xv the openings' upper limits. Every edge opens from Xap0 (Xat0, Xbp0, Xbt0 only bound them): one of
    them different from Xap0 is refused, as are unequal fractions Frap ... Frbt (one c_v). ``sd`` and ``lap``: the
    component file's defaults of Sd and of the laps."""
    from hydroservo.components import FourWayValve, Saturation

    rho = par("rho", 870.0)
    x0, x_vmax, plam = par("Xap0", lap), par("Xvmax", 0.01), par("plam", 1e4)
    others = [f"{name} = {par(name, lap):g} m" for name in ("Xat0", "Xbp0", "Xbt0") if par(name, lap) != x0]
    if others:
        par.problems.append(
            f"{par.where}: {', '.join(others)} differ from Xap0 = {x0:g} m: Hopsan's edges all open from Xap0, with "
            "their limits at X..0 + Xvmax, which a FourWayValve of one lap per edge does not have"
        )
    if plam <= 0.0 or x_vmax <= 0.0:
        par.problems.append(f"{par.where}: plam = {plam:g} Pa, Xvmax = {x_vmax:g} m; only values above 0 are supported")
        plam, x_vmax = 1e4, 0.01
    edges = _valve33_edges(par, rho, x0, plam)
    fraction = _equal_fractions(par, ("Frap", "Frat", "Frbp", "Frbt"))
    c_v = par("Cq", 0.67) * fraction * math.pi * par("Sd", sd) * math.sqrt(2.0 / rho)
    x_lap = x0 if overlap else -x0
    valve = FourWayValve(
        n, c_v=c_v, xv_max=x_vmax, x_PA=x_lap, x_AT=x_lap, x_PB=x_lap, x_BT=x_lap,
        **{k: edges[k] for k in ("rho", "nu", "lambda_crit", "D_h")},
    )
    limit = Saturation(f"{n}_xv", unit="m", lower=-x_vmax, upper=x_vmax)
    return Mapped(
        [limit, valve],
        power={"Pp": f"{n}.P", "Pt": f"{n}.T", "Pa": f"{n}.A", "Pb": f"{n}.B"},
        inputs={"xv": f"{n}_xv.u"},
        internal=[(f"{n}_xv.y", f"{n}.xv")],
        note="a Saturation (xv limited to ±Xvmax) and a FourWayValve",
    )


def _valve43_special(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicValve43.hpp: HydraulicValve33's law with port B, a 4/3 valve whose
    spool position xv [m] is its input (no spool dynamics): its edges open from the underlap Xap0
    (:func:`_special_four_way`: a Saturation and a FourWayValve of laps -Xap0). The flow-force outputs ffpa, ffta,
    ffpb, fftb, ff are not aliased."""
    return _special_four_way(n, par, overlap=False)


def _valve63_open_centre(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicValve63OC.hpp: a 6/3 open-centre valve whose spool position xv [m]
    is its input: four edges opening past the overlap Xap0 (:func:`_special_four_way`, laps +Xap0) and an
    open-centre edge from Pocp to Poct of conductance Ks π Froc Sd limit(Xoc0 - |xv|, 0, Xoc0), turbulent with the
    onset plam as the others: an Absolute of xv (the input's, unsaturated, as Hopsan's; a Gain of 1 ``{n}_in``
    takes the input to both) and a Gain of -1 into a TwoWayValve ``{n}_centre`` of overlap -Xoc0, whose opening
    Xoc0 - |xv| is never above Xoc0 (its own clamp at 0 is Hopsan's lower limit). Xoc0 < 0 is refused."""
    from hydroservo.components import Absolute, Gain, TwoWayValve

    m = _special_four_way(n, par, overlap=True, sd=0.015)
    rho, x_oc, plam = par("rho", 870.0), par("Xoc0", 0.0), max(par("plam", 1e4), 1.0)
    if x_oc < 0.0:
        par.problems.append(f"{par.where}: Xoc0 = {x_oc:g} m; an open-centre underlap of 0 or more is supported")
    edges = _valve33_edges(par, rho, 0.0, plam)
    centre = TwoWayValve(
        f"{n}_centre", c_v=par("Cq", 0.67) * par("Froc", 1.0) * math.pi * par("Sd", 0.015) * math.sqrt(2.0 / rho),
        x_AB=-x_oc,
        **{k: edges[k] for k in ("rho", "nu", "lambda_crit", "D_h")},
    )
    entry = Gain(f"{n}_in", unit="m", input_unit="m", K=1.0)
    m.components += [entry, Absolute(f"{n}_abs", unit="m"), Gain(f"{n}_flip", unit="m", input_unit="m", K=-1.0), centre]
    m.inputs = {"xv": f"{n}_in.u"}
    m.power.update({"Pocp": f"{n}_centre.A", "Poct": f"{n}_centre.B"})
    m.internal += [(f"{n}_in.y", f"{n}_xv.u"), (f"{n}_in.y", f"{n}_abs.u"), (f"{n}_abs.y", f"{n}_flip.u"),
                   (f"{n}_flip.y", f"{n}_centre.xv")]
    m.note += "; the centre edge Pocp-Poct: an Absolute and a Gain (its opening from xv) and a TwoWayValve"
    return m


def _valve43_ls(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicValve43LS.hpp: a 4/3 valve whose spool position xv [m] is its input,
    its edges opening past the overlap Xap0 (:func:`_special_four_way`, laps +Xap0), with a load-sensing port Pls
    joined to A, B and T by three more edges of conductance Ks wls times LS-A's limit(xv - Xlsa0, 0,
    Xvlsmax - Xlsa0), LS-B's limit(-xv - Xlsb0, 0, Xvlsmax - Xlsb0) and LS-T's limit(Xls0 - |xv|, 0, Xls0),
    turbulent with the onset plam. Hopsan takes their flow at Pls only: A, B and T see none of it (their flows are
    the four main edges'). Here the LS edges run between Pls and three PressureSources ``{n}_mirror_a``, ``_b``,
    ``_t`` that hold the pressures of A, B and T (each read by a Sum ``{n}_p<port>``, absolute, as a sensor reads
    its node), so that their oil comes from and goes to no node, as Hopsan's: a ThreeWayValve ``{n}_ls`` (its P on
    A's mirror, A on Pls, T on B's mirror; xv limited to ±Xvlsmax by a Saturation ``{n}_xls``) and a TwoWayValve
    ``{n}_lst`` (Pls to T's mirror, on -|xv|, overlap -Xls0); Pls's flow is their sum, a Sum ``{n}_Qls``. A Gain
    of 1 ``{n}_in`` takes the input to the three. Xvlsmax, wls or Xls0 below 0 are refused."""
    from hydroservo.components import Absolute, Gain, PressureSource, Saturation, Sum, ThreeWayValve, TwoWayValve

    m = _special_four_way(n, par, overlap=True, lap=0.0003)
    rho, plam = par("rho", 870.0), max(par("plam", 1e4), 1.0)
    x_lsmax, w_ls, x_ls0 = par("Xvlsmax", 0.001), par("wls", 0.01), par("Xls0", 0.0003)
    if x_lsmax <= 0.0 or w_ls < 0.0 or x_ls0 < 0.0:
        par.problems.append(f"{par.where}: Xvlsmax = {x_lsmax:g} m, wls = {w_ls:g} m, Xls0 = {x_ls0:g} m; only "
                            "Xvlsmax above 0 and wls, Xls0 of 0 or more are supported")
        x_lsmax = 0.001
    fluid = {k: v for k, v in _valve33_edges(par, rho, 0.0, plam).items() if k in ("rho", "nu", "lambda_crit", "D_h")}
    c_ls = par("Cq", 0.67) * w_ls * math.sqrt(2.0 / rho)
    blocks: list[cbase.Component] = [Gain(f"{n}_in", unit="m", input_unit="m", K=1.0)]
    internal = [(f"{n}_in.y", f"{n}_xv.u")]
    read: dict[str, tuple[str, str]] = {}
    for port in ("a", "b", "t"):
        blocks += [Sum(f"{n}_p{port}", unit="Pa", gain2=0.0), PressureSource(f"{n}_mirror_{port}", p0="0 Pa_abs")]
        internal.append((f"{n}_p{port}.y", f"{n}_mirror_{port}.u"))
        read[f"P{port}"] = (f"{n}_p{port}.u1", "Pressure")
    blocks += [
        Saturation(f"{n}_xls", unit="m", lower=-x_lsmax, upper=x_lsmax),
        ThreeWayValve(f"{n}_ls", c_PA=c_ls, c_AT=c_ls, x_PA=par("Xlsa0", 0.0003), x_AT=par("Xlsb0", 0.0003), **fluid),
        Absolute(f"{n}_abs", unit="m"),
        Gain(f"{n}_flip", unit="m", input_unit="m", K=-1.0),
        TwoWayValve(f"{n}_lst", c_v=c_ls, x_AB=-x_ls0, **fluid),
        Sum(f"{n}_Qls", unit="m^3/s", gain1=1.0, gain2=-1.0),
    ]
    internal += [
        (f"{n}_in.y", f"{n}_xls.u"), (f"{n}_xls.y", f"{n}_ls.xv"), (f"{n}_mirror_a.P", f"{n}_ls.P"),
        (f"{n}_mirror_b.P", f"{n}_ls.T"), (f"{n}_in.y", f"{n}_abs.u"), (f"{n}_abs.y", f"{n}_flip.u"),
        (f"{n}_flip.y", f"{n}_lst.xv"), (f"{n}_ls.A", f"{n}_lst.A"), (f"{n}_mirror_t.P", f"{n}_lst.B"),
        (f"{n}_ls.QA", f"{n}_Qls.u1"), (f"{n}_lst.Q", f"{n}_Qls.u2"),
    ]
    m.components += blocks
    m.inputs = {"xv": f"{n}_in.u"}
    m.power["Pls"] = f"{n}_ls.A"
    m.read = read
    m.flow["Pls"] = f"{n}_Qls.y"  # Hopsan's flow out of the valve at Pls: the LS edges' to A and B less LS-T's
    m.internal += internal
    m.note += ("; the load-sensing edges: a ThreeWayValve (LS-A, LS-B) and a TwoWayValve (LS-T) between Pls and "
               "PressureSources holding A's, B's and T's pressures (read by Sums)")
    return m


def _motor_jload(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicMotorJload.hpp: a Q-type motor of displacement Dm per revolution
    with its inertia Jm: its equation system (the bilinear transform of Jm θ'' = Dm/2π (p_1 - p_2) - Bm θ' - T_m1,
    solved with its ports' and shaft's TLM equations) stands for that law, and the flow out of P2
    Dm/2π θ' + Cim (p_1 - p_2). A Motor (D = Dm per revolution, C_im = Cim, B_m = Bm, J = Jm; no external leakage)
    whose shaft is Pm1, starting at its node's start angle and speed as Hopsan's integrators. Unlike Hopsan's
    Pumps&Motors motors it does not clamp its flow (its ports' pressures are only floored at 0 Pa absolute, the
    volumes' cavity law): option inlet = "free". Jm not above 0 refused."""
    from hydroservo.components import Motor

    j_m = par("Jm", 0.1)
    if j_m <= 0.0:
        par.problems.append(f"{par.where}: Jm = {j_m:g}; only an inertia above 0 is supported")
        return Mapped()
    comp = Motor(
        n, D=f"{par('Dm', 5e-5)!r} m^3/rev", C_im=par("Cim", 0.0), B_m=par("Bm", 0.0), J=j_m,
        theta0=par.start("Pm1", "Angle", 0.0), omega0=par.start("Pm1", "AngularVelocity", 0.0),
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "Pm1": f"{n}.shaft"})


def _piston(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicPiston.hpp: a C-type piston without mass, friction, leakage or end
    stops: its chambers transmission-line volumes V1 = V01 + A1 limit(-x, 0, SL) and V2 = V02 + A2 limit(SL + x,
    0, SL) (x the position of Pm1, Zc = betae Ts/((1 - alpha) V), their waves filtered by alpha as a
    HydraulicVolume's: the volume V in the limit of a vanishing step), the force wave A1 c_1 - A2 c_2 at Pm1 (its
    impedance A1² Zc1 + A2² Zc2). HydraulicCylinderC's law without B_p, leakage and stops: a Cylinder with V_A0 =
    V01, V_B0 = V02 + A2 SL, beta_e = betae, no stops, the chambers' cavity law at 0 Pa absolute, absolute
    pressures on the piston (p_amb 0 Pa_abs), starting at its ports' start pressures; alpha (a numerical filter)
    has no continuous counterpart. Outside [0, SL] Hopsan's chamber volumes stop changing, the Cylinder's do not:
    the cylinder's travel check flags a piston driven there. A1, A2, V01, V02, SL or betae not above 0 refused."""
    from hydroservo.components import Cylinder

    a1, a2, sl = par("A1", 0.001), par("A2", 0.001), par("SL", 0.5)
    v1, v2, beta = par("V01", 0.001), par("V02", 0.001), par("betae", 1.7e7)
    bad = [f"{k} = {val:g}" for k, val in (("A1", a1), ("A2", a2), ("SL", sl), ("V01", v1), ("V02", v2),
                                          ("betae", beta)) if not val > 0.0]
    if bad:
        par.problems.append(f"{par.where}: {', '.join(bad)}; only values above 0 are supported")
        return Mapped()
    comp = Cylinder(
        n, A_A=a1, A_B=a2, V_A0=v1, V_B0=v2 + a2 * sl, beta_e=beta, B_p=0.0, C_Li=0.0, x_min=0.0, x_max=sl,
        k_stop=0.0, c_stop=0.0, pressure_floor="cavity-ports", p_floor="0 Pa_abs", p_amb="0 Pa_abs",
        pA0=_abs(par.start("P1", "Pressure", 1e5)), pB0=_abs(par.start("P2", "Pressure", 1e5)),
    )
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "Pm1": f"{n}.R"})


def _fuel_tank(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/FuelComponents/HydraulicFuelTankG.hpp: a C component of wave variable
    (p0 + gx hx ρ)·[massfuel > 0] and no impedance, hx = hf massfuel/massfuelmax, massfuel = massfuel0 - consfuel,
    consfuel the trapezoidal integral of -ρ q_T (the flow out) limited to [0, massfuel0 + 1e-4] (its memory with
    it): a HeadTank (p0 absolute, rho = rhofuel, g = gx, h_full = hf, m_full = massfuelmax, m0 = massfuel0, the
    mass within [-1e-4 kg, massfuel0] as Hopsan's limit, vacuum when empty). Outputs massfuel and consfuel the
    tank's mass and m_used. massfuelmax or rhofuel not above 0, or massfuel0 below 0, refused."""
    from hydroservo.components import HeadTank

    rho, m_full, m0 = par("rhofuel", 700.0), par("massfuelmax", 1000.0), par("massfuel0", 1000.0)
    if not (rho > 0.0 and m_full > 0.0 and m0 >= 0.0):
        par.problems.append(f"{par.where}: rhofuel = {rho:g} kg/m^3, massfuelmax = {m_full:g} kg, massfuel0 = {m0:g} "
                            "kg; only rhofuel, massfuelmax above 0 and massfuel0 of 0 or more are supported")
        return Mapped()
    comp = HeadTank(
        n, p0=_abs(par("p0", 1e5)), rho=rho, g=par("gx", 9.82), h_full=par("hf", 5.0), m_full=m_full, m0=m0,
        m_min=-1e-4, m_max=max(m0, 1e-4), p_vac=_abs(0.0),
    )
    return Mapped([comp], power={"PT": f"{n}.P"}, outputs={"massfuel": f"{n}.mass", "consfuel": f"{n}.m_used"})


def _pressure_controlled_pump_g(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Special/HydraulicPressureControlledPumpG.hpp: a Q-type pump (P1 suction, P2 outlet,
    P3 its reference, read without flow) whose regulator filters the error u = pdif - (p_2 - p_3) into the rate of
    its displacement flow, dqp = s (1 + s/ω_p1e)/((L_pe s + R_pe)(τ_v s + 1)) u (bilinear, solved with its ports'
    TLM equations; L_pe, R_pe = Lp, Rp times f = speednom √(pnom/p_2)/speed, ω_p1e = wp1 speed/speednom), dqp
    within ±(1 - epsmin) Dp speed/2π √(p_2/pnom)/Tp, Tm and qp, its trapezoidal integral, within [epsmin, 1] Dp
    speed/2π, each clamped with its memory; the flow at P2 qp - Kcp (p_2 - p_1). A LoadSensingPump with
    ``regulator = "g"`` (D = Dp per revolution, omega = speed, C_leak = Kcp, p_dif = pdif, l_p = Lp, R_p = Rp,
    omega_p1 = wp1, tau_v = tauv, t_p = Tp, t_m = Tm, eps_min = epsmin, p_nom = pnom, omega_nom = speednom; no flow
    clamp: its ports are only floored at 0 Pa absolute, the volumes' cavity law), starting at rest at the start
    value of qp (dqp's taken as 0). Its bilinear transform divides each step's terms by that step's f: the filter
    acts on u/f (class notes of LoadSensingPump). Outputs qp and eps = qp/(Dp speed/2π); dqp is not aliased; qmin
    and rho enter none of Hopsan's equations. A speed driven by a signal is refused (the regulator takes a constant
    speed); values Hopsan divides by not above 0 and epsmin outside [0, 1] are refused."""
    from hydroservo.components import LoadSensingPump

    values = {k: par(k, d) for k, d in (("speed", 157.0), ("Dp", 3e-4), ("pnom", 7e6), ("speednom", 157.0),
                                         ("tauv", 0.05), ("Tp", 0.001), ("Tm", 0.001), ("Lp", 1.83e10),
                                         ("wp1", 13.3))}
    bad = [f"{k} = {v:g}" for k, v in values.items() if not v > 0.0]
    eps_min = par("epsmin", 0.0)
    if not 0.0 <= eps_min <= 1.0:
        bad.append(f"epsmin = {eps_min:g}")
    if bad:
        par.problems.append(f"{par.where}: {', '.join(bad)}; only values above 0 and epsmin in [0, 1] are supported")
        return Mapped()
    speed = values["speed"]
    comp = LoadSensingPump(
        n, regulator="g", D=f"{values['Dp']!r} m^3/rev", omega=speed, C_leak=par("Kcp", 1e-12), p_dif=par("pdif", 2e7),
        l_p=values["Lp"], R_p=par("Rp", 1.68e10), omega_p1=values["wp1"], tau_v=values["tauv"], t_p=values["Tp"],
        t_m=values["Tm"], eps_min=eps_min, p_nom=values["pnom"], omega_nom=values["speednom"],
    )
    q_max = comp.values["D"] * speed
    q0 = min(max(par("qp", 0.0), eps_min * q_max), q_max)
    p2 = max(par.start("P2", "Pressure", 1e5), 0.0)
    u0 = par("pdif", 2e7) - p2 + max(par.start("P3", "Pressure", 1e5), 0.0)
    big_u0 = math.sqrt(max(p2, 1.0) / values["pnom"]) * max(speed, 0.1) / values["speednom"] * u0
    return Mapped(
        [comp],
        power={"P1": f"{n}.S", "P2": f"{n}.P", "P3": f"{n}.X"},
        values={"qp": Var(1.0, f"{n}.eps", text=f"{n}.D*{n}.omega*{n}.eps", unit="m^3/s"), "eps": Var(1.0, f"{n}.eps")},
        initial={f"{n}.q": q0, f"{n}.wu": big_u0, f"{n}.wh": big_u0},
    )


def _variable_pump(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Pump

    comp = Pump(n, D=f"{par('D_p', 5e-5)!r} m^3/rev", omega=par("omega_p", 50.0), C_leak=par("K_cp", 1e-12),
                inlet="floor", p_floor=_abs(0.0))
    return Mapped([comp], power={"P1": f"{n}.S", "P2": f"{n}.P"}, inputs={"eps": f"{n}.eps"})


def _pressure_controlled_pump(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Pumps&Motors/HydraulicPressureControlledPump.hpp: a Q-type variable pump whose
    regulator (a limited second-order filter with a lead, of the pressure error p_dif - (p_2 - p_ref)) sets the
    displacement flow: a LoadSensingPump (its law in the limit of a vanishing step, the TLM impedances gone),
    D ω = q_max ω/125 (q_max at Hopsan's nominal 125 rad/s), ε_min = q_min/q_max, port X on PREF (no flow),
    inlet floored at 0 Pa absolute as Hopsan's other pumps. The filter starts at rest at Hopsan's start value of
    eps (its displacement flow q_max ε), its error's lag at the error of the start pressures of its nodes. Output eps (Hopsan's: the
    delivered flow over q_max ω/125) is the pump's QP scaled; the angle a is not mapped. A PREF left unconnected
    and speeds or q_max not above 0 are refused."""
    from hydroservo.components import LoadSensingPump

    omega, q_max, q_min = par("omega_p", 125.0), par("q_max", 0.00125), par("q_min", 0.0)
    if omega <= 0.0 or q_max <= 0.0 or not 0.0 <= q_min <= q_max:
        par.problems.append(f"{par.where}: omega_p = {omega:g} rad/s, q_max = {q_max:g} m^3/s, q_min = {q_min:g} "
                            "m^3/s; only omega_p and q_max above 0 and q_min in [0, q_max] are supported")
        return Mapped()
    if "PREF" not in par.driven:
        par.problems.append(f"{par.where}: its reference port PREF is not connected; connect it (a tank makes the "
                            "pump a pressure compensator at p_dif)")
    comp = LoadSensingPump(
        n,
        D=q_max / 125.0,
        omega=omega,
        C_leak=par("C_lp", 1e-12),
        p_dif=par("p_dif", 1e6),
        l_p=par("l_p", 7e7),
        R_p=par("r_p", 1e9),
        omega_p1=par("omega_p1", 200.0),
        tau_v=par("tao_v", 0.001),
        t_p=par("t_p", 0.15),
        t_m=par("t_m", 0.12),
        eps_min=q_min / q_max,
        inlet="floor",
        p_floor=_abs(0.0),
    )
    # Hopsan's initialize(): the filter at rest at q_2 = q_max ω/125 eps (eps's start value)
    p2 = max(par.start("P2", "Pressure", 1e5), 1.0)
    p_ref = max(par.start("PREF", "Pressure", 1e5), 0.0)
    v = comp.values
    ell = v["l_p"] * math.sqrt(v["p_nom"] / p2) * v["omega_nom"] / (omega + 0.001)
    big_l = ell + v["R_p"] * v["tau_v"]
    u0 = v["p_dif"] - p2 + p_ref
    eps0 = min(max(par("eps", 0.0), v["eps_min"]), 1.0)
    q_l = q_max * omega / 125.0
    return Mapped(
        [comp],
        power={"P1": f"{n}.S", "P2": f"{n}.P", "PREF": f"{n}.X"},
        values={"eps": Var(1.0, f"{n}.QP", text=f"{n}.QP/({n}.D*{n}.omega)", unit="")},
        initial={f"{n}.y": big_l * q_l * eps0, f"{n}.w": u0},
    )


# -- mechanic -------------------------------------------------------------------------------------------------


def _mass(hc: HopsanComponent, n: str, par: _Params, B: float | None = None, k_spring: float | None = None) -> Mapped:
    from hydroservo.components import Mass

    x_min, x_max = par("x_min", -1e300), par("x_max", 1e300)
    x1, x2 = par.start("P1", "Position"), par.start("P2", "Position")
    comp = Mass(
        n,
        m=par("m", 100.0),
        B=par("B", 10.0) if B is None else B,
        k_spring=par("k", 0.0) if k_spring is None else k_spring,
        incline=0.0,
        length=x1 + x2,  # Hopsan keeps the ends' start positions apart by this (its mLength)
        x0=x2,
        v0=par.start("P2", "Velocity"),
    )
    if abs(x_min) < 1e299 or abs(x_max) < 1e299:  # Hopsan's inelastic stops, as stiff ones
        comp.set(x_min=max(x_min, -1e30), x_max=min(x_max, 1e30), k_stop=1e9, c_stop=1e6)
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _mass_coulomb(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """MechanicTranslationalMassWithCoulombFriction.hpp: a mass that sticks while the force on it stays below
    f_s, and slides against f_k (and b v) once it moves; Hopsan stops it whenever its velocity would change sign.
    That law is the limit of the Stribeck law (laws.friction.stribeck) with F_c0 = f_k and F_s0 = f_s - f_k as
    its velocity scales vanish: here v_reg = 1e-5 m/s (a stuck mass creeps at v_reg atanh(F/f_s), under 3e-5 m/s
    below 0.99 f_s) and c_s = 1e-3 m/s (the friction falls from f_s to f_k over about 3 c_s). Not mapped: Hopsan's
    integrator (HopsanCore DoubleIntegratorWithDampingAndCoulombFriction) keeps the trapezoidal rule's memory of the
    last acceleration when the mass stops, so a mass that stopped while slowing under a net force F_stop breaks away
    again in its direction only above 2 f_k - F_stop where that exceeds f_s: an artefact, not a friction law."""
    f_s, f_k = par("f_s", 50.0), par("f_k", 45.0)
    if f_s < f_k or f_k < 0.0:
        par.problems.append(
            f"{par.where}: f_s = {f_s:g} N, f_k = {f_k:g} N: a static friction below the kinetic one (or a negative "
            "one) is not supported (Mass's friction falls from F_c0 + F_s0 at rest to F_c0)"
        )
        return Mapped()
    m = _mass(hc, n, par, B=par("b", 10.0), k_spring=0.0)
    m.components[0].set(F_c0=f_k, F_s0=f_s - f_k, v_reg=1e-5, c_s=1e-3)
    return m


def _shared_starts(par: _Params, ports: tuple[str, ...]) -> bool:
    """Whether each of a mechanical multiport's connections starts at the same position and velocity (hydroservo's
    one port has one; Hopsan keeps each connection's offset from the first): a problem is noted if not."""
    differ = [p for p in ports if STARTS_DIFFER in par.node_start.get(p, {})]
    if differ:
        par.problems.append(
            f"{par.where}: the connections to {', '.join(differ)} start at different positions or velocities; "
            "only connections that start together are supported (hydroservo's port has one position)"
        )
    return not differ


def _multiport_mass(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicMultiPortTranslationalMass.hpp and
    MechanicTranslationalMassWithCoulombFrictionAndMultiPorts.hpp: MechanicTranslationalMass's and
    MechanicTranslationalMassWithCoulombFriction's laws (:func:`_mass`, :func:`_mass_coulomb`; the multiport mass
    has no spring k) with multiports P1 and P2: Hopsan sums the wave variables and impedances of every connection
    to a port, that is the forces of all of them act on the mass, as on hydroservo's Mass whose port each joins.
    Hopsan writes each connection's position as its own start position plus the mass's travel; hydroservo's port
    has one, so connections that start at different positions or velocities are refused."""
    if not _shared_starts(par, ("P1", "P2")):
        return Mapped()
    if hc.typename == "MechanicTranslationalMassWithCoulombFrictionAndMultiPorts":
        return _mass_coulomb(hc, n, par)
    return _mass(hc, n, par, k_spring=0.0)


def _pulley(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicPulley.hpp: a movable pulley of mass m at P2 whose rope end is P1:
    x_1 = -2 x_2, v_1 = -2 v_2, and Hopsan's filter (m s² + (B + 4 Z_x1 + Z_x2) s) x_2 = 2 c_1 - c_2 is, with
    f_1 = c_1 + Z_x1 v_1 and f_2 = c_2 + Z_x2 v_2, the law m ẍ_2 = 2 f_1 - f_2 - B ẋ_2 (the rope's force
    doubled). MechanicTranslationalMassWithLever's law with P1 moving twice as far: a Mass with n_lever = 2, starting
    at minus half P1's start position and velocity, as Hopsan's filters. (Hopsan labels B "Nms/rad"; its law is
    N s/m.)"""
    from hydroservo.components import Mass

    if par("m", 1.0) <= 0.0:
        par.problems.append(f"{par.where}: m = {par('m', 1.0):g} kg; only a mass above 0 is supported")
        return Mapped()
    comp = Mass(
        n, m=par("m", 1.0), B=par("B", 10.0), incline=0.0, n_lever=2.0,
        x0=-0.5 * par.start("P1", "Position"), v0=-0.5 * par.start("P1", "Velocity"),
    )
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _fixed_position_multiport(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicFixedPositionMultiPort.hpp: MechanicFixedPosition with a multiport Pm1,
    each connection standing still at its node's start position, taking the force of what is joined to it: a
    FixedPosition all of them join (connections that start at different positions are refused)."""
    from hydroservo.components import FixedPosition

    if not _shared_starts(par, ("Pm1",)):
        return Mapped()
    return Mapped([FixedPosition(n, x0=par.start("Pm1", "Position"))], power={"Pm1": f"{n}.P"})


def _spring_with_slack(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalSpringWithSlack.hpp: MechanicTranslationalSpring's
    transmission-line element (it integrates its ends' velocities) while x_1 + x_2 <= 0 (its ends' positions, inward,
    as its neighbours write them: stretched), and no force (c = Z_c = 0, the integration restarting from 0)
    otherwise: a rope, f = k min(x_1 + x_2, 0), relaxed where x_1 + x_2 = 0. A Spring with option slack =
    "slack" and e0 = 0. A start force other than that law's at the start positions (k min(x_1 + x_2, 0)) is
    refused (Hopsan's integration would keep it as an offset until the rope first goes slack)."""
    from hydroservo.components import Spring

    k = par("k", 100.0)
    stretch = par.start("P1", "Position") + par.start("P2", "Position")
    f0 = k * min(stretch, 0.0)
    starts = (par.start("P1", "Force"), par.start("P2", "Force"))
    if k < 0.0 or any(abs(f - f0) > 1e-9 * max(1.0, abs(f0)) for f in starts):
        par.problems.append(
            f"{par.where}: k = {k:g} N/m, start forces {starts[0]:g} N and {starts[1]:g} N: only k >= 0 and start "
            f"forces k min(x_1 + x_2, 0) = {f0:g} N at the start positions are supported"
        )
        return Mapped()
    return Mapped([Spring(n, k_spring=k, e0=0.0, slack="slack")], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _spring_free_length(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicSpring.hpp: a C-type spring (ports Pm1, Pm2) whose wave variables
    stand for f = Ks (x_m1 + x_m2 - x0), Hopsan's node force (compression positive) from its ends' positions
    (inward, as Hopsan's Q components write them), x0 the free length (not its start positions, as
    MechanicTranslationalSpring's); alpha (numerical damping) and eps (drift removal) shape the discretisation
    and vanish with the step. A Spring with k_spring = Ks relaxed at the extension e0 = -x0 (hydroservo's ends
    count outward)."""
    from hydroservo.components import Spring

    k = par("Ks", 100.0)
    if k < 0.0:
        par.problems.append(f"{par.where}: Ks = {k:g} N/m; only a stiffness of at least 0 is supported")
        return Mapped()
    return Mapped([Spring(n, k_spring=k, e0=-par("x0", 0.0))], power={"Pm1": f"{n}.P1", "Pm2": f"{n}.P2"})


def _spring(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Spring

    k = par("k", 100.0)
    e0 = _relaxed(par, k, ("P1", "P2"), "Position", "Force")
    return Mapped([Spring(n, k_spring=k, e0=e0)], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _relaxed(par: _Params, k: float, ports: tuple[str, str], position: str, force: str, ratio: float = 1.0) -> float:
    """Where a Hopsan spring is relaxed: it starts at its ends' start positions (inward; hydroservo's are outward)
    with the start force of its nodes (a compression: a preload), and adds k times the ends' displacements (end 1's
    through a gear of ``ratio``, whose start force is end 2's over the ratio)."""
    e0 = -(par.start(ports[0], position) / ratio + par.start(ports[1], position))
    preload = par.start(ports[1], force)
    if par.start(ports[0], force) * ratio != preload:
        par.problems.append(f"{par.where}: start {force.lower()}s at {ports[0]} and {ports[1]} that differ"
                            + (" other than by the gear ratio" if ratio != 1.0 else "") + " are not supported")
    if preload and k > 0.0:
        e0 += preload / k  # compressed by preload / k at the start
    elif preload:
        par.problems.append(f"{par.where}: a start {force.lower()} on a spring of zero stiffness is not supported")
    return e0


def _fixed_position(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import FixedPosition

    return Mapped([FixedPosition(n, x0=par.start("Pm1", "Position"))], power={"Pm1": f"{n}.P"})


def _force_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import ForceSource

    return Mapped([ForceSource(n)], power={"P1": f"{n}.P"}, inputs={"F": f"{n}.u"})


def _velocity_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import VelocitySource

    # MechanicVelocityTransformer.hpp: the position integrates the velocity, or, its input x connected, is that
    if "x" in par.driven:
        comp = VelocitySource(n, position="input")
        return Mapped([comp], power={"Pm1": f"{n}.P"}, inputs={"v": f"{n}.u", "x": f"{n}.x_in"})
    comp = VelocitySource(n, x0=par("x", 0.0))
    return Mapped([comp], power={"Pm1": f"{n}.P"}, inputs={"v": f"{n}.u"})


def _mechanic_c_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalCSource.hpp: a C component that writes its inputs as its
    node's wave variable and impedance, c = in_c, Z_x = in_z, so that the Q component joined to it feels
    f = c + Z_x v (v its velocity towards the source): a force c behind a damper of coefficient Z_x to ground, a
    ForceSource with its input ``B`` = in_z (F = u - B v, v outward of the source). With in_z = 0 (its default)
    it is MechanicForceTransformer's law."""
    from hydroservo.components import ForceSource

    if par("in_z", 0.0) < 0.0 and "in_z" not in par.driven:
        par.problems.append(f"{par.where}: in_z = {par('in_z', 0.0):g} N s/m; only an impedance of at least 0 is "
                            "supported")
        return Mapped()
    return Mapped([ForceSource(n)], power={"P1": f"{n}.P"}, inputs={"in_c": f"{n}.u", "in_z": f"{n}.B"})


def _mechanic_q_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalQSource.hpp: a Q component that writes its inputs as its
    node's force, velocity, position and equivalent mass, whatever the C component joined to it does. Hopsan's C
    components read the velocity (a spring's waves c_1 = c_2 + 2 Z_c v_2) and the position (a cylinder's stops),
    never the force: the source is a VelocitySource of ``in_v`` at the position ``in_x`` (option ``position =
    "input"``, as MechanicVelocityTransformer's with its x connected). ``in_f`` is no more than the force Hopsan
    logs at the node (the C component's own where the signal is consistent with it): a signal driving it is
    refused, a constant only logged by Hopsan. ``in_em`` sets how stiff Hopsan's C components make their stops
    for its step (m_e/T_s², a hard stop as the step vanishes): not used. ``in_x`` not driven while ``in_v`` is
    driven, or not 0, is refused: Hopsan would write a fixed position for a moving node (its springs follow the
    velocity, its cylinders' stops the position); connect in_x to the velocity's integral."""
    from hydroservo.components import VelocitySource

    if "in_f" in par.driven:
        par.problems.append(f"{par.where}: in_f driven by a signal: Hopsan logs it as the node's force, which no C "
                            "component reads; hydroservo's node force is the C component's, so in_f is not supported "
                            "as a signal")
    if "in_x" in par.driven:
        return Mapped([VelocitySource(n, position="input")], power={"P1": f"{n}.P"},
                      inputs={"in_v": f"{n}.u", "in_x": f"{n}.x_in"})
    if "in_v" in par.driven or par("in_v", 0.0) != 0.0:
        par.problems.append(f"{par.where}: in_v moves the node while in_x holds it at {par('in_x', 0.0):g} m (Hopsan "
                            "writes both: its springs follow the velocity, its cylinders' stops the position); "
                            "connect in_x to the velocity's integral")
        return Mapped()
    return Mapped([VelocitySource(n, x0=par("in_x", 0.0))], power={"P1": f"{n}.P"}, inputs={"in_v": f"{n}.u"})


def _lossless_link(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalLosslessConnector.hpp: a Q component between two C
    components, v_2 = (c_1 - c_2)/(Z_1 + Z_2), v_1 = -v_2, x_1 = L - x_2 (L the sum of its ports' start positions),
    whose forces f_i = c_i + Z_i v_i are equal at every step: a massless rigid link, a RigidLink of that length
    (its position solved so that its two forces balance, its velocity that position's rate within 1 µs, as the
    Wall's free end), starting at P2's start position."""
    from hydroservo.components import RigidLink

    x1, x2 = par.start("P1", "Position"), par.start("P2", "Position")
    return Mapped([RigidLink(n, length=x1 + x2, x0=x2)], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _sensor(variable: str, unit: str) -> Builder:
    """Hopsan's sensors of a node's ``variable``: a Sum reading it (fed when the node is known), its output Hopsan's
    ``out``."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Sum

        # A pressure read is Hopsan's absolute one (the node's value plus the atmosphere, as the blocks it feeds
        # expect): its Hopsan-named variable is shown as absolute, as the node's own pressure is, not as a gauge
        # pressure (shown in Pa_abs that added the atmosphere twice)
        values = {"out": Var(1.0, f"{n}.y", unit="Pa_abs")} if variable == "Pressure" else {}
        return Mapped([Sum(n, unit=unit, gain2=0.0)], read={"P1": (f"{n}.u1", variable)}, outputs={"out": f"{n}.y"},
                      values=values)

    return build


def _differential_pressure_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sensors/HydraulicDifferentialPressureSensor.hpp: out = p_1 - p_2, its read ports
    taking no flow: a Sum reading each node's pressure (``{n}_p1``, ``{n}_p2``, as the pressure sensor's) and a
    Sum of their difference (the atmosphere of Hopsan's absolute pressures cancels)."""
    from hydroservo.components import Sum

    comps: list[cbase.Component] = [
        Sum(f"{n}_p1", unit="Pa", gain2=0.0), Sum(f"{n}_p2", unit="Pa", gain2=0.0), Sum(n, unit="Pa"),
    ]
    return Mapped(
        comps, read={"P1": (f"{n}_p1.u1", "Pressure"), "P2": (f"{n}_p2.u1", "Pressure")},
        outputs={"out": f"{n}.y"}, internal=[(f"{n}_p1.y", f"{n}.u1"), (f"{n}_p2.y", f"{n}.u2")],
    )


def _power_sensor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sensors/HydraulicPowerSensor.hpp: out = p q [W] of its node, Hopsan's absolute
    pressure times the node's flow, the read port taking no flow: a Sum reading the pressure (``{n}_p``), one the
    flow (``{n}_q``) and a Product of the two."""
    from hydroservo.components import Product, Sum

    comps = [Sum(f"{n}_p", unit="Pa", gain2=0.0), Sum(f"{n}_q", unit="m^3/s", gain2=0.0), Product(n)]
    return Mapped(
        comps, read={"P1": (f"{n}_p.u1", "Pressure")}, read_also={"P1": [(f"{n}_q.u1", "Flow")]},
        outputs={"out": f"{n}.y"}, internal=[(f"{n}_p.y", f"{n}.u1"), (f"{n}_q.y", f"{n}.u2")],
    )


def _plug(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sources&Sinks/HydraulicPlugQ.hpp: a Q component of no flow, q = 0, p = c (Hopsan
    logs p = 0 where c < 0; hydroservo keeps the node's pressure): a FlowSource of 0."""
    from hydroservo.components import FlowSource

    return Mapped([FlowSource(n, q=0.0)], power={"P1": f"{n}.P"})


#: the conductance [m^3/s/Pa] that stands for Hopsan's lossless connectors' ideal connection (the shuttle
#: valve's open seat's): the nodes' pressures within q/G of each other (17 Pa per L/min), with a time constant
#: V/(β G) (1e-8 s on a 1e-5 m^3 line) far below anything a circuit does
_LOSSLESS_G = 1e-6


def _lossless_connector(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Restrictors/HydraulicLossLessConnector.hpp: q = (c_1 - c_2)/(Z_c1 + Z_c2), the flow
    that makes p_1 = p_2, an ideal connection of its two C nodes (in the limit of a vanishing step, the two
    volumes one): a LaminarOrifice of a conductance large enough that the pressures follow each other
    (:data:`_LOSSLESS_G`). HydraulicLossLessTConnector.hpp: p = Σ(c_i/Z_ci)/Σ(1/Z_ci) at all three ports, the
    three nodes joined: LaminarOrifices from P1 to P2 (``{n}``) and from P1 to P3 (``{n}_3``), P1's flow the
    two summed (a Sum ``{n}_Q1``). Hopsan logs a pressure below 0 as 0; hydroservo keeps it."""
    from hydroservo.components import LaminarOrifice, Sum

    if hc.typename == "HydraulicLosslessConnector":
        return Mapped([LaminarOrifice(n, G_lam=_LOSSLESS_G)], power={"P1": f"{n}.A", "P2": f"{n}.B"})
    comps = [LaminarOrifice(n, G_lam=_LOSSLESS_G), LaminarOrifice(f"{n}_3", G_lam=_LOSSLESS_G),
             Sum(f"{n}_Q1", unit="m^3/s", gain1=-1.0, gain2=-1.0)]
    return Mapped(
        comps, power={"P1": f"{n}.A", "P2": f"{n}.B", "P3": f"{n}_3.B"},
        internal=[(f"{n}.A", f"{n}_3.A"), (f"{n}.Q", f"{n}_Q1.u1"), (f"{n}_3.Q", f"{n}_Q1.u2")],
        flow={"P1": f"{n}_Q1.y"},
    )


#: Hopsan's Nyquist frequency 1/(2 Ts) is the highest its step resolves: a line's default segments carry waves up to
#: it by [Efe2014]'s criterion (a segment shorter than a tenth of the wavelength), n >= 10 T/(2 Ts)
_LINE_SEGMENTS_PER_STEP = 5.0


def _line_segments(par: _Params, delay: float) -> int:
    """The segments of a line of ``delay`` T [s]: the import's ``line_segments`` if given, else those that carry
    the waves up to the Nyquist frequency 1/(2 Ts) of Hopsan's step by [Efe2014] eq. 3.30 per segment, ceil(5 T/Ts)
    (:data:`_LINE_SEGMENTS_PER_STEP`), at least 1 and at most :attr:`hydroservo.components.Line.MAX_SEGMENTS`."""
    from hydroservo.components import Line

    if par.line_segments is not None:
        return par.line_segments
    if par.timestep <= 0.0:
        return Line.MAX_SEGMENTS
    needed = math.ceil(_LINE_SEGMENTS_PER_STEP * delay / par.timestep - 1e-9)
    return min(max(needed, 1), Line.MAX_SEGMENTS)


def _line_starts(par: _Params) -> float | None:
    """The line's start pressure (absolute, Hopsan's), or None (a problem noted): hydroservo's line starts at rest
    at one pressure, so unequal start pressures at its ends or a start flow are refused."""
    p1, p2 = par.start("P1", "Pressure", 1e5), par.start("P2", "Pressure", 1e5)
    q1, q2 = par.start("P1", "Flow", 0.0), par.start("P2", "Flow", 0.0)
    if p1 != p2 or q1 != 0.0 or q2 != 0.0:
        par.problems.append(
            f"{par.where}: start values P1#Pressure = {p1:g} Pa, P2#Pressure = {p2:g} Pa, P1#Flow = {q1:g} m^3/s, "
            f"P2#Flow = {q2:g} m^3/s: a line starting at rest at one pressure (equal pressures, no flow) is supported"
        )
        return None
    return p1


def _tlm_lossless(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Volumes&Lines/HydraulicTLMlossless.hpp: c_1(t) = p_2(t - T) + Z_c q_2(t - T) and the
    same from end 1 to end 2, T = ``deltat``: the characteristics of the wave equation of a lossless line of
    impedance Z_c, solved exactly (Hopsan's one-step TLM delay is part of T). hydroservo's engine holds no delay:
    a LosslessLine, the lumped ladder of that line's capacitance T/Z_c and inertance Z_c T, both ends pressure
    ports (Hopsan's C ends) with half a segment's volume; segments by :func:`_line_segments`. Its low-pass
    coefficient ``alpha`` filters each wave at every step, c = α c + (1 - α) c_0, a filter whose time constant
    α Ts/(1 - α) is tied to Hopsan's step: alpha ≠ 0 is refused."""
    from hydroservo.components import LosslessLine

    alpha = par("alpha", 0.0)
    if alpha != 0.0 or "alpha" in par.driven:
        par.problems.append(
            f"{par.where}: alpha = {alpha:g}: Hopsan filters each wave over one of its steps (time constant "
            "alpha Ts/(1 - alpha), tied to the step); only alpha = 0 is supported"
        )
    p_init = _line_starts(par)
    z_c, delay = par("Z_c", 1e9), par("deltat", 0.1)
    if z_c <= 0.0 or delay <= 0.0:
        par.problems.append(f"{par.where}: Z_c = {z_c:g}, deltat = {delay:g} s; values above 0 are supported")
        return Mapped()
    segments = _line_segments(par, delay)
    comp = LosslessLine(n, segments=segments, Z_c=z_c, deltat=delay, f_max=segments / (10.0 * delay),
                        p_init=_abs(p_init if p_init is not None else 1e5))
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"},
                  note=f"LosslessLine {n} ({segments} segments)")


def _hose(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Volumes&Lines/HydraulicHose.hpp (Krus' line model): the lossless line's
    characteristics over T = l/√(β_e/ρ), with the laminar resistance R = 128 η l/(π d⁴) split into a part lumped
    at the ends (R q low-pass filtered over κ T, κ = 1.25) and a part that attenuates each wave (the filter
    (1 + s/W_2)/(1 + s/W_1), W_1 = 1/(κ T), W_2 = W_1 e^{R/(2 Z_c)}): the two add up, to first order in R/Z_c, to
    R at every frequency, a line with uniform friction. Above a Reynolds number of 2300 Hopsan's friction is
    Blasius' (its ``rq``). hydroservo: a Line of that friction (ν = η/ρ, ``friction = "laminar-blasius"``), both
    ends pressure ports (Hopsan's C ends); the wall's equivalent viscosity ``eta_w``, a further filter on each
    wave, is the Line's ``wall = "viscous"`` (its docstring). Segments by :func:`_line_segments`."""
    from hydroservo.components import Line

    rho, eta, d, length = par("rho", 870.0), par("eta", 0.03), par("d", 0.03), par("l", 1.0)
    beta, eta_w = par("beta_e", 1e9), par("eta_w", 0.03)
    if min(rho, eta, d, length, beta) <= 0.0 or eta_w < 0.0:
        par.problems.append(
            f"{par.where}: rho, eta, d, l and beta_e above 0 and eta_w at least 0 are supported"
        )
        return Mapped()
    p_init = _line_starts(par)
    delay = length / math.sqrt(beta / rho)
    segments = _line_segments(par, delay)
    wall: dict[str, Any] = {"wall": "viscous", "eta_w": eta_w} if eta_w > 0.0 else {}
    comp = Line(n, segments=segments, l=length, d=d, rho=rho, nu=eta / rho, beta_e=beta, friction="laminar-blasius",
                f_max=segments / (10.0 * delay), p_init=_abs(p_init if p_init is not None else 1e5), **wall)
    return Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B"},
                  note=f"Line {n} ({segments} segments{', viscous wall' if wall else ''})")

def _c_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sources&Sinks/HydraulicCSource.hpp: a C component that writes its inputs as its
    node's wave variable and impedance, c = in_c, Z_c = in_z, so that the Q component joined to it sees
    p = c + Z_c q (q the flow into the source): a pressure source c behind a linear resistance Z_c, a
    PressureSource with ``impedance = "input"`` (p = u - Z Q, Q the flow it delivers; its pressure solved with
    the node's flows), ``in_c`` (absolute) into ``u``, ``in_z`` into ``Z``. With Z_c = 0 (its default, and not
    driven) an ideal pressure source: a Tank at ``in_c``, or a PressureSource following the signal driving it."""
    from hydroservo.components import PressureSource, Tank

    if "in_z" in par.driven or par("in_z", 0.0) != 0.0:
        comp = PressureSource(n, p0="0 Pa_abs", impedance="input")
        return Mapped([comp], power={"P1": f"{n}.P"}, inputs={"in_c": f"{n}.u", "in_z": f"{n}.Z"})
    if "in_c" in par.driven:
        return Mapped([PressureSource(n, p0="0 Pa_abs")], power={"P1": f"{n}.P"}, inputs={"in_c": f"{n}.u"})
    return Mapped([Tank(n, p=_abs(par("in_c", 0.0)))], power={"P1": f"{n}.P"})


def _q_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Sources&Sinks/HydraulicQSource.hpp: a Q component that writes its inputs as its
    node's pressure and flow, p = in_p, q = in_q, whatever the wave variable of the C component joined to it.
    Hopsan's C components read only the flow (a volume's waves c_1 = c_2 + 2 Z_c q_2; a tank reads nothing), so
    the source is a flow source of ``in_q`` into the C component (a FlowSource), and ``in_p`` is no more than
    the pressure Hopsan logs at the node: the C component's own pressure where the signal is consistent with it
    (p = c + Z_c q, as an external model coupled through the node computes it), any other number where not.
    hydroservo's node pressure is the C component's: a signal driving ``in_p`` is refused (a constant is what
    Hopsan logs there, not used)."""
    from hydroservo.components import FlowSource

    if "in_p" in par.driven:
        par.problems.append(
            f"{par.where}: in_p driven by a signal: Hopsan logs it as the node's pressure, which no C component "
            "reads (the volume joined to it takes the flow in_q); hydroservo's node pressure is the C component's, "
            "so in_p is not supported as a signal")
    return Mapped([FlowSource(n, q=0.0)], power={"P1": f"{n}.P"}, inputs={"in_q": f"{n}.u"},
                  note=f"FlowSource {n} (in_q; in_p = {par('in_p', 0.0):g} Pa only logged by Hopsan)")


def _node_sensor(variables: tuple[tuple[str, str, str], ...], discretised: tuple[str, ...]) -> Builder:
    """[Hopsan2026] Hydraulic/Sensors/HydraulicNodeSensor.hpp (outputs p, q) and Mechanic/Linear/
    MechanicNodeSensor.hpp (out_f, out_v, out_x): each a Sum reading its node's variable, as the single sensors'
    (``{n}_<output>``; pressures absolute, as Hopsan's). Their other outputs, the node's wave variable, impedance
    and equivalent mass (c, Zc; out_c, out_z, out_em), are quantities of Hopsan's discretisation (a volume's
    Z_c = β T_s/V vanishes with the step, the equivalent mass sets how stiff Hopsan makes its stops for its
    step) and are not mapped: a scope showing them is dropped, a block reading them refused."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Sum

        comps: list[cbase.Component] = [Sum(f"{n}_{out}", unit=unit, gain2=0.0) for out, _, unit in variables]
        (first, var, _), rest = variables[0], variables[1:]
        why = ("a quantity of Hopsan's discretisation (a node's wave variable, impedance or equivalent mass: a "
               "volume's impedance beta Ts/V vanishes with the step), which hydroservo's model has not")
        return Mapped(
            comps, read={"P1": (f"{n}_{first}.u1", var)},
            read_also={"P1": [(f"{n}_{out}.u1", v) for out, v, _ in rest]},
            outputs={out: f"{n}_{out}.y" for out, _, _ in variables},
            unmapped={port: why for port in discretised},
        )

    return build


# -- mechanic, rotational -------------------------------------------------------------------------------------


def _rotational_inertia(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertia.hpp: its transfer function 1/(J s² + B s + k)
    from the torques at its ends (t1 - t2) to the angle of P2 (P1 at minus it) is J θ'' = T1 - T2 - B θ' - k θ, a
    RotationalInertia; it starts at minus P1's start angle and speed, as Hopsan's filters do; its inelastic stops
    a_min, a_max as stiff ones (1e9 N m/rad, 1e6 N m s/rad)."""
    from hydroservo.components import RotationalInertia

    comp = RotationalInertia(
        n,
        J=par("J", 0.1),
        B_rot=par("B", 10.0),
        k_rot=par("k", 0.0),
        theta0=-par.start("P1", "Angle"),
        omega0=-par.start("P1", "AngularVelocity"),
    )
    a_min, a_max = par("a_min", -1e300), par("a_max", 1e300)
    if abs(a_min) < 1e299 or abs(a_max) < 1e299:
        comp.set(theta_min=max(a_min, -1e30), theta_max=min(a_max, 1e30), k_stop_rot=1e9, c_stop_rot=1e6)
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _rotational_inertia_multiport(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertiaMultiPort.hpp: J θ'' = Σt_1 - Σt_2 - B θ' (no
    spring), the torques of every connection to its multiports P1 and P2 summed (as on the one port of
    RotationalInertia each joins); its integrator starts at rest at angle 0 whatever the start values, P2 at the
    angle θ and P1 at P1's and P2's start angles added minus θ; a_min, a_max as stiff stops (as
    :func:`_rotational_inertia`). A RotationalInertia starting at rest at 0; start angles of P1 and P2 that do not
    add to 0 (an offset of P1's angle RotationalInertia has not), or connections that start apart, are refused."""
    from hydroservo.components import RotationalInertia

    if not _shared_starts(par, ("P1", "P2")):
        return Mapped()
    offset = par.start("P1", "Angle") + par.start("P2", "Angle")
    if offset != 0.0:
        par.problems.append(
            f"{par.where}: start angles of P1 and P2 that add to {offset:g} rad, not 0, are not supported (Hopsan "
            "keeps P1 that far from minus P2's angle)"
        )
        return Mapped()
    comp = RotationalInertia(n, J=par("J", 100.0), B_rot=par("B", 10.0), k_rot=0.0, theta0=0.0, omega0=0.0)
    a_min, a_max = par("a_min", -1e300), par("a_max", 1e300)
    if abs(a_min) < 1e299 or abs(a_max) < 1e299:
        comp.set(theta_min=max(a_min, -1e30), theta_max=min(a_max, 1e30), k_stop_rot=1e9, c_stop_rot=1e6)
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _torsional_spring(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicTorsionalSpring.hpp: a transmission-line element of impedance
    k Ts, a spring of stiffness k as Ts vanishes: a TorsionalSpring relaxed at its ends' start angles (less a
    start torque's twist)."""
    from hydroservo.components import TorsionalSpring

    k = par("k", 100.0)
    e0 = _relaxed(par, k, ("P1", "P2"), "Angle", "Torque")
    return Mapped([TorsionalSpring(n, k_rot=k, e0_rot=e0)], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _shaft(stiffness: Callable[[_Params], float]) -> Builder:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotShaft.hpp (stiffness Ks) and MechanicRotShaftG.hpp (Ks = π/32
    (dy⁴ − di⁴) G / len, a hollow shaft of shear modulus G): transmission-line elements of impedance Ks Ts/(1 − α)
    whose wave variables a first-order filter of α damps; impedance and damping vanish with the step, leaving a
    spring of stiffness Ks: a TorsionalSpring, relaxed as Hopsan starts it (its ports' start angles and torque).
    ``alpha`` is numerical only (it acts in the limit no more): values in [0, 1) are accepted and dropped."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import TorsionalSpring

        alpha = par("alpha", 0.1)
        if not 0.0 <= alpha < 1.0:
            par.problems.append(f"{par.where}: alpha = {alpha:g} outside [0, 1), where Hopsan's filter is stable")
        k = stiffness(par)
        e0 = _relaxed(par, k, ("Pmr1", "Pmr2"), "Angle", "Torque")
        return Mapped([TorsionalSpring(n, k_rot=k, e0_rot=e0)], power={"Pmr1": f"{n}.P1", "Pmr2": f"{n}.P2"})

    return build


def _gear_shaft(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicGearShaft.hpp: a shaft behind an ideal gear of ratio gearRatio =
    ω1/ω2 at Pmr1, transmission-line elements of impedances Z/n² and Z = Ks Ts/(1 − α) whose wave variables a
    filter of α smooths: in the limit T2 = K (θ1/n + θ2 − e0), T1 = T2/n, a TorsionalSpring with n_gear. Its
    stiffness is not Ks: a transmission line of impedance Z and delay T_d is a spring of stiffness Z/T_d, and
    Hopsan's gear shaft passes each wave on a step later than its shaft does (it writes the filter's previous
    value), so T_d = Ts/(1 − α) (the filter's lag included) + Ts and K = Ks/(2 − α), whatever the step (RotShaft's
    T_d = Ts/(1 − α) gives Ks). ``alpha`` enters only there; values outside [0, 1) are refused."""
    from hydroservo.components import TorsionalSpring

    alpha, ratio, k = par("alpha", 0.9), par("gearRatio", 1.0), par("Ks", 1000.0)
    if not 0.0 <= alpha < 1.0:
        par.problems.append(f"{par.where}: alpha = {alpha:g} outside [0, 1), where Hopsan's filter is stable")
    if ratio == 0.0:
        par.problems.append(f"{par.where}: gearRatio = 0 is not a gear")
        return Mapped()
    k = k / (2.0 - alpha)  # the stiffness Hopsan's element converges to (docstring)
    e0 = _relaxed(par, k, ("Pmr1", "Pmr2"), "Angle", "Torque", ratio)
    comp = TorsionalSpring(n, k_rot=k, e0_rot=e0, n_gear=ratio)
    return Mapped([comp], power={"Pmr1": f"{n}.P1", "Pmr2": f"{n}.P2"})


def _torque_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicTorqueTransformer.hpp: a C component of wave variable T and no
    impedance, the torque T on its node: a TorqueSource."""
    from hydroservo.components import TorqueSource

    return Mapped([TorqueSource(n)], power={"P1": f"{n}.P"}, inputs={"T": f"{n}.u"})


def _theta_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicThetaSource.hpp: the speed omega, the angle its integral from
    thetain, or thetain itself when that input is connected: an AngularVelocitySource (option position)."""
    from hydroservo.components import AngularVelocitySource

    if "thetain" in par.driven:
        comp = AngularVelocitySource(n, position="input")
        return Mapped([comp], power={"Pmr1": f"{n}.P"}, inputs={"omega": f"{n}.u", "thetain": f"{n}.x_in"})
    comp = AngularVelocitySource(n, theta0=par("thetain", 0.0))
    return Mapped([comp], power={"Pmr1": f"{n}.P"}, inputs={"omega": f"{n}.u"})


def _angular_velocity_source(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicAngularVelocityTransformer.hpp: the speed omega, the angle its
    integral from the start angle of its port: an AngularVelocitySource."""
    from hydroservo.components import AngularVelocitySource

    comp = AngularVelocitySource(n, theta0=par.start("out", "Angle"))
    return Mapped([comp], power={"out": f"{n}.P"}, inputs={"omega": f"{n}.u"})


def _free_length_wall(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicFreeLengthWall.hpp: a Q component whose end, the filter
    x = -c/((B + Z_c) s) of the node's wave variable, is clamped at stop_pos with zero velocity while the wave
    variable presses it there (and writes the force c), and is otherwise free (it writes the force 0). As the
    step vanishes Z_c vanishes and the filter is B ẋ = F, the end held by the damping B alone: a unilateral
    contact of a massless end, a Wall (B, x_stop = stop_pos) starting at its port's start position (clamped to
    the stop, as Hopsan's first step does). With B > 0 the free end's force is B v where Hopsan logs 0 (its
    filter moves the end as a damper would, but it writes no force). m_e is the equivalent mass Hopsan writes
    to the node for its neighbours' numerics: unused, as in hydroservo's laws."""
    from hydroservo.components import Wall

    stop, b = par("stop_pos", 0.0), par("B", 0.001)
    if b < 0.0:
        par.problems.append(f"{par.where}: B = {b:g} Ns/m; a damping of at least 0 is supported")
        return Mapped()
    comp = Wall(n, B=b, x_stop=stop, x0=max(par.start("Pm1", "Position"), stop))
    return Mapped([comp], power={"Pm1": f"{n}.P"})


def _rotational_inertia_coulomb(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertiaWithCoulombFriction.hpp: the translational mass
    with Coulomb friction's law (its DoubleIntegratorWithDampingAndCoulombFriction) on an angle: stuck while the
    torque on it stays below t_s, sliding against t_k and B ω once it turns, stopped whenever its speed would
    change sign. As for MechanicTranslationalMassWithCoulombFriction (:func:`_mass_coulomb`), the limit of the
    Stribeck law as its velocity scales vanish: a RotationalInertia with T_c0 = t_k, T_s0 = t_s - t_k,
    omega_reg = 1e-5 rad/s and omega_s = 1e-3 rad/s. A static friction below the kinetic one (RotationalInertia-
    WithCoulombFrictionTest's t_s = 10, t_k = 50 Nm) acts as the kinetic one: Hopsan's integrator breaks away
    when the torque reaches t_s, but stops again on its next step, its speed about to change sign, unless the
    torque exceeds t_k; so T_s0 = max(t_s - t_k, 0). Hopsan's integrator starts at P2's start angle and speed;
    its inelastic stops a_min, a_max as stiff ones. Older files name the type ...WithCoulumbFriction, which
    Hopsan's GUI renames when it loads them (HopsanGUI/Utilities/XMLUtilities.cpp); both map here."""
    from hydroservo.components import RotationalInertia

    t_s, t_k = par("t_s", 50.0), par("t_k", 45.0)
    if t_s < 0.0 or t_k < 0.0:
        par.problems.append(f"{par.where}: t_s = {t_s:g} Nm, t_k = {t_k:g} Nm: a negative friction is not supported")
        return Mapped()
    comp = RotationalInertia(
        n,
        J=par("J", 1.0),
        B_rot=par("B", 10.0),
        T_c0=t_k,
        T_s0=max(t_s - t_k, 0.0),
        omega_reg=1e-5,
        omega_s=1e-3,
        theta0=par.start("P2", "Angle"),
        omega0=par.start("P2", "AngularVelocity"),
    )
    a_min, a_max = par("a_min", -1e300), par("a_max", 1e300)
    if abs(a_min) < 1e299 or abs(a_max) < 1e299:
        comp.set(theta_min=max(a_min, -1e30), theta_max=min(a_max, 1e30), k_stop_rot=1e9, c_stop_rot=1e6)
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _rotational_inertia_gear(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertiaWithGearRatio.hpp: an inertia J behind an ideal
    gear of ratio omega at P1, its filters 1/(J s² + B s) and 1/(J s + B) of omega T1 - T2 (P1 at -omega θ, turning
    at -omega ω): J θ'' = omega T1 - T2 - B θ', a RotationalInertia with n_gear = omega, starting at P2's start
    angle and speed, as Hopsan's filters."""
    from hydroservo.components import RotationalInertia

    ratio = par("omega", 1.0)
    if ratio == 0.0:
        par.problems.append(f"{par.where}: gear ratio omega = 0 is not a gear")
        return Mapped()
    comp = RotationalInertia(
        n,
        J=par("J", 1.0),
        B_rot=par("B", 10.0),
        n_gear=ratio,
        theta0=par.start("P2", "Angle"),
        omega0=par.start("P2", "AngularVelocity"),
    )
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _rotational_inertia_single_gear(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRotationalInertiaWithSingleGear.hpp: MechanicRotationalInertia-
    WithGearRatio's code with U = -omega (one pair of gears reverses the turn): J θ'' = -omega T1 - T2 - B θ', P1
    turning at omega ω, a RotationalInertia with n_gear = -omega (:func:`_rotational_inertia_gear`)."""
    mapped = _rotational_inertia_gear(hc, n, par)
    for comp in mapped.components:
        comp.set(n_gear=-par("omega", 1.0))
    return mapped


def _ball_screw(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicBallScrew.hpp: a screw of inertia J (P2) whose nut is P1, moving
    L/(2π) per radian: its filter s/(J s² + (B + Z_x1 + Z_x2) s + k) of g c_1 - c_2 is, as the step vanishes,
    J w_2' = g f_1 - t_2 - B w_2 - k a_2 with v_1 = -(L/2π) w_2, x_1 = -(L/2π) a_2, starting at rest at 0; lossless
    (ny = ny2 = 1, g = L/2π) MechanicRackAndPinion's law (:func:`_rack_and_pinion`), a Crank with link = "rack",
    r_link = L/2π. Its efficiencies are refused: Hopsan takes g = L/(2π ny) while g f_1 ≤ t_2 and L ny2/2π
    otherwise, by which torque is the larger rather than by which way the power flows, so that turning forward
    (w_2 > 0) the forward and reverse efficiencies are swapped: driven by its screw, the nut's load is reflected
    with ny2 (less torque than a lossless screw needs), driven by its nut, the screw gets the force through 1/ny
    (more torque than the force gives): power out of nothing. The spring k (a constant, 0 by default), L, J at or
    below 0 are refused too."""
    from hydroservo.components import Crank

    lead, inertia, k = par("L", 0.001), par("J", 1.0), par("k", 0.0)
    ny, ny2 = par("ny", 0.9), par("ny2", 0.8)
    if lead <= 0.0 or inertia <= 0.0 or k != 0.0:
        par.problems.append(
            f"{par.where}: L = {lead:g} m, J = {inertia:g} kg m^2, k = {k:g} N m/rad: only L and J above 0 and k = 0 "
            "are supported"
        )
        return Mapped()
    if ny != 1.0 or ny2 != 1.0:
        par.problems.append(
            f"{par.where}: efficiencies ny = {ny:g}, ny2 = {ny2:g}: only a lossless screw (1 and 1) is supported. "
            "Hopsan chooses ny or ny2 by which of the torques is the larger, not by which way the power flows, so "
            "that turning forward the two are swapped and the screw gives out more power than it takes"
        )
        return Mapped()
    comp = Crank(n, J=inertia, B_rot=par("B", 10.0), r_link=lead / (2.0 * math.pi), x_link=0.0, link="rack")
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _vehicle(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Special/MechanicVehicle1D.hpp: a vehicle of mass Mc on wheels of radius rwheel, both ports its
    wheels' shaft turning at -vc/rwheel. Its generated equations, solved by Newton steps each time step, are the
    trapezoidal rule of Mc v̇c = (t1 + t2)/rwheel - fd - fr (Hopsan's torques press on the component), the drag
    fd = CdA rho vc|vc|/2 and the rolling resistance fr = limit(Mc vc/Ts, -fc, fc), fc = 9.82 cfr Mc: Coulomb's
    law as the step vanishes. A Vehicle (g = 9.82 m/s², Hopsan's; the rolling resistance regularised over
    v_reg = 1e-5 m/s), starting at the start values of its outputs xc and vc; its outputs vc, xc, fd, fr. Hopsan
    integrates its ports' angle as +vc/rwheel while it writes their speed as -vc/rwheel; here the angle is the
    speed's integral, -xc/rwheel."""
    from hydroservo.components import Vehicle

    mass, radius = par("Mc", 1000.0), par("rwheel", 1.0)
    if mass <= 0.0 or radius <= 0.0 or min(par("cfr", 0.02), par("CdA", 0.5), par("rho", 1.25)) < 0.0:
        par.problems.append(f"{par.where}: Mc and rwheel above 0, cfr, CdA and rho at least 0 are supported")
        return Mapped()
    comp = Vehicle(
        n, M=mass, r_wheel=radius, c_r=par("cfr", 0.02), CdA=par("CdA", 0.5), rho_air=par("rho", 1.25), g=9.82,
        v_reg=1e-5, x0=par("xc", 0.0), v0=par("vc", 0.0),
    )
    return Mapped(
        [comp],
        power={"Pmr1": f"{n}.P1", "Pmr2": f"{n}.P2"},
        outputs={"vc": f"{n}.v", "xc": f"{n}.x", "fd": f"{n}.F_d", "fr": f"{n}.F_r"},
    )


def _jlink(two: bool) -> Builder:
    """[Hopsan2026] Mechanic/Rotational/MechanicJLink.hpp and MechanicJLink2.hpp: an inertia JL at Pmr2 turning a
    link whose end, the translational port Pm1 (and Pm0 at the same place, JLink2), is at x0 - link sin θ. Their
    generated equations, solved by Newton steps each time step, are the trapezoidal rule of
    JL θ'' = (f0 + f1) link cos θ - t2 - BL θ' (Hopsan's forces and torque press on the component), θ clamped to
    [thetamin, thetamax] with its speed zeroed (inelastic stops): a Crank with stiff stops. JLink's theta0 is
    declared but unused by its equations, and so here; the angle starts at Pmr2's start angle and speed, the
    link's end where it writes it (`WRITTEN_STARTS`)."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Crank

        link, t_min, t_max = par("link", 0.1), par("thetamin", -1.05), par("thetamax", 1.05)
        if link <= 0.0 or par("JL", 1.0) <= 0.0 or t_max < t_min:
            par.problems.append(f"{par.where}: link and JL above 0 and thetamin <= thetamax are supported")
            return Mapped()
        comp = Crank(
            n, J=par("JL", 1.0), B_rot=par("BL", 1.0), r_link=link, x_link=par("x0", -0.1), theta_min=t_min,
            theta_max=t_max, k_stop_rot=1e9, c_stop_rot=1e6,
            theta0=min(max(par.start("Pmr2", "Angle"), t_min), t_max), omega0=par.start("Pmr2", "AngularVelocity"),
        )
        power = {"Pm1": f"{n}.P1", "Pmr2": f"{n}.P2"}
        if two:
            power["Pm0"] = f"{n}.P0"
        return Mapped([comp], power=power)

    return build


def _rack_and_pinion(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicRackAndPinion.hpp: a pinion of inertia J (P2) driving a rack (P1)
    at the gear ratio omega [m/rad]: its filter (J s + B + ω² Z_x1 + Z_x2) w_2 = ω c_1 - c_2 is, with
    f_1 = c_1 + Z_x1 v_1, v_1 = -ω w_2 and t_2 = c_2 + Z_x2 w_2, the law J w_2' = ω f_1 - t_2 - B w_2, the rack at
    x_1 = -ω a_2: MechanicJLink's law on a rack, a Crank with option link = "rack", r_link = omega, x_link = 0.
    Hopsan's filters start at rest at angle 0 whatever the start values, and so does the Crank. Its spring k (a
    constant, 0 by default) is not supported, nor omega or J at or below 0."""
    from hydroservo.components import Crank

    ratio, inertia, k = par("omega", 1.0), par("J", 1.0), par("k", 0.0)
    if ratio <= 0.0 or inertia <= 0.0 or k != 0.0:
        par.problems.append(
            f"{par.where}: omega = {ratio:g} m/rad, J = {inertia:g} kg m^2, k = {k:g} N m/rad: only omega and J above "
            "0 and k = 0 are supported"
        )
        return Mapped()
    comp = Crank(n, J=inertia, B_rot=par("B", 10.0), r_link=ratio, x_link=0.0, link="rack")
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _mechanic_motor(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Rotational/MechanicMotor.hpp: an ideal motor under speed control, a C component of no
    impedance whose torque is a PID controller's output on its speed error, T = K_p e + K_i ∫e + K_d ė with
    e = omega_ref - ω (ω its own speed, minus the node's, which its Q neighbour writes): a TorqueSource driven
    by a PID (no output limits: Hopsan's Wmax, Tmax and wmax are set and never used) on a Sum reading the node's
    speed. Hopsan's derivative is the bilinear transform of s, starting from a zero error (a step in the error at
    the start is an impulse of torque, K_d e(0)); the PID's derivative is filtered with T_f = 1e-5 s, starting
    from the same zero. Its integrator starts at 0, as Hopsan's."""
    from hydroservo.components import PID, Constant, Sum, TorqueSource

    pid = PID(f"{n}_pid", Kp=par("K_p", 10.0), Ki=par("K_i", 100.0),
              Kd=par("K_d", 100.0), T_f=1e-5)
    # u1 the node's speed (read: minus the motor's; the read sets gain1 and offset), u2 omega_ref
    error = Sum(f"{n}_error", gain2=1.0)
    m = Mapped(
        [TorqueSource(n), error, pid],
        power={"P1": f"{n}.P"},
        read={"P1": (f"{n}_error.u1", "AngularVelocity")},
        internal=[(f"{n}_error.y", f"{n}_pid.e"), (f"{n}_pid.y", f"{n}.u")],
        note="a TorqueSource driven by a PID on a Sum of omega_ref and the node's speed",
    )
    if "omega_ref" in par.driven:
        m.inputs["omega_ref"] = f"{n}_error.u2"
    else:  # older files name it without #Value, which the import's unconnected inputs do not read
        m.components.append(Constant(f"{n}_omega_ref", value=par("omega_ref", 0.0)))
        m.internal.append((f"{n}_omega_ref.y", f"{n}_error.u2"))
    return m


def _mass_lever(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicTranslationalMassWithLever.hpp: a mass m at P2 on a lever of arms L_1
    and L_2 whose other end is P1: with w = (L_1 + L_2)/L_1, P1 at -x/w, moving at -v/w, its force entering as
    f1/w; its damped double integrator is m ẍ = f1/w - f2 - B ẋ. A Mass with n_lever = 1/w = L_1/(L_1 + L_2),
    starting at -w times P1's start position and velocity, as Hopsan's integrator."""
    from hydroservo.components import Mass

    l1, l2 = par("L_1", 1.0), par("L_2", 1.0)
    if l1 <= 0.0 or l2 < 0.0 or par("m", 1.0) <= 0.0:
        par.problems.append(f"{par.where}: L_1 and m above 0 and L_2 at least 0 are supported")
        return Mapped()
    w = (l1 + l2) / l1
    comp = Mass(
        n,
        m=par("m", 1.0),
        B=par("B", 10.0),
        incline=0.0,
        n_lever=1.0 / w,
        x0=-w * par.start("P1", "Position"),
        v0=-w * par.start("P1", "Velocity"),
    )
    return Mapped([comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"})


def _mkc_load(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicMkcload1D.hpp: a mass mL on a spring kL (relaxed at x = 0), damped by
    bL, with dry friction fc, its position x of Pm2 (Pm1 at -x) limited to [xmin, xmax] (its velocity zeroed
    there: inelastic stops). Its generated equations, solved by Newton steps each time step, are the trapezoidal
    rule of mL ẍ = f1 - f2 - bL ẋ - kL x - F_fr with F_fr = limit(bfc mL ẋ/Ts, -fc, fc): the force that would stop
    the mass within a step, at most fc, which is Coulomb's law (stuck below fc, sliding against it) as the step
    vanishes, whatever the numerical factor bfc. A Mass with B = bL, k_spring = kL, F_c0 = fc (static friction
    equal to the kinetic one) regularised as MechanicTranslationalMassWithCoulombFriction's (v_reg 1e-5 m/s),
    the stops as stiff ones; its output fs = kL x."""
    from hydroservo.components import Mass

    fc, x_min, x_max = par("fc", 10.0), par("xmin", 0.0), par("xmax", 1.0)
    if fc < 0.0 or par("mL", 1000.0) <= 0.0 or x_max < x_min:
        par.problems.append(f"{par.where}: mL above 0, fc at least 0 and xmin <= xmax are supported")
        return Mapped()
    comp = Mass(
        n,
        m=par("mL", 1000.0),
        B=par("bL", 10.0),
        k_spring=par("kL", 10.0),
        incline=0.0,
        F_c0=fc,
        v_reg=1e-5,
        c_s=1e-3,
        x_min=x_min,
        x_max=x_max,
        k_stop=1e9,
        c_stop=1e6,
        x0=min(max(par.start("Pm2", "Position"), x_min), x_max),
        v0=par.start("Pm2", "Velocity"),
    )
    return Mapped([comp], power={"Pm1": f"{n}.P1", "Pm2": f"{n}.P2"}, values={"fs": Var(1.0, f"{n}.x", text=f"{n}.k_spring*{n}.x", unit="N")})


def _m2_load(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Mechanic/Linear/MechanicM2load1D.hpp: two masses m1 (Pm1) and m2 (Pm2) that slide on each
    other, their relative displacement x3 the port Pm3 (a cylinder's rod between them) with its stroke
    xp = -x3 limited to [xpmin, xpmax] (velocity zeroed there: inelastic stops), dry friction fc between them. Its
    generated equations, solved by Newton steps each time step, are the trapezoidal rule of
    (m1 + m2) ẍt = f1 - f2 and μ ẍ3 = (m2 f1 + m1 f2)/(m1 + m2) - f3 - F_fr (Hopsan's forces press on the
    component), F_fr = limit(2 bfc μ ẋ3/Ts, -fc, fc), the force that would stop the relative motion within a
    step: Coulomb's law as the step vanishes, whatever bfc. A MassPair with F_c0 = fc regularised as
    MechanicTranslationalMassWithCoulombFriction's (v_reg 1e-5 m/s); bL is declared but unused by Hopsan's
    equations, and so here. Its stops are of 1e12 N/m and 1e8 N s/m, not the default 1e9 and 1e6: Hopsan clamps
    the stroke exactly, so a cylinder joined at Pm3 whose own stops are at the same place (MechanicM2load1D-
    PistonTest's) never takes load there, and a penalty stop as stiff as the cylinder's would share it (the rod
    force 34 % of range off on that test; 0.07 % at 1e12 N/m, which leaves the cylinder 0.1 %). Starts at the outputs' start values xt, vt and Pm3's start position and
    velocity, as Hopsan's; the outputs vt and xt are the centre of gravity's."""
    from hydroservo.components import MassPair

    fc, xp_min, xp_max = par("fc", 10.0), par("xpmin", 0.0), par("xpmax", 1.0)
    if fc < 0.0 or par("m1", 1000.0) <= 0.0 or par("m2", 1000.0) <= 0.0 or xp_max < xp_min:
        par.problems.append(f"{par.where}: m1 and m2 above 0, fc at least 0 and xpmin <= xpmax are supported")
        return Mapped()
    comp = MassPair(
        n,
        m1=par("m1", 1000.0),
        m2=par("m2", 1000.0),
        F_c0=fc,
        v_reg=1e-5,
        c_s=1e-3,
        x_p_min=xp_min,
        x_p_max=xp_max,
        k_stop=1e12,  # the exact clamp takes the whole load from a cylinder whose stop is at the same place
        c_stop=1e8,
        xt0=par("xt", 0.0),
        vt0=par("vt", 0.0),
        x30=min(max(par.start("Pm3", "Position"), -xp_max), -xp_min),
        v30=par.start("Pm3", "Velocity"),
    )
    return Mapped([comp], power={"Pm1": f"{n}.P1", "Pm2": f"{n}.P2", "Pm3": f"{n}.P3"},
                  outputs={"vt": f"{n}.vt", "xt": f"{n}.xt"})


def _motor_q(leakage: str, variable: bool) -> Builder:
    """Hopsan's Q-type motors ([Hopsan2026] Hydraulic/Pumps&Motors/HydraulicFixedDisplacementMotorQ.hpp, leakage
    C_lm; HydraulicVariableDisplacementMotorQ.hpp, leakage C_im and the displacement setting eps limited to
    [-1, 1]): a Motor (D_m per revolution, B_m, J_m; no external leakage, no hydromechanical loss) whose shaft is
    P3, its flow floored at 0 Pa absolute at either port (option inlet = "floor") as Hopsan clamps it; it starts
    at rest at angle 0, as Hopsan's integrator does."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Motor

        comp = Motor(
            n,
            D=f"{par('D_m', 5e-5)!r} m^3/rev",
            B_m=par("B_m", 0.0),
            C_im=par(leakage, 1e-12),
            J=par("J_m", 0.1),
            inlet="floor",
            p_floor=_abs(0.0),
        )
        m = Mapped([comp], power={"P1": f"{n}.A", "P2": f"{n}.B", "P3": f"{n}.shaft"})
        if variable:
            _displacement_setting(m, n, par)
        return m

    return build


def _displacement_setting(m: Mapped, n: str, par: _Params) -> None:
    """A machine's displacement setting ``eps``, which Hopsan limits to [-1, 1]: driven, through a Saturation
    ``{n}_eps``; constant, refused outside it."""
    from hydroservo.components import Saturation

    if "eps" in par.driven:
        m.components.append(Saturation(f"{n}_eps", lower=-1.0, upper=1.0))
        m.internal.append((f"{n}_eps.y", f"{n}.eps"))
        m.inputs["eps"] = f"{n}_eps.u"
        return
    m.inputs["eps"] = f"{n}.eps"
    eps = par("eps", 1.0)
    if not -1.0 <= eps <= 1.0:
        par.problems.append(f"{par.where}: eps = {eps:g} outside [-1, 1], which Hopsan limits it to")


def _machine_c(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/Pumps&Motors/HydraulicMachineC.hpp: a C-type machine, its port volumes V_1, V_2
    transmission-line elements (at least a volume that keeps the element stable at the step, through J_em: a
    numerical bound, dropped) and its shaft a torque characteristic (p1 − p2) ε D_m/2π with the impedance B_m +
    (ε D_m/2π)² (Z_c1 + Z_c2): in the limit a Machine (D_m per revolution, C_lm, B_m, eps limited to [-1, 1])
    between two Volumes with Hopsan's cavity law (their ports see max(p, 0), as the machine's pressures are
    floored), each starting at its port's start pressure. Hopsan's flow into P1 is ε D_m/2π times minus its
    shaft's speed (the Q component's): P1 is the Machine's A. Each port's volume is (1 + α) V_i with Hopsan's
    fixed α = 0.1, not V_i: a transmission-line element of impedance Z and delay T_d holds the oil of a volume
    T_d/Z·β, and the machine's elements have Z = β Ts/((1 - α) V_i) but filter their waves with memories two
    steps old (y_n = α y_(n-2) + (1 - α) x_n, its Delay's update returning the value before the last), so that
    T_d = Ts (1 + α)/(1 - α) whatever the step (HydraulicVolume's one-step filter gives T_d = Ts/(1 - α) and
    V). On Open Centre System, whose motors' volumes are the only ones on their lines, V_i made the trapped
    pressures decay 10 % faster than Hopsan's (pressures 67 % of range off at the valves' switching)."""
    from hydroservo.components import Machine, Volume

    comp = Machine(n, D=f"{par('D_m', 5e-5)!r} m^3/rev", C_im=par("C_lm", 1e-12), B_m=par("B_m", 0.0))
    volumes = [
        Volume(f"{n}_V{i}", V=(1.0 + 0.1) * par(f"V_{i}", 0.005), beta_e=par("Beta_e", 1e9),
               p0=_abs(par.start(f"P{i}", "Pressure", 1e5)), pressure_floor="cavity", p_floor="0 Pa_abs")
        for i in (1, 2)
    ]
    m = Mapped([comp, *volumes], power={"P1": f"{n}_V1.P", "P2": f"{n}_V2.P", "P3": f"{n}.shaft"})
    m.internal.extend([(f"{n}_V1.P", f"{n}.A"), (f"{n}_V2.P", f"{n}.B")])
    _displacement_setting(m, n, par)
    return m



def _centrifugal_pump(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPump.hpp: q2 = Ap signedSquareL(2 (p1 − p2 + Δp_th)/(kl
    ρ), 10) + Kcp (p1 − p2) with Euler's Δp_th = ρ U2² − ρ² U2 q2 cot β2/(π d b), U2 = ω d/2, solved by Newton's
    method at each step, and the torque torp = Bp ω + (p2 − p1 + kl ρ q2²/(2 Ap²)) (q2 − Kcp (p1 − p2))/(ω + 0.001):
    a CentrifugalPump with ``slip = "hopsan"`` (its ρ², as Hopsan writes it) and ``inlet = "floor"`` (no flow
    drawn from an inlet at 0 Pa absolute, as Hopsan's gate onPositive(p1)); its speed omegap a parameter or, driven,
    the input ``omega_in``. Its output q2e, which Hopsan never writes (it stays at its start value), is not mapped;
    torp, Pin and Pout are."""
    from hydroservo.components import CentrifugalPump

    driven = "omegap" in par.driven
    comp = CentrifugalPump(
        n, speed="input" if driven else "constant", slip="hopsan", inlet="floor", p_floor=_abs(0.0),
        omegap=0.0 if driven else par("omegap", 157.0), **_centrifugal_parameters(par),
    )
    return Mapped(
        [comp], power={"P1": f"{n}.P1", "P2": f"{n}.P2"},
        inputs={"omegap": f"{n}.omega_in"} if driven else {},
        outputs={"torp": f"{n}.torp", "Pin": f"{n}.Pin", "Pout": f"{n}.Pout"},
    )


def _centrifugal_pump_j(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] HydroDynamicComponents/HydraulicCentrifugalPumpJ.hpp: HydraulicCentrifugalPump's law (its
    U2 = −d wmr1/2 at its port's speed wmr1) with the impeller an inertia, (tormr1 + Bp wmr1 + Jp dwmr1/dt)(|wmr1|
    + 0.001) = (p2 − p1 + kl ρ q2²/(2 Ap²)) (q2e − Kcp (p1 − p2)): a CentrifugalPumpInertia (ω = −wmr1, its shaft
    Pmr1 counted into the pump) with ``slip = "hopsan"`` and ``inlet = "floor"``, starting at its port's start
    speed. Hopsan's port angle stays at its start value (its code never integrates it); here it is the speed's
    integral. Jp is an inertia [kg m²] (Hopsan's file calls it a friction coefficient in N/m/s). Its output Pin =
    −tormr1 wmr1, the torque at Pmr1 times ω, is a Product (``{n}_Pin``) of a Sum reading the node's torque
    (``{n}_torque``, as a torque sensor's) and the pump's speed."""
    from hydroservo.components import CentrifugalPumpInertia, Product, Sum

    comp = CentrifugalPumpInertia(
        n, slip="hopsan", inlet="floor", p_floor=_abs(0.0), Jp=par("Jp", 0.1),
        omega0=-par.start("Pmr1", "AngularVelocity"), theta0=-par.start("Pmr1", "Angle"),
        **_centrifugal_parameters(par),
    )
    return Mapped(
        [comp, Sum(f"{n}_torque", unit="N*m", gain2=0.0), Product(f"{n}_Pin", unit="W")],
        power={"P1": f"{n}.P1", "P2": f"{n}.P2", "Pmr1": f"{n}.Pmr1"},
        read={"Pmr1": (f"{n}_torque.u1", "Torque")},
        internal=[(f"{n}_torque.y", f"{n}_Pin.u1"), (f"{n}.omega", f"{n}_Pin.u2")],
        outputs={"q2e": f"{n}.q2e", "Pin": f"{n}_Pin.y", "Pout": f"{n}.Pout"},
    )


def _centrifugal_parameters(par: _Params) -> dict[str, Any]:
    """The parameters Hopsan's two centrifugal pumps share, with their defaults."""
    return {"kl": par("kl", 0.1), "b": par("b", 0.03), "d": par("d", 0.3), "beta2": par("beta2", 1.57),
            "Ap": par("Ap", 0.001), "rho": par("rho", 870.0), "Kcp": par("Kcp", 1e-11), "Bp": par("Bp", 0.1)}

def _subport_count(par: _Params, port: str) -> int:
    """How many connections a Hopsan multiport of :data:`SUBPORTS` has (each its own hydroservo port); none is
    refused (a probe of the builder, with no connections, is given one)."""
    count = sum(1 for p in par.fan_in if p.startswith(f"{port}#"))
    if count == 0 and par.where:  # a probe (:func:`_takes_as_input`) has no place in a model
        par.problems.append(f"{par.where}: nothing is connected to its multiport {port}")
    return max(count, 1)


def _cylinder_block(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/MachineParts/MechanicCylinderBlockWithSwashPlate.hpp: a block of inertia J turning
    at its shaft P2, each connection to its multiport P1 a piston's foot at x_0 + r tan(angle) sin a_k,
    a_k = -θ - theta_offset - 2π k/N (k from 0 in the order of the connections): a SwashPlate of that many
    pistons, its C{k+1} the k-th connection. Its filters start at P2's start angle and speed, as Hopsan's; the
    pistons' mean position x_0 is Hopsan's startX, the first connection's position after its initialisation has
    written 0 to every connection's (getSafeMultiPortNodeDataPtr with a value): 0, whatever the start values. J alone turns it (Hopsan adds the pistons'
    m_p (r_p²/2 + r²) after its filters have taken J); the swash plate angle ``angle`` is a parameter (a signal
    that varies is refused); its output movement is Hopsan's, its output torque (the shaft's torque, which
    Hopsan logs at P2 too) is not mapped: a connection to it is refused."""
    from hydroservo.components import SwashPlate

    pistons = _subport_count(par, "P1")
    comp = SwashPlate(
        n, pistons=pistons, J=par("J", 0.1), B_rot=par("B", 10.0), r=par("r", 0.05), angle=par("angle", 0.0),
        theta_offset=par("theta_offset", 0.0), x0=0.0,
        theta0=par.start("P2", "Angle"), omega0=par.start("P2", "AngularVelocity"),
    )
    return Mapped(
        [comp],
        power={"P2": f"{n}.P2", **{f"P1#{k}": f"{n}.C{k}" for k in range(1, pistons + 1)}},
        outputs={"movement": f"{n}.movement"},
    )


def _swash_plate(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/MachineParts/MechanicSwashPlate.hpp: a swash plate turned at ``movement``, each
    connection to its multiport P1 a piston's foot at x_0 + r tan(angle) sin(a_1 - theta_offset - 2π k/N) with
    a_1 the integral of ``movement`` from 0 (k from 0 in the order of the connections): a SwashPlateDrive of that
    many pistons, its C{k+1} the k-th connection, its mean position x_0 0 (Hopsan's startX, read after its
    initialisation has written 0 to every connection's position, as the cylinder block's). ``movement`` a
    parameter (a Constant ``{n}_movement``) or the signal driving it; ``angle`` a parameter (a signal that varies
    is refused); its output torque is not mapped (read from the forces at its ports, it would close an algebraic
    loop through the pistons), and a connection to it is refused."""
    from hydroservo.components import Constant, SwashPlateDrive

    pistons = _subport_count(par, "P1")
    comp = SwashPlateDrive(n, pistons=pistons, r=par("r", 0.05), angle=par("angle", 0.0),
                           theta_offset=par("theta_offset", 0.0), x0=0.0)
    m = Mapped(
        [comp],
        power={f"P1#{k}": f"{n}.C{k}" for k in range(1, pistons + 1)},
    )
    if "movement" in par.driven:
        m.inputs["movement"] = f"{n}.movement"
    else:
        m.components.append(Constant(f"{n}_movement", value=par("movement", 0.0)))
        m.internal.append((f"{n}_movement.y", f"{n}.movement"))
    return m


def _pump_piston(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/MachineParts/HydraulicPumpPiston.hpp: a C-type piston of one chamber, V = V_1 +
    A_1 (s_l/2 - x_3) with x_3 counted into the bore, its leakage c_leak p to 0 Pa absolute and its force
    A_1 p + F_0 + B_p v_3 on absolute pressures: a PumpPiston with ``p_case``, ``p_amb`` and ``p_floor`` at
    0 Pa absolute (its internal wave variables are floored at 0 Pa absolute: a chamber there loses no more
    pressure), starting at P1's start pressure."""
    from hydroservo.components import PumpPiston

    comp = PumpPiston(
        n, A_1=par("A_1", 0.001), s_l=par("s_l", 1.0), V_1=par("V_1", 0.0003), B_p=par("B_p", 1000.0),
        beta_e=par("Beta_e", 1e9), c_leak=par("c_leak", 1e-11), F_0=par("F_0", 1000.0), p_case="0 Pa_abs",
        p_amb="0 Pa_abs", p_floor="0 Pa_abs", p0=_abs(max(par.start("P1", "Pressure", 1e5), 0.0)),
    )
    return Mapped([comp], power={"P1": f"{n}.P1", "P3": f"{n}.P3"})


def _valve_plate(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """[Hopsan2026] Hydraulic/MachineParts/HydraulicValvePlate.hpp: the bores joined to its multiport P1 (the
    k-th connection the k-th bore, its ports starting at 2π k/N and π further) pass its kidney ports PA and PB
    as the block's angle, the integral of ``movement`` from 0, turns: a ValvePlate of that many bores, its
    C{k+1} the k-th connection, with Hopsan's measure of the angle (``angle = "hopsan"``: not periodic, some
    bores shut in the first turn), Hopsan's C_q 0.67 and its angles in degrees; turbulent to about 50 Pa (its
    orifices are turbulent to the null). ``movement`` constant (Hopsan's default 160 rad/s) is a Constant
    ``{n}_movement``; its outputs DEBUG1 to DEBUG3 are the angle, the opening of the first bore to PB and that of
    the third to PA."""
    from hydroservo.components import Constant, ValvePlate

    pistons = _subport_count(par, "P1")
    comp = ValvePlate(
        n, pistons=pistons, angle="hopsan", rho=par("rho", 870.0), R_f=par("R_f", 0.03), Cd=0.67,
        **{key: f"{par(key, default)!r} deg" for key, default in (
            ("phi_P", 160.0), ("phi_1", 6.0), ("phi_2", 6.0), ("Delta_alpha", 5.0), ("alpha_f", 30.0),
            ("theta_1", 6.0), ("theta_2", 90.0))},
    )
    m = Mapped(
        [comp],
        power={"PA": f"{n}.A", "PB": f"{n}.B", **{f"P1#{k}": f"{n}.C{k}" for k in range(1, pistons + 1)}},
        outputs={"DEBUG1": f"{n}.theta", "DEBUG2": f"{n}.A_B1", **({"DEBUG3": f"{n}.A_A3"} if pistons >= 3 else {})},
    )
    if "movement" in par.driven:
        m.inputs["movement"] = f"{n}.movement"
    else:
        m.components.append(Constant(f"{n}_movement", value=par("movement", 160.0)))
        m.internal.append((f"{n}_movement.y", f"{n}.movement"))
    return m


# -- signal ---------------------------------------------------------------------------------------------------


def _step(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Step

    # a step before the start (Hopsan's t_step < 0) is on from the start
    comp = Step(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), t_step=max(par.time("t_step", 1.0), 0.0))
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _ramp(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Ramp, Step

    y0, ya, t0, t1 = par("y_0", 0.0), par("y_A", 1.0), par.time("t_start", 1.0), par.time("t_end", 2.0)
    if t1 <= t0:  # Hopsan jumps at t_start
        return Mapped([Step(n, offset=y0, amplitude=ya, t_step=t0)], outputs={"out": f"{n}.y"})
    comp = Ramp(n, offset=y0, slope=ya / (t1 - t0), t_start=t0, limit=abs(ya))
    if t0 < 0.0:
        par.problems.append(f"{par.where}: a ramp that starts before the run (t_start = {t0 + par.t0:g} s) is not supported")
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _sine(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Sine

    f = par("f", 1.0)
    t0 = par.time("t_start", 0.0)
    # Hopsan's wave is 0 before t_start and sin(2 pi f (t - t_start - y_offset)) from it
    phase = -2.0 * math.pi * f * (par("y_offset", 0.0) + max(-t0, 0.0))
    comp = Sine(n, amplitude=par("y_A", 1.0), frequency=f, phase=phase, t_start=t0)
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _pulse(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Pulse

    t0, t1 = par.time("t_start", 1.0), par.time("t_end", 2.0)
    comp = Pulse(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), t_start=t0, duration=max(t1 - max(t0, 0.0), 0.0))
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _soft_step(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import SoftStep

    t0, t1 = par.time("t_start", 1.0), par.time("t_end", 2.0)
    if t0 < 0.0:
        par.problems.append(f"{par.where}: a soft step that starts before the run (t_start = {t0 + par.t0:g} s) is not supported")
    comp = SoftStep(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), t_start=t0, t_end=t1)
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _constant(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Constant

    return Mapped([Constant(n, value=par("y", 1.0))], outputs={"y": f"{n}.y"})  # Hopsan's output is y


def _constant_old(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalSource, SignalConstant's name in Hopsan before 0.6 (its output port ``out``, today's ``y``; Hopsan's
    loader renames both, HopsanGUI/Utilities/XMLUtilities.cpp)."""
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


def _product(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Product

    return Mapped([Product(n)], inputs={"in1": f"{n}.u1", "in2": f"{n}.u2"}, outputs={"out": f"{n}.y"})


def _quotient(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Quotient

    return Mapped([Quotient(n)], inputs={"in1": f"{n}.u1", "in2": f"{n}.u2"}, outputs={"out": f"{n}.y"})


def _absolute(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Absolute

    return Mapped([Absolute(n)], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _power(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Power

    return Mapped([Power(n, n=par("x", 0.0))], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _function(function: str) -> Builder:
    """Hopsan's math blocks (Signal/MathFunctions/Signal<Name>.hpp, Signal/Arithmetics/SignalSquare.hpp and
    SignalSign.hpp) as a Function with that option; their ``error`` output where they have one (sqrt, log,
    log10, asin, acos), atan2's inputs ``inY`` and ``inX``."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Function

        outputs = {"out": f"{n}.y"}
        if function in ("sqrt", "log", "log10", "asin", "acos"):
            outputs["error"] = f"{n}.error"
        inputs = {"inY": f"{n}.u", "inX": f"{n}.u2"} if function == "atan2" else {"in": f"{n}.u"}
        return Mapped([Function(n, function=function)], inputs=inputs, outputs=outputs)

    return build


def _rate_limiter(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import RateLimiter

    # SignalRateLimiter.hpp: the output steps by c Ts towards the input (c_up rising, c_down falling), or onto it
    c_up, c_down = par("c_up", 1.0), par("c_down", -1.0)
    if c_up < 0.0 or c_down > 0.0:
        par.problems.append(
            f"{par.where}: c_up = {c_up:g}, c_down = {c_down:g}: expected c_up >= 0 and c_down <= 0 (a limit of the "
            "wrong sign makes Hopsan's output move away from its input)"
        )
        return Mapped()
    # Hopsan's output starts at its input: the file's start value of 'in', or what drives it at the start
    comp = RateLimiter(n, c_up=c_up, c_down=c_down, y0=par("in", 0.0))
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"},
                  start_from_input={f"{n}.y0": (f"{n}.u", float)})


def _dead_zone(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import DeadZone

    comp = DeadZone(n, u_dstart=par("u_dstart", -1.0), u_dend=par("u_dend", 1.0))
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _sum_chain(n: str, gains: list[float]) -> tuple[list[cbase.Component], list[str], list[tuple[str, str]]]:
    """Sums of three inputs chained (``n``, ``n_sum2``, ...: each further one adds two inputs and passes its total
    on to the one before) for ``gains`` (at least three: the weights of the inputs in turn); the Sums, their
    inputs in the order of ``gains``, and the internal links."""
    from hydroservo.components import Sum

    count = max(len(gains), 3)
    gains = [*gains, *[1.0] * (count - len(gains))]
    slots = [(0, 1), (0, 2)]
    k = 1
    while len(slots) + 1 < count:
        slots += [(k, 1), (k, 2)]
        k += 1
    slots.append((k - 1, 3))
    weights = [[1.0, 1.0, 1.0] for _ in range(k)]
    for (which, i), gain in zip(slots, gains):
        weights[which][i - 1] = gain
    names = [n, *(f"{n}_sum{j + 1}" for j in range(1, k))]
    sums: list[cbase.Component] = [Sum(m, gain1=w[0], gain2=w[1], gain3=w[2]) for m, w in zip(names, weights)]
    internal = [(f"{names[j]}.y", f"{names[j - 1]}.u3") for j in range(1, k)]
    return sums, [f"{names[w]}.u{i}" for w, i in slots], internal


def _sum(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """Hopsan's multiport sum: one ``Sum`` of three inputs, chained through further ones (``n_sum2``, ...) where
    more signals are connected (each further sum adds two inputs and passes its total on)."""
    sums, inputs, internal = _sum_chain(n, [1.0] * par.fan_in.get("in", 0))
    return Mapped(sums, multi={"in": inputs}, outputs={"out": f"{n}.y"}, internal=internal,
                  note="" if len(sums) == 1 else f"{len(sums)} Sums chained ({n}, ...), {len(inputs)} inputs")


def _low_pass(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Lag

    if abs(par("y_min", -1.5e300)) < 1e299 or abs(par("y_max", 1.5e300)) < 1e299:
        par.problems.append(f"{par.where}: a low-pass filter with output limits is not supported yet")
    comp = Lag(n, K=1.0, tau=1.0 / par("omega", 1000.0), y0=par("out", 0.0))
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _transfer(n: str, par: _Params, num: list[float], den: list[float], limited: bool = True) -> Mapped:
    """Hopsan's filters and transfer functions (num, den: coefficients of s^0, s^1, s^2) as a TransferFunction,
    their continuous law (Hopsan discretises it by the bilinear transform); its output starts at Hopsan's start
    value of ``out``, with the input at its start value ``in`` (Hopsan's FirstOrderTransferFunction.cpp)."""
    from hydroservo.components import TransferFunction

    if limited and (abs(par("y_min", -1.5e300)) < 1e299 or abs(par("y_max", 1.5e300)) < 1e299):
        par.problems.append(f"{par.where}: a filter with output limits (y_min, y_max) is not supported yet")
    num, den = [*num, 0.0, 0.0][:3], [*den, 0.0, 0.0][:3]
    order = 2 if den[2] != 0.0 else 1
    if den[order] == 0.0 or (order == 1 and num[2] != 0.0):
        par.problems.append(f"{par.where}: a transfer function with no s term in its denominator is not supported")
        return Mapped()
    d = num[order] / den[order]  # the direct part
    y0, u0 = par("out", 0.0), par("in", 0.0)
    comp = TransferFunction(
        n, order=str(order), a0=num[0], a1=num[1], a2=num[2], b0=den[0], b1=den[1], b2=den[2], y0=y0 - d * u0
    )
    initial = {}
    c1 = num[1] / den[2] - d * den[1] / den[2] if order == 2 else 0.0
    if order == 2:  # the strictly proper part at rest with the input at u0: its rate x2 + c1 u0 is 0
        initial[f"{n}.x2"] = -c1 * u0
    # Hopsan's filter starts from the value its input has when the model is initialised (FirstOrderTransferFunction
    # ::initialize's u0 is *mpIn): where a signal drives the input, that signal's start value, not the file's 'in'
    starts: dict[str, tuple[str, Callable[[float], float]]] = {f"{n}.y0": (f"{n}.u", lambda u: y0 - d * u)}
    if order == 2:
        starts[f"{n}.x2"] = (f"{n}.u", lambda u: -c1 * u)
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"}, initial=initial,
                  start_from_input=starts)


def _first_order_filter(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalFirstOrderFilter.hpp: k (s/omega_num + 1)/(s/omega_den + 1)
    k = par("k", 1.0)
    return _transfer(n, par, [k, k / par("omega_num", 1e10)], [1.0, 1.0 / par("omega_den", 1000.0)])


def _high_pass(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalHP1Filter.hpp: (s/omega)/(s/omega + 1)
    w = par("omega", 1000.0)
    return _transfer(n, par, [0.0, 1.0 / w], [1.0, 1.0 / w])


def _low_pass2(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalLP2Filter.hpp: 1/(s^2/omega^2 + 2 delta s/omega + 1)
    w = par("omega", 1000.0)
    return _transfer(n, par, [1.0], [1.0, 2.0 * par("delta", 1.0) / w, 1.0 / (w * w)])


def _second_order_filter(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalSecondOrderFilter.hpp: k (s^2/omega_1^2 + 2 delta_1 s/omega_1 + 1)/(s^2/omega_2^2 + 2 delta_2 s/omega_2 + 1)
    k, w1, w2 = par("k", 1.0), par("omega_1", 1e10), par("omega_2", 1000.0)
    num = [k, 2.0 * k * par("delta_1", 1.0) / w1, k / (w1 * w1)]
    return _transfer(n, par, num, [1.0, 2.0 * par("delta_2", 1.0) / w2, 1.0 / (w2 * w2)])


def _high_pass2(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalHP2Filter.hpp: (s^2/omega^2)/(s^2/omega^2 + 2 delta s/omega + 1)
    w = par("omega", 1000.0)
    return _transfer(n, par, [0.0, 0.0, 1.0 / (w * w)], [1.0, 2.0 * par("delta", 1.0) / w, 1.0 / (w * w)])


def _first_order_tf(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalFirstOrderTransferFunction.hpp: (a_1 s + a_0)/(b_1 s + b_0), no output limits
    num = [par("a_0", 1.0), par("a_1", 1.0)]
    return _transfer(n, par, num, [par("b_0", 1.0), par("b_1", 1.0)], limited=False)


def _second_order_tf(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    # SignalSecondOrderTransferFunction.hpp: (a_2 s^2 + a_1 s + a_0)/(b_2 s^2 + b_1 s + b_0), no output limits
    num = [par(f"a_{i}", 1.0) for i in range(3)]
    return _transfer(n, par, num, [par(f"b_{i}", 1.0) for i in range(3)], limited=False)


def _route(inputs: int) -> Builder:
    """SignalDualRoute, SignalTripleRoute, SignalQuadRoute: a Selector with the limits after the last input at
    1e300 (never reached)."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Selector

        if inputs == 2:
            limits = [par("limit", 0.5), 1e300, 1e300]
        else:
            limits = [par("limit12", 0.5), par("limit23", 1.5), par("limit34", 2.5) if inputs == 4 else 1e300]
        comp = Selector(n, limit12=limits[0], limit23=limits[1], limit34=limits[2])
        ports = {f"in{i}": f"{n}.u{i}" for i in range(1, inputs + 1)}
        return Mapped([comp], inputs={**ports, "route": f"{n}.route"}, outputs={"out": f"{n}.y"})

    return build




def _square_wave(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Square

    # SignalSquareWave.hpp: y_0 before t_start, then y_0 + y_A while sin(2 pi f (t - t_start)) >= 0, else y_0 - y_A
    t0 = par.source_time("t_start", 0.0)
    comp = Square(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), frequency=par("f", 1.0), t_start=t0)
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _pulse_wave(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import PulseWave

    t0 = par.source_time("t_start", 0.0)
    comp = PulseWave(
        n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), period=par("dT", 1.0), duty=par("D", 0.5), t_start=t0
    )
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _staircase(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Staircase

    t0 = par.source_time("T_start", 0.0)
    comp = Staircase(n, height=par("H_step", 1.0), width=par("W_step", 1.0), t_start=t0)
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _step_exponential_delay(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import DecayingStep

    t0 = par.source_time("t_step", 1.0)
    comp = DecayingStep(n, offset=par("y_0", 0.0), amplitude=par("y_A", 1.0), tau=par("tao", 1.0), t_step=t0)
    return Mapped([comp], outputs={"out": f"{n}.y"})


def _time(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Ramp

    # SignalTime.hpp: Hopsan's time, which is hydroservo's plus the model's start time
    return Mapped([Ramp(n, offset=par.t0, slope=1.0, t_start=0.0)], outputs={"out": f"{n}.y"})


def _saturation(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Saturation

    comp = Saturation(n, lower=par("y_lower", -1.0), upper=par("y_upper", 1.0))
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _integrator(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    from hydroservo.components import Integrator

    return Mapped([Integrator(n, y0=par("out", 0.0))], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _table_file(par: _Params, folder: Path, filename: str) -> Path:
    """The table file ``filename`` a lookup table names, inside the model file's ``folder`` (a file named by an
    absolute path or outside it is refused: a model file from someone else reads nothing else of the user's
    disk)."""
    if not filename:
        raise ModelFileError(f"{par.where}: no table: neither a file (filename) nor a text (text) given")
    folder = folder.resolve()
    file = (folder / filename).resolve()
    if Path(filename).is_absolute() or not file.is_relative_to(folder):
        raise ModelFileError(
            f"{par.where}: filename = {filename!r}: outside the model file's folder {str(folder)!r}; hydroservo "
            "reads a table only beside the model or below its folder (copy it there and name it relative "
            "to the model)"
        )
    return file


def _input_table(
    n: str,
    par: _Params,
    parse: Callable[[str, str], tuple[Any, Any]],
    read: Callable[[Path, str], tuple[Any, Any]],
) -> Mapped:
    """A Table of its input (``index = "input"``) whose breakpoints and values Hopsan's table block reads from its
    ``text`` or, else, its file ``filename`` (inside the model file's folder: :func:`_table_file`): ``parse(text,
    what)`` or ``read(file, what)``. Probed for its ports outside an import, it reads nothing."""
    from hydroservo.components import Table
    from hydroservo.errors import HydroservoError

    inputs, outputs = {"in": f"{n}.u"}, {"out": f"{n}.y"}
    if par.folder is None:  # probed for its ports (_takes_as_input), outside an import: no file is read
        return Mapped([Table(n, times=[0.0, 1.0], values=[0.0, 0.0], index="input")], inputs=inputs, outputs=outputs)
    text, filename = par.text("text").strip(), par.text("filename").strip()
    try:
        if text:
            x, y = parse(par.text("text"), f"{par.where}: text")
        else:
            x, y = read(_table_file(par, par.folder, filename), f"{par.where}: filename")
    except HydroservoError as exc:
        par.problems.append(str(exc))
        return Mapped()
    comp = Table(n, times=x, values=y, index="input")
    return Mapped([comp], inputs=inputs, outputs=outputs,
                  note=f"Table {n} (index = input), {x.size} rows of {text and 'its text' or repr(filename)}")


def _lookup_table(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """Signal1DLookupTable (Signal/Non-Linearities/Signal1DLookupTable.hpp): a Table with ``index = "input"``,
    its breakpoints and values columns ``inid`` and ``outid`` of the CSV file ``filename`` (or of the text
    ``text``), read at import as Hopsan reads them (``csvsep``, ``numlineskip``, ``comment``). The file is
    read only inside the model file's folder: a file named by an absolute path or outside it is refused (a
    model file from someone else reads nothing else of the user's disk); ``reload`` is moot (the table is
    read once, at import)."""
    from hydroservo.io.tables import parse_lookup_table, read_lookup_table

    inid, outid, skip = int(par("inid", 0)), int(par("outid", 1)), int(par("numlineskip", 0))
    sep, comment = par.text("csvsep", ","), par.text("comment", "")
    return _input_table(
        n, par,
        lambda text, what: parse_lookup_table(text, inid, outid, sep, skip, comment, what=what),
        lambda file, what: read_lookup_table(file, inid, outid, sep, skip, comment, what=what),
    )


def _plo_lookup_table(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """Signal1DPLOLookupTable (Signal/Non-Linearities/Signal1DPLOLookupTable.hpp): Signal1DLookupTable's law
    (a Table with ``index = "input"``), its breakpoints and values the columns named ``invar`` and ``outvar`` of
    the PLO file ``filename`` (or of the text ``text``), read at import as Hopsan's PLOParser reads them
    (:func:`hydroservo.io.tables.parse_plo_table`); the file only inside the model file's folder, as
    Signal1DLookupTable's; ``reload`` is moot."""
    from hydroservo.io.tables import parse_plo_table, read_plo_table

    invar, outvar = par.text("invar", "Time"), par.text("outvar", "Data")
    return _input_table(
        n, par,
        lambda text, what: parse_plo_table(text, invar, outvar, what=what),
        lambda file, what: read_plo_table(file, invar, outvar, what=what),
    )


def _table_of_lines(par: _Params, parse: Any, read: Any, kind: str) -> tuple[Any, ...] | None:
    """The table of a 2D or 3D lookup table, read as Hopsan reads it from its text ``text`` or, if none, the CSV
    file ``filename`` (inside the model file's folder); None, a problem noted, if it cannot be. Hopsan never hands
    ``numlineskip`` to these tables' parser (it reads every line): a value other than 0 is refused."""
    from hydroservo.errors import HydroservoError

    if par("numlineskip", 0.0) != 0.0:
        par.problems.append(f"{par.where}: numlineskip = {par('numlineskip', 0.0):g}: Hopsan's {kind} lookup table "
                            "never skips lines (it does not pass numlineskip to its parser); remove the lines or use "
                            "comment")
        return None
    comment = par.text("comment", "")
    text, filename = par.text("text").strip(), par.text("filename").strip()
    try:
        if text:
            return tuple(parse(par.text("text"), comment, what=f"{par.where}: text"))
        assert par.folder is not None  # its builder returned a probe's table without one
        return tuple(read(_table_file(par, par.folder, filename), comment, what=f"{par.where}: filename"))
    except HydroservoError as exc:
        par.problems.append(str(exc))
        return None


def _table_origin(par: _Params) -> str:
    return "its text" if par.text("text").strip() else repr(par.text("filename").strip())


def _lookup_table_2d(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """Signal2DLookupTable (Signal/Non-Linearities/Signal2DLookupTable.hpp): a Table2D of its inputs ``row`` and
    ``col``, bilinear and held at its edges as Hopsan's LookupTable2D, its table read at import from the CSV file
    ``filename`` (or the text ``text``) as Hopsan reads it (:func:`hydroservo.io.tables.parse_lookup_table_2d`),
    the file only inside the model file's folder, as Signal1DLookupTable's. Hopsan never hands ``numlineskip`` to
    its parser (it reads every line): a value other than 0 is refused; ``reload`` is moot."""
    from hydroservo.components import Table2D
    from hydroservo.io.tables import parse_lookup_table_2d, read_lookup_table_2d

    inputs, outputs = {"row": f"{n}.row", "col": f"{n}.col"}, {"out": f"{n}.y"}
    if par.folder is None:  # probed for its ports (_takes_as_input), outside an import: no file is read
        return Mapped([Table2D(n, rows=[0.0, 1.0], cols=[0.0, 1.0], values=[[0.0, 0.0], [0.0, 0.0]])], inputs=inputs,
                      outputs=outputs)
    table = _table_of_lines(par, parse_lookup_table_2d, read_lookup_table_2d, "2D")
    if table is None:
        return Mapped()
    r, c, v = table
    return Mapped([Table2D(n, rows=r, cols=c, values=v)], inputs=inputs, outputs=outputs,
                  note=f"Table2D {n}, {r.size} x {c.size} of {_table_origin(par)}")


def _lookup_table_3d(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """Signal3DLookupTable (Signal/Non-Linearities/Signal3DLookupTable.hpp): a Table3D of its inputs ``row``,
    ``col`` and ``plane``, trilinear and held at its edges as Hopsan's LookupTable3D, its table read at import from
    the CSV file ``filename`` (or the text ``text``) as Hopsan reads it
    (:func:`hydroservo.io.tables.parse_lookup_table_3d`), the file only inside the model file's folder, as
    Signal2DLookupTable's; ``numlineskip`` ≠ 0 refused (Hopsan never hands it to its parser), ``reload`` moot."""
    from hydroservo.components import Table3D
    from hydroservo.io.tables import parse_lookup_table_3d, read_lookup_table_3d

    inputs, outputs = {"row": f"{n}.row", "col": f"{n}.col", "plane": f"{n}.plane"}, {"out": f"{n}.y"}
    if par.folder is None:  # probed for its ports (_takes_as_input), outside an import: no file is read
        zero = [[[0.0, 0.0], [0.0, 0.0]], [[0.0, 0.0], [0.0, 0.0]]]
        return Mapped([Table3D(n, rows=[0.0, 1.0], cols=[0.0, 1.0], planes=[0.0, 1.0], values=zero)],
                      inputs=inputs, outputs=outputs)
    table = _table_of_lines(par, parse_lookup_table_3d, read_lookup_table_3d, "3D")
    if table is None:
        return Mapped()
    r, c, q, v = table
    return Mapped([Table3D(n, rows=r, cols=c, planes=q, values=v)], inputs=inputs, outputs=outputs,
                  note=f"Table3D {n}, {r.size} x {c.size} x {q.size} of {_table_origin(par)}")


def _unit_delay(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalUnitDelay (Signal/Non-Linearities/SignalUnitDelay.hpp): its output is its input one step late,
    which vanishes as the step does: in the limit it passes its input on (a Gain of 1). In Hopsan it breaks
    algebraic loops; a loop it closed with no state in it is refused after the import (:func:`import_hopsan`)."""
    from hydroservo.components import Gain

    return Mapped([Gain(n, K=1.0)], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"},
                  note=f"Gain {n} of 1 (a delay of one step, which vanishes with the step)")


def _integral_start(n: str, par: _Params, ki: float) -> dict[str, float]:
    """The PID's integral state from Hopsan's start value of ``uI`` (the integral part, Ki I)."""
    u_i = par("uI", 0.0)
    if u_i != 0.0 and ki == 0.0:
        par.problems.append(f"{par.where}: a start value uI = {u_i:g} with no integral gain is not supported")
    return {f"{n}.I": u_i / ki} if u_i != 0.0 and ki != 0.0 else {}


def _pid(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalPID (Signal/Control/SignalPID.hpp): u = limit(uI + Kp (yref - y) - Kd dy, umin, umax) with
    d(uI)/dt = KI Ierr, Ierr the error while the output is inside its limits (Hopsan's dxLimit, 1e-9 at them):
    a ``Sum`` (yref - y) into a PID with ``derivative = "input"`` (de = dy, Kd negated) and
    ``anti_windup = "clamping"``. Hopsan's Newton iteration and trapezoidal step of that law vanish with the
    step. Kp, KI, Kd, umin and umax are constant (a signal driving them is refused)."""
    from hydroservo.components import PID, Sum

    ki = par("KI", 1.0)
    umin, umax = par("umin", -1.0), par("umax", 1.0)
    if umin >= umax:
        par.problems.append(f"{par.where}: umin = {umin:g}, umax = {umax:g}: expected umin < umax")
        return Mapped()
    error = Sum(f"{n}_error", gain1=1.0, gain2=-1.0)
    pid = PID(n, Kp=par("Kp", 1.0), Ki=ki, Kd=-par("Kd", 1.0), lower=umin, upper=umax, derivative="input",
              anti_windup="clamping")
    return Mapped(
        [error, pid], inputs={"yref": f"{error.name}.u1", "y": f"{error.name}.u2", "dy": f"{n}.de"},
        outputs={"u": f"{n}.y"}, values={"uI": Var(1.0, f"{n}.I", text=f"{n}.Ki*{n}.I", unit="")}, internal=[(f"{error.name}.y", f"{n}.e")],
        initial=_integral_start(n, par, ki),
    )


def _pid2(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalPID2 (Signal/Control/SignalPID2.hpp): v = K e + I + K Td de, I' = K/Ti e, plus (Umax - v)/Tt above
    Umax and (Umin - v)/Tt below Umin (back-calculation; Hopsan's explicit steps of it), the output v limited to
    [Uoutmin, Uoutmax]: a PID with ``anti_windup = "tracking"`` (Ki = K/Ti, T_t = Tt, the tracked limits Umin and
    Umax). The derivative is the input ``de`` where it is connected (``derivative = "input"``); Hopsan's
    derivative of ``e`` by a backward difference otherwise, which is refused for Td > 0 (an unfiltered
    derivative). Starts with I = 0, as Hopsan's."""
    from hydroservo.components import PID

    k, ti, tt, td = par("K", 1.0), par("Ti", 1.0), par("Tt", 1.0), par("Td", 0.0)
    lims = {name: par(name, default) for name, default in
            (("Umin", -1e100), ("Umax", 1e100), ("Uoutmin", -1e100), ("Uoutmax", 1e100))}
    if ti <= 0.0 or tt <= 0.0 or k == 0.0:
        par.problems.append(f"{par.where}: K = {k:g}, Ti = {ti:g} s, Tt = {tt:g} s: expected K other than 0, Ti > 0 "
                            "and Tt > 0")
        return Mapped()
    if lims["Umin"] > lims["Umax"] or lims["Uoutmin"] > lims["Uoutmax"]:
        par.problems.append(f"{par.where}: Umin > Umax or Uoutmin > Uoutmax")
        return Mapped()
    by_input = "de" in par.driven
    if td != 0.0 and not by_input:
        par.problems.append(
            f"{par.where}: Td = {td:g} s with 'de' unconnected: Hopsan then differentiates e unfiltered (a backward "
            "difference), which hydroservo does not; connect the derivative to 'de'"
        )
        return Mapped()
    ki = k / ti
    if ki < 0.0:
        par.problems.append(f"{par.where}: K = {k:g}: a negative gain with anti-windup tracking is not supported")
        return Mapped()
    cap = 1e300  # Hopsan's +-1e100 defaults: no limit
    pid = PID(n, Kp=k, Ki=ki, Kd=k * td, T_t=tt, anti_windup="tracking",
              derivative="input" if by_input else "filtered",
              track_lower=max(lims["Umin"], -cap), track_upper=min(lims["Umax"], cap),
              lower=max(lims["Uoutmin"], -cap), upper=min(lims["Uoutmax"], cap))
    inputs = {"e": f"{n}.e", **({"de": f"{n}.de"} if by_input else {})}
    return Mapped([pid], inputs=inputs, outputs={"u": f"{n}.y"})


def _pi_lead(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalPIlead (Signal/Control/SignalPIlead.hpp): a PI controller on the error of a lead-filtered
    measurement. Hopsan's bilinear equation for ``err`` is the transfer function
    err = yref - (1 + 2 da s/wa)/(1 + s/wa) y; u = limit(k1 err + uI, umin, umax), d(uI)/dt = k1 wa Ierr with
    k1 = wa/kx and Ierr the error while u is inside its limits: a ``TransferFunction`` (the lead, at rest with
    its input's start value), a ``Sum`` and a PID with ``anti_windup = "clamping"`` (Kp = k1, Ki = k1 wa). wa, kx,
    da, umin and umax are constant (a signal driving them is refused)."""
    from hydroservo.components import PID, Sum, TransferFunction

    wa, kx, da = par("wa", 1.0), par("kx", 1.0), par("da", 1.0)
    umin, umax = par("umin", -1.0), par("umax", 1.0)
    if wa <= 0.0 or kx == 0.0 or da <= 0.0 or umin >= umax:
        par.problems.append(f"{par.where}: wa = {wa:g}, kx = {kx:g}, da = {da:g}, umin = {umin:g}, umax = {umax:g}: "
                            "expected wa > 0, kx other than 0, da > 0 and umin < umax")
        return Mapped()
    k1 = wa / kx
    d = 2.0 * da  # the lead's direct part a1/b1
    y0 = par("y", 0.0)
    lead = TransferFunction(f"{n}_lead", order="1", a0=1.0, a1=2.0 * da / wa, b0=1.0, b1=1.0 / wa, y0=(1.0 - d) * y0)
    error = Sum(f"{n}_err", gain1=1.0, gain2=-1.0)
    pid = PID(n, Kp=k1, Ki=k1 * wa, lower=umin, upper=umax, anti_windup="clamping")
    return Mapped(
        [lead, error, pid], inputs={"yref": f"{error.name}.u1", "y": f"{lead.name}.u"},
        outputs={"u": f"{n}.y", "err": f"{error.name}.y"}, values={"uI": Var(1.0, f"{n}.I", text=f"{n}.Ki*{n}.I", unit="")},
        internal=[(f"{lead.name}.y", f"{error.name}.u2"), (f"{error.name}.y", f"{n}.e")],
        initial=_integral_start(n, par, k1 * wa),
        start_from_input={f"{lead.name}.y0": (f"{lead.name}.u", lambda u0: (1.0 - d) * u0)},
    )


def _logic(function: str, ports: tuple[str, str]) -> Builder:
    """Hopsan's comparisons and logic (Signal/Logic/SignalGreaterThan.hpp, SignalSmallerThan.hpp, SignalAnd.hpp,
    SignalOr.hpp): a Function with that option, its two inputs ``u`` and ``u2`` (``in`` and ``x_limit``, or
    ``in1`` and ``in2``); an unconnected one takes its start value."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Function

        inputs = {ports[0]: f"{n}.u", ports[1]: f"{n}.u2"}
        return Mapped([Function(n, function=function)], inputs=inputs, outputs={"out": f"{n}.y"})

    return build


def _round_port(function: str, output: str) -> Builder:
    """SignalSegare and SignalDxSegare ([Hopsan2026] Signal/Non-Linearities/SignalSegare.hpp, SignalDxSegare.hpp):
    the opened area (output ``area``) and width (``width``) of a round port of diameter ``diameter`` uncovered by
    ``x`` (HopsanCore's segare and dxSegare), stateless: a Function with option ``round_port_area`` or
    ``round_port_width``, ``x`` its ``u``, ``diameter`` its ``u2``; an unconnected one takes its start value.
    Hopsan's laws divide by the diameter (0 gives NaN); hydroservo's give 0 there."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Function

        inputs = {"x": f"{n}.u", "diameter": f"{n}.u2"}
        return Mapped([Function(n, function=function)], inputs=inputs, outputs={output: f"{n}.y"})

    return build


def _hysteresis(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalHysteresis (Signal/Non-Linearities/SignalHysteresis.hpp): a Hysteresis of width ``y_h`` (constant: a
    signal driving it is refused), its output starting at its input's start value, as Hopsan's."""
    from hydroservo.components import Hysteresis

    width = par("y_h", 1.0)
    if width < 0.0:
        par.problems.append(f"{par.where}: y_h = {width:g}: expected a width of 0 or more")
        return Mapped()
    comp = Hysteresis(n, band=width, y0=par("in", 0.0))
    return Mapped([comp], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"},
                  start_from_input={f"{n}.y0": (f"{n}.u", float)})


def _sr_latch(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalSRlatch (Signal/Logic/SignalSRlatch.hpp): a Latch from the start value of ``Qstate``, its inputs
    ``setCond`` and ``resetCond``, its outputs ``Qstate`` and ``notQstate``."""
    from hydroservo.components import Latch

    q0 = par("Qstate", 0.0)
    if not 0.0 <= q0 <= 1.0:
        par.problems.append(f"{par.where}: start value Qstate = {q0:g}: expected 0 to 1")
        return Mapped()
    return Mapped([Latch(n, Q0=q0)], inputs={"setCond": f"{n}.set", "resetCond": f"{n}.reset"},
                  outputs={"Qstate": f"{n}.Q", "notQstate": f"{n}.notQ"})


def _not(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalNot (Signal/Logic/SignalNot.hpp): 1 where ``in`` is 0.5 or less (Hopsan's doubleToBool), else 0: a
    Function with ``function = "not"``."""
    from hydroservo.components import Function

    return Mapped([Function(n, function="not")], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _extreme(function: str) -> Builder:
    """SignalMax and SignalMin (Signal/Arithmetics/SignalMax.hpp, SignalMin.hpp): the largest or smallest of the
    signals joining their one port ``in``: a Function with ``function = "max"`` (``"min"``) of two of them,
    chained through further ones (``n_max2``, ...) for each further signal; one signal passes on (a Gain of
    1), none gives 0 (Hopsan reads a node of 0)."""

    def build(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
        from hydroservo.components import Constant, Function, Gain

        count = par.fan_in.get("in", 0)
        if count == 0:
            return Mapped([Constant(n, value=0.0)], outputs={"out": f"{n}.y"})
        if count == 1:
            return Mapped([Gain(n, K=1.0)], multi={"in": [f"{n}.u"]}, outputs={"out": f"{n}.y"})
        names = [n, *(f"{n}_{function}{j}" for j in range(2, count))]
        blocks: list[cbase.Component] = [Function(m, function=function) for m in names]
        inputs = [f"{n}.u", f"{n}.u2", *(f"{m}.u2" for m in names[1:])]
        internal = [(f"{a}.y", f"{b}.u") for a, b in zip(names, names[1:])]
        return Mapped(blocks, multi={"in": inputs}, outputs={"out": f"{names[-1]}.y"}, internal=internal,
                      note="" if count == 2 else f"{len(names)} Functions ({function}) chained ({n}, ...)")

    return build


def _sub(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalSub (Signal/Arithmetics/SignalSub.hpp): the sum of the signals joining its port ``insum`` less that
    of those joining ``insub`` (SignalSubtract's two ports are ``in1`` and ``in2``): Sums chained as
    SignalSum's, each signal of ``insub`` weighted -1."""
    n_sum, n_sub = par.fan_in.get("insum", 0), par.fan_in.get("insub", 0)
    sums, inputs, internal = _sum_chain(n, [1.0] * n_sum + [-1.0] * n_sub)
    return Mapped(sums, multi={"insum": inputs[:n_sum], "insub": inputs[n_sum:n_sum + n_sub]},
                  outputs={"out": f"{n}.y"}, internal=internal,
                  note="" if len(sums) == 1 else f"{len(sums)} Sums chained ({n}, ...), {len(inputs)} inputs")


def _counter(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalCounter (Signal/Logic/SignalCounter.hpp): the count of the edges of ``in`` (crossings of 0.5), rising
    ones where ``r``, falling ones where ``f``: a Counter with ``edges = "both"``, ``"rising"`` or ``"falling"``;
    neither counted, Hopsan's output stays 0 (a Gain of 0)."""
    from hydroservo.components import Counter, Gain

    rising, falling = par("r", 1.0) != 0.0, par("f", 1.0) != 0.0
    if not (rising or falling):
        return Mapped([Gain(n, K=0.0)], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"},
                      note=f"Gain {n} of 0 (r and f false: it counts nothing)")
    edges = "both" if rising and falling else "rising" if rising else "falling"
    return Mapped([Counter(n, edges=edges)], inputs={"in": f"{n}.u"}, outputs={"out": f"{n}.y"})


def _sink(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    return Mapped(note="dropped: a plot window; what it shows is logged at its sources")


def _display(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalDisplay, SignalAnimationGauge and SignalAnimationLamp (Signal/Animation/): they show their input in
    Hopsan's GUI and compute nothing; dropped as SignalSink is."""
    return Mapped(note="dropped: shows its input in Hopsan's GUI; what it shows is logged at its source")


def _logger(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalLogger (Signal/Sources&Sinks/SignalLogger.hpp): it writes its inputs to a file (``path``) and
    computes nothing; dropped (hydroservo's result holds what it logs)."""
    return Mapped(note=f"dropped: writes its inputs to {par.text('path') or 'a file'}; they are in the result")


def _numerical_input(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalNumericalInput and SignalAnimationSwitch (Signal/Animation/): an output ``out`` that Hopsan's GUI sets
    while it runs and that stays at its start value in a run without the GUI: a Constant at that value."""
    from hydroservo.components import Constant

    return Mapped([Constant(n, value=par("out", 0.0))], outputs={"out": f"{n}.y"})


def _slider(hc: HopsanComponent, n: str, par: _Params) -> Mapped:
    """SignalAnimationSlider (Signal/Animation/SignalAnimationSlider.hpp): out = min + (max - min) in, ``in``
    set by Hopsan's GUI (its start value where nothing drives it): a Sum of gain max - min and offset min."""
    from hydroservo.components import Sum

    lo, hi = par("min", 0.0), par("max", 1.0)
    return Mapped([Sum(n, gain1=hi - lo, gain2=0.0, gain3=0.0, offset=lo)], inputs={"in": f"{n}.u1"},
                  outputs={"out": f"{n}.y"})


#: Hopsan type -> the function that maps it (each follows the Hopsan component file of that name in
#: ``componentLibraries/defaultLibrary``).
LIBRARY: dict[str, Builder] = {
    "HydraulicTankC": _tank,
    "HydraulicMultiTankC": _tank,
    "HydraulicPressureSourceC": _pressure_source,
    "HydraulicMultiPressureSourceC": _pressure_source,
    "HydraulicFlowSourceQ": _flow_source,
    "HydraulicLaminarOrifice": _laminar_orifice,
    "HydraulicTurbulentOrifice": _turbulent_orifice,
    "HydraulicCheckValve": _check_valve,
    "HydraulicShuttleValve": _shuttle_valve,
    "HydraulicPilotControlledCheckValve": _pilot_check_valve,
    "HydraulicPilotClosableCheckValve": _pilot_check_valve,
    "HydraulicCheckValvePreLoaded": _check_valve,
    "HydraulicCheckValveWithOrifice": _check_valve_with_orifice,
    "Hydraulic22DirectionalCheckValve": _directional_check_valve,
    "HydraulicOrificeG": _orifice_g,
    "HydraulicOrificeCheckValveG": _orifice_g,
    "HydraulicSlitOrifice": _slit_orifice,
    "Hydraulic22PoppetValve": _poppet_valve,
    "Hydraulic33ShuttleValve": _shuttle_valve33,
    "HydraulicValve43": _valve43_special,
    "HydraulicValve63OC": _valve63_open_centre,
    "HydraulicValve43LS": _valve43_ls,
    "HydraulicPressureRelief2ValveG": _pressure_valve_g(reducing=False, mass=True),
    "HydraulicMotorJload": _motor_jload,
    "HydraulicPiston": _piston,
    "HydraulicFuelTankG": _fuel_tank,
    "HydraulicPressureControlledPumpG": _pressure_controlled_pump_g,
    "HydraulicVariableDisplacementPump": _variable_pump,
    "HydraulicPressureControlledPump": _pressure_controlled_pump,
    "MechanicVelocityTransformer": _velocity_source,
    "HydraulicVolume": _volume,
    "HydraulicVolumeMultiPort": _volume,
    "HydraulicPressureReliefValve": _relief,
    "HydraulicPressureDropValve": _pressure_drop_valve,
    "HydraulicPressureReducingValve": _reducing_valve,
    "HydraulicPressureControlledValve": _pressure_controlled_valve,
    "HydraulicPressureCompensatingValve": _compensating,
    "HydraulicAckumulator": _accumulator,
    "HydraulicPistonAckumulator": _piston_accumulator,
    "HydraulicPressureControlled22Valve": _pressure_controlled("22"),
    "HydraulicPressureControlled22Valve2": _pressure_controlled("22-2"),
    "HydraulicPressureControlled42Valve": _pressure_controlled("42"),
    "HydraulicPressureControlled42Valve2": _pressure_controlled("42-2"),
    "HydraulicPressureControlled42Valve3": _pressure_controlled("42-3"),
    "HydraulicPressureReliefValveG": _pressure_valve_g(reducing=False),
    "HydraulicPressureReducingValveG": _pressure_valve_g(reducing=True),
    "HydraulicCounterBalanceValveG": _pressure_valve_g(reducing=False, counterbalance=True),
    "HydraulicOverCenterValve": _over_center,
    "HydraulicPressureControlValveG": _pressure_valve_g(reducing=False, ported=True),
    "HydraulicPressureCompensatingValveG": _pressure_valve_g(reducing=True, ported=True),
    "HydraulicFixedDisplacementPump": _fixed_pump,
    "Hydraulic43Valve": _valve43,
    "HydraulicOpenCenterValve": _open_centre_valve,
    "Hydraulic43ValveNeutralSupplyToTank": _valve43_neutral,
    "Hydraulic43ValveNeutralToTank": _valve43_neutral,
    "Hydraulic43LoadSensingValve": _valve43_load_sensing,
    "Hydraulic42Valve": _valve42("one-sided", all_edges=False),
    "Hydraulic42Valve2": _valve42("one-sided", all_edges=True),
    "Hydraulic42DirectionalValve": _valve42("on-off", all_edges=True),
    "Hydraulic33Valve": _valve33,
    "HydraulicValve33": _valve33_special,
    "HydraulicValve416": _valve416,
    "HydraulicPressureControlValve33": _pressure_control_valve33,
    "Hydraulic32DirectionalValve": _valve32_directional,
    "Hydraulic22Valve": _valve22("one-sided", ("PP", "PA")),
    "Hydraulic22DirectionalValve": _valve22("on-off", ("P1", "P2")),
    "HydraulicCylinderC": _cylinder_c,
    "HydraulicCylinderQ": _cylinder_q,
    "HydraulicFourChamberPiston": _four_chamber_piston,
    "HydraulicPistonMload": _piston_mload,
    "HydraulicSpringLoadedPistonC": _spring_loaded_piston,
    "HydraulicPressureSourceQ": _pressure_source_q,
    "SignalSource": _constant_old,
    "HydraulicPistonMkload": _piston_mkload,
    "HydraulicPressureSensor": _sensor("Pressure", "Pa"),
    "HydraulicFlowSensor": _sensor("Flow", "m^3/s"),
    "HydraulicDifferentialPressureSensor": _differential_pressure_sensor,
    "HydraulicPowerSensor": _power_sensor,
    "HydraulicPlugQ": _plug,
    "HydraulicLosslessConnector": _lossless_connector,
    "HydraulicLosslessTConnector": _lossless_connector,
    "HydraulicTLMlossless": _tlm_lossless,
    "HydraulicHose": _hose,
    "MechanicTranslationalMass": _mass,
    "MechanicTranslationalMassWithCoulombFriction": _mass_coulomb,
    "MechanicTranslationalSpring": _spring,
    "MechanicFixedPosition": _fixed_position,
    "MechanicMultiPortTranslationalMass": _multiport_mass,
    "MechanicTranslationalMassWithCoulombFrictionAndMultiPorts": _multiport_mass,
    "MechanicFixedPositionMultiPort": _fixed_position_multiport,
    "MechanicPulley": _pulley,
    "MechanicSpring": _spring_free_length,
    "MechanicTranslationalSpringWithSlack": _spring_with_slack,
    "MechanicForceTransformer": _force_source,
    "MechanicPositionSensor": _sensor("Position", "m"),
    "MechanicSpeedSensor": _sensor("Velocity", "m/s"),
    "MechanicForceSensor": _sensor("Force", "N"),
    "MechanicRotationalInertia": _rotational_inertia,
    "MechanicTorqueTransformer": _torque_source,
    "MechanicTorsionalSpring": _torsional_spring,
    "MechanicGearShaft": _gear_shaft,
    "MechanicRotShaft": _shaft(lambda par: par("Ks", 1000.0)),
    "MechanicRotShaftG": _shaft(
        lambda par: math.pi / 32.0 * (par("dy", 0.02) ** 4 - par("di", 0.0) ** 4) * par("G", 7.93e10) / par("len", 0.1)
    ),
    "MechanicThetaSource": _theta_source,
    "MechanicAngularVelocityTransformer": _angular_velocity_source,
    "MechanicAngleSensor": _sensor("Angle", "rad"),
    "MechanicAngularVelocitySensor": _sensor("AngularVelocity", "rad/s"),
    "MechanicTorqueSensor": _sensor("Torque", "N*m"),
    "MechanicRotationalInertiaMultiPort": _rotational_inertia_multiport,
    "MechanicRackAndPinion": _rack_and_pinion,
    "MechanicFreeLengthWall": _free_length_wall,
    "MechanicRotationalInertiaWithCoulombFriction": _rotational_inertia_coulomb,
    "MechanicRotationalInertiaWithCoulumbFriction": _rotational_inertia_coulomb,  # older files' spelling
    "MechanicRotationalInertiaWithGearRatio": _rotational_inertia_gear,
    "MechanicRotationalInertiaWithSingleGear": _rotational_inertia_single_gear,
    "MechanicBallScrew": _ball_screw,
    "MechanicMotor": _mechanic_motor,
    "MechanicVehicle1D": _vehicle,
    "MechanicJLink": _jlink(two=False),
    "MechanicJLink2": _jlink(two=True),
    "MechanicTranslationalMassWithLever": _mass_lever,
    "MechanicMkcload1D": _mkc_load,
    "MechanicM2load1D": _m2_load,
    "HydraulicFixedDisplacementMotorQ": _motor_q("C_lm", variable=False),
    "HydraulicMachineC": _machine_c,
    "MechanicCylinderBlockWithSwashPlate": _cylinder_block,
    "MechanicSwashPlate": _swash_plate,
    "HydraulicPumpPiston": _pump_piston,
    "HydraulicValvePlate": _valve_plate,
    "HydraulicVariableDisplacementMotorQ": _motor_q("C_im", variable=True),
    "HydraulicCentrifugalPump": _centrifugal_pump,
    "HydraulicCentrifugalPumpJ": _centrifugal_pump_j,
    "SignalStep": _step,
    "SignalRamp": _ramp,
    "SignalSineWave": _sine,
    "SignalPulse": _pulse,
    "SignalSoftStep": _soft_step,
    "SignalConstant": _constant,
    "SignalGain": _gain,
    "SignalAdd": _sum_of_two(1.0),
    "SignalSubtract": _sum_of_two(-1.0),
    "SignalIntegrator2": _integrator,
    "SignalMultiply": _product,
    "SignalDivide": _quotient,
    "SignalAbsoluteValue": _absolute,
    "SignalPower": _power,
    "SignalSum": _sum,
    "SignalLP1Filter": _low_pass,
    "SignalSaturation": _saturation,
    "SignalFirstOrderFilter": _first_order_filter,
    "SignalHP1Filter": _high_pass,
    "SignalLP2Filter": _low_pass2,
    "SignalFirstOrderTransferFunction": _first_order_tf,
    "SignalSecondOrderTransferFunction": _second_order_tf,
    "SignalSquareWave": _square_wave,
    "SignalPulseWave": _pulse_wave,
    "SignalStaircase": _staircase,
    "SignalStepExponentialDelay": _step_exponential_delay,
    "SignalTime": _time,
    "SignalDualRoute": _route(2),
    "SignalTripleRoute": _route(3),
    "SignalQuadRoute": _route(4),
    "SignalSink": _sink,
    **{f"Signal{name}": _function(name.lower()) for name in (
        "Sqrt", "Exp", "Log", "Log10", "Sin", "Cos", "Tan", "Asin", "Acos", "Atan", "Atan2", "Sinh", "Cosh", "Tanh",
        "Square", "Sign",
    )},
    "SignalRateLimiter": _rate_limiter,
    "SignalDeadZone": _dead_zone,
    "Signal1DLookupTable": _lookup_table,
    "SignalUnitDelay": _unit_delay,
    "SignalPID": _pid,
    "SignalPID2": _pid2,
    "SignalPIlead": _pi_lead,
    "SignalFloor": _function("floor"),
    "SignalCeil": _function("ceil"),
    "SignalRound": _function("round"),
    "SignalGreaterThan": _logic("greater", ("in", "x_limit")),
    "SignalSmallerThan": _logic("smaller", ("in", "x_limit")),
    "SignalAnd": _logic("and", ("in1", "in2")),
    "SignalOr": _logic("or", ("in1", "in2")),
    "SignalSRlatch": _sr_latch,
    "SignalHysteresis": _hysteresis,
    "SignalSegare": _round_port("round_port_area", "area"),
    "SignalDxSegare": _round_port("round_port_width", "width"),
    "SignalMax": _extreme("max"),
    "SignalMin": _extreme("min"),
    "SignalSub": _sub,
    "SignalNot": _not,
    "SignalXor": _logic("xor", ("in1", "in2")),
    "SignalSecondOrderFilter": _second_order_filter,
    "SignalHP2Filter": _high_pass2,
    "SignalDisplay": _display,
    "SignalAnimationGauge": _display,
    "SignalAnimationLamp": _display,
    "SignalLogger": _logger,
    "SignalNumericalInput": _numerical_input,
    "SignalAnimationSwitch": _numerical_input,
    "SignalAnimationSlider": _slider,
    "SignalCounter": _counter,
    "Signal1DPLOLookupTable": _plo_lookup_table,
    "Signal2DLookupTable": _lookup_table_2d,
    "HydraulicCSource": _c_source,
    "HydraulicQSource": _q_source,
    "MechanicTranslationalCSource": _mechanic_c_source,
    "MechanicTranslationalQSource": _mechanic_q_source,
    "HydraulicNodeSensor": _node_sensor((("p", "Pressure", "Pa"), ("q", "Flow", "m^3/s")), ("c", "Zc")),
    "Signal3DLookupTable": _lookup_table_3d,
    "MechanicTranslationalLosslessConnector": _lossless_link,
    "MechanicNodeSensor": _node_sensor(
        (("out_f", "Force", "N"), ("out_v", "Velocity", "m/s"), ("out_x", "Position", "m")), ("out_c", "out_z", "out_em")
    ),
}

#: the mission-logic families of Hopsan's signal library, refused (:data:`REFUSED`)
_FFB_REASON = (
    "a function-flow block (Signal/SignalFFB/) is a state machine stepped once per Hopsan step: it detects an "
    "edge of its inputs as their change from the previous step and answers with 'exiting' pulses one step long "
    "(exiting = oldState onPositive(exit - oldExit - 0.5)), which vanish as the step does, so it has no limit "
    "as the step vanishes"
)
_ACTIVITY_REASON = (
    "an activity-diagram block (Signal/ActivityDiagram/) passes tokens over Hopsan's Petri-net nodes "
    "(NodePetriNet), one transition per Hopsan step from its previous step's state: a discrete state machine with "
    "no limit as the step vanishes, on a kind of node hydroservo has not"
)
_NAVIGATION_REASON = (
    "a flight-mission block (Signal/Navigation/: an aircraft's attitude and thrust-vector control, its earth "
    "coordinates and a mission clock with time compression, waypoints, a monitor of the mission's states) made "
    "to drive Hopsan's aeronautic models (Special/AeroComponents), which are outside hydroservo's physics"
)

#: Hopsan types refused on purpose, with why (named with the components of that type in the refusal)
REFUSED: dict[str, str] = {
    "SignalTimeDelay": "a pure time delay, y(t) = u(t - deltat), is no ordinary differential equation: hydroservo's "
    "engine integrates ODEs with error control and keeps no history of a signal, and an approximation (Padé) is "
    "not Hopsan's law",
    "SignalVariableTimeDelay": "a pure time delay, y(t) = u(t - dT), is no ordinary differential equation: "
    "hydroservo's engine integrates ODEs with error control and keeps no history of a signal, and an "
    "approximation (Padé) is not Hopsan's law",
    "SignalNoiseGenerator": "white noise drawn anew at each of Hopsan's steps has no limit as the step vanishes, "
    "and a random trace cannot be compared sample by sample",
    "SignalStopSimulation": "it ends the run when its input exceeds 0.5, where hydroservo's runs end at t_end; "
    "set t_end to where the model stops",
    "SignalJKlatch": "while both its inputs are set, Hopsan's JK latch toggles its output at every step "
    "(Signal/Logic/SignalJKlatch.hpp: Q_n = 1 - Q_n-1), which has no limit as the step vanishes, and the state it "
    "keeps after depends on the count of steps; an SR latch (SignalSRlatch) has a limit",
    "SignalTimestep": "it outputs Hopsan's fixed time step, which hydroservo's engine, choosing its steps by error "
    "control, has not",
    "SignalAdditiveNoise": "white noise drawn anew at each of Hopsan's steps has no limit as the step vanishes, "
    "and a random trace cannot be compared sample by sample",
    "SignalSteadyStateIdentifier": "its methods have no ODE form (Signal/Logic/SignalSteadyStateIdentifier.hpp): "
    "the rectangular window (method 1) compares the largest and smallest input over the last wl seconds, a history "
    "of the signal such as a time delay keeps and hydroservo's engine does not; the variance-ratio tests (2 and "
    "3) add white noise of deviation sd to the input at each step, which has no limit as the step vanishes, and "
    "method 3's filter factors l1, l2, l3 act per step (time constants of Ts/l that vanish with it)",
    "MechanicWormDrive": "its code (Mechanic/Rotational/MechanicWormDrive.hpp) is MechanicRotationalInertiaWith"
    "GearRatio's with the net torque limited to max(0, omega c1 - c2): nothing but its damping B ever slows the "
    "wheel, so a worm whose input stops or turns back does not stop it (the worm's port keeps turning with it and "
    "winds up the input shaft: -8200 Nm within a second in a test circuit), and it never turns backwards. That is "
    "no self-locking worm (which stops when its input does) nor any physical drive, so hydroservo reproduces it "
    "with none of its components",
    "MechanicGearClutch": "its generated code (Mechanic/Rotational/MechanicGearClutch.hpp) is the trapezoidal rule "
    "of Jg w2' = gearRatio T1 + T2 - Bg w2, the torque T2 at Pmr2 driving the gear where every other Q component "
    "takes it as a load (MechanicRotationalInertiaWithGearRatio: U T1 - T2; the .nb holds both signs, the later "
    "one kept): no power balance at Pmr2 (a spring there has negative stiffness). hydroservo's ports are "
    "power-conjugate, so it cannot reproduce that law, and the physical clutch (T1 limited to tmax by slip, "
    "which is sound) would run opposite to Hopsan's result; myfric and wc are in none of its equations",
    "SignalSampleAndHold": "its output jumps to its input's value at each sampling instant k/f_s and holds it "
    "(Signal/Non-Linearities/SignalSampleAndHold.hpp; in the limit y(t) = u(floor(t f_s)/f_s)): a state that "
    "jumps, which hydroservo's engine does not do (its events end a step at a switch, they reset no state), and a "
    "fast relaxation onto the input would not be Hopsan's law",
    **{name: _FFB_REASON for name in (
        "SignalFFB", "SignalFFBand", "SignalFFBandIn", "SignalFFBloop", "SignalFFBloopIn", "SignalFFBor",
        "SignalFFBorIn",
    )},
    **{f"ActivityDiagram{name}": _ACTIVITY_REASON for name in (
        "Action", "ActionN", "Connector", "Decision", "Edge", "Final", "FinalNode", "Fork", "ForkN",
        "InitiateState", "Join", "Join0", "JoinN", "Merge", "Merge0", "MergeN",
    )},
    **{f"Signal{name}": _NAVIGATION_REASON for name in (
        "AttitudeControl", "AttitudeTVCcontrol", "EarthCoordinates", "StateMonitor", "TimeAccelerator", "Waypoint",
    )},
}


@dataclass
class HopsanImport:
    """A Hopsan model imported: the system, and how each Hopsan component was mapped."""

    system: System
    model: HopsanModel
    mapping: list[tuple[str, str, str]]  #: (Hopsan path, Hopsan type, what it became)
    names: dict[str, str]  #: Hopsan path -> hydroservo component name
    variables: dict[str, str]  #: alias -> Hopsan's name of the variable (``Servo1$Valve#PA#Pressure``)
    #: Hopsan path -> the name it was given where hydroservo's rule for names refuses Hopsan's (a Python keyword,
    #: a name too long): said in the import's report and in the model file's header
    renamed: dict[str, str] = field(default_factory=dict)


def read_hopsan(path: str | Path, line_segments: int | None = None) -> System:
    """The Hopsan model file ``path`` as a hydroservo :class:`~hydroservo.system.system.System`.

    ``line_segments``: the lumped segments of each transmission line and hose (HydraulicTLMlossless,
    HydraulicHose); by default those that carry its waves up to the Nyquist frequency of Hopsan's time step,
    ceil(5 T/Ts) for a delay T, at most 200.

    Raises
    ------
    ModelFileError
        The file cannot be read (:func:`~hydroservo.io.hopsan.read_hmf`), or it holds components or settings that
        are not supported: each is listed with its path in the model.
    """
    return import_hopsan(path, line_segments).system


def import_hopsan(path: str | Path, line_segments: int | None = None) -> HopsanImport:
    """The Hopsan model file ``path`` imported: the system and the mapping (see :func:`read_hopsan`)."""
    from hydroservo.components import Constant
    from hydroservo.system.nodes import port_of
    from hydroservo.system.system import System

    model = _split_subports(read_hmf(path))
    source = str(path)
    problems: list[str] = []
    if line_segments is not None:
        from hydroservo.components import Line

        if isinstance(line_segments, bool) or not isinstance(line_segments, int) or not 1 <= line_segments <= Line.MAX_SEGMENTS:
            raise ModelFileError(f"line_segments = {line_segments!r}: expected a whole number from 1 to {Line.MAX_SEGMENTS}")
    seen_names: set[str] = set()
    heads: dict[str, str] = {}
    for hc in model.components:
        if hc.full_name in seen_names:
            problems.append(f"{source}: two components are named {hc.full_name!r}")
        seen_names.add(hc.full_name)
        head = _alias(hc.full_name)  # its variables' names, as Hopsan's (Ctl-x#out#Value is Ctl_x.out.Value)
        if head in heads and heads[head] != hc.full_name:
            problems.append(
                f"{source}: components {heads[head]!r} and {hc.full_name!r} would both name their variables "
                f"{head!r}.* (characters other than letters, digits and _ become _); expected names that differ "
                "in more than those characters: rename one of them in Hopsan"
            )
        heads.setdefault(head, hc.full_name)
    for connection in model.connections:
        for end in connection:
            if _end(end)[0] not in seen_names:
                problems.append(f"{source}: connection {' – '.join(connection)}: no component {_end(end)[0]!r} in the model")
    if not model.components:
        problems.append(f"{source}: no components; expected a Hopsan model with at least one component")
    if problems:
        raise ModelFileError("; ".join(problems))
    unsupported = [c for c in model.components if c.typename not in LIBRARY]
    if unsupported:
        listed = "; ".join(
            f"{c.full_name} ({c.typename}{': ' + REFUSED[c.typename] if c.typename in REFUSED else ''})"
            for c in unsupported
        )
        raise ModelFileError(
            f"{source}: {len(unsupported)} component(s) of types hydroservo does not map yet: {listed}. Supported: "
            f"{', '.join(sorted(LIBRARY))} (docs/hopsan.md)"
        )
    names: dict[str, str] = {}
    renamed: dict[str, str] = {}
    used: set[str] = set()
    mapped: dict[str, Mapped] = {}
    mapping: list[tuple[str, str, str]] = []
    by_name = {hc.full_name: hc for hc in model.components}
    multiports = {(c.full_name, p) for c in model.components for p in MULTIPORTS.get(c.typename, ())}
    node_start = _node_starts(model, by_name, multiports)
    connected: dict[str, frozenset[str]] = {}
    fan_in: dict[str, dict[str, int]] = {}
    for connection in model.connections:
        for owner, port in (_end(e) for e in connection):
            connected[owner] = connected.get(owner, frozenset()) | {port}
            counts = fan_in.setdefault(owner, {})
            counts[port] = counts.get(port, 0) + 1
    folded = _fold_constant_drives(model, by_name)  # parameters set by constant signals take their values
    for c, ports in folded.items():
        connected[c] = connected.get(c, frozenset()) - ports
    for hc in model.components:
        name = safe_name("_".join((*hc.path, hc.name)))
        if name != _plain_name("_".join((*hc.path, hc.name))):
            renamed[hc.full_name] = name
        base, k = name, 1
        while name in used:
            k += 1
            name = f"{base}_{k}"
        used.add(name)
        names[hc.full_name] = name
        where = f"{source}: {hc.full_name} ({hc.typename})"
        try:
            starts = {port: values for (c, port), values in node_start.items() if c == hc.full_name}
            params = _Params(hc, where, problems, starts, connected.get(hc.full_name, frozenset()),
                             fan_in.get(hc.full_name))
            params.t0 = model.start
            params.folder = Path(source).parent
            params.timestep, params.line_segments = model.timestep, line_segments
            m = LIBRARY[hc.typename](hc, name, params)
        except Exception as exc:  # a value out of a component's range: named with the Hopsan component
            problems.append(f"{where}: {exc}")
            continue
        mapped[hc.full_name] = m
        became = m.note or ", ".join(f"{type(c).__name__} {c.name}" for c in m.components)
        mapping.append((hc.full_name, hc.typename, became))
    if not _kept_components(mapped):
        problems.append(f"{source}: no component hydroservo keeps (each is a display, a sink or a logger, which "
                        "are dropped); expected a model with at least one component that is simulated")
    if problems:
        raise ModelFileError("; ".join(problems))

    system = System(safe_name(model.name or Path(source).stem), t_end=model.stop - model.start)
    system.description = model.description or f"imported from Hopsan model {Path(source).name}"
    system.notes.append(
        f"Imported from the Hopsan model {Path(source).name}, which Hopsan runs from {model.start:g} s to "
        f"{model.stop:g} s at a fixed step of {model.timestep:g} s; hydroservo chooses its steps by the accuracy "
        f"asked for. Hopsan's port variables are aliases named with dots (Mass#P2#Position is Mass.P2.Position)."
        + (f" Hydroservo's time is Hopsan's {'less' if model.start > 0 else 'plus'} {abs(model.start):g} s: its runs "
           "start at 0." if model.start else "")
    )
    system.source = source
    for m in mapped.values():
        for comp in m.components:
            system.add(comp)
    for m in mapped.values():
        for out, inp in m.internal:
            system.connect(out, inp)
        for state, first in m.initial.items():
            if first != 0.0:
                system.set_initial(state, first)

    # group Hopsan's connections into nodes: power ports (and read ports) by union; signal groups each hold one
    # output (or a component's value) and what reads it
    power_groups: list[list[tuple[str, str]]] = []
    signal_groups: list[list[tuple[str, str]]] = []
    for connection in model.connections:
        ends = [e for e in (_end(e) for e in connection) if e[1] not in folded.get(e[0], ())]
        if len(ends) < 2:
            continue  # a constant's value folded into the parameter it drove
        unknown = [(c, p) for c, p in ends if _port_kind(mapped.get(c), p) == "none" and not _is_input_variable(by_name[c], p)]
        if unknown and all(_port_kind(mapped.get(c), p) in ("dropped", "none") for c, p in ends):
            continue  # a scope showing a variable hydroservo does not name (a relief valve's own xv)
        for c, p in unknown:
            m_in = mapped[c]
            known = sorted({*m_in.power, *m_in.read, *m_in.inputs, *m_in.multi, *m_in.outputs, *m_in.values})
            problems.append(
                f"{source}: connection {' – '.join(connection)}: {by_name[c].typename} {c!r} has no port {p!r} that "
                f"hydroservo maps (its ports: {', '.join(known) or 'none'})"
                + (f": {m_in.unmapped[p]}" if p in m_in.unmapped else "")
            )
        if unknown:
            continue
        kinds = {_port_kind(mapped.get(c), p) for c, p in ends}
        (power_groups if kinds <= {"power", "read"} else signal_groups).append(ends)
    power_groups = _union(power_groups, multiports)

    connected_inputs: set[tuple[str, str]] = set()
    scopes: dict[str, list[str]] = {}  # a sink -> what it shows (Hopsan's outputs): the imported model's plots
    filled: dict[tuple[str, str], int] = {}  # a multi-input -> how many of its inputs are taken
    for ends in signal_groups:
        end_kinds = [_port_kind(mapped.get(c), p) for c, p in ends]
        sources = [e for e, k in zip(ends, end_kinds, strict=True) if k in ("output", "value")]
        joined = " – ".join(f"{c}.{p}" for c, p in ends)
        if not sources and set(end_kinds) <= {"none", "dropped"} and "dropped" in end_kinds:
            continue  # a scope showing a variable hydroservo does not name (a relief valve's own xv)
        if len(sources) != 1:
            problems.append(f"{source}: connection {joined}: expected one signal output, found {len(sources)}")
            continue
        co, po = sources[0]
        signal = mapped[co].outputs[po] if po in mapped[co].outputs else None
        for (ci, pi), kind in zip(ends, end_kinds, strict=True):
            if (ci, pi) == (co, po):
                continue
            if kind == "dropped":
                scopes.setdefault(ci, []).append(f"{_alias(co)}.{po}.Value")
            elif kind == "input" and signal is not None:
                m = mapped[ci]
                if pi in m.multi:
                    taken = filled.get((ci, pi), 0)
                    if taken >= len(m.multi[pi]):
                        problems.append(f"{source}: {ci}.{pi} reads more than {len(m.multi[pi])} signals")
                        continue
                    filled[(ci, pi)] = taken + 1
                    system.connect(signal, m.multi[pi][taken])
                    continue
                system.connect(signal, m.inputs[pi])
                connected_inputs.add((ci, pi))
            elif kind == "none":  # an input variable of Hopsan's that hydroservo holds constant
                problems.append(f"{source}: connection {joined}: {ci}.{pi} driven by a signal is not supported yet")
            else:
                problems.append(f"{source}: connection {joined}: {ci}.{pi} ({kind}) cannot read {co}.{po}")

    aliases: dict[str, Var] = {}
    hopsan_names: dict[str, str] = {}

    def hopsan(full_name: str, port: str, variable: str) -> str:
        """Hopsan's name of a variable: subsystems joined by $, then #port#variable."""
        return f"{full_name.replace('.', '$')}#{port}#{variable}"

    for node_ends in power_groups:
        refs = [mapped[c].power[p] for c, p in node_ends if _port_kind(mapped.get(c), p) == "power"]
        if len(set(refs)) > 1:
            system.connect(*dict.fromkeys(refs))
        node = _node_variables(system, refs, port_of)
        for c, p in node_ends:
            if p in mapped[c].flow and _port_kind(mapped[c], p) == "power" and "Flow" in node:
                node["Flow"] = Var(1.0, mapped[c].flow[p])
        for c, p in node_ends:
            for var, value in node.items():
                if (var == "Flow" and (c, p) in multiports) or "#" in p or f"{_alias(c)}.{p}.{var}" in aliases:
                    continue  # a multiport's flow is one per connection: Hopsan logs none of them by the port
                aliases[f"{_alias(c)}.{p}.{var}"] = value
                hopsan_names[f"{_alias(c)}.{p}.{var}"] = hopsan(c, p, var)
            read = mapped[c].read.get(p)
            for target, variable in ([read] if read is not None else []) + mapped[c].read_also.get(p, []):
                if variable not in node:
                    problems.append(f"{source}: {c}.{p} reads {variable}, which the node it is joined to has not")
                    continue
                value = node[variable]
                comp = system[target.split(".")[0]]
                comp.set(gain1=value.coef, offset=value.offset)
                system.connect(value.signal, target)

    try:
        system.hydraulic_inputs()  # every node needs one pressure (motion) port: two C components joined are refused
    except ModelError as exc:
        problems.append(f"{source}: {exc}")

    # Hopsan's signal inputs left unconnected take their start value: a constant where it differs from the default
    for hc in model.components:
        m = mapped[hc.full_name]
        for port, target in m.inputs.items():
            if (hc.full_name, port) in connected_inputs:
                continue
            par = hc.parameters.get(f"{port}#Value")
            start = par.value if par is not None and par.value is not None else 0.0
            cname, iname = target.split(".")
            default = system[cname].INPUTS[iname].default
            if default is None or start != default:
                const = system.add(Constant(f"{cname}_{iname}", value=start))
                system.connect(f"{const.name}.y", target)
        for port, signal in m.outputs.items():
            aliases[f"{_alias(hc.full_name)}.{port}.Value"] = Var(1.0, signal)
            hopsan_names[f"{_alias(hc.full_name)}.{port}.Value"] = hopsan(hc.full_name, port, "Value")
        for variable, value in m.values.items():
            aliases[f"{_alias(hc.full_name)}.{variable}.Value"] = value
            hopsan_names[f"{_alias(hc.full_name)}.{variable}.Value"] = hopsan(hc.full_name, variable, "Value")
    if problems:
        raise ModelFileError("; ".join(problems))
    for name, value in aliases.items():
        unit = "Pa_abs" if value.absolute else _unit_of(system, value)  # Hopsan's pressures are absolute values
        system.alias(name, value.expr(), unit, f"Hopsan's {hopsan_names[name]}")
    system.meta.update({"status": "imported", "hopsan_timestep": f"{model.timestep!r} s"})
    system.plots = [list(dict.fromkeys(shown)) for shown in scopes.values() if shown]
    if not system.plots:  # no scope: what an engineer looks at first, not the first of Hopsan's many variables
        system.plots = system.default_panels(aliases=False)
    system.display_units = ["Pa_abs"]  # pressures shown absolute, as Hopsan shows them
    _refuse_loops_of_unit_delays(system, source, [hc.full_name for hc in model.components if hc.typename == "SignalUnitDelay"])
    _start_from_inputs(system, {k: v for m in mapped.values() for k, v in m.start_from_input.items()})
    return HopsanImport(system, model, mapping, names, hopsan_names, renamed)


def _kept_components(mapped: dict[str, Mapped]) -> list[str]:
    """The names of the hydroservo components the mapped Hopsan components became."""
    return [comp.name for m in mapped.values() for comp in m.components]


def _split_subports(model: HopsanModel) -> HopsanModel:
    """The model with each connection to a multiport of :data:`SUBPORTS` named by its own subport, ``P1#1``,
    ``P1#2``, ... in the order of the file's connections, which is the order in which Hopsan's loader connects
    them and so of the multiport's subports (a valve plate's k-th bore is its k-th connection)."""
    import dataclasses

    types = {hc.full_name: hc.typename for hc in model.components}
    counts: dict[tuple[str, str], int] = {}

    def named(end: str) -> str:
        comp, port = _end(end)
        if port not in SUBPORTS.get(types.get(comp, ""), ()):
            return end
        k = counts[(comp, port)] = counts.get((comp, port), 0) + 1
        return f"{comp}.{port}#{k}"

    connections = [tuple(named(end) for end in connection) for connection in model.connections]
    return dataclasses.replace(model, connections=connections)


def _refuse_loops_of_unit_delays(system: System, source: str, delays: list[str]) -> None:
    """A Hopsan unit delay passes its input on in the limit of a vanishing step (:func:`_unit_delay`); where it
    closed a loop with no state in it, that limit is an algebraic loop, which hydroservo does not solve: refused,
    with the loop and the delays named."""
    if not delays:
        return
    from hydroservo.system.assembly import assemble

    try:
        assemble(system)
    except ModelError as exc:
        if "algebraic loop" not in str(exc):
            raise
        raise ModelFileError(
            f"{source}: {exc}. The model's unit delays ({', '.join(delays)}: SignalUnitDelay) pass their input on in "
            "the limit of a vanishing step, which hydroservo's import takes; a loop one of them closes without a "
            "state in it is then algebraic, and hydroservo does not solve algebraic loops of signals"
        ) from None


def _start_from_inputs(system: System, starts: dict[str, tuple[str, Callable[[float], float]]]) -> None:
    """Set each parameter or initial state of ``starts`` to (a function of) the value its input takes at the
    start, where a signal drives it (what feeds the input, evaluated at t = 0 from the initial states); one that
    nothing drives keeps the file's start value."""
    import warnings

    driven = {key: (system.connections[inp], f) for key, (inp, f) in starts.items() if inp in system.connections}
    if not driven:
        return
    values: dict[str, float] = {}
    for _ in range(len(driven)):  # a start that feeds another (a rate limiter's into a valve's spool): again
        with warnings.catch_warnings():  # one instant of the model: its plausibility is the run's business
            warnings.simplefilter("ignore")
            first = system.simulate(t_eval=[0.0, 1e-12], method="cvodes")
        now = {key: f(float(first[source][0])) for key, (source, f) in driven.items()}
        if now == values:
            break
        values = now
        for key, value in values.items():
            cname, name = key.split(".", 1)
            if name in system.components[cname].STATES:
                system.set_initial(key, value)
            else:
                system.set(key, value)


def _node_starts(
    model: HopsanModel, by_name: dict[str, HopsanComponent], multiports: set[tuple[str, str]]
) -> dict[tuple[str, str], dict[str, float]]:
    """Each port's node start values (``Position`` -> value): those its C component declares, else its Q
    component's, else a sensor's (Hopsan's C components own the start values of their nodes)."""
    groups = _union([[_end(e) for e in c] for c in model.connections], multiports)
    def rank(end: tuple[str, str]) -> int:
        """0 for the component that owns the node's start values (Hopsan's C), 2 for a sensor, 1 otherwise; a file
        that does not say (older files have no cqstype) is read by the type."""
        hc = by_name.get(end[0])
        if hc is None or "Sensor" in hc.typename:
            return 2
        return 0 if hc.cqs == "C" or hc.typename in C_TYPES else 1

    out: dict[tuple[str, str], dict[str, float]] = {}
    shared: dict[tuple[str, str], list[dict[str, float]]] = {}
    for group in groups:
        values: dict[str, float] = {}
        for comp, port in sorted(group, key=rank, reverse=True):
            hc = by_name.get(comp)
            if hc is None:
                continue
            for key, par in hc.parameters.items():
                head, _, variable = key.partition("#")
                if head == port and variable and par.value is not None and variable != "Value":
                    values[variable] = par.value  # later (higher ranked) components overwrite
        for end in group:
            if end not in multiports:
                out[end] = values
            elif end[0] in by_name and by_name[end[0]].typename in SHARED_STARTS:
                shared.setdefault(end, []).append({k: v for k, v in values.items() if k in ("Position", "Velocity", "Angle", "AngularVelocity")})
    for end, each in shared.items():  # a mechanical multiport: one start for all its connections, if they agree
        out[end] = each[0] if all(v == each[0] for v in each) else {STARTS_DIFFER: 1.0}
    for hc in model.components:  # Q components that write their own start positions (a node's values shared)
        written = WRITTEN_STARTS.get(hc.typename)
        if written is not None:
            own = {port: values for (comp, port), values in out.items() if comp == hc.full_name}
            for port, values in written(hc, own).items():
                out.setdefault((hc.full_name, port), {}).update(values)
    return out


def _m2_load_starts(hc: HopsanComponent, starts: dict[str, dict[str, float]]) -> dict[str, dict[str, float]]:
    """MechanicM2load1D's start positions and velocities of Pm1 and Pm2, which it writes at its initialisation
    from the start values of its outputs xt and vt and of Pm3's node (x3, v3), whatever its neighbours declare:
    Pm1 at -(xt + m2 x3/(m1 + m2)), Pm2 at xt - m1 x3/(m1 + m2)."""
    def value(name: str, default: float) -> float:
        par = hc.parameters.get(f"{name}#Value") or hc.parameters.get(name)
        return par.value if par is not None and par.value is not None else default

    m1, m2 = value("m1", 1000.0), value("m2", 1000.0)
    if m1 + m2 == 0.0:
        return {}
    x3, v3 = starts.get("Pm3", {}).get("Position", 0.0), starts.get("Pm3", {}).get("Velocity", 0.0)
    xt, vt = value("xt", 0.0), value("vt", 0.0)
    return {
        "Pm1": {"Position": -(xt + m2 * x3 / (m1 + m2)), "Velocity": -(vt + m2 * v3 / (m1 + m2))},
        "Pm2": {"Position": xt - m1 * x3 / (m1 + m2), "Velocity": vt - m1 * v3 / (m1 + m2)},
    }


#: Hopsan's Q components that write start values of their own to their nodes at initialisation (type -> the
#: values by port, from the component and the start values of its nodes): they override the C components' there
def _jlink_starts(hc: HopsanComponent, starts: dict[str, dict[str, float]]) -> dict[str, dict[str, float]]:
    """MechanicJLink's and MechanicJLink2's start positions and velocities of their translational ports, which they
    write from the start angle and speed of Pmr2's node: x0 - link sin θ, -link cos θ ω."""
    def value(name: str, default: float) -> float:
        par = hc.parameters.get(f"{name}#Value") or hc.parameters.get(name)
        return par.value if par is not None and par.value is not None else default

    theta, omega = starts.get("Pmr2", {}).get("Angle", 0.0), starts.get("Pmr2", {}).get("AngularVelocity", 0.0)
    link = value("link", 0.1)
    end = {"Position": value("x0", -0.1) - link * math.sin(theta), "Velocity": -link * math.cos(theta) * omega}
    return {port: dict(end) for port in ("Pm0", "Pm1") if port in starts}


WRITTEN_STARTS: dict[str, Callable[[HopsanComponent, dict[str, dict[str, float]]], dict[str, dict[str, float]]]] = {
    "MechanicM2load1D": _m2_load_starts,
    "MechanicJLink": _jlink_starts,
    "MechanicJLink2": _jlink_starts,
}


#: Hopsan's signal blocks whose output is constant when their inputs are: type -> (output, inputs, function)
_CONSTANT_BLOCKS: dict[str, tuple[str, tuple[str, ...], Callable[..., float]]] = {
    "SignalConstant": ("y", (), lambda par: par("y")),
    "SignalSource": ("out", (), lambda par: par("y")),
    "SignalGain": ("out", ("in",), lambda par, u: par("k") * u),
}


def _fold_constant_drives(model: Any, by_name: dict[str, HopsanComponent]) -> dict[str, frozenset[str]]:
    """Parameters of Hopsan's components that a constant signal drives (a valve's diameter set by a
    ``SignalConstant``, through gains): their values set to the signal's, in the components' parameters, and the
    driven ports returned (component -> ports) so that the connections are dropped. Hopsan evaluates such a
    signal at every step, to the same value; hydroservo holds the parameter at it. A parameter that a mapped
    component takes as an input (a pressure source's ``p``) is left to be connected."""
    ends = [[_end(e) for e in connection] for connection in model.connections]
    values: dict[tuple[str, str], float] = {}
    for _ in range(len(model.components) + 1):  # through chains of gains, one block a pass
        grew = False
        for hc in model.components:
            block = _CONSTANT_BLOCKS.get(hc.typename)
            if block is None or (hc.full_name, block[0]) in values:
                continue
            out, inputs, function = block
            def par(name: str, hc: HopsanComponent = hc) -> float:
                found = hc.parameters.get(f"{name}#Value") or hc.parameters.get(name)
                return float("nan") if found is None or found.value is None else float(found.value)
            args = []
            for port in inputs:
                sources = [values.get(e) for group in ends if (hc.full_name, port) in group for e in group
                           if e != (hc.full_name, port)]
                known = [v for v in sources if v is not None]
                if sources and len(known) != 1:
                    break
                args.append(known[0] if sources else par(port))
            else:
                value = function(par, *args)
                if math.isfinite(value):
                    values[(hc.full_name, out)] = value
                    grew = True
        if not grew:
            break
    folded: dict[str, set[str]] = {}
    for group in ends:
        source = [values[e] for e in group if e in values]
        if len(source) != 1:
            continue
        for c, port in group:
            hc = by_name.get(c)
            if hc is None or (c, port) in values or hc.typename in _CONSTANT_BLOCKS or hc.typename == "SignalSink":
                continue
            if not _is_input_variable(hc, port) or _takes_as_input(hc, port):
                continue
            key = f"{port}#Value" if f"{port}#Value" in hc.parameters else port
            hc.parameters[key] = HopsanParameter(key, repr(source[0]), hc.parameters[key].unit, source[0])
            folded.setdefault(c, set()).add(port)
    return {c: frozenset(ports) for c, ports in folded.items()}


def _takes_as_input(hc: HopsanComponent, port: str) -> bool:
    """Whether hydroservo's mapping of ``hc`` reads Hopsan's input variable ``port`` as a signal input (a
    pressure source's ``p``, a signal block's ``in``) rather than a parameter."""
    probe = _Params(hc, "", [], driven=frozenset({port}))
    try:
        m = LIBRARY[hc.typename](hc, "probe", probe)
    except Exception:  # noqa: BLE001 - a component that cannot be mapped is refused later, with its message
        return True
    return _port_kind(m, port) != "none"


def _is_input_variable(hc: HopsanComponent, port: str) -> bool:
    """Whether Hopsan's component has an input variable ``port`` (a parameter a signal may drive)."""
    return f"{port}#Value" in hc.parameters or port in hc.parameters


def _alias(full_name: str) -> str:
    """A Hopsan component's path as the head of an alias: each name made safe (``Tank C_1`` -> ``Tank_C_1``), but
    a leading digit kept (``4_3_Servo_Valve.PA.Flow``, as Hopsan logs it)."""
    return ".".join(_shortened(re.sub(r"\W", "_", part, flags=re.ASCII) or "_", LONGEST_NAME)
                    for part in full_name.split("."))


def _end(end: str) -> tuple[str, str]:
    """``Comp.Port`` (the component's path may hold dots) as (component, port)."""
    comp, _, port = end.rpartition(".")
    return comp, port


def _port_kind(m: Mapped | None, port: str) -> str:
    if m is None:
        return "none"
    if port in m.power:
        return "power"
    if port in m.read:
        return "read"
    if port in m.inputs or port in m.multi:
        return "input"
    if port in m.outputs:
        return "output"
    if port in m.values:
        return "value"
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
    position, velocity and force (angle, angular velocity and torque), each from the port that gives it."""
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
            x, v, f = ("Angle", "AngularVelocity", "Torque") if port.kind == "rotational" else (
                "Position", "Velocity", "Force")
            if is_motion_port(comp, port):  # Hopsan's Q ports count outward
                out[x] = Var(port.sign, f"{cname}.{port.x}")
                out[v] = Var(port.sign, f"{cname}.{port.v}")
            else:  # the force (torque) pressing on the node
                out[f] = Var(port.sign, f"{cname}.{port.F}")
    return out


def _unit_of(system: System, value: Var) -> str:
    if value.unit is not None:
        return value.unit
    cname, sig = value.signal.split(".")
    comp = system.components[cname]
    spec = comp.OUTPUTS.get(sig) or comp.STATES.get(sig)
    return spec.unit if spec is not None and spec.unit not in ("@",) else ""
