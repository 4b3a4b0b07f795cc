"""``symimpact frf --method hb`` and ``--method compare``: the curve by harmonic balance beside
the exact one (:mod:`symimpact.forced.orbits.hb_frf`, issue 83, item 2).

``hb`` prints the balance's curve in ``frf``'s JSON schema (points, branches, bifurcations,
peak) with the exact curve under ``"exact"``; ``compare`` prints the exact curve with, per
branch, ``"hb_error"`` and ``"harmonics_for"`` (``{"0.01": H1, "0.001": H2}``), the
stability disagreements and the missed orbits, and the balance's curve under ``"hb"``.  Both
draw the two curves on one figure and write both in the CSV (a ``method`` column)."""

from __future__ import annotations


def balance_of(ns, system, forcing, e) -> tuple[int, int] | None:
    """(H, N) of ``--method hb`` or ``compare``, checked before the exact curve is computed;
    None for ``--method shooting`` (where ``--harmonics`` and ``--time-samples`` are refused)."""
    from ..errors import ParameterError

    if ns.method == "shooting":
        for key, flag in (("harmonics", "harmonics"), ("time_samples", "time-samples")):
            if getattr(ns, key) is not None:
                raise ParameterError(flag, "applies to --method hb or compare")
        return None
    from ..forced.orbits.harmonic_balance import MAX_HARMONICS, _checked
    from .loads import count

    for key, flag, why in (
        ("response", "response", "the balance's curve is of the displacement max |x|"),
        ("propagate", "propagate", "applies to --method shooting"),
    ):
        if getattr(ns, key, None) not in (None, "displacement"):
            raise ParameterError(flag, why)
    H = count("harmonics", "15" if ns.harmonics is None else ns.harmonics, 1, MAX_HARMONICS)
    N = None if ns.time_samples is None else count("time-samples", ns.time_samples, 1, 1 << 20)
    try:
        H, N, _ = _checked(system, forcing, e, H, N, 1)
    except ParameterError as exc:  # the API's names, as the command line spells its options
        name = {"time_samples": "time-samples"}.get(exc.parameter, exc.parameter)
        raise ParameterError(name, exc.reason) from None
    return H, N


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
    from .frf import contact_title, peak_lines, response_text

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
