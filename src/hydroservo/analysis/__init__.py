"""Analysis of systems and components: frequency responses, static test benches.

=====================  ==========================================================
module                 analyses
=====================  ==========================================================
:mod:`.frequency`      amplitude-dependent frequency response of any system by
                       periodic steady state ([FerreiraND] eqs. 41-42)
:mod:`.static_bench`   the ARP490 static tests of a four-way valve: flow gain,
                       pressure gain, leakage, pressure-flow, Table-2 metrics
                       ([MareAttarND])
:mod:`.step`           step-response metrics: rise and settling time, overshoot,
                       peak, steady-state error
:mod:`.study`          parameter studies: grids, Sobol, Latin-hypercube and
                       random designs; a DataFrame of parameters and metrics
=====================  ==========================================================
"""

from hydroservo.analysis.frequency import FrequencyResponse, PeriodicResponse, sine_response
from hydroservo.analysis.static_bench import (
    METRICS,
    Bench,
    BenchCurves,
    bench_curves,
    blocked_ports,
    flow_gain,
    pressure_flow,
    rated_flow,
    table2_metrics,
    temperature_table,
)
from hydroservo.analysis.step import step_metrics
from hydroservo.analysis.study import grid, metrics_table, sample

__all__ = [
    "step_metrics",
    "grid",
    "sample",
    "metrics_table",
    "FrequencyResponse",
    "PeriodicResponse",
    "sine_response",
    "METRICS",
    "Bench",
    "BenchCurves",
    "bench_curves",
    "blocked_ports",
    "flow_gain",
    "pressure_flow",
    "rated_flow",
    "table2_metrics",
    "temperature_table",
]
