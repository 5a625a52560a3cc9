"""``hydroservo cache``: the compiled models' folder, shown and cleared."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import hydroservo as hs
from hydroservo.system.native import has_compiler


@pytest.mark.skipif(not has_compiler(), reason="no C compiler")
def test_cache_shows_the_compiled_models_and_clears_them(tmp_path: Path, cli, monkeypatch) -> None:
    monkeypatch.setenv("HYDROSERVO_CACHE", str(tmp_path / "cache"))
    code, text, _ = cli("cache", "--json")
    assert code == 0 and json.loads(text) == {"folder": str(tmp_path / "cache" / "c"), "entries": 0, "bytes": 0}
    hs.load_model("servo-solenoid-cylinder").simulate(method="ros23", n_points=11)
    (tmp_path / "cache" / "c" / ".build-left-behind").mkdir()  # an interrupted build
    code, text, _ = cli("cache")
    assert code == 0 and "compiled models in" in text and ": 1 (" in text
    code, text, _ = cli("cache", "--clear", "--json")
    report = json.loads(text)
    assert code == 0 and report["cleared"]["entries"] == 1 and report["cleared"]["bytes"] > 10_000
    assert report["entries"] == 0 and list((tmp_path / "cache" / "c").iterdir()) == []
    # built again when next used
    assert hs.load_model("servo-solenoid-cylinder").simulate(method="ros23", n_points=11).stats["method"] == "ros23"
