"""Seed 000, Ferreira, Gomes de Almeida & Quintas: Vickers KBSDG4V-3 servo-solenoid valve.

Values exactly as printed in section 5 (static) and section 6 (dynamics), in
the paper's units (L/min, bar, L/min/bar^0.5); hydroservo converts them on
reading.

* ``DATASHEET``: "Qn = 25.5 l/min and Kq0 = 28 l/min at Pn = 35 bar; Kp0 = 36.5
  and qlk0 = 1.36 l/min at Ps = 70 bar" (the measured characteristics used
  for every figure). ``P_n`` is the drop per metering edge.
* ``VARIABLE``: variable-structure pseudo-sections fitted to pressure gain and
  leakage (eqs. 26, 29, 32).
* ``FIXED``: fixed-structure pseudo-sections fitted to pressure gain and flow
  gain, with zero leakage and zero leakage slope at x_s = 1 (eqs. 34, 36,
  37, 39, 40).
* ``DYNAMICS``: spool dynamics of Fig. 11 fitted to the manufacturer's Bode
  amplitude plots at 5, 25 and 50 % of stroke, 10-300 Hz (eq. 43), and the
  delay fitted to the phase (section 6.2).
"""

DATASHEET = {
    "name": "Vickers KBSDG4V-3 (seed 000)",
    "Q_n": "25.5 L/min",
    "P_n": "35 bar",
    "K_q0": "28 L/min",
    "K_p0": 36.5,
    "q_lk0": "1.36 L/min",
    "P_s": "70 bar",
}

VARIABLE = {
    "k": 36.5,
    "gamma": "0.1149 L/min/bar^0.5",
    "alpha": "4.241 L/min/bar^0.5",
    "beta": "6.877e-2 L/min/bar^0.5",
    "x_t": 3.858e-2,
}

FIXED = {
    "k1": "-2.142 L/min/bar^0.5",
    "k2": "5.818e-3 L/min/bar^0.5",
    "k3": "4.604 (L/min)^2/bar",
    "k4": "-5.554e-2 (L/min)^2/bar",
    "k5": "1.534e-2 (L/min)^2/bar",
}

DYNAMICS = {
    "omega_n": "1007 rad/s",
    "zeta": 0.48,
    "L_v": "125 1/s",
    "L_a": "81184 1/s^2",
    "delay": "7.625e-4 s",
}

#: Amplitudes [% of stroke] and frequencies [Hz] of the manufacturer's Bode plots (Fig. 10, eq. 41).
BODE_AMPLITUDES = (5.0, 25.0, 50.0)
BODE_FREQUENCIES = tuple(float(f) for f in range(10, 301, 10))
