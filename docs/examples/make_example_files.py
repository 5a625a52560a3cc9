"""Write the synthetic example data files that ``hydroservo examples DIR`` hands out (package data).

Run: ``python docs/examples/make_example_files.py [FOLDER]`` (default: the
package's ``src/hydroservo/data/examples``). A test regenerates them and
compares, so the shipped files are what this script makes.

None of these files is a measurement: each says in its first lines that it is
generated, from which published model, and with what noise.

* ``my_valve.toml``: a datasheet, the KBSDG4V-3 values printed by FerreiraND;
* ``measured.csv``: static curves (x_s, P_L, q_lk, Q_L) of the published
  variable-structure pseudo-sections, 1 % noise;
* ``bode.csv``: amplitude-dependent Bode data of the published spool dynamics
  (FerreiraND section 6), 0.3 dB noise on the gains;
* ``flow_gain.csv``, ``blocked_ports.csv``: test-bench curves at -15 degC of
  hydroservo's example staged-slot valve (MareAttarND_example), 1 % noise;
* ``guess.toml``: a start for ``valve identify``, every fitted value 30-40 %
  away from that valve's;
* ``arm_*.csv``: records of the robot arm (Efe2014) made by the virtual rig
  (:mod:`hydroservo.identification.rig`) at Table 5.1's rates with sensor noise
  and resolution, from the published model with :data:`RIG_TRUTH` changed:
  ``arm_step`` and ``arm_check`` (held valve-signal steps, for ``calibrate``
  and its ``--validate``), ``arm_friction`` (twelve held speeds, ``identify
  friction``), ``arm_locked`` (the piston at its stroke end, ``identify
  leakage``), ``arm_sweep_out``/``arm_sweep_in`` (slow sweeps of the valve
  signal, ``identify flow-coefficient``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

import hydroservo as hs
from hydroservo.analysis.frequency import FrequencyResponse
from hydroservo.analysis.static_bench import bench_curves
from hydroservo.components.signals import Table
from hydroservo.data import parameter_set
from hydroservo.identification import fit_datasheet, spool_response
from hydroservo.identification.rig import Sensor, held_steps, triangle, virtual_rig
from hydroservo.identification.staged_slot import noisy_curves
from hydroservo.io import read_staged_slot_valve, staged_slot_valve_toml, write_bench_curves
from hydroservo.io.records import record_files
from hydroservo.laws import pseudo_section as ps
from hydroservo.validation.ferreira import bode_grid, published_dynamics

PACKAGE_EXAMPLES = Path(__file__).resolve().parents[2] / "src" / "hydroservo" / "data" / "examples"
SEED = 2026
#: The start of ``valve identify`` (the same factors as the tests' identification start).
START_FACTORS = {
    "X_a0": 1.3,
    "X_b0": 0.7,
    "X_c0": 1.35,
    "X_d0": 0.65,
    "r": 0.7,
    "c": 1.3,
    "Cq_inf": 0.7,
    "lambda_tL": 1.4,
    "X_a0H": 1.3,
    "X_b0H": 0.7,
    "X_c0H": 0.7,
    "X_d0H": 1.3,
    "lambda_tH": 0.65,
}


def datasheet_file() -> str:
    table = parameter_set("FerreiraND").table("datasheet")
    lines = [
        "# An example datasheet: the values FerreiraND print for the Vickers KBSDG4V-3 (section 5).",
        "# Fit it: hydroservo valve fit my_valve.toml",
        "[datasheet]",
        'name = "my valve (the KBSDG4V-3 values of FerreiraND)"',
    ]
    lines += [f'{k} = "{v}"' for k, v in table.items() if k != "name"]
    return "\n".join(lines) + "\n"


def static_curves_file(rng: np.random.Generator) -> str:
    ds = parameter_set("FerreiraND").table("datasheet")
    fit = fit_datasheet(ds, "variable", "pressure-gain,leakage")
    x = np.linspace(-0.06, 0.06, 25)
    A_p, A_n = fit.sections(x)
    P_s, P_n = fit.datasheet.P_s, fit.datasheet.P_n
    noise = 0.01
    P_L = ps.relative_load_pressure(A_p, A_n) + noise * rng.standard_normal(x.size)
    q_lk = ps.leakage_blocked(A_p, A_n, P_s) * (1 + noise * rng.standard_normal(x.size))
    Q_L = ps.load_flow_no_load(A_p, A_n, 2 * P_n) * (1 + noise * rng.standard_normal(x.size))
    lines = [
        "# SYNTHETIC static curves, not a measurement: the variable-structure pseudo-sections fitted to the",
        "# KBSDG4V-3 datasheet (FerreiraND section 5) with 1 percent Gaussian noise. P_L and q_lk with blocked",
        "# ports at 70 bar, Q_L with connected ports at 35 bar per edge.",
        "# Fit them: hydroservo valve fit my_valve.toml --curves measured.csv",
        "x_s [-], P_L [-], q_lk [L/min], Q_L [L/min]",
    ]
    lines += [f"{a:.6g}, {b:.6g}, {c * 6e4:.6g}, {d * 6e4:.6g}" for a, b, c, d in zip(x, P_L, q_lk, Q_L, strict=True)]
    return "\n".join(lines) + "\n"


def bode_file(rng: np.random.Generator) -> str:
    amps, freqs = bode_grid()
    clean = spool_response(published_dynamics(), amps, freqs, steps_per_period=512)
    noisy = FrequencyResponse(amps, freqs, clean.gain_db + 0.3 * rng.standard_normal(clean.gain_db.shape), clean.phase_deg)
    lines = [
        "# SYNTHETIC Bode data, not a measurement: the rate-limited spool model with the published parameters",
        "# of FerreiraND section 6 (omega_n 1007 rad/s, xi 0.48, L_v 125 1/s, L_a 81184 1/s^2, delay 0.7625 ms),",
        "# 0.3 dB Gaussian noise on every gain. Fit it: hydroservo valve fit-dynamics bode.csv --model all",
        "frequency [Hz], amplitude [%], gain [dB], phase [deg]",
    ]
    lines += [f"{f:.6g}, {a:.6g}, {g:.6g}, {p:.6g}" for f, a, g, p in noisy.rows()]
    return "\n".join(lines) + "\n"


def bench_files(folder: Path) -> dict[str, str]:
    valve, bench = read_staged_slot_valve("aerospace-example")
    assert bench is not None
    curves = noisy_curves(bench_curves(valve, -15.0, bench, n=201), 0.01, seed=SEED)
    tmp = folder / ".bench"
    paths = write_bench_curves(curves, tmp)
    note = (
        "# SYNTHETIC test-bench curves, not a measurement: hydroservo's example staged-slot valve\n"
        "# (parameter set MareAttarND_example) at -15 degC with 1 percent noise on every reading.\n"
        "# Identify it: hydroservo valve identify flow_gain.csv blocked_ports.csv --start guess.toml --predict -40,32\n"
    )
    out = {p.name: note + p.read_text() for p in paths}
    for p in paths:
        p.unlink()
    tmp.rmdir()
    start = valve.replace(**{k: valve.values[k] * f for k, f in START_FACTORS.items()})
    header = (
        "A start for `hydroservo valve identify`: hydroservo's example staged-slot valve\n"
        "(MareAttarND_example) with every identified value 30-40 % away from its own."
    )
    out["guess.toml"] = staged_slot_valve_toml(start, None, header=header)
    return out


#: The robot arm "on the rig": the published model (robot-arm) with these values, which calibrate must find.
RIG_TRUTH = {"spool.tau": "24 ms", "valve.c_v": "1.3e-4 m^2/s/Pa^0.5", "cyl.C_Li": "3e-13 m^3/s/Pa", "load.B": "350 N*s/m",
             "load.F_c0": "60 N"}
#: Table 5.1's logger with the resolution of a 16-bit channel on each sensor's range (0.001 bar, 0.001 mm).
RIG_SENSORS = {
    "cyl.pA": Sensor(40.0, "bar", 0.05, 0.001),
    "cyl.pB": Sensor(40.0, "bar", 0.05, 0.001),
    "load.x": Sensor(200.0, "mm", 0.02, 0.001),
    "command.y": Sensor(200.0, "", 0.0, 0.0001),
}


def _arm(times: list[float], values: list[float], **sets: str) -> hs.System:
    arm = hs.load_model("robot-arm")
    for key, value in sets.items():
        arm.set(key, value)
    arm.replace(Table("command", times=times, values=values))
    return arm


def rig_records() -> dict[str, str]:
    """Records of the robot arm on the virtual rig, by file name."""
    programmes = {
        # name: (valve-signal programme, extra settings, what it is for)
        "arm_step": (held_steps([0.368, -0.5], 0.5, rest=0.4), {}, "hydroservo calibrate"),
        "arm_check": (held_steps([0.505, -0.258, 0.2], 0.5, rest=0.5), {}, "hydroservo calibrate --validate"),
        "arm_friction": (held_steps([s * u for u in (0.2, 0.25, 0.3, 0.4, 0.5, 0.6) for s in (1, -1)], 0.6, rest=0.2), {},
                         "hydroservo identify friction"),
        "arm_locked": (([0.0, 0.1, 0.105, 3.0], [0.0, 0.0, 0.15, 0.15]), {"load.x0": "295 mm"}, "hydroservo identify leakage"),
        "arm_sweep_out": (triangle(0.75, 3.0), {}, "hydroservo identify flow-coefficient"),
        "arm_sweep_in": (triangle(-0.75, 3.0), {"load.x0": "280 mm"}, "hydroservo identify flow-coefficient"),
    }
    out = {}
    for k, (name, ((times, values), sets, use)) in enumerate(programmes.items()):
        t_end = max(times[-1], 4.0) if name in ("arm_step", "arm_check") else times[-1]
        times = [*times[:-1], t_end]
        arm = _arm(times, values, **sets)
        record = virtual_rig(arm, RIG_SENSORS, params=RIG_TRUTH, seed=SEED + k, t_end=t_end, name=name)
        note = (
            f"SYNTHETIC record, not a measurement: the robot arm (Efe2014; built-in model robot-arm{''.join(f', {a} = {b}' for a, b in sets.items())})\n"
            f"on hydroservo's virtual rig with {', '.join(f'{a} = {b}' for a, b in RIG_TRUTH.items())},\n"
            "logged at Efe2014 Table 5.1's rates with 0.05 bar and 0.02 mm of Gaussian noise, 0.001 bar and 0.001 mm resolution.\n"
            f"Use it with: {use}"
        )
        out.update(record_files(record, comment=note))
    return out


def example_data(folder: Path) -> dict[str, str]:
    """The generated example files: name -> text."""
    rng = np.random.default_rng(SEED)
    files = {"my_valve.toml": datasheet_file(), "measured.csv": static_curves_file(rng), "bode.csv": bode_file(rng)}
    files.update(bench_files(folder))
    files.update(rig_records())
    return files


def main(folder: Path = PACKAGE_EXAMPLES) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in example_data(folder).items():
        (folder / name).write_text(text, encoding="utf-8")
        print(folder / name)


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else PACKAGE_EXAMPLES)
