"""Validation against published figures: one table of rows per source document.

Each published figure is a :class:`Row`: the quantity, where the source
prints it, the published value, the tolerance and why, how hydroservo
computes it, and the verdict expected today (``reproduced``,
``NOT reproduced`` or ``info``). A module per source computes every row's
figure with small functions and never adjusts a parameter to hit a figure.
``hydroservo validate`` prints the rows beside the computed values and exits
with code 1 when a verdict differs from the expected one (a regression, or an
improvement to record); ``docs/validation.md`` holds the same tables
(:func:`markdown`), and a test keeps the two equal.

=============================  ==================  =======================================
validation                     source              module
=============================  ==================  =======================================
``flight-simulator``           FlightSimulatorND   :mod:`.flight_simulator`
``servo-solenoid-cylinder``    FerreiraND          :mod:`.ferreira`
``robot-arm-friction``         Efe2014             :mod:`.efe`
``skydrol-fluid``              MareAttarND         :mod:`.mare_attar`
``position-servo``             Hopsan2026          :mod:`.hopsan`
``hopsan-examples``            Hopsan2026          :mod:`.hopsan_examples`
``two-stage-servovalve``       GordicND            :mod:`.gordic`
=============================  ==================  =======================================
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from typing import Any

from hydroservo.errors import ModelError

__all__ = [
    "Row",
    "Check",
    "VALIDATIONS",
    "validate",
    "regressions",
    "format_checks",
    "markdown",
    "printed_digit",
]

VERDICTS = ("reproduced", "NOT reproduced", "info")


@dataclass(frozen=True)
class Row:
    """One published figure: what it is, where it is printed, and how hydroservo checks it.

    ``key`` names the computed value in the dictionary the module's ``compute``
    returns. ``tolerance`` is absolute, in ``unit``; None (with ``published``
    None or not) makes the row information only. ``upper_bound``: the published
    value is a bound the computed one must not exceed.
    """

    key: str
    quantity: str
    source: str
    published: float | None
    unit: str
    tolerance: float | None
    why: str
    method: str
    expected: str
    upper_bound: bool = False

    def __post_init__(self) -> None:
        if self.expected not in VERDICTS:
            raise ValueError(f"row {self.key!r}: expected verdict {self.expected!r} is not one of {VERDICTS}")


@dataclass(frozen=True)
class Check:
    """A row with its computed value."""

    row: Row
    computed: float

    @property
    def verdict(self) -> str:
        r = self.row
        if r.published is None or r.tolerance is None:
            return "info"
        if not math.isfinite(self.computed):
            return "NOT reproduced"
        if r.upper_bound:
            ok = self.computed <= r.published + r.tolerance
        else:
            ok = abs(self.computed - r.published) <= r.tolerance
        return "reproduced" if ok else "NOT reproduced"

    @property
    def regression(self) -> bool:
        """True when the verdict differs from the one the row expects."""
        return self.verdict != self.row.expected

    # The attributes of a row, read through the check (the fields of ``hydroservo validate --json``).
    def __getattr__(self, name: str) -> Any:
        if name in Row.__dataclass_fields__:
            return getattr(self.row, name)
        raise AttributeError(name)

    def as_dict(self) -> dict[str, Any]:
        r = asdict(self.row)
        note = r.pop("why")
        return {
            "quantity": r["quantity"],
            "source": r["source"],
            "published": r["published"],
            "computed": self.computed,
            "unit": r["unit"],
            "tolerance": r["tolerance"],
            "method": r["method"],
            "note": note,
            "upper_bound": r["upper_bound"],
            "verdict": self.verdict,
            "expected": r["expected"],
            "regression": self.regression,
        }


def printed_digit(text: str) -> float:
    """One unit in the last digit of a number printed as ``text`` (the tolerance of a printed value).

    >>> printed_digit("0.1149 L/min/bar^0.5"), printed_digit("-5.554e-2 (L/min)^2/bar"), printed_digit("36.5")
    (0.0001, 1e-05, 0.1)
    """
    number = text.strip().split()[0].lower()
    mant, _, exp = number.partition("e")
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return float(f"1e{(int(exp) if exp else 0) - decimals}")


#: name -> (module, one line: what and which source)
VALIDATIONS: dict[str, tuple[str, str]] = {
    "flight-simulator": ("flight_simulator", "the closed-loop flight-simulator actuator (FlightSimulatorND)"),
    "servo-solenoid-cylinder": ("ferreira", "the KBSDG4V-3 servo-solenoid valve (FerreiraND)"),
    "robot-arm-friction": ("efe", "Stribeck friction of the robot-arm cylinder (Efe2014 Table 5.2)"),
    "skydrol-fluid": ("mare_attar", "Skydrol properties against pressure and temperature (MareAttarND 2.1)"),
    "position-servo": ("hopsan", "Hopsan's Position Servo example against its converged result (Hopsan2026)"),
    "hopsan-examples": (
        "hopsan_examples",
        "Hopsan's example and component-test models, imported, against Hopsan's converged results (Hopsan2026)",
    ),
    "two-stage-servovalve": ("gordic", "the first-principles two-stage servovalve's constants (GordicND Table 1)"),
}


def _module(name: str) -> Any:
    if name not in VALIDATIONS:
        raise ModelError(f"no validation {name!r}; available: {', '.join(VALIDATIONS)}")
    return importlib.import_module(f"hydroservo.validation.{VALIDATIONS[name][0]}")


def rows(name: str) -> list[Row]:
    """The rows of validation ``name``."""
    return list(_module(name).rows())


def validate(name: str) -> list[Check]:
    """Compute every row of validation ``name``."""
    module = _module(name)
    table: list[Row] = list(module.rows())
    values: Mapping[str, float] = module.compute()
    missing = [r.key for r in table if r.key not in values]
    if missing:  # pragma: no cover - a module's rows and its computations are written together
        raise RuntimeError(f"validation {name!r} computed no value for {', '.join(missing)}")
    return [Check(r, float(values[r.key])) for r in table]


def regressions(checks: list[Check]) -> list[Check]:
    """The checks whose verdict differs from the one their row expects."""
    return [c for c in checks if c.regression]


def _fmt(v: float | None) -> str:
    return "-" if v is None else f"{v:.4g}"


def format_checks(name: str, checks: list[Check]) -> str:
    """Plain-text table: quantity, published, computed, tolerance, unit, verdict."""
    from hydroservo.io.text import text_table

    table = []
    for c in checks:
        r = c.row
        pub = ("≤ " if r.upper_bound else "") + _fmt(r.published)
        tol = "-" if r.tolerance is None else ("upper bound" if r.upper_bound else f"±{_fmt(r.tolerance)}")
        verdict = c.verdict + (f" (expected {r.expected})" if c.regression else "")
        table.append((r.quantity, pub, _fmt(c.computed), tol, r.unit, verdict))
    lines = [f"validation of {name!r}"]
    lines += text_table(table, ["quantity", "published", "computed", "tolerance", "unit", "verdict"],
                        align=["left"] * 6)
    n_ok = sum(c.verdict == "reproduced" for c in checks)
    n_no = sum(c.verdict == "NOT reproduced" for c in checks)
    bad = regressions(checks)
    known = n_no - sum(c.verdict == "NOT reproduced" for c in bad)
    lines.append(
        f"{n_ok} reproduced, {n_no} not reproduced, {len(checks) - n_ok - n_no} for information (docs/validation.md)"
        + (f"; the {known} not reproduced are known, and docs/validation.md ({name!r}) says why for each" if known else "")
    )
    if bad:
        lines.append(f"{len(bad)} verdict(s) differ from the expected ones: {', '.join(c.row.quantity for c in bad)}")
    return "\n".join(lines)


def markdown(checks: list[Check]) -> str:
    """The rows as the Markdown table of ``docs/validation.md``."""
    lines = [
        "| quantity | source | published | computed | tolerance | verdict | why this tolerance; how computed |",
        "|---|---|---|---|---|---|---|",
    ]
    for c in checks:
        r = c.row
        unit = "" if r.unit in ("", "-") else f" {r.unit}"
        pub = "–" if r.published is None else ("≤ " if r.upper_bound else "") + f"{r.published:.4g}{unit}"
        tol = "–" if r.tolerance is None else ("upper bound" if r.upper_bound else f"±{r.tolerance:.3g}{unit}")
        verdict = {"reproduced": "reproduced", "NOT reproduced": "**not reproduced**", "info": "information"}[
            c.verdict
        ]
        lines.append(
            f"| {r.quantity} | {r.source} | {pub} | {c.computed:.4g}{unit} | {tol} | {verdict} | {r.why}; {r.method} |"
        )
    return "\n".join(lines)

