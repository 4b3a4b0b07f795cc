"""symimpact: checked numeric kernels for nonlinear resilient impact dampers.

The kernels in :mod:`symimpact.generated` are emitted by the SymPy derivations in the checkout's
``derive/`` folder (``python -m derive``); this runtime imports them and never imports SymPy.

>>> from symimpact.generated import closed_forms
>>> round(float(closed_forms.hertz_contact_duration(0.15, 1.0, 1000.0, 0.075)), 4)
0.1509
"""

from importlib.metadata import PackageNotFoundError, version

from . import generated

try:
    __version__ = version("symimpact")
except PackageNotFoundError:  # pragma: no cover - running from a bare source tree
    __version__ = "0+unknown"

__all__ = ["__version__", "generated"]
