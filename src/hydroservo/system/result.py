"""Simulation results: named signals with units; pandas, CSV, MAT and plots."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO

import numpy as np

from hydroservo.errors import ParameterError, SolverError, UnitError, did_you_mean
from hydroservo.units import UnitChoice, check_unit, convert, si_unit

if TYPE_CHECKING:
    import pandas as pd
    from matplotlib.figure import Figure

    from hydroservo.system.plausibility import Implausible

__all__ = ["Result", "BatchResult"]


#: What computes outputs of a result: names -> values (SI), only those asked for.
Outputs = Callable[[Sequence[str]], dict[str, np.ndarray]]


class _Signals:
    """Signals by name; outputs other than states are computed when first read, only those read."""

    t: np.ndarray
    model: str
    units: dict[str, str]
    _data: dict[str, np.ndarray]
    _outputs: Outputs | None
    _pending: dict[str, None]  # outputs not computed yet, in the model's order

    def _init_signals(self, data: dict[str, np.ndarray], outputs: Outputs | None, pending: Sequence[str]) -> None:
        self._data, self._outputs = data, outputs
        self._pending = dict.fromkeys(n for n in pending if n not in data) if outputs is not None else {}
        self._order = [*data, *self._pending]

    def _compute(self, names: Sequence[str]) -> None:
        assert self._outputs is not None
        self._data.update(self._outputs(list(names)))
        for name in names:
            self._pending.pop(name, None)

    @property
    def data(self) -> dict[str, np.ndarray]:
        """All signals (SI): the states, then the outputs, computed now if they were not read yet."""
        if self._pending:
            self._compute(list(self._pending))
            self._data = {n: self._data[n] for n in self._order if n in self._data} | self._data
        return self._data

    @property
    def names(self) -> list[str]:
        return [*self._data, *(n for n in self._pending if n not in self._data)]

    def __getitem__(self, name: str) -> np.ndarray:
        if name in ("t", "time"):
            return self.t
        if name in self._pending:
            self._compute([name])
        data = self._data if name in self._data else self.data
        try:
            return data[name]
        except KeyError:
            raise ParameterError(
                f"no signal {name!r} in the result of {self.model!r}{did_you_mean(name, self.data)}; signals: "
                f"{', '.join(self.data)}"
            ) from None

    #: The units the model shows its signals in (:meth:`hydroservo.system.System.unit_choice`); SI if none.
    unit_choice: UnitChoice

    panels: list[list[str]]

    def main_signals(self) -> list[str]:
        """The model's main signals, those of its plot panels (:attr:`panels`) in their order; all if none."""
        return list(dict.fromkeys(n for panel in self.panels for n in panel if n in self.units)) or list(self.names)

    def shown_units(self, units: Any = None) -> dict[str, str]:
        """The unit each signal is shown in: ``units`` (``"p=bar, mm"``, a mapping, ``"si"``;
        :class:`~hydroservo.units.UnitChoice`) over the model's own choice (:attr:`unit_choice`), else SI.

        Raises
        ------
        ParameterError
            If ``units`` names a signal the result does not have, or gives one a unit of another dimension.
        """
        asked = UnitChoice.parse(units, what="units")
        asked.check(self.units, "units")
        choice = asked.over(self.unit_choice)
        return {name: choice.unit(name, self.units.get(name, "")) for name in self.names}

    def get(self, name: str, unit: str | None = None) -> np.ndarray:
        """Signal ``name``, converted to ``unit`` if given (e.g. ``"psi"``; offsets too: ``"bar_abs"``, ``"degF"``)."""
        values = self[name]
        if unit is None:
            return values
        own = self.units.get(name, "")
        try:
            check_unit(unit)
        except UnitError as exc:
            raise UnitError(f"signal {name!r} of {self.model!r}: {exc}") from None
        try:
            converted: np.ndarray = convert(values, own, unit)
            return converted
        except UnitError:
            raise UnitError(
                f"signal {name!r} of {self.model!r} is in {si_unit(own)}: cannot show it in {unit!r}, a unit of another "
                "dimension"
            ) from None


class Result(_Signals):
    """One simulation run.

    ``result["cyl.pA"]`` is the signal in SI units; ``result.get("cyl.pA", "psi")``
    converts. ``result.t`` is the time [s]. :attr:`stats` holds solver statistics
    and the wall time; :attr:`params` the parameter values used (SI).
    """

    def __init__(
        self,
        t: np.ndarray,
        data: dict[str, np.ndarray],
        units: dict[str, str],
        descriptions: dict[str, str],
        stats: dict[str, Any],
        params: dict[str, float],
        model: str,
        outputs: Outputs | None = None,
        pending: Sequence[str] = (),
    ) -> None:
        self.t = t
        self._init_signals(data, outputs, pending)
        self.unit_choice = UnitChoice()
        self.units = units
        self.descriptions = descriptions
        self.stats = stats
        self.params = params
        self.model = model
        #: Physical bounds the run crossed (:mod:`hydroservo.system.plausibility`); empty if none.
        self.warnings: list[Implausible] = []
        #: The main signals, panel by panel, that :meth:`plot` shows without arguments (set by the system).
        self.panels: list[list[str]] = []

    def __repr__(self) -> str:
        from hydroservo.io.notebook import result_title

        return f"<{result_title(self)}>"

    def _repr_html_(self) -> str:
        """In a notebook: the run, its warnings, its main signals in the model's units, a plot, every signal."""
        from hydroservo.io.notebook import result_html

        return result_html(self)

    def summary(self, units: Any = None) -> dict[str, dict[str, Any]]:
        """Unit, final, minimum and maximum value of every signal, in the units shown (:meth:`shown_units`:
        the model's, ``units`` over them, ``"si"`` for SI)."""
        out = {}
        for n, unit in self.shown_units(units).items():
            v = self.get(n, unit)
            out[n] = {"unit": si_unit(unit), "final": float(v[-1]), "min": float(np.min(v)), "max": float(np.max(v))}
        return out

    def to_pandas(self, units: Any = None) -> pd.DataFrame:
        """A DataFrame indexed by time ``t`` [s], one column per signal named by the signal (``df["cyl.pA"]``),
        in the units shown (:meth:`shown_units`: the model's, ``units`` over them, ``"si"`` for SI); the unit of
        each column is in ``df.attrs["units"]``.

        Examples
        --------
        >>> import hydroservo as hs
        >>> r = hs.load_model("flight-simulator").simulate(t_end=0.05, n_points=6)
        >>> df = r.to_pandas(units="p=bar")
        >>> df.attrs["units"]["cyl.pA"], df.attrs["units"]["load.x"], round(float(df["cyl.pA"].iloc[0]), 1)
        ('bar', 'in', 53.2)
        """
        import pandas as pd

        shown = self.shown_units(units)
        df = pd.DataFrame({n: self.get(n, u) for n, u in shown.items()}, index=pd.Index(self.t, name="t"))
        df.attrs["units"] = {"t": "s", **{n: si_unit(u) for n, u in shown.items()}}
        return df

    def to_csv(self, path: str | Path, units: Any = None, ascii: bool = False) -> Path:
        """Write a CSV, one column ``signal [unit]`` per signal in the units shown (:meth:`shown_units`), UTF-8
        with a byte-order mark, or ASCII unit names (``m^3/s``) with ``ascii`` (:func:`hydroservo.io.results.write_csv`)."""
        from hydroservo.io.results import write_csv

        return write_csv(self, path, units=units, ascii=ascii)

    def to_mat(self, path: str | Path) -> Path:
        """Write a MATLAB .mat file (:func:`hydroservo.io.results.write_mat`)."""
        from hydroservo.io.results import write_mat

        return write_mat(self, path)

    def plot(
        self,
        *names: str | Sequence[str],
        units: Any = None,
        title: str | None = None,
        file: str | Path | BinaryIO | None = None,
    ) -> Figure:
        """Plot signals against time, one panel per argument (:func:`hydroservo.plotting.results.plot_result`).

        Without arguments, the main signals (:attr:`panels`). An argument may be
        a name or a list of names sharing a panel (same unit). Signals are shown
        in the model's units, ``units`` over them (``"p=bar, mm"``,
        ``{"y": "in"}``, ``"si"``; :meth:`shown_units`).

        Returns the figure. With ``file`` (``.png``, ``.svg``, ``.pdf``) it is
        written there and closed; without, it is shown where it can be: a
        notebook shows it (once, also as a cell's last value), a script with a display opens it in a window
        (``plt.show()``), and where there is no display a warning says to give
        ``file``.
        """
        from hydroservo.plotting.results import plot_result

        return plot_result(self, *names, units=self.shown_units(units), title=title, file=file,
                           show=None if file is None else False)


class BatchResult(_Signals):
    """Many runs: ``result["load.x"]`` has shape (runs, times); ``result.params`` the values per run.

    Runs fail on their own: :attr:`failed` maps the index of each failed run
    to its reason (its signals are NaN), :attr:`ok` marks the runs that
    succeeded, and :meth:`failed_params` gives a failed run's parameters to
    repeat it with :meth:`~hydroservo.system.System.simulate`, which says
    where and why it fails.
    """

    def __init__(
        self,
        t: np.ndarray,
        data: dict[str, np.ndarray],
        units: dict[str, str],
        params: dict[str, np.ndarray],
        stats: dict[str, Any],
        model: str,
        outputs: Outputs | None = None,
        failed: dict[int, str] | None = None,
        varied: Sequence[str] = (),
        param_units: dict[str, str] | None = None,
        pending: Sequence[str] = (),
    ) -> None:
        self.t, self.units, self.params, self.stats, self.model = t, units, params, stats, model
        self._init_signals(data, outputs, pending)
        self.unit_choice = UnitChoice()
        self.failed: dict[int, str] = dict(failed or {})
        #: The parameters the batch varied, and the units of all parameters (SI).
        self.varied = list(varied)
        self.param_units = dict(param_units or {})
        #: Physical bounds crossed, by run (:mod:`hydroservo.system.plausibility`).
        self.warnings: dict[int, list[Implausible]] = {}
        #: The model's main signals, panel by panel (set by the system): a notebook plots the first.
        self.panels: list[list[str]] = []

    def _repr_html_(self) -> str:
        """In a notebook: how many runs succeeded, each run's varied values and status, the family of the
        model's first main signal."""
        from hydroservo.io.notebook import batch_html

        return batch_html(self)

    def __len__(self) -> int:
        return int(self.stats["runs"])

    def __repr__(self) -> str:
        n, bad = len(self), len(self.failed)
        span = f"{self.t.size} times, {self.t[0]:g} to {self.t[-1]:g} s"
        return (
            f"<BatchResult of {self.model!r}: {n} runs, {n - bad} ok ({len(self.warnings)} implausible), {bad} failed; "
            f"varied {', '.join(self.varied) or 'nothing'}; {span}>"
        )

    def table(
        self,
        signal: str | None = None,
        *,
        unit: str | None = None,
        t_step: float = 0.0,
        y_final: float | None = None,
        reference: float | None = None,
        band: float = 0.02,
    ) -> pd.DataFrame:
        """A DataFrame, one row per run: varied parameters, status, and the step metrics of ``signal``
        (:func:`hydroservo.analysis.study.metrics_table`)."""
        from hydroservo.analysis.study import metrics_table

        return metrics_table(
            self, signal, unit=unit, t_step=t_step, y_final=y_final, reference=reference, band=band
        )

    def plot(
        self,
        signal: str,
        *,
        unit: str | None = None,
        color_by: str | None = None,
        title: str | None = None,
        file: str | Path | BinaryIO | None = None,
    ) -> Figure:
        """The family of curves of ``signal``, one per run that did not fail, coloured by the value of
        ``color_by`` (default: the first varied parameter) (:func:`hydroservo.plotting.study.plot_family`), in
        ``unit`` (default: the model's unit for it, :meth:`shown_units`)."""
        from hydroservo.plotting.study import plot_family

        if unit is None and signal in self.units:
            unit = self.shown_units().get(signal)

        return plot_family(self, signal, unit=unit, color_by=color_by, title=title, file=file)

    @property
    def ok(self) -> np.ndarray:
        """True for every run that succeeded."""
        mask = np.ones(len(self), dtype=bool)
        mask[list(self.failed)] = False
        return mask

    def failed_params(self, k: int) -> dict[str, float]:
        """Parameters (SI) of run ``k``."""
        return {n: float(v[k]) for n, v in self.params.items()}

    def summary(self) -> str:
        """One line: how many runs succeeded and failed, and the most common reasons."""
        n, bad = len(self), len(self.failed)
        text = f"{n - bad} of {n} runs succeeded ({len(self.warnings)} with physically implausible results), {bad} failed"
        if bad:
            reasons: dict[str, int] = {}
            for r in self.failed.values():
                reasons[r] = reasons.get(r, 0) + 1
            common = sorted(reasons.items(), key=lambda kv: -kv[1])[:3]
            text += ": " + "; ".join(f"{c} x {r}" for r, c in common)
        return text

    def run(self, k: int) -> Result:
        """Run ``k`` as a :class:`Result`."""
        if not -len(self) <= k < len(self):
            raise ParameterError(f"run {k}: the batch has runs 0 to {len(self) - 1}")
        k %= len(self)
        if k in self.failed:
            raise SolverError(f"run {k} of the batch of {self.model!r} failed: {self.failed[k]}")
        result = Result(
            self.t,
            {n: v[k] for n, v in self.data.items()},
            self.units,
            {},
            {},
            {n: float(v[k]) for n, v in self.params.items()},
            self.model,
        )
        result.warnings = list(self.warnings.get(k, []))
        result.unit_choice = self.unit_choice
        return result
