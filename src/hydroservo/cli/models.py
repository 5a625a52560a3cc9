"""``hydroservo models``, ``simulate`` and ``export``: built-in systems and model files."""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from collections.abc import Sequence
from typing import Any

from hydroservo.cli.common import add_output_options, output_folder
from hydroservo.errors import HydroservoError, ImplausibleResultError, ParameterError, shorten

__all__ = ["add_parsers", "load_with_sets"]


def _parse_sets(items: Sequence[str]) -> list[tuple[str, str]]:
    out = []
    for item in items:
        if "=" not in item:
            raise ParameterError(f'--set {shorten(item)!r}: expected COMPONENT.PARAMETER=VALUE, e.g. --set "load.W=3000 lbf"')
        key, val = item.split("=", 1)
        out.append((key.strip(), val.strip()))
    return out


def load_with_sets(name: str, sets: Sequence[str]) -> Any:
    """A built-in model or model file with ``--set`` values applied."""
    from hydroservo.io.model_file import load_model

    system = load_model(name)
    touched: dict[str, list[str]] = {}
    for key, val in _parse_sets(sets):
        if key.count(".") != 1:
            raise ParameterError(f"--set {shorten(key)}={shorten(val)}: expected COMPONENT.PARAMETER, e.g. load.W")
        cname, pname = key.split(".")
        if cname not in system.components:
            raise ParameterError(
                f"--set {shorten(key)}={shorten(val)}: no component {cname!r}; components: {', '.join(system.components)}"
            )
        comp = system.components[cname]
        known = set(comp.PARAMETERS) | set(comp.OPTIONS) | set(comp.RENAMED)
        if pname not in known:
            names = ", ".join(list(comp.PARAMETERS) + list(comp.OPTIONS))
            raise ParameterError(
                f"--set {shorten(key)}={shorten(val)}: {cname!r} has no parameter {pname!r}; parameters: {names}"
            )
        try:
            system.set(key, val)
        except HydroservoError as exc:
            raise ParameterError(f"--set {key}={shorten(val)}: {exc}") from None
        touched.setdefault(cname, []).append(f"{key}={shorten(val)}")
    for cname, items in touched.items():  # a cross-parameter check the --set values break is theirs, not the file's
        try:
            system.components[cname].check()
        except HydroservoError as exc:
            raise ParameterError(f"--set {', '.join(items)}: {exc}") from None
    return system


def cmd_models(args: argparse.Namespace) -> int:
    from hydroservo.io.model_file import builtin_models

    models = builtin_models()
    width = max(len(n) for n in models)
    for name, meta in models.items():
        source = f" [{meta['citation']}, {meta['status']}]" if meta["citation"] else ""
        print(f"{name.ljust(width)}  {meta['description']}{source}\n{' ' * width}  validation: {meta['validation']}")
    return 0


def _check_plots(system: Any, panels: list[list[str]]) -> None:
    """Refuse, before the run, plot panels naming unknown signals and plot units of the wrong dimension."""
    from hydroservo.units import from_si

    model = system.build()
    signals = set(model.state_names) | set(model.output_names)
    where = system.source or system.name
    for name in (n for panel in panels for n in panel):
        if name not in signals:
            raise ParameterError(f"{where}: [model] plots: no signal {name!r}; signals: {', '.join(sorted(signals))}")
    for name, unit in system.plot_units.items():
        if name not in signals:
            raise ParameterError(f"{where}: [model] plot_units: no signal {name!r}")
        try:
            from_si(1.0, model.units.get(name, ""), unit)
        except HydroservoError as exc:
            raise ParameterError(f"{where}: [model] plot_units {name} = {unit!r}: {exc}") from None


def _print_summary(system: Any, result: Any, t_end: float, wall: float, files: dict[str, str]) -> None:
    print(
        f"simulated {system.name!r} for {t_end:g} s in {wall * 1e3:.1f} ms "
        f"(integration {result.stats['wall_time_s'] * 1e3:.2f} ms, {result.stats.get('nsteps', '?')} steps)"
    )
    rows = [(n, s["unit"], s["final"], s["min"], s["max"]) for n, s in result.summary().items()]
    w = max(len(r[0]) for r in rows)
    print(f"{'signal'.ljust(w)}  {'unit':>8}  {'final':>12}  {'min':>12}  {'max':>12}")
    for n, unit, fin, lo, hi in rows:
        print(f"{n.ljust(w)}  {unit:>8}  {fin:>12.5g}  {lo:>12.5g}  {hi:>12.5g}")
    if files:
        print(f"wrote {' and '.join(files.values())}")


def _accuracy(text: str | None) -> float | None:
    """``--accuracy``: a fraction (``1e-3``) or a percentage (``0.1%``) of each signal's range."""
    if text is None:
        return None
    stripped = text.strip()
    try:
        return float(stripped[:-1]) / 100 if stripped.endswith("%") else float(stripped)
    except ValueError:
        raise ParameterError(
            f"--accuracy {shorten(text)!r}: expected a fraction of each signal's range, e.g. 1e-3 or 0.1%"
        ) from None


def _check_solver_options(args: argparse.Namespace) -> None:
    """Refuse --rtol, --accuracy and --points before anything is loaded or built."""
    from hydroservo.system.integration import MAX_POINTS, SolverSettings

    if args.rtol is not None and args.accuracy is not None:
        raise ParameterError(f"--rtol {args.rtol:g} and --accuracy {args.accuracy}: give one of them, not both")
    try:
        SolverSettings.of(rtol=args.rtol, accuracy=_accuracy(args.accuracy))
    except ParameterError as exc:
        option = f"--rtol {args.rtol:g}" if args.rtol is not None else f"--accuracy {args.accuracy}"
        raise ParameterError(f"{option}: {str(exc).split(': ', 1)[-1]}") from None
    if not 2 <= args.points <= MAX_POINTS:
        raise ParameterError(f"--points {args.points}: expected a whole number of output times from 2 to {MAX_POINTS}")


def _warnings(result: Any) -> list[str]:
    """The physical bounds the run crossed, and signals (such as aliases) that are not finite."""
    import numpy as np

    found = [str(w) for w in result.warnings]
    for name, values in result.data.items():
        bad = ~np.isfinite(values)
        if bad.any():
            found.append(f"{name} is NaN or infinite from t = {result.t[int(np.argmax(bad))]:.6g} s")
    return found


def _report_warnings(result: Any, strict: bool) -> list[str]:
    """Print what is implausible in the result; with --strict, refuse it (exit 2, nothing written)."""
    found = _warnings(result)
    if strict and found:
        lines = "\n  ".join(found)
        raise ImplausibleResultError(
            f"--strict: the result of {result.model!r} is physically implausible "
            f"({len(found)} warning(s); margins: docs/reliability.md):\n  {lines}"
        )
    for text in found:
        print(f"hydroservo: warning: {text}", file=sys.stderr)
    return found


#: The files ``simulate`` writes, by the name ``--write`` gives them.
WRITABLE = ("csv", "png", "mat")


def _files_to_write(args: argparse.Namespace) -> list[str]:
    """``--write``: the files to write. Without it, a CSV and a plot, except that ``--json`` alone writes
    nothing: a program reading the JSON asks for the files it wants (``--write csv`` or ``--out DIR``)."""
    if args.write is None:
        return [] if args.json and args.out is None else ["csv", "png"]
    kinds = [k.strip().lower() for k in args.write.split(",") if k.strip()]
    if kinds == ["none"]:
        return []
    wrong = [k for k in kinds if k not in WRITABLE]
    if wrong or not kinds:
        raise ParameterError(
            f"--write {shorten(args.write)!r}: expected 'none' or a comma-separated list of {', '.join(WRITABLE)}"
        )
    return list(dict.fromkeys(kinds))


def cmd_simulate(args: argparse.Namespace) -> int:
    from hydroservo.io.files import safe_name
    from hydroservo.units import to_si

    _check_solver_options(args)
    kinds = _files_to_write(args)
    system = load_with_sets(args.model, args.set)
    t_end = to_si(args.t_end, "s", what="--t-end") if args.t_end is not None else system.t_end
    if not (math.isfinite(t_end) and t_end > 0):
        raise ParameterError(f"--t-end {args.t_end}: expected a positive, finite duration")
    name = safe_name(system.name)
    out = output_folder(args, f"hydroservo-{name}") if kinds else None
    if out is not None:
        out.expect([f"{name}.{kind}" for kind in kinds])
    if system.plots and "png" in kinds:
        _check_plots(system, system.plots)
    start = time.perf_counter()
    result = system.simulate(
        t_end=t_end, n_points=args.points, initial=args.initial, rtol=args.rtol, accuracy=_accuracy(args.accuracy)
    )
    wall = time.perf_counter() - start
    found = _report_warnings(result, args.strict)
    files: dict[str, str] = {}
    if out is not None:
        with out:
            if "csv" in kinds:
                result.to_csv(out.file(f"{name}.csv"))
            if "mat" in kinds:
                result.to_mat(out.file(f"{name}.mat"))
            if "png" in kinds:
                changed = ", ".join(s.strip() for s in args.set)
                title = f"{system.name}: simulated response" + (f" ({changed})" if changed else "")
                result.plot(units=system.plot_units, file=out.file(f"{name}.png"), title=title)
        files = {kind: out.final(f"{name}.{kind}") for kind in kinds}
    if not args.json:
        _print_summary(system, result, t_end, wall, files)
        return 0
    solver = {k: v for k, v in result.stats.items() if k != "wall_time_s"}
    solver["integration_wall_time_s"] = result.stats["wall_time_s"]
    report = {
        "model": system.name,
        "t_end_s": t_end,
        "signals": result.summary(),
        "solver": solver,
        "wall_time_s": wall,
        "warnings": [w.to_dict() for w in result.warnings]
        + [{"message": text} for text in found[len(result.warnings) :]],
        "files": files,
    }
    print(json.dumps(report, indent=2))
    return 0


def cmd_export(args: argparse.Namespace) -> int:
    from hydroservo.io.model_file import model_to_toml

    system = load_with_sets(args.model, args.set)
    sys.stdout.write(model_to_toml(system))
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``models``, ``simulate`` and ``export``."""
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
    p.add_argument(
        "--accuracy",
        default=None,
        metavar="A",
        help="deviation wanted, relative to each signal's range: 1e-3 or 0.1%% (default 1e-4: rtol 1e-6, atol 1e-8)",
    )
    p.add_argument("--rtol", type=float, default=None, help="relative tolerance instead (atol = rtol/100)")
    p.add_argument(
        "--strict",
        action="store_true",
        help="refuse a physically implausible result (exit 2, nothing written) instead of warning",
    )
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

    p = sub.add_parser("export", help="write a system as an editable TOML model file to stdout")
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE")
    p.set_defaults(func=cmd_export)
