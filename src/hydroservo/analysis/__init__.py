"""Analysis of built systems: frequency responses."""

from hydroservo.analysis.frequency import FrequencyResponse, PeriodicResponse, sine_response

__all__ = ["FrequencyResponse", "PeriodicResponse", "sine_response"]
