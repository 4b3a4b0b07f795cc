"""``symimpact simulate``: free vibration with impacts (Eq. 7, 10, 36–38)."""

from __future__ import annotations

from typing import Any

from .common import (
    add_initial,
    add_output,
    add_system,
    emit,
    fmt,
    notice_first_compilation,
    system_from,
    write_csv,
)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("simulate", help="free vibration with impacts (Eq. 7, 10, 36–38)")
    add_system(p)
    add_initial(p)
    p.add_argument(
        "--rest",
        default="1e-12",
        metavar="FRACTION",
        help="stop at rest once the energy falls below this fraction of its initial value "
        "(0: never); default 1e-12",
    )
    add_output(p, plot=True)


def run(ns) -> None:
    notice_first_compilation(ns.command)
    from ..simulation import simulate

    system = system_from(ns)
    res = simulate(
        system,
        ns.x0,
        ns.xdot0,
        ns.y0,
        ns.ydot0,
        ns.t_end,
        contact=ns.contact,
        history=bool(ns.plot or ns.csv),
        rest=_fraction("rest", ns.rest),
    )
    if ns.csv:
        names = list(res.history)
        columns = zip(*res.history.values(), strict=True)
        write_csv(ns.csv, "csv", [dict(zip(names, c, strict=True)) for c in columns])
    if ns.plot:
        from ..plots import plot_simulation

        plot_simulation(res, ns.plot)
    out = res.as_dict()
    di = res.damping_inclination
    residual = res.energy["relative_residual"]
    text = (
        f"impacts {res.n_impacts}, effective {res.n_effective}, effectiveness "
        f"{fmt(res.effectiveness, '.3g')}, DI {fmt(None if di is None else di * 1e6, '.2f')} µm, "
        f"energy residual {fmt(residual, '.1e')} of the initial energy"
    )
    text += "".join(f"\nnote: {n}" for n in res.notes)
    emit(ns, out, text)


def _fraction(name: str, text: str) -> float:
    from ..errors import ParameterError

    try:
        return float(text)
    except ValueError:
        raise ParameterError(name, f"{text!r} is not a number") from None


#: The subcommands this module runs.
COMMANDS = {"simulate": run}
