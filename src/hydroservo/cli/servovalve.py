"""``hydroservo servovalve``: the first-principles two-stage servovalve of [GordicND] on its test bench."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]

#: The built-in servovalves: name -> description.
VALVES = {"gordic-table1": "PPT B.31.210.12.1000.U2V, Table 1 of GordicND (12 L/min at 10 mA, 210 bar)"}


def _add_design_point_options(p: Any, set_help: str) -> None:
    """The valve, ``--supply``, ``--current``, ``--set``, the fidelity and ``--json`` every servovalve command takes."""
    p.add_argument("valve", nargs="?", default="gordic-table1", help=f"built-in servovalve ({', '.join(VALVES)})")
    p.add_argument("--supply", default="210 bar", help="supply pressure (default 210 bar)")
    p.add_argument("--current", default="10 mA", help="rated current (default 10 mA)")
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help=set_help)
    p.add_argument("--first-stage", default="quasi-static", choices=["quasi-static", "compressible"],
                   help="the flapper-nozzle stage: the paper's simplified model (default) or eqs. 20-22 whole")
    p.add_argument("--flapper", default="bent", choices=["bent", "rigid"],
                   help="flapper tip from eqs. 13-14 (default) or theta l_a")
    p.add_argument("--json", action="store_true")


def _bench_valve(args: argparse.Namespace) -> Any:
    """The servovalve component of the bench: Table 1, the chosen fidelity, ``--set`` applied (values with units)."""
    from hydroservo.components import TwoStageServovalve

    if args.valve not in VALVES:
        raise ParameterError(f"servovalve {args.valve!r}: unknown; built-in: {', '.join(VALVES)}")
    valve = TwoStageServovalve("sv", first_stage=args.first_stage, flapper=args.flapper)
    for item in args.set or []:
        key, sep, value = item.partition("=")
        key = key.strip()
        if not sep or key not in valve.PARAMETERS:
            raise ParameterError(
                f"--set {item!r}: expected NAME=VALUE with NAME a parameter of TwoStageServovalve "
                f"({', '.join(sorted(valve.PARAMETERS))})"
            )
        valve.set(**{key: value.strip()})
    valve.check()
    return valve


def _design_point(args: argparse.Namespace) -> tuple[Any, float, float]:
    """The valve (:func:`_bench_valve`), the supply pressure and the rated current, each checked."""
    from hydroservo.units import to_si

    valve = _bench_valve(args)
    p_s = to_si(args.supply, "Pa", what="--supply")
    if not p_s > 2e5:
        raise ParameterError(
            f"--supply {args.supply!r}: expected above the return (1 bar absolute, Table 1's p_0), e.g. '210 bar'"
        )
    i_rated = to_si(args.current, "A", what="--current")
    if not i_rated > 0:
        raise ParameterError(f"--current {args.current!r}: expected a positive rated current, e.g. '10 mA'")
    return valve, p_s, i_rated


#: The bench's files per test.
BENCH_FILES = {
    "static": ["characteristic.csv", "flow-current.png"],
    "blocked": ["blocked.csv", "blocked.png"],
    "steps": ["steps.csv", "steps.png"],
    "hysteresis": ["hysteresis.csv"],
    "threshold": [],
    "bode": ["bode.csv", "bode.png"],
}


def cmd_bench(args: argparse.Namespace) -> int:
    import sys

    from hydroservo.analysis.servovalve_bench import TESTS, bench_report
    from hydroservo.cli.common import output_folder, print_json
    from hydroservo.io import servovalve as files
    from hydroservo.plotting import servovalve as plots

    valve, p_s, i_rated = _design_point(args)
    tests = [t.strip() for t in args.tests.split(",") if t.strip()]
    unknown = [t for t in tests if t not in TESTS]
    if unknown or not tests:
        raise ParameterError(f"--tests {args.tests!r}: expected a comma-separated choice of {', '.join(TESTS)}")
    names = ["figures.csv"] + [f for t in TESTS if t in tests for f in BENCH_FILES[t]]
    if "hysteresis" in tests and "static" not in tests:
        names.append("flow-current.png")
    out = output_folder(args, f"hydroservo-servovalve-{args.valve}")
    out.expect(names)
    label = f"{args.valve} ({args.first_stage}, {args.flapper} flapper)" + (f", {', '.join(args.set)}" if args.set else "")

    def progress(name: str) -> None:
        if not args.json:
            print(f"  running the {name} tests ...", file=sys.stderr, flush=True)

    if not 5 <= args.points <= 401:
        raise ParameterError(f"--points {args.points}: expected 5 to 401 currents")
    report = bench_report(valve, p_s, i_rated, tests=tests, label=label, progress=progress, points=args.points)
    with out:
        files.write_figures(report, out.file("figures.csv"))
        if report.static is not None:
            files.write_static_characteristic(report.static, out.file("characteristic.csv"))
        if report.static is not None or report.hysteresis is not None:
            plots.plot_flow_current(report, title=label, file=out.file("flow-current.png"))
        if report.hysteresis is not None:
            files.write_hysteresis(report, out.file("hysteresis.csv"))
        if report.blocked is not None:
            files.write_blocked(report, out.file("blocked.csv"))
            plots.plot_blocked(report, title=label, file=out.file("blocked.png"))
        if report.steps:
            files.write_steps(report, out.file("steps.csv"))
            plots.plot_steps(report, title=label, file=out.file("steps.png"))
        if report.bode is not None:
            files.write_bench_bode(report, out.file("bode.csv"))
            plots.plot_bench_bode(report, title=label, file=out.file("bode.png"))
    written = [out.final(n) for n in names]
    unsettled = report.bode.info["unsettled"] if report.bode is not None else []
    if args.json:
        print_json(
            {
                "valve": args.valve,
                "first_stage": args.first_stage,
                "flapper": args.flapper,
                "changes": args.set or [],
                "supply_bar": p_s / 1e5,
                "rated_current_mA": i_rated * 1e3,
                "figures": [{"figure": n, "value": float(v), "unit": u} for n, v, u in report.table()],
                "not_periodic": [{"amplitude": a, "frequency_Hz": f} for a, f, _ in unsettled],
                "files": written,
            }
        )
        return 0
    print(f"{VALVES[args.valve]}: bench tests at {p_s / 1e5:g} bar, rated current {i_rated * 1e3:g} mA")
    print(f"model: first stage {args.first_stage}, {args.flapper} flapper" + (f"; changed: {', '.join(args.set)}" if args.set else ""))
    rows = report.table()
    width = max(len(n) for n, _, _ in rows)
    for name, value, unit in rows:
        print(f"  {name.ljust(width)}  {float(value):10.4g} {unit}")
    if unsettled:
        by_amp: dict[float, list[float]] = {}
        for a, f, _ in unsettled:
            by_amp.setdefault(a, []).append(f)
        for a, fs in by_amp.items():
            print(f"  no periodic response at +-{a * 100:g} % from {min(fs):.3g} Hz (the flapper bounces on the nozzles)")
    print(f"wrote {', '.join(written)}")
    return 0


def cmd_fit_catalogue(args: argparse.Namespace) -> int:
    import numpy as np

    from hydroservo.analysis.servovalve_bench import frequency_test, static_tests
    from hydroservo.cli.common import output_folder, print_json
    from hydroservo.identification.servovalve_catalogue import ORDERS, fit_catalogue
    from hydroservo.io.component_file import component_file_text
    from hydroservo.plotting.servovalve import plot_catalogue_fits
    from hydroservo.units import to_si

    valve, p_s, i_rated = _design_point(args)
    orders = [o.strip() for o in args.orders.split(",") if o.strip()]
    if not orders or any(o not in ORDERS for o in orders):
        raise ParameterError(f"--orders {args.orders!r}: expected a comma-separated choice of 1, 2, 3")
    amplitude = to_si(args.amplitude, "", what="--amplitude")
    if not 0 < amplitude <= 1:
        raise ParameterError(f"--amplitude {args.amplitude!r}: expected a fraction of rated current, e.g. '5 %'")
    f_max = to_si(args.f_max, "Hz", what="--f-max")
    if not 10 <= f_max <= 2000:
        raise ParameterError(f"--f-max {args.f_max!r}: expected 10 Hz to 2 kHz")
    names = ["catalogue.csv", "catalogue-bode.png"] + [f"catalogue-order{o}.toml" for o in orders]
    out = output_folder(args, f"hydroservo-servovalve-catalogue-{args.valve}")
    out.expect(names)
    static = static_tests(valve, p_s, i_rated, points=11)
    bode = frequency_test(valve, p_s, i_rated, amplitudes=(amplitude,), frequencies=np.geomspace(5.0, f_max, 12))
    fits = [
        fit_catalogue(bode, o, rated_flow=static.rated_flow, i_rated=i_rated, dp_rated=p_s - 1e5,
                      leakage_null=static.internal_leakage_null)
        for o in orders
    ]
    label = f"{args.valve} ({args.first_stage}, {args.flapper} flapper)" + (f", {', '.join(args.set)}" if args.set else "")
    with out:
        lines = [
            f"# catalogue models of {label}, fitted at +-{amplitude * 100:g} % of rated current, 5 Hz to {f_max:g} Hz",
            "order, tau [ms], omega_n [rad/s], zeta [-], gain error [dB], phase error [deg]",
        ]
        for fit in fits:
            tau = fit.params.get("tau", float("nan")) * 1e3
            lines.append(f"{fit.order}, {tau!r}, {fit.params.get('omega_n', float('nan'))!r}, "
                         f"{fit.params.get('zeta', float('nan'))!r}, {fit.gain_error_db!r}, {fit.phase_error_deg!r}")
            header = (f"CatalogueServovalve of order {fit.order} fitted to {label}\nat +-{amplitude * 100:g} % of "
                      f"rated current up to {f_max:g} Hz: within {fit.gain_error_db:.2f} dB and {fit.phase_error_deg:.1f} deg")
            used = ["Q_N", "dp_N", "i_N", *ORDERS[fit.order], "G_leak", "p_tr"]
            out.file(f"catalogue-order{fit.order}.toml").write_text(component_file_text(fit.valve, used, header=header))
        out.file("catalogue.csv").write_text("\n".join(lines) + "\n")
        plot_catalogue_fits(bode, fits, title=label, file=out.file("catalogue-bode.png"))
    written = [out.final(n) for n in names]
    if args.json:
        print_json({
            "valve": args.valve, "amplitude": amplitude, "f_max_Hz": f_max,
            "rated_flow_L_min": static.rated_flow * 6e4,
            "fits": [{"order": f.order, "params": f.params, "gain_error_dB": f.gain_error_db,
                      "phase_error_deg": f.phase_error_deg} for f in fits],
            "files": written,
        })
        return 0
    print(f"catalogue models of {label}: +-{amplitude * 100:g} % of rated current, 5 Hz to {f_max:g} Hz")
    print(f"  rated flow {static.rated_flow * 6e4:.4g} L/min, internal leakage at null {static.internal_leakage_null * 6e4:.3g} L/min")
    for fit in fits:
        shown = ", ".join(f"{k} = {v * 1e3:.4g} ms" if k == "tau" else f"{k} = {v:.4g}" + (" rad/s" if k == "omega_n" else "")
                          for k, v in fit.params.items())
        print(f"  order {fit.order}: {shown}; within {fit.gain_error_db:.2f} dB and {fit.phase_error_deg:.1f} deg")
    print(f"wrote {', '.join(written)}")
    return 0


def cmd_design(args: argparse.Namespace) -> int:
    import sys

    from hydroservo.analysis.servovalve_design import FIGURES, design_study
    from hydroservo.cli.common import output_folder, print_json
    from hydroservo.io.servovalve import write_sensitivity
    from hydroservo.plotting.servovalve import plot_sensitivity

    valve, p_s, i_rated = _design_point(args)
    if not 1 <= args.top <= 50:
        raise ParameterError(f"--top {args.top}: expected 1 to 50 parameters per figure")
    def progress(stage: str) -> None:
        if not args.json:
            print(f"  {stage} ...", file=sys.stderr, flush=True)

    figures = None if args.figures == "all" else [f.strip() for f in args.figures.split(",") if f.strip()]
    if figures is not None and (not figures or set(figures) - set(FIGURES)):
        raise ParameterError(f"--figures {args.figures!r}: expected 'all' or a comma-separated choice of {', '.join(FIGURES)}")
    out = output_folder(args, f"hydroservo-servovalve-design-{args.valve}")
    out.expect(["sensitivity.csv", "sensitivity.png"])
    study = design_study(valve, p_s, i_rated, progress=progress, figures=figures)
    shown = {k: v[:3] for k, v in FIGURES.items()}
    with out:
        write_sensitivity(study, out.file("sensitivity.csv"))
        plot_sensitivity(study, shown, top=args.top, title=f"{args.valve}: what moves each figure", file=out.file("sensitivity.png"))
    files = [out.final("sensitivity.csv"), out.final("sensitivity.png")]
    if args.json:
        print_json(
            {
                "valve": args.valve,
                "changes": args.set or [],
                "figures": {
                    k: {"value": study.figures[k] * FIGURES[k][2], "unit": FIGURES[k][1], "derivatives": FIGURES[k][3]}
                    for k in study.figures
                },
                "elasticity": study.elasticity,
                "files": files,
            }
        )
        return 0
    print(f"{VALVES[args.valve]}: what moves each figure at {p_s / 1e5:g} bar, {i_rated * 1e3:g} mA")
    print("(elasticity: % change of the figure per % change of the parameter, the largest first)")
    for key, (description, unit, scale, how) in FIGURES.items():
        if key not in study.figures:
            continue
        ranked = ", ".join(f"{n} {e:+.2f}" for n, e in study.ranked(key, args.top))
        print(f"  {description} = {study.figures[key] * scale:.4g} {unit} ({how}): {ranked}")
    print(f"wrote {', '.join(files)}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``servovalve bench``, ``servovalve fit-catalogue`` and ``servovalve design``."""
    from hydroservo.cli.common import add_output_options

    group = sub.add_parser("servovalve", help="the first-principles two-stage servovalve (GordicND) on its bench")
    commands = group.add_subparsers(dest="servovalve_command", required=True, metavar="COMMAND")
    p = commands.add_parser(
        "bench", help="the test bench: flow-current, blocked ports, square-wave steps, hysteresis, frequency response"
    )
    _add_design_point_options(p, "change a parameter of TwoStageServovalve, e.g. --set 'K_f=2100 N/m'")
    p.add_argument("--tests", default="static,blocked,steps,hysteresis,threshold,bode",
                   help="comma-separated tests (default all: static,blocked,steps,hysteresis,threshold,bode)")
    p.add_argument("--points", type=int, default=41, help="currents of the static characteristic (default 41)")
    add_output_options(p, "hydroservo-servovalve-NAME")
    p.set_defaults(func=cmd_bench)
    c = commands.add_parser(
        "fit-catalogue", help="catalogue models (first to third order) fitted to the valve's small-signal response"
    )
    _add_design_point_options(c, "change a parameter of TwoStageServovalve, e.g. --set 'K_f=2100 N/m'")
    c.add_argument("--orders", default="1,2,3", help="orders to fit (default 1,2,3)")
    c.add_argument("--amplitude", default="5 %", help="amplitude of the response fitted (default 5 %% of rated current)")
    c.add_argument("--f-max", default="150 Hz", help="highest frequency fitted (default 150 Hz)")
    add_output_options(c, "hydroservo-servovalve-catalogue-NAME")
    c.set_defaults(func=cmd_fit_catalogue)
    d = commands.add_parser("design", help="what moves each figure: elasticities to every physical parameter, ranked")
    _add_design_point_options(d, "the design point: change a parameter of TwoStageServovalve first")
    d.add_argument("--top", type=int, default=8, help="parameters shown per figure (default 8)")
    d.add_argument("--figures", default="all", help="comma-separated figures, e.g. rated_flow,f_90 (default all)")
    add_output_options(d, "hydroservo-servovalve-design-NAME")
    d.set_defaults(func=cmd_design)
