"""The flight-simulator actuator of seed 003 as a built-in system.

Closed position loop of one of six asymmetric actuators of a flight-simulator
motion platform: command voltage, summing junction with potentiometer
feedback, RC network, amplifier, MOOG 72 two-stage servovalve (torque motor,
flapper-nozzle, critical-centre spool), differential cylinder, load mass with
weight. Parameters: Appendix C (:data:`hydroservo.parameters.APPENDIX_C`).

Sign conventions
----------------
The seed takes retraction as positive (``y``, section 3.2); hydroservo's
cylinder extends with +x. So ``y = -x``; the rod-end chamber 1 of the seed is
the cylinder's side B, the full-end chamber 2 its side A; valve port A feeds
the rod end, so positive spool travel retracts the rod, as in Fig. 2-3. The
potentiometer reads ``G_f y = -G_f x``: its gain is entered as ``-G_f``.

Choices (see ``docs/flight_simulator.md``)
------------------------------------------
* ``rc_form="seed"`` (default): the simulated RC network
  :math:`\\dot E_o = E_i - E_o/RC` of eqs. (3-35), (3-36) and Appendix D (pot Q09),
  whose DC gain is RC = 0.34; ``"physical"``: :math:`E_o = E_i/(RCs + 1)`.
* Current: :math:`I_s = G_a E_o / R_v` (eq. 3-37 with 10^3 as the mA/A factor).
* Chamber volumes frozen at mid-stroke (``k_V = 0``), as the seed's final model;
  ``volumes="variable"`` lets them follow the piston.
* Orifice law regularised below a transition pressure from a critical flow
  number of 1000, with a hydraulic diameter of 2 x 0.1 in (twice the largest
  spool opening of Appendix D) and 14 cSt, a MIL-H-5606-class fluid at about
  40 degC; the seed gives no viscosity. This puts the transition at about
  0.4 psi, far below every pressure drop of interest, so the seed's turbulent
  law is what is simulated.
* Initial state of Appendix D: all zero but the full-end pressure, W/A2.
"""

from __future__ import annotations

import math

from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.parameters.flight_simulator_003 import APPENDIX_C
from hydroservo.system import System
from hydroservo.units import to_si

__all__ = ["flight_simulator"]


def _v(key: str, unit: str) -> float:
    return to_si(APPENDIX_C[key][0], unit, what=f"Appendix C {key}")


def flight_simulator(step: float | str = "2 V", rc_form: str = "seed", volumes: str = "frozen") -> System:
    """Build the seed-003 actuator loop.

    Parameters
    ----------
    step : float or str
        Command step ``V_i`` at t = 0 [V]; positive retracts (seed convention).
    rc_form : {"seed", "physical"}
        RC network as simulated in the seed (DC gain RC) or as a physical RC lag.
    volumes : {"frozen", "variable"}
        Chamber volumes fixed at mid-stroke (seed) or following the piston.
    """
    if rc_form not in ("seed", "physical"):
        raise ParameterError(f"rc_form = {rc_form!r}: expected 'seed' or 'physical'")
    if volumes not in ("frozen", "variable"):
        raise ParameterError(f"volumes = {volumes!r}: expected 'frozen' or 'variable'")
    rc = _v("RC", "s")
    Cd = 0.61  # Appendix A
    k = _v("Cd_sqrt_2_rho", "m^2/s/N^0.5")  # = Cd*sqrt(2/rho), SI m^1.5/kg^0.5
    rho = 2.0 * (Cd / k) ** 2

    s = System(
        "flight-simulator",
        "Seed 003: closed-loop flight-simulator actuator, asymmetric cylinder, MOOG 72 two-stage servovalve (Appendix C)",
        t_end=2.0,
    )
    s.add(c.Step("source", unit="V", amplitude=step, t_step=0.0))
    s.add(c.Transducer("feedback", G=-_v("Gf", "V/m")))
    s.add(c.Sum("summer", unit="V", k1=1.0, k2=-1.0))
    s.add(c.Lag("rc", unit="V", K=rc if rc_form == "seed" else 1.0, T=rc))
    s.add(c.Amplifier("amp", G_a=_v("Ga", ""), R=_v("Rv", "ohm"), I_max=1.0))
    s.add(
        c.TorqueMotor(
            "torque_motor",
            omega_n=_v("omega_n", "rad/s"),
            zeta_n=_v("zeta_n", ""),
            K1=_v("K1", "N*m/A"),
            Kf=_v("Kf", "N"),
            Kw=_v("Kw", "N"),
        )
    )
    s.add(
        c.FlapperNozzleSpool(
            "spool",
            K2=_v("K2", "m^2/s"),
            Av=_v("Av", "m^2"),
            omega_h=_v("omega_h", "rad/s"),
            delta_h=_v("delta_h", ""),
        )
    )
    s.add(c.ConstantPressure("supply", p=_v("Ps", "Pa")))
    s.add(c.Tank("tank", p=0.0))
    s.add(
        c.FourWayValve(
            "valve",
            c_v=k * _v("w", "m"),
            x_max=to_si("0.1 in", "m"),
            rho=rho,
            nu=14e-6,
            D_h=2 * to_si("0.1 in", "m"),
            lambda_crit=1000.0,
        )
    )
    s.add(
        c.Cylinder(
            "cyl",
            A_A=_v("A2", "m^2"),
            A_B=_v("A1", "m^2"),
            V_A0=_v("Vt2", "m^3"),
            V_B0=_v("Vt1", "m^3"),
            k_V=0.0 if volumes == "frozen" else 1.0,
            C_Li=_v("Cl", "m^5/s/N"),
            beta=_v("beta", "Pa"),
            rho=rho,
            x_min=-to_si("15 in", "m"),
            x_max=to_si("15 in", "m"),
            bulk_modulus="constant",
            pressure_floor="check-valve",
            p_floor=0.0,
        )
    )
    s.add(c.Mass("load", m=_v("M", "kg"), W=_v("W", "N"), incline=math.pi / 2, B=_v("Bm", "N*s/m")))

    s.connect("source.y", "summer.u1")
    s.connect("load.x", "feedback.u", "cyl.x")
    s.connect("load.v", "cyl.v")
    s.connect("feedback.y", "summer.u2")
    s.connect("summer.y", "rc.u")
    s.connect("rc.y", "amp.E")
    s.connect("amp.i", "torque_motor.i")
    s.connect("torque_motor.xf", "spool.xf")
    s.connect("spool.xv", "torque_motor.xv", "valve.xv")
    s.connect("spool.vv", "valve.vv")
    s.connect("supply.p", "valve.pS")
    s.connect("tank.p", "valve.pT")
    s.connect("cyl.pB", "valve.pA")
    s.connect("cyl.pA", "valve.pB")
    s.connect("valve.QA", "cyl.QB")
    s.connect("valve.QB", "cyl.QA")
    s.connect("cyl.F", "load.F")

    s.set_initial("cyl.pA", "load.W / cyl.A_A")

    s.alias("y", "-load.x", "m", "actuator displacement, positive in retraction")
    s.alias("ydot", "-load.v", "m/s", "actuator velocity, positive in retraction")
    s.alias("p1", "cyl.pB", "Pa", "rod end chamber pressure")
    s.alias("p2", "cyl.pA", "Pa", "full end chamber pressure")
    s.alias("xv", "spool.xv", "m", "main spool displacement")
    s.alias("xf", "torque_motor.xf", "m", "flapper displacement")
    s.alias("vi", "source.y", "V", "command voltage")
    s.alias("ei", "summer.y", "V", "error voltage at the summing junction")
    s.alias("eo", "rc.y", "V", "error voltage at the RC network output")
    s.alias("i_s", "amp.i", "A", "valve current")
    s.plots = [["vi", "eo"], ["xv"], ["ydot"], ["y"], ["p1", "p2"]]
    s.plot_units = {"xv": "in", "ydot": "in/s", "y": "in", "p1": "psi", "p2": "psi"}
    return s
