"""``hydroservo valve``: the valve tools. ``fit``, ``bode`` and ``fit-dynamics`` here (the servo-solenoid valve of
FerreiraND; :mod:`hydroservo.workflows.valve`); ``characteristics`` and ``identify`` (the staged-slot valve of
MareAttarND) in :mod:`hydroservo.cli.valve_bench`."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli import valve_bench
from hydroservo.cli.common import add_output_options, execute, frequencies, numbers
from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]


def cmd_fit(args: argparse.Namespace) -> int:
    from hydroservo.workflows.valve import ValveFit

    return execute(ValveFit(args.datasheet, args.structure, args.match, args.curves, cli=True), args)


def cmd_bode(args: argparse.Namespace) -> int:
    from hydroservo.workflows.valve import SpoolBode

    amps = numbers(args.amplitudes, "--amplitudes", above=0.0, at_most=100.0, expected="0 < amplitude <= 100 % of stroke")
    job = SpoolBode(args.params, [a / 100.0 for a in amps], frequencies(args.frequencies), cli=True)
    return execute(job, args)


def _start(text: str | None) -> dict[str, str]:
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        if "=" not in item:
            raise ParameterError(f"--start {item!r}: expected NAME=VALUE, e.g. 'omega_n=700 rad/s,zeta=0.7'")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def cmd_fit_dynamics(args: argparse.Namespace) -> int:
    from hydroservo.workflows.valve import FitDynamics

    return execute(FitDynamics(args.bode, args.model, _start(args.start), cli=True), args)


def add_parsers(sub: Any) -> None:
    """Add ``valve`` and its sub-commands."""
    valve = sub.add_parser(
        "valve",
        help="valve tools: datasheet fit, Bode, dynamics fit (FerreiraND); characteristics, identify (MareAttarND)",
    )
    vsub = valve.add_subparsers(dest="valve_command", required=True)

    p = vsub.add_parser("fit", help="pseudo-section parameters from datasheet values, with plots and a parameter file")
    p.add_argument(
        "datasheet", metavar="DATASHEET", help="TOML file with a [datasheet] table, or a built-in valve (KBSDG4V-3)"
    )
    p.add_argument("--structure", choices=["variable", "fixed"], default="variable")
    p.add_argument(
        "--match",
        default=None,
        metavar="A,B",
        help="the two null characteristics to reproduce: pressure-gain, flow-gain, leakage "
        "(default: pressure-gain,leakage when given)",
    )
    p.add_argument(
        "--curves",
        default=None,
        metavar="CSV",
        help="measured x_s, P_L, q_lk (and Q_L): fit them by least squares instead of the null characteristics",
    )
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fit)

    p = vsub.add_parser("bode", help="amplitude-dependent Bode plot of spool dynamics")
    p.add_argument("params", metavar="PARAMS", help="component file (SpoolRateLimited, ...) or built-in valve name")
    p.add_argument(
        "--amplitudes", default="5,25,50", metavar="A,B,...", help="amplitudes in %% of stroke (default 5,25,50)"
    )
    p.add_argument(
        "--frequencies", default="10:300:10", metavar="F", help="START:STOP:STEP or list [Hz] (default 10:300:10)"
    )
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_bode)

    p = vsub.add_parser("fit-dynamics", help="fit spool dynamics to Bode data (CSV: frequency, amplitude, gain, phase)")
    p.add_argument("bode", metavar="BODE.csv")
    p.add_argument("--model", choices=["rate-limited", "second-order", "first-order", "all"], default="rate-limited")
    p.add_argument("--start", default=None, metavar="NAME=VALUE,...", help="starting values, e.g. 'omega_n=700 rad/s'")
    add_output_options(p, "a folder named after the input")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fit_dynamics)

    valve_bench.add_parsers(vsub)
