"""``hydroservo examples DIR``: write the example files the README's commands use, and a Hopsan model file to try
``import-hopsan`` on (:mod:`hydroservo.workflows.examples`)."""

from __future__ import annotations

import argparse
from typing import Any

__all__ = ["add_parsers"]


def cmd_examples(args: argparse.Namespace) -> int:
    from hydroservo.workflows.base import output_folder
    from hydroservo.workflows.examples import Examples

    report = Examples(cli=True).run()
    report.write(output_folder(args.dir, args.dir, force=args.force, what="examples"))
    print(report)
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``examples``."""
    p = sub.add_parser(
        "examples", help="write the example model, datasheet and curve files the README uses, and a Hopsan model to import"
    )
    p.add_argument("dir", metavar="DIR", help="folder to write them to (created if missing)")
    p.add_argument("--force", action="store_true", help="replace files of the same names")
    p.set_defaults(func=cmd_examples)
