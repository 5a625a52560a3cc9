"""``hydroservo linearize``: the linear model of a system at an operating point, its modes and valve coefficients
(:mod:`hydroservo.workflows.linear`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, add_unit_options, execute, frequencies, numbers
from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]


def _names(text: str | None) -> list[str] | None:
    if text is None:
        return None
    names = [n.strip() for n in text.split(",") if n.strip()]
    if not names:
        raise ParameterError(f"{text!r}: expected comma-separated signal names, e.g. spool.u,load.F_ext")
    return names


def cmd_linearize(args: argparse.Namespace) -> int:
    from hydroservo.workflows.linear import Linearize

    job = Linearize(
        args.model, args.set, at=args.at, t=args.t, free=_names(args.free) or [], inputs=_names(args.inputs),
        outputs=_names(args.outputs), frequencies=frequencies(args.frequencies) if args.frequencies else None,
        simulate=numbers(args.simulate, "--simulate", above=0.0, expected="positive amplitudes in the input's unit")
        if args.simulate else None,
        write=args.out is not None or not args.json,  # --json alone writes nothing
        units=args.units, si=args.si, cli=True,
    )
    return execute(job, args)


def add_parsers(sub: Any) -> None:
    """Add ``linearize``."""
    p = sub.add_parser(
        "linearize",
        help="linear model of a system at an operating point: matrices, modes, valve coefficients",
        description="State-space matrices A, B, C, D from the exact Jacobians at an operating point, the modes "
        "(poles, natural frequencies, damping, participating states) and the valve coefficients of "
        "[Efe2014] eqs. 4.8-4.12.",
    )
    p.add_argument("model", metavar="NAME_OR_FILE")
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter or option, with units: --set "command.amplitude=0.5"')
    p.add_argument("--at", default="trim", metavar="trim|run|initial|FILE|STATE=VALUE,...",
                   help="operating point: an equilibrium (default), the state a run from the initial state reaches at "
                   "--t (every state as simulated), the initial state, an operating-point file "
                   "(TOML, state = value with units) or states given here")
    p.add_argument("--t", default="0", metavar="T", help="time of the operating point (the signals' values then), e.g. 0.3")
    p.add_argument("--free", default=None, metavar="STATE,...",
                   help="states left free by the trim: a steady motion, e.g. --free load.x; they keep the values a run "
                   "from the initial state has at --t")
    p.add_argument("--inputs", default=None, metavar="NAME,...",
                   help="component inputs (spool.u) or parameters (supply.p); default: the inputs fed by signal blocks")
    p.add_argument("--outputs", default=None, metavar="NAME,...", help="states, outputs or aliases; default: the states")
    p.add_argument("--frequencies", default=None, metavar="F1,F2,...|START:STOP:STEP",
                   help="frequencies [Hz] of the Bode plot (and of the JSON's frequency response)")
    p.add_argument("--simulate", default=None, metavar="A1,A2,...",
                   help="also run the nonlinear system with sines of these amplitudes (the first input's unit) about "
                   "the operating point: its gain beside the linear one, for the first output, shows where linearity ends")
    add_unit_options(p, csv=False, note="the JSON stays SI, as the linear model's matrices are")
    add_output_options(p, "hydroservo-NAME-linear")
    p.add_argument("--json", action="store_true",
                   help="print the matrices with their names, the modes and the valve coefficients as JSON "
                   "(files are written only with --out)")
    p.set_defaults(func=cmd_linearize)
