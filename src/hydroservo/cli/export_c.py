"""``hydroservo export-c``: a model as C code with a fixed-step stepper for real time (docs/realtime.md)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from hydroservo.cli.common import add_output_options, component_inputs, output_folder, print_json
from hydroservo.cli.models import load_with_sets

if TYPE_CHECKING:
    from hydroservo.system.system import System

__all__ = ["add_parsers", "export_arguments"]


def export_arguments(args: argparse.Namespace) -> tuple[System, float, str | None, tuple[str, ...]]:
    """What ``export-c`` and ``export-fmu`` share: the model with its ``--set`` values, ``--step``, ``--name`` and
    ``--inputs``, each checked and named in errors by its option."""
    from hydroservo.io.c_export import check_inputs, check_name, check_step

    step = check_step(args.step, what="--step")
    name = check_name(args.name, what="--name") if args.name is not None else None
    system = load_with_sets(args.model, args.set)
    return system, step, name, check_inputs(system, component_inputs(args.inputs), what="--inputs")


def cmd_export_c(args: argparse.Namespace) -> int:
    from hydroservo.io.c_export import export_c
    from hydroservo.io.files import safe_name

    system, step, name, inputs = export_arguments(args)
    target = output_folder(args, f"hydroservo-{safe_name(system.name)}-c").target
    export = export_c(
        system, target, step=step, method=args.method, inputs=inputs, name=name, force=args.force, build=args.build
    )
    if args.json:
        print_json(_report(export))
        return 0
    print(
        f"exported {system.name!r} as C ({export.method}, step {export.step:g} s) to {export.directory}: "
        f"parameters {len(export.parameters)}, inputs {len(export.inputs)}, states {len(export.states)}, "
        f"outputs {len(export.outputs)}"
    )
    print(f"  API: {export.directory / f'{export.name}.h'}; build: cd {export.directory} && cc -O2 -c *.c (or make)")
    if export.inputs:
        print(f"  inputs (each added to what drives it in the system): {', '.join(export.inputs)}")
    if args.build:
        print(f"  built: {export.library}")
    return 0


def _report(export: Any) -> dict[str, Any]:
    """What ``--json`` prints: the folder, the method, the files and every named vector with its unit."""

    def named(names: tuple[str, ...]) -> list[dict[str, Any]]:
        return [{"index": i, "name": n, "unit": export.units[n]} for i, n in enumerate(names)]

    report: dict[str, Any] = {
        "model": export.model,
        "name": export.name,
        "directory": str(export.directory),
        "method": export.method,
        "step_s": export.step,
        "files": list(export.files),
        "parameters": [
            {"index": i, "name": n, "unit": export.units[n], "default": v}
            for i, (n, v) in enumerate(zip(export.parameters, export.defaults))
        ],
        "inputs": named(export.inputs),
        "states": named(export.states),
        "outputs": named(export.outputs),
    }
    if export.method == "bdf2":
        report["newton_tolerance"] = export.newton_tolerance
    if export.library.name in export.files:
        report["library"] = str(export.library)
    return report


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
    p.add_argument("--step", required=True, metavar="H", help="the fixed step, e.g. 1e-4 or '0.1 ms' (baked in)")
    p.add_argument("--method", choices=["rk4", "bdf2"], default="rk4",
                   help="rk4 (explicit, default) or bdf2 (implicit, Newton with the exact Jacobian: stiff circuits, "
                   "longer steps)")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs the host sets, e.g. valve.u: each is added to what drives it in the system")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option before export (the C defaults), with units: --set "load.m=60 kg"')
    p.add_argument("--name", default=None, metavar="ID",
                   help="the C identifier that starts every symbol and file (default: from the model's name)")
    p.add_argument("--build", action="store_true",
                   help="also compile a shared library into the folder with the system's C compiler (CC or cc)")
    add_output_options(p, "hydroservo-NAME-c")
    p.add_argument("--json", action="store_true",
                   help="print the folder, files and every parameter, input, state and output with its unit as JSON")
    p.set_defaults(func=cmd_export_c)
