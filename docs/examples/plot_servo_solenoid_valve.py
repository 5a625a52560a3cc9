"""Servo-solenoid valve: characteristics from a datasheet
======================================================

Figures of the servo-solenoid valve of FerreiraND for the docs (analogues of the paper's Figs. 2-9 and 12).

Run: ``python docs/examples/plot_servo_solenoid_valve.py``; writes ``docs/img/ferreira_*.png``.
"""

from __future__ import annotations

import os
from pathlib import Path

from hydroservo import load_model
from hydroservo.data import parameter_set
from hydroservo.identification import fit_datasheet, fit_spool_dynamics, spool_response
from hydroservo.plotting import pseudo_section as plotting
from hydroservo.validation.ferreira import bode_grid, published_dynamics

IMG = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img")


def main() -> None:
    datasheet = parameter_set("FerreiraND").table("datasheet")
    var = fit_datasheet(datasheet, "variable", "pressure-gain,leakage").valve
    fix = fit_datasheet(datasheet, "fixed", "pressure-gain,flow-gain").valve
    ds = fit_datasheet(datasheet).datasheet
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
    amps, freqs = bode_grid()
    data = spool_response(published_dynamics(), amps, freqs, steps_per_period=512, label="published model")
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
