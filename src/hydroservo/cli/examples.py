"""``hydroservo examples DIR``: write the example files the README's commands use."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

__all__ = ["add_parsers"]


def cmd_examples(args: argparse.Namespace) -> int:
    from hydroservo.data import example_files
    from hydroservo.io.files import OutputFolder

    files = example_files()
    out = OutputFolder(Path(args.dir), force=args.force, what="examples")
    out.expect(list(files))
    with out:
        for name, text in files.items():
            out.file(name).write_text(text, encoding="utf-8")
    print(f"wrote {len(files)} example files to {args.dir}: {', '.join(files)}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``examples``."""
    p = sub.add_parser("examples", help="write the example model, datasheet and curve files the README uses")
    p.add_argument("dir", metavar="DIR", help="folder to write them to (created if missing)")
    p.add_argument("--force", action="store_true", help="replace files of the same names")
    p.set_defaults(func=cmd_examples)
