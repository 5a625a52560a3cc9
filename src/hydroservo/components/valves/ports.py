"""The ports valves share: a four-way valve's four pressures and flows, a two-port valve's two; the oil they read.

Port A is the use port that supply feeds for positive spool travel (the
sources' port 1), B the other (port 2); flows are positive out of A and B
into their lines, from supply into the valve, and from the valve to tank.
"""

from __future__ import annotations

from hydroservo.components.base import Hydraulic, Output, Param, Port

__all__ = [
    "PRESSURE_PORTS",
    "FLOW_OUTPUTS",
    "HYDRAULIC_PORTS",
    "TWO_PORT_PRESSURES",
    "TWO_PORT_HYDRAULIC",
    "FLUID_PARAMETERS",
]

#: Inputs: supply, tank and use-port pressures.
PRESSURE_PORTS = {
    "pS": Port("Pa", "supply pressure"),
    "pT": Port("Pa", "tank pressure", default=0.0),
    "pA": Port("Pa", "pressure in line A (port 1)"),
    "pB": Port("Pa", "pressure in line B (port 2)"),
}

#: Outputs: the flows of the four ports.
FLOW_OUTPUTS = {
    "QA": Output("m^3/s", "flow out of port A (port 1) into line A"),
    "QB": Output("m^3/s", "flow out of port B (port 2) into line B"),
    "QS": Output("m^3/s", "flow drawn from supply"),
    "QT": Output("m^3/s", "flow returned to tank"),
}

#: The hydraulic ports: each pairs a pressure input with its flow output (flow ports).
HYDRAULIC_PORTS = {
    "P": Hydraulic("pS", "QS", "supply port", into=True),
    "T": Hydraulic("pT", "QT", "tank port", into=False),
    "A": Hydraulic("pA", "QA", "use port A (port 1)", into=False),
    "B": Hydraulic("pB", "QB", "use port B (port 2)", into=False),
}

#: A two-port valve or restriction: the pressures it reads (its output ``Q`` is the flow from A to B).
TWO_PORT_PRESSURES = {"pA": Port("Pa", "pressure at port A"), "pB": Port("Pa", "pressure at port B")}

#: A two-port valve's hydraulic ports: positive ``Q`` enters at A and leaves at B.
TWO_PORT_HYDRAULIC = {
    "A": Hydraulic("pA", "Q", "port A (inlet for positive Q)", into=True),
    "B": Hydraulic("pB", "Q", "port B (outlet for positive Q)", into=False),
}

#: Density, viscosity and critical flow number of the orifice law (taken from the circuit's fluid).
FLUID_PARAMETERS = {
    "rho": Param(870.0, "kg/m^3", "oil density", min=0.0, min_inclusive=False, fluid="density"),
    "nu": Param(
        32e-6, "m^2/s", "kinematic viscosity (ISO VG 32 at 40 degC)", min=0.0, min_inclusive=False, fluid="kinematic_viscosity"
    ),
    "lambda_crit": Param(1000.0, "", "critical flow number (MareAttarND eq. 4)", min=0.0, min_inclusive=False),
}
