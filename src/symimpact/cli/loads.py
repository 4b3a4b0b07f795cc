"""``symimpact random``, ``symimpact shock``, ``symimpact sweep-sine``: the primary with its impact
damper (rigid impacts, Eq. F2, or a compliant contact: Eq. 8, 9, 35, F4) under the loads machines
and buildings see, each compared with the primary alone on the same load; the flight between
impacts is exact for the sampled load (Step 16, Eq. F8)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from .common import (
    add_budget,
    add_output,
    add_quiet,
    add_system,
    announce,
    base_participation,
    emit,
    progress_drawn,
    system_from,
    write_csv,
)
from .frf import contact_of

if TYPE_CHECKING:
    import numpy as np

G = 9.80665  # standard gravity [m/s²], for the text only (inputs go through pint)


def _load_options(g: Any, what: str, force: str, base: str) -> None:
    g.add_argument(f"--force-{what}", dest="force_load", default=None, metavar="Q",
                   help=f"{force} on the main mass")  # fmt: skip
    g.add_argument(f"--base-{what}", dest="base_load", default=None, metavar="Q",
                   help=f"{base} of the base under the primary")  # fmt: skip


def _common(p: Any) -> None:
    add_system(p, extra_laws=("rigid", "hunt-crossley"), contact_default="rigid")
    g = p.add_argument_group("impacts and sampling")
    g.add_argument("--e", default=None, metavar="E",
                   help="Newton's coefficient of restitution of --contact rigid (the default), "
                   "0 ≤ e ≤ 1 (Eq. F2); 'material' with --impactor and --cavity: e of the "
                   "materials at each impact's speed (Step 13); 'thornton V': the same law "
                   "with the yield speed V")  # fmt: skip
    g.add_argument("--chi", default=None, metavar="Q",
                   help="Hunt–Crossley damping χ [s/m] of --contact hunt-crossley (Eq. F4)")  # fmt: skip
    g.add_argument("--dt", default=None, metavar="Q",
                   help="the record's sample interval [s]; default: 20 samples a period at the "
                   "highest frequency of the load.  Random and swept samples are raised by the "
                   "loss of the straight lines between them, 1/sinc²(f·dt), so the load holds "
                   "every frequency at its amplitude (a sweep's peak within 1e-4 of the exact "
                   "chirp's at the default; the lines alone had lost (πf·dt)²/3, 0.8 %% at the "
                   "top)")  # fmt: skip
    add_budget(g)


def _events(ns) -> str:
    """What the run counts: impacts (rigid) or contacts (a compliant law; their onsets)."""
    return "impacts" if ns.contact == "rigid" else "contacts"


def add_parser(sub: Any) -> None:
    """Add the three subcommands' parsers to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser(
        "random",
        help="band-limited random vibration: RMS with 95 %% intervals over realisations, the "
        "reduction against the primary alone, the displacement's PSD (Welch)",
    )
    _common(p)
    g = p.add_argument_group("the load: a one-sided PSD, flat over --band (or a table)")
    _load_options(g, "psd", 'force PSD [N²/Hz], e.g. "0.02 N^2/Hz"',
                  'acceleration PSD [(m/s²)²/Hz], e.g. "0.01 g^2/Hz"')  # fmt: skip
    g.add_argument("--force-rms", default=None, metavar="Q",
                   help='instead of --force-psd: the force\'s RMS over --band, e.g. "5 N", read '
                   "as the flat PSD of that RMS, rms²/(F2 − F1)")  # fmt: skip
    g.add_argument("--base-acc-rms", default=None, metavar="Q",
                   help='instead of --base-psd: the base acceleration\'s RMS over --band, e.g. '
                   '"0.5 g" (a test specification\'s grms), read as the flat PSD '
                   "rms²/(F2 − F1)")  # fmt: skip
    g.add_argument("--psd-file", default=None, metavar="FILE.csv",
                   help="a PSD table instead: columns 'frequency [Hz]' and 'psd [N^2/Hz]' (a "
                   "force) or 'psd [g^2/Hz]' / 'psd [(m/s^2)^2/Hz]' (a base acceleration), joined "
                   "by straight lines, zero outside; --band gives the band simulated")  # fmt: skip
    g.add_argument("--kanai-tajimi", default=None, metavar="FG:ZG",
                   help="with --base-psd: shape it as Kanai and Tajimi's ground motion, a layer of "
                   'natural frequency FG [Hz] and damping ratio ZG (e.g. "2.5:0.6"); the level '
                   "is the white noise under the layer")  # fmt: skip
    g.add_argument("--band", required=True, metavar="F1:F2",
                   help='the band [Hz], e.g. "1:50" or "1 Hz:50 Hz"')  # fmt: skip
    g.add_argument(
        "--duration",
        default="100 s",
        metavar="Q",
        help="the time each realisation is kept for statistics; default 100 s",
    )
    g.add_argument(
        "--realisations",
        default="8",
        metavar="N",
        help="independent records; default 8 (fewer are warned of).  The 95 %% intervals are "
        "the spread of the records' mean (Student's t on the logarithms: never below 0), not a "
        "bound on one record",
    )
    g.add_argument(
        "--seed",
        default="0",
        metavar="S",
        help="the ensemble's seed (realisation i: SeedSequence([S, i])); default 0",
    )
    g.add_argument("--settle", default=None, metavar="Q",
                   help="the start left out of the statistics; default the primary's decay to "
                   "1e-3, ln(1000)/(ζω_n)")  # fmt: skip
    g.add_argument(
        "--segment",
        default=None,
        metavar="Q",
        help="Welch's segment [s] (resolution 1/segment Hz); default duration/8",
    )
    g = p.add_argument_group("an ensemble as a map (RMS and reduction; no PSD)")
    g.add_argument("--executor", choices=("serial", "processes", "dask"), default=None,
                   help="run the realisations as map runs: serially, on local processes or on "
                   "Dask (with --scheduler); the same seed gives the same rows on each")  # fmt: skip
    g.add_argument("--workers", type=int, default=None, help="processes; default all cores")
    g.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on this Dask scheduler (tcp://host:8786)")  # fmt: skip
    g.add_argument("--out", metavar="FILE",
                   help="stream one row per realisation to FILE.csv or FILE.parquet; the same "
                   "command after an interruption runs only the missing realisations")  # fmt: skip
    g.add_argument("--force", action="store_true", help="replace an existing --out file")
    add_quiet(g)
    add_output(p, plot=True)

    p = sub.add_parser(
        "shock",
        help="a shock pulse: peak displacement and the shock-response spectrum of the main "
        "mass's motion, with and without the damper",
    )
    _common(p)
    g = p.add_argument_group("the pulse")
    _load_options(g, "peak", "the pulse height [N]", 'the pulse height [m/s²], e.g. "50 g"')
    g.add_argument("--shape", default="half-sine", choices=("half-sine", "haversine", "sawtooth"),
                   help="pulse shape (sawtooth: terminal peak); default half-sine")  # fmt: skip
    g.add_argument("--pulse", default=None, metavar="Q", help='its duration, e.g. "11 ms"')
    g.add_argument("--record-file", default=None, metavar="FILE.csv",
                   help="a recorded shock instead of a pulse: columns 'time [s]' and the value "
                   "with its unit ('acceleration [g]' on the base, 'force [N]' on the mass), "
                   "equally spaced from t = 0")  # fmt: skip
    g.add_argument(
        "--duration",
        default=None,
        metavar="Q",
        help="the run from the shock's start, pulse or record included (the rest after it is "
        "the free vibration, the residual response); default the shock, then 20 natural periods "
        "of the primary and 3 periods of the SRS's lowest oscillator; the SRS also reads each "
        "oscillator's residual after the run in closed form",
    )
    g.add_argument(
        "--srs-range",
        default=None,
        metavar="F1:F2",
        help="the SRS's frequencies [Hz]; default 0.1 to 10 times the primary's",
    )
    g.add_argument(
        "--srs-points", default="40", metavar="N", help="SRS frequencies, log-spaced; default 40"
    )
    g.add_argument(
        "--srs-zeta",
        default="0.05",
        metavar="Z",
        help="the SRS oscillators' damping ratio; default 0.05 (Q = 10)",
    )
    add_output(p, plot=True)

    p = sub.add_parser(
        "sweep-sine",
        help="a sine sweep up and down through a band: the displacement's envelope against the "
        "instantaneous frequency, with and without the damper",
    )
    _common(p)
    g = p.add_argument_group("the sweep")
    _load_options(
        g, "amplitude", "force amplitude [N]", 'acceleration amplitude [m/s²], e.g. "0.5 g"'
    )
    g.add_argument("--band", required=True, metavar="F1:F2", help="from and to [Hz]")
    g.add_argument(
        "--rate", required=True, metavar="R", help="Hz/s (linear) or octaves a minute (--law log)"
    )
    g.add_argument("--law", default="linear", choices=("linear", "log"), help="default linear")
    g.add_argument(
        "--no-steady", action="store_true",
        help="leave out the steady curve of frf at the sweep's amplitude (drawn and in the JSON "
        "by default: the continued branches' stable orbits over the band)",
    )  # fmt: skip
    add_output(p, plot=True)


def band_from(name: str, text: str) -> tuple[float, float]:
    """(f₁, f₂) [Hz] from "f1:f2" with a unit on either or both ends (Hz when none)."""
    from ..errors import ParameterError
    from ..model.checks import bounds
    from ..model.units import split_quantity

    parts = [t.strip() for t in str(text).split(":")]
    if len(parts) != 2 or not all(parts):
        raise ParameterError(name, f"must be f1:f2, got {text!r}")
    units = [split_quantity(name, t)[1] for t in parts]
    if units[1] and not units[0]:
        parts[0] = f"{parts[0]} {units[1]}"
    return bounds(name, parts, "Hz")


def _kind(ns) -> tuple[str, str]:
    """("force" | "base-acceleration", the value's text) from --force-X / --base-X."""
    from ..errors import ParameterError

    if (ns.force_load is None) == (ns.base_load is None):
        flag = {"shock": "peak", "sweep-sine": "amplitude"}[ns.command]
        raise ParameterError(
            f"force-{flag}", f"give the load once: --force-{flag} or --base-{flag}"
        )
    if ns.force_load is not None:
        return "force", ns.force_load
    flag = {"shock": "peak", "sweep-sine": "amplitude"}[ns.command]
    return "base-acceleration", ns.base_load


def _flat_psd(ns, f1: float, f2: float) -> tuple[str, float]:
    """("force" | "base-acceleration", the one-sided PSD [N²/Hz or (m/s²)²/Hz]) flat over
    [f1, f2] Hz, from --force-psd / --base-psd, or from an RMS over the band, --force-rms /
    --base-acc-rms: S = rms²/(f2 − f1), as a test specification's "0.5 grms, 5–100 Hz" is
    0.25/95 g²/Hz (the RMS of a one-sided PSD is the square root of its integral)."""
    from ..errors import ParameterError
    from ..model.units import ACCELERATION_PSD, si_float

    given = [(flag, value) for flag, value in (
        ("--force-psd", ns.force_load), ("--base-psd", ns.base_load),
        ("--force-rms", ns.force_rms), ("--base-acc-rms", ns.base_acc_rms),
    ) if value is not None]  # fmt: skip
    if len(given) != 1:
        raise ParameterError(
            (given[0][0] if given else "--force-psd")[2:],
            "give the load once: --force-psd, --base-psd, --force-rms or --base-acc-rms"
            + (f" (given: {', '.join(f for f, _ in given)})" if given else ""),
        )
    (flag, text), name = given[0], given[0][0][2:]
    kind = "force" if flag.startswith("--force") else "base-acceleration"
    if flag.endswith("-psd"):
        psd = si_float(name, text, "N^2/Hz" if kind == "force" else ACCELERATION_PSD)
        if psd < 0:
            raise ParameterError(name, "must be ≥ 0")
        return kind, psd
    if ns.kanai_tajimi is not None:
        raise ParameterError(
            "kanai-tajimi", f"shapes the white noise under the layer, given by --base-psd; "
            f"{flag} is the RMS of a flat band"
        )  # fmt: skip
    rms = si_float(name, text, "N" if kind == "force" else "m/s^2")
    if rms < 0:
        raise ParameterError(name, "must be ≥ 0")
    return kind, rms * rms / (f2 - f1)


def _height(ns, kind: str, text: str) -> float:
    """The pulse height or sweep amplitude in SI: [N] on the mass, [m/s²] of the base ("g" is
    standard gravity)."""
    from ..model.units import si_float

    what = {"shock": "peak", "sweep-sine": "amplitude"}[ns.command]
    if kind == "force":
        return si_float(f"force-{what}", text, "N")
    return si_float(f"base-{what}", text, "m/s^2")


def _sampling(ns, total: float, default_dt: float) -> float:
    """The sample interval: --dt as given (the record refuses one that does not divide the
    duration), else the default made to divide ``total`` [s] (at most the default)."""
    from ..model.units import positive_float

    if ns.dt is not None:
        return positive_float("dt", ns.dt, "s")
    return total / max(1, math.ceil(total / default_dt - 1e-9))


def count(name: str, text: str, low: int, high: int) -> int:
    """A whole number typed on the command line, in [low, high]."""
    from ..errors import ParameterError
    from ..model.checks import whole_number

    try:
        value = int(str(text).strip())
    except ValueError:
        raise ParameterError(name, f"must be a whole number, got {text!r}") from None
    return whole_number(name, value, low, high)


def psd_table(path: str) -> tuple[Callable[[np.ndarray], np.ndarray], str]:
    """(function of f [Hz] → PSD [SI], kind) from a CSV table (see ``--psd-file``)."""
    import numpy as np

    f, s, kind = _psd_file(path)
    return (lambda x: np.interp(x, f, s, left=0.0, right=0.0)), kind


def psd_points(path: str) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies [Hz], PSD [SI]) of a CSV table (see ``--psd-file``)."""
    f, s, _ = _psd_file(path)
    return f, s


def _psd_file(path: str):
    import numpy as np

    from ..errors import ParameterError
    from ..forced.loads.records import unit_columns
    from ..model.units import ACCELERATION_PSD, si_float

    (f_unit, s_unit), values = unit_columns(path, "psd-file", ("frequency [Hz]", "psd [g^2/Hz]"))
    f = values[:, 0] * si_float("psd-file", f"1 {f_unit}", "Hz")
    try:
        scale, kind = si_float("psd-file", f"1 {s_unit}", "N^2/Hz"), "force"
    except ParameterError:
        scale, kind = si_float("psd-file", f"1 {s_unit}", ACCELERATION_PSD), "base-acceleration"
    s = values[:, 1] * scale
    if np.any(np.diff(f) <= 0):
        raise ParameterError("psd-file", "frequencies must increase from row to row")
    if np.any(s < 0) or not np.all(np.isfinite(s)):
        raise ParameterError("psd-file", "a PSD must be finite and ≥ 0")
    return f, s, kind


def run_random(ns) -> None:
    """``symimpact random``."""
    from ..errors import ParameterError
    from ..forced.loads.random_response import UNITS, random_statistics
    from ..forced.loads.records import SAMPLES_PER_PERIOD
    from ..model.units import positive_float

    system = system_from(ns)
    e = contact_of(ns)
    f1, f2 = band_from("band", ns.band)
    load = None
    if ns.psd_file is not None:
        if ns.kanai_tajimi is not None:
            raise ParameterError("kanai-tajimi", "shapes --base-psd's level; a --psd-file is its "
                                 "own shape")  # fmt: skip
        if any(v is not None for v in (ns.force_load, ns.base_load, ns.force_rms,
                                       ns.base_acc_rms)):  # fmt: skip
            raise ParameterError(
                "psd-file",
                "give the PSD once: --psd-file, --force-psd, --base-psd, --force-rms or "
                "--base-acc-rms",
            )
        psd, kind = psd_table(ns.psd_file)
    else:
        kind, psd = _flat_psd(ns, f1, f2)
        load = _flat_load(kind, psd, f1, f2)
        if ns.kanai_tajimi is not None:
            from ..forced.loads.records import kanai_tajimi

            if kind != "base-acceleration":
                raise ParameterError(
                    "kanai-tajimi", "shapes a ground acceleration: give --base-psd"
                )
            parts = str(ns.kanai_tajimi).split(":")
            if len(parts) != 2:
                raise ParameterError("kanai-tajimi", f"must be FG:ZG, got {ns.kanai_tajimi!r}")
            psd = kanai_tajimi(psd, parts[0].strip(), parts[1].strip())
    gamma = base_participation(ns) if kind != "force" else 1.0
    T = positive_float("duration", ns.duration, "s")
    dt = _sampling(ns, T, 1.0 / (2 * SAMPLES_PER_PERIOD * f2))
    from ..forced.loads.random_response import MAX_REALISATIONS

    n = count("realisations", ns.realisations, 1, MAX_REALISATIONS)
    seed = count("seed", ns.seed, 0, 2**63 - 1)
    from ..forced.loads.random_response import ensemble_estimate

    as_map = any(v is not None for v in (ns.executor, ns.workers, ns.scheduler, ns.out))
    announce(ns, ensemble_estimate(system, psd, (f1, f2), T, dt, e=e, realisations=n, seed=seed,
                                   settle=ns.settle, kind=kind, segment=ns.segment,
                                   welch=not as_map, participation=gamma), "realisations",
             ", of one core: the map shares it among its workers" if as_map else "")  # fmt: skip
    if as_map:
        from ..maps.ensemble import random_ensemble

        if ns.plot or ns.csv or ns.segment is not None:
            flag = "plot" if ns.plot else ("csv" if ns.csv else "segment")
            raise ParameterError(flag, "an ensemble run as a map keeps the RMS values, not the "
                                 "PSD; drop --executor/--workers/--scheduler/--out for it")  # fmt: skip
        if ns.psd_file is not None:
            psd = psd_points(ns.psd_file)
        st, _ = random_ensemble(system, psd, (f1, f2), T, dt, e=e, realisations=n, seed=seed,
                                settle=ns.settle, kind=kind, executor=ns.executor,
                                workers=ns.workers, scheduler=ns.scheduler, out=ns.out,
                                force=ns.force, progress=progress_drawn(ns),
                                participation=gamma)  # fmt: skip
    else:
        st = random_statistics(system, psd, (f1, f2), T, dt, e=e, realisations=n, seed=seed,
                               settle=ns.settle, kind=kind, segment=ns.segment,
                               participation=gamma)  # fmt: skip
    if ns.csv:
        write_csv(ns.csv, "csv", [
            {"frequency": f, "displacement_psd": a, "baseline_displacement_psd": b}
            for f, a, b in zip(st.psd_frequency, st.psd, st.baseline_psd, strict=True)
        ])  # fmt: skip
    if ns.plot:
        from ..report.plots import plot_random

        plot_random(st, ns.plot, band=(f1, f2))
    scale = {"displacement": (1e3, "mm"), "velocity": (1e3, "mm/s"),
             "acceleration": (1 / G, "g"), "base_force": (1.0, "N")}  # fmt: skip
    lines = [f"{st.realisations} realisations of {st.duration:g} s after {st.settle:.3g} s, "
             f"seed {st.seed}, {st.impacts_per_second:.3g} {_events(ns)}/s"]  # fmt: skip
    for key in UNITS:
        k, u = scale[key]
        lo, hi = st.rms_ci95[key]
        rlo, rhi = st.reduction_ci95[key]
        lines.append(
            f"RMS {key.replace('_', ' ')}: {st.rms[key] * k:.4g} {u} (95 %: {lo * k:.4g}–"
            f"{hi * k:.4g}), alone {st.baseline_rms[key] * k:.4g} {u}: reduction "
            f"{100 * st.reduction[key]:.1f} % ({100 * rlo:.1f}–{100 * rhi:.1f} %)"
        )
    if not as_map:
        lines.append(f"PSD resolution {st.psd_resolution:.3g} Hz (Welch, Hann, half overlap)")
    elif ns.out:
        lines.append(f"wrote {ns.out} ({st.realisations} realisations)")
    out = st.as_dict()
    if load is not None and ns.kanai_tajimi is None:
        lines.insert(0, load.pop("text"))
        out["load"] = load
    if kind != "force" and getattr(ns, "reduced_base", None) is not None:
        text, out["structure"] = _whole_structure(ns, psd, (f1, f2), gamma)
        lines += text
    emit(ns, out, "\n".join(lines))


def _whole_structure(ns, psd: Any, band: tuple[float, float], gamma: float) -> tuple[list, dict]:
    """What a one-mode reduction under random base motion leaves out: the bare structure's RMS
    at the damper's point over the band, all its modes and the reduced mode alone, in closed form
    (:func:`~symimpact.forced.loads.random_response.modal_random_rms`), as text lines and JSON
    (SI): the run's "alone" is the second, which the first shows in full."""
    from ..forced.loads.random_response import modal_random_rms

    _, i, at = ns.reduced_base
    s = ns.reduced_structure
    every = modal_random_rms(s, at, psd, band)
    alone = modal_random_rms(s, at, psd, band, modes=(i,))
    text = [
        f"the bare structure at {at!r} over the band (closed form, Eq. F7): all {len(s.modes)} "
        f"modes {every['displacement'] * 1e3:.4g} mm and {every['acceleration'] / G:.4g} g rms; "
        f"mode {i} alone (this run's primary, Γφ = {gamma:.4g}) "
        f"{alone['displacement'] * 1e3:.4g} mm and {alone['acceleration'] / G:.4g} g"
    ]
    return text, {"point": at, "mode": i, "participation": gamma, "modes": len(s.modes),
                  "baseline_rms_all_modes": every, "baseline_rms_mode": alone}  # fmt: skip


def _flat_load(kind: str, psd: float, f1: float, f2: float) -> dict:
    """The flat load as the run reads it (SI in ``psd`` and ``rms``; ``text`` in a test
    engineer's units: N²/Hz and N, or g²/Hz and g): the level S and its RMS √(S·(f2 − f1))."""
    rms = math.sqrt(psd * (f2 - f1))
    if kind == "force":
        text = f"load: force PSD {psd:.6g} N²/Hz flat over {f1:g}–{f2:g} Hz, {rms:.6g} N rms"
    else:
        text = (f"load: base acceleration PSD {psd / G**2:.6g} g²/Hz flat over {f1:g}–{f2:g} Hz, "
                f"{rms / G:.6g} g rms")  # fmt: skip
    return {"kind": kind, "psd": psd, "band": [f1, f2], "rms": rms, "text": text}


def run_shock(ns) -> None:
    """``symimpact shock``."""
    import numpy as np

    from ..forced.loads.records import shock_record
    from ..forced.loads.shock_response import shock_response
    from ..model.units import positive_float

    system = system_from(ns)
    e = contact_of(ns)
    fn = system.omega_n / (2 * math.pi)
    if ns.record_file is not None:
        from ..errors import ParameterError
        from ..forced.loads.records import followed_by_rest, read_record

        given = [f"--{k.replace('_', '-')}" for k in ("pulse", "dt") if getattr(ns, k)]
        if ns.force_load is not None or ns.base_load is not None or given:
            raise ParameterError("record-file", "the record gives the load and its samples: "
                                 "drop --force-peak/--base-peak, --pulse and --dt")  # fmt: skip
        record = read_record(ns.record_file)
        # the record, then rest: its residual response (default: as after a pulse, 20 natural
        # periods, and 3 periods of the SRS's lowest oscillator)
        rest = max(20.0 / fn, 3.0 / _srs_range(ns, fn)[0])
        total = (positive_float("duration", ns.duration, "s") if ns.duration is not None
                 else record.duration + rest)  # fmt: skip
        record = followed_by_rest(record, total)
    else:
        from ..errors import ParameterError

        kind, text = _kind(ns)
        if ns.pulse is None:
            raise ParameterError("pulse", "give the pulse's duration (or --record-file)")
        td = positive_float("pulse", ns.pulse, "s")
        if ns.duration is None:  # the pulse, then 20 natural periods and 3 of the SRS's lowest
            total = td + max(20.0 / fn, 3.0 / _srs_range(ns, fn)[0])
            total = td / 200.0 * math.ceil(total / (td / 200.0))  # whole default steps
        else:
            total = positive_float("duration", ns.duration, "s")
        dt = _sampling(ns, total, td / 200.0)
        record = shock_record(ns.shape, _height(ns, kind, text), td, total, dt, kind)
    lo, hi = _srs_range(ns, fn)
    n = count("srs-points", ns.srs_points, 2, 10_000)
    from ..forced.loads.record_cost import record_estimate
    from ..forced.loads.shock_response import srs_oscillators

    frequencies = np.geomspace(lo, hi, n)
    srs_oscillators(frequencies, ns.srs_zeta, record.dt)  # refused before the estimate's runs
    gamma = base_participation(ns) if record.kind != "force" else 1.0

    # the record with the damper and without, and each SRS oscillator on both motions
    estimate = record_estimate(system, record, e=e, marches=2 * n, participation=gamma)
    announce(ns, estimate, "record-file" if ns.record_file else "duration")
    out = shock_response(system, record, e=e, frequencies=frequencies, zeta=ns.srs_zeta,
                         participation=gamma)  # fmt: skip
    if ns.csv:
        write_csv(ns.csv, "csv", [
            {"frequency": f, "srs": a, "baseline_srs": b}
            for f, a, b in zip(out.frequency, out.srs, out.baseline_srs, strict=True)
        ])  # fmt: skip
    if ns.plot:
        from ..report.plots import plot_shock

        plot_shock(out, ns.plot)
    i = int(np.argmax(out.baseline_srs))
    text_out = (
        f"peak displacement {out.peak * 1e3:.4g} mm with the damper, {out.baseline_peak * 1e3:.4g}"
        f" mm alone ({out.impacts} {_events(ns)}); peak acceleration "
        f"{out.peak_acceleration / G:.4g} g, alone {out.baseline_peak_acceleration / G:.4g} g "
        f"({'between impacts' if ns.contact == 'rigid' else 'at the samples'})\n"
        f"SRS (ζ {out.zeta:g}) at {out.frequency[i]:.4g} Hz, the primary's largest: "
        f"{out.srs[i] / G:.4g} g with the damper, {out.baseline_srs[i] / G:.4g} g alone"
    )
    emit(ns, out.as_dict(), text_out)


def _srs_range(ns, fn: float) -> tuple[float, float]:
    """The SRS's frequencies [Hz]: --srs-range, or a decade either side of the primary's fn."""
    if ns.srs_range is None:
        return 0.1 * fn, 10.0 * fn
    lo, hi = band_from("srs-range", ns.srs_range)
    if lo <= 0:
        from ..errors import ParameterError

        raise ParameterError("srs-range", f"must start above 0 Hz (an oscillator's frequency), "
                             f"got {lo:g}")  # fmt: skip
    return lo, hi


def run_sweep(ns) -> None:
    """``symimpact sweep-sine``."""
    from ..forced.loads.records import SAMPLES_PER_PERIOD
    from ..forced.loads.sweep_response import sweep_response
    from ..model.units import positive_float

    system = system_from(ns)
    e = contact_of(ns)
    kind, text = _kind(ns)
    f1, f2 = band_from("band", ns.band)
    # a sweep's length follows from its band and rate: --dt as given, or 20 samples a period
    dt = positive_float("dt", ns.dt, "s") if ns.dt else 1.0 / (2 * SAMPLES_PER_PERIOD * f2)
    from ..forced.loads.sweep_response import sweep_estimate

    gamma = base_participation(ns) if kind != "force" else 1.0
    steady = not ns.no_steady
    announce(ns, sweep_estimate(system, _height(ns, kind, text), f1, f2, ns.rate, dt, e=e,
                                law=ns.law, kind=kind, participation=gamma), "rate",
             ", and then the steady curve" if steady else "")  # fmt: skip
    out = sweep_response(system, _height(ns, kind, text), f1, f2, ns.rate, dt, e=e,
                         law=ns.law, kind=kind, steady=steady, participation=gamma)  # fmt: skip
    if ns.csv:
        rows = []
        for name, d in (("up", out.up), ("down", out.down)):
            rows += [
                {"direction": name, "frequency": f, "envelope": a, "baseline_envelope": b}
                for f, a, b in zip(d["frequency"], d["envelope"], d["baseline"], strict=True)
            ]
        write_csv(ns.csv, "csv", rows)
    if ns.plot:
        from ..report.plots import plot_sine_sweep

        plot_sine_sweep(out, ns.plot)
    d = out.as_dict()
    lines = [
        f"{name}: peak {d[name]['peak'] * 1e3:.4g} mm at {d[name]['peak_frequency']:.4g} Hz; "
        f"alone {d[name]['baseline_peak'] * 1e3:.4g} mm at "
        f"{d[name]['baseline_peak_frequency']:.4g} Hz"
        for name in ("up", "down")
    ]
    if out.steady is not None:
        c = out.steady
        lines.append(
            "steady (frf): no stable orbit over the band"
            if c.peak is None
            else f"steady (frf): largest stable amplitude {c.peak * 1e3:.4g} mm at "
            f"{c.peak_frequency:.4g} Hz"
        )
    emit(ns, d, "\n".join(lines))


COMMANDS = {"random": run_random, "shock": run_shock, "sweep-sine": run_sweep}
