"""``hydroservo components`` and ``describe``: the component reference (:mod:`hydroservo.workflows.components`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import execute

__all__ = ["add_parsers"]


def cmd_components(args: argparse.Namespace) -> int:
    from hydroservo.workflows.components import Catalogue

    return execute(Catalogue(cli=True), args)


def cmd_describe(args: argparse.Namespace) -> int:
    from hydroservo.workflows.components import Describe

    report = Describe(args.type, cli=True).run()
    if args.json:
        print(report.to_json())
    else:
        print(report.text(), end="")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``components`` and ``describe``."""
    p = sub.add_parser("components", help="list every component type, by kind")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_components)
    p = sub.add_parser("describe", help="a component type's equations, parameters (unit, default, range), ports, options")
    p.add_argument("type", metavar="TYPE", help="a component type, e.g. Cylinder (see hydroservo components)")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_describe)
