"""``hydroservo report`` and ``hydroservo draw``: a page to show a colleague, and the circuit diagram
(:mod:`hydroservo.workflows.report`, :mod:`hydroservo.workflows.draw`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, add_unit_options, execute
from hydroservo.cli.progress import progress_bars
from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]


def cmd_report(args: argparse.Namespace) -> int:
    from hydroservo.workflows.report import ReportOf

    if args.si and args.units:
        raise ParameterError(f"--si and --units {args.units!r}: give one of them")
    job = ReportOf(args.source, args.set, t_end=args.t_end, accuracy=args.accuracy,
                   validation=not args.no_validation, units="si" if args.si else args.units, cli=True)
    return execute(job, args, progress_bars(args))


def cmd_draw(args: argparse.Namespace) -> int:
    from hydroservo.workflows.draw import Draw

    return execute(Draw(args.model, args.set, formats=args.format, parameters=not args.names_only, cli=True), args)


def add_parsers(sub: Any) -> None:
    """Add ``report`` and ``draw``."""
    p = sub.add_parser(
        "report",
        help="one self-contained HTML page of a model's run (circuit, parameters, plots, warnings, solver, "
        "validation, references) or of a result file's signals",
        description="Simulates MODEL (a built-in model or a model file) and writes NAME.html: its circuit diagram, "
        "its response as interactive plots (zoom, pan, values with units on hover), the signals' final and extreme "
        "values, every parameter with its unit and where it comes from, the warnings, the solver's statistics, the "
        "verdicts of its published figures where it has them, and the references it stands on. A RESULT file (CSV "
        "with 't [s]' and 'signal [unit]' columns, as 'hydroservo simulate' writes) is shown as it is. The page "
        "needs no network to open.",
    )
    p.add_argument("source", metavar="MODEL|RESULT.csv")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option first, with units: --set "load.W=3000 lbf"')
    p.add_argument("--t-end", default=None, metavar="T", help="duration, e.g. 2 or '500 ms' (default: the model's)")
    p.add_argument("--accuracy", default=None, metavar="A",
                   help="deviation wanted, relative to each signal's range: 1e-3 or 0.1%% (default 1e-4)")
    p.add_argument("--no-validation", action="store_true",
                   help="leave out the published figures' verdicts (they take a few seconds for some models)")
    add_unit_options(p, csv=False)
    add_output_options(p, "hydroservo-NAME-report")
    p.add_argument("--json", action="store_true", help="print what the page shows as JSON")
    p.set_defaults(func=cmd_report)

    p = sub.add_parser("draw", help="the circuit diagram of a model (ISO 1219-1 symbols): SVG, PNG or PDF")
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE", help="set a parameter first")
    p.add_argument("--format", default="svg,png", metavar="LIST",
                   help="comma-separated formats: svg, png, pdf (default svg,png)")
    p.add_argument("--names-only", action="store_true", help="names only, no parameters beside the symbols")
    add_output_options(p, "hydroservo-NAME-circuit")
    p.add_argument("--json", action="store_true", help="print the components and connections drawn as JSON")
    p.set_defaults(func=cmd_draw)
