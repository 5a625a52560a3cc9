"""Component library: every component type, registered by its class name.

=====================  ==========================================================
module                 components
=====================  ==========================================================
:mod:`.sources`        ConstantPressure, Tank, PressureTable, PressureSource,
                       FlowSource
:mod:`.volume`         Volume
:mod:`.line`           Line, Hose, LosslessLine
:mod:`.accumulator`    Accumulator
:mod:`.pumps`          Pump, VariablePump, LoadSensingPump, Motor, Machine,
                       CentrifugalPump, CentrifugalPumpInertia
:mod:`.machine_parts`  SwashPlate, SwashPlateDrive, PumpPiston, ValvePlate (an axial piston
                       machine of its parts)
:mod:`.cylinder`       Cylinder, FourChamberCylinder
:mod:`.mass`           Mass, MassPair
:mod:`.mechanics`      Spring, Damper, FixedPosition, Wall, RigidLink, ForceSource, VelocitySource
:mod:`.rotational`     RotationalInertia, TorsionalSpring, TorqueSource,
                       AngularVelocitySource, Vehicle, Crank
:mod:`.valves`         FourWayValve, ThreeWayValve, ThreeWayPressureValve, TwoWayValve, PseudoSectionValve,
                       ServoSolenoidValve,
                       StagedSlotValve, Orifice, LaminarOrifice, CheckValve, ShuttleValve, ReliefValve,
                       PressureReducingValve, CounterbalanceValve, PressureCompensatorValve, PilotCheckValve
:mod:`.spools`         SpoolFirstOrder, SpoolSecondOrder, SpoolRateLimited,
                       TorqueMotor, FlapperNozzleSpool
:mod:`.signals`        Constant, Step, SoftStep, DecayingStep, Pulse, PulseWave,
                       Staircase, Ramp, Sine, Square, Table, Table2D, Table3D
:mod:`.control`        Sum, Product, Quotient, Absolute, Power, Function, Gain,
                       Lag, TransferFunction, Integrator, Saturation, DeadZone,
                       RateLimiter, Hysteresis, Latch, Counter, Selector, PID,
                       Amplifier, Transducer
:mod:`.linearized`     Linearized, LoadPressureCylinder (any component, or a
                       cylinder, expanded about an operating point)
=====================  ==========================================================

What a component is (declarations and equations): :mod:`.base`.
"""

from hydroservo.components.accumulator import Accumulator
from hydroservo.components.base import (
    REGISTRY,
    Component,
    FromSet,
    Limit,
    Option,
    Output,
    Param,
    Port,
    RenamedWarning,
    State,
)
from hydroservo.components.control import (
    PID,
    Absolute,
    Amplifier,
    Counter,
    DeadZone,
    Function,
    Gain,
    Hysteresis,
    Integrator,
    Lag,
    Latch,
    Power,
    Product,
    Quotient,
    RateLimiter,
    Saturation,
    Selector,
    Sum,
    Transducer,
    TransferFunction,
)
from hydroservo.components.cylinder import Cylinder, FourChamberCylinder
from hydroservo.components.line import Hose, Line, LosslessLine
from hydroservo.components.linearized import Linearized, LoadPressureCylinder
from hydroservo.components.machine_parts import PumpPiston, SwashPlate, SwashPlateDrive, ValvePlate
from hydroservo.components.mass import Mass, MassPair
from hydroservo.components.mechanics import (
    Damper,
    FixedPosition,
    ForceSource,
    RigidLink,
    Spring,
    VelocitySource,
    Wall,
)
from hydroservo.components.pumps import (
    CentrifugalPump,
    CentrifugalPumpInertia,
    LoadSensingPump,
    Machine,
    Motor,
    Pump,
    VariablePump,
)
from hydroservo.components.rotational import (
    AngularVelocitySource,
    Crank,
    RotationalInertia,
    TorqueSource,
    TorsionalSpring,
    Vehicle,
)
from hydroservo.components.signals import (
    Constant,
    DecayingStep,
    Pulse,
    PulseWave,
    Ramp,
    Sine,
    SoftStep,
    Square,
    Staircase,
    Step,
    Table,
    Table2D,
    Table3D,
)
from hydroservo.components.sources import (
    ConstantPressure,
    FlowSource,
    HeadTank,
    PressureSource,
    PressureTable,
    Tank,
)
from hydroservo.components.spools import (
    FlapperNozzleSpool,
    SpoolFirstOrder,
    SpoolOrificeDamped,
    SpoolRateLimited,
    SpoolSecondOrder,
    TorqueMotor,
)
from hydroservo.components.valves import (
    CatalogueServovalve,
    CheckValve,
    CounterbalanceValve,
    FourWayValve,
    LaminarOrifice,
    Orifice,
    PilotCheckValve,
    PressureCompensatorValve,
    PressureReducingValve,
    PseudoSectionValve,
    ReliefValve,
    ServoSolenoidValve,
    ShuttleValve,
    StagedSlotValve,
    ThreeWayPressureValve,
    ThreeWayValve,
    TwoStageServovalve,
    TwoWayValve,
)
from hydroservo.components.volume import Volume

__all__ = [
    "REGISTRY",
    "Component",
    "FromSet",
    "Param",
    "State",
    "Port",
    "Output",
    "Option",
    "Limit",
    "RenamedWarning",
    "Cylinder",
    "FourChamberCylinder",
    "Mass",
    "MassPair",
    "Spring",
    "Damper",
    "FixedPosition",
    "Wall",
    "RigidLink",
    "ForceSource",
    "VelocitySource",
    "RotationalInertia",
    "TorsionalSpring",
    "TorqueSource",
    "AngularVelocitySource",
    "Vehicle",
    "Crank",
    "Constant",
    "SoftStep",
    "FlowSource",
    "PressureSource",
    "LaminarOrifice",
    "Integrator",
    "Product",
    "Quotient",
    "Absolute",
    "Power",
    "Function",
    "ConstantPressure",
    "Tank",
    "HeadTank",
    "PressureTable",
    "Volume",
    "Line",
    "Hose",
    "LosslessLine",
    "Accumulator",
    "Pump",
    "VariablePump",
    "LoadSensingPump",
    "Motor",
    "Machine",
    "CentrifugalPump",
    "CentrifugalPumpInertia",
    "SwashPlate",
    "SwashPlateDrive",
    "PumpPiston",
    "ValvePlate",
    "FourWayValve",
    "ThreeWayValve",
    "ThreeWayPressureValve",
    "TwoWayValve",
    "PseudoSectionValve",
    "ServoSolenoidValve",
    "StagedSlotValve",
    "TwoStageServovalve",
    "CatalogueServovalve",
    "Orifice",
    "CheckValve",
    "ShuttleValve",
    "PilotCheckValve",
    "ReliefValve",
    "PressureReducingValve",
    "CounterbalanceValve",
    "PressureCompensatorValve",
    "SpoolFirstOrder",
    "SpoolSecondOrder",
    "SpoolRateLimited",
    "SpoolOrificeDamped",
    "TorqueMotor",
    "FlapperNozzleSpool",
    "Step",
    "DecayingStep",
    "Pulse",
    "PulseWave",
    "Staircase",
    "Ramp",
    "Sine",
    "Square",
    "Table",
    "Table2D",
    "Table3D",
    "Sum",
    "Gain",
    "Lag",
    "TransferFunction",
    "Saturation",
    "DeadZone",
    "RateLimiter",
    "Hysteresis",
    "Latch",
    "Counter",
    "Selector",
    "PID",
    "Amplifier",
    "Transducer",
    "Linearized",
    "LoadPressureCylinder",
]
