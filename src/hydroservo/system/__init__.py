"""Systems, compiled models and results."""

from hydroservo.system.model import Model
from hydroservo.system.result import BatchResult, Result
from hydroservo.system.system import Alias, System

__all__ = ["System", "Alias", "Model", "Result", "BatchResult"]
