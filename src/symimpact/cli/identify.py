"""``symimpact identify``: the model's parameters from measurements, with their uncertainty."""

from __future__ import annotations

from typing import Any

from ..model.display import display_unit, shown
from .common import Parser, add_output, add_system, emit, system_from
from .common import wrapped as _wrapped

#: identify's text is narrower than the other commands': the guide shows it in a code block of
#: its 720 px column, where 72 columns measured 686 px of Chromium's monospace (over by ~2).
WIDTH = 66


def wrapped(text: str, indent: str = "  ") -> str:
    """``text`` wrapped to :data:`WIDTH` columns (see :func:`.common.wrapped`)."""
    return _wrapped(text, indent, WIDTH)


#: The laws in words, for the text.
_LAW_TEXT = {
    "constant": "Newton's constant e (Eq. F2)",
    "thornton": "e = 1 up to the yield speed, Thornton's elastic–plastic e above it (Step 13)",
    "power": "e = 1 up to the yield speed v_y, (v_y/v)^α above it",
}


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("identify", help="the model's parameters from measurements (single "
                       "impacts, a free decay), with standard errors and 95 %% intervals")  # fmt: skip
    kinds = p.add_subparsers(dest="data", required=True, parser_class=Parser,
                             metavar="{impacts,decay}")  # fmt: skip
    q = kinds.add_parser(
        "impacts",
        help="the restitution e(v) from single impacts: a CSV of approach and rebound speeds "
        "('approach speed [m/s]', 'rebound speed [m/s]') or drop and rebound heights ('drop "
        "height [mm]', 'rebound height [mm]')",
    )
    q.add_argument("file", metavar="FILE.csv", help="the impacts, one a row, units in the header")
    q.add_argument("--law", choices=("constant", "thornton", "power"), default="constant",
                   help="constant: Newton's e; thornton: e = 1 up to a yield speed, Thornton's "
                   "elastic–plastic e above (what --e material runs); power: (v_y/v)^α above "
                   "the yield speed; default constant")  # fmt: skip
    q.add_argument("--out", metavar="FILE.toml", default=None,
                   help="write the identified parameters as a system file (TOML, or JSON by "
                   "the suffix .json) for any command's --system")  # fmt: skip
    add_output(q, plot=True)
    q = kinds.add_parser(
        "decay",
        help="e, ζ and the clearance from a free decay after a tap: a CSV of time and the "
        "primary's displacement, velocity or acceleration ('time [s]', 'displacement [mm]')",
    )
    q.add_argument("file", metavar="FILE.csv",
                   help="the record, equally spaced from the tap at t = 0, units in the header")  # fmt: skip
    q.add_argument("--fit", default="e,zeta,gap", metavar="NAMES",
                   help="what to fit, of e, zeta, gap (comma-separated; the others are given "
                   "by their options); default e,zeta,gap")  # fmt: skip
    q.add_argument("--until", default=None, metavar="T",
                   help="fit the record's first T seconds only (e.g. where a warning says the "
                   "fitted motion leaves the record)")  # fmt: skip
    q.add_argument("--e", default=None, metavar="E",
                   help="Newton's restitution if not fitted (0 ≤ e ≤ 1); or 'thornton V': "
                   "Thornton's e(v) with the yield speed V, which --fit e then fits (from V)")  # fmt: skip
    q.add_argument("--out", metavar="FILE.toml", default=None,
                   help="write the identified system (M, K, m, ζ, d, e) for any command's "
                   "--system (TOML, or JSON by the suffix .json)")  # fmt: skip
    add_system(q, contact=False)
    # the primary and the ball are the user's: no default stands in for a measured rig
    q.set_defaults(M=None, K=None, m=None, gap=None)
    add_output(q, plot=True)


def _quantity(name: str, value: float | None, digits: int = 5) -> str:
    """``value`` [SI] of quantity ``name`` in its display unit (``--show NAME=UNIT``; e.g. the
    clearance in mm, a yield speed in mm/s), to ``digits`` significant digits."""
    if value is None:
        return "open"
    unit = display_unit(name)
    text = f"{shown(name, value):.{digits}g}"
    return text if unit == "dimensionless" else f"{text} {unit}"


def _law_line(law: str, result: Any, best: bool) -> str:
    """One law of the comparison: its AIC and rms, the lowest marked."""
    text = (
        f"  {law:<9} AIC {result.aic:9.2f}   rms {_quantity('rebound_speed', result.residual_rms)}"
    )
    return text + ("   <- lowest" if best else "")


def _parameter_lines(result: Any) -> list[str]:
    lines = []
    for p in result.parameters.values():
        se = ("not determined" if p.stderr is None
              else f"± {_quantity(p.name, p.stderr, 2)} (1 se)")  # fmt: skip
        lo, hi = p.ci95
        lines.append(wrapped(f"{p.name} = {_quantity(p.name, p.value)} {se}; 95 % interval "
                             f"{_quantity(p.name, lo)} to {_quantity(p.name, hi)}"))  # fmt: skip
    return lines


def run_impacts(ns) -> None:
    """``identify impacts FILE.csv``: fit the law, compare it with the others, write the system
    file and the figure."""
    from ..identify.impacts import LAWS, fit_restitution, law_setting, read_impacts

    if ns.out and ns.law == "power":
        law_setting("power", None)  # refused: the engines run constant e or Thornton's law
    data = read_impacts(ns.file)
    results = {law: fit_restitution(data, law) for law in LAWS}
    result = results[ns.law]
    setting = None if ns.law == "power" else law_setting(ns.law, result)
    if ns.out:
        _write_system(ns, "impacts", result, {"e": setting})
    if ns.plot:
        from ..report.plots import plot_restitution_fit

        plot_restitution_fit(data, results, ns.law, ns.plot)
    if ns.csv:
        _write_csv(ns, data, result)
    out = {
        "law": ns.law,
        **result.as_dict(),
        "compared": {k: {"residual_rms": r.residual_rms, "aic": r.aic} for k, r in results.items()},
        "system": {} if setting is None else {"e": setting},
        "data": {"impacts": int(data.v_in.size), "given": data.given},
    }
    best = min(results, key=lambda k: results[k].aic)
    text = [
        wrapped(
            f"{data.v_in.size} impacts (given as {data.given}s), approach speeds "
            f"{_quantity('rebound_speed', data.v_in.min())} to {_quantity('rebound_speed', data.v_in.max())}",
            "",
        ),
        wrapped(f"law: {ns.law}: {_LAW_TEXT[ns.law]}", ""),
        *_parameter_lines(result),
        wrapped(
            f"residual rms {_quantity('rebound_speed', result.residual_rms)} of the rebound speed "
            f"({result.dof} degrees of freedom)"
        ),
        "the laws compared (Akaike's criterion: lower is better):",
        *(_law_line(k, r, k == best) for k, r in results.items()),
        *(wrapped(f"warning: {w}", "") for w in result.warnings),
    ]
    if setting is not None:
        v = result.parameters.get("yield_speed")
        e_text = f"thornton {v.value:.6g} m/s" if v is not None else f"{setting:.6g}"
        text.append(wrapped(f"for any command: --e '{e_text}'"
                            + (f" or --system {ns.out}" if ns.out else ""), ""))  # fmt: skip
    emit(ns, out, "\n".join(text))


def _write_system(ns, kind: str, result: Any, values: dict[str, Any],
                  uncertainty: dict[str, Any] | None = None) -> None:  # fmt: skip
    """The identified ``values`` as a --system file at ``ns.out``: TOML, with the fit's
    parameters (``result``) in comments and ``uncertainty`` as its [uncertainty] table; or
    JSON, by the suffix .json, the values and the uncertainty alone."""
    import json

    from ..io import atomic_write

    if str(ns.out).lower().endswith(".json"):
        table = {**values, **({"uncertainty": uncertainty} if uncertainty else {})}
        payload = json.dumps(table, indent=2)
        atomic_write(ns.out, lambda f: f.write(payload + "\n"), "out")
        return
    lines = [f"# identified by 'symimpact identify {kind}' from {ns.file}"]
    for p in result.parameters.values():
        lines.append(f"# {p.name} = {p.value!r} {p.unit}, standard error {p.stderr!r}, "
                     f"95 % interval [{p.ci95[0]!r}, {p.ci95[1]!r}]")  # fmt: skip
    lines += [f"{k} = {json.dumps(v) if isinstance(v, str) else repr(v)}"
              for k, v in values.items()]  # fmt: skip
    if uncertainty:
        u = uncertainty
        lines += ["", "# the fitted parameters' covariance (SI), for frf --propagate N",
                  "[uncertainty]", f"names = {json.dumps(u['names'])}",
                  f"values = {u['values']!r}",
                  "covariance = [" + ", ".join(repr(r) for r in u["covariance"]) + "]"]  # fmt: skip
    atomic_write(ns.out, lambda f: f.write("\n".join(lines) + "\n"), "out")


def _write_csv(ns, data: Any, result: Any) -> None:
    """Per impact: approach and rebound speed, the measured and fitted e, the residual."""
    import csv

    from ..identify.impacts import restitution
    from ..io import atomic_write

    e_fit = restitution(ns.law, list(result.values().values()), data.v_in)

    def write(f) -> None:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["approach speed [m/s]", "rebound speed [m/s]", "e measured [1]",
                    "e fitted [1]", "residual [m/s]"])  # fmt: skip
        for row in zip(data.v_in, data.v_out, data.v_out / data.v_in, e_fit, result.residuals,
                       strict=True):  # fmt: skip
            w.writerow([repr(float(x)) for x in row])

    atomic_write(ns.csv, write, "csv")


def _decay_system(ns, fitted: list[str]):
    """The rig's system from the options: M, K (or --fn) and m given; ζ (or C), d and e given
    unless fitted (a fitted one's option, if given, is ignored: its start is found from the
    record)."""
    from ..errors import ParameterError

    for key, flag in (("M", "M"), ("K", "K (or --fn with --M)"), ("m", "m")):
        if getattr(ns, key) is None:
            raise ParameterError(key, f"the rig's {key} is needed: give --{flag}")
    if "zeta" in fitted:
        ns.C, ns.zeta = None, 0.01  # a placeholder: the fit starts from the record's decrement
    elif ns.C is None and ns.zeta is None:
        raise ParameterError("zeta", "give the primary's damping (--zeta, --C, --q-factor) or "
                             "fit it (--fit ...,zeta)")  # fmt: skip
    if "gap" in fitted:
        ns.gap = 1.0  # a placeholder: the fit starts from the record's amplitude
    elif ns.gap is None:
        raise ParameterError("gap", "give the clearance --gap or fit it (--fit ...,gap)")
    if "e" not in fitted and ns.e is None:
        raise ParameterError("e", "give the restitution --e or fit it (--fit ...,e)")
    ns.k_hz = ns.k_hz or 1000.0  # rigid impacts: the compliant law is not used
    return system_from(ns)


def run_decay(ns) -> None:
    """``identify decay FILE.csv``: fit e, ζ, d (those asked for) and the tap's x₀, ẋ₀."""
    from ..errors import ParameterError
    from ..identify.decay import FITTABLE, fit_decay, read_decay
    from ..model.units import si_float

    fitted = [f.strip() for f in str(ns.fit).split(",") if f.strip()]
    for name in fitted:
        if name not in FITTABLE:
            raise ParameterError("fit", f"{name!r} is not one of {', '.join(FITTABLE)}")
    if not fitted:
        raise ParameterError("fit", "names nothing to fit")
    from ..forced.contact_law import MaterialRestitution

    system = _decay_system(ns, fitted)
    if isinstance(ns.e, MaterialRestitution):  # --e 'thornton V'
        e = ns.e
    else:
        e = 0.5 if "e" in fitted and ns.e is None else si_float("e", ns.e)
    data = read_decay(ns.file)
    if ns.until is not None:
        from ..identify.decay import Decay
        from ..model.units import positive_float

        keep = int(positive_float("until", ns.until, "s") / data.dt) + 1
        if keep < 8:
            raise ParameterError("until", f"keeps {keep} samples of the record: at least 8")
        data = Decay(data.values[:keep], data.dt, data.quantity)
    result, response = fit_decay(system, data, fitted, e=e)
    values = result.values()
    restitution: Any = values.get("e", e)
    if isinstance(e, MaterialRestitution):  # the law as --e takes it
        restitution = f"thornton {values.get('yield_speed', e.yield_speed)!r} m/s"
    identified = {"M": system.M, "K": system.K, "m": system.m,
                  "zeta": values.get("zeta", system.zeta),
                  "gap": values.get("gap", system.gap), "e": restitution}  # fmt: skip
    if ns.out:
        _write_system(ns, "decay", result, identified, _uncertainty(result))
    if ns.plot:
        from ..report.plots import plot_decay_fit

        plot_decay_fit(data, result, response, ns.plot)
    if ns.csv:
        _write_decay_csv(ns, data, result)
    n_imp = int(response.impact_times.size)
    out = {"kind": "decay", **result.as_dict(), "system": identified,
           "data": {"samples": int(data.values.size), "dt": data.dt, "quantity": data.quantity},
           "impacts": n_imp}  # fmt: skip
    text = [
        wrapped(
            f"decay: {data.values.size} samples of {data.quantity} over "
            f"{data.dt * (data.values.size - 1):.4g} s; the rig: M {system.M:.5g} kg, K "
            f"{system.K:.5g} N/m (f_n {system.omega_n / 6.283185307179586:.5g} Hz), m "
            f"{system.m * 1e3:.5g} g",
            "",
        ),
        wrapped(
            f"fitted: {', '.join(_fitted_text(fitted, e))} and the tap's x0, xdot0 (rigid "
            "impacts; the ball at rest in the middle of its clearance at t = 0)",
            "",
        ),
        *_parameter_lines(result),
        wrapped(
            f"{n_imp} impacts in the fitted motion; residual rms "
            f"{_quantity(f'residual_{data.quantity}', result.residual_rms, 4)} ({result.dof} degrees of "
            "freedom)"
        ),
        *(wrapped(f"warning: {w}", "") for w in result.warnings),
    ]
    if ns.out:
        text.append(f"the identified system: --system {ns.out}")
    emit(ns, out, "\n".join(text))


def _fitted_text(fitted: list[str], e: Any) -> list[str]:
    """The fitted parameters in words: e by Thornton's law is its yield speed."""
    from ..forced.contact_law import MaterialRestitution

    thornton = isinstance(e, MaterialRestitution)
    return ["Thornton's yield speed" if k == "e" and thornton else k for k in fitted]


def _uncertainty(result: Any) -> dict[str, Any] | None:
    """The fitted system parameters' values and covariance (SI), Cov = ρ·se·seᵀ, for a system
    file's [uncertainty]; None if one of them is not determined."""
    import numpy as np

    from ..identify.decay import FITTABLE

    names = [k for k in result.parameters if k in FITTABLE]
    idx = [list(result.parameters).index(k) for k in names]
    se = np.array([result.parameters[k].stderr or np.nan for k in names])
    cov = result.correlation[np.ix_(idx, idx)] * np.outer(se, se)
    if not names or not np.all(np.isfinite(cov)):
        return None
    return {"names": names, "values": [result.parameters[k].value for k in names],
            "covariance": [[float(x) for x in row] for row in cov]}  # fmt: skip


def _write_decay_csv(ns, data: Any, result: Any) -> None:
    """Per sample: time, measured, fitted, residual (SI, units in the header)."""
    import csv

    from ..identify.decay import QUANTITIES
    from ..io import atomic_write

    unit = QUANTITIES[data.quantity]

    def write(f) -> None:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["time [s]", f"{data.quantity} measured [{unit}]",
                    f"{data.quantity} fitted [{unit}]", f"residual [{unit}]"])  # fmt: skip
        for t, y, r in zip(data.times, data.values, result.residuals, strict=True):
            w.writerow([repr(float(t)), repr(float(y)), repr(float(y - r)), repr(float(r))])

    atomic_write(ns.csv, write, "csv")


def run(ns) -> None:
    """``identify``: by the kind of data."""
    {"impacts": run_impacts, "decay": run_decay}[ns.data](ns)


#: The subcommands this module runs.
COMMANDS = {"identify": run}
