"""``hydroservo ladder``: the model-fidelity ladder of a system and its error table ([Efe2014] Table 5.3)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, numbers, output_folder, print_json
from hydroservo.cli.models import load_with_sets
from hydroservo.errors import ParameterError, shorten

__all__ = ["add_parsers"]


def _measured(items: list[str]) -> dict[float, tuple[Any, Any]] | None:
    """``STEP=FILE[:COLUMN]`` -> {step: (t, y)}: a CSV per step, time in column 0."""
    from hydroservo.io import read_time_table

    if not items:
        return None
    out: dict[float, tuple[Any, Any]] = {}
    for item in items:
        if "=" not in item:
            raise ParameterError(f"--measured {shorten(item)!r}: expected STEP=FILE.csv, e.g. 36.8=run_368.csv")
        step_text, file = item.split("=", 1)
        (step,) = numbers(step_text, "--measured", above=0.0, at_most=100.0, expected="a step in % (0 to 100]")
        column: Any = 1
        if ":" in file and not file.endswith(":"):
            file, column = file.rsplit(":", 1)
            column = int(column) if column.isdigit() else column
        out[step / 100.0] = read_time_table(file, column, what=f"--measured {step_text}")
    return out


def cmd_ladder(args: argparse.Namespace) -> int:
    from hydroservo.analysis.ladder import RUNGS, STEPS, build_ladder, ladder_defaults, ladder_table
    from hydroservo.io.files import safe_name
    from hydroservo.plotting.ladder import plot_ladder_classes, plot_ladder_responses
    from hydroservo.units import to_si

    system = load_with_sets(args.model, args.set)
    defaults = ladder_defaults(system)
    parameter = args.parameter or defaults["parameter"]
    if parameter is None:
        raise ParameterError(f"{system.name}: no Step or Pulse signal block to step; name the parameter with --parameter")
    system.parameter_key(parameter)
    output = args.output or defaults["output"]
    if output is None or output not in system.build().units:
        raise ParameterError(f"--output {output!r}: expected a signal of {system.name!r} (a state, output or alias)")
    steps = [v / 100 for v in numbers(args.steps, "--steps", above=0.0, at_most=100.0, expected="steps in % (0 to 100]")] \
        if args.steps else list(STEPS)
    t = to_si(args.t, "s", what="--t") if args.t is not None else defaults["t"]
    free = [s.strip() for s in args.free.split(",") if s.strip()] if args.free is not None else defaults["free"]
    kinds = [k.strip() for k in args.models.split(",")] if args.models else list(RUNGS)
    for k in kinds:
        if k not in RUNGS:
            raise ParameterError(f"--models {args.models!r}: {k!r} is not a model of the ladder; expected some of {', '.join(RUNGS)}")
    measured = _measured(args.measured)
    name = safe_name(system.name)
    out = output_folder(args, f"hydroservo-{name}-ladder")
    files = ["ladder.csv", "ladder-responses.png", "ladder-classes.png"]
    out.expect(files)
    rungs = build_ladder(system, "trim", t=t, free=free, kinds=kinds)
    ladder = ladder_table(rungs, steps, parameter=parameter, output=output, n_points=args.points, reference=measured)
    unit = system.build().units.get(output, "")
    with out:
        ladder.table.to_csv(out.file("ladder.csv"))
        plot_ladder_responses(ladder, unit=unit, file=out.file("ladder-responses.png"),
                              title=f"{system.name}: {output} of every model at each step of {parameter}")
        plot_ladder_classes(ladder, file=out.file("ladder-classes.png"))
    written = {f: out.final(f) for f in files}
    if args.json:
        print_json({"model": system.name, "operating_point": {"t": t, "free": free}, **ladder.to_dict(), "files": written})
        return 0
    print(f"{system.name}: model-fidelity ladder, linearised at the steady motion at t = {t:g} s "
          f"(free: {', '.join(free) or 'none'}); steps of {parameter}; {output} against {ladder.reference}")
    short = {"accurate": "A", "moderate": "M", "inaccurate": "I", "failed": "F"}
    print("  error against the reference [%] and class (A accurate < 7.5 %, M moderate to 20 %, I inaccurate; "
          "* implausible run)")
    print("    " + "model".ljust(30) + "".join(f"{100 * s:>10g} %" for s in steps) + "   cost")
    for model, row in ladder.table.iterrows():
        cells = ""
        for s in steps:
            cls = str(row[f"class {100 * s:g} %"])
            mark = short.get(cls.split(" ")[0], "?") + ("*" if "implausible" in cls else " ")
            cells += f"{row[f'error {100 * s:g} % [%]']:+9.1f} {mark}"
        print(f"    {model:<30}{cells}   {int(row['states'])} states, {row['solver steps']:.0f} steps, "
              f"{row['wall time [ms]']:.1f} ms")
    for f, path in written.items():
        print(f"  {f}: {path}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``ladder``."""
    p = sub.add_parser(
        "ladder",
        help="model-fidelity ladder: nonlinear, linearised, simplified, with parameter feedback; error table",
        description="Derive from a model its linearised and simplified (load-pressure) versions, with and without "
        "parameter feedback and the valves' compensation tables, run them at each valve-signal step and classify "
        "each model's steady-state displacement error as Efe's Table 5.3 (< 7.5 %% accurate, 7.5-20 %% moderate, "
        "> 20 %% inaccurate), against the model as given or measured responses.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--steps", default=None, metavar="S1,S2,...",
                   help="valve-signal steps in %% (default 20.3,25.8,36.8,50.5,71.3,91.6)")
    p.add_argument("--parameter", default=None, help="what a step sets (default: the amplitude of the first Step or Pulse)")
    p.add_argument("--output", default=None, help="the displacement compared (default: the first alias or position)")
    p.add_argument("--t", default=None, metavar="T", help="time of the operating point (default: while the signal is on)")
    p.add_argument("--free", default=None, metavar="STATE,...",
                   help="states free in the operating point (default: the masses' positions: a steady motion)")
    p.add_argument("--models", default=None, metavar="M1,M2", help="some of nonlinear,linear,linear-feedback,simplified,simplified-feedback")
    p.add_argument("--measured", action="append", default=[], metavar="STEP=FILE.csv[:COLUMN]",
                   help="a measured response for a step (time [s] in column 0, the output in its unit): the reference")
    p.add_argument("--points", type=int, default=301, help="output times per run (default 301)")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE", help="set a parameter first")
    add_output_options(p, "hydroservo-NAME-ladder")
    p.add_argument("--json", action="store_true", help="print the ladder table (displacements, errors, classes, costs) as JSON")
    p.set_defaults(func=cmd_ladder)
