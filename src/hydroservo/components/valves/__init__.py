"""Valves: components that turn a spool position and port pressures into flows.

One file per valve kind: :mod:`.four_way` (sharp edges, per-edge laps,
[Efe2014]), :mod:`.directional` (three- and two-way spool valves, of the same edges), :mod:`.pseudo_section` (the servo-solenoid valve of
[FerreiraND]), :mod:`.staged_slot` (the staged-slot valve across temperature
of [MareAttarND]), :mod:`.orifice` (the fixed orifice), :mod:`.check` (check
valves), :mod:`.shuttle` (the shuttle valve), :mod:`.pressure_control` (relief, pressure-reducing and counterbalance
valves), :mod:`.two_stage` (the first-principles two-stage servovalve of
[GordicND]), :mod:`.catalogue` (a servovalve as its catalogue gives it). A new valve goes into a new file here.
"""

from hydroservo.components.valves.catalogue import CatalogueServovalve
from hydroservo.components.valves.check import CheckValve, PilotCheckValve
from hydroservo.components.valves.directional import ThreeWayPressureValve, ThreeWayValve, TwoWayValve
from hydroservo.components.valves.four_way import FourWayValve
from hydroservo.components.valves.orifice import LaminarOrifice, Orifice
from hydroservo.components.valves.pressure_control import (
    CounterbalanceValve,
    PressureCompensatorValve,
    PressureReducingValve,
    ReliefValve,
)
from hydroservo.components.valves.pseudo_section import PseudoSectionValve, ServoSolenoidValve
from hydroservo.components.valves.shuttle import ShuttleValve
from hydroservo.components.valves.staged_slot import StagedSlotValve
from hydroservo.components.valves.two_stage import TwoStageServovalve

__all__ = [
    "FourWayValve",
    "ThreeWayValve",
    "ThreeWayPressureValve",
    "TwoWayValve",
    "PseudoSectionValve",
    "ServoSolenoidValve",
    "StagedSlotValve",
    "Orifice",
    "LaminarOrifice",
    "CheckValve",
    "ShuttleValve",
    "PilotCheckValve",
    "ReliefValve",
    "PressureReducingValve",
    "CounterbalanceValve",
    "PressureCompensatorValve",
    "TwoStageServovalve",
    "CatalogueServovalve",
]
