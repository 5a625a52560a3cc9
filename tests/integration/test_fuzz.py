"""Fuzz: random parameter sets inside the declared ranges of every built-in and example model (issue 10).

The harness is ``benchmarks/fuzz_models.py`` (its docstring says how sets are
drawn and runs classified). Each run is a ``system.simulate(params=...)`` in a
worker process with a bounded wall time. What every run must be, whatever the
parameters: ``ok``, a clean error (:class:`hydroservo.errors.HydroservoError`;
a solver failure naming the state and the time), or implausible *with* a
warning in ``result.warnings``; never a traceback of another exception, never a
hang. A batch must return every good run even when some of its runs fail.

The default suite runs 150 sets (fixed seed; one set in about thirty
varies every parameter, the rest 1 to 5, because the full sets are the ones
that fail, and fail slowly today); ``-m slow`` runs thousands. The two
acceptance points that need new API (``result.warnings``; a batch that marks
its failed runs, ``BatchResult.failed``) are ``xfail`` while the code lacks the
API and enforced as soon as it has it.

"Implausible" is the harness's definition (``benchmarks/fuzz_models.py``),
with hydroservo's documented margins (docs/reliability.md) but its own code: a
chamber more than :data:`PRESSURE_MARGIN` above the largest source pressure or
more than 1 % of it below vacuum, a piston more than 1 % of its stroke beyond
an end stop, a chamber volume at or below zero.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

FUZZ = Path(__file__).resolve().parents[2] / "benchmarks" / "fuzz_models.py"

#: How far above the largest source pressure (a fraction of its absolute pressure) a chamber may go before a run
#: is implausible: hydroservo's documented margin (docs/reliability.md), checked here by the harness's own code.
PRESSURE_MARGIN = 0.5
#: The default suite: sets per model (5 models: 150 in all), seed, bound of one run's wall time [s]. 30, not 50:
#: the default suite stays inside its 5 minutes; the slow suite runs 800 per model.
DEFAULT = {
    "n": 30,
    "seed": 4,
    "batch_size": 50,
    "timeout": 60.0,
    "all_prob": 0.03,
    "pressure_margin": PRESSURE_MARGIN,
}
#: The slow suite: thousands of sets (800 per model), one in ten varying every parameter.
SLOW = {"n": 800, "seed": 20, "batch_size": 200, "timeout": 60.0, "pressure_margin": PRESSURE_MARGIN}


def _harness() -> ModuleType:
    name = "hydroservo_fuzz_models"
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.spec_from_file_location(name, FUZZ)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


def _campaign(**kw: Any) -> dict[str, Any]:
    fz = _harness()
    report: dict[str, Any] = fz.fuzz(fz.Config(quiet=True, **kw))
    print(fz.format_report(report))  # shown by pytest when a test fails, or with -s
    return report


@pytest.fixture(scope="module")
def report() -> dict[str, Any]:
    return _campaign(**DEFAULT)


def _show(records: list[dict[str, Any]], keys: tuple[str, ...] = ("model", "index", "error_type", "message")) -> str:
    lines = []
    for r in records[:10]:
        lines.append(" ".join(f"{k}={str(r.get(k))[:300]}" for k in keys) + f"\n    params={r.get('params')}")
    return "\n".join(lines)


# -- what must hold today -------------------------------------------------------------------------
def _no_crash_no_hang(report: dict[str, Any]) -> None:
    records = report["records"]
    assert records, "no runs"
    crashes = [r for r in records if r["outcome"] == "crash"]
    hangs = [r for r in records if r["outcome"] == "hang"]
    assert not crashes, f"{len(crashes)} runs raised an exception that is not a HydroservoError:\n{_show(crashes)}"
    assert not hangs, (
        f"{len(hangs)} runs went over {report['config']['timeout']} s:\n{_show(hangs, ('model', 'index'))}"
    )
    bad = [b for b in report["batches"] if b.get("outcome") not in (None, "returned", "clean_error")]
    assert not bad, f"batches that crashed or hung: {bad}"


def _solver_errors_are_located(report: dict[str, Any]) -> None:
    unlocated = [
        r
        for r in report["records"]
        if r["outcome"] == "clean_error" and r.get("error_type") == "SolverError" and not r.get("located")
    ]
    assert not unlocated, f"solver errors that name no state or no time:\n{_show(unlocated)}"


def _every_run_classified(report: dict[str, Any]) -> None:
    fz = _harness()
    per_model = report["summary"]["per_model"]
    for label, row in per_model.items():
        assert sum(row[o] for o in fz.OUTCOMES) == row["runs"], label
    assert set(per_model) - {"total"} == set(report["models"])


def test_no_run_crashes_or_hangs(report: dict[str, Any]) -> None:
    _no_crash_no_hang(report)


def test_solver_errors_name_the_state_and_the_time(report: dict[str, Any]) -> None:
    _solver_errors_are_located(report)


def test_every_model_and_run_is_classified(report: dict[str, Any]) -> None:
    _every_run_classified(report)
    assert len(report["models"]) >= 5  # 2 built-in models, 3 example model files
    for label, model in report["models"].items():
        assert model["candidates"], label


# -- issue 10: enforced once the code has the feature ------------------------------------------------
def _has_warnings(report: dict[str, Any]) -> bool:
    """Whether results carry ``result.warnings`` (issue 10)."""
    return any(r.get("has_warnings_attr") for r in report["records"])


def _has_failure_marking(report: dict[str, Any]) -> bool:
    """Whether batch results mark failed runs (``BatchResult.failed``, issue 10)."""
    return any("failed" in (b.get("failure_marking") or {}) for b in report["batches"])


def _issue(i: dict[str, Any]) -> str:
    text = f"{i['check']} {i.get('signal')}"
    if isinstance(i.get("value"), float):
        text += f" = {i['value']:.4g} (bound {i.get('bound')})"
    if isinstance(i.get("ratio"), float):
        text += f", {i['ratio']:.3g} x the largest source"
    return text


def _implausible_runs_are_warned(report: dict[str, Any]) -> None:
    silent = [r for r in report["records"] if r["outcome"] == "implausible_silent"]
    if not _has_warnings(report):
        pytest.xfail(f"issue 10: results have no warnings yet ({len(silent)} implausible runs are silent)")
    assert not silent, (
        f"{len(silent)} finite but physically impossible results carry no result.warnings:\n"
        + "\n".join(
            f"  {r['model']} #{r['index']}: "
            + "; ".join(_issue(i) for i in r["issues"])
            + f"\n      params {r['params']}"
            for r in silent[:10]
        )
    )


def _batches_keep_good_runs(report: dict[str, Any]) -> None:
    mixed = [b for b in report["batches"] if b["kind"] == "mixed" and "note" not in b]
    assert mixed, "no run failed alone: no batch mixes good runs with a failing one"
    if not _has_failure_marking(report):
        raised = [b for b in mixed if b.get("outcome") != "returned"]
        pytest.xfail(
            f"issue 10: batches do not mark failed runs yet ({len(raised)} of {len(mixed)} mixed batches raised)"
        )
    for b in mixed:
        assert b.get("outcome") == "returned", (
            f"{b['model']}: a batch of {b['size']} sets, one of which fails alone ({b['failing_alone']}), "
            f"returned nothing: {b.get('error_type')}: {str(b.get('message'))[:200]}"
        )
        assert b["runs_returned"] == b["size"], b
        diff = b.get("good_runs_max_rel_diff")
        assert diff is not None and diff < 1e-6, f"{b['model']}: good runs differ from the same sets alone: {diff}"
        assert b.get("marked_failed") == [b["failing_index"]], (
            f"{b['model']}: run {b['failing_index']} fails alone (the others run well alone), but the batch marks "
            f"{b.get('marked_failed')} as failed: {b.get('failure_marking')}"
        )


def test_implausible_runs_carry_a_warning(report: dict[str, Any]) -> None:
    _implausible_runs_are_warned(report)


def test_a_batch_returns_its_good_runs_when_one_fails(report: dict[str, Any]) -> None:
    _batches_keep_good_runs(report)


# -- thousands ------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def large_report() -> dict[str, Any]:
    return _campaign(**SLOW)


@pytest.mark.slow
def test_thousands_of_sets_neither_crash_nor_hang(large_report: dict[str, Any]) -> None:
    _every_run_classified(large_report)
    _no_crash_no_hang(large_report)
    _solver_errors_are_located(large_report)


@pytest.mark.slow
def test_thousands_of_sets_implausible_runs_carry_a_warning(large_report: dict[str, Any]) -> None:
    _implausible_runs_are_warned(large_report)


@pytest.mark.slow
def test_thousands_of_sets_batches_return_their_good_runs(large_report: dict[str, Any]) -> None:
    _batches_keep_good_runs(large_report)
