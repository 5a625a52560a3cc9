"""Seed 002, Maré & Attar: four-way servovalve power stage across temperature.

* ``TABLE_2``: the published "model performance over temperature changes"
  (measured values and the model's relative errors) for the aerospace
  servovalve of the paper, at fluid temperatures -40, -15 and +32 degC. The
  paper identified its model at -15 degC.
* ``EXAMPLE_VALVE`` and ``EXAMPLE_BENCH``: **not published**. The paper prints
  no geometry, no identified parameters and no rated values of its valve
  ("an aerospace servovalve equipping a recent commercial aircraft flight
  control actuator"). These are hydroservo's own plausible flight-control
  servovalve power stage, chosen so that its -15 degC characteristics have the
  magnitudes of Table 2 (leakage about 0.2 % Q_n, pressure gain a few hundred
  % P_s / % X_n, low and high flow gains about 0.5 and 1 % Q_n / % X_n, useport
  pressure at null below half supply): two staged slots per edge, 4 mm wide up
  to a step at 100 um (25 % of the 0.4 mm rated stroke) and 8 mm beyond, a
  1.5 um radial clearance, 2 um edge radius, a few tenths of a micrometre of
  overlap on the supply edges and more underlap on the return edges (as the
  paper's section 3.3 describes), each edge slightly different, as machining
  leaves them; 3000 psi supply; Skydrol.
"""

#: Seed 002 Table 2, as printed. ``measured`` in the row's unit; ``error`` is the
#: model's relative error, read as (model - measured) / measured.
TABLE_2 = {
    "temperatures": (-40.0, -15.0, 32.0),
    "max_leakage": {"measured": (0.12, 0.23, 0.33), "error": (-0.1236, -0.0182, -0.0093)},
    "pressure_gain_025": {"measured": (202.0, 300.0, 381.0), "error": (-0.02, -0.31, -0.45)},
    "pressure_gain_40": {"measured": (209.0, 319.0, 481.0), "error": (-0.24, -0.33, -0.55)},
    "flow_gain_low": {"measured": (0.48, 0.46, 0.49), "error": (0.01, 0.04, -0.01)},
    "flow_gain_high": {"measured": (0.85, 1.02, 1.03), "error": (-0.13, 0.01, -0.06)},
    "useport_null": {"measured": (37.6, 46.2, 54.3), "error": (0.077, -0.156, -0.277)},
}

#: Printed changes from -15 degC (the rows "Change from -15 degC").
TABLE_2_CHANGES = {
    "max_leakage": (-0.48, 0.44),
    "pressure_gain_025": (-0.34, 0.27),
    "pressure_gain_40": (-0.34, 0.51),
    "useport_null": (-0.19, 0.18),
}

#: hydroservo's example valve (see the module docstring): parameters of
#: :class:`hydroservo.components.spool.MareSpoolValve`.
EXAMPLE_VALVE = {
    "fluid": "skydrol",
    "n": 2,
    "w_L": "4 mm",
    "w_H": "8 mm",
    "r": "2 um",
    "c": "1.5 um",
    "Cq_inf": 0.65,
    "lambda_tL": 8.0,
    "lambda_tH": 300.0,
    "X_a0": "-0.3 um",
    "X_b0": "0.6 um",
    "X_c0": "-0.4 um",
    "X_d0": "0.5 um",
    "X_a0H": "-100 um",
    "X_b0H": "-102 um",
    "X_c0H": "-98 um",
    "X_d0H": "-101 um",
}

#: Test conditions of the example (ARP490 bench).
EXAMPLE_BENCH = {"P_s": "3000 psi", "P_r": "0 psi", "X_n": "0.4 mm"}
