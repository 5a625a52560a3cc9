"""The ports every four-way valve shares: the four pressures it reads and the four flows it gives.

Port A is the use port that supply feeds for positive spool travel (the
sources' port 1), B the other (port 2); flows are positive out of A and B
into their lines, from supply into the valve, and from the valve to tank.
"""

from __future__ import annotations

from hydroservo.components.base import Hydraulic, Output, Port

__all__ = ["PRESSURE_PORTS", "FLOW_OUTPUTS", "HYDRAULIC_PORTS"]

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
