"""Identification: model parameters from datasheets, measured curves and frequency responses."""

from hydroservo.identification.datasheet import Datasheet, PseudoSectionModel, fit_curves, fit_datasheet
from hydroservo.identification.spool import SPOOL_MODELS, SpoolFit, fit_spool_dynamics, spool_response

__all__ = [
    "Datasheet",
    "PseudoSectionModel",
    "fit_datasheet",
    "fit_curves",
    "SPOOL_MODELS",
    "SpoolFit",
    "fit_spool_dynamics",
    "spool_response",
]
