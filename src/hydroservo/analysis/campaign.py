"""Many runs of one system, in chunks: on local threads, or on a Dask cluster, written as they arrive.

:func:`run_design` runs a design (parameter name -> one SI value per run) and
returns one row per run: the parameters, every metric
(:mod:`hydroservo.analysis.metrics`), the run's status (``ok``,
``implausible``, ``failed``) and why. The runs go in chunks; each chunk is one
:meth:`~hydroservo.system.model.Model.batch` (the integrator mapped over the
runs on threads) whose signals are reduced to the metrics at once, so memory
stays bounded however many runs there are.

* **Locally** (default) the chunks run one after the other, each on all the
  machine's threads.
* **On a cluster** (``scheduler``: a ``dask.distributed.Client`` or the
  address of a scheduler) each chunk is one task; a worker builds the model
  once (the compiled model is cached per worker process) and returns only
  the metrics. A chunk is sized to take about a second, enough to pay for its
  scheduling. The numbers are the same as locally: the same runs through
  the same integrator.
* **Written as they arrive**: with a ``store`` (:class:`hydroservo.io.RunStore`)
  every finished chunk is written at once; a study started again with the
  same store skips the chunks written, so an interrupted study resumes.
* **Failures** are rows like the others, with their reason: one run failing
  never loses the rest. A run the solver gives up on is tried once more,
  alone, at a tolerance ten times tighter (its ``reason`` says so when that
  succeeds): a rare error-test failure at a kink of the equations (a
  valve's hysteresis switching) would otherwise cost a Sobol study every
  index of every metric.
* ``progress(done, failed, total, elapsed)`` is called after every chunk.
"""

from __future__ import annotations

import math
import pickle
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np

from hydroservo.analysis.metrics import Metric, describe, metrics_of
from hydroservo.errors import HydroservoError, ParameterError

if TYPE_CHECKING:
    import pandas as pd

    from hydroservo.system.system import System

__all__ = ["run_design", "Store", "Runs"]

#: Runs per chunk when the caller does not say: a chunk of the robot arm takes about a second on one core.
DEFAULT_CHUNK = 128


class Store(Protocol):
    """Where chunks are written as they arrive (:class:`hydroservo.io.RunStore` is one)."""

    def done(self) -> set[tuple[int, int]]: ...

    def write(self, first: int, end: int, frame: pd.DataFrame) -> Any: ...

    def load(self) -> pd.DataFrame: ...


@dataclass
class Runs:
    """The runs of a design: a DataFrame (index ``run``) and what produced it."""

    table: pd.DataFrame
    parameters: list[str]
    metrics: list[Metric]
    stats: dict[str, Any]

    @property
    def columns(self) -> list[str]:
        """The metric columns, ``"final(x_mm) [mm]"``."""
        return [describe(m) for m in self.metrics]

    def values(self) -> np.ndarray:
        """The metrics (runs x metrics); NaN for failed runs."""
        return self.table[self.columns].to_numpy(dtype=float)

    @property
    def failed(self) -> dict[int, str]:
        bad = self.table[self.table["status"] == "failed"]
        return {int(k): str(v) for k, v in bad["reason"].items()}


# -- one chunk: the same function locally and on a worker --------------------------------------------
_MODELS: dict[bytes, Any] = {}  # per process: the system's pickle -> (system, built model)


def _system(blob: bytes) -> tuple[Any, Any]:
    key = blob
    if key not in _MODELS:
        system = pickle.loads(blob)
        _MODELS.clear()  # one study at a time per worker: do not hoard compiled models
        _MODELS[key] = (system, system.build())
    return _MODELS[key]


def _chunk(
    blob: bytes,
    first: int,
    sets: dict[str, list[Any]],
    metrics: list[Metric],
    t_end: float,
    n_points: int,
    rtol: float,
    threads: int | None,
    max_steps: int | None = None,
) -> tuple[int, np.ndarray, list[str], list[str]]:
    """Run one chunk; returns (first, metrics (runs x metrics), status, reason)."""
    import warnings

    from hydroservo.errors import ImplausibleResultWarning

    system, _ = _system(blob)
    n = len(next(iter(sets.values())))
    status, reason = ["ok"] * n, [""] * n
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ImplausibleResultWarning)  # reported per run in the table
            batch = system.batch(sets, t_end, n_points=n_points, rtol=rtol, threads=threads, max_steps=max_steps)
    except HydroservoError as exc:  # the whole chunk refused (a parameter out of range): every run says why
        return first, np.full((n, len(metrics)), np.nan), ["failed"] * n, [str(exc)] * n
    names = sorted({s for m in metrics for s in m.signals} | ({*batch.names} if any(m.function for m in metrics) else set()))
    signals = {name: batch[name] for name in names}
    values = metrics_of(metrics, batch.t, signals)
    for k, found in batch.warnings.items():
        status[k], reason[k] = "implausible", "; ".join(str(w) for w in found)
    for k, why in batch.failed.items():
        status[k], reason[k] = "failed", why
        values[k] = np.nan
        # a run the solver gave up on (an error test failing at a kink of the equations) gets one more try, alone,
        # at a tolerance ten times tighter; a run refused for its parameters fails again at once
        one = {key: [column[k]] for key, column in sets.items()}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ImplausibleResultWarning)
                again = system.batch(one, t_end, n_points=n_points, rtol=rtol / 10, max_steps=1_000_000, threads=1)
        except HydroservoError:
            continue
        if 0 in again.failed:
            continue
        values[k] = metrics_of(metrics, again.t, {name: again[name] for name in names})[0]
        status[k] = "implausible" if 0 in again.warnings else "ok"
        reason[k] = f"solved at rtol {rtol / 10:g} after: {why}" + (
            "; " + "; ".join(str(w) for w in again.warnings[0]) if 0 in again.warnings else ""
        )
    return first, values, status, reason


# -- the design ---------------------------------------------------------------------------------------
def _frame(first: int, sets: Mapping[str, np.ndarray], metrics: list[Metric], values: np.ndarray,
           status: list[str], reason: list[str], units: Mapping[str, str]) -> pd.DataFrame:
    import pandas as pd

    from hydroservo.units import si_unit

    n = len(status)
    data: dict[str, Any] = {f"{k} [{si_unit(units.get(k, ''))}]": np.asarray(v, dtype=float) for k, v in sets.items()}
    for j, m in enumerate(metrics):
        data[describe(m)] = values[:, j]
    data["status"], data["reason"] = status, reason
    return pd.DataFrame(data, index=pd.RangeIndex(first, first + n, name="run"))


def _client(scheduler: Any) -> Any:
    if scheduler is None:
        return None
    if isinstance(scheduler, str):
        try:
            from distributed import Client
        except ImportError:
            raise ParameterError(
                f"scheduler {scheduler!r}: running on a Dask cluster needs dask.distributed: pip install 'hydroservo[cluster]'"
            ) from None
        try:
            return Client(scheduler, timeout="5s")
        except (OSError, TimeoutError) as exc:
            raise ParameterError(f"scheduler {scheduler!r}: cannot connect ({exc}); expected a running Dask scheduler's address") from None
    return scheduler


def _si(system: System, key: str, values: list[Any]) -> np.ndarray:
    """A design column in SI for the table (NaN where a value cannot be read: its run fails with the reason)."""
    cname, pname = key.split(".", 1)
    out = np.full(len(values), np.nan)
    for i, v in enumerate(values):
        try:
            out[i] = system[cname].parse(pname, v) if isinstance(v, str) else float(v)
        except (HydroservoError, TypeError, ValueError):
            pass
    return out


def run_design(
    system: System,
    design: Mapping[str, Sequence[float] | np.ndarray],
    metrics: Sequence[Metric],
    *,
    t_end: float | None = None,
    n_points: int = 301,
    rtol: float = 1e-6,
    max_steps: int | None = None,
    chunk: int | None = None,
    threads: int | None = None,
    scheduler: Any = None,
    store: Store | None = None,
    progress: Callable[[int, int, int, float], None] | None = None,
) -> Runs:
    """Run every point of ``design`` (name -> SI values, one per run) and measure ``metrics`` (module notes)."""
    import pandas as pd

    t_end = system.t_end if t_end is None else float(t_end)
    model = system.build()
    keys = [system.parameter_key(k) for k in design]
    raw = {key: list(np.atleast_1d(np.asarray(v, dtype=object)).ravel()) for key, v in zip(keys, design.values(), strict=True)}
    columns = {key: _si(system, key, values) for key, values in raw.items()}
    sizes = {v.size for v in columns.values()}
    if len(sizes) != 1:
        raise ParameterError(f"design: every parameter needs one value per run; got {sorted(sizes)} values")
    n = sizes.pop()
    if n == 0:
        raise ParameterError("design: no runs")
    if not metrics:
        raise ParameterError("design: no metrics to measure")
    size = int(chunk or DEFAULT_CHUNK)
    if size < 1:
        raise ParameterError(f"chunk = {chunk!r}: expected at least one run per chunk")
    ranges = [(i, min(i + size, n)) for i in range(0, n, size)]
    done = store.done() if store is not None else set()
    todo = [r for r in ranges if r not in done]
    blob = pickle.dumps(system)
    units = dict(model.parameter_units)
    start = time.perf_counter()
    frames: dict[int, pd.DataFrame] = {}
    count = {"done": sum(e - f for f, e in ranges if (f, e) in done), "failed": 0}
    if store is not None and done:
        old = store.load()
        count["failed"] = int((old["status"] == "failed").sum())

    def finish(first: int, values: np.ndarray, status: list[str], reason: list[str]) -> None:
        end = first + len(status)
        frame = _frame(first, {k: v[first:end] for k, v in columns.items()}, list(metrics), values, status, reason, units)
        if store is not None:
            store.write(first, end, frame)
        frames[first] = frame
        count["done"] += end - first
        count["failed"] += status.count("failed")
        if progress is not None:
            progress(count["done"], count["failed"], n, time.perf_counter() - start)

    client = _client(scheduler)
    owns = client is not None and isinstance(scheduler, str)
    try:
        if client is None:
            for first, end in todo:
                sets = {k: v[first:end] for k, v in raw.items()}
                finish(*_chunk(blob, first, sets, list(metrics), t_end, n_points, rtol, threads, max_steps))
        else:
            from distributed import as_completed

            shared = client.scatter(blob, broadcast=True)
            futures = [
                client.submit(
                    _chunk, shared, first, {k: v[first:end] for k, v in raw.items()}, list(metrics),
                    t_end, n_points, rtol, 1, max_steps, pure=False,
                )
                for first, end in todo
            ]
            for future in as_completed(futures):
                finish(*future.result())
    finally:
        if owns:
            client.close()
    wall = time.perf_counter() - start
    if store is not None:
        table = store.load()
    else:
        table = pd.concat([frames[k] for k in sorted(frames)]) if frames else pd.DataFrame()
    ran = sum(e - f for f, e in todo)
    stats = {
        "runs": n,
        "run_now": ran,
        "resumed": n - ran,
        "chunks": len(ranges),
        "chunk": size,
        "failed": int((table["status"] == "failed").sum()),
        "implausible": int((table["status"] == "implausible").sum()),
        "wall_time_s": wall,
        "runs_per_s": ran / wall if wall > 0 else math.inf,
        "where": "local" if client is None else "dask",
    }
    return Runs(table, keys, list(metrics), stats)
