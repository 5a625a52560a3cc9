"""Spool dynamics: components that turn a command into a spool position.

One file per model: :mod:`.first_order` and :mod:`.second_order` (catalogue
lags), :mod:`.rate_limited` (the servo-solenoid spool of [FerreiraND]), and
the two-stage servovalve's first stage, :mod:`.torque_motor` and
:mod:`.flapper_nozzle` ([FlightSimulatorND]), and the massless spool or poppet that a damping orifice
slows, :mod:`.orifice_damped` (Hopsan's poppet and 3/3 shuttle valves). A new spool or pilot-stage model
goes into a new file here.
"""

from hydroservo.components.spools.first_order import SpoolFirstOrder
from hydroservo.components.spools.flapper_nozzle import FlapperNozzleSpool
from hydroservo.components.spools.orifice_damped import SpoolOrificeDamped
from hydroservo.components.spools.rate_limited import SpoolRateLimited
from hydroservo.components.spools.second_order import SpoolSecondOrder
from hydroservo.components.spools.torque_motor import TorqueMotor

__all__ = ["SpoolFirstOrder", "SpoolSecondOrder", "SpoolRateLimited", "TorqueMotor", "FlapperNozzleSpool", "SpoolOrificeDamped"]
