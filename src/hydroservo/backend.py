"""The array backend: elementwise functions that work on NumPy values and CasADi expressions alike.

The published laws of :mod:`hydroservo.laws` are written once, with these
helpers, and serve both as vectorised NumPy functions for users and as
symbolic building blocks of the components.
"""

from __future__ import annotations

from collections.abc import Callable
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


def _elementwise(symbolic: Callable[[Any], Any], numeric: Callable[[Any], Any]) -> Callable[[Any], Any]:
    """One function of one argument: CasADi's for an expression, NumPy's otherwise."""

    def apply(x: Any) -> Any:
        return symbolic(x) if isinstance(x, _SYMBOLIC) else numeric(x)

    apply.__name__ = numeric.__name__
    apply.__doc__ = f"Elementwise {numeric.__name__}, of a NumPy value or a CasADi expression."
    return apply


sqrt = _elementwise(ca.sqrt, np.sqrt)
exp = _elementwise(ca.exp, np.exp)
log10 = _elementwise(ca.log10, np.log10)
sin = _elementwise(ca.sin, np.sin)
atan = _elementwise(ca.atan, np.arctan)
floor = _elementwise(ca.floor, np.floor)
tanh = _elementwise(ca.tanh, np.tanh)
cos = _elementwise(ca.cos, np.cos)
fabs = _elementwise(ca.fabs, np.abs)
sign = _elementwise(ca.sign, np.sign)
log = _elementwise(ca.log, np.log)
tan = _elementwise(ca.tan, np.tan)
asin = _elementwise(ca.asin, np.arcsin)
acos = _elementwise(ca.acos, np.arccos)
sinh = _elementwise(ca.sinh, np.sinh)
cosh = _elementwise(ca.cosh, np.cosh)


def atan2(y: Any, x: Any) -> Any:
    """The angle of the point (x, y), in (-pi, pi]."""
    return ca.atan2(y, x) if is_symbolic(y, x) else np.arctan2(y, x)


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
