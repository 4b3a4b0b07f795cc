"""From measurements to the model: parameters identified from data, with their uncertainty.

- :mod:`.least_squares` — the fit every identification shares: standard errors, 95 % profile
  intervals, correlation and identifiability warnings;
- :mod:`.impacts` — the restitution e(v) from single impacts (speeds or drop heights).
"""

from .impacts import LAWS, Impacts, fall_speed, fit_restitution, read_impacts, restitution
from .least_squares import Fit, Parameter, Unknown, fit

__all__ = [
    "LAWS",
    "Fit",
    "Impacts",
    "Parameter",
    "Unknown",
    "fall_speed",
    "fit",
    "fit_restitution",
    "read_impacts",
    "restitution",
]
