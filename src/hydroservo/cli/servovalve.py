"""``hydroservo servovalve``: the first-principles two-stage servovalve of [GordicND] on its test bench."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]

#: The built-in servovalves: name -> description.
VALVES = {"gordic-table1": "PPT B.31.210.12.1000.U2V, Table 1 of GordicND (12 L/min at 10 mA, 210 bar)"}


def _design_point(args: argparse.Namespace) -> tuple[dict[str, float], float, float]:
    """The valve's parameters (Table 1 with ``--set NAME=VALUE`` applied, values with units), the supply
    pressure and the rated current, each checked and named in its error."""
    from hydroservo.analysis.servovalve import PARAMETER_UNITS, table1
    from hydroservo.units import to_si

    if args.valve not in VALVES:
        raise ParameterError(f"servovalve {args.valve!r}: unknown; built-in: {', '.join(VALVES)}")
    changes: dict[str, float] = {}
    for item in args.set or []:
        key, sep, value = item.partition("=")
        key = key.strip()
        if not sep or key not in PARAMETER_UNITS:
            raise ParameterError(
                f"--set {item!r}: expected NAME=VALUE with NAME one of {', '.join(sorted(PARAMETER_UNITS))}"
            )
        changes[key] = to_si(value.strip(), PARAMETER_UNITS[key], what=f"--set {key}")
    p_s = to_si(args.supply, "Pa", what="--supply")
    i_rated = to_si(args.current, "A", what="--current")
    if not i_rated > 0:
        raise ParameterError(f"--current {args.current!r}: expected a positive rated current, e.g. '10 mA'")
    return table1(**changes), p_s, i_rated


def _add_design_point_options(p: Any, set_help: str) -> None:
    """The valve, ``--supply``, ``--current``, ``--set`` and ``--json`` every servovalve command takes."""
    p.add_argument("valve", nargs="?", default="gordic-table1", help=f"built-in servovalve ({', '.join(VALVES)})")
    p.add_argument("--supply", default="210 bar", help="supply pressure (default 210 bar)")
    p.add_argument("--current", default="10 mA", help="rated current (default 10 mA)")
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help=set_help)
    p.add_argument("--json", action="store_true")


def cmd_bench(args: argparse.Namespace) -> int:
    from hydroservo.analysis.servovalve import static_bench
    from hydroservo.cli.common import output_folder, print_json
    from hydroservo.io.servovalve import write_static_characteristic
    from hydroservo.plotting.servovalve import plot_static_bench

    params, p_s, i_rated = _design_point(args)
    if not 5 <= args.points <= 401:
        raise ParameterError(f"--points {args.points}: expected 5 to 401 currents")
    out = output_folder(args, f"hydroservo-servovalve-{args.valve}")
    out.expect(["characteristic.csv", "characteristic.png"])
    bench = static_bench(p_s, i_rated, params, args.points)
    title = f"{args.valve}" + (f" ({', '.join(args.set)})" if args.set else "")
    with out:
        write_static_characteristic(bench, out.file("characteristic.csv"))
        plot_static_bench(bench, title=title, file=out.file("characteristic.png"))
    files = [out.final("characteristic.csv"), out.final("characteristic.png")]
    if args.json:
        print_json(
            {
                "valve": args.valve,
                "changes": args.set or [],
                "supply_bar": p_s / 1e5,
                "rated_current_mA": i_rated * 1e3,
                "figures": [{"figure": n, "value": float(v), "unit": u} for n, v, u in bench.table()],
                "files": files,
            }
        )
        return 0
    print(f"{VALVES[args.valve]}: static tests at {p_s / 1e5:g} bar, no load, rated current {i_rated * 1e3:g} mA")
    if args.set:
        print(f"changed: {', '.join(args.set)}")
    width = max(len(n) for n, _, _ in bench.table())
    for name, value, unit in bench.table():
        print(f"  {name.ljust(width)}  {float(value):10.4g} {unit}")
    print("(dynamic tests and hysteresis: issue 12, in progress; what moves each figure: servovalve design)")
    print(f"wrote {', '.join(files)}")
    return 0


def cmd_design(args: argparse.Namespace) -> int:
    from hydroservo.analysis.servovalve import DESIGN_FIGURES, sensitivity
    from hydroservo.cli.common import output_folder, print_json
    from hydroservo.io.servovalve import write_sensitivity
    from hydroservo.plotting.servovalve import plot_sensitivity

    params, p_s, i_rated = _design_point(args)
    if not 1 <= args.top <= 50:
        raise ParameterError(f"--top {args.top}: expected 1 to 50 parameters per figure")
    out = output_folder(args, f"hydroservo-servovalve-design-{args.valve}")
    out.expect(["sensitivity.csv", "sensitivity.png"])
    sens = sensitivity(p_s, i_rated, params)
    with out:
        write_sensitivity(sens, out.file("sensitivity.csv"))
        plot_sensitivity(sens, DESIGN_FIGURES, top=args.top, title=f"{args.valve}: what moves each figure", file=out.file("sensitivity.png"))
    files = [out.final("sensitivity.csv"), out.final("sensitivity.png")]
    if args.json:
        print_json(
            {
                "valve": args.valve,
                "changes": args.set or [],
                "figures": {
                    k: {"value": sens.figures[k] * DESIGN_FIGURES[k][2], "unit": DESIGN_FIGURES[k][1]} for k in sens.figures
                },
                "elasticity": sens.elasticity,
                "files": files,
            }
        )
        return 0
    print(f"{VALVES[args.valve]}: what moves each figure at {p_s / 1e5:g} bar, {i_rated * 1e3:g} mA")
    print("(elasticity: % change of the figure per % change of the parameter, the largest first)")
    for key, (description, unit, scale) in DESIGN_FIGURES.items():
        ranked = ", ".join(f"{n} {e:+.2f}" for n, e in sens.ranked(key, args.top))
        print(f"  {description} = {sens.figures[key] * scale:.4g} {unit}: {ranked}")
    print(f"wrote {', '.join(files)}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``servovalve bench`` and ``servovalve design``."""
    from hydroservo.cli.common import add_output_options

    group = sub.add_parser("servovalve", help="the first-principles two-stage servovalve (GordicND) on its bench")
    commands = group.add_subparsers(dest="servovalve_command", required=True, metavar="COMMAND")
    p = commands.add_parser("bench", help="static tests: rated flow, symmetry, linearity, flow gain, leakage")
    _add_design_point_options(p, "change a physical parameter, e.g. --set 'K_f=2100 N/m'")
    p.add_argument("--points", type=int, default=41, help="currents of the characteristic (default 41)")
    add_output_options(p, "hydroservo-servovalve-NAME")
    p.set_defaults(func=cmd_bench)
    d = commands.add_parser("design", help="what moves each figure: elasticities to every physical parameter, ranked")
    _add_design_point_options(d, "the design point: change a parameter first")
    d.add_argument("--top", type=int, default=8, help="parameters shown per figure (default 8)")
    add_output_options(d, "hydroservo-servovalve-design-NAME")
    d.set_defaults(func=cmd_design)
