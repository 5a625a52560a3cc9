"""Published figures beside computed ones, one table per source (``hydroservo validate``).

>>> from hydroservo.workflows import validate
>>> report = validate.run("robot-arm-friction")
>>> report.exit_code(), report.lines()[0]
(0, "validation of 'robot-arm-friction'")
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

from hydroservo.workflows.base import Progress, Report, Workflow

if TYPE_CHECKING:
    from hydroservo.io.html import Page
    from hydroservo.validation import Check

__all__ = ["Validate", "ValidationReport", "run"]


@dataclass
class ValidationReport(Report):
    """The checks of each validation (:mod:`hydroservo.validation`): row, computed value, verdict."""

    command: ClassVar[str] = "validate"

    checks: dict[str, list[Check]] = field(default_factory=dict)

    def title(self) -> str:
        return "validation of " + ", ".join(repr(n) for n in self.checks)

    def failed(self) -> list[str]:
        """The rows whose verdict differs from the expected one (``validation: quantity``)."""
        from hydroservo.validation import regressions

        return [f"{name}: {c.row.quantity}" for name, checks in self.checks.items() for c in regressions(checks)]

    def exit_code(self) -> int:
        """1 when a verdict differs from the expected one (a regression, or an improvement to record)."""
        return 1 if self.failed() else 0

    def lines(self) -> list[str]:
        from hydroservo.validation import format_checks

        return [line for name, checks in self.checks.items() for line in format_checks(name, checks).splitlines()]

    def markdown(self) -> str:
        """The tables of docs/validation.md, each between its markers."""
        from hydroservo.validation import markdown

        return "\n".join(
            f"<!-- validation: {name} -->\n{markdown(checks)}\n<!-- end validation: {name} -->\n"
            for name, checks in self.checks.items()
        )

    def to_dict(self) -> dict[str, Any]:
        return {name: [c.as_dict() for c in checks] for name, checks in self.checks.items()}

    def document(self) -> Page:
        from hydroservo.io.html import Notice, Page, Section, Table
        from hydroservo.validation import VALIDATIONS
        from hydroservo.workflows.base import footer

        sections = []
        for name, checks in self.checks.items():
            rows = []
            for c in checks:
                r = c.row
                rows.append([r.quantity, r.source, r.published, c.computed, r.tolerance, r.unit, c.verdict, r.why])
            items: list[Any] = [Table(["quantity", "source", "published", "computed", "tolerance", "unit", "verdict",
                                       "why this tolerance"], rows)]
            for c in checks:
                if c.regression:
                    items.append(Notice(f"{c.row.quantity}: {c.verdict}, expected {c.row.expected}", "error"))
            sections.append(Section(f"{name}: {VALIDATIONS[name][1]}", items))
        return Page(self.title(), "published figures beside computed ones", sections, footer())


@dataclass
class Validate(Workflow):
    """Compute the rows of ``names`` (default: every validation of :data:`hydroservo.validation.VALIDATIONS`)."""

    names: list[str] | str | None = None

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> ValidationReport:
        from hydroservo.validation import VALIDATIONS, validate

        names = [self.names] if isinstance(self.names, str) else list(self.names or VALIDATIONS)
        checks = {}
        for name in names:
            if progress is not None:
                progress(f"validating {name}")
            checks[name] = validate(name)
        return ValidationReport(checks)


def run(names: list[str] | str | None = None) -> ValidationReport:
    """The validation report of ``names`` (default all)."""
    return Validate(names).run()
