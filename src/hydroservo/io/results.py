"""Result files: CSV with the units in the column headers, MATLAB .mat files."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from hydroservo.units import si_unit

if TYPE_CHECKING:
    import numpy as np

__all__ = ["write_csv", "write_mat", "read_csv"]


class Result(Protocol):
    """What the writers read of a result (:class:`hydroservo.system.Result` is one)."""

    t: np.ndarray
    units: dict[str, str]

    @property
    def data(self) -> dict[str, np.ndarray]: ...


def write_csv(result: Result, path: str | Path) -> Path:
    """Write ``result`` as CSV: a time column ``t [s]``, then one column ``signal [unit]`` per signal (SI).

    Ten significant digits; written by NumPy, so that a command-line run does
    not load pandas (``pandas.read_csv`` reads it back, ``nan`` as NaN).
    """
    import csv

    import numpy as np

    path = Path(path)
    data = result.data
    header = ["t [s]", *(f"{n} [{si_unit(result.units.get(n, ''))}]" for n in data)]
    with path.open("w", encoding="utf-8", newline="") as f:
        csv.writer(f, lineterminator="\n").writerow(header)
        np.savetxt(f, np.column_stack([result.t, *data.values()]), fmt="%.10g", delimiter=",")
    return path


def write_mat(result: Result, path: str | Path) -> Path:
    """Write ``result`` as a MATLAB .mat file: one variable per signal (dots become underscores), ``t`` and ``units``."""
    from scipy.io import savemat

    path = Path(path)
    content: dict[str, Any] = {"t": result.t}
    units = {}
    for n, v in result.data.items():
        key = n.replace(".", "_")
        content[key] = v
        units[key] = si_unit(result.units.get(n, ""))
    content["units"] = units
    savemat(path, content)
    return path


_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⋅", "0123456789-.")


def parseable_unit(printed: str) -> str:
    """A unit as :func:`hydroservo.units.si_unit` prints it (``m³/Pa⁰⋅⁵/s``, ``m·N``, ``-``) in the form the
    unit parser reads (``m^3/Pa^0.5/s``, ``m*N``, ``""``).

    >>> parseable_unit("m³/Pa⁰⋅⁵/s"), parseable_unit("m·N"), parseable_unit("-"), parseable_unit("kg/m^3")
    ('m^3/Pa^0.5/s', 'm*N', '', 'kg/m^3')
    """
    import re

    text = printed.strip()
    if text in ("-", ""):
        return ""
    text = re.sub(r"[⁰¹²³⁴⁵⁶⁷⁸⁹⁻⋅]+", lambda m: "^" + m.group(0).translate(_SUPERSCRIPTS), text)
    return text.replace("·", "*")


def read_csv(path: str | Path, model: str | None = None) -> Any:
    """A result read back from a CSV with a time column ``t [s]`` and columns ``signal [unit]`` (SI), as
    :func:`write_csv` writes it (or a rig's record in that form): a :class:`hydroservo.system.result.Result`.

    Empty cells and ``nan`` are NaN. ``model`` names the result (default: the file's name).
    """
    import csv
    import io

    import numpy as np

    from hydroservo.errors import ParameterError
    from hydroservo.io.files import read_text
    from hydroservo.system.result import Result as RunResult

    path = Path(path)
    text = read_text(path, "result file")
    rows = list(csv.reader(io.StringIO(text)))
    if len(rows) < 3:
        raise ParameterError(f"result file {str(path)!r}: {max(len(rows) - 1, 0)} row(s); expected a header and at "
                             "least two times")
    header = [h.strip() for h in rows[0]]
    names, units = [], []
    for h in header:
        if not (h.endswith("]") and " [" in h):
            raise ParameterError(f"result file {str(path)!r}: column {h!r}: expected 'name [unit]', e.g. 'cyl.pA [Pa]'")
        name, unit = h[:-1].split(" [", 1)
        names.append(name.strip())
        units.append(parseable_unit(unit))
    if names[0] not in ("t", "time") or units[0] != "s":
        raise ParameterError(f"result file {str(path)!r}: first column {header[0]!r}: expected the time, 't [s]'")
    try:
        values = np.array([[float(c) if c.strip() else np.nan for c in r] for r in rows[1:] if r], dtype=float)
    except ValueError as exc:
        raise ParameterError(f"result file {str(path)!r}: {exc}; expected numbers") from None
    if values.ndim != 2 or values.shape[1] != len(names):
        raise ParameterError(f"result file {str(path)!r}: every row needs {len(names)} cells, as the header")
    t = values[:, 0]
    if not np.all(np.diff(t) > 0):
        raise ParameterError(f"result file {str(path)!r}: the time column must increase from row to row")
    data = {n: values[:, i] for i, n in enumerate(names) if i}
    return RunResult(t, data, dict(zip(names[1:], units[1:])), {}, {}, {}, model or path.stem)
