"""``hydroservo valve characteristics`` and ``valve identify``: the seed-002 spool-valve tools (thin shell)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

import numpy as np

from hydroservo.cli_valve import _numbers
from hydroservo.errors import ParameterError

__all__ = ["add_spool_commands"]


def _temperatures(text: str, what: str) -> list[float]:
    if text.strip().lower().endswith(("degc", "°c", "c")):
        raise ParameterError(f"{what} {text!r}: give bare numbers in degC, e.g. -40,-15,32")
    return _numbers(text, what)


def _metrics_table(table: dict[str, Any]) -> list[str]:
    from hydroservo.analysis.bench import METRICS

    temps = sorted(table["metrics"])
    ref = table["reference"]
    lines = [f"{'':44s}" + "".join(f"{t:>11g} °C" for t in temps)]
    for key, (label, unit) in METRICS.items():
        lines.append(f"{label + ' [' + unit + ']':44s}" + "".join(f"{table['metrics'][t][key]:>14.4g}" for t in temps))
        lines.append(
            f"{'  change from ' + format(ref, 'g') + ' °C':44s}"
            + "".join(f"{'-':>14s}" if t == ref else f"{table['change'][t][key] * 100:>+13.0f}%" for t in temps)
        )
    return lines


def _json_table(table: dict[str, Any]) -> dict[str, Any]:
    return {
        "reference_degC": table["reference"],
        "Q_n_m3_s": table["Q_n"],
        "metrics": {f"{t:g}": v for t, v in table["metrics"].items()},
        "change_from_reference": {f"{t:g}": v for t, v in table["change"].items()},
    }


def cmd_characteristics(args: argparse.Namespace) -> int:
    from hydroservo import plotting
    from hydroservo.analysis.bench import SpoolBridge, bench_curves, pressure_flow, temperature_table
    from hydroservo.identification.files import read_spool_valve, write_bench_curves

    comp, bench = read_spool_valve(args.params)
    if bench is None:
        raise ParameterError(f"{args.params}: no [bench] table; expected P_s and X_n (the test conditions)")
    valve = SpoolBridge.from_component(comp)
    temps = _temperatures(args.temperature, "--temperature")
    if args.points < 21:
        raise ParameterError(f"--points {args.points}: expected at least 21 openings")
    stem = Path(args.params).stem
    out = Path(args.out or f"hydroservo-characteristics-{stem}")
    out.mkdir(parents=True, exist_ok=True)
    curves = [bench_curves(valve, t, bench, n=args.points, strict=args.strict) for t in temps]
    table = temperature_table(valve, bench, temps, args.reference)
    files: dict[str, str] = {}
    for c in curves:
        for path in write_bench_curves(c, out, stem=f"T{c.temperature:g}_"):
            files[path.stem] = str(path)
    title = f"{stem}: {valve.fluid.name}, P_s = {bench.P_s / 1e5:.4g} bar, X_n = {bench.X_n * 1e3:g} mm"
    plotting.plot_bench_characteristics(curves, title=title, file=out / "characteristics.png")
    openings = [f * bench.X_n for f in (-1.0, -0.5, -0.25, -0.1, 0.1, 0.25, 0.5, 1.0)]
    P_L, Q_L = pressure_flow(valve, table["reference"], bench, openings)
    plotting.plot_pressure_flow_family(
        P_L,
        Q_L,
        openings,
        bench,
        title=f"{stem}: pressure-flow at {table['reference']:g} °C",
        file=out / "pressure_flow.png",
    )
    plotting.plot_discharge_coefficient(valve.params, file=out / "discharge_coefficient.png")
    files.update({k: str(out / f"{k}.png") for k in ("characteristics", "pressure_flow", "discharge_coefficient")})
    if args.json:
        print(json.dumps({"valve": str(args.params), **_json_table(table), "files": files}, indent=2))
        return 0
    qn_note = "" if bench.Q_n is not None else f" (computed: no-load flow at X_n, {bench.T_rated:g} °C)"
    print(f"{title}, Q_n = {table['Q_n'] * 6e4:.4g} L/min{qn_note}")
    print("\n".join(_metrics_table(table)))
    print(f"wrote {len(files)} files to {out}")
    return 0


def cmd_identify(args: argparse.Namespace) -> int:
    from hydroservo import plotting
    from hydroservo.analysis.bench import SpoolBridge, bench_curves, temperature_table
    from hydroservo.identification.bridge import HIGH_GAIN, LOW_GAIN, identify_bridge
    from hydroservo.identification.files import read_bench_curves, read_spool_valve, spool_valve_toml

    data = read_bench_curves(args.curves)
    comp, _ = read_spool_valve(args.start)
    start = SpoolBridge.from_component(comp)
    start.fluid.check_range(np.array([data.bench.P_r, data.bench.P_s]), data.temperature, args.strict)
    weights = tuple(_numbers(args.weights, "--weights")) if args.weights else (1.0, 1.0)
    if len(weights) != 2 or min(weights) < 0:
        raise ParameterError(f"--weights {args.weights!r}: expected two non-negative numbers W_P,W_LK")
    fixed = () if args.fit_widths else ("w_L", "w_H")
    res = identify_bridge(data, start, weights=(weights[0], weights[1]), high_laps=args.high_laps, fixed=fixed)
    out = Path(args.out or f"hydroservo-identify-{Path(args.curves[0]).stem}")
    out.mkdir(parents=True, exist_ok=True)
    header = (
        f"Identified by hydroservo from {', '.join(Path(c).name for c in args.curves)} at {data.temperature:g} degC\n"
        f"(seed 002 eqs. 21-24); max relative errors: "
        + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items())
    )
    param_file = out / "identified.toml"
    param_file.write_text(spool_valve_toml(res.valve.params, start.fluid.name, data.bench, header=header))
    temps = [data.temperature] + (_temperatures(args.predict, "--predict") if args.predict else [])
    model = [bench_curves(res.valve, t, data.bench) for t in temps]
    plotting.plot_bench_characteristics(
        model,
        measured=data,
        title="Identified model and the curves it was identified from",
        file=out / "identification.png",
    )
    table = temperature_table(res.valve, data.bench, temps, data.temperature)
    files = {"parameters": str(param_file), "plot": str(out / "identification.png")}
    names = [n for n in LOW_GAIN + HIGH_GAIN if n not in fixed]
    if args.json:
        print(
            json.dumps(
                {
                    "temperature_degC": data.temperature,
                    "start": {n: start.params[n] for n in names},
                    "identified": {n: res.valve.params[n] for n in names},
                    "steps": res.steps,
                    "max_relative_errors": res.errors,
                    "prediction": _json_table(table),
                    "files": files,
                },
                indent=2,
            )
        )
        return 0
    print(f"identified at {data.temperature:g} °C from {len(args.curves)} file(s); held: {', '.join(fixed) or 'none'}")
    for n in names:
        unit, scale = ("µm", 1e6) if n.startswith(("X_", "r", "c")) and n != "Cq_inf" else ("", 1.0)
        print(f"  {n:10s} {start.params[n] * scale:>12.5g} -> {res.valve.params[n] * scale:>12.5g} {unit}")
    last = res.steps[-2:]
    for s in last:
        print(
            f"  {s['step']}: rms {s['rms']:.3g} (full-scale units), condition {s['condition']:.3g}, round {s['round']}"
        )
    print("max relative errors: " + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items()))
    print("\n".join(_metrics_table(table)))
    print(f"wrote {param_file} and {out / 'identification.png'}")
    return 0


def add_spool_commands(vsub: Any) -> None:
    """Add ``characteristics`` and ``identify`` to the ``valve`` sub-commands."""
    p = vsub.add_parser(
        "characteristics",
        help="seed-002 spool valve: flow gain, pressure gain, leakage and Table-2 metrics across temperature",
    )
    p.add_argument("params", metavar="PARAMS", help="MareSpoolValve file with a [bench] table, or 'aerospace-example'")
    p.add_argument("--temperature", default="-15,-40,32", metavar="T,...", help="fluid temperatures [degC]")
    p.add_argument("--reference", type=float, default=None, metavar="T", help="changes from (default: first)")
    p.add_argument("--points", type=int, default=401, help="openings per test (default 401)")
    p.add_argument("--strict", action="store_true", help="refuse temperatures outside the fluid model's range")
    p.add_argument("--out", default=None, metavar="DIR")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_characteristics)

    p = vsub.add_parser("identify", help="seed-002 spool valve: two-step identification from test-bench curves")
    p.add_argument(
        "curves", nargs="+", metavar="CURVES.csv", help="flow gain, pressure gain, leakage (one temperature)"
    )
    p.add_argument("--start", required=True, metavar="PARAMS", help="MareSpoolValve file: starting values, n, widths")
    p.add_argument("--predict", default=None, metavar="T,...", help="predict Table-2 metrics at these temperatures")
    p.add_argument("--weights", default=None, metavar="W_P,W_LK", help="pressure and leakage weights (default 1,1)")
    p.add_argument("--high-laps", choices=["pairs", "orifice"], default="pairs")
    p.add_argument("--fit-widths", action="store_true", help="also fit w_L and w_H (not separable from C_q_inf)")
    p.add_argument("--strict", action="store_true")
    p.add_argument("--out", default=None, metavar="DIR")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_identify)
