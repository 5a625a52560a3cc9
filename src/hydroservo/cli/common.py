"""What every command group shares: reading lists of numbers, output folders, JSON output.

NumPy is imported by the functions that need it, so that building the parser stays fast.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.errors import ParameterError, shorten

if TYPE_CHECKING:
    import numpy as np

    from hydroservo.io.files import OutputFolder

__all__ = ["numbers", "frequencies", "component_inputs", "add_output_options", "output_folder", "print_json"]


#: Most frequencies one command computes (each is a periodic orbit per amplitude).
MAX_FREQUENCIES = 2000


def numbers(
    text: str,
    what: str,
    *,
    above: float | None = None,
    at_most: float | None = None,
    expected: str = "",
) -> list[float]:
    """Comma-separated finite numbers, e.g. ``5,25,50``; each above ``above`` and at most ``at_most`` if given.

    An error names the option ``what``, the value and ``expected``.
    """
    import math

    try:
        vals = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise ParameterError(f"{what} {text!r}: expected comma-separated numbers, e.g. 5,25,50") from None
    if not vals:
        raise ParameterError(f"{what} {text!r}: expected at least one number")
    for v in vals:
        bad = not math.isfinite(v) or (above is not None and v <= above) or (at_most is not None and v > at_most)
        if bad:
            raise ParameterError(f"{what} {text!r}: {v:g} is not acceptable; expected {expected or 'finite numbers'}")
    return vals


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


def add_output_options(p: Any, default: str) -> None:
    """``--out DIR`` and ``--force`` of a command that writes files."""
    p.add_argument(
        "--out", default=None, metavar="DIR", help=f"folder for the files written (default: a new {default}[-N])"
    )
    p.add_argument("--force", action="store_true", help="replace files of the same names in that folder")


def output_folder(args: Any, default: str) -> OutputFolder:
    """The command's output folder, written all or nothing, nothing replaced unasked.

    ``--out DIR`` is used as given (files already in it are replaced only with
    ``--force``); without it, a fresh folder: ``default``, or ``default-2``,
    ``default-3``, ... if it exists, so repeated runs never collide.
    """
    from hydroservo.io.files import OutputFolder, safe_name

    if args.out:
        return OutputFolder(Path(args.out), force=args.force)
    base = safe_name(default)
    target, n = Path(base), 1
    while target.exists() and not args.force:
        n += 1
        target = Path(f"{base}-{n}")
    return OutputFolder(target, force=args.force, what="output folder")


def print_json(data: Any) -> None:
    """Print ``data`` as indented JSON (NumPy numbers as floats)."""
    print(json.dumps(data, indent=2, default=float))
