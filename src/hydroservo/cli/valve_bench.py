"""``hydroservo valve characteristics`` and ``valve identify``: the staged-slot valve of MareAttarND on its test bench
(:mod:`hydroservo.workflows.staged_slot`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, execute, numbers

__all__ = ["add_parsers"]


def cmd_characteristics(args: argparse.Namespace) -> int:
    from hydroservo.workflows.staged_slot import Characteristics

    job = Characteristics(args.params, args.temperature, args.reference, args.points, args.strict, cli=True)
    return execute(job, args)


def cmd_identify(args: argparse.Namespace) -> int:
    from hydroservo.workflows.staged_slot import Identify

    weights = tuple(numbers(args.weights, "--weights")) if args.weights else (1.0, 1.0)
    job = Identify(args.curves, args.start, args.predict, weights, args.high_laps, args.fit_widths, args.strict,
                   cli=True)
    return execute(job, args)


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
