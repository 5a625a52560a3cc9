"""``hydroservo sensitivity``: which parameter matters, one at a time or globally (Sobol, Morris;
:mod:`hydroservo.workflows.sensitivity`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, add_unit_options, execute
from hydroservo.cli.progress import progress_bars

__all__ = ["add_parsers"]


def cmd_sensitivity(args: argparse.Namespace) -> int:
    from hydroservo.workflows.sensitivity import Sensitivity

    bars = progress_bars(args)
    job = Sensitivity(
        args.model, args.vary, method=args.method, sets=args.set, n=args.n, levels=args.levels,
        metrics=args.metric or None, signals=args.signals.split(",") if args.signals else None, t_end=args.t_end,
        points=args.points, seed=args.seed, threads=args.threads, chunk=args.chunk, scheduler=args.scheduler,
        force=args.force, runs_progress=bars.runs, units=args.units, si=args.si, cli=True,
    )
    return execute(job, args, bars)


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
    add_unit_options(p, csv=False, note="the levels and ranges varied are shown as given")
    add_output_options(p, "hydroservo-NAME-sensitivity")
    p.add_argument("--json", action="store_true", help="print the indices with their confidence intervals as JSON")
    p.set_defaults(func=cmd_sensitivity)
