"""``hydroservo models``, ``simulate`` and ``export``: built-in systems and model files
(:mod:`hydroservo.workflows.models`, :mod:`~hydroservo.workflows.simulate`, :mod:`~hydroservo.workflows.export`)."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from hydroservo.cli.common import add_output_options, add_unit_options, execute

__all__ = ["add_parsers"]


def cmd_models(args: argparse.Namespace) -> int:
    from hydroservo.workflows.models import Models

    return execute(Models(cli=True), args)


def cmd_simulate(args: argparse.Namespace) -> int:
    from hydroservo.workflows.simulate import Simulate

    # --json alone writes nothing: a program reading the JSON asks for the files it wants (--write or --out)
    write = "none" if args.write is None and args.json and args.out is None else args.write
    job = Simulate(
        args.model, args.set, t_end=args.t_end, points=args.points, initial=args.initial, accuracy=args.accuracy,
        rtol=args.rtol, strict=args.strict, write=write, method=args.method, max_steps=args.max_steps,
        units=args.units, si=args.si,
        ascii=args.ascii, all_signals=args.all, cli=True,
    )
    return execute(job, args)


def cmd_cache(args: argparse.Namespace) -> int:
    from hydroservo.workflows.cache import Cache

    return execute(Cache(clear=args.clear, cli=True), args)


def cmd_docs(args: argparse.Namespace) -> int:
    from hydroservo.workflows.docs import Docs

    return execute(Docs(args.page, path_only=args.path, cli=True), args)


def cmd_export(args: argparse.Namespace) -> int:
    from hydroservo.workflows.export import ExportModel

    sys.stdout.write(ExportModel(args.model, args.set, full=args.full, cli=True).run().text)
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``models``, ``cache``, ``simulate``, ``docs`` and ``export``."""
    p = sub.add_parser("models", help="list the built-in systems")
    p.set_defaults(func=cmd_models)

    p = sub.add_parser(
        "cache",
        help="show the folder of compiled models (simulate --method ros23|dopri5), or clear it",
        description="Compiled models are kept in $HYDROSERVO_CACHE, else the user's cache folder "
        "(~/.cache/hydroservo), one per model structure, hydroservo version and compiler; each is built again "
        "when next used after --clear.",
    )
    p.add_argument("--clear", action="store_true", help="remove every compiled model from the folder")
    p.add_argument("--json", action="store_true", help="print the folder, the entries and their size as JSON")
    p.set_defaults(func=cmd_cache)

    p = sub.add_parser("simulate", help="simulate a built-in system or a TOML model file")
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument(
        "--set",
        action="append",
        default=[],
        metavar="PARAM=VALUE",
        help='set a parameter or option, with units: --set "load.W=3000 lbf"',
    )
    p.add_argument("--t-end", default=None, metavar="T", help="duration, e.g. 2 or '500 ms'")
    p.add_argument("--points", type=int, default=1001, help="number of output times (default 1001)")
    p.add_argument(
        "--initial",
        choices=["parameters", "trim"],
        default="parameters",
        help="initial state from the parameters (default) or from an equilibrium",
    )
    p.add_argument(
        "--accuracy",
        default=None,
        metavar="A",
        help="deviation wanted, relative to each signal's range: 1e-3 or 0.1%% (default 1e-4: rtol 1e-6, atol 1e-8)",
    )
    p.add_argument("--rtol", type=float, default=None, help="relative tolerance instead (atol = rtol/100)")
    p.add_argument(
        "--method",
        default="auto",
        metavar="M",
        help="integration method: auto (default: rodas3 for models of up to 20 states where a C compiler is found, "
        "else cvodes), rodas3 (compiled "
        "Rosenbrock 3(2), stiff circuits), ros23 (compiled Rosenbrock 2(3)), dopri5 (compiled Dormand-Prince, "
        "non-stiff) or cvodes (BDF, interpreted); the compiled ones are built once per model and cached",
    )
    p.add_argument(
        "--max-steps",
        type=int,
        default=None,
        metavar="N",
        help="the run's step budget (default at the default accuracy: 100000 for cvodes, shared over the output "
        "times, and 1000000 for the compiled methods; a long run of a stiff circuit may need more)",
    )
    p.add_argument(
        "--strict",
        action="store_true",
        help="refuse a physically implausible result (exit 2, nothing written) instead of warning",
    )
    add_unit_options(p)
    p.add_argument("--all", action="store_true", help="list every signal in the table, not only the main ones")
    add_output_options(p, "hydroservo-NAME")
    p.add_argument(
        "--write",
        default=None,
        metavar="LIST",
        help="files to write: a comma-separated list of csv, png, mat, or none (default: csv,png; "
        "with --json and no --out: none)",
    )
    p.add_argument("--json", action="store_true", help="print signals, solver statistics and wall time as JSON")
    p.set_defaults(func=cmd_simulate)

    p = sub.add_parser(
        "docs",
        help="the user guide: list its pages, or print one (the pages messages name, docs/NAME.md)",
        description="The user guide's pages, installed with hydroservo: without a page, their names and titles.",
    )
    p.add_argument("page", nargs="?", default=None, metavar="PAGE", help="a page: validation, engine.md, ...")
    p.add_argument("--path", action="store_true", help="print only where the page is")
    p.add_argument("--json", action="store_true", help="print the folder and the pages as JSON")
    p.set_defaults(func=cmd_docs)

    p = sub.add_parser(
        "export",
        help="write a system as an editable TOML model file to stdout",
        description="Write the model's own file (a model file or a built-in model's) with the values of --set "
        "written in, as given: its comments, order and layout are kept, and former type and parameter names are "
        "written as they are now called. --full writes every parameter of every component instead, each with its "
        "description and unit.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE", help="set a parameter or option first")
    p.add_argument("--full", action="store_true",
                   help="every parameter of every component, with its description (default: the file as written)")
    p.set_defaults(func=cmd_export)
