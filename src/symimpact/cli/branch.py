"""``symimpact branch``: one branch of periodic orbits continued in the clearance d, the force
amplitude F0, the base-motion amplitude X_b or the restitution e at a fixed forcing frequency —
the orbit a brute-force run from rest settles near, found by shooting, then followed both ways by
pseudo-arclength continuation (:func:`symimpact.forced.trace_branch`) with its stability and
located bifurcations."""

from __future__ import annotations

from typing import Any

from .. import budgets
from .common import add_forcing, add_output, add_system, emit, forcing_from, system_from, write_csv

#: The parameters ``--parameter`` takes (Ω is ``symimpact frf``'s); m, a damper's mass, is a
#: structure file's (``--structure``), X_b the one-mode primary's.
PARAMETERS = ("gap", "F0", "X_b", "e", "m")


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
                   "base motion X_b or the restitution e (rigid impacts); with a --structure "
                   "file that gives dampers: gap, e or the mass m of --damper, or F0")  # fmt: skip
    g.add_argument("--damper", default=None, metavar="NAME",
                   help="with --structure: the damper whose gap, e or m is continued (default: "
                   "the file's only damper)")  # fmt: skip
    g.add_argument("--range", dest="bounds", required=True, metavar="LOW:HIGH",
                   help="the parameter's range, with units, e.g. '5 mm:40 mm'; it must hold "
                   "the start (the system's value)")  # fmt: skip
    g.add_argument("--warmup", default=None, metavar="N",
                   help="forcing periods simulated from rest before shooting; default 300")  # fmt: skip
    g.add_argument("--multiple", default=None, metavar="K",
                   help="an orbit of K forcing periods (K > 1: a subharmonic); default 1")  # fmt: skip
    g.add_argument("--folds", default=None, metavar="N",
                   help="rigid impacts: at most N times in each direction the branch turns back "
                   "at a grazing beyond which no orbit continues it, onto the orbits with the "
                   "new impact (a non-smooth fold); default 0: the branch ends there")  # fmt: skip
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
    if getattr(ns, "structure_model", None) is not None:
        return run_structure(ns)
    from ..errors import ParameterError
    from ..forced import shoot_from_rest, trace_branch
    from ..forced.orbits.continuation import PARAMETERS as UNITS
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..model.display import display_unit, omega_text, shown
    from .frf import contact_of, contact_title
    from .loads import count

    if ns.parameter == "m":
        raise ParameterError("parameter", "m, a damper's mass, is continued on a --structure "
                                          "file's damper")  # fmt: skip
    if ns.damper is not None:
        raise ParameterError("damper", "names a damper of a --structure file, which is not given")
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
    folds = 0 if ns.folds is None else count("folds", ns.folds, 0, 1000)
    orbit = shoot_from_rest(system, forcing, e, warmup=warmup, periods=multiple)
    branch = trace_branch(system, forcing, e, orbit.state, bounds, parameter=ns.parameter,
                          periods=multiple, folds=folds)  # fmt: skip
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


def run_structure(ns) -> None:
    """A structure file with dampers or stops: the orbit a run of --warmup periods from rest
    settles near at --omega, shot on the state of its N modes and K dampers, continued both ways
    over --range in a damper's gap, e or m or in F0
    (:func:`symimpact.forced.orbits.structure_branch.parameter_branch`), with its bifurcations and
    grazings located."""
    from ..errors import ParameterError
    from ..forced.orbits.structure_branch import PARAMETERS as UNITS
    from ..forced.orbits.structure_branch import parameter_branch
    from ..forced.orbits.structure_orbits import shoot_structure
    from ..forced.simulation import MAX_MULTIPLE, period_count
    from ..forced.structure_response import simulate_structure
    from ..model.display import omega_text
    from .common import quantity_text, structure_forcing

    for key, why in (("chi", "the file gives each damper's and stop's contact"),
                     ("folds", "a structure's branch ends at a grazing no orbit continues "
                               "beyond; turning back there is the one-mode model's")):  # fmt: skip
        if getattr(ns, key, None) is not None:
            raise ParameterError(key, why)
    model = ns.structure_model
    if ns.parameter not in UNITS:
        raise ParameterError("parameter", f"{ns.parameter} is the one-mode primary's; a "
                             f"structure's branch is continued in {', '.join(UNITS)}")  # fmt: skip
    forcing = structure_forcing(ns)
    names = [d.name for d in model.dampers]
    damper = None
    if ns.parameter == "F0":
        if ns.damper is not None:
            raise ParameterError("damper", "names the damper whose gap, e or m is continued, "
                                           "not F0")  # fmt: skip
        start_value = model.F0
        if start_value == 0.0:
            raise ParameterError("parameter", f"{ns.structure} gives no force to continue")
    else:
        damper = ns.damper if ns.damper is not None else (names[0] if len(names) == 1 else None)
        if damper not in names:
            raise ParameterError("damper", f"name the damper whose {ns.parameter} is continued "
                                           f"(the file's dampers: {', '.join(names) or 'none'})")  # fmt: skip
        start_value = getattr(model.dampers[names.index(damper)], ns.parameter)
    low, high = bounds_from(ns)
    if not low <= start_value <= high:
        raise ParameterError("range", f"must hold the start, {ns.parameter} = {start_value:g} "
                                      "(SI, the file's)")  # fmt: skip
    if low <= 0.0 or (ns.parameter == "e" and high > 1.0):
        raise ParameterError("range", f"{ns.parameter} must lie in "
                                      f"{'(0, 1]' if ns.parameter == 'e' else '(0, ∞)'}, got "
                                      f"{ns.bounds!r}")  # fmt: skip
    warmup = period_count("warmup", "300" if ns.warmup is None else ns.warmup)
    multiple = period_count("multiple", "1" if ns.multiple is None else ns.multiple)
    if not 1 <= multiple <= MAX_MULTIPLE:
        raise ParameterError("multiple", f"must be 1 to {MAX_MULTIPLE}, got {multiple}")
    args = (model.structure, model.dampers, model.force_at, model.F0)
    X_b = model.base_at(forcing.omega)
    settled = simulate_structure(*args, forcing.omega, periods=warmup, phase=forcing.phase,
                                 stops=model.stops, base=X_b)  # fmt: skip
    n = 2 * len(model.structure.modes) + 2 * len(model.dampers)
    try:
        start = shoot_structure(*args, forcing.omega, settled.final_state[1 : 1 + n], multiple,
                                model.stops, forcing.phase, base=X_b)  # fmt: skip
    except ParameterError as exc:
        raise ParameterError("multiple", f"no orbit of {multiple} period(s) near the state after "
                             f"--warmup {warmup} periods (Newton's method: {exc.reason}): "
                             "'symimpact periodic' with the same file says which --multiple "
                             "the motion comes back after") from None  # fmt: skip
    branches = []
    for end in (low, high):
        if end == start_value:
            continue
        try:
            branches.append(parameter_branch(*args, forcing.omega, ns.parameter, start_value,
                                             end, start.state, damper=damper, periods=multiple,
                                             stops=model.stops, phase=forcing.phase,
                                             base=X_b))  # fmt: skip
        except ParameterError as exc:  # the range's ends, named for the option that gives them
            if exc.parameter in ("start", "end"):
                raise ParameterError("range", exc.reason) from None
            raise
    unit = UNITS[ns.parameter]

    def value_text(v: float) -> str:
        if ns.parameter == "gap":
            return quantity_text("gap", v)
        return f"{v:.6g}{' ' + unit if unit else ''}"

    out = {"parameter": ns.parameter, "unit": unit, "damper": damper, "omega": forcing.omega,
           "start": start.as_dict() | {"value": start_value},
           "branches": [b.as_dict() for b in branches]}  # fmt: skip
    if ns.csv:
        from .common import structure_rows, write_csv

        write_csv(ns.csv, "csv", structure_rows(branches, model.structure.points,
                                                parameter=ns.parameter))  # fmt: skip
    if ns.plot:
        from ..report.plots import plot_structure_curve

        plot_structure_curve(branches, model.structure.points, ns.plot,
                             title=f"Ω {omega_text(forcing.omega)}, continued in {ns.parameter}"
                             + (f" of damper {damper!r}" if damper else ""),
                             parameter=ns.parameter)  # fmt: skip
    what = f"{ns.parameter} of damper {damper!r}" if damper else ns.parameter
    lines = [f"Ω {omega_text(forcing.omega)}: the orbit of {multiple} forcing period(s) at "
             f"{what} = {value_text(start_value)} ({'stable' if start.stable else 'unstable'}), "
             f"continued to {value_text(low)} and {value_text(high)}"]  # fmt: skip
    for b in branches:
        vs = b.values
        lines.append(f"towards {value_text(vs[-1])}: {len(b.orbits)} orbits, "
                     f"{sum(o.stable for o in b.orbits)} stable"
                     + (f"; {b.ended}" if b.ended else ""))  # fmt: skip
        for f in b.bifurcations:
            lines.append(f"  {f.kind} at {ns.parameter} = {value_text(f.value)} (multiplier "
                         f"{f.multiplier.real:.4f}{f.multiplier.imag:+.4f}i)")  # fmt: skip
        for g in b.grazings:
            lines.append(f"  grazing between {value_text(g['between'][0])} and "
                         f"{value_text(g['between'][1])}: {g['before']} → {g['after']}")  # fmt: skip
    for p in model.structure.points:
        amps = [o.amplitudes[p] for b in branches for o in b.orbits if o.stable]
        if amps:
            lines.append(f"largest stable amplitude at {p!r}: {quantity_text('x', max(amps))}")
    emit(ns, out, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"branch": run}
