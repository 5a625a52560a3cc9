"""What every command group shares: reading lists of numbers, output folders, running a workflow, JSON output.

A command parses its options into a workflow (:mod:`hydroservo.workflows`) and hands it to
:func:`execute`, which makes the output folder (refusing names already there before any work), runs
it, prints its warnings, writes its files and prints its report. NumPy and the workflows are imported
by the functions that need them, so that building the parser stays fast.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any

from hydroservo.errors import ParameterError, shorten
from hydroservo.workflows.base import numbers

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.io.files import OutputFolder
    from hydroservo.workflows.base import Workflow

__all__ = [
    "numbers", "frequencies", "component_inputs", "add_output_options", "output_folder", "print_json", "execute",
]


#: Most frequencies one command computes (each is a periodic orbit per amplitude).
MAX_FREQUENCIES = 2000


def frequencies(text: str) -> np.ndarray:
    """``START:STOP:STEP`` or a comma-separated list of frequencies [Hz], at most :data:`MAX_FREQUENCIES`."""
    import math

    import numpy as np

    if ":" in text:
        parts = text.split(":")
        try:
            lo, hi, step = (float(p) for p in parts)
        except ValueError:
            raise ParameterError(f"--frequencies {text!r}: expected START:STOP:STEP in Hz, e.g. 10:300:10") from None
        if not (all(math.isfinite(v) for v in (lo, hi, step)) and 0 < lo <= hi and step > 0):
            raise ParameterError(f"--frequencies {text!r}: expected finite 0 < START <= STOP and STEP > 0 [Hz]")
        count = math.floor((hi - lo) / step + 0.5) + 1
        if count > MAX_FREQUENCIES:
            raise ParameterError(f"--frequencies {text!r}: {count} frequencies; expected at most {MAX_FREQUENCIES}")
        return np.arange(lo, hi + step / 2, step)
    vals = np.array(numbers(text, "--frequencies", above=0.0, expected="positive, finite frequencies [Hz]"))
    if vals.size > MAX_FREQUENCIES:
        raise ParameterError(f"--frequencies: {vals.size} frequencies; expected at most {MAX_FREQUENCIES}")
    return vals


def component_inputs(text: str | None, what: str = "--inputs") -> list[str]:
    """The component inputs of an option such as ``--inputs valve.u,load.F_ext`` (none if not given)."""
    if text is None:
        return []
    names = [n.strip() for n in text.split(",") if n.strip()]
    if not names:
        raise ParameterError(f"{what} {shorten(text)!r}: expected comma-separated component inputs, e.g. valve.u")
    return names


def add_unit_options(p: Any, csv: bool = True, note: str = "") -> None:
    """``--units``, ``--si`` and (with ``csv``) ``--ascii``: the units results are shown and written in; ``note``
    ends the help of ``--units`` (what they do not apply to)."""
    p.add_argument(
        "--units",
        default=None,
        metavar="LIST",
        help="units to show results in, over the model's own: a unit for every signal of its dimension (bar), "
        "a quantity's (p=bar, x=mm, v=mm/s, Q=L/min, F=kN) or a signal's (cyl.pA=psi), comma-separated"
        + (f"; {note}" if note else ""),
    )
    p.add_argument("--si", action="store_true", help="show and write every result in SI units instead")
    if csv:
        p.add_argument("--ascii", action="store_true", help="CSV unit names in ASCII (m^3/s), without a byte-order mark")


def add_output_options(p: Any, default: str) -> None:
    """``--out DIR`` and ``--force`` of a command that writes files."""
    p.add_argument(
        "--out", default=None, metavar="DIR", help=f"folder for the files written (default: a new {default}[-N])"
    )
    p.add_argument("--force", action="store_true", help="replace files of the same names in that folder")


def output_folder(args: Any, default: str) -> OutputFolder:
    """The command's output folder (``--out``, ``--force``; :func:`hydroservo.workflows.base.output_folder`)."""
    from hydroservo.workflows.base import output_folder as folder

    return folder(args.out, default, force=args.force)


def execute(job: Workflow, args: Any, progress: Any = None) -> int:
    """Run a command's workflow: the folder first (nothing there replaced unasked, refused before the work),
    then the run, its warnings on stderr, its files, and its report on stdout (JSON with ``--json``)."""
    import sys

    names = job.planned()
    out = output_folder(args, job.folder()) if names or job.WRITES_ITSELF else None
    if out is not None:
        out.expect(names)
    try:
        report = job.run(progress=progress, folder=None if out is None else out.target)
    finally:
        if hasattr(progress, "close"):
            progress.close()  # the last stage's line ends before the report or the error is printed
    for text in report.warnings:
        print(f"hydroservo: warning: {text}", file=sys.stderr)
    if out is not None and report.artifacts():
        report.write(out)
    if getattr(args, "json", False):
        print(report.to_json())
    else:
        print("\n".join(report.lines()))
    return report.exit_code()


def print_json(data: Any) -> None:
    """Print ``data`` as indented JSON (NumPy numbers as floats)."""
    print(json.dumps(data, indent=2, default=float))
