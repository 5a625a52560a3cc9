"""``hydroservo sensitivity``: which parameter matters, one at a time or globally (Sobol, Morris)."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from hydroservo.cli.common import add_output_options, output_folder, print_json
from hydroservo.cli.models import load_with_sets
from hydroservo.errors import ParameterError, shorten

__all__ = ["add_parsers"]


def _vary(items: list[str], method: str, levels: int) -> tuple[dict[str, Any], dict[str, tuple[str, str]]]:
    """``NAME=LOW..HIGH`` (a range) or ``NAME=V1,V2,...`` (levels, one at a time only)."""
    listed: dict[str, Any] = {}
    ranges: dict[str, tuple[str, str]] = {}
    order: list[str] = []
    if not items:
        raise ParameterError("--vary: no parameter to vary; expected e.g. --vary 'valve.c_v=1e-4..2e-4'")
    for item in items:
        if "=" not in item:
            raise ParameterError(f"--vary {shorten(item)!r}: expected NAME=LOW..HIGH or NAME=V1,V2,...")
        name, text = (s.strip() for s in item.split("=", 1))
        if name in listed or name in ranges:
            raise ParameterError(f"--vary {name}: given twice")
        order.append(name)
        if ".." in text:
            lo, _, hi = text.partition("..")
            if not lo.strip() or not hi.strip():
                raise ParameterError(f"--vary {shorten(item)!r}: expected LOW..HIGH, e.g. 25bar..35bar")
            ranges[name] = (lo.strip(), hi.strip())
        else:
            values = [v.strip() for v in text.split(",") if v.strip()]
            if len(values) < 2:
                raise ParameterError(f"--vary {shorten(item)!r}: expected LOW..HIGH or at least two levels V1,V2")
            if method != "oat":
                raise ParameterError(
                    f"--vary {shorten(item)!r}: --method {method} samples ranges; give NAME=LOW..HIGH "
                    "(levels and options are for --method oat)"
                )
            listed[name] = values
    if method == "oat":
        for name, (lo, hi) in ranges.items():
            listed[name] = _spaced(name, lo, hi, levels)
        return {name: listed[name] for name in order}, {}
    return {}, ranges


def _spaced(name: str, lo: str, hi: str, levels: int) -> list[str]:
    """``levels`` values evenly spaced from ``lo`` to ``hi``, in their unit."""
    import numpy as np

    from hydroservo.analysis.sensitivity import bounds

    _, ((a, b),), (unit,) = bounds({name: (_quantity(lo), _quantity(hi))})
    return [f"{v:.6g} {unit}".strip() for v in np.linspace(a, b, levels)]


def _quantity(text: str) -> Any:
    try:
        return float(text)
    except ValueError:
        return text


class _Progress:
    """Runs done, failures and time left, on stderr: one updating line on a terminal, else a line per tenth."""

    def __init__(self) -> None:
        self.tty = sys.stderr.isatty()
        self.shown = -1

    def __call__(self, done: int, failed: int, total: int, elapsed: float) -> None:
        left = elapsed / done * (total - done) if done else float("nan")
        text = f"runs {done}/{total}, {failed} failed, {elapsed:.0f} s, about {left:.0f} s left"
        if self.tty:
            print("\r" + text + " " * 8, end="" if done < total else "\n", file=sys.stderr, flush=True)
        elif done * 10 // total != self.shown:
            self.shown = done * 10 // total
            print(text, file=sys.stderr, flush=True)


def cmd_sensitivity(args: argparse.Namespace) -> int:
    from hydroservo.analysis.sensitivity import morris, one_at_a_time, sobol
    from hydroservo.io.files import safe_name
    from hydroservo.units import to_si

    system = load_with_sets(args.model, args.set)
    if args.levels is None:
        args.levels = 4 if args.method == "morris" else 5
    if args.levels < 2 or (args.method == "morris" and args.levels % 2):
        raise ParameterError(f"--levels {args.levels}: expected at least 2" + (", even for morris" if args.method == "morris" else ""))
    factors, ranges = _vary(args.vary, args.method, args.levels)
    t_end = to_si(args.t_end, "s", what="--t-end") if args.t_end else system.t_end
    if not t_end > 0:
        raise ParameterError(f"--t-end {args.t_end}: expected a positive duration")
    if args.points < 11:
        raise ParameterError(f"--points {args.points}: expected at least 11")
    metrics = args.metric or None
    name = safe_name(system.name)
    out = output_folder(args, f"hydroservo-{name}-sensitivity")
    if args.method == "oat":
        files = ["oat.csv", *(f"oat-{safe_name(f)}.png" for f in factors)]
        out.expect(files)
        signals = args.signals.split(",") if args.signals else None
        study = one_at_a_time(system, factors, metrics=metrics, signals=signals, t_end=t_end, n_points=args.points)
        with out:
            study.table.to_csv(out.file("oat.csv"), index=False)
            for f in study.levels:
                study.plot(f, signals, units=system.plot_units, file=out.file(f"oat-{safe_name(f)}.png"))
        written = {f: out.final(f) for f in files}
        if args.json:
            print_json({"method": "oat", "table": study.table.to_dict(orient="records"), "files": written})
        else:
            _print_oat(study, written)
        return 0
    from hydroservo.analysis.metrics import parse_metric
    from hydroservo.analysis.sensitivity import bounds
    from hydroservo.io import RunStore

    files = ["indices.csv", "indices.png"]
    out.expect(files)
    n = args.n or (256 if args.method == "sobol" else 20)
    # everything checked before the runs folder is made: a refused study leaves nothing behind
    bounds({k: (_quantity(lo), _quantity(hi)) for k, (lo, hi) in ranges.items()})
    for k in ranges:
        system.parameter_key(k)
    units = system.build().units
    for m in metrics or []:
        parse_metric(m, units, t_end)
    if args.method == "sobol" and (n < 2 or n & (n - 1)):
        raise ParameterError(f"--n {n}: sobol: n = {n}: expected a power of two (the base sample), e.g. 256")
    if args.method == "morris" and n < 2:
        raise ParameterError(f"--n {n}: morris: expected at least 2 trajectories")
    fingerprint = {
        "model": system.name,
        "parameters": {k: repr(v) for k, v in sorted(system.parameter_values().items())},
        "method": args.method, "ranges": ranges, "n": n, "levels": args.levels, "seed": args.seed,
        "metrics": metrics or system.metrics, "t_end": t_end, "points": args.points,
    }
    made = not out.target.exists()
    store = RunStore(out.target / "runs", fingerprint, force=args.force)
    kwargs: dict[str, Any] = {
        "metrics": metrics, "t_end": t_end, "n_points": args.points, "seed": args.seed, "store": store,
        "progress": _Progress(), "chunk": args.chunk, "threads": args.threads, "scheduler": args.scheduler,
    }
    start = time.perf_counter()
    try:
        if args.method == "sobol":
            result = sobol(system, ranges, n, **kwargs)
        else:
            result = morris(system, ranges, n, levels=args.levels, **kwargs)
    except BaseException:
        if not store.parts():  # nothing run yet: leave nothing behind (runs written are kept, to resume)
            store.remove()
            if made and out.target.is_dir() and not any(out.target.iterdir()):
                out.target.rmdir()
        raise
    wall = time.perf_counter() - start
    with out:
        result.indices.to_csv(out.file("indices.csv"), index=False)
        result.plot(file=out.file("indices.png"), title=f"{system.name}: {args.method} ({result.runs.stats['runs']} runs)")
    written = {f: out.final(f) for f in files} | {"runs": str(out.target / "runs")}
    if args.json:
        print_json({**result.to_dict(), "wall_time_s": wall, "files": written})
    else:
        _print_global(result, written, wall)
    return 0


def _print_oat(study: Any, files: dict[str, str]) -> None:
    cols = [c for c in study.table.columns if c not in ("factor", "level", "status", "reason")]
    print(f"{study.model}: one factor at a time")
    for factor, levels in study.levels.items():
        rows = study.table[study.table["factor"] == factor]
        print(f"  {factor}:")
        for (_, row), level in zip(rows.iterrows(), levels):
            vals = "  ".join(f"{c.split(' [')[0]} {row[c]:.4g}" for c in cols)
            flag = "" if row["status"] == "ok" else f"  FAILED: {row['reason']}"
            print(f"    {level:<24} {vals}{flag}")
    for f, path in files.items():
        print(f"  {f}: {path}")


def _print_global(result: Any, files: dict[str, str], wall: float) -> None:
    s = result.runs.stats
    print(f"{result.method}: {s['runs']} runs ({s['run_now']} now, {s['resumed']} resumed), {s['failed']} failed, "
          f"{s['implausible']} implausible; {wall:.1f} s, {s['runs_per_s']:.0f} runs/s ({s['where']})")
    keys = ("S1", "S1_conf", "ST", "ST_conf") if result.method == "sobol" else ("mu_star", "mu_star_conf", "sigma")
    for metric, rows in result.indices.groupby("metric", sort=False):
        print(f"  {metric}")
        for _, r in rows.sort_values(keys[2] if result.method == "sobol" else keys[0], ascending=False).iterrows():
            if result.method == "sobol":
                print(f"    {r['parameter']:<24} S1 {r['S1']:6.3f} ± {r['S1_conf']:.3f}   ST {r['ST']:6.3f} ± {r['ST_conf']:.3f}")
            else:
                print(f"    {r['parameter']:<24} mu* {r['mu_star']:10.4g} ± {r['mu_star_conf']:.3g}   sigma {r['sigma']:.4g}")
    for note in result.notes:
        print(f"  note: {note}")
    for f, path in files.items():
        print(f"  {f}: {path}")


def add_parsers(sub: Any) -> None:
    """Add ``sensitivity``."""
    p = sub.add_parser(
        "sensitivity",
        help="which parameter matters: one at a time, Sobol indices or Morris screening",
        description="Vary parameters of a model and measure each run (metrics such as final(x_mm), "
        "mean(cyl.pA, 0.4 s, 0.6 s), rise_time(x_mm, 0.1 s)). --method oat runs each factor's levels with the "
        "others fixed (options too: --vary cyl.bulk_modulus=lee,eggerth); sobol and morris sample the ranges "
        "(SALib) and run the points in chunks, locally or on a Dask cluster (--scheduler). The runs are written "
        "to OUT/runs as they finish (Parquet: pandas.read_parquet('OUT/runs')); the same command again resumes.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--vary", action="append", default=[], metavar="PARAM=LOW..HIGH|PARAM=V1,V2,...",
                   help="a parameter and its range (or levels / option choices for oat), with units: "
                   "--vary 'load.m=15 kg..35 kg'")
    p.add_argument("--method", choices=["oat", "sobol", "morris"], default="oat", help="default oat")
    p.add_argument("--n", type=int, default=None,
                   help="sobol: base sample, a power of two (runs: n (d + 2)), default 256; morris: trajectories "
                   "(runs: n (d + 1)), default 20")
    p.add_argument("--levels", type=int, default=None, help="oat: levels per range (default 5); morris: grid levels, even (default 4)")
    p.add_argument("--metric", action="append", default=[], metavar="KIND(SIGNAL[,T0[,T1]])",
                   help="a metric of each run (repeatable); default: the model's")
    p.add_argument("--signals", default=None, metavar="S1,S2", help="oat: the signals drawn (default: the model's panels)")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE", help="set a parameter first")
    p.add_argument("--t-end", default=None, metavar="T", help="duration of each run (default: the model's)")
    p.add_argument("--points", type=int, default=301, help="output times per run (default 301)")
    p.add_argument("--seed", type=int, default=0, help="seed of the sample (default 0: repeatable)")
    p.add_argument("--threads", type=int, default=None, help="local threads (default: all cores)")
    p.add_argument("--chunk", type=int, default=None, help="runs per chunk (default 128)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run the chunks on this Dask scheduler, e.g. tcp://10.0.0.5:8786")
    add_output_options(p, "hydroservo-NAME-sensitivity")
    p.add_argument("--json", action="store_true", help="print the indices with their confidence intervals as JSON")
    p.set_defaults(func=cmd_sensitivity)
