"""Component library. Every component type is registered by its class name."""

from hydroservo.components.actuators import Cylinder
from hydroservo.components.base import REGISTRY, Component, Option, Output, Param, Port, State
from hydroservo.components.control import (
    PID,
    Amplifier,
    Gain,
    Lag,
    Ramp,
    Saturation,
    Sine,
    Square,
    Step,
    Sum,
    Table,
    Transducer,
)
from hydroservo.components.hydraulics import ConstantPressure, PressureTable, Tank, Volume
from hydroservo.components.mechanics import Mass
from hydroservo.components.proportional import PseudoSectionValve, ServoSolenoidValve, SpoolRateLimited
from hydroservo.components.servovalve import FlapperNozzleSpool, TorqueMotor
from hydroservo.components.spool import MareSpoolValve
from hydroservo.components.valves import FourWayValve, SpoolFirstOrder, SpoolSecondOrder

__all__ = [
    "REGISTRY",
    "Component",
    "Param",
    "State",
    "Port",
    "Output",
    "Option",
    "Cylinder",
    "Mass",
    "ConstantPressure",
    "Tank",
    "PressureTable",
    "Volume",
    "FourWayValve",
    "MareSpoolValve",
    "SpoolFirstOrder",
    "SpoolSecondOrder",
    "SpoolRateLimited",
    "PseudoSectionValve",
    "ServoSolenoidValve",
    "TorqueMotor",
    "FlapperNozzleSpool",
    "Step",
    "Ramp",
    "Sine",
    "Square",
    "Table",
    "Sum",
    "Gain",
    "Lag",
    "Saturation",
    "PID",
    "Amplifier",
    "Transducer",
]
