"""``symimpact``: the command line, one module per subcommand.

Every parameter takes an SI number or a quantity with units ("100 N/cm", "9 mm").  Bad input exits
with status 2 and one line naming the parameter and the reason.

Adding a subcommand: a module here with ``add_parser(sub)`` (its options, from the shared groups
of :mod:`.common`), the function that runs it and ``COMMANDS = {"name": function}``, and one line
in :data:`SUBCOMMANDS`.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence

from .._progress import end_open_bar_line
from ..errors import SymimpactError
from . import (
    branch,
    contact,
    contact_duration,
    design,
    export,
    fit,
    frf,
    identify,
    loads,
    modes,
    periodic,
    reproduce,
    ritz,
    simulate,
    sweep,
)
from .common import (
    Parser,
    apply_engineer_inputs,
    apply_materials,
    apply_system_file,
    progress_drawn,
)

#: The subcommands, in the order of ``symimpact --help``.
SUBCOMMANDS = [reproduce, ritz, modes, fit, contact, contact_duration, simulate, periodic, frf, branch, design,
               loads, identify, export, sweep]  # fmt: skip

#: What runs each subcommand (by name, aliases included).
COMMANDS = {name: run for module in SUBCOMMANDS for name, run in module.COMMANDS.items()}


class _Version(argparse.Action):
    """``--version``: the installed version, looked up only when asked for."""

    def __call__(self, parser, namespace, values, option_string=None):
        from .. import __version__

        parser.exit(message=f"symimpact {__version__}\n")


def build_parser() -> argparse.ArgumentParser:
    """The ``symimpact`` argument parser (also used to document the command line)."""
    parser = Parser(
        prog="symimpact",
        description="Nonlinear resilient impact dampers: Ritz constants, contact fits, contact "
        "durations, simulations with impacts (free, or forced with rigid impacts), periodic "
        "orbits and gap sweeps.  Quantities accept units.",
    )
    parser.add_argument("--version", action=_Version, nargs=0, help="show the version and exit")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    for module in SUBCOMMANDS:
        module.add_parser(sub)
    _store_once(parser)
    return parser


def _store_once(parser: argparse.ArgumentParser) -> None:
    """Every option that stores a value, in ``parser`` and its subcommands (``identify
    impacts`` too), made a :class:`_StoreOnce`."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for command in action.choices.values():
                _store_once(command)
        elif type(action) is argparse._StoreAction:
            action.__class__ = _StoreOnce


class _StoreOnce(argparse._StoreAction):
    """An option that holds one value: given twice (``--force 2 --force 3``) it is refused in one
    line, not silently replaced by the second."""

    def __call__(self, parser, namespace, values, option_string=None):
        given = namespace.__dict__.setdefault(GIVEN, set())
        if self.dest in given:
            parser.error(f"argument {option_string}: given twice")
        given.add(self.dest)
        super().__call__(parser, namespace, values, option_string)


#: The namespace's record of the options given (removed once parsed).
GIVEN = "_options_given"


_NEGATIVE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def _value_options(parser: argparse.ArgumentParser) -> set[str]:
    """Option strings (of the parser and its subcommands) that take a value."""
    out: set[str] = set()
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                out |= _value_options(sub)
        elif action.option_strings and action.nargs != 0:
            out.update(action.option_strings)
    return out


def _join_negative_values(parser: argparse.ArgumentParser, argv: Sequence[str]) -> list[str]:
    """``--x0 -1mm`` → ``--x0=-1mm``: argparse takes a value that starts with '-' for an option
    unless it is a plain number, so negative quantities with units would be refused."""
    takes_value = _value_options(parser)
    out: list[str] = []
    for tok in argv:
        if out and out[-1] in takes_value and _NEGATIVE.match(tok):
            out[-1] = f"{out[-1]}={tok}"
        else:
            out.append(tok)
    return out


#: Exit statuses: 0 done, 2 bad input (one line naming the parameter), 3 a fault of the machine
#: or of the files (full disk, unreadable path, lost Dask cluster: one line saying what and why),
#: 128 + N when ended by signal N (130 for Ctrl-C, 143 for SIGTERM, 129 for SIGHUP), 70 for an
#: internal error (a bug; SYMIMPACT_DEBUG=1 shows its traceback).
EXIT_BAD_INPUT, EXIT_FAULT = 2, 3


def _ending_on_signal(command: str):
    """A SIGTERM/SIGHUP (and, run as the program, SIGINT) handler: end the pool workers, say so
    in one line, exit 128 + N (130 for Ctrl-C: "interrupted").

    It does not raise into the main thread: an exception raised by a signal handler while a
    finaliser runs is printed and dropped, and the command would go on to the end.  Nothing is
    lost by ending at once: every output is written to a temporary name and renamed when
    complete, and the leftovers of an ended run are removed by the next one."""

    def end(signum, frame) -> None:
        import os
        import signal

        # Each module is read from sys.modules, never imported here, and each of its names with
        # getattr: a signal that lands while one is being imported finds it partially
        # initialized, without the name yet.  An AttributeError raised here surfaces in the
        # main thread inside that import: tqdm's ended a design at 1.39 s as an internal error
        # (exit 70, not 130), and multiprocessing's or symimpact.io's a simulate at 0.35 s as
        # "ImportError: cannot import name 'simulate_forced'" (the package's lazy __getattr__
        # turned it into one).  Where multiprocessing is not imported, no child was started.
        children = getattr(sys.modules.get("multiprocessing"), "active_children", None)
        for child in children() if children is not None else ():
            child.terminate()
        end_open_bar_line()  # a progress bar open mid-line: the message gets its own
        # os._exit runs no finally: the half-written outputs go here
        remove = getattr(sys.modules.get("symimpact.io"), "remove_in_progress", None)
        if remove is not None:
            remove()
        words = "interrupted" if signum == signal.SIGINT else f"ended by signal {signum}"
        print(f"symimpact {command}: {words}", file=sys.stderr, flush=True)
        os._exit(128 + signum)

    return end


def _one_line_warning(command: str):
    def show(message, category, filename, lineno, file=None, line=None) -> None:
        text = " ".join(str(message).split())
        print(f"symimpact {command}: warning: {text}", file=sys.stderr)

    return show


#: Exit status of an internal error (a bug in symimpact, not in the input): EX_SOFTWARE.
EXIT_INTERNAL = 70


def _internal(command: str, exc: BaseException) -> int:
    import os

    if os.environ.get("SYMIMPACT_DEBUG"):
        raise exc
    text = " ".join(str(exc).split())[:300]
    print(
        f"symimpact {command}: internal error: {type(exc).__name__}: {text} (a bug; rerun with "
        "SYMIMPACT_DEBUG=1 for the traceback and report it)",
        file=sys.stderr,
    )
    return EXIT_INTERNAL


#: Options that collect a list (action="append"); every other option holds one string.
LIST_OPTIONS = ("vary", "show")


def _dashes_as_empty(ns: argparse.Namespace, parser: argparse.ArgumentParser) -> argparse.Namespace:
    """``--opt=--`` reaches argparse as the end-of-options marker and leaves ``[]`` as the value;
    read it as an empty value instead, which the checks then refuse by name.  An option that
    argparse converts (a whole number: ``ritz --mode=--``) is left as ``[]`` unconverted: it is
    refused by :func:`_refuse_unconverted` (it had reached the command and ended in an internal
    error; found by the command-line fuzz)."""
    for key, value in vars(ns).items():
        if key in LIST_OPTIONS:
            setattr(ns, key, ["" if v == [] else v for v in value])
        elif value == [] and key not in _typed_options(parser, ns.command):
            setattr(ns, key, "")
    return ns


def _typed_options(parser: argparse.ArgumentParser, command: str) -> set[str]:
    """The destinations of ``command``'s options that argparse converts (``type=``)."""
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return {a.dest for a in sub.choices[command]._actions if a.type is not None}


def _refuse_unconverted(ns: argparse.Namespace) -> None:
    """A converted option written ``--opt=--`` (its value ``[]``, see :func:`_dashes_as_empty`):
    refused in one line naming it."""
    from ..errors import ParameterError

    for key, value in vars(ns).items():
        if value == [] and key not in LIST_OPTIONS:
            raise ParameterError(key.replace("_", "-"), "needs a value ('--' is not one)")


#: Options that name a file a command writes, checked before the command computes anything.
OUTPUT_FILES = ("plot", "csv")
#: Options that name a file a command reads (an output may not replace one).
INPUT_FILES = ("system", "structure", "record_file", "psd_file", "fe", "stiffness", "mass")
#: Commands whose --out is a file (a map's table); the others' --out is a folder.
FILE_OUT = ("sweep", "map", "design", "identify")


def _check_outputs(ns: argparse.Namespace) -> None:
    """Refuse an output path that cannot be written before the computation starts
    (:func:`symimpact.io.output_target`), not after it."""
    import os

    from ..errors import ParameterError
    from ..io import output_target

    written: dict[str, str] = {}
    for name in OUTPUT_FILES + (("out",) if ns.command in FILE_OUT else ()):
        value = getattr(ns, name, None)
        if value:
            output_target(value, name)
            where = os.path.realpath(value)
            if where in written:  # the second file would replace the first
                raise ParameterError(name, f"{value!r} is already the --{written[where]} file: "
                                     "give each output its own path")  # fmt: skip
            written[where] = name
    for name in INPUT_FILES:
        value = getattr(ns, name, None)
        if isinstance(value, str) and value and os.path.realpath(value) in written:
            out = written[os.path.realpath(value)]
            raise ParameterError(out, f"{value!r} is the --{name.replace('_', '-')} file read: "
                                 "writing it would replace the input")  # fmt: skip


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``symimpact``; returns the exit status (see ``EXIT_*``: 2 on bad input, 3
    on a fault, 128 + N on signal N)."""
    import signal
    import warnings

    parser = build_parser()
    argv_given = argv
    argv = sys.argv[1:] if argv is None else list(argv)
    ns = _dashes_as_empty(parser.parse_args(_join_negative_values(parser, argv)), parser)
    given = ns.__dict__.pop(GIVEN, set())
    from ..model import display

    units_before = dict(display.DISPLAY_UNITS)
    shown_warning = warnings.showwarning
    warnings.showwarning = _one_line_warning(ns.command)  # every warning: one line
    previous = {}
    # Run as the program (no argv given), Ctrl-C ends it like SIGTERM: at once, in one line.  A
    # KeyboardInterrupt raised in Python's import machinery (a lazy import of the simulation) is
    # printed as "Exception ignored" and dropped, and the command ran on to exit 0.  Called with
    # an argv (tests, notebooks), Ctrl-C stays a KeyboardInterrupt, caught below.
    ending = (signal.SIGTERM, signal.SIGHUP) + ((signal.SIGINT,) if argv_given is None else ())
    end = _ending_on_signal(ns.command)
    for sig in ending:
        try:
            previous[sig] = signal.signal(sig, end)
        except ValueError:  # not the main thread (e.g. called from a worker thread)
            pass
    # a person waits: a first compilation says so (symimpact._notices), as the bars are drawn
    if progress_drawn(ns):
        from .. import _notices

        _notices.command = ns.command
    try:
        display.parse_show(getattr(ns, "show", []))
        hz = getattr(ns, "freq_range", None) is not None or getattr(ns, "freq", None) is not None
        if hz and not any(
            spec.partition("=")[0].strip() == "omega" for spec in getattr(ns, "show", None) or []
        ):
            display.set_display_unit("omega", "Hz")  # the user's unit back
        _refuse_unconverted(ns)
        _check_outputs(ns)
        apply_system_file(ns, given)
        apply_engineer_inputs(ns, given)
        apply_materials(ns, given)
        COMMANDS[ns.command](ns)
    except SymimpactError as exc:
        print(f"symimpact {ns.command}: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print(f"symimpact {ns.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # output piped into a program that stopped reading (e.g. head)
        sys.stderr.close()
        return 0
    except (OSError, MemoryError) as exc:  # the machine or the files, not the input
        what = f"{exc.strerror} ({exc.filename})" if getattr(exc, "strerror", None) else exc
        if getattr(exc, "filename", None) is None and getattr(exc, "strerror", None):
            what = exc.strerror
        print(f"symimpact {ns.command}: fault: {what or type(exc).__name__}", file=sys.stderr)
        return EXIT_FAULT
    except Exception as exc:  # a bug: one line naming it (SYMIMPACT_DEBUG=1 shows the traceback)
        return _internal(ns.command, exc)
    finally:
        warnings.showwarning = shown_warning
        display.DISPLAY_UNITS.clear()
        display.DISPLAY_UNITS.update(units_before)
        for sig, handler in previous.items():
            signal.signal(sig, handler)
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
