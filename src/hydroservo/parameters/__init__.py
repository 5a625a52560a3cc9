"""Published parameter sets, named after their source, in the source's own units."""

from hydroservo.parameters import ferreira_000
from hydroservo.parameters.flight_simulator_003 import APPENDIX_C

__all__ = ["APPENDIX_C", "ferreira_000"]
