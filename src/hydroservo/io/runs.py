"""The runs of a study, written as they arrive: a folder of Parquet parts a user loads with pandas.

::

    out/runs/_study.json              what the study is (its fingerprint): a resume must be the same study
    out/runs/part-00000000-00000256.parquet    runs 0 to 255: parameters, metrics, status, reason
    ...

``pandas.read_parquet("out/runs")`` loads every part (files starting with ``_``
are not data). A part is written to a temporary name and renamed, so a part
either exists whole or not at all; an interrupted study keeps its parts, and
the same study started again skips them (:class:`RunStore`).
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

from hydroservo.errors import HydroservoError, ParameterError
from hydroservo.io.files import read_text

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["RunStore", "read_runs"]

_PART = re.compile(r"^part-(\d{8})-(\d{8})\.parquet$")


class RunStore:
    """A folder of Parquet parts for one study, identified by ``fingerprint`` (any JSON-able description).

    Opening a folder that holds parts of another study is refused unless
    ``force`` (which deletes those parts: they belong to nothing any more).
    """

    def __init__(self, folder: str | Path, fingerprint: dict[str, Any], *, force: bool = False) -> None:
        self.folder = Path(folder)
        if self.folder.exists() and not self.folder.is_dir():
            raise ParameterError(f"runs folder {str(self.folder)!r}: exists and is not a folder; expected a folder")
        manifest = self.folder / "_study.json"
        text = json.dumps(fingerprint, sort_keys=True, default=str)
        if manifest.exists():
            try:
                old = json.dumps(json.loads(read_text(manifest, "runs manifest")), sort_keys=True, default=str)
            except (HydroservoError, ValueError):
                old = ""
            if old != text:
                if not force:
                    raise ParameterError(
                        f"runs folder {str(self.folder)!r}: holds the runs of another study (other parameters, ranges, "
                        "metrics or model); expected a new folder, the same study to resume, or --force to start over"
                    )
                for part in self.parts():
                    part.unlink()
        elif self.folder.exists() and any(self.folder.iterdir()) and not force:
            raise ParameterError(
                f"runs folder {str(self.folder)!r}: not empty and not a study's; expected a new folder (--force uses it anyway)"
            )
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            tmp = manifest.with_name("_study.json.tmp")
            tmp.write_text(json.dumps(fingerprint, indent=2, sort_keys=True, default=str) + "\n", encoding="utf-8")
            os.replace(tmp, manifest)
        except OSError as exc:
            raise ParameterError(f"runs folder {str(self.folder)!r}: cannot write there ({exc.strerror})") from None

    def remove(self) -> None:
        """Delete the folder of a study that wrote no runs (its manifest only)."""
        if self.parts():
            raise ParameterError(f"runs folder {str(self.folder)!r}: holds runs; not removed")
        (self.folder / "_study.json").unlink(missing_ok=True)
        if self.folder.is_dir() and not any(self.folder.iterdir()):
            self.folder.rmdir()

    def parts(self) -> list[Path]:
        return sorted(p for p in self.folder.iterdir() if _PART.match(p.name))

    def done(self) -> set[tuple[int, int]]:
        """The (first, end) run ranges already written."""
        found = set()
        for p in self.parts():
            m = _PART.match(p.name)
            if m:
                found.add((int(m.group(1)), int(m.group(2))))
        return found

    def write(self, first: int, end: int, frame: pd.DataFrame) -> Path:
        """Write runs ``first`` to ``end - 1`` (atomically)."""
        path = self.folder / f"part-{first:08d}-{end:08d}.parquet"
        tmp = path.with_name("." + path.name + ".tmp")
        frame.to_parquet(tmp, index=True)
        os.replace(tmp, path)
        return path

    def load(self) -> pd.DataFrame:
        return read_runs(self.folder)


def read_runs(folder: str | Path) -> pd.DataFrame:
    """Every run written to ``folder``, in run order (index ``run``)."""
    import pandas as pd

    parts = [p for p in sorted(Path(folder).iterdir()) if _PART.match(p.name)] if Path(folder).is_dir() else []
    if not parts:
        raise ParameterError(f"runs folder {str(folder)!r}: no runs written there")
    frame = pd.concat([pd.read_parquet(p) for p in parts])
    return frame.sort_index()
