"""Exceptions and warnings raised by hydroservo.

Every error a user can cause is a :class:`HydroservoError`; its message names
what was wrong (file, option, component, parameter), the value given and what
was expected.  The CLI prints the message and exits with code 2.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

__all__ = [
    "HydroservoError",
    "UnitError",
    "ParameterError",
    "ModelError",
    "ModelFileError",
    "SolverError",
    "TrimError",
    "ImplausibleResultError",
    "FluidRangeWarning",
    "ImplausibleResultWarning",
    "InterpretedWarning",
    "RenamedWarning",
    "shorten",
    "did_you_mean",
    "close_names",
]


class HydroservoError(Exception):
    """Base class of all errors caused by input to hydroservo."""


class UnitError(HydroservoError, ValueError):
    """A quantity could not be read, or has the wrong dimension."""


class ParameterError(HydroservoError, ValueError):
    """A parameter name or value is not acceptable."""


class ModelError(HydroservoError):
    """A system is not well formed (unknown component, unconnected input, loop)."""


class ModelFileError(HydroservoError):
    """A model file cannot be read."""


class SolverError(HydroservoError, RuntimeError):
    """The integrator failed; the message says when, where and why."""


class TrimError(HydroservoError, RuntimeError):
    """No equilibrium was found."""


class ImplausibleResultError(HydroservoError):
    """A result crossed a physical bound and the caller asked for strictness (``--strict``)."""


class FluidRangeWarning(UserWarning):
    """A fluid property was evaluated outside the range its model was fitted to."""


class ImplausibleResultWarning(UserWarning):
    """A run crossed a physical bound (``Result.warnings`` holds each crossing)."""


class InterpretedWarning(UserWarning):
    """``method="auto"`` runs CVODES in the interpreter: no C compiler was found (said once a process)."""


class RenamedWarning(UserWarning):
    """A parameter or component type was given under the name it had before it was renamed."""


class BareNumberWarning(UserWarning):
    """A bare number was given in Python (``params={"load.W": 3000}``) for a parameter the model gives in a unit
    other than SI (``"6400 lbf"``): it is taken in SI (3000 N), as numbers always are; the CLI refuses it."""


def shorten(text: str, limit: int = 60) -> str:
    """``text`` as a message shows it: whole, or its first ``limit`` characters and how long it was."""
    return text if len(text) <= limit else f"{text[:limit]}... ({len(text)} characters)"


def close_names(name: str, known: Iterable[str], n: int = 3) -> list[str]:
    """The names of ``known`` closest to ``name`` (difflib's ratio at least 0.62), best first, at most ``n``: the
    same name in another case first, then by spelling, then by spelling regardless of case."""
    known = [k for k in dict.fromkeys(known) if isinstance(k, str)]
    name = str(name)
    same = [k for k in known if k.lower() == name.lower() and k != name]
    close = same + [k for k in difflib.get_close_matches(name, known, n=n, cutoff=0.62) if k not in same]
    if not close:  # case apart: 'cylinder' for Cylinder, 'Flight-Simulatr' for flight-simulator
        by_lower = {k.lower(): k for k in known}
        close = [by_lower[k] for k in difflib.get_close_matches(name.lower(), list(by_lower), n=n, cutoff=0.62)]
    return close[:n]


def did_you_mean(name: str, known: Iterable[str]) -> str:
    """`` (did you mean 'X'?)`` with the names of ``known`` closest to ``name`` (:func:`close_names`), or "" if
    none is close: for a message that refuses an unknown name."""
    close = close_names(name, known)
    return " (did you mean " + " or ".join(repr(k) for k in close) + "?)" if close else ""
