"""Whole-command times of ``hydroservo simulate MODEL --json``: with the compiled model in the cache (warm), and
the first run of a model, which compiles it (cold cache), against a bare interpreter in the same loop.

Run: ``python benchmarks/bench_cli.py [REPEATS]`` (default 7). Prints medians (min - max) of wall and CPU time
(user + system of the command's process and its children, the operating system's accounting), and writes them
to benchmarks/results/cli.json.

Every command runs as a fresh process, in turn with the others (A B C A B C ...) so that the machine's load
touches all alike. The modules' bytecode is compiled first (into a folder of this run, as ``pip install``
leaves it). Warm: the compiled models are in a cache folder of this run, filled by a first run. First run: each
repeat starts with an empty cache folder, so the command builds, compiles and caches the model's C code
(docs/engine.md, "Compiled solvers"). CPU time is the steadier figure on a shared machine: quote it first.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from results import record  # noqa: E402

MODELS = ("position-servo", "flight-simulator")


def timed(argv: list[str], env: dict[str, str]) -> tuple[float, float]:
    """(wall, cpu) seconds of one process, its children included."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} exited {proc.returncode}")
    return wall, usage.ru_utime + usage.ru_stime


def main(repeats: int = 7) -> dict[str, float]:
    found: dict[str, float] = {}
    with tempfile.TemporaryDirectory() as folder:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["PYTHONPYCACHEPREFIX"] = str(Path(folder) / "pycache")
        warm_cache = Path(folder) / "cache"
        commands = {"baseline": [sys.executable, "-c", "pass"]}
        for model in MODELS:
            commands[model] = [sys.executable, "-m", "hydroservo", "simulate", model, "--json"]
        times: dict[str, list[tuple[float, float]]] = {}
        for argv in commands.values():  # bytecode, and the warm cache filled
            timed(argv, {**env, "HYDROSERVO_CACHE": str(warm_cache)})
        for k in range(repeats):
            for name, argv in commands.items():
                times.setdefault(f"{name}_warm", []).append(timed(argv, {**env, "HYDROSERVO_CACHE": str(warm_cache)}))
                if name != "baseline":
                    cold = Path(folder) / f"cold{k}-{name}"
                    times.setdefault(f"{name}_first", []).append(timed(argv, {**env, "HYDROSERVO_CACHE": str(cold)}))
    print(f"{repeats} runs each, seconds: median (min - max); CPU = user + system, children included")
    for name, pairs in times.items():
        walls, cpus = [w for w, _ in pairs], [c for _, c in pairs]
        key = name.replace("-", "_")
        found[f"{key}_wall_s"] = statistics.median(walls)
        found[f"{key}_cpu_s"] = statistics.median(cpus)
        print(f"  {name:<26} wall {statistics.median(walls):6.2f} ({min(walls):.2f} - {max(walls):.2f})"
              f"   CPU {statistics.median(cpus):6.2f} ({min(cpus):.2f} - {max(cpus):.2f})")  # fmt: skip
    found["repeats"] = repeats
    record("cli", found)
    return found


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
