"""``hydroservo docs``: the user guide's pages, which the package's messages name, exist where it runs."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[2] / "src" / "hydroservo"


def test_docs_lists_the_pages_and_prints_one(cli) -> None:
    code, out, _ = cli("docs")
    assert code == 0 and "validation.md" in out and "hydroservo beside Hopsan" in out
    code, out, _ = cli("docs", "validation", "--path")
    assert code == 0 and Path(out.strip()).is_file() and out.strip().endswith("validation.md")
    code, out, _ = cli("docs", "docs/hopsan.md")
    assert code == 0 and out.startswith("# hydroservo beside Hopsan")
    code, out, _ = cli("docs", "--json")
    assert code == 0 and "engine.md" in json.loads(out)["pages"]
    code, _, err = cli("docs", "valdation")
    assert code == 2 and "did you mean 'validation.md'" in err


def test_every_page_a_message_names_exists() -> None:
    from hydroservo.data import guide_folder

    named = set()
    for path in PACKAGE.rglob("*.py"):
        named |= set(re.findall(r"docs/([a-z_]+\.md)", path.read_text(encoding="utf-8")))
    folder = guide_folder()
    assert folder is not None and named
    assert sorted(n for n in named if not (folder / n).is_file()) == []


@pytest.mark.slow
def test_the_wheel_carries_the_guide(tmp_path: Path) -> None:
    # a wheel built as pip builds one (isolated, setuptools from the package index) holds docs/*.md and the figures
    root = PACKAGE.parents[1]
    done = subprocess.run([sys.executable, "-m", "pip", "wheel", str(root), "--no-deps", "-q", "-w", str(tmp_path)],
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr[-2000:]
    names = zipfile.ZipFile(next(tmp_path.glob("hydroservo-*.whl"))).namelist()
    pages = {Path(n).name for n in names if n.startswith("hydroservo/docs/") and n.endswith(".md")}
    assert {"validation.md", "engine.md", "hopsan.md", "components.md"} <= pages and "index.md" not in pages
    assert any(n.startswith("hydroservo/docs/img/") and n.endswith(".png") for n in names)
