"""Measured curves (CSV, ``name [unit]`` headers): static valve curves and test-bench curves.

Measured static curves of a pseudo-section valve: ``x_s [-]``, ``P_L [-]`` and
``q_lk [L/min]`` (blocked ports, at the datasheet's P_s), and optionally
``Q_L [L/min]`` (connected ports, P_n per edge). Empty cells are allowed.

Test-bench curves of a staged-slot spool valve (one or more files at one
temperature), as ``hydroservo valve characteristics --out`` writes them and
``hydroservo valve identify`` reads them: a column ``X`` (opening, a length)
and any of ``Q_L`` (flow gain, ports connected), ``P_1``, ``P_2`` (ports
blocked) and ``Q_lk`` (leakage, ports blocked), with the test conditions in
comment lines::

    # temperature = -15 degC
    # P_s = 3000 psi
    # P_r = 0 bar
    # X_n = 0.4 mm
    X [um], P_1 [bar], P_2 [bar], Q_lk [L/min]
    -25.0, 0.012, 206.8, 0.0101
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from hydroservo.analysis.static_bench import Bench, BenchCurves
from hydroservo.errors import ParameterError, shorten
from hydroservo.io.files import csv_rows, plain_float, read_text
from hydroservo.units import from_si, to_si

__all__ = [
    "read_csv_table", "read_static_curves", "read_bench_curves", "write_bench_curves", "write_bench_table", "bench_tables",
    "BENCH_TABLES",
]

_CURVE_COLUMNS = {"x_s": "", "P_L": "", "q_lk": "m^3/s", "Q_L": "m^3/s"}


def read_csv_table(
    path: str | Path, columns: Mapping[str, str], what: str = "curves file"
) -> tuple[dict[str, np.ndarray], dict[str, str]]:
    """Columns ``name [unit]`` of a CSV file in SI, and its ``# key = value`` comment lines.

    ``columns`` maps the known column names to their SI unit ("" dimensionless);
    other columns are ignored; a dimensional column without a unit, or a cell
    that is not a number, is an error naming the file, row and column. Empty
    cells become NaN.
    """
    path = Path(path)
    where = f"{what} {str(path)!r}"
    lines = [line for line in read_text(path, what, kind="table").splitlines() if line.strip()]
    meta: dict[str, str] = {}
    for line in lines:
        if line.startswith("#") and "=" in line:
            key, _, value = line[1:].partition("=")
            meta[key.strip()] = value.split("#")[0].strip()
    rows = csv_rows("\n".join(lines), where)
    if len(rows) < 2:
        raise ParameterError(f"{where}: expected a header and data rows")
    cols: dict[str, tuple[int, str]] = {}
    for i, head in enumerate(rows[0]):
        name = head.split("[")[0].strip()
        unit = head.split("[")[1].split("]")[0].strip() if "[" in head else None
        if name in columns:
            if unit is None and columns[name]:
                raise ParameterError(
                    f"{where}, column {head.strip()!r}: expected a unit in brackets, e.g. '{name} [{columns[name]}]'"
                )
            cols[name] = (i, unit or "")
    out: dict[str, np.ndarray] = {}
    for name, (i, unit) in cols.items():
        vals = []
        for lineno, row in enumerate(rows[1:], start=2):
            cell = row[i].strip() if i < len(row) else ""
            try:
                number = plain_float(cell) if cell else np.nan
            except ValueError:
                raise ParameterError(f"{where}, row {lineno}, column {name}: {shorten(cell)!r} is not a number") from None
            if cell and not np.isfinite(number):
                raise ParameterError(
                    f"{where}, row {lineno}, column {name}: {cell!r}; expected a finite number "
                    "(leave the cell empty for a missing value)"
                )
            vals.append(number)
        scale = 1.0 if unit in ("", "-") else to_si(f"1 {unit}", columns[name], what=f"{where}, column {name}")
        out[name] = np.array(vals) * scale
    return out, meta


#: Fewest points of a curve that a fit can use.
MIN_POINTS = 3


def _check_curves(where: str, x: np.ndarray, curves: Mapping[str, np.ndarray], name: str) -> None:
    """Refuse a row that has a curve value but no abscissa (the point could not be placed), and a curve
    of fewer than :data:`MIN_POINTS` points."""
    for c, values in curves.items():
        orphan = np.isfinite(values) & ~np.isfinite(x)
        if orphan.any():
            row = int(np.argmax(orphan)) + 2
            raise ParameterError(f"{where}, row {row}: a value of {c} but no {name}; expected {name} in every row")
        count = int(np.sum(np.isfinite(values) & np.isfinite(x)))
        if count < MIN_POINTS:
            raise ParameterError(f"{where}: {count} point(s) of {c}; expected at least {MIN_POINTS}")


def read_static_curves(path: str | Path) -> dict[str, np.ndarray]:
    """Measured static curves (CSV with ``name [unit]`` headers), values in SI; see the module docstring."""
    out, _ = read_csv_table(path, _CURVE_COLUMNS)
    missing = [c for c in ("x_s", "P_L", "q_lk") if c not in out]
    if missing:
        raise ParameterError(
            f"curves file {str(path)!r}: missing column(s) {', '.join(missing)}; expected 'x_s [-], P_L [-], "
            "q_lk [L/min]' and optionally 'Q_L [L/min]'"
        )
    _check_curves(f"curves file {str(path)!r}", out["x_s"], {k: v for k, v in out.items() if k != "x_s"}, "x_s")
    if np.any(out["q_lk"][np.isfinite(out["q_lk"])] < 0):
        raise ParameterError(f"curves file {str(path)!r}: negative leakage flow in q_lk; expected >= 0")
    if np.any(np.abs(out["x_s"][np.isfinite(out["x_s"])]) > 1):
        raise ParameterError(f"curves file {str(path)!r}: x_s outside [-1, 1]; expected the normalised spool position")
    return out


_BENCH_COLUMNS = {"X": "m", "Q_L": "m^3/s", "P_1": "Pa", "P_2": "Pa", "Q_lk": "m^3/s"}
_BENCH_META = {"temperature": "degC", "P_s": "Pa", "P_r": "Pa", "X_n": "m", "Q_n": "m^3/s"}


def read_bench_curves(paths: Sequence[str | Path]) -> BenchCurves:
    """Test-bench curves at one temperature from one or more CSV files (module docstring), SI."""
    if not paths:
        raise ParameterError("bench curves: no file given")
    meta: dict[str, tuple[float, str]] = {}
    arrays: dict[str, np.ndarray] = {}
    for path in paths:
        where = f"curves file {str(path)!r}"
        cols, head = read_csv_table(path, _BENCH_COLUMNS)
        for key, unit in _BENCH_META.items():
            if key in head:
                value = to_si(head[key], unit, what=f"{where}, {key}")
                if key in meta and not np.isclose(meta[key][0], value, rtol=1e-9, atol=1e-12):
                    raise ParameterError(
                        f"{where}: {key} = {head[key]} differs from {meta[key][1]}'s; "
                        "expected curves at one temperature and one bench"
                    )
                meta[key] = (value, str(path))
        tests = [c for c in ("Q_L", "P_1", "P_2", "Q_lk") if c in cols]
        if "X" not in cols or not tests:
            raise ParameterError(
                f"{where}: expected a column 'X [um]' (or another length unit) and at least one of "
                "'Q_L [L/min]', 'P_1 [bar]', 'P_2 [bar]', 'Q_lk [L/min]'"
            )
        if ("P_1" in cols) != ("P_2" in cols):
            raise ParameterError(f"{where}: expected both P_1 and P_2 (the pressure-gain test), or neither")
        _check_curves(where, cols["X"], {c: cols[c] for c in tests}, "X")
        for c in tests:
            if c in arrays:
                raise ParameterError(f"{where}: column {c} is also in another file; expected each curve once")
            arrays[c] = cols[c]
            arrays["X_" + c] = cols["X"]
    for key in ("temperature", "P_s", "X_n"):
        if key not in meta:
            raise ParameterError(
                f"bench curves {', '.join(map(str, paths))}: missing '# {key} = ...' "
                "(expected the temperature, P_s and X_n in comment lines)"
            )
    if "Q_lk" in arrays and np.any(arrays["Q_lk"][np.isfinite(arrays["Q_lk"])] < 0):
        raise ParameterError("bench curves: negative leakage flow in Q_lk; expected >= 0")
    bench = Bench(
        P_s=meta["P_s"][0],
        X_n=meta["X_n"][0],
        P_r=meta.get("P_r", (0.0, ""))[0],
        Q_n=meta["Q_n"][0] if "Q_n" in meta else None,
    )
    return BenchCurves(
        meta["temperature"][0],
        bench,
        arrays.get("X_Q_L"),
        arrays.get("Q_L"),
        arrays.get("X_P_1"),
        arrays.get("P_1"),
        arrays.get("P_2"),
        arrays.get("X_Q_lk"),
        arrays.get("Q_lk"),
    )


#: The tables of test-bench curves a folder holds: name -> (openings' attribute, columns and their attributes).
BENCH_TABLES: dict[str, tuple[str, dict[str, str]]] = {
    "flow_gain": ("X_flow", {"Q_L [L/min]": "Q_L"}),
    "blocked_ports": ("X_blocked", {"P_1 [bar]": "P_1", "P_2 [bar]": "P_2", "Q_lk [L/min]": "Q_lk"}),
}


def bench_tables(curves: BenchCurves) -> list[str]:
    """The names of the tables of :data:`BENCH_TABLES` that ``curves`` holds (a test may be absent)."""
    return [
        name for name, (x, cols) in BENCH_TABLES.items()
        if getattr(curves, x) is not None and any(getattr(curves, c) is not None for c in cols.values())
    ]


def write_bench_table(curves: BenchCurves, name: str, path: str | Path) -> Path:
    """Write table ``name`` of :data:`BENCH_TABLES` of ``curves`` as CSV (um, L/min, bar) to ``path``."""
    from hydroservo.io.results import write_table

    b = curves.bench
    head = [
        f"# temperature = {curves.temperature!r} degC",
        f"# P_s = {from_si(b.P_s, 'Pa', 'bar')!r} bar",
        f"# P_r = {from_si(b.P_r, 'Pa', 'bar')!r} bar",
        f"# X_n = {from_si(b.X_n, 'm', 'mm')!r} mm",
    ]
    if b.Q_n is not None:
        head.append(f"# Q_n = {from_si(b.Q_n, 'm^3/s', 'L/min')!r} L/min")
    x_name, columns = BENCH_TABLES[name]
    X = getattr(curves, x_name)
    cols = {k: getattr(curves, attr) for k, attr in columns.items() if getattr(curves, attr) is not None}
    scale = {"L/min": from_si(1.0, "m^3/s", "L/min"), "bar": 1e-5}
    data = [np.asarray(X) * 1e6] + [np.asarray(v) * scale[k.split("[")[1][:-1]] for k, v in cols.items()]
    return write_table(path, ["X [um]", *cols], zip(*data, strict=True), [line.removeprefix("# ") for line in head])


def write_bench_curves(curves: BenchCurves, folder: str | Path, stem: str = "") -> list[Path]:
    """Write ``curves`` as ``{stem}flow_gain.csv`` and ``{stem}blocked_ports.csv`` (um, L/min, bar); the paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    return [write_bench_table(curves, name, folder / f"{stem}{name}.csv") for name in bench_tables(curves)]
