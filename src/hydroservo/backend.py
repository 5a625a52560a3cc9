"""The array backend: elementwise functions that work on NumPy values and CasADi expressions alike.

The published laws of :mod:`hydroservo.laws` are written once, with these
helpers, and serve both as vectorised NumPy functions for users and as
symbolic building blocks of the components.
"""

from __future__ import annotations

from typing import Any

import casadi as ca
import numpy as np

_SYMBOLIC = (ca.SX, ca.MX, ca.DM)


def is_symbolic(*args: Any) -> bool:
    """True if any argument is a CasADi expression (the laws then build CasADi expressions)."""
    for a in args:
        if isinstance(a, _SYMBOLIC):
            return True
    return False


def sqrt(x: Any) -> Any:
    return ca.sqrt(x) if isinstance(x, _SYMBOLIC) else np.sqrt(x)


def exp(x: Any) -> Any:
    return ca.exp(x) if isinstance(x, _SYMBOLIC) else np.exp(x)


def log10(x: Any) -> Any:
    return ca.log10(x) if isinstance(x, _SYMBOLIC) else np.log10(x)


def sin(x: Any) -> Any:
    return ca.sin(x) if isinstance(x, _SYMBOLIC) else np.sin(x)


def atan(x: Any) -> Any:
    return ca.atan(x) if isinstance(x, _SYMBOLIC) else np.arctan(x)


def floor(x: Any) -> Any:
    return ca.floor(x) if isinstance(x, _SYMBOLIC) else np.floor(x)


def tanh(x: Any) -> Any:
    return ca.tanh(x) if isinstance(x, _SYMBOLIC) else np.tanh(x)


def fabs(x: Any) -> Any:
    return ca.fabs(x) if isinstance(x, _SYMBOLIC) else np.abs(x)


def sign(x: Any) -> Any:
    return ca.sign(x) if isinstance(x, _SYMBOLIC) else np.sign(x)


def fmax(a: Any, b: Any) -> Any:
    return ca.fmax(a, b) if is_symbolic(a, b) else np.maximum(a, b)


def fmin(a: Any, b: Any) -> Any:
    return ca.fmin(a, b) if is_symbolic(a, b) else np.minimum(a, b)


def clip(x: Any, lo: Any, hi: Any) -> Any:
    """``x`` limited to ``[lo, hi]``."""
    return fmin(fmax(x, lo), hi)


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
