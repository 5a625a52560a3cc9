"""Command-line interface: a thin shell over the public API, one module per command group.

=====================  ==========================================================
module                 commands
=====================  ==========================================================
:mod:`.models`         ``models``, ``simulate``, ``export``
:mod:`.export_c`       ``export-c``
:mod:`.export_fmu`     ``export-fmu``
:mod:`.hopsan`         ``import-hopsan``
:mod:`.linear`         ``linearize``
:mod:`.ladder`         ``ladder``
:mod:`.sensitivity`    ``sensitivity``
:mod:`.components`     ``components``, ``describe``
:mod:`.valve`          ``valve fit``, ``valve bode``, ``valve fit-dynamics``
:mod:`.valve_bench`    ``valve characteristics``, ``valve identify``
:mod:`.servovalve`     ``servovalve bench``
:mod:`.fluid`          ``fluid``
:mod:`.validate`       ``validate``
:mod:`.report`         ``report``, ``draw``
:mod:`.examples`       ``examples``
=====================  ==========================================================

A command module imports the library when its command runs, not when the
parser is built, so that ``--help`` and ``--version`` answer at once. Every
error caused by the input (files, options, values) is printed as one message
and exits with code 2; Ctrl-C stops the run, says where, writes nothing and
exits with code 130; ``--debug`` shows the traceback instead.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import warnings
from collections.abc import Sequence
from typing import Any, NoReturn

from hydroservo.cli import (
    calibrate,
    components,
    examples,
    export_c,
    export_fmu,
    fluid,
    hopsan,
    ladder,
    linear,
    models,
    report,
    sensitivity,
    servovalve,
    validate,
    valve,
)
from hydroservo.errors import (
    FluidRangeWarning,
    HydroservoError,
    ImplausibleResultWarning,
    RenamedWarning,
    close_names,
    did_you_mean,
)
from hydroservo.version import __version__

__all__ = ["main", "build_parser"]


class _Parser(argparse.ArgumentParser):
    """An argument parser whose errors look like every other error: one line, exit code 2."""

    def error(self, message: str) -> NoReturn:
        where = self.prog.removeprefix("hydroservo").strip()  # the subcommand, if any
        meant = self._meant()
        see = meant.prog if meant is not None and not where else self.prog
        self.exit(2, f"hydroservo: error: {where + ': ' if where else ''}{message}{self._hint(message, meant)} "
                     f"(see {see} --help)\n")  # fmt: skip

    def parse_args(self, args: Sequence[str] | None = None, namespace: Any = None) -> Any:  # type: ignore[override]
        self._argv = list(sys.argv[1:] if args is None else args)  # for the hints: which subcommand was meant
        return super().parse_args(args, namespace)

    def _meant(self) -> argparse.ArgumentParser | None:
        """The subcommand's parser, if the arguments given name one (the top-level parser reports unknown
        options of a subcommand)."""
        commands = {name: sub for action in self._actions if isinstance(action, argparse._SubParsersAction)
                    for name, sub in action.choices.items()}  # fmt: skip
        return next((commands[a] for a in getattr(self, "_argv", []) if a in commands), None)

    def _hint(self, message: str, meant: argparse.ArgumentParser | None) -> str:
        """The closest commands, choices or options to a mistyped one (argparse's messages name them)."""
        choice = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)", message)
        if choice:
            return did_you_mean(choice.group(1), re.findall(r"'([^']*)'", choice.group(2)))
        unknown = re.search(r"unrecognized arguments: (.*)", message)
        if unknown:
            parsers = [self] if meant is None else [self, meant]
            options = [o[2:] for parser in parsers for o in parser._option_string_actions if o.startswith("--")]
            for token in unknown.group(1).split():
                close = close_names(token.split("=", 1)[0].lstrip("-"), options, n=2) if token.startswith("-") else []
                if close:  # matched without the dashes, which every option shares
                    return " (did you mean " + " or ".join(repr("--" + o) for o in close) + "?)"
        return ""


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="hydroservo", description="Electro-hydraulic servo systems: simulate, export, validate.",
        epilog="The user guide is installed with hydroservo: hydroservo docs lists its pages, hydroservo docs NAME "
        "prints one (a message naming docs/NAME.md means that page).",
    )
    parser.add_argument("--version", action="version", version=f"hydroservo {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks on errors")
    sub = parser.add_subparsers(dest="command", required=True)
    models.add_parsers(sub)
    export_c.add_parsers(sub)
    export_fmu.add_parsers(sub)
    hopsan.add_parsers(sub)
    linear.add_parsers(sub)
    ladder.add_parsers(sub)
    sensitivity.add_parsers(sub)
    components.add_parsers(sub)
    valve.add_parsers(sub)
    servovalve.add_parsers(sub)
    fluid.add_parsers(sub)
    validate.add_parsers(sub)
    report.add_parsers(sub)
    calibrate.add_parsers(sub)
    examples.add_parsers(sub)
    return parser


#: Options whose value may start with a minus sign.
_NUMERIC_OPTIONS = (
    "--temperature", "--pressure", "--amplitudes", "--frequencies", "--predict", "--reference", "--current", "--supply",
    "--at",
)


def _join_negative_values(argv: list[str]) -> list[str]:
    """``--temperature -40,20`` -> ``--temperature=-40,20``: argparse would take -40,20 for an option."""
    out: list[str] = []
    it = iter(argv)
    for tok in it:
        if tok in _NUMERIC_OPTIONS:
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


class _WarningPrinter:
    """Prints each warning once, as one line: the same message from several call sites is one message."""

    def __init__(self) -> None:
        self.shown: set[str] = set()

    def __call__(self, message: Warning | str, category: type[Warning], *args: object, **kwargs: object) -> None:
        text = str(message)
        if text not in self.shown:
            self.shown.add(text)
            print(f"hydroservo: warning: {text}", file=sys.stderr)


#: The command line's BLAS: one thread. A command's matrices are small (a model's Jacobian, a fit's normal
#: equations), and OpenBLAS's second thread only spins: 0.1 s of CPU beyond the wall time of a one-off
#: ``simulate`` (measured: 0.32 s user for 0.25 s wall, 0.23 s with one thread). Set before NumPy is imported
#: (it is not, until a command runs); a value the user set is kept.
BLAS_THREADS = {"OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}


def main(argv: Sequence[str] | None = None) -> int:
    if "numpy" not in sys.modules:
        for variable, value in BLAS_THREADS.items():
            os.environ.setdefault(variable, value)
    parser = build_parser()
    args = parser.parse_args(_join_negative_values(list(sys.argv[1:] if argv is None else argv)))
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always", FluidRangeWarning)  # the printer shows each message once
            warnings.simplefilter("always", RenamedWarning)
            warnings.simplefilter("ignore", ImplausibleResultWarning)  # simulate prints each crossing itself
            warnings.showwarning = _WarningPrinter()
            return int(args.func(args))
    except BrokenPipeError:  # output piped into head & co.
        sys.stderr.close()
        return 0
    except HydroservoError as exc:
        if args.debug:
            raise
        print(f"hydroservo: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:  # Ctrl-C: the solvers stop within a step (hydroservo.system.integration)
        if args.debug:
            raise
        solvers = sys.modules.get("hydroservo.system.integration")  # imported if a run was under way
        said = str(exc) if solvers is not None and isinstance(exc, solvers.Interrupted) else "interrupted"
        print(f"hydroservo: {said}; nothing written", file=sys.stderr)
        return INTERRUPTED


#: The exit status after Ctrl-C: 128 + SIGINT, as a shell reports a command it interrupted.
INTERRUPTED = 130


if __name__ == "__main__":
    sys.exit(main())
