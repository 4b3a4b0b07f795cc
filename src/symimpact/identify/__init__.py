"""From measurements to the model: parameters identified from data, with their uncertainty.

- :mod:`.least_squares` — the fit every identification shares: standard errors, 95 % profile
  intervals, correlation and identifiability warnings;
- :mod:`.impacts` — the restitution e(v) from single impacts (speeds or drop heights);
- :mod:`.decay` — e, ζ and the clearance from a free decay after a tap;
- :mod:`.propagation` — their uncertainty carried into the curve's peak.
"""

from .impacts import LAWS, Impacts, fall_speed, fit_restitution, read_impacts, restitution
from .least_squares import Fit, Parameter, Unknown, fit

__all__ = [
    "LAWS",
    "Decay",
    "Fit",
    "Impacts",
    "Parameter",
    "Unknown",
    "fall_speed",
    "fit",
    "fit_decay",
    "fit_restitution",
    "read_decay",
    "read_impacts",
    "restitution",
]


def __getattr__(name: str):
    """The decay's names, imported when first asked for: they need the compiled record engine,
    which fitting single impacts does not."""
    if name in ("Decay", "fit_decay", "read_decay"):
        from . import decay

        return getattr(decay, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
