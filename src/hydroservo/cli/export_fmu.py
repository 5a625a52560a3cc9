"""``hydroservo export-fmu``: a model as an FMI 2.0 FMU, Model Exchange and Co-Simulation (docs/fmu.md)."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from hydroservo.cli.common import print_json
from hydroservo.cli.export_c import export_arguments

__all__ = ["add_parsers"]


def cmd_export_fmu(args: argparse.Namespace) -> int:
    from hydroservo.io.c_export import c_identifier
    from hydroservo.io.files import OutputFolder
    from hydroservo.io.fmu import export_fmu

    system, step, name, inputs = export_arguments(args)
    filename = f"{name or c_identifier(system.name)}.fmu"
    OutputFolder(Path(args.out), force=args.force, what="--out").expect([filename])  # refused before the build
    export = export_fmu(
        system,
        Path(args.out),
        step=step,
        method=args.method,
        inputs=inputs,
        name=name,
        binary=not args.sources_only,
        force=args.force,
    )
    if args.json:
        print_json(_report(export))
        return 0
    built = f"binary for {export.platform} and sources" if export.platform else "sources only (no binary)"
    print(
        f"exported {system.name!r} as an FMI 2.0 FMU (Model Exchange and Co-Simulation) to {export.path}: "
        f"{built}; parameters {len(export.parameters)} ({sum(export.tunable)} tunable), inputs "
        f"{len(export.inputs)}, states {len(export.states)}, outputs {len(export.outputs)}"
    )
    print(f"  co-simulation: {export.method}, fixed step {export.step:g} s (communication steps a whole number of it)")
    renamed = [v for v in export.variables if v.name != v.signal and v.kind != "derivative"]
    if renamed:
        print("  renamed (FMI needs unique names): " + ", ".join(f"{v.signal} ({v.kind}) -> {v.name}" for v in renamed))
    return 0


def _report(export: Any) -> dict[str, Any]:
    """What ``--json`` prints: the file, GUID, co-simulation stepper and every variable with its value reference."""
    variables = []
    for vr, v in enumerate(export.variables):
        item: dict[str, Any] = {"value_reference": vr, "name": v.name, "kind": v.kind, "unit": v.unit}
        if v.name != v.signal:
            item["signal"] = v.signal
        if v.kind == "parameter":
            item["start"] = export.defaults[vr]
            item["variability"] = "tunable" if export.tunable[vr] else "fixed"
        variables.append(item)
    return {
        "model": export.model,
        "fmu": str(export.path),
        "model_identifier": export.name,
        "guid": export.guid,
        "fmi_version": "2.0",
        "interfaces": ["ModelExchange", "CoSimulation"],
        "platform": export.platform,
        "co_simulation": {"method": export.method, "step_s": export.step},
        "files": list(export.files),
        "variables": variables,
    }


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
    p.add_argument("--method", choices=["rk4", "bdf2"], default="rk4",
                   help="co-simulation: rk4 (explicit, default) or bdf2 (implicit, for stiff circuits)")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs the host sets, e.g. valve.u: each is added to what drives it in the system")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option before export (the start values), with units: --set "load.m=60 kg"')
    p.add_argument("--name", default=None, metavar="ID",
                   help="the model identifier, a C identifier (default: from the model's name)")
    p.add_argument("--sources-only", action="store_true",
                   help="no binary: the FMU holds the C sources only (for a host that builds FMUs itself)")
    p.add_argument("--out", default=".", metavar="DIR", help="folder to write NAME.fmu into (default: this folder)")
    p.add_argument("--force", action="store_true", help="replace a file NAME.fmu already there")
    p.add_argument("--json", action="store_true",
                   help="print the file, GUID and every variable with its value reference and unit as JSON")
    p.set_defaults(func=cmd_export_fmu)
