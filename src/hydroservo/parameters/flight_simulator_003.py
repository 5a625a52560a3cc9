"""Seed 003, "Simulation of a nonlinear hydraulic system", Appendix C.

Flight-simulator actuator: asymmetric cylinder, MOOG 72 two-stage servovalve,
closed position loop. Values exactly as printed, in the dissertation's units
(in, lb, psi, mA, V); hydroservo converts them on reading.

Notes on the table
------------------
* ``C_d sqrt(2/rho)`` is printed as "C 2/9 104.5 in^2/sqrt(lb) sec": the
  discharge coefficient times sqrt(2/rho), whose unit in^2/(sqrt(lb) s) fits.
  Multiplied by the area gradient ``w`` it is the valve flow coefficient.
  Eq. (4-9) confirms the reading: with it, the spool null offset comes out
  at 5.0e-5 in, the published 5.07e-5 in.
* ``omega_n`` and ``zeta_n`` of the first stage and ``omega_h``, ``delta_h``
  of the spool stage are given directly; ``J_f``, ``B_f``, ``M_v``, ``V_v``
  and ``K_ce`` are not needed.
* ``M`` is the mass in lb s^2/in (slug-inch units): 16.6 lb s^2/in = 2907 kg;
  ``W`` = 6400 lb is the weight component along the actuator.
"""

from __future__ import annotations

#: Appendix C, name -> (value with unit as printed, description from Appendix E)
APPENDIX_C: dict[str, tuple[str, str]] = {
    "A1": ("3.40 in^2", "actuator rod end area"),
    "A2": ("8.29 in^2", "actuator full end area"),
    "Av": ("0.1104 in^2", "valve spool end area"),
    "Bm": ("10 lbf*s/in", "damping coefficient of actuator"),
    "Cl": ("0.6e-3 in^5/s/lbf", "actuator leakage coefficient"),
    "Cd_sqrt_2_rho": ("104.5 in^2/lbf^0.5/s", "orifice discharge coefficient times sqrt(2/rho)"),
    "Ga": ("6.0", "forward gain"),
    "Gf": ("0.278 V/in", "feedback gain"),
    "K1": ("0.031 in*lbf/mA", "torque motor gain"),
    "K2": ("187.0 in^3/s/in", "flapper nozzle flow gain"),
    "Kf": ("90.0 in*lbf/in", "net stiffness of armature/flapper"),
    "Kw": ("2.4 in*lbf/in", "feedback wire stiffness"),
    "M": ("16.6 lbf*s^2/in", "actuator load mass"),
    "Ps": ("1500 psi", "supply pressure"),
    "Rv": ("668.1 ohm", "electrical resistance of valve and circuit"),
    "RC": ("0.34 s", "time constant of RC network"),
    "Vt1": ("106.7 in^3", "rod end volume at mid stroke, including piping"),
    "Vt2": ("245.0 in^3", "full end volume at mid stroke, including piping"),
    "w": ("2.36 in", "valve spool area gradient"),
    "W": ("6400 lbf", "actuator load weight"),
    "omega_n": ("4580 rad/s", "natural frequency of first stage"),
    "zeta_n": ("0.4", "damping factor of first stage"),
    "omega_h": ("1940 rad/s", "natural frequency of second stage"),
    "delta_h": ("1.0", "damping factor of second stage"),
    "beta": ("1.0e5 psi", "fluid bulk modulus"),
}
