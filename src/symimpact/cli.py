"""``symimpact``: the command line (subcommands reproduce, ritz, fit, contact-duration, simulate,
sweep or map).

Every parameter takes an SI number or a quantity with units ("100 N/cm", "9 mm").  Bad input exits
with status 2 and one line naming the parameter and the reason.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import re
import sys
from collections.abc import Sequence
from typing import Any

from .display import label, shown
from .errors import SymimpactError

#: The defaults are one stated system in which impacts happen and DI is defined: the report's
#: reading of the paper's Table 2 (K in N/m, c1 = 5C = 5 N s/m, Ẋ0 = 0.5 m/s, t' = t·√(K/M) = 200).
SYSTEM_OPTIONS = [
    ("--M", "main mass M [kg]", "1 kg"),
    ("--K", "main stiffness K [N/m]", "100 N/m"),
    ("--C", "main damping C [N s/m] (or --zeta)", "1 N s/m"),
    ("--zeta", "damping ratio ζ = C/(2√(KM)) [1], instead of --C", None),
    ("--m", "impact mass m [kg]", "0.25 kg"),
    ("--gap", "clearance d [m]", "9 mm"),
    ("--a", "cubic coefficient a [N/m^3] (Eq. 9)", "0.1553 N/cm^3"),
    ("--b", "cubic coefficient b [N/m] (Eq. 9)", "0.8360 N/cm"),
    ("--k-hz", "Hertz stiffness K_Hz [N/m^1.5] (Eq. 8)", "1000 N/m^1.5"),
    ("--k1", "linear contact stiffness k1 [N/m] (Eq. 35); default fitted to K_Hz", None),
    ("--c1", "contact damping c1 [N s/m] (Eq. 10)", "5 N s/m"),
]


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> None:  # one line, status 2, no usage dump
        self.exit(2, f"{self.prog}: error: {message}\n")


def _add_system(p: argparse.ArgumentParser, contact: bool = True) -> None:
    g = p.add_argument_group("system (SI numbers or quantities with units)")
    for flag, helptext, default in SYSTEM_OPTIONS:
        g.add_argument(
            flag,
            dest=flag[2:].replace("-", "_"),
            default=None if flag == "--C" else default,  # --zeta replaces the default C
            metavar="Q",
            help=f"{helptext}; default {default!r}" if default else helptext,
        )
    if contact:
        g.add_argument(
            "--contact",
            choices=("cubic", "hertz", "linear", "perturbation"),
            default="cubic",
            help="contact law integrated numerically, or the perturbation solution (Eq. 31–33); "
            "default cubic",
        )


def _system(ns: argparse.Namespace):
    from .system import ImpactSystem

    law = getattr(ns, "contact", "cubic")
    kw: dict[str, Any] = {
        k: getattr(ns, k) for k in ("M", "K", "C", "zeta", "m", "gap", "k_hz", "k1", "c1")
    }
    if kw["C"] is None and kw["zeta"] is None:
        kw["C"] = dict((f, d) for f, _, d in SYSTEM_OPTIONS)["--C"]
    return ImpactSystem(contact="cubic" if law == "perturbation" else law, a=ns.a, b=ns.b, **kw)


def _add_initial(p: argparse.ArgumentParser) -> None:
    g = p.add_argument_group("initial state and duration")
    g.add_argument("--x0", default="0", metavar="Q", help="main-mass displacement [m]; default 0")
    g.add_argument(
        "--xdot0", default="0.5 m/s", metavar="Q", help="main-mass velocity [m/s]; default 0.5 m/s"
    )
    g.add_argument("--y0", default="0", metavar="Q", help="impact-mass displacement [m]; default 0")
    g.add_argument(
        "--ydot0", default="0", metavar="Q", help="impact-mass velocity [m/s]; default 0"
    )
    g.add_argument("--t-end", default="20 s", metavar="Q", help="end time [s]; default 20 s")


def _add_show(p: Any) -> None:
    p.add_argument(
        "--show",
        action="append",
        default=[],
        metavar="NAME=UNIT",
        help="show a quantity in another unit in text and plots, e.g. --show gap=µm "
        "(defaults: mm for gaps and displacements, µm for DI, ms for durations; JSON and CSV "
        "stay SI)",
    )


def _add_output(p: argparse.ArgumentParser, plot: bool = False) -> None:
    p.add_argument("--json", action="store_true", help="machine-readable output on stdout (SI)")
    _add_show(p)
    if plot:
        p.add_argument(
            "--plot", metavar="FILE.png", help="write a figure (a symbolic link: to its target)"
        )
        p.add_argument(
            "--csv", metavar="FILE", help="write a table (a symbolic link: to its target)"
        )


def build_parser() -> argparse.ArgumentParser:
    """The ``symimpact`` argument parser (also used to document the command line)."""
    parser = _Parser(
        prog="symimpact",
        description="Nonlinear resilient impact dampers: Ritz constants, contact fits, contact "
        "durations, simulations with impacts and gap sweeps.  Quantities accept units.",
    )
    from . import __version__

    parser.add_argument("--version", action="version", version=f"symimpact {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    p = sub.add_parser(
        "reproduce",
        help="the paper's tables and figures beside ours, as a report folder (HTML, Markdown, "
        "PNG, CSV)",
    )
    p.add_argument(
        "out",
        nargs="?",
        default="symimpact-report",
        help="report folder (created; must be new or empty unless --force); "
        "default symimpact-report",
    )
    p.add_argument("--quick", action="store_true", help="coarser grids: seconds, not a minute")
    p.add_argument(
        "--force",
        action="store_true",
        help="replace a report folder symimpact wrote before (never another non-empty folder)",
    )
    p.add_argument("--quiet", action="store_true", help="no progress bars")

    p = sub.add_parser("ritz", help="Ritz constants of the cantilever (Eq. 1–6)")
    for flag, helptext in (
        ("--E", "Young modulus E [Pa]"),
        ("--I", "second moment of area I [m^4]"),
        ("--rho", "density ρ [kg/m^3]"),
        ("--A", "cross-section A [m^2]"),
        ("--L", "length L [m]"),
        ("--position", "damper position from the clamp [m]; default the tip"),
    ):
        p.add_argument(flag, metavar="Q", help=helptext)
    _add_output(p)

    p = sub.add_parser("fit", help="cubic and linear fits of the Hertz law (Eq. 8–9, 35)")
    p.add_argument("--k-hz", default="1000 N/m^1.5", metavar="Q", help="K_Hz [N/m^1.5]")
    p.add_argument("--delta-max", default="2 cm", metavar="Q", help="fit range [m]; default 2 cm")
    p.add_argument(
        "--continuous", action="store_true", help="continuous least squares, not 21 samples"
    )
    _add_output(p)

    p = sub.add_parser("contact-duration", help="contact duration of one impact (Eq. 31, 34, 35)")
    _add_system(p, contact=False)
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
    _add_output(p)

    p = sub.add_parser("simulate", help="free vibration with impacts (Eq. 7, 10, 36–38)")
    _add_system(p)
    _add_initial(p)
    p.add_argument(
        "--rest",
        default="1e-12",
        metavar="FRACTION",
        help="stop at rest once the energy falls below this fraction of its initial value "
        "(0: never); default 1e-12",
    )
    _add_output(p, plot=True)

    p = sub.add_parser(
        "export",
        help="copy the generated kernels of one target (NumPy, C99, MATLAB/Octave) into a "
        "folder, with a README on how to compile, call or import them",
    )
    p.add_argument(
        "--target", required=True, choices=("c", "octave", "numpy"), help="which kernels"
    )
    p.add_argument(
        "--out", required=True, metavar="DIR", help="folder to create (new or empty unless --force)"
    )
    p.add_argument(
        "--force",
        action="store_true",
        help="replace a folder symimpact wrote before (never another non-empty folder)",
    )

    p = sub.add_parser(
        "sweep",
        aliases=["map"],
        help="simulations over one or more swept inputs (a sweep, or a map: grid or "
        "parameter sets), on local processes or a Dask cluster",
    )
    _add_system(p)
    _add_initial(p)
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
    g.add_argument("--quiet", action="store_true", help="no progress bar")
    g = p.add_argument_group("output")
    g.add_argument("--json", action="store_true", help="machine-readable rows on stdout (SI)")
    _add_show(g)
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
    return parser


def _emit(ns, data: dict[str, Any] | list[Any], text: str) -> None:
    if ns.json:
        json.dump(_jsonable(data), sys.stdout, indent=2, allow_nan=False)
        sys.stdout.write("\n")
    else:
        print(text)


def _jsonable(v: Any) -> Any:
    import numpy as np

    if isinstance(v, dict):
        return {str(k): _jsonable(x) for k, x in v.items()}
    if isinstance(v, list | tuple):
        return [_jsonable(x) for x in v]
    if isinstance(v, np.ndarray):
        return _jsonable(v.tolist())
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def _cmd_ritz(ns) -> None:
    from .generated import ritz
    from .system import beam_constants

    out: dict[str, Any] = {
        "beta_L": ritz.BETA_L[0],
        "stiffness_coefficient": float(ritz.stiffness_coefficient(ritz.BETA_L[0], 1.0)),
        "mass_coefficient": float(ritz.mass_coefficient(ritz.BETA_L[0], 1.0)),
    }
    beam = [ns.E, ns.I, ns.rho, ns.A, ns.L]
    if any(v is not None for v in beam):
        missing = [n for n, v in zip(("E", "I", "rho", "A", "L"), beam, strict=True) if v is None]
        if missing:
            raise SymimpactError(f"{missing[0]}: needed with the other beam parameters")
        K, M = beam_constants(*beam, position=ns.position)
        out.update(K=K, M=M)
        if ns.position is not None:
            from .units import positive_float

            xi = positive_float("position", ns.position) / positive_float("L", ns.L)
            out["stiffness_coefficient"] = float(ritz.stiffness_coefficient(ritz.BETA_L[0], xi))
            out["mass_coefficient"] = float(ritz.mass_coefficient(ritz.BETA_L[0], xi))
    units = {"K": "N/m", "M": "kg", "stiffness_coefficient": "(× EI/L³)",
             "mass_coefficient": "(× ρAL)"}  # fmt: skip
    lines = [f"{k} = {v:.10g} {units.get(k, '')}".rstrip() for k, v in out.items()]
    _emit(ns, out, "\n".join(lines))


def _cmd_fit(ns) -> None:
    from .generated import contact_fits as cf
    from .units import positive_float

    k = positive_float("k-hz", ns.k_hz, "N/m^1.5")
    d = positive_float("delta-max", ns.delta_max, "m")
    sfx = "_continuous" if ns.continuous else ""
    out = {
        "a": float(getattr(cf, f"cubic_fit_a{sfx}")(k, d)),
        "b": float(getattr(cf, f"cubic_fit_b{sfx}")(k, d)),
        "k1": float(getattr(cf, f"linear_fit_k1{sfx}")(k, d)),
    }
    _emit(ns, out, f"a = {out['a']:.6g} N/m^3\nb = {out['b']:.6g} N/m\nk1 = {out['k1']:.6g} N/m")


def _cmd_contact_duration(ns) -> None:
    from .contact import contact_duration, contact_durations

    system = _system(ns)
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
        f"{k:<22} {_quantity('duration', v)}" if isinstance(v, float) and k != "ba"
        else f"{k:<22} {v}"
        for k, v in out.items()
        if k != "perturbation_history"
    )  # fmt: skip
    _emit(ns, out, text)


def _cmd_simulate(ns) -> None:
    from .simulation import simulate

    system = _system(ns)
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
        _write_csv(ns.csv, "csv", [dict(zip(names, c, strict=True)) for c in columns])
    if ns.plot:
        from .plots import plot_simulation

        plot_simulation(res, ns.plot)
    out = res.as_dict()
    di = res.damping_inclination
    residual = res.energy["relative_residual"]
    text = (
        f"impacts {res.n_impacts}, effective {res.n_effective}, effectiveness "
        f"{_fmt(res.effectiveness, '.3g')}, DI {_fmt(None if di is None else di * 1e6, '.2f')} µm, "
        f"energy residual {_fmt(residual, '.1e')} of the initial energy"
    )
    text += "".join(f"\nnote: {n}" for n in res.notes)
    _emit(ns, out, text)


def _fraction(name: str, text: str) -> float:
    from .errors import ParameterError

    try:
        return float(text)
    except ValueError:
        raise ParameterError(name, f"{text!r} is not a number") from None


def _sweepable() -> tuple[str, ...]:
    from .maps import SWEEPABLE

    return SWEEPABLE


def _points(ns):
    from .errors import ParameterError
    from .maps import as_points

    given = [
        flag for flag, v in (("--vary", ns.vary), ("--sets", ns.sets), ("--values", ns.values)) if v
    ]
    if len(given) > 1:
        raise ParameterError(
            given[1][2:], f"give one of --vary, --sets, --values, not {', '.join(given)}"
        )
    if ns.sets:
        from .maps import read_sets

        return read_sets(ns.sets, progress=not ns.quiet)
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


SYSTEM_DEFAULTS = {flag[2:].replace("-", "_"): default for flag, _, default in SYSTEM_OPTIONS}


def _cmd_sweep(ns) -> None:
    from .maps import parameter_map, table_rows

    points = _points(ns)
    system = _system(ns)
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
        progress=not (ns.quiet or ns.json),
    )
    rows = table_rows(table)
    if ns.csv:
        _write_csv(ns.csv, "csv", rows)
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
                + f" {r['n_impacts']:>6} {r['n_effective']:>6} {_fmt(r['effectiveness'], '.3f'):>8}"
                f" {_fmt(shown('damping_inclination', r['damping_inclination']), '.5g'):>11}"
                f" {_fmt(r['zeta_eq'], '.5f'):>9}  {r['class']}"
            )
    else:
        lines = [f"{len(rows)} runs over {', '.join(names)}"]
        di = table["damping_inclination"].astype("float64")
        if di.notna().any():
            best = rows[int(di.idxmax())]
            at = ", ".join(f"{n} = {_quantity(n, best[n])}" for n in names)
            lines.append(
                f"largest DI {_quantity('damping_inclination', best['damping_inclination'])} at {at}"
            )
        counts = table["class"].value_counts()
        lines.append(", ".join(f"{k}: {v}" for k, v in counts.items()))
    _emit(ns, rows, "\n".join(lines + notes))


def _quantity(name: str, value: float) -> str:
    """``6 mm``-style text of an SI value in its display unit."""
    from .display import display_unit

    unit = display_unit(name)
    text = f"{shown(name, value):.6g}"
    return text if unit == "dimensionless" else f"{text} {unit}"


def _fmt(v, spec: str) -> str:
    """A value for people: ``spec``-formatted, or "—" where it is missing (JSON has null)."""
    return "—" if v is None else format(v, spec)


def _plot_sweep(ns, table, names) -> str:
    from .errors import ParameterError
    from .maps import table_rows
    from .plots import plot_map, plot_sweep

    if len(names) == 1:
        plot_sweep(table_rows(table), names[0], ns.plot)
        return f"wrote {ns.plot}"
    if ns.axes:
        axes = [a.strip().replace("-", "_") for a in ns.axes.split(",")]
        if len(axes) != 2:
            raise ParameterError("axes", f"{ns.axes!r} must be two swept inputs X,Y")
    else:
        axes = list(names[:2])
    opt = plot_map(table, axes[0], axes[1], ns.value, ns.plot, best=ns.best)
    return (
        f"wrote {ns.plot}: {ns.best} {ns.value} {_quantity(ns.value, opt[ns.value])} at "
        f"{axes[0]} = {_quantity(axes[0], opt[axes[0]])}, "
        f"{axes[1]} = {_quantity(axes[1], opt[axes[1]])}"
    )


def _write_csv(path: str, what: str, rows: list[dict[str, Any]]) -> None:
    from .display import csv_header
    from .io import atomic_write

    def write(f):  # SI values, each header with its SI unit ("gap [m]")
        names = list(rows[0]) if rows else []
        w = csv.writer(f)
        w.writerow([csv_header(n) for n in names])
        w.writerows([[r[n] for n in names] for r in _jsonable(rows)])

    atomic_write(path, write, what)


def _cmd_reproduce(ns) -> None:
    from .report import reproduce

    out, sections = reproduce(ns.out, quick=ns.quick, force=ns.force, progress=not ns.quiet)
    n_fig = sum(len(s.figures()) for s in sections)
    n_tab = sum(len(s.tables()) for s in sections)
    print(
        f"wrote {out}/index.html (open it in a browser), report.md, {n_fig} figures, {n_tab} tables"
    )


def _cmd_export(ns) -> None:
    from .export import export_kernels

    paths = export_kernels(ns.target, ns.out, force=ns.force)
    print(f"wrote {len(paths)} {ns.target} files to {ns.out} (see {ns.out}/README.md)")


COMMANDS = {
    "reproduce": _cmd_reproduce,
    "export": _cmd_export,
    "ritz": _cmd_ritz,
    "fit": _cmd_fit,
    "contact-duration": _cmd_contact_duration,
    "simulate": _cmd_simulate,
    "sweep": _cmd_sweep,
    "map": _cmd_sweep,
}


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
    """A SIGTERM/SIGHUP handler: end the pool workers, say so in one line, exit 128 + N.

    It does not raise into the main thread: an exception raised by a signal handler while a
    finaliser runs is printed and dropped, and the command would go on to the end.  Nothing is
    lost by ending at once: every output is written to a temporary name and renamed when
    complete, and the leftovers of an ended run are removed by the next one."""

    def end(signum, frame) -> None:
        import multiprocessing
        import os

        for child in multiprocessing.active_children():
            child.terminate()
        print(f"symimpact {command}: ended by signal {signum}", file=sys.stderr, flush=True)
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


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``symimpact``; returns the exit status (see ``EXIT_*``: 2 on bad input, 3
    on a fault, 128 + N on signal N)."""
    import signal
    import warnings

    parser = build_parser()
    argv = sys.argv[1:] if argv is None else list(argv)
    ns = parser.parse_args(_join_negative_values(parser, argv))
    from . import display

    units_before = dict(display.DISPLAY_UNITS)
    shown_warning = warnings.showwarning
    warnings.showwarning = _one_line_warning(ns.command)  # every warning: one line
    previous = {}
    for sig in (signal.SIGTERM, signal.SIGHUP):
        try:
            previous[sig] = signal.signal(sig, _ending_on_signal(ns.command))
        except ValueError:  # not the main thread (e.g. called from a worker thread)
            pass
    try:
        display.parse_show(getattr(ns, "show", []))
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
