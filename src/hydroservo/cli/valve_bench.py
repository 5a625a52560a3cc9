"""``hydroservo valve characteristics`` and ``valve identify``: the staged-slot valve of MareAttarND on its test bench."""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.cli.common import add_output_options, numbers, output_folder
from hydroservo.errors import ParameterError

if TYPE_CHECKING:
    from hydroservo.io.files import OutputFolder

__all__ = ["add_parsers"]


#: Most openings per test curve (each is a bridge solved at every opening).
MAX_OPENINGS = 10_001


def _temperatures(text: str, what: str) -> list[float]:
    """Finite temperatures [degC]; whether the fluid model holds at them is its own check (``Fluid.check_range``)."""
    if text.strip().lower().endswith(("degc", "°c", "c")):
        raise ParameterError(f"{what} {text!r}: give bare numbers in degC, e.g. -40,-15,32")
    return numbers(text, what)


def _metrics_table(table: dict[str, Any]) -> list[str]:
    from hydroservo.analysis.static_bench import METRICS

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


_CHARACTERISTICS_PLOTS = ("characteristics", "pressure_flow", "discharge_coefficient")


def _characteristics_plots(
    valve: Any, curves: list[Any], bench: Any, reference: float, out: OutputFolder, stem: str
) -> str:
    from hydroservo.analysis.static_bench import pressure_flow
    from hydroservo.plotting import staged_slot as plots

    title = f"{stem}: {valve.fluid.name}, P_s = {bench.P_s / 1e5:.4g} bar, X_n = {bench.X_n * 1e3:g} mm"
    plots.plot_bench_characteristics(curves, title=title, file=out.file("characteristics.png"))
    openings = [f * bench.X_n for f in (-1.0, -0.5, -0.25, -0.1, 0.1, 0.25, 0.5, 1.0)]
    P_L, Q_L = pressure_flow(valve, reference, bench, openings)
    plots.plot_pressure_flow_family(
        P_L,
        Q_L,
        openings,
        bench,
        title=f"{stem}: pressure-flow at {reference:g} °C",
        file=out.file("pressure_flow.png"),
    )
    plots.plot_discharge_coefficient(valve.bridge_parameters(), file=out.file("discharge_coefficient.png"))
    return title


def cmd_characteristics(args: argparse.Namespace) -> int:
    import numpy as np

    from hydroservo.analysis.static_bench import bench_curves, temperature_table
    from hydroservo.io.component_file import read_staged_slot_valve
    from hydroservo.io.curves import write_bench_curves

    valve, bench = read_staged_slot_valve(args.params)
    if bench is None:
        raise ParameterError(f"{args.params}: no [bench] table; expected P_s and X_n (the test conditions)")
    temps = _temperatures(args.temperature, "--temperature")
    if not 21 <= args.points <= MAX_OPENINGS:
        raise ParameterError(f"--points {args.points}: expected 21 to {MAX_OPENINGS} openings")
    if args.reference is not None and args.reference not in temps:
        raise ParameterError(
            f"--reference {args.reference:g}: expected one of the temperatures {', '.join(f'{t:g}' for t in temps)}"
        )
    try:  # every temperature, before any is computed
        valve.fluid.check_range(np.array([bench.P_r, bench.P_s]), np.array(temps), args.strict)
    except ParameterError as exc:
        raise ParameterError(f"--temperature {args.temperature!r}: {exc}") from None
    stem = Path(args.params).stem
    out = output_folder(args, f"hydroservo-characteristics-{stem}")
    tables = [f"T{t:g}_{name}.csv" for t in temps for name in ("flow_gain", "blocked_ports")]
    out.expect(tables + [f"{k}.png" for k in _CHARACTERISTICS_PLOTS])
    curves = [bench_curves(valve, t, bench, n=args.points, strict=args.strict) for t in temps]
    table = temperature_table(valve, bench, temps, args.reference)
    files: dict[str, str] = {}
    with out:
        for c in curves:
            for path in write_bench_curves(c, out.folder, stem=f"T{c.temperature:g}_"):
                files[path.stem] = out.final(path.name)
        title = _characteristics_plots(valve, curves, bench, table["reference"], out, stem)
    files.update({k: out.final(f"{k}.png") for k in _CHARACTERISTICS_PLOTS})
    if args.json:
        print(json.dumps({"valve": str(args.params), **_json_table(table), "files": files}, indent=2))
        return 0
    qn_note = "" if bench.Q_n is not None else f" (computed: no-load flow at X_n, {bench.T_rated:g} °C)"
    print(f"{title}, Q_n = {table['Q_n'] * 6e4:.4g} L/min{qn_note}")
    print("\n".join(_metrics_table(table)))
    print(f"wrote {len(files)} files to {out.target}")
    return 0


def _print_identification(res: Any, start: Any, names: list[str], fixed: tuple[str, ...], table: Any, n_files: int) -> None:
    print(f"identified at {res.curves.temperature:g} °C from {n_files} file(s); held: {', '.join(fixed) or 'none'}")
    for n in names:
        unit, scale = ("µm", 1e6) if n.startswith(("X_", "r", "c")) and n != "Cq_inf" else ("", 1.0)
        print(f"  {n:10s} {start.values[n] * scale:>12.5g} -> {res.valve.values[n] * scale:>12.5g} {unit}")
    for s in res.steps[-2:]:
        print(
            f"  {s['step']}: rms {s['rms']:.3g} (full-scale units), condition {s['condition']:.3g}, round {s['round']}"
        )
    print("max relative errors: " + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items()))
    print("\n".join(_metrics_table(table)))


def cmd_identify(args: argparse.Namespace) -> int:
    import numpy as np

    from hydroservo.analysis.static_bench import bench_curves, temperature_table
    from hydroservo.identification.staged_slot import HIGH_GAIN, LOW_GAIN, identify_staged_slot
    from hydroservo.io.component_file import read_staged_slot_valve, staged_slot_valve_toml
    from hydroservo.io.curves import read_bench_curves
    from hydroservo.plotting.staged_slot import plot_bench_characteristics

    data = read_bench_curves(args.curves)
    start, _ = read_staged_slot_valve(args.start)
    start.fluid.check_range(np.array([data.bench.P_r, data.bench.P_s]), data.temperature, args.strict)
    weights = tuple(numbers(args.weights, "--weights")) if args.weights else (1.0, 1.0)
    if len(weights) != 2 or min(weights) < 0:
        raise ParameterError(f"--weights {args.weights!r}: expected two non-negative numbers W_P,W_LK")
    fixed: tuple[str, ...] = () if args.fit_widths else ("w_L", "w_H")
    predicted = _temperatures(args.predict, "--predict") if args.predict else []
    try:
        start.fluid.check_range(np.array([data.bench.P_r, data.bench.P_s]), np.array(predicted), args.strict)
    except ParameterError as exc:
        raise ParameterError(f"--predict {args.predict!r}: {exc}") from None
    temps = [data.temperature, *predicted]
    out = output_folder(args, f"hydroservo-identify-{Path(args.curves[0]).stem}")
    out.expect(["identified.toml", "identification.png"])
    res = identify_staged_slot(data, start, weights=(weights[0], weights[1]), high_laps=args.high_laps, fixed=fixed)
    header = (
        f"Identified by hydroservo from {', '.join(Path(c).name for c in args.curves)} at {data.temperature:g} degC\n"
        f"(MareAttarND eqs. 21-24); max relative errors: "
        + ", ".join(f"{k} {v * 100:.2f} %" for k, v in res.errors.items())
    )
    model = [bench_curves(res.valve, t, data.bench) for t in temps]
    table = temperature_table(res.valve, data.bench, temps, data.temperature)
    title = "Identified model and the curves it was identified from"
    with out:
        out.file("identified.toml").write_text(staged_slot_valve_toml(res.valve, data.bench, header=header))
        plot_bench_characteristics(model, measured=data, title=title, file=out.file("identification.png"))
    files = {"parameters": out.final("identified.toml"), "plot": out.final("identification.png")}
    names = [n for n in LOW_GAIN + HIGH_GAIN if n not in fixed]
    if not args.json:
        _print_identification(res, start, names, fixed, table, len(args.curves))
        print(f"wrote {files['parameters']} and {files['plot']}")
        return 0
    report = {
        "temperature_degC": data.temperature,
        "start": {n: start.values[n] for n in names},
        "identified": {n: res.valve.values[n] for n in names},
        "steps": res.steps,
        "max_relative_errors": res.errors,
        "prediction": _json_table(table),
        "files": files,
    }
    print(json.dumps(report, indent=2))
    return 0


def add_parsers(vsub: Any) -> None:
    """Add ``characteristics`` and ``identify`` to the ``valve`` sub-commands."""
    p = vsub.add_parser(
        "characteristics",
        help="staged-slot spool valve: flow gain, pressure gain, leakage and Table-2 metrics across temperature",
    )
    p.add_argument("params", metavar="PARAMS", help="StagedSlotValve file with a [bench] table, or 'aerospace-example'")
    p.add_argument("--temperature", default="-15,-40,32", metavar="T,...", help="fluid temperatures [degC]")
    p.add_argument("--reference", type=float, default=None, metavar="T", help="changes from (default: first)")
    p.add_argument("--points", type=int, default=401, help="openings per test (default 401)")
    p.add_argument("--strict", action="store_true", help="refuse temperatures outside the fluid model's range")
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_characteristics)

    p = vsub.add_parser("identify", help="staged-slot spool valve: two-step identification from test-bench curves")
    p.add_argument(
        "curves", nargs="+", metavar="CURVES.csv", help="flow gain, pressure gain, leakage (one temperature)"
    )
    p.add_argument("--start", required=True, metavar="PARAMS", help="StagedSlotValve file: starting values, n, widths")
    p.add_argument("--predict", default=None, metavar="T,...", help="predict Table-2 metrics at these temperatures")
    p.add_argument("--weights", default=None, metavar="W_P,W_LK", help="pressure and leakage weights (default 1,1)")
    p.add_argument("--high-laps", choices=["pairs", "orifice"], default="pairs")
    p.add_argument("--fit-widths", action="store_true", help="also fit w_L and w_H (not separable from C_q_inf)")
    p.add_argument("--strict", action="store_true")
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_identify)
