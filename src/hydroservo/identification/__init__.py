"""Identification: model parameters from datasheets, measured curves and frequency responses.

========================  ========================================================
module                    fits
========================  ========================================================
:mod:`.datasheet`         pseudo-sections from a datasheet's null
                          characteristics ([FerreiraND] sections 3-5)
:mod:`.curves`            pseudo-sections from measured static curves
:mod:`.spool_dynamics`    spool dynamics (rate-limited, second, first order) from
                          amplitude-dependent Bode data ([FerreiraND] eq. 43)
:mod:`.staged_slot`       the staged-slot valve from test-bench curves, two steps
                          ([MareAttarND] eqs. 21-24)
:mod:`.servovalve_...`    catalogue servovalves (first to third order) from a
``catalogue``             small-signal frequency response and the static bench
:mod:`.calibration`       any system's parameters from rig records: weighted least
                          squares with exact gradients, intervals, identifiability
:mod:`.friction`          friction from a rig record and the Stribeck law
                          ([Efe2014] eqs. 4.24-4.25, 3.47)
:mod:`.leakage`           internal leakage from a locked piston ([Efe2014] 4.5.5)
:mod:`.flow_coefficient`  the valve's K(x_v) and H(x_v, d_f) ([Efe2014] 5.1.2-3)
========================  ========================================================

Rig records (one experiment each, channels at their own rates) are
:mod:`.records`; :mod:`.rig` makes them from any model (a virtual rig);
:mod:`.steady` finds the held intervals of a record and reads parameters off
a model at a measured steady state.

Each fit returns the components it identified, so that a fitted valve is the
same object a system simulates.
"""

from hydroservo.identification.calibration import (
    Calibration,
    ExperimentPlan,
    Prediction,
    calibrate,
    plan_experiment,
    predict,
)
from hydroservo.identification.curves import fit_curves
from hydroservo.identification.datasheet import Datasheet, PseudoSectionFit, fit_datasheet
from hydroservo.identification.flow_coefficient import FlowCoefficientTables, flow_coefficient_tables
from hydroservo.identification.friction import FrictionPoints, StribeckFit, fit_stribeck, friction_from_record
from hydroservo.identification.leakage import LeakageEstimate, leakage_from_record
from hydroservo.identification.records import Channel, Record
from hydroservo.identification.rig import Sensor, virtual_rig
from hydroservo.identification.servovalve_catalogue import CatalogueFit, fit_catalogue
from hydroservo.identification.spool_dynamics import SPOOL_MODELS, SpoolFit, fit_spool_dynamics, spool_response
from hydroservo.identification.staged_slot import StagedSlotIdentification, identify_staged_slot

__all__ = [
    "Calibration",
    "ExperimentPlan",
    "Prediction",
    "calibrate",
    "plan_experiment",
    "predict",
    "FlowCoefficientTables",
    "flow_coefficient_tables",
    "FrictionPoints",
    "StribeckFit",
    "fit_stribeck",
    "friction_from_record",
    "LeakageEstimate",
    "leakage_from_record",
    "Channel",
    "Record",
    "Sensor",
    "virtual_rig",
    "CatalogueFit",
    "fit_catalogue",
    "Datasheet",
    "PseudoSectionFit",
    "fit_datasheet",
    "fit_curves",
    "SPOOL_MODELS",
    "SpoolFit",
    "fit_spool_dynamics",
    "spool_response",
    "StagedSlotIdentification",
    "identify_staged_slot",
]
