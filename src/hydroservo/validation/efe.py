"""Stribeck friction against Table 5.2 of [Efe2014] (simulated column)."""

from __future__ import annotations

from hydroservo.data import parameter_set
from hydroservo.laws.friction import stribeck
from hydroservo.units import to_si
from hydroservo.validation import Row

__all__ = ["rows", "compute"]

_SRC = "Efe2014"


def _table() -> list[tuple[str, str]]:
    table = parameter_set(_SRC).table("table_5_2")
    return list(zip(table["velocity"], table["simulated"], strict=True))


def rows() -> list[Row]:
    """One row per velocity of Table 5.2: the simulated friction force as printed."""
    return [
        Row(
            f"F_f({v})",
            f"friction force at {v}",
            f"{_SRC} Table 5.2, eq. 3.47",
            to_si(force, "N"),
            "N",
            0.005,
            "the table prints two decimals: half a unit in the last place",
            "eq. 3.47 with the table's c_s, F_v, F_c0, F_s0 (the published law, sign not smoothed)",
            "reproduced",
        )
        for v, force in _table()
    ]


def compute() -> dict[str, float]:
    """The friction force of eq. 3.47 at each velocity of the table."""
    pset = parameter_set(_SRC)
    c_s, F_v = pset.si("stribeck", "c_s", "m/s"), pset.si("stribeck", "F_v", "N*s/m")
    F_c0, F_s0 = pset.si("stribeck", "F_c0", "N"), pset.si("stribeck", "F_s0", "N")
    return {f"F_f({v})": float(stribeck(to_si(v, "m/s"), F_v, F_c0, F_s0, c_s)) for v, _ in _table()}
