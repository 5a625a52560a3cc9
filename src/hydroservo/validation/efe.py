"""The Stribeck friction of [Efe2014] Table 5.2: its simulated column and its error column from the thesis's
parameters, and the law fitted again to its experimental column."""

from __future__ import annotations

import numpy as np

from hydroservo.data import parameter_set
from hydroservo.identification.friction import fit_stribeck, relative_errors
from hydroservo.laws.friction import stribeck
from hydroservo.units import to_si
from hydroservo.validation import Row, printed_digit

__all__ = ["rows", "compute"]

_SRC = "Efe2014"
_WHERE = f"{_SRC} Table 5.2"


def _table() -> dict[str, list[str]]:
    return parameter_set(_SRC).table("table_5_2")


def _published() -> dict[str, float]:
    pset = parameter_set(_SRC)
    return {
        "c_s": pset.si("stribeck", "c_s", "m/s"), "F_v": pset.si("stribeck", "F_v", "N*s/m"),
        "F_c0": pset.si("stribeck", "F_c0", "N"), "F_s0": pset.si("stribeck", "F_s0", "N"),
    }


def _columns() -> tuple[np.ndarray, np.ndarray]:
    t = _table()
    return np.array([to_si(v, "m/s") for v in t["velocity"]]), np.array([to_si(f, "N") for f in t["experimental"]])


def rows() -> list[Row]:
    """The simulated force and the relative error at each velocity of Table 5.2, from the thesis's parameters;
    and the law fitted to the experimental column: its largest error against the thesis's, and its viscous and
    Coulomb coefficients against the thesis's."""
    t = _table()
    out = [
        Row(
            f"F_f({v})", f"friction force at {v}", f"{_WHERE}, eq. 3.47", to_si(force, "N"), "N", 0.005,
            "the table prints two decimals: half a unit in the last place",
            "eq. 3.47 with the table's c_s, F_v, F_c0, F_s0 (the published law, sign not smoothed)", "reproduced",
        )
        for v, force in zip(t["velocity"], t["simulated"], strict=True)
    ]
    out += [
        Row(
            f"error({v})", f"relative error of the law at {v}", f"{_WHERE}, error column", float(err.split()[0]), "%",
            0.5 * printed_digit(err) + 1e-9,
            "two decimals printed: half a unit in the last place",
            "(experimental - simulated) / experimental, the simulated force from eq. 3.47 with the table's parameters",
            "reproduced",
        )
        for v, err in zip(t["velocity"], t["relative_error"], strict=True)
    ]
    worst = max(abs(float(e.split()[0])) for e in t["relative_error"])
    out += [
        Row(
            "max|error| refit", "largest relative error of the law fitted to the experimental column", f"{_WHERE}, error column",
            worst, "%", 0.0, "a least-squares fit of the same law to the same six forces can only do as well or better",
            "hydroservo.identification.fit_stribeck on the experimental column (least squares on the relative errors)",
            "reproduced", upper_bound=True,
        ),
        Row(
            "F_v refit", "viscous coefficient F_v fitted to the experimental column", f"{_WHERE}, friction model parameters",
            _published()["F_v"], "N*s/m", 2 * 30.7,
            "two standard errors of the refit (30.7 N s/m: six forces, four parameters)",
            "fit_stribeck on the experimental column", "reproduced",
        ),
        Row(
            "F_c0 refit", "Coulomb force F_c0 fitted to the experimental column", f"{_WHERE}, friction model parameters",
            _published()["F_c0"], "N", 2 * 2.4,
            "two standard errors of the refit (2.4 N); F_s0 and c_s are not determined by the table, whose slowest "
            "speed is the thesis's c_s itself (docs/calibration.md)",
            "fit_stribeck on the experimental column", "reproduced",
        ),
    ]
    return out


def compute() -> dict[str, float]:
    """The friction force of eq. 3.47 and its relative error at each velocity of the table; the refit's figures."""
    t = _table()
    pub = _published()
    v, experimental = _columns()
    simulated = np.asarray(stribeck(v, pub["F_v"], pub["F_c0"], pub["F_s0"], pub["c_s"]))
    errors = relative_errors(experimental, simulated)
    out = {f"F_f({name})": float(f) for name, f in zip(t["velocity"], simulated)}
    out.update({f"error({name})": float(e) for name, e in zip(t["velocity"], errors)})
    fit = fit_stribeck(v, experimental)
    out["max|error| refit"] = float(np.max(np.abs(fit.relative_error)))
    out["F_v refit"] = fit.parameters["B"]
    out["F_c0 refit"] = fit.parameters["F_c0"]
    return out
