"""TOML: the one reader of TOML files and the one writer of TOML values, for every file hydroservo writes."""

from __future__ import annotations

import numbers
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.io.files import read_text
from hydroservo.units import format_quantity

__all__ = ["read_toml", "toml_string", "toml_key", "toml_value", "toml_quantity", "toml_table"]


def read_toml(path: str | Path, what: str, error: type[HydroservoError] = ParameterError) -> dict[str, Any]:
    """Parse a TOML file; an unreadable or malformed file raises ``error`` naming ``what`` and the path."""
    text = read_text(path, what, error)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{what} {str(path)!r}: malformed TOML: {exc}") from None


_ESCAPES = {"\\": "\\\\", '"': '\\"', "\n": "\\n", "\r": "\\r", "\t": "\\t", "\b": "\\b", "\f": "\\f"}


def toml_string(s: str) -> str:
    """A TOML basic string: backslashes, quotes and control characters escaped (a Hopsan model's description
    holds line breaks)."""
    return '"' + "".join(_ESCAPES.get(ch) or (f"\\u{ord(ch):04x}" if ord(ch) < 0x20 or ord(ch) == 0x7F else ch) for ch in s) + '"'


def toml_key(k: str) -> str:
    """A TOML key: bare when it can be, quoted otherwise."""
    return k if k and k.replace("_", "a").replace("-", "a").isalnum() else toml_string(k)


def toml_value(v: Any) -> str:
    """A TOML value: strings, booleans, numbers (floats at full precision), lists and inline tables."""
    if isinstance(v, str):
        return toml_string(v)
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, numbers.Integral):  # a count stays whole (a line's segments)
        return str(int(v))
    if isinstance(v, numbers.Real):
        return repr(float(v))
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{toml_key(k)} = {toml_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def toml_quantity(value: float, unit: str, given: str | None = None) -> str:
    """A parameter value: the text it was given as (``"1500 psi"``) if any, else SI at full precision."""
    if given is not None:
        return toml_string(given)
    if unit in ("", "-"):
        return toml_value(value)
    return toml_string(format_quantity(value, unit))


def toml_table(name: str, entries: Mapping[str, Any], comments: Mapping[str, str] | None = None) -> list[str]:
    """Lines of a ``[name]`` table of already formatted values (``entries``: key -> TOML text)."""
    lines = [f"[{name}]"]
    for key, text in entries.items():
        note = (comments or {}).get(key)
        lines.append(f"{toml_key(key)} = {text}" + (f"  # {note}" if note else ""))
    return lines
