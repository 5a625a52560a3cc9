"""Plain-text tables, as reports print them in a terminal: laid out by tabulate, the one place columns are
aligned (numbers on their decimal point, text to the left, a missing value as ``-``).

>>> print("\\n".join(text_table([["cyl.pA", 6.78e6, "Pa"], ["load.x", -0.18285, "m"]], ["signal", "final", "unit"])))
signal        final  unit
--------  ---------  ------
cyl.pA    6.78e+06   Pa
load.x     -0.18285  m
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

__all__ = ["text_table"]


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
