"""Main spool driven by the flapper-nozzle stage of a two-stage servovalve (MOOG 72 series, [FlightSimulatorND])."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, Output, Param, Port, State, register
from hydroservo.errors import ParameterError
from hydroservo.laws.flapper_nozzle import spool_jerk

__all__ = ["FlapperNozzleSpool"]


@register
class FlapperNozzleSpool(Component):
    r"""Main spool driven by the flapper-nozzle stage, [FlightSimulatorND] eq. (3-16) re-derived.

    .. math:: \dddot x_v = \frac{K_2}{A_v}\omega_h^2 x_f - 2\delta_h\omega_h\ddot x_v - \omega_h^2\dot x_v

    (:func:`hydroservo.laws.flapper_nozzle.spool_jerk`, whose docstring holds
    the re-derivation). Flow forces are left out, as in the dissertation's
    final model.

    The spool stops at :math:`\pm x_{v,max}`, the valve's full travel (one stroke with the valve it drives,
    ``System.stroke_pairs``): there it moves only back inwards, so its position, and with it the feedback
    wire's torque, stay within the travel. The dissertation's runs never reach the stops (the published
    step: 0.79 mm of 2.54 mm). A pilot stage that is unstable (too high a loop gain
    :math:`K_w K_2 / (K_f A_v)`, or too little damping) then chatters between them, as a real one does, instead
    of running off to infinity.
    """

    PARAMETERS = {
        "K2": Param(0.12065, "m^2/s", "flapper-nozzle flow gain", min=0.0),
        "Av": Param(7.1226e-5, "m^2", "spool end area", min=0.0, min_inclusive=False),
        "omega_h": Param(1940.0, "rad/s", "natural frequency of the spool stage", min=0.0, min_inclusive=False),
        "delta_h": Param(1.0, "", "damping ratio of the spool stage", min=0.0),
        "xv0": Param(0.0, "m", "initial spool position"),
        "xv_max": Param(
            2.54e-3, "m", "spool stroke (its stops; one stroke with the valve it drives)", min=0.0, min_inclusive=False
        ),
    }
    STATES = {
        "xv": State("m", "spool position", initial="xv0", nominal=2.54e-3),
        "vv": State("m/s", "spool velocity", nominal=0.254),
        "av": State("m/s^2", "spool acceleration", nominal=254.0),
    }
    INPUTS = {"xf": Port("m", "flapper displacement")}
    OUTPUTS = {"xv": Output("m", "spool position"), "vv": Output("m/s", "spool velocity")}

    def check(self) -> None:
        xv0, xv_max = float(self.values["xv0"]), float(self.values["xv_max"])
        if abs(xv0) > xv_max:
            raise ParameterError(
                f"{self.name}.xv0 = {xv0:.4g} m: expected a start within the spool's travel, |xv0| <= xv_max = "
                f"{xv_max:.4g} m"
            )

    @staticmethod
    def _motion(x: Mapping[str, Any], p: Mapping[str, Any]) -> Any:
        """The spool's velocity: ``vv``, but only inwards at a stop."""
        at_max = bk.if_else(x["xv"] >= p["xv_max"], bk.fmin(x["vv"], 0.0), x["vv"])
        return bk.if_else(x["xv"] <= -p["xv_max"], bk.fmax(x["vv"], 0.0), at_max)

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xv": x["xv"], "vv": self._motion(x, p)}

    def switch_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, tuple[Any, float]]:
        """The stops reached."""
        return {"stop_min": (x["xv"] + p["xv_max"], 2.54e-3), "stop_max": (x["xv"] - p["xv_max"], 2.54e-3)}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        jerk = spool_jerk(u["xf"], x["vv"], x["av"], p["K2"], p["Av"], p["omega_h"], p["delta_h"])
        return {"xv": self._motion(x, p), "vv": x["av"], "av": jerk}
