"""What a long record costs: reading it, and calibrating on it (docs/reliability.md, "Files", large records).

Run: ``python benchmarks/bench_large_records.py [--rows=75001,1000000] [--json=FILE]``

A synthetic step record of the robot arm (``hydroservo rig`` at 50 kHz, ``load.x`` with 0.01 mm of noise and
``command.y``), interpolated to each number of rows, is written to a temporary folder; then, each in a child
process, ``read_record`` alone and ``hydroservo calibrate robot-arm --record R --input command.y --fit load.B``.
Printed per size: the file's size, the CPU time (user + system) and the peak resident memory of each child, and the
thinning warning calibrate gave. ``HYDROSERVO_MAX_RECORD_MB`` is raised for sizes over the default cap.
"""

from __future__ import annotations

import datetime
import json
import os
import platform
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np


def _child(argv: list[str], env: dict[str, str]) -> dict[str, Any]:
    """Run ``argv``; its exit code, CPU seconds, peak memory [MB] and stderr (os.wait4: this child's own usage)."""
    proc = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    assert proc.stderr is not None
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    return {"exit": proc.returncode, "cpu_s": round(usage.ru_utime + usage.ru_stime, 2),
            "peak_mb": round(usage.ru_maxrss / 1024, 1), "stderr": err.strip().splitlines()}


def main(rows: list[int], json_path: str | None = None) -> dict[str, Any]:
    env = dict(os.environ)
    found: dict[str, Any] = {"date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
                             "machine": f"{platform.node()} {platform.machine()} {os.cpu_count()} cores, {platform.python_version()}",
                             "sizes": {}}
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        subprocess.run([sys.executable, "-m", "hydroservo", "rig", "robot-arm", "--sensor", "load.x=50 kHz,0.01 mm",
                        "--sensor", "command.y=50 kHz", "--seed", "1", "--name", "arm", "--out", str(folder / "rig")],
                       check=True, capture_output=True)
        base = np.genfromtxt(folder / "rig" / "arm.csv", delimiter=",", skip_header=1)
        rng = np.random.default_rng(2)
        for n in rows:
            t = np.linspace(0.0, base[-1, 0], n)
            path = folder / f"arm-{n}.csv"
            with path.open("w") as f:
                f.write("t [s],load.x [mm],command.y [-]\n")
                x = np.interp(t, base[:, 0], base[:, 1]) + rng.normal(0.0, 0.01, n)
                np.savetxt(f, np.column_stack([t, x, np.interp(t, base[:, 0], base[:, 2])]), fmt="%.9g", delimiter=",")
            size = path.stat().st_size
            env["HYDROSERVO_MAX_RECORD_MB"] = str(max(256, int(size / 1e6) + 1))
            read = _child([sys.executable, "-c", f"from hydroservo.io.records import read_record; read_record({str(path)!r})"], env)
            fit = _child([sys.executable, "-m", "hydroservo", "calibrate", "robot-arm", "--record", str(path), "--input",
                          "command.y", "--fit", "load.B", "--out", str(folder / f"cal-{n}"), "--json"], env)
            found["sizes"][n] = {"bytes": size, "read": read, "calibrate": fit}
            warning = next((line for line in fit["stderr"] if "samples" in line), "(no thinning)")
            print(f"{n:>9} rows  {size / 1e6:7.1f} MB   read: {read['cpu_s']:6.2f} CPU-s {read['peak_mb']:7.1f} MB   "
                  f"calibrate: exit {fit['exit']}, {fit['cpu_s']:6.2f} CPU-s {fit['peak_mb']:7.1f} MB\n    {warning}")
    print(f"{found['date']}, {found['machine']}")
    if json_path:
        Path(json_path).write_text(json.dumps(found, indent=1) + "\n")
    return found


if __name__ == "__main__":
    options = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
    main([int(r) for r in options.get("rows", "75001,1000000").split(",")], options.get("json"))
