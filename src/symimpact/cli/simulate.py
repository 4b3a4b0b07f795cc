"""``symimpact simulate``: free vibration with impacts (Eq. 7, 10, 36–38), or the forced response
with rigid impacts (Eq. F1, F2) and its steady state."""

from __future__ import annotations

from typing import Any

from .common import (
    add_forcing,
    add_initial,
    add_output,
    add_system,
    emit,
    fmt,
    forcing_from,
    has_forcing,
    notice_first_compilation,
    quantity_text,
    system_from,
    write_csv,
)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "simulate",
        help="free vibration with impacts (Eq. 7, 10, 36–38), or the forced response with rigid "
        "impacts (Eq. F1, F2)",
    )
    add_system(p, extra_laws=("rigid",))
    add_initial(p, forced=True)
    p.add_argument(
        "--rest",
        default=None,
        metavar="FRACTION",
        help="free vibration: stop at rest once the energy falls below this fraction of its "
        "initial value (0: never); default 1e-12",
    )
    add_forcing(p)
    g = p.add_argument_group("forced response: duration and steady state")
    g.add_argument(
        "--periods", default=None, metavar="N", help="forcing periods to simulate; default 400"
    )
    g.add_argument(
        "--discard",
        default=None,
        metavar="N0",
        help="report the steady state over the periods after the first N0; default: the first "
        "three quarters of --periods",
    )
    add_output(p, plot=True)


_FORCED_ONLY = {"periods": "--periods", "discard": "--discard", "e": "--e"}


def run(ns) -> None:
    from ..errors import ParameterError

    if ns.contact == "rigid" or has_forcing(ns):
        return run_forced(ns)
    for key, flag in _FORCED_ONLY.items():
        if getattr(ns, key) is not None:
            raise ParameterError(
                flag[2:],
                "applies to the forced response (give --force or --base, --omega or "
                "--freq, and --contact rigid)",
            )
    notice_first_compilation(ns.command)
    from ..simulation import simulate

    system = system_from(ns)
    res = simulate(
        system,
        ns.x0,
        "0.5 m/s" if ns.xdot0 is None else ns.xdot0,
        ns.y0,
        ns.ydot0,
        "20 s" if ns.t_end is None else ns.t_end,
        contact=ns.contact,
        history=bool(ns.plot or ns.csv),
        rest=_fraction("rest", "1e-12" if ns.rest is None else ns.rest),
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


def run_forced(ns) -> None:
    """The forced response with rigid impacts (Eq. F1, F2) and its steady state."""
    from ..errors import MethodNotApplicable, ParameterError
    from ..forced import simulate_forced
    from ..forced.simulation import MAX_MULTIPLE, period_count

    if ns.contact != "rigid":
        raise MethodNotApplicable(
            "simulate",
            f"contact {ns.contact!r} with forcing: the forced simulation takes "
            "--contact rigid (with --e)",
        )
    if not has_forcing(ns):
        raise ParameterError(
            "force",
            "contact rigid simulates the forced response: give --force F0 or --base "
            "X_b, and --omega or --freq",
        )
    if ns.t_end is not None:
        raise ParameterError("t-end", "a forced run lasts --periods forcing periods")
    if ns.rest is not None:
        raise ParameterError("rest", "applies to free vibration; a forced run never comes to rest")
    if ns.e is None:
        raise ParameterError("e", "contact rigid needs Newton's coefficient of restitution --e")
    system = system_from(ns)
    forcing = forcing_from(ns)
    periods = period_count("periods", "400" if ns.periods is None else ns.periods)
    discard = int(0.75 * periods) if ns.discard is None else period_count("discard", ns.discard)
    res = simulate_forced(
        system,
        forcing,
        contact="rigid",
        e=ns.e,
        periods=periods,
        discard=discard,
        x0=ns.x0,
        xdot0="0" if ns.xdot0 is None else ns.xdot0,
        y0=ns.y0,
        ydot0=ns.ydot0,
    )
    if ns.csv or ns.plot:
        _forced_outputs(ns, res, discard)
    st = res.steady
    text = (
        f"Ω {forcing.omega:.6g} rad/s ({forcing.freq:.6g} Hz), {len(res.impacts)} impacts in "
        f"{len(res.period_max)} periods; steady over the last {len(res.period_max) - discard}"
        f": amplitude {quantity_text('x', st.amplitude)}, {st.impacts_per_period:.4g} impacts "
        "per period, "
        + (
            f"periodic with {st.period_multiple} forcing period(s)"
            if st.periodic
            else f"not periodic within {MAX_MULTIPLE} periods (section spread {st.section_spread:.1e})"
        )
        + f"; energy residual {res.energy['relative_residual']:.1e}"
    )
    text += "".join(f"\nnote: {n}" for n in res.notes)
    emit(ns, res.as_dict(), text)


def _forced_outputs(ns, res, discard: int) -> None:
    """--csv: the state sampled 64 times per forcing period; --plot: x(t) and the impacts."""
    import numpy as np

    from ..forced.simulation import state_at

    T = res.forcing.period
    n = len(res.period_max)
    t = np.arange(n * 64 + 1) * (T / 64)
    s = state_at(res, t)
    if ns.csv:
        rows = [
            {"t": a, "x": b, "xdot": c, "z": d, "ydot": f}
            for a, b, c, d, f in zip(t, s[:, 0], s[:, 1], s[:, 2], s[:, 3], strict=True)
        ]
        write_csv(ns.csv, "csv", rows)
    if ns.plot:
        from ..plots import plot_forced

        plot_forced(res, t, s, discard, ns.plot)


def _fraction(name: str, text: str) -> float:
    from ..errors import ParameterError

    try:
        return float(text)
    except ValueError:
        raise ParameterError(name, f"{text!r} is not a number") from None


#: The subcommands this module runs.
COMMANDS = {"simulate": run}
