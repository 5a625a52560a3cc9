"""``hydroservo examples DIR``: write the example files the README's commands use."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from hydroservo.errors import ParameterError

__all__ = ["add_parsers"]


def cmd_examples(args: argparse.Namespace) -> int:
    from hydroservo.data import example_files

    files = example_files()
    out = Path(args.dir)
    if out.exists() and not out.is_dir():
        raise ParameterError(f"examples {args.dir!r}: exists and is not a folder; expected a folder to write into")
    existing = [name for name in files if (out / name).exists()]
    if existing and not args.force:
        raise ParameterError(
            f"examples {args.dir!r}: {', '.join(existing)} already exist; expected a new or empty folder "
            "(--force replaces them)"
        )
    out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (out / name).write_text(text, encoding="utf-8")
    print(f"wrote {len(files)} example files to {out}: {', '.join(files)}")
    return 0


def add_parsers(sub: Any) -> None:
    """Add ``examples``."""
    p = sub.add_parser("examples", help="write the example model, datasheet and curve files the README uses")
    p.add_argument("dir", metavar="DIR", help="folder to write them to (created if missing)")
    p.add_argument("--force", action="store_true", help="replace files of the same names")
    p.set_defaults(func=cmd_examples)
