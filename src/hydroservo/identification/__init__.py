"""Identification: model parameters from datasheets, measured curves and frequency responses.

=======================  ========================================================
module                   fits
=======================  ========================================================
:mod:`.datasheet`        pseudo-sections from a datasheet's null
                         characteristics ([FerreiraND] sections 3-5)
:mod:`.curves`           pseudo-sections from measured static curves
:mod:`.spool_dynamics`   spool dynamics (rate-limited, second, first order) from
                         amplitude-dependent Bode data ([FerreiraND] eq. 43)
:mod:`.staged_slot`      the staged-slot valve from test-bench curves, two steps
                         ([MareAttarND] eqs. 21-24)
:mod:`.servovalve_...`   catalogue servovalves (first to third order) from a
``catalogue``            small-signal frequency response and the static bench
=======================  ========================================================

Each fit returns the components it identified, so that a fitted valve is the
same object a system simulates.
"""

from hydroservo.identification.curves import fit_curves
from hydroservo.identification.datasheet import Datasheet, PseudoSectionFit, fit_datasheet
from hydroservo.identification.servovalve_catalogue import CatalogueFit, fit_catalogue
from hydroservo.identification.spool_dynamics import SPOOL_MODELS, SpoolFit, fit_spool_dynamics, spool_response
from hydroservo.identification.staged_slot import StagedSlotIdentification, identify_staged_slot

__all__ = [
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
