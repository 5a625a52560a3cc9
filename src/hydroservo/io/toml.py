"""TOML: the one reader of TOML files and the one writer of TOML values, for every file hydroservo writes.

Values are written by tomlkit, which escapes and formats them as TOML requires; :func:`edit_toml` changes
values of a file's text with everything else in it kept (its comments, order and layout). Every string and key
hydroservo writes into a TOML file goes through :func:`toml_string` or :func:`toml_key`, and every comment through
:func:`toml_comment`: whatever a name, a description or a path holds (a line break, a quote, ``#``, ``[``, a
control character, U+2028), it is written escaped and reads back as the same text, and it never becomes TOML.
"""

from __future__ import annotations

import numbers
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from hydroservo.errors import HydroservoError, ParameterError, shorten
from hydroservo.io.files import read_text
from hydroservo.io.text import comment_lines, one_line
from hydroservo.units import format_quantity

__all__ = [
    "read_toml", "toml_string", "toml_key", "toml_value", "toml_quantity", "toml_table", "toml_comment", "toml_comments",
    "edit_toml",
]


def read_toml(path: str | Path, what: str, error: type[HydroservoError] = ParameterError) -> dict[str, Any]:
    """Parse a TOML file; an unreadable or malformed file raises ``error`` naming ``what`` and the path."""
    text = read_text(path, what, error)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{what} {str(path)!r}: malformed TOML: {exc}") from None
    except RecursionError:  # arrays or tables nested a thousand deep: the parser recurses once per level
        raise error(f"{what} {str(path)!r}: values nested too deep to read; expected a model file's few levels") from None


def _printable(quoted: str, text: str) -> str:
    """A basic string or quoted key tomlkit wrote, with what it leaves raw and is not printable (U+2028, U+0085,
    a byte-order mark) as a TOML escape; a text TOML cannot hold (a lone surrogate) is refused."""
    if quoted.isprintable():
        return quoted
    if any(0xD800 <= ord(ch) <= 0xDFFF for ch in text):
        raise ParameterError(f"text {shorten(text)!r}: holds a lone surrogate, which no file can hold; expected text")
    return "".join(
        ch if ch.isprintable() else (f"\\u{ord(ch):04X}" if ord(ch) <= 0xFFFF else f"\\U{ord(ch):08X}") for ch in quoted
    )


def toml_string(s: str) -> str:
    """A TOML basic string, escaped as TOML requires (quotes, backslashes, newlines and control characters) and
    every other character that is not printable escaped too (U+2028), so that it shows on one line.

    >>> print(toml_string('a"b\\n[c]\\u2028'))
    "a\\"b\\n[c]\\u2028"
    """
    import tomlkit

    return _printable(tomlkit.string(s).as_string(), s)


def toml_key(k: str) -> str:
    """A TOML key: bare when it can be, quoted (and escaped as :func:`toml_string` escapes) otherwise."""
    import tomlkit

    return _printable(tomlkit.key(k).as_string(), k)


def toml_comment(text: str) -> str:
    """A TOML comment of one line: ``# `` and ``text`` with every character that is not printable written as
    its escape (:func:`hydroservo.io.text.one_line`), so that nothing in it can end the comment.

    >>> print(toml_comment('Force\\n[initial]'))
    # Force\\n[initial]
    """
    return f"# {one_line(text)}"


def toml_comments(text: str) -> list[str]:
    """The lines of ``text`` as TOML comment lines (:func:`hydroservo.io.text.comment_lines`)."""
    return comment_lines(text, "#")


def toml_value(v: Any) -> str:
    """A TOML value: strings, booleans, numbers (floats at full precision), lists and inline tables."""
    return _item(v).as_string()


def _item(v: Any) -> Any:
    import tomlkit

    if isinstance(v, (str, bool)):
        return tomlkit.item(v)
    if isinstance(v, numbers.Integral):  # a count stays whole (a line's segments)
        return tomlkit.integer(int(v))
    if isinstance(v, numbers.Real):
        return tomlkit.float_(repr(float(v)))
    if isinstance(v, (list, tuple)):
        array = tomlkit.array()
        array.extend(_item(x) for x in v)
        return array
    if isinstance(v, Mapping):
        table = tomlkit.inline_table()
        for key, x in v.items():
            table[str(key)] = _item(x)
        return table
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
    lines = [f"[{toml_key(name)}]"]
    for key, text in entries.items():
        note = (comments or {}).get(key)
        lines.append(f"{toml_key(key)} = {text}" + (f"  {toml_comment(note)}" if note else ""))
    return lines


def edit_toml(
    text: str, changes: Mapping[tuple[str, ...], str | None], renames: Mapping[tuple[str, ...], str] | None = None
) -> str:
    """``text`` (a TOML document) with the values at each path of ``changes`` replaced by the TOML value text
    given (``{("components", "cyl", "A_A"): '"2 in^2"'}``), added at the end of their table if absent, or
    removed (None), and the keys at the paths of ``renames`` renamed where they stand (after the changes); every
    comment, the order and the layout of the rest are kept.

    >>> print(edit_toml('[load]  # the mass\\nm = "20 kg"  # loaded\\n', {("load", "m"): '"25 kg"'}), end="")
    [load]  # the mass
    m = "25 kg"  # loaded
    """
    import tomlkit

    doc = tomlkit.parse(text)
    for path, value in changes.items():
        table: Any = doc
        for key in path[:-1]:
            if key not in table:
                table[key] = tomlkit.table()
            table = table[key]
        if value is None:
            if path[-1] in table:
                del table[path[-1]]
        else:
            table[path[-1]] = tomlkit.value(value)
    for path, name in (renames or {}).items():
        table = doc
        for key in path[:-1]:
            table = table[key]
        container = getattr(table, "value", table)
        try:  # in place, with its comment (tomlkit's container has no public rename)
            container._replace(path[-1], name, table[path[-1]])
        except (AttributeError, KeyError):
            table[name] = table.pop(path[-1])
    return tomlkit.dumps(doc)
