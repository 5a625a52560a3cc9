"""``hydroservo ladder``: the model-fidelity ladder of a system and its error table ([Efe2014] Table 5.3;
:mod:`hydroservo.workflows.ladder`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, add_unit_options, execute, numbers
from hydroservo.cli.progress import progress_bars
from hydroservo.errors import ParameterError, shorten

__all__ = ["add_parsers"]


def _measured(items: list[str]) -> dict[float, tuple[str, Any]] | None:
    """``STEP=FILE[:COLUMN]`` -> {step: (file, column)}: a CSV per step, time in column 0."""
    if not items:
        return None
    out: dict[float, tuple[str, Any]] = {}
    for item in items:
        if "=" not in item:
            raise ParameterError(f"--measured {shorten(item)!r}: expected STEP=FILE.csv, e.g. 36.8=run_368.csv")
        step_text, file = item.split("=", 1)
        (step,) = numbers(step_text, "--measured", above=0.0, at_most=100.0, expected="a step in % (0 to 100]")
        column: Any = 1
        if ":" in file and not file.endswith(":"):
            file, column = file.rsplit(":", 1)
            column = int(column) if column.isdigit() else column
        out[step / 100.0] = (file, column)
    return out


def cmd_ladder(args: argparse.Namespace) -> int:
    from hydroservo.workflows.ladder import Ladder

    steps = numbers(args.steps, "--steps", above=0.0, at_most=100.0, expected="steps in % (0 to 100]") if args.steps \
        else None
    job = Ladder(
        args.model, args.set, steps=None if steps is None else [v / 100 for v in steps], parameter=args.parameter,
        output=args.output, t=args.t, free=[s.strip() for s in args.free.split(",") if s.strip()]
        if args.free is not None else None, models=[k.strip() for k in args.models.split(",")] if args.models
        else None, measured=_measured(args.measured), points=args.points, units=args.units, si=args.si,
        write=args.out is not None or not args.json,  # --json alone writes nothing, as simulate and linearize
        cli=True,
    )
    return execute(job, args, progress_bars(args))


def add_parsers(sub: Any) -> None:
    """Add ``ladder``."""
    p = sub.add_parser(
        "ladder",
        help="model-fidelity ladder: nonlinear, linearised, simplified, with parameter feedback; error table",
        description="Derive from a model its linearised and simplified (load-pressure) versions, with and without "
        "parameter feedback and the valves' compensation tables, run them at each valve-signal step and classify "
        "each model's steady-state displacement error as Efe's Table 5.3 (< 7.5 % accurate, 7.5-20 % moderate, "
        "> 20 % inaccurate), against the model as given or measured responses.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--steps", default=None, metavar="S1,S2,...",
                   help="valve-signal steps in %% (default 20.3,25.8,36.8,50.5,71.3,91.6)")
    p.add_argument("--parameter", default=None, help="what a step sets (default: the amplitude of the first Step or Pulse)")
    p.add_argument("--output", default=None, help="the displacement compared (default: the first alias or position)")
    p.add_argument("--t", default=None, metavar="T", help="time of the operating point (default: while the signal is on)")
    p.add_argument("--free", default=None, metavar="STATE,...",
                   help="states free in the operating point (default: the masses' positions: a steady motion), at the "
                   "values a run from the initial state has at --t")
    p.add_argument("--models", default=None, metavar="M1,M2", help="some of nonlinear,linear,linear-feedback,simplified,simplified-feedback")
    p.add_argument("--measured", action="append", default=[], metavar="STEP=FILE.csv[:COLUMN]",
                   help="a measured response for a step (time [s] in column 0, the output in its unit): the reference")
    p.add_argument("--points", type=int, default=301, help="output times per run (default 301)")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE", help="set a parameter first")
    add_unit_options(p, csv=False)
    add_output_options(p, "hydroservo-NAME-ladder")
    p.add_argument("--json", action="store_true", help="print the ladder table (displacements, errors, classes, costs) as JSON")
    p.set_defaults(func=cmd_ladder)
