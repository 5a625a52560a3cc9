"""``hydroservo servovalve``: the first-principles two-stage servovalve of [GordicND] on its test bench
(:mod:`hydroservo.workflows.servovalve`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import execute
from hydroservo.cli.progress import progress_bars

__all__ = ["add_parsers"]


def _add_design_point_options(p: Any, set_help: str) -> None:
    """The valve, ``--supply``, ``--current``, ``--set``, the fidelity and ``--json`` every servovalve command takes."""
    p.add_argument("valve", nargs="?", default="gordic-table1", help="built-in servovalve (gordic-table1)")
    p.add_argument("--supply", default=None, help="supply pressure (default: the valve's rating, 210 bar)")
    p.add_argument("--current", default=None, help="rated current (default: the valve's rating, 10 mA)")
    p.add_argument("--set", action="append", metavar="NAME=VALUE", help=set_help)
    p.add_argument("--first-stage", default="quasi-static", choices=["quasi-static", "compressible"],
                   help="the flapper-nozzle stage: the paper's simplified model (default) or eqs. 20-22 whole")
    p.add_argument("--flapper", default="bent", choices=["bent", "rigid"],
                   help="flapper tip from eqs. 13-14 (default) or theta l_a")
    p.add_argument("--json", action="store_true")


def _design_point(args: argparse.Namespace) -> dict[str, Any]:
    return {"valve": args.valve, "supply": args.supply, "current": args.current, "sets": args.set,
            "first_stage": args.first_stage, "flapper": args.flapper, "cli": True}


def cmd_bench(args: argparse.Namespace) -> int:
    from hydroservo.workflows.servovalve import Bench

    job = Bench(**_design_point(args), tests=args.tests, points=args.points)
    return execute(job, args, progress_bars(args))


def cmd_fit_catalogue(args: argparse.Namespace) -> int:
    from hydroservo.workflows.servovalve import FitCatalogue

    job = FitCatalogue(**_design_point(args), orders=args.orders, amplitude=args.amplitude, f_max=args.f_max)
    return execute(job, args)


def cmd_design(args: argparse.Namespace) -> int:
    from hydroservo.workflows.servovalve import Design

    job = Design(**_design_point(args), top=args.top, figures=args.figures)
    return execute(job, args, progress_bars(args))


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
