"""Make the Hopsan reference traces of ``hydroservo/data/reference/hopsan/``: Hopsan's own results, converged.

Needs Hopsan's command-line simulator built from source (``../shared/tools/hopsan/build_hopsan.sh`` in the
development setup: ``hopsancli``) and a clone of Hopsan's repository for its model files::

    python scripts/hopsan_references.py --cli $HOPSAN_ROOT/install/bin/hopsancli --source path/to/hopsan

For each model of :data:`hydroservo.validation.hopsan_examples.MODELS` it runs Hopsan at its own time step and at
steps halved again and again, logging the positions, velocities, forces, pressures and flows of its ports (one column per
Hopsan node; the variables are the imported model's aliases of those kinds) and its signal outputs, until two successive halvings
change no trace by more than ``--tol`` of its range, or ``--levels`` halvings are done, or two halvings in a
row bring no improvement (at very small steps Hopsan's accumulated time and round-off make the result drift
again): the runs that end with the smallest change are used. Hopsan's scheme
converges to first order in the step; the order is estimated from the last three runs and the result
extrapolated (Richardson) to a vanishing step. It writes ``NAME.csv`` (time and the extrapolated traces, SI,
pressures absolute as Hopsan logs them), ``NAME.toml`` (the model as ``hydroservo import-hopsan`` writes it) and adds the provenance to ``hopsan_examples.json``: the model file's
SHA-256, the steps, the convergence table (largest change per halving, % of range), the order and the estimated
uncertainty of the extrapolation (how far it moved from the one a halving earlier).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
OUT = HERE.parent / "src" / "hydroservo" / "data" / "reference" / "hopsan"


#: component types Hopsan's GUI renames when it loads an older model (HopsanGUI/Utilities/XMLUtilities.cpp,
#: updateHmfComponentProperties), which hopsancli does not: such a model is run as the GUI would load it
GUI_RENAMES = {"MechanicRotationalInertiaWithCoulumbFriction": "MechanicRotationalInertiaWithCoulombFriction"}


def run_hopsan(
    cli: Path, model: Path, h: float, t0: float, t1: float, samples: int, renamed: tuple[tuple[str, str], ...] = ()
) -> dict[str, np.ndarray]:
    """Hopsan's logged variables (``Comp#Port#Var`` -> trace) of one run at step ``h``; with ``renamed``, of a
    copy of the model with those components renamed (old, new), beside links to the files of its folder (a
    lookup table's CSV), its variables named back; a model with types of :data:`GUI_RENAMES`, of a copy with
    them renamed as Hopsan's GUI does."""
    with tempfile.TemporaryDirectory() as tmp:
        if renamed or any(f'typename="{old}"' in model.read_text(encoding="utf-8") for old in GUI_RENAMES):
            model = _renamed_copy(model, Path(tmp), renamed)
        out = Path(tmp) / "out.csv"
        cmd = [str(cli), "-m", str(model), "-s", f"{t0!r},{h!r},{t1!r}", "-l", str(samples),
               "--resultsFullCSV", str(out), "--resultsCSVSort", "cols"]
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
        if done.returncode != 0 or not out.exists():
            raise RuntimeError(f"hopsancli failed on {model.name} at step {h:g}: {done.stdout[-2000:]}{done.stderr[-2000:]}")
        lines = out.read_text().splitlines()
    names = lines[0].split(",")
    back = {f"{new}#": f"{old}#" for old, new in renamed}
    names = [next((back[k] + name[len(k):] for k in back if name.startswith(k)), name) for name in names]
    data = np.array([[float(v) for v in line.split(",")] for line in lines[3:] if line.strip()])
    return {name: data[:, i] for i, name in enumerate(names)}


def _renamed_copy(model: Path, folder: Path, renamed: tuple[tuple[str, str], ...]) -> Path:
    """A copy of ``model`` in ``folder`` with components renamed (their names and the connections' ends) and the
    types of :data:`GUI_RENAMES` renamed, and links to the other files of the model's folder, which the model may
    name relative to itself."""
    for other in model.parent.iterdir():
        if other.is_file() and other != model:
            (folder / other.name).symlink_to(other)
    text = model.read_text(encoding="utf-8")
    for old_type, new_type in GUI_RENAMES.items():
        text = text.replace(f'typename="{old_type}"', f'typename="{new_type}"')
    for old, new in renamed:
        for attribute in ("name", "startcomponent", "endcomponent"):
            text = re.sub(rf'(\s{attribute}=)"{re.escape(old)}"', rf'\1"{new}"', text)
    copy = folder / model.name
    copy.write_text(text, encoding="utf-8")
    return copy


def variables(model: Path, logged: set[str]) -> dict[str, str]:
    """Hopsan variable -> the imported model's alias: one per node (the first port of it Hopsan logs), of the
    positions, velocities, pressures and flows, and each signal output (``Comp#out#Value``)."""
    from hydroservo.io.hopsan_library import import_hopsan

    imported = import_hopsan(model)
    chosen: dict[str, str] = {}
    seen: set[str] = set()
    for name, alias in imported.system.aliases.items():
        var = imported.variables[name]
        kind = name.rsplit(".", 1)[-1]
        if kind in KINDS and var in logged and alias.expr not in seen:
            seen.add(alias.expr)
            chosen[var] = name
            if kind == "Value":
                UNITS[var] = alias.unit or "1"
    return chosen


#: the kinds of variable compared (the last part of an alias); "Value" is a signal's
KINDS = ("Position", "Velocity", "Force", "Angle", "AngularVelocity", "Torque", "Pressure", "Flow", "Value")
#: Hopsan variable -> the unit of its alias (signals have the unit of what they carry)
UNITS: dict[str, str] = {}


def jumps(y: np.ndarray) -> np.ndarray:
    """The samples next to a jump of a trace (a change of more than a fifth of its range from one sample to the
    next: a source's edge, and the signals it passes through at once). At such a sample Hopsan logs one side or
    the other depending on the step's round-off, so it neither measures convergence nor is extrapolated: the
    finest run's value is kept, and the comparison takes the model either side of it."""
    span = float(np.ptp(y))
    big = np.abs(np.diff(y)) > 0.2 * span if span > 0 else np.zeros(len(y) - 1, dtype=bool)
    near = np.zeros(len(y), dtype=bool)
    near[:-1] |= big
    near[1:] |= big
    return near


def main() -> int:
    from hydroservo.validation.hopsan_examples import MODELS

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", type=Path, required=True, help="hopsancli")
    ap.add_argument("--source", type=Path, required=True, help="a clone of Hopsan's repository")
    ap.add_argument("--samples", type=int, default=501)
    ap.add_argument("--levels", type=int, default=14, help="most halvings of the step")
    ap.add_argument("--tol", type=float, default=1e-4, help="change between halvings to stop at, fraction of range")
    ap.add_argument("--commit", default="", help="Hopsan's commit, when --source is no git clone (an archive)")
    ap.add_argument("--toml-only", action="store_true", help="only write the imported models again (NAME.toml)")
    ap.add_argument("--finest", action="store_true",
                    help="extrapolate from the three finest runs, not from those that end with the smallest change "
                         "(a model some of whose traces do not converge: each trace's uncertainty is recorded)")
    ap.add_argument("--min-step", type=float, default=0.0,
                    help="halve the step at least down to this [s] before stopping (a model whose traces move between "
                         "two samples faster than the sampling shows: the samples on such an edge count as jumps, "
                         "and the change between halvings does not see them converge)")
    ap.add_argument("names", nargs="*", help="models (default: all)")
    args = ap.parse_args()
    OUT.mkdir(parents=True, exist_ok=True)
    index_path = OUT / "hopsan_examples.json"
    index = json.loads(index_path.read_text()) if index_path.exists() else {}
    commit = args.commit or subprocess.run(
        ["git", "-C", str(args.source), "rev-parse", "HEAD"], capture_output=True, text=True
    ).stdout.strip()
    for name, spec in MODELS.items():
        if args.names and name not in args.names:
            continue
        model = args.source / "Models" / spec.path
        from hydroservo.io.hopsan import read_hmf
        from hydroservo.workflows.hopsan import ImportHopsan

        if args.toml_only:
            (OUT / f"{name}.toml").write_text(ImportHopsan(model).run().text, encoding="utf-8")
            continue

        hmf = read_hmf(model)
        h = spec.timestep or hmf.timestep
        chosen = variables(model, set(run_hopsan(args.cli, model, h, hmf.start, hmf.stop, 3, spec.renamed)))
        runs: list[tuple[float, dict[str, np.ndarray], float]] = []
        table = []
        for _ in range(args.levels + 1):
            started = time.perf_counter()
            result = run_hopsan(args.cli, model, h, hmf.start, hmf.stop, args.samples, spec.renamed)
            runs.append((h, result, time.perf_counter() - started))
            if len(runs) >= 2:
                change = {v: _rel(np.where(jumps(runs[-1][1][v]) | jumps(runs[-2][1][v]), 0.0, runs[-1][1][v] - runs[-2][1][v]),
                                  runs[-1][1][v]) for v in chosen}
                worst = max(change.values())
                table.append({"step": h, "largest_change_percent": 100 * worst, "seconds": runs[-1][2]})
                print(f"{name}: step {h:.3g} s, largest change {100 * worst:.4f} % of range ({runs[-1][2]:.1f} s)",
                      file=sys.stderr)
                settled = len(table) >= 2 and table[-2]["largest_change_percent"] < 1.0  # both halvings converging
                if args.min_step > 0.0 and h > args.min_step * (1.0 + 1e-9):
                    h /= 2.0
                    continue
                if worst < args.tol and settled:
                    break
                best = min(range(len(table)), key=lambda k: table[k]["largest_change_percent"])
                # within ten times the tolerance: a change that then grows again is round-off; a larger one may be a
                # convergence that is not monotonic yet (a relief valve's limit cycle changing phase as the step halves)
                converging = table[best]["largest_change_percent"] < 1000 * args.tol
                if converging and len(table) - 1 - best >= 2:  # two halvings without progress: round-off rules
                    break
            h /= 2.0
        # the three runs that end with the smallest change (past it, Hopsan's accumulated time and round-off grow)
        last = len(table) if args.finest else 1 + min(range(len(table)), key=lambda k: table[k]["largest_change_percent"])
        table = table[:last]
        last = max(last, 2)
        runs = runs[: last + 1]
        r2, r1, r0 = runs[-3][1], runs[-2][1], runs[-1][1]
        t = r0["Time"]
        out = {"t [s]": t}
        orders, uncertainty = {}, {}
        for var, alias in chosen.items():
            edge = jumps(r0[var]) | jumps(r1[var]) | jumps(r2[var])
            d1 = np.where(edge, 0.0, r1[var] - r2[var])
            d0 = np.where(edge, 0.0, r0[var] - r1[var])
            n1, n0 = np.max(np.abs(d1)), np.max(np.abs(d0))
            order = float(np.log2(n1 / n0)) if n0 > 0 and n1 > 0 else 1.0
            order = min(max(order, 0.5), 2.0)
            extrapolated = r0[var] + d0 / (2.0**order - 1.0)
            before = np.where(edge, r0[var], r1[var] + d1 / (2.0**order - 1.0))  # the same one a halving earlier
            out[f"{alias} [{UNITS.get(var) or _unit(var)}]"] = extrapolated
            orders[alias] = round(order, 2)
            uncertainty[alias] = 100 * _rel(extrapolated - before, extrapolated)
        header = ",".join(out)
        rows = np.column_stack(list(out.values()))
        np.savetxt(OUT / f"{name}.csv", rows, delimiter=",", header=header, comments="", fmt="%.10g")
        (OUT / f"{name}.toml").write_text(ImportHopsan(model).run().text, encoding="utf-8")
        index[name] = {
            "model": f"Models/{spec.path}",
            "sha256": hashlib.sha256(model.read_bytes()).hexdigest(),
            "hopsan_commit": commit,
            "start": hmf.start,
            "stop": hmf.stop,
            "hopsan_step": hmf.timestep,
            "steps": [r[0] for r in runs],
            "convergence": table,
            "order": orders,
            "extrapolation_uncertainty_percent": {k: round(v, 5) for k, v in uncertainty.items()},
            "samples": args.samples,
            **({"min_step": args.min_step} if args.min_step else {}),
            **({"finest": True} if args.finest else {}),
        }
        index_path.write_text(json.dumps(index, indent=1) + "\n")
        print(f"{name}: wrote {OUT / f'{name}.csv'}", file=sys.stderr)
    return 0


def _rel(diff: np.ndarray, ref: np.ndarray) -> float:
    span = float(np.ptp(ref))
    return float(np.max(np.abs(diff))) / span if span > 0 else float(np.max(np.abs(diff)))


def _unit(var: str) -> str:
    return {"Position": "m", "Velocity": "m/s", "Force": "N", "Angle": "rad", "AngularVelocity": "rad/s",
            "Torque": "N*m", "Pressure": "Pa", "Flow": "m^3/s"}[var.rsplit("#", 1)[-1]]


if __name__ == "__main__":
    sys.exit(main())
