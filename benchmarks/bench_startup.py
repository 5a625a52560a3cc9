"""Start-up time: ``import hydroservo``, ``hydroservo --version`` and ``--help`` against a bare interpreter.

Run: ``python benchmarks/bench_startup.py [REPEATS]`` (default 15). Each
command runs as a fresh process, alternating with the baseline (``python -c
pass``) in the same loop, so that machine load affects both alike; prints the
median and the spread of CPU times, and each median's excess over the
baseline's. Times are CPU time (user + system, children included), steadier than wall time on a shared
machine. The budgets (on an idle machine): ``import hydroservo`` under
0.4 s, ``--version`` and ``--help`` under 0.3 s (issue 9); ``hydroservo simulate
flight-simulator --json`` end to end under 0.6 s (issue 14).
"""

from __future__ import annotations

import os
import shutil
import statistics
import subprocess
import sys

PY = sys.executable
CLI = shutil.which("hydroservo") or ""

COMMANDS = {
    "baseline: python -c pass": [PY, "-c", "pass"],
    "import hydroservo": [PY, "-c", "import hydroservo"],
    "import hydroservo; first use of hs.System": [PY, "-c", "import hydroservo as hs; hs.System"],
    "hydroservo --version": [CLI, "--version"] if CLI else [PY, "-m", "hydroservo", "--version"],
    "hydroservo --help": [CLI, "--help"] if CLI else [PY, "-m", "hydroservo", "--help"],
    "hydroservo validate --help": [CLI, "validate", "--help"] if CLI else [PY, "-m", "hydroservo", "validate", "--help"],
    # a whole one-off run: load, build, integrate, print the JSON summary (no files: --json alone writes none)
    "hydroservo simulate flight-simulator --json": (
        [CLI, "simulate", "flight-simulator", "--json"] if CLI else [PY, "-m", "hydroservo", "simulate",
                                                                     "flight-simulator", "--json"]
    ),
}


def cpu(argv: list[str]) -> float:
    """The CPU time [s] of one process (user + system, its children included): steadier than wall time on a
    shared machine."""
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"{' '.join(argv)} failed")
    return usage.ru_utime + usage.ru_stime


def main(repeats: int = 15) -> dict[str, float]:
    times: dict[str, list[float]] = {name: [] for name in COMMANDS}
    for argv in COMMANDS.values():  # warm the file cache
        cpu(argv)
    for _ in range(repeats):
        for name, argv in COMMANDS.items():
            times[name].append(cpu(argv))
    base = statistics.median(times["baseline: python -c pass"])
    print(f"{repeats} runs each, CPU time [s]: median (min - max); excess over the bare interpreter")
    for name, ts in times.items():
        med = statistics.median(ts)
        print(f"  {name:44s} {med:6.3f} ({min(ts):.3f} - {max(ts):.3f})   +{med - base:.3f}   x{med / base:.1f}")
    return {name: statistics.median(ts) for name, ts in times.items()}


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 15)
