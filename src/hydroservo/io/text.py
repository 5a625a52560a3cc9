"""Plain text: tables as reports print them in a terminal, laid out by tabulate, the one place columns are
aligned (numbers on their decimal point, text to the left, a missing value as ``-``); and text that must stay on
one line of a file we write (a comment of a model file or a CSV), whatever it holds (:func:`one_line`,
:func:`comment_lines`).

>>> print("\\n".join(text_table([["cyl.pA", 6.78e6, "Pa"], ["load.x", -0.18285, "m"]], ["signal", "final", "unit"])))
signal        final  unit
--------  ---------  ------
cyl.pA    6.78e+06   Pa
load.x     -0.18285  m
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["text_table", "one_line", "comment_lines", "xml_text"]


def text_table(
    rows: Sequence[Sequence[Any]],
    header: Sequence[str] = (),
    *,
    indent: int = 0,
    digits: int | str | Sequence[int | str] = 5,
    align: Sequence[str] | None = None,
) -> list[str]:
    """The lines of a table of ``rows`` under ``header`` (none: no header line), each indented by ``indent``
    spaces. Numbers get ``digits`` significant digits: one count for all columns, or one per column (a count or a
    format such as ``".2f"``). None and NaN (no number) are shown as ``-``, -0 as 0. ``align`` gives each column's
    alignment (``"left"``, ``"right"``, ``"decimal"``, ``"center"``; default: numbers on their decimal point, text
    left)."""
    import math

    from tabulate import tabulate

    ncols = max([len(header), *(len(r) for r in rows)], default=0)
    floatfmt: str | list[str]
    if isinstance(digits, str):
        floatfmt = digits
    elif isinstance(digits, int):
        floatfmt = f".{digits}g"
    else:
        floatfmt = [d if isinstance(d, str) else f".{d}g" for d in digits] + [".5g"] * (ncols - len(digits))
    formats = floatfmt if isinstance(floatfmt, list) else [floatfmt] * ncols

    def cell(value: Any, fmt: str) -> Any:
        if isinstance(value, float) and not isinstance(value, bool):
            if math.isnan(value):
                return None  # shown as the missing value: no number
            if fmt.endswith("f"):  # fixed decimals: what rounds to zero is 0, not -0.000
                value = round(value, int(fmt[1:-1] or 6))
            return value + 0.0  # -0.0 shown as 0
        return value

    rows = [[cell(v, formats[k] if k < len(formats) else ".5g") for k, v in enumerate(row)] for row in rows]
    text = tabulate(
        [list(r) for r in rows],
        list(header) if header else (),
        tablefmt="simple",
        floatfmt=floatfmt,
        missingval="-",
        colalign=list(align) if align is not None else None,
    )
    pad = " " * indent
    return [(pad + line).rstrip() for line in text.splitlines()]


def one_line(text: str) -> str:
    """``text`` as one line of printable characters: each character that is not printable (a line break, a
    carriage return, a tab, a control character, U+2028, a lone surrogate) written as its escape, ``\\n``,
    ``\\x00``, ``\\u2028``, so that a name or a path in a comment can neither end the comment nor make the
    file unreadable. Every comment hydroservo writes into a file puts its text through this.

    >>> print(one_line('Force\\n[initial]\\r\\x00 \\u2028ok'))
    Force\\n[initial]\\r\\x00 \\u2028ok
    """
    return _escaped(text, lambda ch: not ch.isprintable())


def _escaped(text: str, bad: Callable[[str], bool]) -> str:
    """``text`` with each character ``bad`` says it cannot hold written as its Python escape (``\\x00``)."""
    if not any(bad(ch) for ch in text):
        return text
    return "".join(repr(ch)[1:-1] if bad(ch) else ch for ch in text)


def comment_lines(text: str, mark: str = "#") -> list[str]:
    """The lines of ``text`` as comment lines of a file (TOML, CSV): each ``mark`` and a space, then the line
    with every character that is not printable escaped (:func:`one_line`); an empty line is ``mark`` alone.

    >>> comment_lines('made from "a\\nb.hmf"\\n\\nsecond')
    ['# made from "a', '# b.hmf"', '#', '# second']
    """
    return [f"{mark} {one_line(line)}".rstrip() if line.strip() else mark for line in text.splitlines()]


def _xml_forbidden(ch: str) -> bool:
    code = ord(ch)
    return (code < 0x20 and ch not in "\t\n\r") or 0xD800 <= code <= 0xDFFF or code in (0xFFFE, 0xFFFF)


def xml_text(text: str) -> str:
    """``text`` as an XML 1.0 document can hold it (an attribute's value, an element's text): the characters XML
    forbids even as references (control characters other than tab, line feed and carriage return, lone
    surrogates, U+FFFE, U+FFFF) written as their escapes (``\\x00``); the XML writer (ElementTree) escapes the
    rest (``&``, ``<``, quotes, line breaks in attributes). Every name and description in an FMU's
    modelDescription.xml goes through this.

    >>> xml_text('a\\x00b\\nc<d>')
    'a\\\\x00b\\nc<d>'
    """
    return _escaped(text, _xml_forbidden)
