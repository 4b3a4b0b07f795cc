"""``symimpact design``: the clearance design map — the worst steady amplitude of the primary
over a frequency band against the clearance (and the mass ratio), the best clearance of each
mass ratio, beside the primary without the damper (:mod:`symimpact.maps.design`)."""

from __future__ import annotations

import math
from typing import Any

from .. import budgets
from .common import (
    add_multistart,
    add_quiet,
    add_system,
    emit,
    forcing_of,
    progress_drawn,
    structure_band,
    system_from,
    write_csv,
)
from .frf import add_band, band_from, contact_of, contact_title


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "design",
        help="clearance design map: peak amplitude over a band against the clearance",
        epilog=budgets.text(),
    )
    add_system(p, extra_laws=("rigid", "hunt-crossley"), contact_default=None)
    g = p.add_argument_group("forcing F0·cos(Ωt) and/or base motion X_b·cos(Ωt) over a band")
    add_band(g)
    g = p.add_argument_group("the designs")
    g.add_argument("--gaps", required=True, metavar="RANGE",
                   help='clearances, e.g. "10 mm:200 mm:10 mm" or "10 mm,20 mm"')  # fmt: skip
    g.add_argument("--mass-ratios", default=None, metavar="RANGE",
                   help='mass ratios m/M, e.g. "0.02,0.05,0.1" (default: --m as given)')  # fmt: skip
    g.add_argument("--tolerance", default="0.01 mm", metavar="Q",
                   help="the best clearance is refined by Brent's method between the grid's "
                        "neighbours to this (default 0.01 mm)")  # fmt: skip
    add_multistart(g)
    g.add_argument("--e-samples", type=int, default=5, metavar="N",
                   help="with --e LOW:HIGH: restitutions sampled over the range (odd; default 5: "
                   "the ends, the middle and the quarters)")  # fmt: skip
    g.add_argument("--no-refine", action="store_true",
                   help="report the grid's best clearance as it is")  # fmt: skip
    g.add_argument("--response", default="displacement", metavar="NAME",
                   help="what the peaks measure: displacement (max |x|, default), "
                   "relative-displacement, acceleration, force (into the base) or "
                   "transmissibility, as for frf --response")  # fmt: skip
    g = p.add_argument_group("a --structure file with dampers")
    g.add_argument("--damper", default=None, metavar="NAME",
                   help="the damper whose clearance --gaps sweeps; default the file's first")  # fmt: skip
    g.add_argument("--point", default=None, metavar="NAME",
                   help="the point whose peak is compared; default the driven point")  # fmt: skip
    g = p.add_argument_group("execution and files")
    g.add_argument("--executor", choices=("serial", "processes", "dask"), default=None,
                   help="where the designs run (default: local processes)")  # fmt: skip
    g.add_argument("--workers", type=int, default=None, help="processes; default all cores")
    g.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="a running Dask scheduler, e.g. tcp://10.0.0.5:8786")  # fmt: skip
    g.add_argument("--out", default=None, metavar="FILE",
                   help="stream the rows to FILE (.csv or .parquet); run again to resume")  # fmt: skip
    g.add_argument("--overwrite", action="store_true", help="replace an existing --out file")
    add_quiet(g)
    g = p.add_argument_group("output")
    g.add_argument("--json", action="store_true", help="machine-readable rows on stdout (SI)")
    g.add_argument("--plot", metavar="FILE.png", help="write the design map's figure")
    g.add_argument("--csv", metavar="FILE", help="write the rows as CSV (SI, units in headers)")


def run_structure(ns) -> None:
    """--structure FILE with dampers: one damper's clearance chosen by the located peak of the
    structure's curve at a point (:func:`symimpact.maps.structure_design.structure_design`)."""

    from ..errors import ParameterError
    from ..maps.points import parse_range
    from ..maps.structure_design import structure_design
    from ..model.display import omega_text
    from .common import quantity_text

    refused = {"mass_ratios": "mass-ratios", "multistart": "multistart", "no_refine": "no-refine",
               "out": "out", "chi": "chi"}  # fmt: skip
    for key, flag in refused.items():
        if getattr(ns, key, None) not in (None, False):
            raise ParameterError(flag, "not taken by a structure's design yet (it sweeps one "
                                       "damper's clearance)")  # fmt: skip
    if ns.response not in (None, "displacement"):
        raise ParameterError("response", "a structure's design compares displacements")
    lo, hi, step = structure_band(ns)
    model = ns.structure_model
    if not model.dampers:
        raise ParameterError("structure", f"{ns.structure} gives no damper to design")
    damper = model.dampers[0].name if ns.damper is None else ns.damper
    point = model.force_at if ns.point is None else ns.point
    try:
        model.structure._point(point)
    except ParameterError as exc:
        raise ParameterError("point", exc.reason) from None
    gaps = parse_range("gaps", ns.gaps)
    d = structure_design(model.structure, model.dampers, model.force_at, model.F0, damper,
                         gaps, lo, hi, step, point, model.stops, base=model.base_at,
                         executor=ns.executor, workers=ns.workers,
                         scheduler=ns.scheduler)  # fmt: skip
    lines = [f"damper {damper!r}: its clearance against the peak at {point!r} over Ω "
             f"{omega_text(lo)}–{omega_text(hi)}"]  # fmt: skip
    for g, pk in zip(d.gaps, d.peaks, strict=True):
        lines.append(f"  gap {quantity_text('gap', g)}: " + ("no stable orbit traced" if pk is None
                     else f"peak {quantity_text('x', pk.amplitude)} at Ω {omega_text(pk.omega)} "
                     f"({pk.kind})"))  # fmt: skip
    best = d.best
    lines.append(f"bare structure: {quantity_text('x', d.bare.amplitude)} at Ω "
                 f"{omega_text(d.bare.omega)}")  # fmt: skip
    if best is not None:
        lines.append(f"best: gap {quantity_text('gap', best[0])}, peak "
                     f"{quantity_text('x', best[1].amplitude)} (reduction "
                     f"{100 * (1 - best[1].amplitude / d.bare.amplitude):.1f} %)")  # fmt: skip
    if ns.csv or ns.plot:
        rows = [{"gap": g, "peak_amplitude": math.nan if pk is None else pk.amplitude,
                 "peak_omega": math.nan if pk is None else pk.omega,
                 "peak_kind": "" if pk is None else pk.kind, "baseline_peak": d.bare.amplitude,
                 "baseline_omega": d.bare.omega,
                 "best": best is not None and g == best[0]}
                for g, pk in zip(d.gaps, d.peaks, strict=True)]  # fmt: skip
        if ns.csv:
            write_csv(ns.csv, "csv", rows)
        if ns.plot:
            import pandas as pd

            from ..report.plots import plot_design

            marks = [] if best is None else [{"gap": best[0], "peak_amplitude": best[1].amplitude}]
            plot_design(pd.DataFrame(rows), ns.plot, best=marks,
                        title=f"damper {damper!r}, peak at {point!r}")  # fmt: skip
    emit(ns, d.as_dict(), "\n".join(lines))


def run(ns) -> None:
    if getattr(ns, "structure_model", None) is not None:
        return run_structure(ns)
    if ns.damper is not None or ns.point is not None:
        from ..errors import ParameterError

        raise ParameterError("damper" if ns.damper is not None else "point",
                             "names a damper or point of a --structure file with dampers")  # fmt: skip
    from ..errors import ParameterError
    from ..maps.design import best_clearances, design_map, refine_best
    from ..maps.points import parse_range
    from ..maps.table import table_rows
    from ..model.display import display_unit, omega_text, shown
    from ..model.units import positive_float
    from .frf import response_text

    e_range = _e_range(ns)  # before the band's checks read --e as one number
    omegas = band_from(ns)
    system = system_from(ns)
    forcing = forcing_of(ns, omega=float(omegas[0]))
    grid: dict[str, Any] = {"gap": parse_range("gaps", ns.gaps)}
    if len(grid["gap"]) == 0:
        raise ParameterError("gaps", "give at least one clearance")
    if ns.mass_ratios is not None:
        grid["mass_ratio"] = parse_range("mass-ratios", ns.mass_ratios)
        if len(grid["mass_ratio"]) == 0:
            raise ParameterError("mass-ratios", "give at least one mass ratio")
    n = len(grid["gap"]) * len(grid.get("mass_ratio", [0]))
    if n > 10_000:
        raise ParameterError("gaps", f"{n} designs; at most 10000")
    if ns.workers is not None and ns.workers < 1:
        raise ParameterError("workers", "must be a positive integer")
    e = contact_of(ns)
    from ..forced.contact_law import is_rigid
    from ..forced.responses import checked_response

    response = checked_response(ns.response, forcing, rigid=is_rigid(e))
    tolerance = positive_float("tolerance", ns.tolerance, "m")
    if e_range is not None:
        if ns.mass_ratios is not None or ns.out is not None:
            raise ParameterError(
                "e", "a restitution range takes one mass ratio and no --out (it runs one map "
                "per restitution)"
            )  # fmt: skip
        return _robust(ns, system, forcing, e_range, omegas, grid["gap"], response)
    from ..forced.orbits.coverage import FREQUENCIES

    multistart = FREQUENCIES if ns.multistart is None else ns.multistart
    table = design_map(system, forcing, e, omegas, grid, executor=ns.executor,
                       workers=ns.workers, scheduler=ns.scheduler, out=ns.out,
                       force=ns.overwrite, progress=progress_drawn(ns),
                       multistart=multistart, response=response)  # fmt: skip
    rows = table_rows(table)
    if ns.no_refine or len(grid["gap"]) < 2:
        best = table_rows(best_clearances(table))
    else:
        best = refine_best(table, system, forcing, e, omegas, tolerance=tolerance,
                           multistart=multistart, response=response,
                           progress=progress_drawn(ns))  # fmt: skip
    rows, best = _named(rows, response), _named(best, response)

    def k(name: str) -> str:
        return _renamed(name, response)

    refined = not (ns.no_refine or len(grid["gap"]) < 2)
    if ns.csv:
        write_csv(ns.csv, "csv", csv_rows(rows, best if refined else []))
    if ns.plot:
        from ..report.plots import plot_design

        plot_design(table, ns.plot, title=f"band {shown('omega', omegas[0]):.4g}–"
                    f"{omega_text(omegas[-1], '.4g')}, "
                    f"{contact_title(ns, e)}", response=response,
                    best=[{**r, "peak_amplitude": r[k("peak_amplitude")]} for r in best]
                    if refined else None)  # fmt: skip
    gunit = display_unit("gap")

    def value(v: float) -> str:
        return response_text(response, v)

    what = "peak" if response == "displacement" else f"peak {response}"
    lines = [f"{len(rows)} design(s) over Ω {shown('omega', omegas[0]):.6g}–"
             f"{omega_text(omegas[-1])} ({len(omegas)} frequencies); without the damper the "
             f"{what} is {value(rows[0][k('baseline_peak')])} at Ω "
             f"{omega_text(rows[0]['baseline_omega'], '.5g')}"]  # fmt: skip
    for r in rows:
        ratio = f", m/M {r['mass_ratio']:g}" if "mass_ratio" in r else ""
        lines.append(
            f"d {shown('gap', r['gap']):.4g} {gunit}{ratio}: {what} "
            f"{value(r[k('peak_amplitude')])} at Ω {omega_text(r['peak_omega'], '.5g')} "
            f"({r['peak_motion']}), {r['peak_ratio']:.3f} of the primary alone"
        )
    for r in best:
        ratio = f" (m/M {r['mass_ratio']:g})" if "mass_ratio" in r else ""
        if "tolerance" in r:
            where = (f"d {gap_text(r['gap'], r['tolerance'])} {gunit} "
                     f"(Brent's method from the grid's {shown('gap', r['grid_gap']):.4g} {gunit} and a "
                     f"walk of {r['walk_moves']} step(s), {r['evaluations']} designs)")  # fmt: skip
        else:
            where = f"d {shown('gap', r['gap']):.4g} {gunit}"
        line = (f"best clearance{ratio}: {where}, {what} {value(r[k('peak_amplitude')])} "
                f"at Ω {omega_text(r['peak_omega'], '.5g')} ({r['peak_motion']}; "
                f"{r['peak_ratio']:.3f} of the primary alone)")  # fmt: skip
        if k("peak_e_minus") in r:
            line += (f"; the {what} with e − 0.1: {value(r[k('peak_e_minus')])}, "
                     f"with e + 0.1: {value(r[k('peak_e_plus')])}")  # fmt: skip
        lines.append(line)
    answer = headline(best, response)
    lines.insert(0, answer.pop("text"))
    emit(ns, {**answer, "designs": rows, "best": best, "response": _response_json(response)},
         "\n".join(lines))  # fmt: skip


def headline(best: list[dict[str, Any]], response: str) -> dict[str, Any]:
    """The design's answer, as frf states a curve's (the same JSON keys): ``peak`` (the worst
    case over the band at the best clearance: its value, Ω, motion, the clearance and, refined,
    its tolerance), ``baseline_peak`` (the primary alone's) and ``reduction`` (1 − peak/baseline),
    and ``text``, the line the command prints first: the clearance with its tolerance, the worst
    case and its Ω, the primary alone's peak, and the reduction in % and in dB
    (20·log₁₀(baseline/peak)).  With several mass ratios, the best of their best."""
    from ..forced.responses import response_key
    from ..model.display import display_unit, omega_text, shown
    from .frf import decibels, response_text

    def k(name: str) -> str:
        return _renamed(name, response)

    top = min(best, key=lambda r: r[k("peak_amplitude")])
    key = "amplitude" if response == "displacement" else response_key(response)
    peak, base = top[k("peak_amplitude")], top[k("baseline_peak")]
    reduction = 1.0 - peak / base
    gunit = display_unit("gap")
    where = (gap_text(top["gap"], top["tolerance"]) if "tolerance" in top
             else f"{shown('gap', top['gap']):.6g}")  # fmt: skip
    ratio = f" (m/M {top['mass_ratio']:g})" if "mass_ratio" in top else ""
    what = "worst case" if response == "displacement" else f"worst-case {response}"
    text = (f"best clearance{ratio}: d {where} {gunit}; {what} {response_text(response, peak)} "
            f"at Ω {omega_text(top['peak_omega'], '.5g')} ({top['peak_motion']}); without the "
            f"damper {response_text(response, base)} at Ω "
            f"{omega_text(top['baseline_omega'], '.5g')}; reduction {100 * reduction:.1f} % "
            f"({decibels(base, peak) or 'no motion left'})")  # fmt: skip
    out = {key: peak, "omega": top["peak_omega"], "motion": top["peak_motion"],
           "gap": top["gap"]}  # fmt: skip
    if "tolerance" in top:
        out["tolerance"] = top["tolerance"]
    if "mass_ratio" in top:
        out["mass_ratio"] = top["mass_ratio"]
    return {"peak": out, "baseline_peak": {key: base, "omega": top["baseline_omega"]},
            "reduction": reduction, "text": text}  # fmt: skip


def gap_text(gap: float, tolerance: float) -> str:
    """A refined clearance and its tolerance [m] in the display unit, the clearance given to the
    decimal place of the tolerance's leading digit: "9.2 ± 0.5", "20.10 ± 0.01", "49 ± 2"."""
    from ..model.display import shown

    g, tol = shown("gap", gap), shown("gap", tolerance)
    places = max(0, -math.floor(math.log10(tol))) if tol > 0 else 6
    return f"{g:.{places}f} ± {tol:.2g}"


def csv_rows(rows: list[dict[str, Any]], best: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The design map's rows for the CSV, each flagged ``refined`` False, then the refined best
    clearances (``best``, from Brent's method between grid points) flagged True, in the grid's
    columns with their ``tolerance`` (empty on grid rows): the CSV holds the answer the command
    prints and draws."""
    names = list(rows[0]) if rows else []
    out = [{**{n: r.get(n, "") for n in names}, "refined": False, "tolerance": ""} for r in rows]
    for r in best:
        row = {n: r.get(n, "") for n in names}
        row["run"] = ""
        out.append({**row, "refined": True, "tolerance": r.get("tolerance", "")})
    return out


def _named(rows: list[dict[str, Any]], response: str) -> list[dict[str, Any]]:
    """``rows`` with their peak keys named for ``response`` (SI in its unit): the JSON and CSV
    say which response a number is; the displacement's rows are as they were."""
    return [{_renamed(k, response): v for k, v in r.items()} for r in rows]


def _renamed(name: str, response: str) -> str:
    """A design row's key ``name`` under ``response`` (peaks renamed,
    :data:`symimpact.model.display.DESIGN_PEAK_NAMES`)."""
    from ..forced.responses import response_key
    from ..model.display import DESIGN_PEAK_NAMES

    if response == "displacement" or name not in DESIGN_PEAK_NAMES:
        return name
    return DESIGN_PEAK_NAMES[name].format(key=response_key(response))


def _response_json(response: str) -> dict[str, str]:
    from ..forced.responses import response_unit

    return {"name": response, "unit": response_unit(response)}


def _e_range(ns) -> tuple[float, float] | None:
    """--e LOW:HIGH (rigid impacts): the range, with ns.e set to its middle (the nominal e)."""
    from ..errors import ParameterError
    from ..model.units import nonnegative_float

    if not isinstance(ns.e, str) or ":" not in ns.e:  # none, a number, or the materials' e
        return None
    parts = str(ns.e).split(":")
    if len(parts) != 2 or ns.contact != "rigid":
        raise ParameterError("e", "a range is LOW:HIGH (e.g. 0.4:0.8), for --contact rigid")
    lo, hi = (nonnegative_float("e", p) for p in parts)
    if not lo < hi <= 1.0:
        raise ParameterError("e", f"a range needs low < high ≤ 1, got {lo:g}:{hi:g}")
    ns.e = repr(0.5 * (lo + hi))
    return lo, hi


def _robust(ns, system, forcing, e_range, omegas, gaps, response: str) -> None:
    """The robust design over a restitution range (:func:`symimpact.maps.design.robust_design`)."""
    from ..forced.orbits.coverage import FREQUENCIES
    from ..maps.design import robust_design
    from ..model.display import display_unit, omega_text, shown
    from .frf import response_text

    def value(v: float) -> str:
        return response_text(response, v)

    def k(name: str) -> str:
        return _renamed(name, response)

    multistart = FREQUENCIES if ns.multistart is None else ns.multistart
    res = robust_design(system, forcing, e_range, omegas, gaps, samples=ns.e_samples,
                        multistart=multistart, response=response,
                        executor=ns.executor, workers=ns.workers, scheduler=ns.scheduler,
                        progress=progress_drawn(ns))  # fmt: skip
    gunit = display_unit("gap")
    es = res["e"]
    lines = [f"{len(res['rows'])} clearance(s) at e = " + ", ".join(f"{e:.3g}" for e in es)
             + f" over Ω {shown('omega', omegas[0]):.6g}–{omega_text(omegas[-1])}; without the "
             f"damper the {'peak' if response == 'displacement' else 'peak ' + response} "
             f"is {value(res['rows'][0]['baseline_peak'])}"]  # fmt: skip
    for r in res["rows"]:
        lines.append(
            f"d {shown('gap', r['gap']):.4g} {gunit}: peak {value(min(r['peaks']))}–"
            f"{value(r['worst_peak'])} over e {es[0]:.3g}–{es[-1]:.3g} (worst "
            f"at e {r['worst_e']:.3g}; nominal {value(r['nominal_peak'])})"
        )
    nb, rb = res["nominal_best"], res["robust_best"]
    lines.append(f"best clearance at the nominal e {es[len(es) // 2]:.3g}: d "
                 f"{shown('gap', nb['gap']):.4g} {gunit} (peak {value(nb['nominal_peak'])}; "
                 f"worst case {value(nb['worst_peak'])})")  # fmt: skip
    lines.append(f"robust clearance (smallest worst case over e): d {shown('gap', rb['gap']):.4g} "
                 f"{gunit} (worst case {value(rb['worst_peak'])} at e "
                 f"{rb['worst_e']:.3g})")  # fmt: skip
    if ns.plot:
        from ..report.plots import plot_robust_design

        plot_robust_design(res, ns.plot, title=f"band {shown('omega', omegas[0]):.4g}–"
                           f"{omega_text(omegas[-1], '.4g')}, "
                           f"rigid, e {es[0]:.3g}–{es[-1]:.3g}", response=response)  # fmt: skip
    if ns.csv:
        rows = [{"gap": r["gap"], "e": e, k("peak_amplitude"): p}
                for r in res["rows"] for e, p in zip(es, r["peaks"], strict=True)]  # fmt: skip
        write_csv(ns.csv, "csv", rows)
    named = {**res, "rows": _named(res["rows"], response),
             "nominal_best": _named([res["nominal_best"]], response)[0],
             "robust_best": _named([res["robust_best"]], response)[0],
             "response": _response_json(response)}  # fmt: skip
    emit(ns, named, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"design": run}
