"""``symimpact simulate``: free vibration with impacts (Eq. 7, 10, 36–38), or the forced response
(Eq. F1) with rigid impacts (Eq. F2) or a compliant contact (Eq. 8–10, 35, F4) and its steady
state."""

from __future__ import annotations

from typing import Any

from .. import budgets
from .common import (
    add_forcing,
    add_initial,
    add_output,
    add_system,
    emit,
    fmt,
    forcing_from,
    has_forcing,
    quantity_text,
    structure_forcing,
    system_from,
    write_csv,
)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "simulate",
        help="free vibration with impacts (Eq. 7, 10, 36–38), or the forced response (Eq. F1) "
        "with rigid impacts (Eq. F2) or a compliant contact",
        epilog=budgets.text(),
    )
    # no default law: free vibration takes cubic, a forced run asks for the law by name
    add_system(p, extra_laws=("rigid", "hunt-crossley"), contact_default=None)
    add_initial(p, forced=True)
    p.add_argument(
        "--rest",
        default=None,
        metavar="FRACTION",
        help="free vibration: stop at rest once the energy falls below this fraction of its "
        "initial value (0: never); default 1e-12",
    )
    add_forcing(p)
    g = p.add_argument_group("forced response: contact, duration and steady state")
    g.add_argument(
        "--chi",
        default=None,
        metavar="Q",
        help="Hunt–Crossley damping χ [s/m] of --contact hunt-crossley (Eq. F4; Step 11 gives "
        "the χ·v of a wanted restitution)",
    )
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
    g.add_argument(
        "--response",
        default=None,
        metavar="NAME",
        help="also the steady relative-displacement, acceleration (between impacts), force "
        "(into the base) or transmissibility, as frf --response",
    )
    add_output(p, plot=True)


_FORCED_ONLY = {"periods": "--periods", "discard": "--discard", "e": "--e", "chi": "--chi",
                "response": "--response"}  # fmt: skip
#: The laws the forced run takes (the perturbation solution is free vibration only).
_FORCED_LAWS = ("rigid", "cubic", "hertz", "linear", "hunt-crossley")
#: Samples of the state per forcing period for --csv and --plot.
_SAMPLES = 64


def run(ns) -> None:
    from ..errors import ParameterError

    if getattr(ns, "structure_model", None) is not None:
        return run_structure(ns)
    if ns.contact in ("rigid", "hunt-crossley") or has_forcing(ns):
        return run_forced(ns)
    for key, flag in _FORCED_ONLY.items():
        if getattr(ns, key) is not None:
            raise ParameterError(
                flag[2:],
                "applies to the forced response (give --force or --base, --omega or "
                "--freq, and --contact)",
            )
    from ..free.simulation import simulate

    system = system_from(ns)
    res = simulate(
        system,
        ns.x0,
        "0.5 m/s" if ns.xdot0 is None else ns.xdot0,
        ns.y0,
        ns.ydot0,
        "20 s" if ns.t_end is None else ns.t_end,
        contact=ns.contact or "cubic",
        history=bool(ns.plot or ns.csv),
        rest=_fraction("rest", "1e-12" if ns.rest is None else ns.rest),
    )
    if ns.csv:
        names = list(res.history)
        columns = zip(*res.history.values(), strict=True)
        write_csv(ns.csv, "csv", [dict(zip(names, c, strict=True)) for c in columns])
    if ns.plot:
        from ..report.plots import plot_simulation

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
    """The forced response (Eq. F1) with rigid impacts (Eq. F2) or a compliant contact, and its
    steady state."""
    from ..errors import MethodNotApplicable, ParameterError
    from ..forced import simulate_forced
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..model.display import display_unit, impacts_text, omega_text

    if ns.contact is None:
        raise ParameterError(
            "contact",
            f"a forced run needs the contact law by name: one of {', '.join(_FORCED_LAWS)} "
            "(rigid with --e, hunt-crossley with --chi)",
        )
    if ns.contact not in _FORCED_LAWS:
        raise MethodNotApplicable(
            "simulate",
            f"contact {ns.contact!r} is a free-vibration solution; a forced run takes "
            f"{', '.join(_FORCED_LAWS)}",
        )
    if not has_forcing(ns):
        raise ParameterError(
            "force",
            f"contact {ns.contact} simulates the forced response: give --force F0 or --base "
            "X_b, and --omega or --freq",
        )
    if ns.t_end is not None:
        raise ParameterError("t-end", "a forced run lasts --periods forcing periods")
    if ns.rest is not None:
        raise ParameterError("rest", "applies to free vibration; a forced run never comes to rest")
    if ns.contact == "rigid" and ns.e is None:
        raise ParameterError("e", "contact rigid needs Newton's coefficient of restitution --e")
    if ns.contact != "rigid" and ns.e is not None:
        raise ParameterError(
            "e", f"applies to --contact rigid; contact {ns.contact} sets its own restitution"
        )
    if ns.contact == "hunt-crossley" and ns.chi is None:
        raise ParameterError("chi", "contact hunt-crossley needs its damping --chi χ [s/m]")
    if ns.contact != "hunt-crossley" and ns.chi is not None:
        raise ParameterError("chi", "applies to --contact hunt-crossley only")
    system = system_from(ns)
    forcing = forcing_from(ns)
    if ns.response is not None:  # refused before the run
        from ..forced.responses import SAMPLES, checked_response, steady_response

        checked_response(ns.response, forcing, rigid=ns.contact == "rigid")
    periods = period_count("periods", "400" if ns.periods is None else ns.periods)
    discard = int(0.75 * periods) if ns.discard is None else period_count("discard", ns.discard)
    res = simulate_forced(
        system,
        forcing,
        contact=ns.contact,
        e=ns.e,
        chi=ns.chi,
        periods=periods,
        discard=discard,
        x0=ns.x0,
        xdot0="0" if ns.xdot0 is None else ns.xdot0,
        y0=ns.y0,
        ydot0=ns.ydot0,
        samples_per_period=SAMPLES if ns.response is not None and ns.contact != "rigid"
        else _SAMPLES if (ns.csv or ns.plot) else 16,
    )  # fmt: skip
    if ns.csv or ns.plot:
        _forced_outputs(ns, res, discard)
    st = res.steady
    text = (
        f"contact {ns.contact}, Ω {omega_text(forcing.omega)}"
        + ("" if display_unit("omega") == "Hz" else f" ({forcing.freq:.6g} Hz)")
        + f", {len(res.impacts)} impacts in "
        f"{len(res.period_max)} periods; steady over the last {len(res.period_max) - discard}"
        f": amplitude {quantity_text('x', st.amplitude)}, "
        f"{impacts_text(st.impacts_per_period, st.impact_events_per_period)}, "
        + (
            f"periodic with {st.period_multiple} forcing period(s)"
            if st.periodic
            else f"not periodic within {MAX_MULTIPLE} periods (section spread {st.section_spread:.1e})"
        )
        + f"; energy residual {res.energy['relative_residual']:.1e}"
    )
    out = res.as_dict()
    if ns.response is not None:
        from ..forced.responses import response_unit
        from .frf import response_text

        value = steady_response(ns.response, res, discard)
        out["response"] = {"name": ns.response, "unit": response_unit(ns.response), "value": value}
        text += f"\nsteady {ns.response}: {response_text(ns.response, value)}"
    text += "".join(f"\nnote: {n}" for n in res.notes)
    emit(ns, out, text)


def run_structure(ns) -> None:
    """The forced response of a structure file's structure of several modes with its dampers,
    stops and force (Eq. F1 per mode, Step 15's impacts, Eq. F7; a pressed stop's spring and
    dashpot in the closed form): each damper's impacts, each stop's contacts and every point's
    steady amplitude."""
    import csv

    from ..errors import ParameterError
    from ..forced.simulation import period_count
    from ..forced.structure_response import simulate_structure
    from ..io import atomic_write
    from ..model.display import display_unit, omega_text

    for key, flag, why in (
        ("t_end", "t-end", "a forced run lasts --periods forcing periods"),
        ("rest", "rest", "applies to free vibration; a forced run never comes to rest"),
        ("response", "response", "the responses of a structure of several modes are not built "
                                 "yet: --json gives every point's amplitude"),
    ):  # fmt: skip
        if getattr(ns, key, None) is not None:
            raise ParameterError(flag, why)
    model = ns.structure_model
    forcing = structure_forcing(ns)
    periods = period_count("periods", "400" if ns.periods is None else ns.periods)
    discard = int(0.75 * periods) if ns.discard is None else period_count("discard", ns.discard)
    if discard >= periods:
        raise ParameterError("discard", f"must be fewer than --periods ({periods}), got {discard}")
    X_b = model.base_at(forcing.omega)
    res = simulate_structure(model.structure, model.dampers, model.force_at, model.F0,
                             forcing.omega, periods, forcing.phase, stops=model.stops,
                             base=X_b)  # fmt: skip
    amplitudes = {p: float(res.period_max[discard:, j].max()) for j, p in enumerate(res.points)}
    if ns.csv:

        def write(f):  # SI values, the unit in each header
            w = csv.writer(f)
            w.writerow(["period"] + [f"x_max {p} [m]" for p in res.points])
            w.writerows([[k, *map(float, row)] for k, row in enumerate(res.period_max)])

        atomic_write(ns.csv, write, "csv")
    if ns.plot:
        from ..report.plots import plot_structure_run

        plot_structure_run(res.period_max, res.points, forcing.period, discard,
                           ns.plot, title=f"{len(res.structure.modes)}-mode structure, Ω "
                           f"{omega_text(forcing.omega)}")  # fmt: skip
    text = (
        f"{res.structure.source} model, {len(res.structure.modes)} modes; "
        + (f"force {model.F0:.6g} N at {model.force_at!r}" if model.F0 else "no force")
        + (f", supports moving {quantity_text('x', X_b)} (absolute amplitudes)" if X_b else "")
        + f", Ω {omega_text(forcing.omega)}"
        + ("" if display_unit("omega") == "Hz" else f" ({forcing.freq:.6g} Hz)")
        + f"; {periods} periods, steady over the last {periods - discard}\n"
        + "".join(f"damper {d.name!r} at {d.at!r}: {len(res.impacts(d.name))} "
                  f"{'impacts' if d.rigid else d.contact + ' contacts'}\n" for d in res.dampers)
        + "".join(f"stop {s.name!r} at {s.at!r}: {len(res.contacts(s.name))} contacts\n"
                  for s in res.stops)
        + "\n".join(f"amplitude at {p!r}: {quantity_text('x', a)}"
                    for p, a in amplitudes.items())
        + f"\nenergy residual {res.energy['relative_residual']:.1e}"
        + "".join(f"\nnote: {n}" for n in res.notes)
    )  # fmt: skip
    out = res.as_dict()
    out["amplitudes"] = amplitudes
    out["periods"], out["discard"] = periods, discard
    emit(ns, out, text)


def _forced_outputs(ns, res, discard: int) -> None:
    """--csv: the state sampled _SAMPLES times per forcing period; --plot: x(t) and the
    impacts."""
    import numpy as np

    from ..forced.simulation import state_at

    T = res.forcing.period
    n = len(res.period_max)
    t = np.arange(n * _SAMPLES + 1) * (T / _SAMPLES)
    s = state_at(res, t)
    if ns.csv:
        rows = [
            {"t": a, "x": b, "xdot": c, "z": d, "ydot": f}
            for a, b, c, d, f in zip(t, s[:, 0], s[:, 1], s[:, 2], s[:, 3], strict=True)
        ]
        write_csv(ns.csv, "csv", rows)
    if ns.plot:
        from ..report.plots import plot_forced

        plot_forced(res, t, s, discard, ns.plot)


def _fraction(name: str, text: str) -> float:
    from ..errors import ParameterError

    try:
        return float(text)
    except ValueError:
        raise ParameterError(name, f"{text!r} is not a number") from None


#: The subcommands this module runs.
COMMANDS = {"simulate": run}
