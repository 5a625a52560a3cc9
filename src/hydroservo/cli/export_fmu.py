"""``hydroservo export-fmu``: a model as an FMI 2.0 FMU, Model Exchange and Co-Simulation (docs/fmu.md;
:mod:`hydroservo.workflows.export`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, execute
from hydroservo.cli.export_c import export_arguments

__all__ = ["add_parsers"]


def cmd_export_fmu(args: argparse.Namespace) -> int:
    from hydroservo.workflows.export import ExportFmu

    return execute(ExportFmu(**export_arguments(args), binary=not args.sources_only, accuracy=args.accuracy), args)


def add_parsers(sub: Any) -> None:
    """Add ``export-fmu``."""
    p = sub.add_parser(
        "export-fmu",
        help="write a model as an FMI 2.0 FMU (Model Exchange and Co-Simulation) for Simulink, Dymola, "
        "OpenModelica, FMPy or a real-time rig",
        description="Writes NAME.fmu: modelDescription.xml (parameters, tunable where the dynamics use them, inputs, "
        "states and outputs, each with its unit), the binary for this machine built with the C compiler, and the C "
        "sources to build it elsewhere. Co-simulation steps with a fixed-step stepper inside. See docs/fmu.md.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--step", default="1e-4", metavar="H",
                   help="co-simulation: the fixed step of the stepper inside, e.g. 1e-4 or '0.1 ms' (default 1e-4 s)")
    p.add_argument("--method", choices=["rk4", "bdf2", "rodas3", "ros23", "dopri5"], default="rk4",
                   help="co-simulation: the fixed-step rk4 (explicit, default) or bdf2 (implicit, for stiff circuits), "
                   "or a variable-step method with error control, rodas3 or ros23 (stiff circuits) or dopri5, that takes any "
                   "communication step")
    p.add_argument("--accuracy", default=None, metavar="A",
                   help="co-simulation with ros23 or dopri5: the deviation wanted, relative to each signal's range, "
                   "e.g. 1e-3 or 0.1%% (default 1e-4)")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs the host sets, e.g. valve.u: each is added to what drives it in the system")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option before export (the start values), with units: --set "load.m=60 kg"')
    p.add_argument("--name", default=None, metavar="ID",
                   help="the model identifier, a C identifier (default: from the model's name)")
    p.add_argument("--sources-only", action="store_true",
                   help="no binary: the FMU holds the C sources only (for a host that builds FMUs itself)")
    add_output_options(p, "hydroservo-NAME-fmu")
    p.add_argument("--json", action="store_true",
                   help="print the file, GUID and every variable with its value reference and unit as JSON")
    p.set_defaults(func=cmd_export_fmu)
