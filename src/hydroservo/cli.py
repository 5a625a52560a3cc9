"""Command-line interface: a thin shell over the public API.

Every error caused by the input (files, options, values) is printed as one
message and exits with code 2; ``--debug`` shows the traceback instead.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.fluid_library import FluidRangeWarning

__all__ = ["main"]


def _parse_sets(items: Sequence[str]) -> list[tuple[str, str]]:
    out = []
    for item in items:
        if "=" not in item:
            raise ParameterError(f'--set {item!r}: expected COMPONENT.PARAMETER=VALUE, e.g. --set "load.W=3000 lbf"')
        key, val = item.split("=", 1)
        out.append((key.strip(), val.strip()))
    return out


def _load(name: str, sets: Sequence[str]) -> Any:
    from hydroservo.models import load_model

    system = load_model(name)
    for key, val in _parse_sets(sets):
        if key.count(".") != 1:
            raise ParameterError(f"--set {key}={val}: expected COMPONENT.PARAMETER, e.g. load.W")
        cname, pname = key.split(".")
        if cname not in system.components:
            raise ParameterError(
                f"--set {key}={val}: no component {cname!r}; components: {', '.join(system.components)}"
            )
        comp = system.components[cname]
        if pname not in comp.PARAMETERS and pname not in comp.OPTIONS:
            known = ", ".join(list(comp.PARAMETERS) + list(comp.OPTIONS))
            raise ParameterError(f"--set {key}={val}: {cname!r} has no parameter {pname!r}; parameters: {known}")
        try:
            system.set(key, val)
        except HydroservoError as exc:
            raise ParameterError(f"--set {key}={val}: {exc}") from None
    return system


def cmd_models(args: argparse.Namespace) -> int:
    from hydroservo.models import BUILTIN

    width = max(len(n) for n in BUILTIN)
    for name, (_, desc, status) in BUILTIN.items():
        print(f"{name.ljust(width)}  {desc}\n{' ' * width}  validation: {status}")
    return 0


def _default_panels(system: Any, result: Any) -> list[list[str]]:
    if system.plots:
        return system.plots
    if system.aliases:
        return [[a] for a in list(system.aliases)[:8]]
    return [[n] for n in result.names[: min(8, len(result.names))]]


def cmd_simulate(args: argparse.Namespace) -> int:
    from hydroservo.units import to_si

    system = _load(args.model, args.set)
    t_end = to_si(args.t_end, "s", what="--t-end") if args.t_end is not None else system.t_end
    if not t_end > 0:
        raise ParameterError(f"--t-end {args.t_end}: expected a positive duration")
    start = time.perf_counter()
    result = system.simulate(t_end=t_end, n_points=args.points, initial=args.initial, rtol=args.rtol)
    wall = time.perf_counter() - start
    out = Path(args.out or f"hydroservo-{system.name}")
    out.mkdir(parents=True, exist_ok=True)
    csv = result.to_csv(out / f"{system.name}.csv")
    png = out / f"{system.name}.png"
    result.plot(
        *_default_panels(system, result), units=system.plot_units, file=png, title=f"{system.name}: simulated response"
    )
    if args.json:
        print(
            json.dumps(
                {
                    "model": system.name,
                    "t_end_s": t_end,
                    "signals": result.summary(),
                    "solver": {
                        **{k: v for k, v in result.stats.items() if k != "wall_time_s"},
                        "integration_wall_time_s": result.stats["wall_time_s"],
                    },
                    "wall_time_s": wall,
                    "files": {"csv": str(csv), "plot": str(png)},
                },
                indent=2,
            )
        )
        return 0
    print(
        f"simulated {system.name!r} for {t_end:g} s in {wall * 1e3:.1f} ms "
        f"(integration {result.stats['wall_time_s'] * 1e3:.2f} ms, {result.stats.get('nsteps', '?')} steps)"
    )
    rows = [(n, s["unit"], s["final"], s["min"], s["max"]) for n, s in result.summary().items()]
    w = max(len(r[0]) for r in rows)
    print(f"{'signal'.ljust(w)}  {'unit':>8}  {'final':>12}  {'min':>12}  {'max':>12}")
    for n, unit, fin, lo, hi in rows:
        print(f"{n.ljust(w)}  {unit:>8}  {fin:>12.5g}  {lo:>12.5g}  {hi:>12.5g}")
    print(f"wrote {csv} and {png}")
    return 0


def cmd_export(args: argparse.Namespace) -> int:
    from hydroservo.modelfile import model_to_toml

    system = _load(args.model, args.set)
    sys.stdout.write(model_to_toml(system))
    return 0


def cmd_validate(args: argparse.Namespace) -> int:
    from hydroservo.validation import VALIDATIONS, format_checks, validate

    names = [args.model] if args.model else list(VALIDATIONS)
    report = {}
    for name in names:
        checks = validate(name)
        report[name] = [c.as_dict() for c in checks]
        if not args.json:
            print(format_checks(name, checks))
    if args.json:
        print(json.dumps(report, indent=2))
    return 0


def build_parser() -> argparse.ArgumentParser:
    from hydroservo import __version__

    parser = argparse.ArgumentParser(
        prog="hydroservo", description="Electro-hydraulic servo systems: simulate, export, validate."
    )
    parser.add_argument("--version", action="version", version=f"hydroservo {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks on errors")
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("models", help="list the built-in systems")
    p.set_defaults(func=cmd_models)

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
    p.add_argument("--rtol", type=float, default=1e-6, help="relative tolerance (default 1e-6)")
    p.add_argument("--out", default=None, metavar="DIR", help="folder for CSV and PNG (default hydroservo-NAME)")
    p.add_argument("--json", action="store_true", help="print signals, solver statistics and wall time as JSON")
    p.set_defaults(func=cmd_simulate)

    p = sub.add_parser("export", help="write a system as an editable TOML model file to stdout")
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE")
    p.set_defaults(func=cmd_export)

    from hydroservo.cli_valve import add_valve_parser

    add_valve_parser(sub)
    from hydroservo.cli_fluid import add_fluid_parser

    add_fluid_parser(sub)

    p = sub.add_parser("validate", help="compare a built-in system with its published figures")
    p.add_argument("model", nargs="?", metavar="NAME")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_validate)
    return parser


def _join_negative_values(argv: list[str]) -> list[str]:
    """``--temperature -40,20`` -> ``--temperature=-40,20``: argparse would take -40,20 for an option."""
    out: list[str] = []
    it = iter(argv)
    for tok in it:
        if tok in ("--temperature", "--pressure", "--amplitudes", "--frequencies", "--predict", "--reference"):
            nxt = next(it, None)
            if nxt is not None and nxt.startswith("-") and len(nxt) > 1 and (nxt[1].isdigit() or nxt[1] == "."):
                out.append(f"{tok}={nxt}")
                continue
            out.append(tok)
            if nxt is not None:
                out.append(nxt)
            continue
        out.append(tok)
    return out


def _show_warning(message: Warning | str, category: type[Warning], *args: object, **kwargs: object) -> None:
    print(f"hydroservo: warning: {message}", file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(_join_negative_values(list(sys.argv[1:] if argv is None else argv)))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("once", FluidRangeWarning)  # one line per message, not per call site
            warnings.showwarning = _show_warning
            return int(args.func(args))
    except BrokenPipeError:  # output piped into head & co.
        sys.stderr.close()
        return 0
    except HydroservoError as exc:
        if args.debug:
            raise
        print(f"hydroservo: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
