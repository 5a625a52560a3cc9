"""Growth with model size: N flight-simulator actuator loops in one system, built and run.

Run: ``python benchmarks/bench_growth.py``

The built-in ``flight-simulator`` (one closed-loop actuator, 10 states) copied
N = 1, 6 (a motion platform's six actuators) and 24 times into one system,
each copy's components prefixed (``a3_valve``), each loop on its own; the
command step of loop k is 2 V x (1 + k/N), so the loops differ and the solver
cannot take one loop's steps for all. Timed: building the model (assembly, CasADi functions;
each N a structure of its own, so a fresh build) and a run (median of repeats),
each per loop as a ratio to N = 1, and the run's cost per step and loop. One
integrator steps all the loops together, so its steps follow the most
demanding loop at each time: the cost per step and loop is what linear growth
keeps flat; the number of steps grows as the loops differ.
"""

from __future__ import annotations

import re
import statistics
import time
import tomllib
from typing import Any

import hydroservo as hs
from hydroservo.data import model_text
from hydroservo.io.model_file import system_from_dict


def loops(n: int) -> hs.System:
    """``n`` copies of the flight-simulator actuator in one system."""
    data = tomllib.loads(model_text("flight-simulator"))
    names = list(data["components"])
    pattern = re.compile(r"\b(" + "|".join(map(re.escape, names)) + r")\.")

    def prefixed(text: str, k: int) -> str:
        return pattern.sub(lambda m: f"a{k}_{m.group(1)}.", text)

    out: dict[str, Any] = {"model": {"name": f"flight-simulator x{n}", "t_end": data["model"]["t_end"]}}
    out["components"] = {f"a{k}_{c}": dict(v) for k in range(n) for c, v in data["components"].items()}
    out["connections"] = {prefixed(a, k): prefixed(b, k) for k in range(n) for a, b in data["connections"].items()}
    out["initial"] = {prefixed(a, k): prefixed(b, k) for k in range(n) for a, b in data["initial"].items()}
    for k in range(n):
        out["components"][f"a{k}_source"]["amplitude"] = f"{2.0 * (1 + k / n):g} V"
    return system_from_dict(out, where=f"{n} loops")


def main(repeat: int = 5) -> dict[int, tuple[float, float, int]]:
    found: dict[int, tuple[float, float, int]] = {}
    print(f"{'loops':>6}{'states':>8}{'build':>10}{'per loop':>10}{'run':>10}{'per loop':>10}{'steps':>8}{'us/step/loop':>14}")
    for n in (1, 6, 24):
        system = loops(n)
        start = time.perf_counter()
        model = system.build()
        build = time.perf_counter() - start
        steps = system.simulate(method="cvodes").stats["nsteps"]  # the integrator built once
        runs = []
        for _ in range(repeat):
            start = time.perf_counter()
            system.simulate(method="cvodes")
            runs.append(time.perf_counter() - start)
        run = statistics.median(runs)
        found[n] = (build, run, steps)
        b1, r1, _ = found[1]
        print(
            f"{n:>6}{model.nx:>8}{build:>9.3f}s{build / n / b1:>9.2f}x{run * 1e3:>8.1f}ms{run / n / r1:>9.2f}x"
            f"{steps:>8}{run / steps / n * 1e6:>14.2f}"
        )
    return found


if __name__ == "__main__":
    main()
