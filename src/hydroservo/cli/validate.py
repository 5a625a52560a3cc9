"""``hydroservo validate``: published figures beside computed ones, one table per source
(:mod:`hydroservo.workflows.validate`)."""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["add_parsers"]


def cmd_validate(args: argparse.Namespace) -> int:
    from hydroservo.workflows.validate import Validate

    report = Validate(args.model, cli=True).run()
    if args.markdown:
        print(report.markdown())
    else:
        print(report.to_json() if args.json else str(report))
    return report.exit_code()


def add_parsers(sub: Any) -> None:
    """Add ``validate``."""
    p = sub.add_parser(
        "validate",
        help="compare built-in models and laws with their published figures "
        "(exit 1 if a verdict differs from the expected one)",
    )
    p.add_argument("model", nargs="?", metavar="NAME", help="one validation (default: all)")
    p.add_argument("--json", action="store_true")
    p.add_argument("--markdown", action="store_true", help="print the tables of docs/validation.md")
    p.set_defaults(func=cmd_validate)
