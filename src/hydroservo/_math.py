"""Elementwise functions that work on NumPy values and CasADi expressions alike.

The published laws in :mod:`hydroservo.fluids`, :mod:`hydroservo.orifices` and
:mod:`hydroservo.friction` are written once, with these helpers, and serve both
as vectorised NumPy functions for users and as symbolic building blocks of the
components.
"""

from __future__ import annotations

from typing import Any

import casadi as ca
import numpy as np

_SYMBOLIC = (ca.SX, ca.MX, ca.DM)


def is_symbolic(*args: Any) -> bool:
    return any(isinstance(a, _SYMBOLIC) for a in args)


def sqrt(x: Any) -> Any:
    return ca.sqrt(x) if is_symbolic(x) else np.sqrt(x)


def exp(x: Any) -> Any:
    return ca.exp(x) if is_symbolic(x) else np.exp(x)


def log10(x: Any) -> Any:
    return ca.log10(x) if is_symbolic(x) else np.log10(x)


def sin(x: Any) -> Any:
    return ca.sin(x) if is_symbolic(x) else np.sin(x)


def atan(x: Any) -> Any:
    return ca.atan(x) if is_symbolic(x) else np.arctan(x)


def floor(x: Any) -> Any:
    return ca.floor(x) if is_symbolic(x) else np.floor(x)


def tanh(x: Any) -> Any:
    return ca.tanh(x) if is_symbolic(x) else np.tanh(x)


def fabs(x: Any) -> Any:
    return ca.fabs(x) if is_symbolic(x) else np.abs(x)


def sign(x: Any) -> Any:
    return ca.sign(x) if is_symbolic(x) else np.sign(x)


def fmax(a: Any, b: Any) -> Any:
    return ca.fmax(a, b) if is_symbolic(a, b) else np.maximum(a, b)


def fmin(a: Any, b: Any) -> Any:
    return ca.fmin(a, b) if is_symbolic(a, b) else np.minimum(a, b)


def if_else(cond: Any, a: Any, b: Any) -> Any:
    if is_symbolic(cond, a, b):
        return ca.if_else(cond, a, b)
    return np.where(cond, a, b)


def interp(x: Any, xp: Any, fp: Any) -> Any:
    """Piecewise-linear interpolation, held constant outside ``xp``."""
    xp = np.asarray(xp, dtype=float)
    fp = np.asarray(fp, dtype=float)
    if is_symbolic(x):
        if xp.size == 1:
            return ca.SX(float(fp[0])) if isinstance(x, ca.SX) else float(fp[0])
        xc = ca.fmin(ca.fmax(x, float(xp[0])), float(xp[-1]))
        return ca.pw_lin(xc, ca.DM(xp), ca.DM(fp))
    return np.interp(x, xp, fp)
