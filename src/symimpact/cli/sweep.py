"""``symimpact sweep``: simulations over swept inputs (a sweep, or a map)."""

from __future__ import annotations

from typing import Any

from ..model.display import label, shown
from .common import (
    SYSTEM_DEFAULTS,
    add_initial,
    add_quiet,
    add_show,
    add_system,
    emit,
    fmt,
    progress_drawn,
    quantity_text,
    system_from,
    write_csv,
)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "sweep",
        aliases=["map"],
        help="simulations over one or more swept inputs (a sweep, or a map: grid or "
        "parameter sets), on local processes or a Dask cluster",
        description="Simulations over one or more swept inputs: a sweep, or a map (a grid or "
        "parameter sets), on local processes or a Dask cluster.  'symimpact map' and "
        "'symimpact sweep' are two names of this one command.",
    )
    add_system(p)
    add_initial(p)
    g = p.add_argument_group("what is swept (give --vary, --sets or --values)")
    g.add_argument(
        "--vary",
        action="append",
        default=[],
        metavar="NAME=RANGE",
        help='a swept input and its values, "start:stop:step" or "v1,v2,..." with units, e.g. '
        '--vary "gap=6 mm:35 mm:1 mm" --vary mass_ratio=0.1,0.2 (in a range every value carries '
        "its unit, or none for SI: 6 mm:35 mm:1 is refused); repeat for a grid (the first varies "
        "slowest); names: " + ", ".join(_sweepable()),
    )
    g.add_argument(
        "--sets",
        metavar="FILE.csv",
        help="parameter sets, one per row; header cells are input names, optionally with a unit "
        '("gap [mm]")',
    )
    g.add_argument("--over", default="gap", metavar="NAME", help="input swept by --values")
    g.add_argument(
        "--values",
        metavar="RANGE",
        help='"start:stop:step" or "v1,v2,..." of --over; for gaps --gap may hold the range',
    )
    g = p.add_argument_group("execution and files")
    g.add_argument(
        "--executor",
        choices=("serial", "processes", "dask"),
        default=None,
        help="default processes (all cores), or dask with --scheduler",
    )
    g.add_argument("--workers", type=int, default=None, help="processes; default all cores")
    g.add_argument(
        "--scheduler", metavar="ADDRESS", help="run on this Dask scheduler (tcp://host:8786)"
    )
    g.add_argument("--chunk-size", type=int, default=None, help="runs per task")
    g.add_argument(
        "--out",
        metavar="FILE",
        help="stream the table to FILE.csv or FILE.parquet as chunks finish; the same command "
        "after an interruption computes only the missing runs (a symbolic link: written to its "
        "target)",
    )
    g.add_argument("--force", action="store_true", help="replace an existing --out file")
    add_quiet(g)
    g = p.add_argument_group("output")
    g.add_argument("--json", action="store_true", help="machine-readable rows on stdout (SI)")
    add_show(g)
    g.add_argument(
        "--csv",
        metavar="FILE",
        help="write the table as CSV when done (a symbolic link: to its target)",
    )
    g.add_argument(
        "--plot",
        metavar="FILE.png",
        help="one swept input: DI, N_eff and effectiveness against it; two or more: a heat map "
        "of --value over --axes with the optimum marked (a symbolic link: to its target)",
    )
    g.add_argument(
        "--value", default="damping_inclination", metavar="OUTPUT", help="heat-map output"
    )
    g.add_argument(
        "--axes", metavar="X,Y", help="heat-map inputs; default the first two swept inputs"
    )
    g.add_argument("--best", choices=("max", "min"), default="max", help="optimum; default max")


def _sweepable() -> tuple[str, ...]:
    from ..model.names import SWEEPABLE

    return SWEEPABLE


def _points(ns):
    from ..errors import ParameterError
    from ..maps import as_points

    given = [
        flag for flag, v in (("--vary", ns.vary), ("--sets", ns.sets), ("--values", ns.values)) if v
    ]
    if len(given) > 1:
        raise ParameterError(
            given[1][2:], f"give one of --vary, --sets, --values, not {', '.join(given)}"
        )
    if ns.sets:
        from ..maps import read_sets

        return read_sets(ns.sets, progress=progress_drawn(ns))
    grid: dict[str, str] = {}
    for item in ns.vary:
        if "=" not in item:
            raise ParameterError("vary", f"{item!r} must be NAME=RANGE")
        name, spec = (t.strip() for t in item.split("=", 1))
        name = name.replace("-", "_")
        if name in grid:
            raise ParameterError(name, "is swept twice")
        grid[name] = spec
    if not grid:
        over = ns.over.replace("-", "_")
        spec = ns.values
        if spec is None and over == "gap" and ns.gap and (":" in ns.gap or "," in ns.gap):
            spec = ns.gap
        if spec is None:
            raise ParameterError(
                "values", "give the swept values (--vary, --sets, --values, or a range in --gap)"
            )
        grid[over] = spec
    for name in grid:
        value = getattr(ns, name, None)
        if isinstance(value, str) and (":" in value or "," in value):
            setattr(ns, name, SYSTEM_DEFAULTS.get(name))  # the range is swept, not the base
    return as_points(grid)


def run(ns) -> None:
    from ..maps import parameter_map, table_rows

    points = _points(ns)
    system = system_from(ns)
    table = parameter_map(
        system,
        sets=points,
        x0=ns.x0,
        xdot0=ns.xdot0,
        y0=ns.y0,
        ydot0=ns.ydot0,
        t_end=ns.t_end,
        contact=ns.contact,
        executor=ns.executor,
        workers=ns.workers,
        scheduler=ns.scheduler,
        out=ns.out,
        force=ns.force,
        chunk_size=ns.chunk_size,
        progress=progress_drawn(ns),
    )
    rows = table_rows(table)
    if ns.csv:
        write_csv(ns.csv, "csv", rows)
    notes = []
    if ns.out:
        notes.append(f"wrote {ns.out} ({len(rows)} runs)")
    if ns.plot:
        notes.append(_plot_sweep(ns, table, points.names))
    names = points.names
    di_head = label("damping_inclination").replace("damping_inclination", "DI")
    if len(rows) <= 60:
        head = " ".join(f"{label(n):>14}" for n in names)
        lines = [
            f"{head} {'N_tot':>6} {'N_eff':>6} {'effect.':>8} {di_head:>11} {'ζ_eq':>9}  class"
        ]
        for r in rows:
            lines.append(
                " ".join(f"{shown(n, r[n]):>14.6g}" for n in names)
                + f" {r['n_impacts']:>6} {r['n_effective']:>6} {fmt(r['effectiveness'], '.3f'):>8}"
                f" {fmt(shown('damping_inclination', r['damping_inclination']), '.5g'):>11}"
                f" {fmt(r['zeta_eq'], '.5f'):>9}  {r['class']}"
            )
    else:
        lines = [f"{len(rows)} runs over {', '.join(names)}"]
        di = table["damping_inclination"].astype("float64")
        if di.notna().any():
            best = rows[int(di.idxmax())]
            at = ", ".join(f"{n} = {quantity_text(n, best[n])}" for n in names)
            lines.append(
                f"largest DI {quantity_text('damping_inclination', best['damping_inclination'])} at {at}"
            )
        counts = table["class"].value_counts()
        lines.append(", ".join(f"{k}: {v}" for k, v in counts.items()))
    lines += _without_damper(ns, system, names)
    emit(ns, rows, "\n".join(lines + notes))


#: Swept inputs that change the primary alone (its mass, spring, damper or start).
PRIMARY_INPUTS = ("M", "K", "C", "zeta", "x0", "xdot0", "t_end")


def _without_damper(ns, system, names) -> list[str]:
    """The line giving DI and ζ_eq of the primary alone from the same start (Eq. 36 and the
    envelope's decay; for a linear oscillator ζ_eq = ζ): the baseline every row compares with."""
    from ..errors import SymimpactError
    from ..free.simulation import simulate

    varied = [n for n in names if n in PRIMARY_INPUTS]
    if varied:
        return [f"without the damper: differs from row to row ({varied[0]} varies)"]
    try:  # the impact mass rides with the primary in a clearance it never reaches
        alone = simulate(system.with_(gap=1e3), x0=ns.x0, xdot0=ns.xdot0, y0=ns.x0,
                         ydot0=ns.xdot0, t_end=ns.t_end)  # fmt: skip
    except SymimpactError as exc:
        return [f"without the damper: not computed ({exc})"]
    if alone.n_impacts:
        return []
    di, zeta_eq = alone.damping_inclination, alone.zeta_eq
    return [
        "without the damper (the primary alone from the same start):",
        "  DI "
        + ("n/a" if di is None else quantity_text("damping_inclination", di))
        + f", ζ_eq {fmt(zeta_eq, '.5f')} (its own ζ {system.zeta:.5f})",
    ]


#: The column names the text table shows, for the outputs they stand for (``--value DI``).
TABLE_NAMES = {"DI": "damping_inclination", "N_tot": "n_impacts", "N_eff": "n_effective",
               "effect.": "effectiveness", "ζ_eq": "zeta_eq"}  # fmt: skip


def _plot_sweep(ns, table, names) -> str:
    from ..errors import ParameterError
    from ..maps import table_rows
    from ..report.plots import plot_map, plot_sweep

    if len(names) == 1:
        plot_sweep(table_rows(table), names[0], ns.plot)
        return f"wrote {ns.plot}"
    if ns.axes:
        axes = [a.strip().replace("-", "_") for a in ns.axes.split(",")]
        if len(axes) != 2:
            raise ParameterError("axes", f"{ns.axes!r} must be two swept inputs X,Y")
    else:
        axes = list(names[:2])
    value = TABLE_NAMES.get(ns.value, ns.value)  # the names the text table shows
    opt = plot_map(table, axes[0], axes[1], value, ns.plot, best=ns.best)
    text = (
        f"wrote {ns.plot}: {ns.best} {ns.value} {quantity_text(value, opt[value])} at "
        f"{axes[0]} = {quantity_text(axes[0], opt[axes[0]])}, "
        f"{axes[1]} = {quantity_text(axes[1], opt[axes[1]])}"
    )
    if opt["isolated"]:
        text += (
            f" — isolated: its best neighbour gives {quantity_text(value, opt['neighbour_best'])}"
            " (a lone cell the neighbourhood does not confirm; refine the grid there)"
        )
    return text


#: The subcommands this module runs.
COMMANDS = {"sweep": run, "map": run}
