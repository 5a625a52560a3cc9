"""A servo-solenoid valve of seed 000 positioning a cylinder and mass (built-in example).

Closed position loop: a reference step, a proportional controller, the
Vickers KBSDG4V-3 of seed 000 (:class:`~hydroservo.components.ServoSolenoidValve`:
rate-limited spool dynamics of Fig. 11 with its delay, pseudo-sections fitted
to the datasheet), a differential cylinder (bore 40 mm, rod 22 mm) and a
horizontal 50 kg load with viscous and Coulomb friction. Supply 70 bar, the
pressure of the paper's measurements.

The paper gives the valve, not a circuit: cylinder, load, supply and
controller gain are a plausible small NG6 drive, chosen here. The initial
chamber pressures are the equilibrium of the blocked valve at null with the
piston at rest: the pressures at which the centred valve's leakage into and
out of each chamber balance, scaled so the piston forces cancel (the
cylinder is asymmetric).
"""

from __future__ import annotations

from hydroservo import components as c
from hydroservo.errors import ParameterError
from hydroservo.system import System
from hydroservo.units import to_si

__all__ = ["servo_solenoid_cylinder"]


def servo_solenoid_cylinder(
    step: float | str = "50 mm", structure: str = "variable", gain: float | str = "40 1/m"
) -> System:
    """Build the loop.

    Parameters
    ----------
    step : float or str
        Position reference step at t = 10 ms [m].
    structure : {"variable", "fixed"}
        Pseudo-section family of the valve (seed 000 eq. 24 or 33); both
        reproduce the KBSDG4V-3 datasheet.
    gain : float or str
        Proportional gain from position error to normalised valve command [1/m].
    """
    if structure not in ("variable", "fixed"):
        raise ParameterError(f"structure = {structure!r}: expected 'variable' or 'fixed'")
    s = System(
        "servo-solenoid-cylinder",
        "Seed 000: Vickers KBSDG4V-3 servo-solenoid valve in a position loop with a cylinder and mass",
        t_end=0.4,
    )
    p_s = to_si("70 bar", "Pa")
    s.add(c.Step("reference", unit="m", amplitude=step, t_step=0.01))
    s.add(c.Sum("error", unit="m", k1=1.0, k2=-1.0))
    s.add(c.Gain("controller", k=to_si(gain, "1/m", what="gain")))
    s.add(c.ConstantPressure("supply", p=p_s))
    s.add(c.Tank("tank", p=0.0))
    s.add(c.ServoSolenoidValve("valve", structure=structure))
    s.add(
        c.Cylinder(
            "cyl",
            A_A="12.566 cm^2",
            A_B="8.765 cm^2",
            V_A0="0.2 L",
            V_B0="0.2 L",
            beta="1.4 GPa",
            x_min="-0.1 m",
            x_max="0.1 m",
        )
    )
    s.add(c.Mass("load", m="50 kg", B="500 N*s/m", incline=0.0, F_c0="50 N", F_s0="20 N", c_s="5 mm/s"))
    s.connect("reference.y", "error.u1")
    s.connect("load.x", "error.u2", "cyl.x")
    s.connect("load.v", "cyl.v")
    s.connect("error.y", "controller.u")
    s.connect("controller.y", "valve.u")
    s.connect("supply.p", "valve.pS")
    s.connect("tank.p", "valve.pT")
    s.connect("cyl.pA", "valve.pA")
    s.connect("cyl.pB", "valve.pB")
    s.connect("valve.QA", "cyl.QA")
    s.connect("valve.QB", "cyl.QB")
    s.connect("cyl.F", "load.F")
    # Piston forces balanced, p_A A_A = p_B A_B, with p_A + p_B = P_s (the centred matched valve).
    s.set_initial("cyl.pA", "supply.p * cyl.A_B / (cyl.A_A + cyl.A_B)")
    s.set_initial("cyl.pB", "supply.p * cyl.A_A / (cyl.A_A + cyl.A_B)")
    s.alias("x_mm", "1000 * load.x", "mm", "piston position")
    s.alias("ref_mm", "1000 * reference.y", "mm", "position reference")
    s.alias("u", "controller.y", "", "valve command (saturated to [-1, 1] in the valve)")
    s.alias("xs", "valve.xs", "", "normalised spool position")
    s.plots = [["ref_mm", "x_mm"], ["u", "xs"], ["load.v"], ["cyl.pA", "cyl.pB"]]
    s.plot_units = {"cyl.pA": "bar", "cyl.pB": "bar"}
    return s
