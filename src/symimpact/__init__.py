"""symimpact: checked numeric kernels for nonlinear resilient impact dampers.

The kernels in :mod:`symimpact.generated` are emitted by the SymPy derivations in the checkout's
``derive/`` folder (``python -m derive``); this runtime imports them and never imports SymPy.

>>> from symimpact.generated import closed_forms
>>> round(float(closed_forms.hertz_contact_duration(0.15, 1.0, 1000.0, 0.075)), 4)
0.1509
"""


def _interrupted_while_starting(signum, frame) -> None:  # pragma: no cover - timing
    """Ctrl-C (or SIGTERM, SIGHUP) while the command line is still importing: one line and
    128 + N, not the 40-line KeyboardInterrupt traceback of an import; the command line's
    own handlers replace this one once its parser is built."""
    import os

    os.write(2, b"symimpact: interrupted\n" if signum == 2 else b"symimpact: ended by signal\n")
    os._exit(128 + signum)


def _as_the_program() -> bool:
    """Whether this import starts the ``symimpact`` program (its console script, or
    ``python -m symimpact.cli``), not a library user's session."""
    import os
    import sys

    arg0 = sys.argv[0] if sys.argv else ""
    return os.path.basename(arg0) == "symimpact" or arg0.endswith(
        os.path.join("symimpact", "cli", "__main__.py")
    )


if _as_the_program():  # before numpy and the generated kernels are imported
    import signal as _signal

    for _sig in (_signal.SIGINT, _signal.SIGTERM, _signal.SIGHUP):
        _signal.signal(_sig, _interrupted_while_starting)

from . import generated  # noqa: E402

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
