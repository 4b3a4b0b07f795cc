"""symimpact: checked numeric kernels for nonlinear resilient impact dampers.

The kernels in :mod:`symimpact.generated` are emitted by the SymPy derivations in the checkout's
``derive/`` folder (``python -m derive``); this runtime imports them and never imports SymPy.

>>> from symimpact.generated import closed_forms
>>> round(float(closed_forms.hertz_contact_duration(0.15, 1.0, 1000.0, 0.075)), 4)
0.1509
"""

from . import generated

__all__ = ["__version__", "generated"]


def __getattr__(name: str) -> str:
    """``symimpact.__version__``, read from the installed metadata on first use (importing
    :mod:`importlib.metadata` costs 0.04 s of every command's start-up otherwise)."""
    if name != "__version__":
        raise AttributeError(f"module 'symimpact' has no attribute {name!r}")
    from importlib.metadata import PackageNotFoundError, version

    try:
        found = version("symimpact")
    except PackageNotFoundError:  # pragma: no cover - running from a bare source tree
        found = "0+unknown"
    globals()["__version__"] = found
    return found
