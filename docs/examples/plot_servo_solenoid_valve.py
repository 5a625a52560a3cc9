"""Figures of the seed-000 servo-solenoid valve for the docs (analogues of the paper's Figs. 2-9 and 12).

Run: ``python docs/examples/plot_servo_solenoid_valve.py``; writes ``docs/img/ferreira_*.png``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from hydroservo import load_model, plotting
from hydroservo.identification import fit_datasheet, fit_spool_dynamics, spool_response
from hydroservo.parameters import ferreira_000 as paper

IMG = Path(__file__).resolve().parents[1] / "img"


def main() -> None:
    var = fit_datasheet(paper.DATASHEET, "variable", "pressure-gain,leakage")
    fix = fit_datasheet(paper.DATASHEET, "fixed", "pressure-gain,flow-gain")
    ds = var.datasheet
    plotting.plot_pseudo_sections(
        var,
        title="KBSDG4V-3, variable structure (k, gamma from K_p0 and q_lk0)",
        file=IMG / "ferreira_pseudo_sections.png",
    )
    plotting.plot_null_characteristics(
        var,
        ds.P_s,
        title="Variable structure: P_L and q_lk at 70 bar (cf. Fig. 4)",
        file=IMG / "ferreira_null_variable.png",
    )
    plotting.plot_null_characteristics(
        fix, ds.P_s, title="Fixed structure: P_L and q_lk at 70 bar (cf. Fig. 7)", file=IMG / "ferreira_null_fixed.png"
    )
    plotting.plot_load_flow(
        fix, ds.P_n, title="Fixed structure: load flow (cf. Figs. 8-9)", file=IMG / "ferreira_load_flow_fixed.png"
    )
    plotting.plot_pressure_flow(var, ds.P_s, file=IMG / "ferreira_pressure_flow.png")
    dyn = {"omega_n": 1007.0, "zeta": 0.48, "L_v": 125.0, "L_a": 81184.0, "delay": 7.625e-4}
    amps, freqs = np.array(paper.BODE_AMPLITUDES) / 100, np.array(paper.BODE_FREQUENCIES)
    data = spool_response(dyn, amps, freqs, steps_per_period=512, label="published model")
    fits = [fit_spool_dynamics(data, m) for m in ("rate-limited", "second-order", "first-order")]
    for f in fits:
        f.response.label = f"{f.model} fit"
    data.plot(
        [f.response for f in fits],
        title="Spool Bode data of the published model and three fitted fidelities",
        file=IMG / "ferreira_bode_fidelities.png",
        f_max=200.0,
    )
    system = load_model("servo-solenoid-cylinder")
    res = system.simulate(n_points=801)
    res.plot(
        *system.plots,
        units=system.plot_units,
        title="KBSDG4V-3 positioning a cylinder: 50 mm step",
        file=IMG / "ferreira_cylinder_step.png",
    )


if __name__ == "__main__":
    main()
