"""Where every published figure is kept: ``benchmarks/results/<bench>.json``, one file per benchmark.

A benchmark that measures a figure quoted in README.md or docs/*.md prints it and calls :func:`record`, which
writes the figures with the date and the machine they were measured on (cpu model, cores, Python, the versions
of the packages that decide the speed). A page quotes a figure after a marker naming its key and the format it
is printed in, ``<!-- bench:hopsan.ratio_x_1e-3 .1f -->15.6``: tests/integration/test_claims.py reads the pages
and these files and fails when a number differs from its last measurement, or when a page makes a speed claim
with no marker.

Keys: ``<bench>.<figure>``, where ``<bench>`` is the file's stem and ``<figure>`` a key of its ``figures`` (no
dots in either). A figure is a number, or null for one that could not be measured (its page then says "not
measured").
"""

from __future__ import annotations

import datetime
import json
import math
import os
import platform
import re
import subprocess
import sys
from importlib import metadata
from pathlib import Path

FOLDER = Path(__file__).resolve().parent / "results"
PACKAGES = ("hydroservo", "numpy", "scipy", "casadi")


def median_cpu(fn, repeat: int) -> float:
    """The median CPU time [s] of ``fn()`` over ``repeat`` calls: this process's, so ``fn`` must run in it on one
    thread (a C stepper's loop, one CVODES call); steadier than wall time on a shared machine."""
    import statistics
    import time

    times = []
    for _ in range(repeat):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return statistics.median(times)


def cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def machine() -> dict:
    """The machine and software a figure was measured on."""
    versions = {}
    for name in PACKAGES:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = None
    try:
        import hydroservo

        versions["hydroservo"] = hydroservo.__version__  # the copy imported, not the one installed
    except ImportError:
        pass
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                                cwd=FOLDER.parent, timeout=10).stdout.strip() or None  # fmt: skip
    except (OSError, subprocess.SubprocessError):
        commit = None
    return {
        "cpu": cpu_model(),
        "cores": os.cpu_count(),
        "system": f"{platform.system()} {platform.release()} {platform.machine()}",
        "python": sys.version.split()[0],
        "packages": versions,
        "commit": commit,
        # other processes' load moves wall time most, CPU time too (shared caches): say how busy the machine was
        "load_average_1min": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
    }


def _clean(value):
    if isinstance(value, dict):
        return {str(k): _clean(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_clean(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if hasattr(value, "item"):  # a NumPy scalar
        return _clean(value.item())
    return value


def record(bench: str, figures: dict, *, script: str | None = None, notes: dict | None = None) -> Path:
    """Write ``figures`` (flat: name -> number or None) as benchmarks/results/<bench>.json; print where."""
    bad = [k for k in figures if "." in k or " " in k]
    if "." in bench or bad:
        raise ValueError(f"figure keys hold no dots or spaces: {bench!r} {bad}")
    FOLDER.mkdir(exist_ok=True)
    path = FOLDER / f"{bench}.json"
    data = {
        "bench": bench,
        "script": script or f"benchmarks/{Path(sys.argv[0]).name}",
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "machine": machine(),
        "figures": _clean(dict(figures)),
    }
    if notes:
        data["notes"] = _clean(notes)
    path.write_text(json.dumps(data, indent=1, sort_keys=False) + "\n", encoding="utf-8")
    print(f"figures written to {path.relative_to(FOLDER.parent.parent)}")
    return path


def load(bench: str) -> dict:
    return json.loads((FOLDER / f"{bench}.json").read_text(encoding="utf-8"))


def mark(key: str, value: float | None, spec: str) -> str:
    """A figure as a page quotes it: its marker, then the number formatted by ``spec`` (or "not measured")."""
    text = "not measured" if value is None or value != value else format(value, spec)
    return f"<!-- bench:{key} {spec} -->{text}"


#: a marker and the figure after it (tests/integration/test_claims.py reads them the same way)
MARKER = re.compile(
    r"(?P<marker><!--\s*bench:(?P<bench>[A-Za-z0-9_-]+)\.(?P<key>[A-Za-z0-9_-]+)\s+(?P<spec>\S+?)\s*-->)"
    r"(?P<text>not measured|[-+−]?\d+(?:[.,]\d+)*(?:e[-+]?\d+)?)?"
)


def fill(page: Path) -> int:
    """Rewrite every marked figure of ``page`` from its JSON; the number of figures changed."""
    cache: dict[str, dict | None] = {}
    changed = 0

    def one(m: re.Match[str]) -> str:
        nonlocal changed
        bench = m["bench"]
        if bench not in cache:
            try:
                cache[bench] = load(bench)["figures"]
            except FileNotFoundError:
                print(f"{page}: no benchmarks/results/{bench}.json yet: its figures are left as they are")
                cache[bench] = None
        if cache[bench] is None:
            return m[0]
        if m["key"] not in cache[bench]:
            raise SystemExit(f"{page}: {bench}.{m['key']} is in no benchmarks/results/{bench}.json")
        new = mark(f"{bench}.{m['key']}", cache[bench][m["key"]], m["spec"])
        changed += new != m[0]
        return new

    text = page.read_text(encoding="utf-8")
    page.write_text(MARKER.sub(one, text), encoding="utf-8")
    return changed


if __name__ == "__main__":
    # python benchmarks/results.py PAGE...: each marked figure rewritten from its last measurement
    for name in sys.argv[1:]:
        print(f"{name}: {fill(Path(name))} figures changed")
