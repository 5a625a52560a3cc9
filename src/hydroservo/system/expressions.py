"""A small, safe arithmetic language for aliases and initial conditions.

``"-mass.x"``, ``"load.W / cyl.A_A"``, ``"2 * pi * f.frequency"``: numbers,
``+ - * / **``, parentheses, dotted names and the functions ``sqrt``, ``abs``,
``sin``, ``cos``, the constants ``pi`` and ``p_atm`` (the standard atmosphere,
101325 Pa: an absolute pressure is ``cyl.pA + p_atm``). Names are looked up in a mapping supplied by the caller
(signals for aliases, parameters for initial conditions). Nothing else is
evaluated: no attribute access, calls or imports.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Callable, Mapping
from typing import Any

import casadi as ca

from hydroservo.errors import ModelError
from hydroservo.units import Dimension, dimension, registry

__all__ = ["evaluate", "names_in", "check_dimension"]

_FUNCS: dict[str, Callable[[Any], Any]] = {"sqrt": ca.sqrt, "abs": ca.fabs, "sin": ca.sin, "cos": ca.cos}
_CONSTS = {"pi": math.pi}
#: Constants with a unit: name -> (value in SI, unit).
_UNIT_CONSTS = {"p_atm": (101325.0, "Pa")}


def _dotted(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        base = _dotted(node.value)
        return None if base is None else f"{base}.{node.attr}"
    return None


#: Longest expression [characters]: aliases and initial conditions are short; a longer text is not one.
MAX_LENGTH = 500


def _parse(text: str, what: str) -> ast.Expression:
    text = str(text).strip()
    if len(text) > MAX_LENGTH:
        raise ModelError(f"{what}: expression of {len(text)} characters; expected at most {MAX_LENGTH}")
    try:
        return ast.parse(text, mode="eval")
    except (SyntaxError, RecursionError, MemoryError, ValueError):
        raise ModelError(f"{what}: cannot read expression {text!r}") from None


def names_in(text: str, what: str = "expression") -> list[str]:
    """Dotted names an expression refers to."""
    out: list[str] = []

    def walk(node: ast.AST) -> None:
        name = _dotted(node)
        if name is not None and isinstance(node, ast.Attribute):
            out.append(name)
            return
        if isinstance(node, ast.Name) and node.id not in _CONSTS and node.id not in _UNIT_CONSTS and node.id not in _FUNCS:
            out.append(node.id)
            return
        for child in ast.iter_child_nodes(node):
            walk(child)

    walk(_parse(text, what).body)
    return out


_OPERATORS: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
    ast.Pow: lambda a, b: a**b,
}


def _is_zero(value: Any) -> bool:
    if isinstance(value, float):
        return value == 0.0
    if isinstance(value, (ca.SX, ca.DM)):
        return bool(value.is_zero())
    return False  # a quantity of the dimension check: magnitude 1 by construction


def _evaluate(
    text: str, names: Mapping[str, Any], funcs: Mapping[str, Callable[[Any], Any]], what: str
) -> Any:
    """The value of ``text`` on ``names``: numbers, CasADi expressions or pint quantities alike."""
    tree = _parse(text, what)

    def ev(node: ast.AST) -> Any:
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) and not isinstance(node.value, bool):
            return float(node.value)
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            val = ev(node.operand)
            return -val if isinstance(node.op, ast.USub) else val
        if isinstance(node, ast.BinOp) and type(node.op) in _OPERATORS:
            a, b = ev(node.left), ev(node.right)
            if isinstance(node.op, ast.Div) and _is_zero(b):
                raise ModelError(f"{what}: {text!r} divides by zero")
            try:
                value = _OPERATORS[type(node.op)](a, b)
            except (ZeroDivisionError, OverflowError):
                raise ModelError(f"{what}: {text!r} has no finite value") from None
            if isinstance(value, complex) or (isinstance(value, float) and not math.isfinite(value)):
                raise ModelError(f"{what}: {text!r} has no finite value")
            return value
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in funcs and len(node.args) == 1:
            return funcs[node.func.id](ev(node.args[0]))
        name = _dotted(node)
        if name is not None:
            if name in names:
                return names[name]
            if name in _CONSTS:
                return _CONSTS[name]
            if name in _UNIT_CONSTS:
                return _UNIT_CONSTS[name][0]
            raise ModelError(f"{what}: unknown name {name!r} in {text!r}")
        raise ModelError(f"{what}: {text!r} uses something other than numbers, names, + - * / ** and sqrt/abs/sin/cos")

    try:
        return ev(tree.body)
    except RecursionError:
        raise ModelError(f"{what}: expression {text!r} is nested too deeply") from None


def evaluate(text: str | float, names: Mapping[str, Any], what: str = "expression") -> Any:
    """Evaluate ``text`` with dotted names taken from ``names``."""
    if isinstance(text, (int, float)):
        return float(text)
    return _evaluate(text, names, _FUNCS, what)


def check_dimension(text: str, units: Mapping[str, str], declared: str, what: str = "expression") -> None:
    """Refuse an expression whose dimension is not that of ``declared``, or that adds unlike quantities.

    The expression is evaluated once on quantities of magnitude 1 in each
    name's unit (``units``: name -> unit), so ``load.x + cyl.pA`` and a length
    declared in bar are found when the model is built.
    """
    units = {**units, **{k: u for k, (_, u) in _UNIT_CONSTS.items() if k in text}}
    named = {name: dimension(units[name]) for name in [*names_in(text, what), *_UNIT_CONSTS] if name in units}
    want_known = dimension(declared)
    if want_known is not None and all(d is not None for d in named.values()):  # shipped units: no registry
        dims: dict[str, Callable[[Any], Any]] = {
            "sqrt": lambda d: d**0.5, "abs": lambda d: d, "sin": _dimensionless_of, "cos": _dimensionless_of
        }
        try:
            got_known = Dimension.of(_evaluate(text, named, dims, what))
        except ModelError:
            raise
        except (TypeError, ValueError):  # unlike dimensions: pint's message says which
            got_known = None
        if got_known == want_known:
            return
    reg = registry()
    one = {name: reg.Quantity(1.0, unit or "") for name, unit in units.items()}
    funcs: dict[str, Callable[[Any], Any]] = {"sqrt": lambda q: q**0.5, "abs": abs, "sin": _dimensionless, "cos": _dimensionless}
    try:
        value = _evaluate(text, one, funcs, what)
    except ModelError:
        raise
    except Exception as exc:  # pint's DimensionalityError and the like
        raise ModelError(f"{what}: {text!r} mixes quantities of different dimensions: {exc}") from None
    got = value if isinstance(value, reg.Quantity) else reg.Quantity(value, "")
    want = reg.Quantity(1.0, declared or "")
    if got.dimensionality != want.dimensionality:
        raise ModelError(
            f"{what}: {text!r} is a quantity of dimension {got.dimensionality} (in {got.units:~P}), "
            f"but its unit is declared {declared or 'dimensionless'!r} ({want.dimensionality})"
        )


def _dimensionless_of(d: Any) -> float:
    if Dimension.of(d).exponents:
        raise ValueError("sin and cos take dimensionless arguments")
    return 1.0


def _dimensionless(q: Any) -> Any:
    if hasattr(q, "dimensionless") and not q.dimensionless:
        raise ValueError(f"sin and cos take dimensionless arguments, not {q.units}")
    return 1.0
