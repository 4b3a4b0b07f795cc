"""``symimpact identify``: the model's parameters from measurements, with their uncertainty."""

from __future__ import annotations

from typing import Any

from .common import Parser, add_output, emit, wrapped

#: The laws in words, for the text.
_LAW_TEXT = {
    "constant": "Newton's constant e (Eq. F2)",
    "thornton": "e = 1 up to the yield speed, Thornton's elastic–plastic e above it (Step 13)",
    "power": "e = 1 up to the yield speed v_y, (v_y/v)^α above it",
}


def add_parser(sub: Any) -> None:
    """Add the subcommand's parser to ``sub`` (the parsers' subparsers action)."""
    p = sub.add_parser("identify", help="the model's parameters from measurements (impacts), "
                       "with standard errors and 95 % intervals")  # fmt: skip
    kinds = p.add_subparsers(dest="data", required=True, parser_class=Parser,
                             metavar="{impacts}")  # fmt: skip
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


def _quantity(value: float | None, unit: str, digits: int = 5) -> str:
    """``value`` (SI ``unit``) as people read it, to ``digits`` significant digits: speeds below
    1 m/s in mm/s."""
    if value is None:
        return "open"
    if unit == "m/s" and abs(value) < 1.0:
        return f"{value * 1e3:.{digits}g} mm/s"
    return f"{value:.{digits}g}" if unit == "1" else f"{value:.{digits}g} {unit}"


def _law_line(law: str, result: Any, best: bool) -> str:
    """One law of the comparison: its AIC and rms, the lowest marked."""
    text = f"  {law:<9} AIC {result.aic:9.2f}   rms {_quantity(result.residual_rms, 'm/s')}"
    return text + ("   <- lowest" if best else "")


def _parameter_lines(result: Any) -> list[str]:
    lines = []
    for p in result.parameters.values():
        se = ("not determined" if p.stderr is None
              else f"± {_quantity(p.stderr, p.unit, 2)} (1 se)")  # fmt: skip
        lo, hi = p.ci95
        lines.append(f"  {p.name} = {_quantity(p.value, p.unit)} {se}; 95 % interval "
                     f"{_quantity(lo, p.unit)} to {_quantity(hi, p.unit)}")  # fmt: skip
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
        _write_system(ns, result, setting)
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
        f"{data.v_in.size} impacts (given as {data.given}s), approach speeds "
        f"{_quantity(data.v_in.min(), 'm/s')} to {_quantity(data.v_in.max(), 'm/s')}",
        f"law: {ns.law} — {_LAW_TEXT[ns.law]}",
        *_parameter_lines(result),
        f"  residual rms {_quantity(result.residual_rms, 'm/s')} of the rebound speed "
        f"({result.dof} degrees of freedom)",
        "the laws compared (Akaike's criterion, lower fits better for its parameters):",
        *(_law_line(k, r, k == best) for k, r in results.items()),
        *(wrapped(f"warning: {w}", "") for w in result.warnings),
    ]
    if setting is not None:
        v = result.parameters.get("yield_speed")
        e_text = f"thornton {v.value:.6g} m/s" if v is not None else f"{setting:.6g}"
        text.append(f"for any command: --e '{e_text}'"
                    + (f" or --system {ns.out}" if ns.out else ""))  # fmt: skip
    emit(ns, out, "\n".join(text))


def _write_system(ns, result: Any, setting: str | float) -> None:
    """The system file: ``e`` as the command line's --e takes it, with the fit in comments
    (TOML) or beside it (JSON's ``"identified"`` is not read back: only system keys are)."""
    import json

    from ..io import atomic_write

    p = next(iter(result.parameters.values()))
    lo, hi = p.ci95
    if str(ns.out).lower().endswith(".json"):
        payload = json.dumps({"e": setting}, indent=2)
        atomic_write(ns.out, lambda f: f.write(payload + "\n"), "out")
        return
    lines = [
        f"# identified by 'symimpact identify impacts' from {ns.file} (law {ns.law})",
        f"# {p.name} = {p.value!r} {p.unit}, standard error {p.stderr!r}, "
        f"95 % interval [{lo!r}, {hi!r}]",
        f"e = {json.dumps(setting)}",
    ]
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


def run(ns) -> None:
    """``identify``: by the kind of data."""
    {"impacts": run_impacts}[ns.data](ns)


#: The subcommands this module runs.
COMMANDS = {"identify": run}
