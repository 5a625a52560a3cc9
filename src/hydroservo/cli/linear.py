"""``hydroservo linearize``: the linear model of a system at an operating point, its modes and valve coefficients."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, output_folder, print_json
from hydroservo.cli.models import load_with_sets
from hydroservo.errors import ParameterError, shorten

__all__ = ["add_parsers"]


def _names(text: str | None) -> list[str] | None:
    if text is None:
        return None
    names = [n.strip() for n in text.split(",") if n.strip()]
    if not names:
        raise ParameterError(f"{text!r}: expected comma-separated signal names, e.g. spool.u,load.F_ext")
    return names


def _at(text: str) -> Any:
    """``trim``, ``initial``, ``STATE=VALUE,...`` or an operating-point file (TOML)."""
    from pathlib import Path

    from hydroservo.io import read_operating_point

    if text in ("trim", "initial"):
        return text
    if "=" in text and not Path(text).exists():
        point = {}
        for item in text.split(","):
            if "=" not in item:
                raise ParameterError(f"--at {shorten(text)!r}: {shorten(item)!r}: expected STATE=VALUE, e.g. cyl.pA=6.5bar")
            key, val = item.split("=", 1)
            point[key.strip()] = val.strip()
        return point
    return read_operating_point(text)


def cmd_linearize(args: argparse.Namespace) -> int:
    from hydroservo.analysis.linear import linearize, valve_coefficients
    from hydroservo.cli.common import frequencies
    from hydroservo.io import write_linear_model
    from hydroservo.io.files import safe_name
    from hydroservo.units import to_si

    system = load_with_sets(args.model, args.set)
    at = _at(args.at)
    t = to_si(args.t, "s", what="--t")
    free = _names(args.free) or []
    lin = linearize(system, at, inputs=_names(args.inputs), outputs=_names(args.outputs), t=t, free=free)
    valves = valve_coefficients(system, lin.x0, t=t)
    f = frequencies(args.frequencies) if args.frequencies else None
    simulated = None
    if args.simulate:
        import numpy as np

        from hydroservo.analysis.linear import simulated_response
        from hydroservo.cli.common import numbers

        amps = numbers(args.simulate, "--simulate", above=0.0, expected="positive amplitudes in the input's unit")
        grid_sim = f if f is not None else np.logspace(0, 2, 9)
        simulated = simulated_response(system, lin, grid_sim, amps, input=lin.inputs[0], output=lin.outputs[0])
    files: dict[str, str] = {}
    if args.out is not None or not args.json:
        import numpy as np

        from hydroservo.plotting.linear import plot_linear_bode, plot_poles

        name = safe_name(system.name)
        out = output_folder(args, f"hydroservo-{name}-linear")
        names = [f"{name}-linear.json", f"{name}-poles.png", f"{name}-bode.png"]
        if simulated is not None:
            names.append(f"{name}-bode-simulated.png")
        out.expect(names)
        grid = f if f is not None else np.logspace(-1, 3, 400)
        pairs = [(i, o) for i in lin.inputs[:1] for o in lin.outputs[:4]]
        with out:
            write_linear_model(lin, out.file(names[0]), {"valves": [v.to_dict() for v in valves]})
            plot_poles(lin, file=out.file(names[1]))
            plot_linear_bode(lin, grid, pairs, file=out.file(names[2]))
            if simulated is not None:
                linear_fr = lin.bode(simulated.frequencies, lin.inputs[0], lin.outputs[0])
                simulated.plot([linear_fr], file=out.file(names[3]),
                               title=f"{lin.outputs[0]} / {lin.inputs[0]}: simulated sines (markers) and the linear model")
        files = {"json": out.final(names[0]), "poles": out.final(names[1]), "bode": out.final(names[2])}
        if simulated is not None:
            files["bode_simulated"] = out.final(names[3])
    if args.json:
        report = {**lin.to_dict(), "valves": [v.to_dict() for v in valves]}
        if f is not None:
            report["frequency_response"] = [
                {"input": i, "output": o, "frequencies_Hz": f.tolist(),
                 "real": (H := lin.transfer(f, i, o)).real.tolist(), "imag": H.imag.tolist()}
                for i in lin.inputs for o in lin.outputs
            ]
        if simulated is not None:
            report["simulated_response"] = {
                "input": lin.inputs[0], "output": lin.outputs[0], "amplitudes": simulated.amplitudes.tolist(),
                "frequencies_Hz": simulated.frequencies.tolist(), "gain_dB": simulated.gain_db.tolist(),
                "phase_deg": simulated.phase_deg.tolist(),
                "linear_gain_dB": lin.bode(simulated.frequencies, lin.inputs[0], lin.outputs[0]).gain_db[0].tolist(),
                **({"note": simulated.info["not_run"]} if "not_run" in simulated.info else {}),
            }
        if files:
            report["files"] = files
        print_json(report)
        return 0
    _print(lin, valves, files)
    if simulated is not None:
        _print_simulated(lin, simulated)
    return 0


def _print_simulated(lin: Any, sim: Any) -> None:
    linear = lin.bode(sim.frequencies, lin.inputs[0], lin.outputs[0])
    print(f"  {lin.outputs[0]} / {lin.inputs[0]}, simulated sines against the linear model [dB]:")
    print("    " + "f [Hz]".rjust(8) + "linear".rjust(10) + "".join(f"{'A=' + format(a, 'g'):>12}" for a in sim.amplitudes))
    for j, fk in enumerate(sim.frequencies):
        print("    " + f"{fk:8.3g}" + f"{linear.gain_db[0, j]:10.2f}" + "".join(f"{sim.gain_db[i, j]:12.2f}" for i in range(sim.amplitudes.size)))
    if "not_run" in sim.info:
        print(f"    note: {sim.info['not_run']}")


def _print(lin: Any, valves: list[Any], files: dict[str, str]) -> None:
    from hydroservo.units import si_unit

    print(f"{lin.name}: linear model at {lin.info.get('at', '')} (t = {lin.t:g} s)"
          + (f", steady motion of {', '.join(lin.info['free'])}" if lin.info.get("free") else ""))
    print(f"  {len(lin.states)} states, {len(lin.inputs)} inputs ({', '.join(lin.inputs)}), {len(lin.outputs)} outputs")
    print("  operating point:")
    for s, v in lin.x0.items():
        drift = lin.drift[s]
        moving = f"   (rate {drift:.4g} {si_unit(lin.units[s])}/s)" if abs(drift) > 1e-9 * max(1.0, abs(v)) else ""
        print(f"    {s:<24} {v:>12.5g} {si_unit(lin.units[s])}{moving}")
    print("  modes (slowest first):")
    print(f"    {'pole [1/s]':>26}  {'f_n [Hz]':>9}  {'damping':>7}  {'tau [s]':>9}  states taking part")
    for m in lin.modes():
        lam = m.eigenvalue
        pole = f"{lam.real + 0.0:.4g}" + (f" ± {abs(lam.imag):.4g}j" if m.oscillatory else "")
        zeta = "   -   " if m.damping != m.damping else f"{m.damping:7.3f}"
        tau = f"{m.time_constant:9.3g}" if abs(m.time_constant) < 1e12 else "      inf"
        parts = ", ".join(f"{s} {100 * m.participation[s]:.0f}%" for s in m.main_states(0.1))
        print(f"    {pole:>26}  {m.frequency:9.4g}  {zeta}  {tau}  {parts}")
    for vc in valves:
        print(f"  valve {vc.valve} at x_v = {vc.point['xv'] * 1e3:.4g} mm, p_A = {vc.point['pA'] / 1e5:.4g} bar, "
              f"p_B = {vc.point['pB'] / 1e5:.4g} bar ([Efe2014] eqs. 4.8-4.12; closed form in parentheses):")
        for key, unit in (("K_Qx", "m^2/s"), ("K_Qp", "m^3/(s Pa)"), ("K_px", "Pa/m")):
            for side in ("A", "B"):
                k = f"{key}_{side}"
                closed = f"  ({vc.closed_form[k]:.4g})" if vc.closed_form else ""
                print(f"    {k:<7} {vc.model[k]:>11.4g}{closed} {unit}")
    for what, path in files.items():
        print(f"  {what}: {path}")


def add_parsers(sub: Any) -> None:
    """Add ``linearize``."""
    p = sub.add_parser(
        "linearize",
        help="linear model of a system at an operating point: matrices, modes, valve coefficients",
        description="State-space matrices A, B, C, D from the exact Jacobians at an operating point, the modes "
        "(poles, natural frequencies, damping, participating states) and the valve coefficients of "
        "[Efe2014] eqs. 4.8-4.12.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option, with units: --set "command.amplitude=0.5"')
    p.add_argument("--at", default="trim", metavar="trim|initial|FILE|STATE=VALUE,...",
                   help="operating point: an equilibrium (default), the initial state, an operating-point file "
                   "(TOML, state = value with units) or states given here")
    p.add_argument("--t", default="0", metavar="T", help="time of the operating point (the signals' values then), e.g. 0.3")
    p.add_argument("--free", default=None, metavar="STATE,...",
                   help="states left free by the trim: a steady motion, e.g. --free load.x")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs (spool.u) or parameters (supply.p); default: the inputs fed by signal blocks")
    p.add_argument("--outputs", default=None, metavar="NAME,...", help="states, outputs or aliases; default: the states")
    p.add_argument("--frequencies", default=None, metavar="F1,F2,...|START:STOP:STEP",
                   help="frequencies [Hz] of the Bode plot (and of the JSON's frequency response)")
    p.add_argument("--simulate", default=None, metavar="A1,A2,...",
                   help="also run the nonlinear system with sines of these amplitudes (the first input's unit) about "
                   "the operating point: its gain beside the linear one, for the first output, shows where linearity ends")
    add_output_options(p, "hydroservo-NAME-linear")
    p.add_argument("--json", action="store_true",
                   help="print the matrices with their names, the modes and the valve coefficients as JSON "
                   "(files are written only with --out)")
    p.set_defaults(func=cmd_linearize)
