"""Solver robustness on random valid parameter sets: how many fail, under which method, and why (issue 37).

Run: ``python benchmarks/bench_robustness.py [N] [--seed S] [--all-prob P] [--methods auto cvodes]``
(N valid sets per built-in model, default 150).

A set is drawn as ``benchmarks/fuzz_models.py`` draws one (1 to 5 parameters, or with probability
``--all-prob`` every parameter, inside each parameter's declared range) and is *valid* when the components'
own cross-parameter checks accept it (``fuzz_models.cross_check``: chamber volumes positive over the stroke,
a valve's structure coefficients, ...); a valve and the spool that drives it share one stroke, so a set that
draws one of the pair gives it to both. Invalid sets are drawn again, so that every model gets N valid sets.
Each set runs as ``system.simulate(params=...)`` with the model's own ``t_end``, once per method (``auto``:
the default, compiled rodas3; ``cvodes``), in a worker process with a 60 s bound.

A failure is classified from its message (the engine says where, which state and why):

* ``diverges``: a state grew beyond a million times its nominal magnitude (the solution runs away: an
  unstable loop with nothing to bound it);
* ``out of proportion``: refused at the start, a rate faster than any circuit has (a parameter out of all
  proportion, ``Model.FASTEST_RATE``);
* ``step budget``: the step budget was used up without a runaway state (a stiff or fast transient);
* ``no derivative``: the Jacobian is not finite where the run stopped (a law without a derivative there, such
  as a square root at zero drop with its regularisation set to 0);
* ``step collapse``: the step fell below what floating point resolves, or CVODES' corrector failed
  (a kink or a discontinuity the step control does not get past);
* ``not finite``: the rates gave NaN or Inf;
* ``algebraic``: an algebraic unknown was not solved;
* ``other``: anything else (its message is kept in the JSON).

Prints a table per model and method (sets, ok, failed, failures by class) and writes
``benchmarks/results/robustness.json`` (``--json`` to change) with the date, the machine and every
failing set (its parameters, its message).
"""

from __future__ import annotations

import argparse
import contextlib
import datetime
import importlib.util
import json
import os
import platform
import re
import sys
import tempfile
from collections import Counter
from importlib import metadata
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results" / "robustness.json"
CLASSES = (
    "diverges",
    "out of proportion",
    "step budget",
    "no derivative",
    "step collapse",
    "not finite",
    "algebraic",
    "other",
)
#: A state beyond this many times its nominal magnitude at the failure: the solution runs away.
RUNAWAY = 1e6


def _fuzz() -> ModuleType:
    name = "hydroservo_fuzz_models"
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, HERE / "fuzz_models.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def valid_sets(system: Any, n: int, seed: int, label: str, all_prob: float) -> tuple[list[dict[str, float]], int]:
    """``n`` valid random sets of ``system``, and how many draws the components' checks refused on the way."""
    fz = _fuzz()
    cands, _ = fz.candidates(system)
    rng = fz._rng(seed, label, "robustness")
    sets: list[dict[str, float]] = []
    refused = 0
    while len(sets) < n:
        s = fz.draw_set(system, cands, rng, all_prob=all_prob)
        for a, b in system.stroke_pairs():  # one stroke for a spool and its valve: the first one drawn
            if a in s or b in s:
                s[a] = s[b] = s[a] if a in s else s[b]
        if fz.cross_check(system, s) is None:
            sets.append(s)
        else:
            refused += 1
    return sets, refused


_STATE = re.compile(r"state changing fastest was (\S+) = ([-+0-9.eE]+|nan|inf|-inf)")


def classify(message: str, error_type: str, nominal: dict[str, float]) -> str:
    """The class of a failure (see the module docstring) from its message."""
    if "solution diverges" in message:  # the engine's own verdict (not "... or a state diverges")
        return "diverges"
    found = _STATE.search(message)
    if found and found.group(1) in nominal:
        value = float(found.group(2))
        if not np.isfinite(value) or abs(value) > RUNAWAY * nominal[found.group(1)]:
            return "diverges"
    if error_type == "ParameterError" and "out of all proportion" in message:
        return "out of proportion"
    if "algebraic unknown" in message:
        return "algebraic"
    if "step budget" in message:
        return "step budget"
    if "Jacobian there is not finite" in message:
        return "no derivative"
    if any(m in message for m in ("step fell to", "corrector did not converge", "error test failed", "too close")):
        return "step collapse"
    if "NaN" in message or "not finite" in message or "Inf" in message:
        return "not finite"
    return "other"


def run(n: int, seed: int, all_prob: float, methods: list[str], timeout: float) -> dict[str, Any]:
    from hydroservo.data import model_names
    from hydroservo.io import load_model

    fz = _fuzz()
    plans = []
    for label in model_names():
        system = load_model(label)
        model = system.build()
        sets, refused = valid_sets(system, n, seed, label, all_prob)
        plans.append((label, dict(zip(model.state_names, model.nominal.tolist())), sets, refused))
    reqs = [
        {"op": "run", "model": label, "params": s, "method": method, "id": k}
        for method in methods
        for label, _, sets, _ in plans
        for k, s in enumerate(sets)
    ]
    pool = fz.Pool(1, Path(tempfile.mkdtemp(prefix="hydroservo-robustness-")))
    try:
        outs = pool.map(reqs, timeout)
    finally:
        pool.close()
    models: dict[str, Any] = {}
    nominals = {label: nom for label, nom, _, _ in plans}
    for req, out in zip(reqs, outs):
        label, method = req["model"], req["method"]
        entry = models.setdefault(label, {"refused_draws": next(r for m, _, _, r in plans if m == label)})
        row = entry.setdefault(
            method, {"sets": 0, "ok": 0, "implausible_warned": 0, "failed": 0, "classes": Counter(), "failures": []}
        )
        row["sets"] += 1
        outcome = out.get("outcome")
        if outcome in ("ok", "implausible_warned"):
            row[outcome] += 1
            continue
        row["failed"] += 1
        message = str(out.get("message", ""))
        cls = (
            classify(message, str(out.get("error_type", "")), nominals[label]) if outcome == "clean_error" else outcome
        )
        row["classes"][cls] += 1
        row["failures"].append({"index": req["id"], "class": cls, "params": req["params"], "message": message})
    for entry in models.values():
        for method in methods:
            entry[method]["classes"] = dict(entry[method]["classes"])
            entry[method]["failed_percent"] = 100.0 * entry[method]["failed"] / max(entry[method]["sets"], 1)
    figures = {  # flat, no dots in the keys (benchmarks/results/<bench>.json: "figures" are numbers)
        f"{label.replace('-', '_')}_{method}_{what}": models[label][method][key]
        for label in models
        for method in methods
        for what, key in (("sets", "sets"), ("failed", "failed"), ("failed_percent", "failed_percent"))
    }
    return {
        "bench": "robustness",
        "script": "benchmarks/bench_robustness.py",
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "machine": machine(),
        "code": fz._code_version(),
        "config": {"sets_per_model": n, "seed": seed, "all_prob": all_prob, "methods": methods, "timeout_s": timeout},
        "figures": figures,
        "models": models,
    }


def machine() -> dict[str, Any]:
    """The machine and software the figures were measured on."""
    cpu = platform.processor() or platform.machine()
    with contextlib.suppress(OSError):
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    packages: dict[str, str | None] = {}
    for name in ("numpy", "scipy", "casadi"):
        try:
            packages[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            packages[name] = None
    import hydroservo

    packages["hydroservo"] = hydroservo.__version__
    return {
        "cpu": cpu,
        "cores": os.cpu_count(),
        "system": f"{platform.system()} {platform.release()} {platform.machine()}",
        "python": sys.version.split()[0],
        "packages": packages,
        "load_average_1min": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
    }


def table(report: dict[str, Any]) -> str:
    methods = report["config"]["methods"]
    head = f"{'model':26s} {'method':7s} {'sets':>5s} {'ok':>5s} {'impl+w':>6s} {'failed':>6s} {'%':>6s}  reasons"
    lines = [head, "-" * len(head)]
    for label, entry in report["models"].items():
        for method in methods:
            row = entry[method]
            reasons = ", ".join(f"{c} {row['classes'][c]}" for c in (*CLASSES, "crash", "hang") if c in row["classes"])
            lines.append(
                f"{label:26s} {method:7s} {row['sets']:5d} {row['ok']:5d} {row['implausible_warned']:6d} "
                f"{row['failed']:6d} {row['failed_percent']:6.1f}  {reasons or '-'}"
            )
    cfg, m = report["config"], report["machine"]
    lines.append(
        f"({cfg['sets_per_model']} valid sets per model, seed {cfg['seed']}, every parameter varied in "
        f"{100 * cfg['all_prob']:.0f} % of them; impl+w: implausible and warned; {report['date']}; "
        f"{m['cpu']}, {m['cores']} cores, {m['system']}, Python {m['python']}, load {m['load_average_1min']}; "
        f"code {report['code']})"
    )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", nargs="?", type=int, default=150, help="valid sets per model (default 150)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--all-prob", type=float, default=0.1, help="fraction of sets that vary every parameter")
    ap.add_argument("--methods", nargs="+", default=["auto", "cvodes"])
    ap.add_argument("--timeout", type=float, default=60.0, help="wall-time bound of one run [s]")
    ap.add_argument("--json", type=Path, default=RESULTS)
    args = ap.parse_args(argv)
    report = run(args.n, args.seed, args.all_prob, args.methods, args.timeout)
    print(table(report))
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(report, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
