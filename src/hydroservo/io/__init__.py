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
:mod:`.linear`           operating points (TOML) and linear models (JSON)
:mod:`.runs`             the runs of a study, written as they arrive (Parquet parts)
:mod:`.toml`             the TOML reader and value writer they share
=======================  ========================================================

A new file format gets a module here; nothing outside this package opens a
user's file. (The package's own data files are found by :mod:`hydroservo.data`.)
"""

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

__all__ = [
    "read_bode",
    "write_bode",
    "read_component_file",
    "component_toml",
    "component_file_text",
    "read_staged_slot_valve",
    "staged_slot_valve_toml",
    "read_csv_table",
    "read_static_curves",
    "read_bench_curves",
    "write_bench_curves",
    "read_datasheet",
    "read_model",
    "write_model",
    "model_to_toml",
    "load_model",
    "builtin_models",
    "write_csv",
    "write_mat",
    "read_time_table",
    "read_operating_point",
    "write_linear_model",
    "RunStore",
    "read_runs",
    "read_toml",
    "write_static_characteristic",
    "write_sensitivity",
    "write_figures",
    "write_steps",
    "write_hysteresis",
    "write_blocked",
    "write_bench_bode",
]
