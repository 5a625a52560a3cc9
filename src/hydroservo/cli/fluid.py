"""``hydroservo fluid``: quick look-ups of fluid properties (:mod:`hydroservo.workflows.fluid`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import execute

__all__ = ["add_parsers"]

def cmd_fluid(args: argparse.Namespace) -> int:
    from hydroservo.workflows.fluid import FluidProperties

    job = FluidProperties(args.property, args.fluid, args.temperature, args.pressure, args.strict, cli=True)
    return execute(job, args)


def add_parsers(sub: Any) -> None:
    """Add ``fluid``."""
    p = sub.add_parser("fluid", help="fluid properties against temperature and pressure (skydrol, iso-vg32, iso-vg46)")
    p.add_argument(
        "property", help="density, specific-volume, kinematic-viscosity, dynamic-viscosity, bulk-modulus or all"
    )
    p.add_argument("--fluid", default="skydrol", help="built-in fluid (default skydrol)")
    p.add_argument(
        "--temperature", default="20", metavar="T,...", help="temperatures; bare numbers in degC (default 20)"
    )
    p.add_argument(
        "--pressure",
        default="0",
        metavar="P,...",
        help="gauge pressures; bare numbers in Pa, or a unit once at the end: '0,10,30 MPa' (default 0)",
    )
    p.add_argument(
        "--strict", action="store_true", help="refuse values outside the fluid model's range (default: warn)"
    )
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_fluid)
