"""``hydroservo export-c``: a model as C code with a fixed-step stepper for real time (docs/realtime.md;
:mod:`hydroservo.workflows.export`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, component_inputs, execute

__all__ = ["add_parsers", "export_arguments"]


def export_arguments(args: argparse.Namespace) -> dict[str, Any]:
    """What ``export-c`` and ``export-fmu`` share: the model with its ``--set`` values, ``--step``, ``--method``,
    ``--name``, ``--inputs`` and ``--force``, as the workflow's inputs."""
    return {"model": args.model, "sets": args.set, "step": args.step, "method": args.method,
            "inputs": component_inputs(args.inputs), "c_name": args.name, "force": args.force, "cli": True}


def cmd_export_c(args: argparse.Namespace) -> int:
    from hydroservo.workflows.export import ExportC

    return execute(ExportC(**export_arguments(args), build=args.build, main=args.main), args)


def add_parsers(sub: Any) -> None:
    """Add ``export-c``."""
    p = sub.add_parser(
        "export-c",
        help="write a model as C code with a fixed-step real-time stepper (rk4 or bdf2) and its C API",
        description="Writes the model's functions (CasADi code generation), a fixed-step stepper with a documented "
        "C API (new, reset, set_parameter, set_input, step, get_output, names and units), a README and a Makefile: "
        "C99 with libc and libm only, no Python on the target. See docs/realtime.md.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--step", default=None, metavar="H",
                   help="the fixed step, e.g. 1e-4 or '0.1 ms' (baked in); required unless --main (default 1e-4 there)")
    p.add_argument("--method", choices=["rk4", "bdf2"], default="rk4",
                   help="rk4 (explicit, default) or bdf2 (implicit, Newton with the exact Jacobian: stiff circuits, "
                   "longer steps)")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs the host sets, e.g. valve.u: each is added to what drives it in the system")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option before export (the C defaults), with units: --set "load.m=60 kg"')
    p.add_argument("--name", default=None, metavar="ID",
                   help="the C identifier that starts every symbol and file (default: from the model's name)")
    p.add_argument("--main", action="store_true",
                   help="also write the standalone simulator main.c: a command that reads parameters, runs a "
                   "variable-step method (rodas3, ros23 or dopri5) and writes CSV, no Python needed (built with --build)")
    p.add_argument("--build", action="store_true",
                   help="also compile a shared library into the folder with the system's C compiler (CC or cc)")
    add_output_options(p, "hydroservo-NAME-c")
    p.add_argument("--json", action="store_true",
                   help="print the folder, files and every parameter, input, state and output with its unit as JSON")
    p.set_defaults(func=cmd_export_c)
