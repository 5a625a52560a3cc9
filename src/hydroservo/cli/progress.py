"""The progress of a long command on stderr, with tqdm (docs/reliability.md, "Progress").

A command's workflow reports stages by name (``progress("running the bode tests")``) and, where a stage counts
its work (periodic orbits, runs), how far it is (``progress.count(done, total)``). :class:`Bars` shows each
stage as a line with its time and, once counted, a bar with the rate and the time left. Nothing is shown under
``--json`` or when stderr is not a terminal (a log, a pipe, CI): the report says what was done.
"""

from __future__ import annotations

import sys
from typing import Any

__all__ = ["Bars", "progress_bars"]


class Bars:
    """One command's progress bars on stderr; a callable for its stages, :meth:`count` for counted work."""

    def __init__(self, enabled: bool | None = None) -> None:
        self.enabled = sys.stderr.isatty() if enabled is None else enabled
        self._bar: Any = None

    def __call__(self, stage: str) -> None:
        """A stage starts: a line with its name and the time it has taken."""
        self.close()
        if self.enabled:
            from tqdm import tqdm

            self._bar = tqdm(desc=stage, total=None, file=sys.stderr, bar_format="{desc}: {elapsed}", leave=True,
                             dynamic_ncols=True)  # fmt: skip

    def count(self, done: int, total: int, **postfix: Any) -> None:
        """The current stage has done ``done`` of ``total`` (runs, orbits): a bar with the rate and time left."""
        if not self.enabled:
            return
        if self._bar is None:
            self("working")
        bar = self._bar
        if bar.total != total:
            bar.bar_format = "{desc}: {percentage:3.0f}%|{bar}| {n_fmt}/{total_fmt} [{elapsed}<{remaining}{postfix}]"
            bar.reset(total=total)
        bar.n = done
        if postfix:
            bar.set_postfix(postfix, refresh=False)
        bar.refresh()

    def runs(self, done: int, failed: int, total: int, elapsed: float) -> None:
        """A study's runs (``runs_progress`` of :class:`~hydroservo.workflows.sensitivity.Sensitivity`)."""
        if self._bar is None:
            self("runs")
        self.count(done, total, failed=failed)

    def close(self) -> None:
        """End the current stage's line (its final time stays on screen)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def progress_bars(args: Any) -> Bars:
    """The bars of a command: shown on a terminal, never with ``--json``."""
    return Bars(enabled=False if getattr(args, "json", False) else None)
