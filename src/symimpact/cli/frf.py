"""``symimpact frf``: the frequency-response curve of the primary with an impact damper (rigid
impacts, or a compliant contact integrated through each contact) — branches of periodic orbits
continued in Ω with their stability and bifurcations, the primary without the damper, and
brute-force sweeps up and down the band.

``--method hb`` draws the curve by harmonic balance beside it
(:mod:`symimpact.forced.orbits.hb_frf`, issue 83, item 2): the JSON is the balance's curve in
this schema with the exact one under ``"exact"``; ``--method compare`` prints the exact curve
with, per branch, ``"hb_error"`` and ``"harmonics_for"`` (``{"0.01": H1, "0.001": H2}``), the
stability disagreements and the missed orbits, and the balance's curve under ``"hb"``.  Both
draw the two curves on one figure and write both in the CSV (a ``method`` column)."""

from __future__ import annotations

import math
from typing import Any

from .. import budgets
from .common import (
    AMPLITUDE_NEEDED,
    add_multistart,
    add_output,
    add_quiet,
    add_system,
    emit,
    forcing_of,
    progress_drawn,
    structure_band,
    system_from,
    write_csv,
)


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "frf",
        help="frequency-response curve: continued branches, stability, bifurcations, sweeps",
        epilog=budgets.text(),
    )
    add_system(p, extra_laws=("rigid", "hunt-crossley"), contact_default=None)
    g = p.add_argument_group("forcing F0·cos(Ωt) and/or base motion X_b·cos(Ωt) over a band")
    add_band(g)
    g.add_argument("--no-sweeps", action="store_true",
                   help="skip the brute-force sweeps up and down the band")  # fmt: skip
    g.add_argument("--jumps", default=None, metavar="N",
                   help="at most N runs from the branches' ends and losses of stability, whose "
                   "landings start new branches (default 256 with rigid impacts, 0 with a "
                   "compliant contact, whose runs integrate every contact)")  # fmt: skip
    g.add_argument("--folds", action="store_true",
                   help="rigid impacts: turn each branch that ends at a grazing beyond which no "
                   "orbit continues it back onto the orbits with the new impact (a non-smooth "
                   "fold), and trace the orbits with one more impact beside each turned branch; "
                   "more of the curve's orbits, at more cost (twice the time on the "
                   "README's system over 25-45 rad/s, benchmark 6, whose default curve already "
                   "holds 127 of the 128 periodic motions a 200-frequency brute force finds, "
                   "as it does with --folds, --embedded or both)")  # fmt: skip
    g.add_argument("--embedded", action="store_true",
                   help="also trace the periodic orbits embedded in the multi-start's chaotic "
                   "motions (shot from the close returns of their Poincaré sections): stable "
                   "windows inside a chaotic band that the multi-start steps over; more of the "
                   "curve's orbits, at more cost (benchmark 6)")  # fmt: skip
    add_multistart(g)
    add_quiet(g)
    g.add_argument("--workers", type=int, default=None, metavar="N",
                   help="processes: with --structure for the runs from rest at each "
                   "frequency, else for the multi-start's initial states (default all cores; "
                   "1 runs them here)")  # fmt: skip
    g = p.add_argument_group("harmonic balance beside the exact curve (a compliant contact)")
    g.add_argument(
        "--method",
        choices=("shooting", "hb", "compare"),
        default="shooting",
        help="shooting: the exact orbits' branches (default); hb: the curve by multi-harmonic "
        "balance (AFT, Hill's stability) drawn beside them; compare: the exact curve with, per "
        "branch, the balance's amplitude error, the harmonics it needs for 1 %% and 0.1 %%, and "
        "where the two disagree",
    )
    g.add_argument("--harmonics", default=None, metavar="H",
                   help="harmonics of the balance; default 15")  # fmt: skip
    g.add_argument("--time-samples", default=None, metavar="N",
                   help="time samples a period (AFT), at least 2H + 1; default 4H")  # fmt: skip
    p.add_argument(
        "--response",
        default="displacement",
        metavar="NAME",
        help="what the curve shows: displacement (max |x|, default), relative-displacement "
        "(max |x − x_b|), acceleration (max |ẍ| between impacts), force (into the base, "
        "max |K(x − x_b) + C(ẋ − ẋ_b)|) or transmissibility (force/F0 under a force, "
        "max |x|/X_b under base motion); the text, JSON, CSV and plot then carry it",
    )
    add_output(p, plot=True)


def response_text(name: str, value: float, spec: str = ".5g", unit: bool = True) -> str:
    """``value`` [SI] of the response ``name`` in its display unit (with it, if ``unit``)."""
    from ..forced.responses import QUANTITY, shown_response
    from ..model.display import display_unit

    q = QUANTITY[name]
    text = format(shown_response(name, value), spec)
    return text + (f" {display_unit(q)}" if unit and q is not None else "")


def add_band(g: Any) -> None:
    """--force/--base, --omega-range/--freq-range and --e, into the argument group ``g``."""
    g.add_argument("--force", dest="F0", default=None, metavar="Q",
                   help='force amplitude F0 on the main mass [N] ("35.4 N rms" is read as '
                   "its amplitude, 50 N; so are 'peak' and 'pk-pk' levels)")  # fmt: skip
    g.add_argument("--base", dest="X_b", default=None, metavar="Q",
                   help='base-motion amplitude X_b under the primary [m] ("2 mm pk-pk" is 1 mm)')  # fmt: skip
    g.add_argument("--base-vel", dest="V_b", default=None, metavar="Q",
                   help="base velocity amplitude V_b [m/s], constant over the band "
                   "(X_b = V_b/Ω)")  # fmt: skip
    g.add_argument("--base-acc", dest="A_b", default=None, metavar="Q",
                   help='base acceleration amplitude A_b [m/s²], constant over the band as on '
                   'a shaker (X_b = A_b/Ω²); "0.5 g" is 0.5 standard gravity')  # fmt: skip
    g.add_argument("--omega-range", default=None, metavar="START:STOP:STEP",
                   help="the band in rad/s, e.g. 25:40:0.1 (or --freq-range)")  # fmt: skip
    g.add_argument("--freq-range", default=None, metavar="START:STOP:STEP",
                   help="the band in Hz (Ω = 2πf)")  # fmt: skip
    g.add_argument("--e", default=None, metavar="E",
                   help="Newton's coefficient of restitution of the rigid law, 0 ≤ e ≤ 1 "
                   "(design: or a range LOW:HIGH, for a clearance robust to e); 'material' or "
                   "'thornton V' (yield speed V): Thornton's e at each impact (Step 13)")  # fmt: skip
    g.add_argument("--chi", default=None, metavar="Q",
                   help="Hunt–Crossley damping χ [s/m] of --contact hunt-crossley (Eq. F4)")  # fmt: skip
    g.add_argument("--propagate", default=None, type=int, metavar="N",
                   help="with --system FILE holding the fit's [uncertainty] ('symimpact "
                   "identify decay --out'): the curve at N draws of the identified parameters "
                   "(e, ζ, d), and the peak's median and the interval of the middle 95 %% of "
                   "the draws")  # fmt: skip


def band_from(ns) -> Any:
    """The band [rad/s] of --omega-range or --freq-range, after the contact (--contact, --e,
    --chi) and the forcing are checked (each refusal one line naming the option)."""
    import numpy as np

    from ..errors import ParameterError
    from ..maps.points import parse_range

    contact_of(ns)
    if all(getattr(ns, k) is None for k in ("F0", "X_b", "V_b", "A_b")):
        raise ParameterError("force", AMPLITUDE_NEEDED)
    if (ns.omega_range is None) == (ns.freq_range is None):
        raise ParameterError("omega-range", "give the band once: --omega-range or --freq-range")
    if ns.omega_range is not None:
        omegas = parse_range("omega-range", ns.omega_range)
    else:
        omegas = 2 * np.pi * parse_range("freq-range", ns.freq_range)
    name = "omega-range" if ns.omega_range is not None else "freq-range"
    if len(omegas) < 2:
        raise ParameterError(name, "the band needs at least two frequencies")
    if omegas[0] <= 0:
        raise ParameterError(name, "the band's frequencies must be positive")
    if len(omegas) > 5000:
        raise ParameterError(name, f"{len(omegas)} frequencies; at most 5000")
    return omegas


def contact_of(ns) -> Any:
    """The contact of the options, checked (each refusal one line naming the option): --e for
    rigid impacts, else a :class:`~symimpact.forced.CompliantContact` (with --chi for
    Hunt–Crossley)."""
    from ..errors import MethodNotApplicable, ParameterError
    from ..forced.contact_law import CompliantContact, MaterialRestitution, restitution_or_law
    from ..model.units import nonnegative_float

    if ns.contact is None:
        raise ParameterError("contact", "name the contact: rigid (with --e), cubic, hertz, "
                             "linear or hunt-crossley (with --chi)")  # fmt: skip
    if ns.contact == "perturbation":
        raise MethodNotApplicable(
            ns.command, "contact 'perturbation' is a free-vibration solution (Eq. 31–33); a "
            "forced motion takes rigid, cubic, hertz, linear or hunt-crossley",
        )  # fmt: skip
    if ns.contact == "rigid" and ns.e is None:
        raise ParameterError("e", "contact rigid needs Newton's coefficient of restitution --e")
    if ns.contact != "rigid" and ns.e is not None:
        raise ParameterError("e", f"applies to rigid impacts; contact {ns.contact} sets its own")
    if ns.contact == "hunt-crossley" and ns.chi is None:
        raise ParameterError("chi", "contact hunt-crossley needs its damping --chi χ [s/m]")
    if ns.contact != "hunt-crossley" and ns.chi is not None:
        raise ParameterError("chi", "applies to --contact hunt-crossley only")
    if ns.contact == "rigid" and isinstance(ns.e, MaterialRestitution):
        return restitution_or_law(ns.e)  # the materials' e at each impact (Eq. F5)
    if ns.contact == "rigid":
        e = nonnegative_float("e", ns.e)
        if e > 1.0:
            raise ParameterError("e", f"must lie in [0, 1], got {e:g}")
        return e
    return CompliantContact(ns.contact, ns.chi)


def contact_title(ns, e: Any) -> str:
    """``e = 0.6`` or ``contact hunt-crossley, χ = 0.5 s/m``: the contact for a plot's title."""
    from ..forced.contact_law import MaterialRestitution, contact_text, is_rigid

    if isinstance(e, MaterialRestitution):
        return f"e of the materials (yield speed {e.yield_speed * 1e3:.3g} mm/s)"
    return f"e = {float(e):g}" if is_rigid(e) else f"contact {contact_text(e)}"


def run_structure(ns) -> None:
    """A structure file with dampers or stops: its branches of orbits continued over the band
    from both ends with the period-doubled branches, its runs from rest on ``--workers``
    processes (:func:`symimpact.maps.structure_curve.structure_curve_map`) and every point's
    located peak beside the bare structure's (the linear receptance, no damper or stop)."""

    from ..errors import ParameterError
    from ..forced.orbits.structure_branch import bare_peak, curve_peak
    from ..maps.structure_curve import structure_curve_map
    from ..model.display import omega_text
    from .common import quantity_text

    for key, flag, why in (("response", "response", "the responses of a structure's orbits are "
                            "not built yet: the amplitude of every point is given"),
                           ("chi", "chi", "the file gives each damper's and stop's contact")):  # fmt: skip
        if getattr(ns, key, None) not in (None, False, "displacement"):
            raise ParameterError(flag, why)
    if ns.method != "shooting" or ns.harmonics is not None or ns.time_samples is not None:
        raise ParameterError("method", "harmonic balance is built for the one-mode primary: a "
                                       "structure's curve is its exact orbits'")  # fmt: skip
    if ns.folds:
        raise ParameterError("folds", "a structure's branches end at a grazing no orbit "
                                      "continues beyond; turning back there is the one-mode "
                                      "model's")  # fmt: skip
    if ns.embedded:
        raise ParameterError("embedded", "a structure's curve runs no multi-start: its branches "
                                         "start from the motions settled at the band's ends")  # fmt: skip
    if ns.no_sweeps:
        raise ParameterError("no-sweeps", "a structure's curve runs no sweeps: its branches start "
                                          "from the motions settled at the band's ends")  # fmt: skip
    lo, hi, step = structure_band(ns)
    model = ns.structure_model
    args = (model.structure, model.dampers, model.force_at, model.F0)

    curve = structure_curve_map(*args, lo, hi, step, model.stops, base=model.base_at,
                                workers=ns.workers,
                                progress=progress_drawn(ns))  # fmt: skip
    branches, notes = curve.branches, curve.notes
    peaks, bare = {}, {}
    for p in model.structure.points:
        pk = curve_peak(*args, curve, p, model.stops, base=model.base_at)
        peaks[p] = None if pk is None else pk.as_dict()
        bare[p] = bare_peak(model.structure, model.force_at, model.F0, p, lo, hi,
                            base=model.base_at).as_dict()  # fmt: skip
    out = curve.as_dict() | {"peaks": peaks, "bare_peaks": bare}
    if ns.csv:
        from .common import structure_rows

        write_csv(ns.csv, "csv", structure_rows(curve.branches, model.structure.points,
                                                curve.settled))  # fmt: skip
    if ns.plot:
        from ..forced.orbits.structure_branch import bare_curve
        from ..report.plots import plot_structure_curve

        curves = {p: bare_curve(model.structure, model.force_at, model.F0, p, lo, hi,
                                model.base_at) for p in model.structure.points}  # fmt: skip
        plot_structure_curve(curve.branches, model.structure.points, ns.plot,
                             title=f"{len(model.structure.modes)}-mode structure, "
                             f"{len(model.dampers)} damper(s), {len(model.stops)} stop(s)",
                             settled=curve.settled, bare=curves, peaks=peaks)  # fmt: skip
    lines = [f"Ω {omega_text(lo)}–{omega_text(hi)}: {len(branches)} branch(es) of the "
             f"{len(model.structure.modes)}-mode structure, "
             f"{sum(len(b.orbits) for b in branches)} orbits"]  # fmt: skip
    for i, b in enumerate(branches):
        ws = b.omegas
        lines.append(f"branch {i}: {b.orbits[0].periods} period(s), Ω {omega_text(ws.min())}–"
                     f"{omega_text(ws.max())}, {sum(o.stable for o in b.orbits)} of "
                     f"{len(b.orbits)} orbits stable" + (f"; {b.ended}" if b.ended else ""))  # fmt: skip
        for f in b.bifurcations:
            within = (f" ± {f.tolerance / 2:.2g} rad/s" if f.tolerance > 1e-8 * f.omega
                      else "")  # fmt: skip
            lines.append(f"  {f.kind} at Ω {omega_text(f.omega)}{within} (multiplier "
                         f"{f.multiplier.real:.4f}{f.multiplier.imag:+.4f}i)")  # fmt: skip
        for g in b.grazings:
            lines.append(f"  grazing between Ω {omega_text(g['between'][0])} and "
                         f"{omega_text(g['between'][1])}: {g['before']} → {g['after']}")  # fmt: skip
    for p in model.structure.points:
        pk, bp = peaks[p], bare[p]
        head = f"peak at {p!r}: "
        if pk is None:
            head += "no stable orbit traced"
        else:
            head += (f"{quantity_text('x', pk['amplitude'])} at Ω {omega_text(pk['omega'])} "
                     f"({pk['kind']})")  # fmt: skip
        head += (f"; bare structure {quantity_text('x', bp['amplitude'])} at Ω "
                 f"{omega_text(bp['omega'])}")  # fmt: skip
        if pk is not None:
            head += f", reduction {100 * (1 - pk['amplitude'] / bp['amplitude']):.1f} %"
        lines.append(head)
    lines += [f"note: {x}" for x in notes]
    emit(ns, out, "\n".join(lines))


def run(ns) -> None:
    if getattr(ns, "structure_model", None) is not None:
        return run_structure(ns)
    from ..errors import ParameterError

    if ns.workers is not None and ns.workers < 1:
        raise ParameterError("workers", f"must be a positive integer, got {ns.workers}")
    from ..forced.orbits.frf import frequency_response
    from ..model.display import display_unit, omega_text, shown

    omegas = band_from(ns)
    system = system_from(ns)
    forcing = forcing_of(ns, omega=float(omegas[0]))
    e = contact_of(ns)
    balance = balance_of(ns, system, forcing, e)  # (H, N) with --method hb or compare, checked
    from ..forced.contact_law import is_rigid
    from ..forced.responses import checked_response, response_key

    response = checked_response(ns.response, forcing, rigid=is_rigid(e))
    from .loads import count

    jumps = None if ns.jumps is None else count("jumps", ns.jumps, 0, 10_000)
    if ns.folds and not is_rigid(e):
        raise ParameterError("folds", "turning back at a grazing is for rigid impacts: a "
                                      "compliant contact's orbits change smoothly there")  # fmt: skip
    from ..forced.orbits.coverage import FREQUENCIES

    multistart = FREQUENCIES if ns.multistart is None else count("multistart", ns.multistart, 0,
                                                                 1000)  # fmt: skip

    # at a terminal, each stage's runs as they end, with the time it has left (issue 80, item 5)
    frf = frequency_response(system, forcing, e, omegas, sweeps=not ns.no_sweeps, jumps=jumps,
                             folds=ns.folds, embedded=ns.embedded, workers=ns.workers,
                             multistart=multistart,
                             progress=progress_drawn(ns))  # fmt: skip
    if balance is not None:
        return run_beside(ns, system, forcing, e, frf, *balance)
    if response != "displacement":
        from ..forced.orbits.response_curve import response_curve

        frf = response_curve(frf, response, system, forcing, e)
    out = frf.as_dict()
    spread = _propagated(ns, system, forcing, e, omegas, multistart)
    if spread is not None:
        out["propagated"] = spread.as_dict()
    if ns.csv:
        write_csv(ns.csv, "csv", out["points"])
    if ns.plot:
        from ..report.plots import plot_frf

        plot_frf(frf, ns.plot, title=f"m/M = {system.m / system.M:.3g}, d = "
                 f"{shown('gap', system.gap):.4g} {display_unit('gap')}, {contact_title(ns, e)}")  # fmt: skip
    what = "amplitude" if response == "displacement" else response
    key = response_key(response)
    lines = [
        f"Ω {shown('omega', omegas[0]):.6g}–{omega_text(omegas[-1])}: {len(frf.branches)} "
        f"branch(es), "
        f"{len(out['points'])} points, {len(out['bifurcations'])} located bifurcation(s)"
    ]
    for i, b in enumerate(frf.branches):
        amps = [p.amplitude for p in b.points]
        stable = sum(p.stable for p in b.points)
        lines.append(
            f"branch {i}: {b.period_multiple} period(s), Ω "
            f"{shown('omega', min(p.omega for p in b.points)):.4g}"
            f"–{omega_text(max(p.omega for p in b.points), '.4g')}, {what} "
            f"{response_text(response, min(amps), '.4g', unit=False)}–"
            f"{response_text(response, max(amps), '.4g')}, "
            f"{stable} of {len(amps)} points stable"
            + (", asymmetric orbits (each with its mirror image)" if b.mirrored else "")
            + (f"; from the {_origin_text(b)}" if b.origin else "")
        )
    for f in out["bifurcations"]:
        lines.append(
            f"  {f['kind']} at Ω {omega_text(f['omega'])}, {what} "
            f"{response_text(response, f[key])} (branch {f['branch']})"
        )
    if frf.no_impact:
        spans = ", ".join(f"{shown('omega', a):.5g}–{shown('omega', b):.5g}"
                          for a, b in frf.no_impact)  # fmt: skip
        grazes = ", ".join(f"{shown('omega', g):.6g}" for g in frf.no_impact_grazings)
        ou = display_unit("omega")
        lines.append(f"no impact (the impact mass at rest midway, the primary alone) for Ω {spans} "
                     f"{ou}; it grazes a wall at Ω "
                     + (f"{grazes} {ou}" if grazes else "nowhere in the band"))  # fmt: skip
    lines += _not_periodic_lines(frf)
    lines = peak_lines(frf) + _spread_lines(ns, spread) + lines + coverage_lines(frf)
    ou = display_unit("omega")
    for reason, ws in frf.note_omegas:
        at = ", ".join(f"{shown('omega', w):.4g}" for w in ws)
        lines.append(f"note: {reason} (at Ω {at} {ou})" if ws else f"note: {reason}")
    emit(ns, out, "\n".join(lines))


def _propagated(ns, system, forcing, e, omegas, multistart):
    """--propagate N: the peak over N draws of the parameters the --system file identified
    (symimpact.identify.propagation), or None without the option."""
    if ns.propagate is None:
        return None
    import numpy as np

    from ..errors import ParameterError
    from ..forced.contact_law import is_constant
    from ..identify.propagation import VARIED, parameter_draws, peak_spread
    from .common import read_uncertainty
    from .loads import count

    n = count("propagate", ns.propagate, 2, 10_000)
    unc = None if ns.system is None else read_uncertainty(ns.system)
    if unc is None:
        raise ParameterError("propagate", "needs --system FILE with the fit's [uncertainty] "
                             "(written by 'symimpact identify decay --out')")  # fmt: skip
    taken = set(getattr(ns, "system_taken", ()))
    keep = [i for i, k in enumerate(unc["names"]) if k in VARIED and k in taken
            and (k != "e" or is_constant(e))]  # fmt: skip
    if not keep:
        raise ParameterError("propagate", "the command line gives every parameter the file "
                             "identified: nothing uncertain is left to vary")  # fmt: skip
    names = [unc["names"][i] for i in keep]
    draws = parameter_draws(names, unc["values"][keep], unc["covariance"][np.ix_(keep, keep)], n)
    return peak_spread(system, forcing, e, omegas, names, draws, sweeps=not ns.no_sweeps,
                       folds=ns.folds, embedded=ns.embedded, workers=ns.workers,
                       multistart=multistart)  # fmt: skip


def _not_periodic_lines(frf) -> list[str]:
    """The sweeps' motions that do not repeat (``not_periodic`` of the JSON, the figure's shaded
    envelope), one line a sweep: how many frequencies, over which Ω, and the range of their
    periods' largest abs(x)."""
    from ..model.display import omega_text, shown

    lines = []
    for sweep in ("up", "down"):
        rows = [r for r in frf.not_periodic if r[0] == sweep]
        if not rows:
            continue
        ws = [r[1] for r in rows]
        lo, hi = min(r[2] for r in rows), max(r[3] for r in rows)
        lines.append(f"sweep {sweep}: motions that do not repeat at {len(rows)} of its "
                     f"{len(frf.omegas)} frequencies, Ω {shown('omega', min(ws)):.5g}–"
                     f"{omega_text(max(ws), '.5g')}; their periods' largest |x| "
                     f"{response_text('displacement', lo, '.4g', unit=False)}–"
                     f"{response_text('displacement', hi, '.4g')}")  # fmt: skip
    return lines


def _spread_lines(ns, spread) -> list[str]:
    if spread is None:
        return []
    lo, hi = spread.ci95
    return [f"peak displacement over the identified {', '.join(spread.names)} "
            f"({spread.peaks.size} draws from {ns.system}, seed {spread.seed}): median "
            f"{response_text('displacement', spread.median)}, 95 % of the draws within "
            f"{response_text('displacement', lo, unit=False)}–"
            f"{response_text('displacement', hi)}"]  # fmt: skip


def _origin_text(branch) -> str:
    """Where a switched branch starts, its Ω in the display unit."""
    from ..model.display import omega_text

    if math.isnan(branch.origin_omega):
        return branch.origin
    return branch.origin.split(" at Ω = ")[0] + f" at Ω = {omega_text(branch.origin_omega)}"


def peak_lines(frf) -> list[str]:
    """The curve's answer, printed first: the located peak with and without the damper, and the
    reduction in % and in dB (20·log₁₀ of the amplitudes' ratio)."""
    from ..model.display import display_unit, impacts_text, omega_text

    name = getattr(frf, "response", "displacement")
    what = "peak" if name == "displacement" else f"peak {name}"

    def at(p) -> str:
        other = "" if display_unit("omega") == "Hz" else f" ({p.omega / (2 * math.pi):.6g} Hz)"
        return f"{response_text(name, p.amplitude)} at Ω {omega_text(p.omega)}{other}"

    if frf.peak is None:
        lines = [f"{what} with the damper: no stable motion traced in the band"]
    else:
        p = frf.peak
        if p.motion == "periodic":
            events = p.impact_events_per_period
            kind = (f"periodic, {p.period_multiple} period(s), "
                    f"{impacts_text(p.impacts_per_period, events or p.impacts_per_period)}, "
                    f"branch {p.branch}")  # fmt: skip
        elif p.where == "multi-start":
            kind = f"{p.motion}, {p.impacts_per_period:g} impacts a period"
        else:
            kind = p.motion
        how = ("sampled by the multi-start" if p.where == "multi-start"
               else f"located: {p.where}")  # fmt: skip
        lines = [f"{what} with the damper: {at(p)} ({kind}; {how})"]
    lines.append(f"{what} without the damper: {at(frf.baseline_peak)}")
    if not math.isnan(frf.reduction):
        db = decibels(frf.baseline_peak.amplitude, frf.peak.amplitude) if frf.peak else None
        lines.append(f"reduction: {100 * frf.reduction:.4g} %" + (f" ({db})" if db else ""))
    return lines


def decibels(base: float, peak: float) -> str | None:
    """The reduction of an amplitude from ``base`` to ``peak`` in dB, "7.58 dB" for
    20·log₁₀(base/peak); None where no motion is left (peak 0)."""
    if peak <= 0.0:
        return None
    return f"{20.0 * math.log10(base / peak):.2f} dB"


def coverage_lines(frf) -> list[str]:
    """What the multi-start found and how much of it the curve traces, in words."""
    lines: list[str] = []
    cov = frf.coverage
    if cov.attractors:
        share = (
            "no periodic one"
            if not cov.traced
            else (f"{sum(cov.traced)} of {len(cov.traced)} periodic ones on a traced branch")
        )
        kinds = sorted({a.kind for a in cov.missed})
        lines.append(f"multi-start: {len(cov.attractors)} attractor(s) at {len(cov.frequencies)} "
                     f"frequencies from {cov.starts} starts each, {share}"
                     + (f"; not traced: {', '.join(kinds)}" if kinds else ""))  # fmt: skip
        if cov.check is not None:
            c = cov.check
            got = (f"{sum(c.traced)} of {len(c.traced)} periodic ones on a traced branch"
                   if c.traced else "no periodic one")  # fmt: skip
            from ..model.display import omega_text

            missed = ", ".join(f"{omega_text(a.omega)} ({a.kind}"
                               + (f", period {a.period_multiple})" if a.period_multiple else ")")
                               for a in c.missed)  # fmt: skip
            lines.append(f"check at {len(c.frequencies)} random frequencies (seed {cov.seed}): "
                         f"{got}" + (f"; missed: {missed}" if missed else ""))  # fmt: skip
        if not math.isnan(cov.share):
            lines.append(f"coverage: {100 * cov.share:.3g} % (the lower of the two shares)")
    return lines


# --- harmonic balance beside the exact curve (--method hb, compare; issue 83, item 2) -----


def balance_of(ns, system, forcing, e) -> tuple[int, int] | None:
    """(H, N) of ``--method hb`` or ``compare``, checked before the exact curve is computed;
    None for ``--method shooting`` (where ``--harmonics`` and ``--time-samples`` are refused)."""
    from ..errors import ParameterError

    if ns.method == "shooting":
        for key, flag in (("harmonics", "harmonics"), ("time_samples", "time-samples")):
            if getattr(ns, key) is not None:
                raise ParameterError(flag, "applies to --method hb or compare")
        return None
    from .common import harmonics_of

    for key, flag, why in (
        ("response", "response", "the balance's curve is of the displacement max |x|"),
        ("propagate", "propagate", "applies to --method shooting"),
    ):
        if getattr(ns, key, None) not in (None, "displacement"):
            raise ParameterError(flag, why)
    return harmonics_of(ns, system, forcing, e)


def _branch_line(i: int, b, what: str) -> str:
    from ..model.display import display_unit, omega_text, shown

    amps = [p.amplitude for p in b.points]
    ws = [p.omega for p in b.points]
    stable = sum(p.stable for p in b.points)
    return (f"{what} branch {i}: {b.period_multiple} period(s), Ω {shown('omega', min(ws)):.5g}–"
            f"{omega_text(max(ws), '.5g')}, amplitude {shown('x', min(amps)):.4g}–"
            f"{shown('x', max(amps)):.4g} {display_unit('x')}, {stable} of {len(amps)} points stable")  # fmt: skip


def _spans(omegas: list[float]) -> str:
    from ..model.display import omega_text, shown

    if not omegas:
        return ""
    lo, hi = min(omegas), max(omegas)
    if lo == hi:
        return f"Ω {omega_text(lo, '.5g')}"
    return f"Ω {shown('omega', lo):.5g}–{omega_text(hi, '.5g')}"


def comparison_lines(cmp) -> list[str]:
    """``compare``'s table in words: one line per exact branch, one per unmatched stretch."""
    from ..model.display import omega_text

    lines = []
    for r in cmp.branches:
        if not r.compared:
            lines.append(f"exact branch {r.branch}: {r.period_multiple} periods, more than H: "
                         "not balanced")  # fmt: skip
            continue
        need = ", ".join(f"{100 * float(k):g} %: " + ("more than 128" if v is None else str(v))
                         for k, v in r.harmonics_for.items())  # fmt: skip
        err = ("no balanced orbit near any" if r.hb_error is None else
               f"amplitude error up to {100 * r.hb_error:.3g} % (at Ω {omega_text(r.worst_omega)})")  # fmt: skip
        line = (f"exact branch {r.branch} ({r.compared} orbits balanced at H = {cmp.harmonics}): "
                f"{err}; harmonics needed for {need}")  # fmt: skip
        if r.stability_disagreements:
            line += (
                f"; Hill's stability differs from shooting's at "
                f"{len(r.stability_disagreements)} ({_spans(r.stability_disagreements)})"
            )
        if r.missed:
            line += f"; no balanced orbit near {len(r.missed)} ({_spans(r.missed)})"
        lines.append(line)
    for u in cmp.unmatched:
        said = {"exists": "shooting from its state finds a stable orbit there (missing from the "
                          "exact curve)",
                "unstable": "shooting from its state finds the orbit, unstable",
                "not found": "shooting from its state finds no orbit near: a motion the balance "
                             "predicts that the exact model does not have"}[u.shooting]  # fmt: skip
        lines.append(f"balance branch {u.branch} stable with no exact orbit near over "
                     f"{_spans([u.omega_from, u.omega_to])}: {said}")  # fmt: skip
    return lines


def run_beside(ns, system, forcing, e, exact, H: int, N: int) -> None:
    """The balance's curve (H, N) beside ``exact``: text, JSON, CSV and figure (module text)."""
    from ..forced.orbits.hb_frf import compare, hb_frequency_response
    from .common import emit, write_csv

    hb = hb_frequency_response(system, forcing, e, exact, H, N)
    head = f"harmonic balance (H = {H}, N = {N} time samples a period; Hill's stability)"
    lines = [f"{head} beside the exact curve (shooting)"]
    from ..model.display import omega_text

    if hb.peak is None:
        lines.append("balance: no stable balanced orbit in the band (Hill)")
    else:
        p = hb.peak
        lines.append(f"balance: largest stable orbit {response_text('displacement', p.amplitude)} "
                     f"at Ω {omega_text(p.omega)} (branch {p.branch}, to the arc's step)")  # fmt: skip
    lines += [f"exact: {x}" for x in peak_lines(exact)]
    lines += [_branch_line(i, b, "balance") for i, b in enumerate(hb.branches)]
    for i, b in enumerate(hb.branches):
        for f in b.bifurcations:
            lines.append(f"  {f.kind} at Ω {omega_text(f.omega)} (balance branch {i})")
    lines += [_branch_line(i, b, "exact") for i, b in enumerate(exact.branches)]
    lines += [f"note: {x}" for x in hb.notes]
    if ns.method == "compare":
        cmp = compare(system, forcing, e, exact, hb, H, N)
        out = exact.as_dict()
        for row, r in zip(out["branches"], cmp.branches, strict=True):
            row |= {k: v for k, v in r.as_dict().items() if k not in ("branch", "period_multiple")}
        out |= {"method": "compare", "harmonics": H, "time_samples": N, "hb": hb.as_dict(),
                "unmatched": [u.as_dict() for u in cmp.unmatched]}  # fmt: skip
        lines += comparison_lines(cmp)
    else:
        out = hb.as_dict() | {"method": "hb", "harmonics": H, "time_samples": N,
                              "exact": exact.as_dict()}  # fmt: skip
    if ns.csv:
        rows = [{"method": "hb", **p} for p in hb.as_dict()["points"]]
        rows += [{"method": "shooting", **p} for p in exact.as_dict()["points"]]
        write_csv(ns.csv, "csv", rows)
    if ns.plot:
        from ..model.display import display_unit, shown
        from ..report.plots import plot_frf_beside

        title = (f"m/M = {system.m / system.M:.3g}, d = {shown('gap', system.gap):.4g} "
                 f"{display_unit('gap')}, {contact_title(ns, e)}")  # fmt: skip
        plot_frf_beside(exact, hb, ns.plot, f"harmonic balance, H = {H}", title=title)
    emit(ns, out, "\n".join(lines))


#: The subcommands this module runs.
COMMANDS = {"frf": run}
