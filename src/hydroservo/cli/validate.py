"""``hydroservo validate``: published figures beside computed ones, one table per source."""

from __future__ import annotations

import argparse
import json
from typing import Any

__all__ = ["add_parsers"]


def cmd_validate(args: argparse.Namespace) -> int:
    from hydroservo.validation import VALIDATIONS, format_checks, markdown, regressions, validate

    names = [args.model] if args.model else list(VALIDATIONS)
    report = {}
    failed = []
    for name in names:
        checks = validate(name)
        report[name] = [c.as_dict() for c in checks]
        failed += [f"{name}: {c.row.quantity}" for c in regressions(checks)]
        if args.markdown:
            print(f"<!-- validation: {name} -->\n{markdown(checks)}\n<!-- end validation: {name} -->\n")
        elif not args.json:
            print(format_checks(name, checks))
    if args.json:
        print(json.dumps(report, indent=2))
    return 1 if failed else 0


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
