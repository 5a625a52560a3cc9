"""Hopsan's models beside Hopsan
=============================

Each of Hopsan's example models that ``hydroservo validate hopsan-examples`` runs, imported, beside Hopsan's
converged result of the original file (its component tests are rows of the validation table): two of its main traces each (a position and a pressure, the flows of a valve test, the signals of
a signal test), one panel per trace, hydroservo's run (default solver settings) over Hopsan's reference, with the
trace's largest deviation in per cent of its range (the validation's figure) in the panel's title.

Run: ``python docs/examples/plot_hopsan_examples.py`` (writes docs/img/hopsan_examples.png).
"""

import os
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from hydroservo.data import reference_path
from hydroservo.io.model_file import load_model
from hydroservo.validation.hopsan_examples import MODELS, TOLERANCE, _index, _reference, deviations

#: the traces drawn of each model (aliases of its Hopsan variables); a model not listed shows its widest position
#: and pressure, or its two widest signals
TRACES = {
    "position-servo": ["Translational_Spring.P1.Position", "4_3_Servo_Valve.PA.Pressure"],
    "hydraulic-open-centre-valve-test": ["Flow_Sensor_4.P1.Flow", "6_3_Open_Center_Valve.PT.Flow"],
    "open-centre-system": [
        "C_type_Variable_Displacement_Machine.P3.AngularVelocity", "6_3_Open_Center_Valve.PA.Pressure",
    ],
    "pressure-controlled-pump": ["HydraulicPistonMkload.Pmp.Position", "HydraulicPistonMkload.P1.Pressure"],
    "pressure-controlled-pump-simple": ["Position_Transducer.P1.Position", "Q_Type_Variable_Displacement_Pump.P2.Pressure"],
    "sub-system-example": ["Servo1.Translational_Mass.P2.Position", "Servo1.4_3_Servo_Valve.PA.Pressure"],
    "hydraulic-43-valve-test": ["4_3_Servo_Valve.PA.Flow", "4_3_Servo_Valve.PB.Flow"],
    "hydraulic-valve-43-test": ["4_3_Directional_Valve.PA.Flow", "4_3_Directional_Valve.PP.Flow"],
    "hydraulic-variable-displacement-pump-test": ["Laminar_Orifice_2.P1.Pressure", "Hydraulic_Volume_4.P2.Pressure"],
    "dynamic-pressure-feedback": ["Position_Sensor.out.Value", "Pressure_Sensor_1.P1.Pressure"],
    "routing-test": ["Staircase.out.Value", "Route_With_Four_Inputs.out.Value"],
    "pressure-relief-valve-characteristics": ["Pressure_Relief_Valve.P1.Flow", "Turbulent_Orifice.P1.Flow"],
    "hydraulic-22-valve-test": ["Rate_limiter_1.out.Value", "2_2_Directional_Valve.PP.Flow"],
    "hydraulic-22-on-off-valve-test": ["Rate_limiter_2.out.Value", "Flow_Rate_Transducer.P1.Flow"],
    "hydraulic-32-on-off-valve-test": ["Rate_limiter_2.out.Value", "Flow_Rate_Transducer.P1.Flow"],
    "hydraulic-42-on-off-valve-test": ["Flow_Rate_Transducer.P1.Flow", "Flow_Rate_Transducer_1.P1.Flow"],
    "signal-math-functions-test": ["Atan2.out.Value", "Log_1.out.Value"],
    "translational-mass-with-coulomb-friction-test": [
        "Translational_Mass_With_Coulomb_Friction.P2.Velocity", "Force_Transducer.P1.Force",
    ],
    "rate-limiter-test": ["Rate_limiter.out.Value", "Rate_limiter_1.out.Value"],
    "hydraulic-pressure-relief-valve-g-test": ["Prescribed_Source_Q.P1.Pressure", "HydraulicPressureReliefValveG.xv.Value"],
    "hydraulic-pressure-reducing-valve-g-test": [
        "Pressure_Transducer.P1.Pressure", "HydraulicPressureReducingValveG.xv.Value",
    ],
    "hydraulic-pressure-controlled-22-valve-test": [
        "Pressure_Controlled_2_2_Valve__default_closed_.x_v.Value", "Pressure_Controlled_2_2_Valve__default_closed_.PA.Flow",
    ],
    "hydraulic-pressure-controlled-22-valve2-test": [
        "Pressure_Controlled_2_2_Valve__default_open_.x_v.Value", "Pressure_Controlled_2_2_Valve__default_open_.PP.Flow",
    ],
    "hydraulic-pressure-controlled-42-valve-test": [
        "Pressure_Controlled_4_2_Valve__default_closed_.x_v.Value", "Pressure_Controlled_4_2_Valve__default_closed_.PB.Flow",
    ],
    "hydraulic-pressure-controlled-42-valve2-test": ["Flow_Sensor.P1.Flow", "Flow_Sensor_1.P1.Flow"],
    "hydraulic-pressure-controlled-42-valve3-test": [
        "Pressure_Controlled_4_2_Valve.PA.Flow", "Pressure_Controlled_4_2_Valve.PB.Flow",
    ],
    "hydraulic-ackumulator-test": ["Gas_Accumulator.pa.Value", "Gas_Accumulator.P1.Flow"],
    "hydraulic-piston-ackumulator-test": [
        "HydraulicPistonAckumulator.xmp.Value", "HydraulicPistonAckumulator.P1.Flow",
    ],
}
#: how each kind is shown: (factor from SI, unit)
SHOWN = {
    "Position": (1e3, "mm"), "Velocity": (1.0, "m/s"), "Force": (1.0, "N"), "Pressure": (1e-5, "bar (abs.)"),
    "Flow": (6e4, "L/min"), "Value": (1.0, ""), "Angle": (1.0, "rad"), "AngularVelocity": (1.0, "rad/s"),
    "Torque": (1.0, "N m"),
}


def chosen(name: str, columns: list[str], ref: np.ndarray) -> list[str]:
    if name in TRACES:
        return TRACES[name]
    width = {c: float(np.ptp(ref[:, i + 1])) for i, c in enumerate(columns)}
    out = []
    for kind in ("Position", "Pressure"):
        of_kind = [c for c in columns if c.endswith(f".{kind}") and width[c] > 0]
        out += sorted(of_kind, key=width.get, reverse=True)[:1]
    signals = sorted((c for c in columns if c.endswith(".Value")), key=width.get, reverse=True)
    return (out + signals)[:2]


def main() -> None:
    # the example models: the component tests (which check one part each) are rows of the validation table
    names = [n for n in MODELS if n in _index() and MODELS[n].path.startswith("Example Models/")]
    columns_of_panels = 4
    rows = -(-2 * len(names) // columns_of_panels)
    fig, axes = plt.subplots(rows, columns_of_panels, figsize=(17, 2.9 * rows), squeeze=False)
    for ax in axes.flat[2 * len(names):]:
        ax.set_visible(False)
    warnings.simplefilter("ignore")  # implausible peaks are Hopsan's too (Position Servo's 53 MPa)
    for k, name in enumerate(names):
        header, ref = _reference(name)
        columns = [c.split(" [")[0] for c in header[1:]]
        start = float(_index()[name]["start"])
        system = load_model(reference_path(f"hopsan/{name}.toml"))
        spec = MODELS[name]  # a model that needs a tighter accuracy or a larger budget says so in its Spec
        settings = {} if spec.accuracy is None else {"accuracy": spec.accuracy}
        result = system.simulate(n_points=4001, max_steps=spec.max_steps, method=spec.method, **settings)
        dev = deviations(name)
        for j, alias in enumerate(chosen(name, columns, ref)):
            ax = axes.flat[2 * k + j]
            kind = alias.rsplit(".", 1)[-1]
            factor, unit = SHOWN[kind]
            y_ref = ref[:, columns.index(alias) + 1]
            ax.plot(ref[:, 0], factor * y_ref, color="0.6", lw=4, label="Hopsan, converged")
            ax.plot(result.t + start, factor * result[alias], color="tab:blue", lw=1, label="hydroservo")
            figure = dev[alias]
            ax.set_title(
                f"{name}\n{alias}: {figure:.2g} % of range",
                fontsize=8.5, color="tab:red" if figure > TOLERANCE else "black",
            )
            ax.set_ylabel(f"{kind.lower() if kind != 'Value' else 'signal'}" + (f" [{unit}]" if unit else ""), fontsize=8)
            ax.tick_params(labelsize=7.5)
            ax.set_xlim(ref[0, 0], ref[-1, 0])  # Hopsan's logged span (a model that starts before 0 runs from there)
            ax.grid(True, alpha=0.3)
            if k == 0 and j == 0:
                ax.legend(fontsize=7.5, loc="lower right")
    for ax in axes[-1]:
        ax.set_xlabel("time [s]", fontsize=8)
    fig.suptitle(
        "Hopsan's example models imported by hydroservo (blue) against Hopsan's converged results (grey); "
        f"red titles: beyond the {TOLERANCE:g} % criterion",
        fontsize=11,
    )
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    out = Path(os.environ.get("HYDROSERVO_DOCS_IMG") or Path(__file__).resolve().parents[1] / "img") / "hopsan_examples.png"
    fig.savefig(out, dpi=80)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
