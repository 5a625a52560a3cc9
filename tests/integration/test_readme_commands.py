"""Every command of the README's CLI quick start runs, from the files ``hydroservo examples`` writes.

The README promises that its commands work from an installed package, not only
from a clone: this runs each ``hydroservo ...`` line of its ``bash`` blocks in a
fresh folder (``cd`` and ``> file`` honoured) and expects exit code 0.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import pytest

from hydroservo.system.native import has_compiler

README = Path(__file__).resolve().parents[2] / "README.md"


def readme_commands() -> list[str]:
    """The ``hydroservo`` command lines of the README's bash blocks, comments removed."""
    blocks = re.findall(r"```bash\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    lines = []
    for block in blocks:
        for line in block.splitlines():
            line = line.split("  #")[0].strip()
            if line.startswith("hydroservo"):
                lines.append(line)
    return lines


def test_the_readme_has_commands() -> None:
    commands = readme_commands()
    assert len(commands) >= 15 and commands[0].startswith("hydroservo examples")


def _needs_a_compiler(line: str) -> bool:
    """The command compiles C: a compiled method, or an export built."""
    return "--build" in line or "--method dopri5" in line or "--method ros23" in line




@pytest.mark.slow
def test_every_readme_command_runs(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, command_line: Callable[[str], None]) -> None:
    """Every command runs (those that compile C only where there is a C compiler)."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HYDROSERVO_CACHE", str(tmp_path / "cache"))
    compiles = has_compiler()
    for line in readme_commands():
        if _needs_a_compiler(line) and not compiles:
            continue
        command_line(line)


@pytest.mark.slow
def test_readme_python_blocks_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The README's Python examples run as written, one after the other, in a fresh folder."""
    import matplotlib

    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) >= 3
    namespace: dict[str, object] = {}
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)  # noqa: S102 - the README's own examples
    assert (tmp_path / "family.png").exists() and (tmp_path / "metrics.png").exists()
