"""Every reader and writer of hydroservo's files.

=======================  ========================================================
module                   files
=======================  ========================================================
:mod:`.model_file`       model files (TOML): systems, built-in models by name
:mod:`.component_file`   component parameter files (TOML), staged-slot valve files
:mod:`.datasheet`        valve datasheets (TOML)
:mod:`.curves`           measured curves (CSV): static curves, test-bench curves
:mod:`.bode`             Bode data (CSV)
:mod:`.tables`           time tables (CSV) of recorded signals
:mod:`.results`          simulation results (CSV, MAT)
:mod:`.records`          rig records (CSV, one file per sample rate)
:mod:`.linear`           operating points (TOML) and linear models (JSON)
:mod:`.runs`             the runs of a study, written as they arrive (Parquet parts)
:mod:`.toml`             the TOML reader and value writer they share
=======================  ========================================================

A model written as code (C, an FMU) is :mod:`hydroservo.codegen`'s. A new file format gets a module here; nothing outside this package opens a
user's file. (The package's own data files are found by :mod:`hydroservo.data`.)

Names are imported on first use (PEP 562): reading a model file must not load
SciPy's optimisers (the datasheet reader's fit) or pandas.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

#: Public name -> the module that defines it.
_LAZY: dict[str, str] = {
    "read_bode": "hydroservo.io.bode",
    "read_hmf": "hydroservo.io.hopsan",
    "read_hopsan": "hydroservo.io.hopsan_library",
    "write_bode": "hydroservo.io.bode",
    "component_file_text": "hydroservo.io.component_file",
    "component_toml": "hydroservo.io.component_file",
    "read_component_file": "hydroservo.io.component_file",
    "read_staged_slot_valve": "hydroservo.io.component_file",
    "staged_slot_valve_toml": "hydroservo.io.component_file",
    "read_bench_curves": "hydroservo.io.curves",
    "read_csv_table": "hydroservo.io.curves",
    "read_static_curves": "hydroservo.io.curves",
    "write_bench_curves": "hydroservo.io.curves",
    "read_datasheet": "hydroservo.io.datasheet",
    "read_operating_point": "hydroservo.io.linear",
    "write_linear_model": "hydroservo.io.linear",
    "builtin_models": "hydroservo.io.model_file",
    "load_model": "hydroservo.io.model_file",
    "model_to_toml": "hydroservo.io.model_file",
    "read_model": "hydroservo.io.model_file",
    "write_model": "hydroservo.io.model_file",
    "read_record": "hydroservo.io.records",
    "write_record": "hydroservo.io.records",
    "write_csv": "hydroservo.io.results",
    "write_mat": "hydroservo.io.results",
    "RunStore": "hydroservo.io.runs",
    "read_runs": "hydroservo.io.runs",
    "write_bench_bode": "hydroservo.io.servovalve",
    "write_blocked": "hydroservo.io.servovalve",
    "write_figures": "hydroservo.io.servovalve",
    "write_hysteresis": "hydroservo.io.servovalve",
    "write_sensitivity": "hydroservo.io.servovalve",
    "write_static_characteristic": "hydroservo.io.servovalve",
    "write_steps": "hydroservo.io.servovalve",
    "read_time_table": "hydroservo.io.tables",
    "read_toml": "hydroservo.io.toml",
}

__all__ = [
    "read_bode",
    "read_hmf",
    "read_hopsan",
    "write_bode",
    "component_file_text",
    "component_toml",
    "read_component_file",
    "read_staged_slot_valve",
    "staged_slot_valve_toml",
    "read_bench_curves",
    "read_csv_table",
    "read_static_curves",
    "write_bench_curves",
    "read_datasheet",
    "read_operating_point",
    "write_linear_model",
    "builtin_models",
    "load_model",
    "model_to_toml",
    "read_model",
    "write_model",
    "read_record",
    "write_record",
    "write_csv",
    "write_mat",
    "RunStore",
    "read_runs",
    "write_bench_bode",
    "write_blocked",
    "write_figures",
    "write_hysteresis",
    "write_sensitivity",
    "write_static_characteristic",
    "write_steps",
    "read_time_table",
    "read_toml",
]


def __getattr__(name: str) -> Any:
    if name not in _LAZY:
        raise AttributeError(f"module 'hydroservo.io' has no attribute {name!r}")
    value = getattr(importlib.import_module(_LAZY[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


if TYPE_CHECKING:  # the names the lazy imports give, for type checkers and editors
    from hydroservo.io.bode import read_bode, write_bode
    from hydroservo.io.component_file import (
        component_file_text,
        component_toml,
        read_component_file,
        read_staged_slot_valve,
        staged_slot_valve_toml,
    )
    from hydroservo.io.curves import read_bench_curves, read_csv_table, read_static_curves, write_bench_curves
    from hydroservo.io.datasheet import read_datasheet
    from hydroservo.io.linear import read_operating_point, write_linear_model
    from hydroservo.io.model_file import builtin_models, load_model, model_to_toml, read_model, write_model
    from hydroservo.io.records import read_record, write_record
    from hydroservo.io.results import write_csv, write_mat
    from hydroservo.io.runs import RunStore, read_runs
    from hydroservo.io.servovalve import (
        write_bench_bode,
        write_blocked,
        write_figures,
        write_hysteresis,
        write_sensitivity,
        write_static_characteristic,
        write_steps,
    )
    from hydroservo.io.tables import read_time_table
    from hydroservo.io.toml import read_toml
