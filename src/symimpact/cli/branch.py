"""``symimpact branch``: one branch of periodic orbits continued in the clearance d, the force
amplitude F0, the base-motion amplitude X_b or the restitution e at a fixed forcing frequency —
the orbit a brute-force run from rest settles near, found by shooting, then followed both ways by
pseudo-arclength continuation (:func:`symimpact.forced.trace_branch`) with its stability and
located bifurcations."""

from __future__ import annotations

from typing import Any

from .. import budgets
from .common import add_forcing, add_output, add_system, emit, forcing_from, system_from, write_csv

#: The parameters ``--parameter`` takes (Ω is ``symimpact frf``'s).
PARAMETERS = ("gap", "F0", "X_b", "e")


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "branch",
        help="a branch of periodic orbits continued in the clearance, F0, X_b or e",
        epilog=budgets.text(),
    )
    add_system(p, extra_laws=("rigid", "hunt-crossley"), contact_default=None)
    add_forcing(p)
    g = p.add_argument_group("continuation")
    g.add_argument("--chi", default=None, metavar="Q",
                   help="Hunt–Crossley damping χ [s/m] of --contact hunt-crossley (Eq. F4)")  # fmt: skip
    g.add_argument("--parameter", choices=PARAMETERS, required=True,
                   help="what the branch is continued in: the clearance gap, the force F0, the "
                   "base motion X_b or the restitution e (rigid impacts)")  # fmt: skip
    g.add_argument("--range", dest="bounds", required=True, metavar="LOW:HIGH",
                   help="the parameter's range, with units, e.g. '5 mm:40 mm'; it must hold "
                   "the start (the system's value)")  # fmt: skip
    g.add_argument("--warmup", default=None, metavar="N",
                   help="forcing periods simulated from rest before shooting; default 300")  # fmt: skip
    g.add_argument("--multiple", default=None, metavar="K",
                   help="an orbit of K forcing periods (K > 1: a subharmonic); default 1")  # fmt: skip
    add_output(p, plot=True)


def bounds_from(ns) -> tuple[float, float]:
    """(low, high) of --range in SI, in the unit of --parameter (one line when malformed)."""
    from ..errors import ParameterError
    from ..model.units import si, units_alike

    parts = str(ns.bounds).split(":")
    if len(parts) != 2:
        raise ParameterError("range", f"must be LOW:HIGH, got {ns.bounds!r}")
    units_alike("range", str(ns.bounds), parts)
    lo, hi = (si(ns.parameter, part.strip()) for part in parts)
    if not lo < hi:
        raise ParameterError("range", f"LOW must be below HIGH, got {ns.bounds!r}")
    return float(lo), float(hi)


def run(ns) -> None:
    from ..errors import ParameterError
    from ..forced import shoot_from_rest, trace_branch
    from ..forced.continuation import PARAMETERS as UNITS
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..model.display import display_unit, omega_text, shown
    from .frf import contact_of, contact_title

    e = contact_of(ns)
    system = system_from(ns)
    forcing = forcing_from(ns)
    bounds = bounds_from(ns)
    if ns.parameter == "e" and ns.contact != "rigid":
        raise ParameterError("parameter", "e is continued for rigid impacts; a compliant law "
                             "sets its own restitution")  # fmt: skip
    start = {"gap": system.gap, "F0": forcing.F0, "X_b": forcing.X_b}.get(ns.parameter)
    start = float(e) if start is None else start
    if not bounds[0] <= start <= bounds[1]:
        raise ParameterError("range", f"must hold the start, {ns.parameter} = {start:g} (SI)")
    warmup = period_count("warmup", "300" if ns.warmup is None else ns.warmup)
    multiple = period_count("multiple", "1" if ns.multiple is None else ns.multiple)
    if not 1 <= multiple <= MAX_MULTIPLE:
        raise ParameterError("multiple", f"must be 1 to {MAX_MULTIPLE}, got {multiple}")
    orbit = shoot_from_rest(system, forcing, e, warmup=warmup, periods=multiple)
    branch = trace_branch(system, forcing, e, orbit.state, bounds, parameter=ns.parameter,
                          periods=multiple)  # fmt: skip
    name = ns.parameter
    out = {
        "parameter": name,
        "unit": UNITS[name],
        "omega": forcing.omega,
        "start": orbit.as_dict(),
        "points": [
            {
                "value": p.value,
                "amplitude": p.amplitude,
                "stable": p.stable,
                "impacts_per_period": p.impacts_per_period,
                "period_multiple": branch.period_multiple,
            }
            for p in branch.points
        ],
        "bifurcations": [
            {"kind": f.kind, "value": f.value, "amplitude": f.amplitude}
            for f in branch.bifurcations
        ],
        "stopped": branch.stopped,
    }
    if ns.csv:
        # the parameter's own column name, so the header carries its unit ("gap [m]")
        write_csv(ns.csv, "csv", [{name: r["value"], **{k: v for k, v in r.items() if k != "value"}}
                                  for r in out["points"]])  # fmt: skip
    if ns.plot:
        from ..report.plots import plot_branch

        plot_branch(branch, ns.plot,
                    title=f"Ω = {forcing.omega:.4g} rad/s, {contact_title(ns, e)}")  # fmt: skip
    unit = display_unit("x")

    def shown_value(v: float) -> str:
        if name in ("gap", "X_b"):
            return f"{shown('gap', v):.5g} {display_unit('gap')}"
        return f"{v:.6g}{' ' + UNITS[name] if UNITS[name] else ''}"

    values = [p.value for p in branch.points]
    stable = sum(p.stable for p in branch.points)
    lines = [
        f"Ω {omega_text(forcing.omega)}: a branch of {multiple} forcing period(s) in {name}, "
        f"{len(values)} points over {shown_value(min(values))} – {shown_value(max(values))}, "
        f"{stable} stable; {len(branch.bifurcations)} located bifurcation(s)"
    ]
    for f in branch.bifurcations:
        lines.append(f"  {f.kind} at {name} = {shown_value(f.value)}, amplitude "
                     f"{shown('x', f.amplitude):.5g} {unit}")  # fmt: skip
    lines.append(f"ends: {branch.stopped}")
    emit(ns, out, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"branch": run}
