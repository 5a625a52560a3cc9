"""The folder of compiled models, as ``hydroservo cache`` shows and clears it (:mod:`hydroservo.system.native`).

>>> from hydroservo.workflows.cache import Cache
>>> report = Cache().run()
>>> report.folder.name
'c'
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, ClassVar

from hydroservo.workflows.base import Progress, Report, Workflow

__all__ = ["Cache", "CacheReport"]


@dataclass
class CacheReport(Report):
    """The cache folder, its compiled models and their size; what was cleared."""

    command: ClassVar[str] = "cache"

    folder: Path
    entries: int
    size: int
    cleared: tuple[int, int] | None = None

    def title(self) -> str:
        return "hydroservo's compiled models"

    def lines(self) -> list[str]:
        out = [f"compiled models in {self.folder}: {self.entries} ({self.size / 1e6:.1f} MB)"]
        if self.cleared is not None:
            out.append(f"cleared {self.cleared[0]} ({self.cleared[1] / 1e6:.1f} MB); each is built again when next used")
        else:
            out.append("each is a model's C, compiled once (simulate --method ros23|dopri5); --clear removes them")
        return out

    def to_dict(self) -> dict[str, Any]:
        found: dict[str, Any] = {"folder": str(self.folder), "entries": self.entries, "bytes": self.size}
        if self.cleared is not None:
            found["cleared"] = {"entries": self.cleared[0], "bytes": self.cleared[1]}
        return found


@dataclass
class Cache(Workflow):
    """Show the compiled models in the cache folder, or ``clear`` them."""

    clear: bool = False

    def run(self, progress: Progress | None = None, folder: Path | None = None) -> CacheReport:
        from hydroservo.system.native import cache_entries, cache_folder, clear_cache

        cleared = clear_cache() if self.clear else None
        entries = cache_entries()
        return CacheReport(cache_folder() / "c", len(entries), sum(size for _, size in entries), cleared)
