"""``hydroservo components`` and ``describe``: the component reference (thin shell over
:mod:`hydroservo.components.reference`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import print_json

__all__ = ["add_parsers"]


def cmd_components(args: argparse.Namespace) -> int:
    from hydroservo.components.reference import catalogue

    refs = catalogue()
    if args.json:
        print_json([{"name": r.name, "kind": r.kind, "summary": r.summary} for r in refs])
        return 0
    width = max(len(r.name) for r in refs)
    kind = None
    for r in refs:
        group = r.kind.split(".")[0]
        if group != kind:
            print(f"{'' if kind is None else chr(10)}{group}:")
            kind = group
        print(f"  {r.name.ljust(width)}  {r.summary}")
    print("\nhydroservo describe TYPE: equations, parameters, ports and options of one")
    return 0


def cmd_describe(args: argparse.Namespace) -> int:
    from hydroservo.components.reference import reference, text

    ref = reference(args.type)
    if args.json:
        print_json(ref.to_dict())
        return 0
    print(text(ref), end="")
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
