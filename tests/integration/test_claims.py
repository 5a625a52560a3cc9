"""Every speed and accuracy figure the README and the guide quote is its last measurement.

A page quotes a measured figure after a marker naming its key in ``benchmarks/results/<bench>.json`` and the
format it is printed in (benchmarks/results.py): ``<!-- bench:cli.position_servo_warm_cpu_s .2f -->0.34 s``.
These tests only read files: each marked number must be the JSON's value in that format, each JSON a page
cites must say when and on what machine it was measured, and a page must make no speed claim (a ratio such as
"3x faster", "times faster", "takes 0.2 s", "0.3 s CPU") without a marker. JSON files no page cites are not
looked at (other benchmarks write there too).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
RESULTS = ROOT / "benchmarks" / "results"
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]

NUMBER = r"[-+−]?\d+(?:[.,]\d+)*(?:e[-+]?\d+)?"
MARKER = re.compile(
    r"<!--\s*bench:(?P<bench>[A-Za-z0-9_-]+)\.(?P<key>[A-Za-z0-9_-]+)\s+(?P<spec>\S+?)\s*-->"
    rf"(?P<text>not measured|{NUMBER})?"
)
#: a claim of speed: a ratio ("3.1x", "29×", "3 times faster"), a time taken ("takes 0.4 s", "0.3 s CPU",
#: "0.67 s wall", "22 ms against 0.51 s"); after the marked figures are taken out
SPEED = re.compile(
    r"\d(?:x|×)(?![\w-])"
    r"|times faster"
    r"|\d\s*(?:µs|us|ms|s)\s+(?:wall|CPU)\b"
    r"|\btak(?:es|ing|e)\s+(?:about\s+|some\s+)?\d[\d.]*(?:[–-]\d[\d.]*)?\s*(?:µs|ms|s)\b"
    r"|\d\s*(?:µs|ms|s)\s+against\s+\d"
)


def markers(text: str) -> list[re.Match[str]]:
    return list(MARKER.finditer(text))


def figure(bench: str, key: str, cache: dict[str, dict]) -> tuple[bool, float | None]:
    """(found, value) of ``bench.key`` in benchmarks/results."""
    if bench not in cache:
        path = RESULTS / f"{bench}.json"
        cache[bench] = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
    figures = cache[bench].get("figures", {})
    return key in figures, figures.get(key)


def check_markers(text: str, cache: dict[str, dict]) -> list[str]:
    """Every marker's figure against its JSON: the problems, one line each (line number: what)."""
    problems = []
    for m in markers(text):
        line = text.count("\n", 0, m.start()) + 1
        name = f"{m['bench']}.{m['key']}"
        found, value = figure(m["bench"], m["key"], cache)
        if not found:
            problems.append(f"line {line}: {name} is in no benchmarks/results/{m['bench']}.json")
            continue
        shown = m["text"]
        if shown is None:
            problems.append(f"line {line}: {name}: no number right after the marker")
            continue
        if value is None:
            if shown != "not measured":
                problems.append(f"line {line}: {name} was not measured; the page says {shown}")
            continue
        expected = format(value, m["spec"])
        if shown.replace("−", "-") != expected:
            problems.append(
                f"line {line}: {name} is {value!r}, printed {m['spec']!r}: {expected}; the page says {shown}"
            )
    return problems


def unmarked_claims(text: str) -> list[str]:
    """Speed claims with no marker: each as 'line N: ...its context...'."""
    stripped = MARKER.sub(lambda m: "N" if m["text"] else "", text)
    stripped = re.sub(r"<!--.*?-->", lambda m: "\n" * m[0].count("\n"), stripped, flags=re.S)
    found = []
    for m in SPEED.finditer(stripped):
        line = stripped.count("\n", 0, m.start()) + 1
        start = max(stripped.rfind("\n", 0, m.start()) + 1, m.start() - 50)
        found.append(f"line {line}: ...{stripped[start : m.end() + 20].splitlines()[0]}...")
    return found


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_marked_figure_is_its_last_measurement(page: Path) -> None:
    problems = check_markers(page.read_text(encoding="utf-8"), {})
    assert not problems, f"{page.relative_to(ROOT)}:\n" + "\n".join(problems)


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_no_speed_claim_without_its_measurement(page: Path) -> None:
    found = unmarked_claims(page.read_text(encoding="utf-8"))
    assert not found, (
        f"{page.relative_to(ROOT)}: speed claims with no `<!-- bench:FILE.KEY FORMAT -->` marker "
        "(benchmarks/results.py):\n" + "\n".join(found)
    )


def test_each_cited_measurement_says_when_and_where() -> None:
    cited = {m["bench"] for page in PAGES for m in markers(page.read_text(encoding="utf-8"))}
    assert cited, "no page cites a measurement"
    for bench in sorted(cited):
        data = json.loads((RESULTS / f"{bench}.json").read_text(encoding="utf-8"))
        assert re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", data["date"]), bench
        machine = data["machine"]
        assert machine["cpu"] and machine["cores"] >= 1 and machine["python"], bench
        assert machine["packages"]["hydroservo"], bench
        script = ROOT / data["script"]
        assert script.is_file(), f"{bench}.json: its script {data['script']} is not in the repository"


# -- the checks themselves -------------------------------------------------------------
def test_a_stale_figure_fails(tmp_path: Path) -> None:
    cache = {"x": {"figures": {"ratio": 15.62, "gone": None}}}
    assert check_markers("<!-- bench:x.ratio .1f -->15.6x faster", cache) == []
    assert check_markers("about <!-- bench:x.ratio .1f -->34x faster", cache)
    assert check_markers("<!-- bench:x.ratio .1f -->", cache)  # no number after it
    assert check_markers("<!-- bench:x.other .1f -->1.0", cache)  # no such figure
    assert check_markers("<!-- bench:x.gone .1f -->not measured", cache) == []
    assert check_markers("<!-- bench:x.gone .1f -->1.0", cache)


def test_an_unmarked_claim_fails() -> None:
    for claim in ("1.4x faster than Hopsan", "runs 830 times faster", "takes 0.35-0.45 s", "0.19 s wall",
                  "0.34 s CPU", "22 ms against 0.51 s", "(29×, medians)"):  # fmt: skip
        assert unmarked_claims(f"text {claim} text"), claim
    assert unmarked_claims("<!-- bench:x.r .1f -->15.6x faster, and 2x faster") != []
    assert unmarked_claims("<!-- bench:x.r .1f -->15.6x faster; <!-- bench:x.s .2f -->0.34 s CPU") == []
    assert unmarked_claims("a time constant of 24 ms; 3 × 30 frequencies; 1e-3 of range") == []
