"""``symimpact contact-duration``: contact duration of one impact (Eq. 31, 34, 35)."""

from __future__ import annotations

import argparse
from typing import Any

from .common import add_output, add_system, emit, quantity_text, system_from


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("contact-duration", help="contact duration of one impact (Eq. 31, 34, 35)")
    add_system(p, contact=False)
    p.add_argument("--v0", default="7.5 cm/s", metavar="Q", help="approach speed [m/s]")
    p.add_argument(
        "--method",
        choices=("perturbation", "hertz", "linear", "numerical", "all"),
        default="all",
        help="default all",
    )
    p.add_argument(
        "--contact",
        choices=("cubic", "hertz", "linear"),
        default="cubic",
        help="contact force law of the numerical method (as in simulate); default cubic",
    )
    # the former name, still read (hidden): one vocabulary in --help, no broken scripts
    p.add_argument("--law", dest="contact", choices=("cubic", "hertz", "linear"),
                   help=argparse.SUPPRESS)  # fmt: skip
    p.add_argument(
        "--ba",
        default="impact",
        metavar="B/A",
        help="B/A in Eq. 31: impact (default), out_of_phase, in_phase, free (−M/m) or a number",
    )
    p.add_argument("--free", action="store_true", help="numerical: no main spring (free bodies)")
    add_output(p)


def run(ns) -> None:
    from ..free.contact import contact_duration, contact_durations

    system = system_from(ns)
    kw = dict(ba=ns.ba, law=ns.contact, free=ns.free)
    if ns.method == "all":
        res = contact_durations(system, ns.v0, **kw)
    else:
        res = {ns.method: contact_duration(system, ns.v0, ns.method, **kw)}
    out: dict[str, Any] = {}
    for k, v in res.items():
        if k == "not_applicable":
            out[k] = v
            continue
        out[k] = float(v.value)
        if k == "perturbation":
            out["perturbation_printed"] = float(v.printed)
            out["perturbation_history"] = [float(h) for h in v.history]
            out["ba"] = float(v.ba)
    text = "\n".join(
        f"{k:<22} {quantity_text('duration', v)}" if isinstance(v, float) and k != "ba"
        else f"{k:<22} {v}"
        for k, v in out.items()
        if k != "perturbation_history"
    )  # fmt: skip
    emit(ns, out, text)


#: The subcommands this module runs.
COMMANDS = {"contact-duration": run}
