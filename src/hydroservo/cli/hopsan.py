"""``hydroservo import-hopsan``: a Hopsan model file as a hydroservo model file (:mod:`hydroservo.workflows.hopsan`)."""

from __future__ import annotations

import argparse
from typing import Any

from hydroservo.cli.common import add_output_options, execute


def cmd_import_hopsan(args: argparse.Namespace) -> int:
    from hydroservo.workflows.hopsan import ImportHopsan

    return execute(ImportHopsan(args.file, args.line_segments, cli=True), args)


def add_parsers(sub: Any) -> None:
    """Add ``import-hopsan``."""
    p = sub.add_parser(
        "import-hopsan",
        help="import a Hopsan model file (.hmf) as a hydroservo model file",
        description="Map each component of a Hopsan model to hydroservo's, with Hopsan's law, and write the model "
        "file. A model with components hydroservo does not map yet is refused with the list of them "
        "(docs/hopsan.md lists the components mapped).",
    )
    p.add_argument("file", metavar="FILE.hmf")
    p.add_argument("--line-segments", type=int, metavar="N",
                   help="lumped segments of each transmission line and hose (default: those that carry its waves up "
                   "to the Nyquist frequency of Hopsan's time step Ts, ceil(5 T/Ts) for a delay T, at most 200)")
    add_output_options(p, "hydroservo-NAME")
    p.add_argument("--json", action="store_true", help="print the mapping as JSON")
    p.set_defaults(func=cmd_import_hopsan)
