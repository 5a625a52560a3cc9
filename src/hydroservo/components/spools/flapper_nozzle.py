"""Main spool driven by the flapper-nozzle stage of a two-stage servovalve (MOOG 72 series, [FlightSimulatorND])."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.laws.flapper_nozzle import spool_jerk

__all__ = ["FlapperNozzleSpool"]


@register
class FlapperNozzleSpool(Component):
    r"""Main spool driven by the flapper-nozzle stage, [FlightSimulatorND] eq. (3-16) re-derived.

    .. math:: \dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v

    (:func:`hydroservo.laws.flapper_nozzle.spool_jerk`, whose docstring holds
    the re-derivation). Flow forces are left out, as in the dissertation's
    final model.
    """

    PARAMETERS = {
        "K2": Param(0.12065, "m^2/s", "flapper-nozzle flow gain", min=0.0),
        "Av": Param(7.1226e-5, "m^2", "spool end area", min=0.0, min_inclusive=False),
        "omega_h": Param(1940.0, "rad/s", "natural frequency of the spool stage", min=0.0, min_inclusive=False),
        "delta_h": Param(1.0, "", "damping ratio of the spool stage", min=0.0),
        "xv0": Param(0.0, "m", "initial spool position"),
    }
    STATES = {
        "xv": State("m", "spool position", initial="xv0", nominal=2.54e-3),
        "vv": State("m/s", "spool velocity", nominal=0.254),
        "av": State("m/s^2", "spool acceleration", nominal=254.0),
    }
    INPUTS = {"xf": Port("m", "flapper displacement")}
    OUTPUTS = {"xv": Output("m", "spool position"), "vv": Output("m/s", "spool velocity")}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xv": x["xv"], "vv": x["vv"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        jerk = spool_jerk(u["xf"], x["vv"], x["av"], p["K2"], p["Av"], p["omega_h"], p["delta_h"])
        return {"xv": x["vv"], "vv": x["av"], "av": jerk}
