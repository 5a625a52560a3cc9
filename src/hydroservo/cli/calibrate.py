"""``hydroservo calibrate``, ``hydroservo identify`` and ``hydroservo rig``: from rig records to a calibrated
model (:mod:`hydroservo.workflows.calibrate`, :mod:`hydroservo.workflows.identify`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, execute
from hydroservo.cli.progress import progress_bars

__all__ = ["add_parsers"]

_RECORD = "a record: one CSV file, or several separated by commas (one per sample rate), each with 't [s]' and 'signal [unit]' columns"


def cmd_calibrate(args: argparse.Namespace) -> int:
    from hydroservo.workflows.calibrate import Calibrate

    job = Calibrate(args.model, args.record, args.fit, inputs=args.input, noise=args.noise, validate=args.validate,
                    starts=args.starts, initial=args.initial, sets=args.set, plan=args.plan,
                    max_evaluations=args.max_evaluations, cli=True)
    return execute(job, args, progress_bars(args))


def cmd_rig(args: argparse.Namespace) -> int:
    from hydroservo.workflows.calibrate import VirtualRig

    job = VirtualRig(args.model, args.sensor, t_end=args.t_end, seed=args.seed, sets=args.set, name_=args.name, cli=True)
    return execute(job, args)


def cmd_friction(args: argparse.Namespace) -> int:
    from hydroservo.workflows.identify import IdentifyFriction

    job = IdentifyFriction(args.model, args.records, command=args.command_signal, cylinder=args.cylinder, load=args.load,
                           sets=args.set, cli=True)
    return execute(job, args)


def cmd_leakage(args: argparse.Namespace) -> int:
    from hydroservo.workflows.identify import IdentifyLeakage

    job = IdentifyLeakage(args.model, args.records, inputs=args.input or ["command.y"], cylinder=args.cylinder,
                          load=args.load, sets=args.set, cli=True)
    return execute(job, args)


def cmd_flow(args: argparse.Namespace) -> int:
    from hydroservo.workflows.identify import IdentifyFlowCoefficient

    job = IdentifyFlowCoefficient(args.model, args.records, inputs=args.input or ["command.y"], valve=args.valve,
                                  cylinder=args.cylinder, load=args.load, sets=args.set, cli=True)
    return execute(job, args)


def _model_options(p: Any) -> None:
    p.add_argument("--set", action="append", default=[], metavar="PARAM=VALUE",
                   help='set a parameter first, with units: --set "load.m=30 kg"')


def add_parsers(sub: Any) -> None:
    """Add ``calibrate``, ``identify`` and ``rig``."""
    p = sub.add_parser(
        "calibrate",
        help="fit a model's parameters to rig records, with standard errors, 95 %% intervals and a check on records "
        "kept out",
        description="Weighted least squares over every record at once (parameters shared), with exact gradients from "
        "the model's sensitivity equations. Prints each parameter with its standard error and 95 % interval (in the "
        "unit it was given in), the correlations, the RMS residual of each signal beside its noise, and warns of "
        "parameters the records cannot separate. Writes the calibrated model file, plots of measured against model "
        "with residuals, and calibration.json.",
    )
    p.add_argument("model", metavar="MODEL", help="built-in model or model file")
    p.add_argument("--record", action="append", default=[], metavar="A.csv[,B.csv]", required=True, help=_RECORD + "; repeat for more experiments")
    p.add_argument("--fit", action="append", default=[], metavar="COMP.PARAM[=LO..HI]", required=True,
                   help="a parameter to fit, with optional bounds in units: --fit 'spool.tau=5 ms..100 ms'; repeat")
    p.add_argument("--input", action="append", default=[], metavar="SIGNAL",
                   help="a recorded signal that drives the model (its source replaced): command.y, supply.p; repeat")
    p.add_argument("--noise", action="append", default=[], metavar="SIGNAL=SIGMA",
                   help="a signal's noise (standard deviation): --noise 'load.x=0.02 mm'; others are estimated")
    p.add_argument("--validate", action="append", default=[], metavar="C.csv[,D.csv]",
                   help="a record kept out of the fit, to check the prediction; repeat")
    p.add_argument("--starts", type=int, default=1, metavar="N", help="starting points (the model's values and N-1 drawn over the bounds)")
    p.add_argument("--initial", default="estimate", choices=["estimate", "record", "trim", "model"],
                   help="initial states: fitted from the records' first samples (default), taken as recorded, or the model's")
    p.add_argument("--max-evaluations", type=int, default=200, metavar="N",
                   help="residual evaluations each fit may use before it stops, unconverged (default 200)")
    p.add_argument("--plan", action="store_true",
                   help="do not fit: tell what the records, as planned experiments (hydroservo rig), would determine")
    _model_options(p)
    add_output_options(p, "hydroservo-calibrate-NAME")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_calibrate)

    p = sub.add_parser("rig", help="records of a model as a rig's logger would make them (rates, noise, resolution)")
    p.add_argument("model", metavar="MODEL")
    p.add_argument("--sensor", action="append", default=[], metavar="SIGNAL=RATE[,NOISE[,RESOLUTION]]", required=True,
                   help="a logged signal: --sensor 'cyl.pA=40 Hz,0.05 bar' (the unit of the noise is the file's); repeat")
    p.add_argument("--t-end", default=None, metavar="T", help="duration (default: the model's)")
    p.add_argument("--seed", type=int, default=None, help="seed of the noise")
    p.add_argument("--name", default=None, help="the record's name (its files' stem)")
    _model_options(p)
    add_output_options(p, "hydroservo-rig-NAME")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_rig)

    ident = sub.add_parser("identify", help="Efe's identification procedures on rig records: friction, leakage, flow-coefficient")
    isub = ident.add_subparsers(dest="identify_command", required=True)
    p = isub.add_parser("friction", help="friction forces at held valve signals (eq. 4.24) and the Stribeck law (eq. 3.47)")
    p.add_argument("--command-signal", default="command.y", metavar="SIGNAL", help="the valve signal's column (default command.y)")
    _procedure_options(p, "+", "friction", cmd_friction, inputs=False)

    p = isub.add_parser("leakage", help="internal leakage C_Li from a locked-piston record (section 4.5.5)")
    _procedure_options(p, 1, "leakage", cmd_leakage)

    p = isub.add_parser("flow-coefficient", help="the valve's K(x_v) and H(x_v, d_f) tables from swept records (eqs. 3.22-3.23)")
    p.add_argument("--valve", default="valve", metavar="NAME")
    _procedure_options(p, "+", "flow-coefficient", cmd_flow)


def _procedure_options(p: Any, nargs: Any, name: str, func: Any, *, inputs: bool = True) -> None:
    """What every ``identify`` procedure takes: records, the model, its recorded inputs, the cylinder and load."""
    p.add_argument("records", nargs=nargs, metavar="RECORD", help=_RECORD)
    p.add_argument("--model", required=True, help="the model whose laws and dimensions apply (its other parameters matter)")
    if inputs:
        p.add_argument("--input", action="append", default=[], metavar="SIGNAL", help="recorded inputs (default command.y)")
    p.add_argument("--cylinder", default="cyl", metavar="NAME")
    p.add_argument("--load", default="load", metavar="NAME")
    _model_options(p)
    add_output_options(p, f"hydroservo-{name}-NAME")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=func)
