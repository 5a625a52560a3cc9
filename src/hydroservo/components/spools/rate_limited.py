r"""Spool position of a servo-solenoid valve with its card: the rate-limited second order of [FerreiraND] Fig. 11, then a delay.

The equations are :func:`hydroservo.laws.spool_dynamics.rate_limited_spool_acceleration`
(the re-derivation of Fig. 11 is in :mod:`hydroservo.laws.spool_dynamics`); the
pure delay of section 6.2 is replaced in a system by its Padé approximant
(option ``delay_model``: ``"pade2"``, the default, ``"pade1"`` or ``"none"``).
Frequency-response analysis (:mod:`hydroservo.analysis.frequency`) applies the
delay exactly, as a phase :math:`-\omega\Delta t`.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from hydroservo import backend as bk
from hydroservo.components.base import Component, FromSet, Option, Output, Param, Port, State, register
from hydroservo.errors import ParameterError
from hydroservo.laws.spool_dynamics import pade1_delay, pade2_delay, rate_limited_spool_acceleration

__all__ = ["SpoolRateLimited"]

_DELAY_STATES = {
    "none": {},
    "pade1": {"w1": State("", "Padé (1,1) state of the delay", initial="s0", nominal=1.0)},
    "pade2": {
        "w1": State("", "Padé (2,2) state of the delay", initial="s0", nominal=1.0),
        "w2": State("1/s", "Padé (2,2) state of the delay (rate)", nominal=100.0),
    },
}


def _published(key: str) -> FromSet:
    return FromSet("FerreiraND", "dynamics", key)


@register
class SpoolRateLimited(Component):
    """Spool position of a servo-solenoid valve with its card: [FerreiraND] Fig. 11, then a delay.

    Defaults: the KBSDG4V-3 fit of [FerreiraND] section 6 (omega_n = 1007 rad/s,
    xi = 0.48, L_v = 125 1/s, L_a = 81184 1/s^2, delay 0.7625 ms; parameter set
    ``FerreiraND``). The command is saturated to [-1, 1] and the delivered
    position clipped to the stroke.
    """

    PARAMETERS = {
        "omega_n": Param(_published("omega_n"), "rad/s", "natural angular frequency", min=0.0, min_inclusive=False),
        "zeta": Param(_published("zeta"), "", "damping ratio (xi of FerreiraND)", min=0.0, min_inclusive=False),
        "L_v": Param(_published("L_v"), "1/s", "velocity limit (arctangent limiter)", min=0.0, min_inclusive=False),
        "L_a": Param(
            _published("L_a"), "1/s^2", "acceleration limit (hard saturation)", min=0.0, min_inclusive=False
        ),
        "delay": Param(_published("delay"), "s", "pure delay of the spool position", min=0.0),
        "s0": Param(0.0, "", "initial normalised spool position", min=-1.0, max=1.0),
    }
    STATES = {
        "s": State("", "normalised spool position before the delay", initial="s0", nominal=1.0),
        "v": State("1/s", "normalised spool velocity", nominal=100.0),
        **_DELAY_STATES["pade2"],
    }
    INPUTS = {"u": Port("", "normalised command, -1 to 1")}
    OUTPUTS = {"xs": Output("", "normalised spool position, delayed"), "vs": Output("1/s", "spool velocity")}
    OPTIONS = {
        "delay_model": Option("pade2", ("pade2", "pade1", "none"), "how the pure delay is approximated in time"),
    }

    def set_option(self, key: str, value: Any) -> None:
        super().set_option(key, value)
        if key == "delay_model":
            base = {k: v for k, v in self.STATES.items() if not k.startswith("w")}
            self.STATES = {**base, **_DELAY_STATES[str(value)]}  # type: ignore[misc]

    def check(self) -> None:
        if self.option("delay_model") != "none" and self.values["delay"] <= 0:
            raise ParameterError(
                f"{self.name}.delay = {self.values['delay']:g} s with delay_model = "
                f"{self.option('delay_model')!r}: expected a positive delay, or delay_model = 'none'"
            )

    def _delay(self, x: Mapping[str, Any], p: Mapping[str, Any]) -> tuple[Any, dict[str, Any]]:
        """The delayed position and the rates of the delay's states."""
        mode = self.option("delay_model")
        if mode == "none":
            return x["s"], {}
        if mode == "pade1":
            y, dw1 = pade1_delay(x["s"], x["w1"], p["delay"])
            return y, {"w1": dw1}
        y, dw1, dw2 = pade2_delay(x["s"], x["w1"], x["w2"], p["delay"])
        return y, {"w1": dw1, "w2": dw2}

    def output_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any]
    ) -> dict[str, Any]:
        return {"xs": bk.clip(self._delay(x, p)[0], -1.0, 1.0), "vs": x["v"]}

    def state_equations(
        self, t: Any, x: Mapping[str, Any], u: Mapping[str, Any], p: Mapping[str, Any], y: Mapping[str, Any]
    ) -> dict[str, Any]:
        cmd = bk.clip(u["u"], -1.0, 1.0)
        acc = rate_limited_spool_acceleration(cmd, x["s"], x["v"], p["omega_n"], p["zeta"], p["L_v"], p["L_a"])
        return {"s": x["v"], "v": acc, **self._delay(x, p)[1]}
