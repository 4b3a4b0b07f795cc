"""The forced-response checks page: the closed-form two-impact orbits against the simulator, and
the compliant contacts stiffened towards the rigid limit.

Every number on the page is computed when the documentation is built (about a minute).
"""

from __future__ import annotations

# The system of the forced-response issue (inputs, not results): SI units.
SYSTEM = {"M": 1.0, "K": 1000.0, "C": 0.5, "m": 0.05, "gap": 0.02}
F0, E = 2.0, 0.6
OMEGAS = (30.0, 32.0, 34.0, 36.0, 38.0, 40.0)
W_LIMIT = 36.0
LINEAR_K1 = (1e5, 1e6, 1e7, 1e8, 1e9)
HERTZ_K = (1e7, 1e8, 1e9, 1e10, 1e11)
#: Periods of each compliant run (the last 30 kept): 150 leave ~1e-7 of the transient from the
#: rigid orbit in the section, far below the smallest error in the tables (1e-4).
PERIODS = 150


def _closed_form_rows() -> list[str]:
    """Each closed-form orbit (Eq. F3) beside a simulation started 1e-4 off it (Eq. F1, F2)."""
    from symimpact.forced import Forcing, periodic_orbits, simulate_forced
    from symimpact.model.system import ImpactSystem

    s = ImpactSystem(**SYSTEM, contact="linear", k1=1e6)  # the rigid law uses M, K, C, m, d
    rows = []
    for w in OMEGAS:
        orbits = periodic_orbits(s, Forcing(F0=F0, omega=w), E)
        if not orbits:
            rows.append(f"| {w:g} | none | | | | | |")
            continue
        for o in orbits:
            sim, verdict = "", ""
            if o.admissible:
                f = Forcing(F0=F0, omega=w, phase=o.impact_phase)
                x0 = o.X * (1 + 1e-4)
                res = simulate_forced(s, f, e=E, periods=600, discard=500, x0=x0, xdot0=o.V,
                                      y0=x0 + SYSTEM["gap"] / 2, ydot0=o.U)  # fmt: skip
                diff = (res.steady.amplitude - o.amplitude) / o.amplitude
                sim = f"{res.steady.amplitude * 1e3:.6f} ({diff:+.1e})"
                verdict = "stays" if abs(diff) < 1e-6 else "leaves"
            rows.append(
                f"| {w:g} | {o.amplitude * 1e3:.6f} | {o.impact_speed:.4f} | "
                f"{'yes' if o.admissible else 'no'} | {o.multipliers[0]:.4f} "
                f"({'stable' if o.stable else 'unstable'}) | {sim} | {verdict} |"
            )
    return rows


def _limit_rows(contact: str, stiffnesses) -> tuple[float, list[str]]:
    from symimpact.forced import Forcing, rigid_limit
    from symimpact.model.system import ImpactSystem

    s = ImpactSystem(**SYSTEM, k_hz=1e9)
    orbit, rows = rigid_limit(s, Forcing(F0=F0, omega=W_LIMIT), E, contact, stiffnesses,
                              periods=PERIODS, discard=PERIODS - 30)  # fmt: skip
    out, prev = [], None
    for r in rows:
        ratio = "" if prev is None else f"{prev / r.relative_error:.3f}"
        out.append(
            f"| {r.stiffness:.0e} | {r.damping:.5g} | {r.amplitude * 1e3:.6f} | "
            f"{r.relative_error:+.3e} | {ratio} | {r.section_spread:.1e} |"
        )
        prev = r.relative_error
    return orbit.amplitude, out


#: Stiffnesses of the linear law whose symmetric branch is continued to its pitchfork.
BRANCH_K1 = (1e6, 1e7, 1e8)


def _branch_rows() -> list[str]:
    """The symmetric branch continued down from W_LIMIT to its symmetry-breaking branch point,
    with rigid impacts and with the linear law stiffened (c1 from Step 9 for e)."""
    from symimpact.generated import rigid_impact as ri

    from symimpact.forced import (
        CompliantContact,
        Forcing,
        continue_orbit,
        periodic_orbits,
        shoot,
        simulate_forced,
    )
    from symimpact.model.system import ImpactSystem

    s = ImpactSystem(**SYSTEM, contact="linear", k1=1e6)
    (orbit,) = [o for o in periodic_orbits(s, Forcing(F0=F0, omega=W_LIMIT), E) if o.stable]
    f = Forcing(F0=F0, omega=W_LIMIT, phase=orbit.impact_phase - 0.3)  # a section in flight
    x, v, y, u = simulate_forced(s, f, contact="rigid", e=E, periods=400).final_state

    def pitchfork(system, contact):
        start = shoot(system, f, contact, (x, v, y - x, u))
        branch = continue_orbit(system, f, contact, start.state, (33.0, W_LIMIT + 0.5),
                                direction=-1, step=0.05)  # fmt: skip
        bp = next(b for b in branch.bifurcations if b.kind == "branch-point")
        return bp.omega, start.amplitude

    w0, a0 = pitchfork(s, E)
    rows = [f"| rigid | | {w0:.6f} | | | {a0 * 1e3:.6f} | | |"]
    prev = None
    for k1 in BRANCH_K1:
        c1 = float(ri.linear_c1_for_restitution(s.m, s.M, k1, E))
        w, a = pitchfork(s.with_(k1=k1, c1=c1), CompliantContact("linear"))
        err = (w0 - w, (a0 - a) / a0)
        ratio = ("", "") if prev is None else (f"{prev[0] / err[0]:.3f}", f"{prev[1] / err[1]:.3f}")
        rows.append(f"| {k1:.0e} | {c1:.5g} | {w:.6f} | {err[0]:.3e} | {ratio[0]} | "
                    f"{a * 1e3:.6f} | {err[1]:+.3e} | {ratio[1]} |")  # fmt: skip
        prev = err
    return rows


def forced_checks_page() -> str:
    """The page's Markdown."""
    m = SYSTEM
    head = (
        f"M = {m['M']:g} kg, K = {m['K']:g} N/m, C = {m['C']:g} N s/m, m = {m['m']:g} kg, "
        f"d = {m['gap'] * 1e3:g} mm, F0 = {F0:g} N, e = {E:g}"
    )
    out = [
        "# Forced response: checks",
        "",
        f"The system of these tables: {head}. Every number below is computed when this page "
        "is built, by `docs/_ext/forced_page.py`.",
        "",
        "## The two-impact orbits against the simulator",
        "",
        "Each symmetric two-impact orbit of the closed form (Eq. F3) with its largest Floquet "
        "multiplier, and the event-driven simulation (Eq. F1, F2) started on it with x 1e-4 "
        "off, after 600 forcing periods (the last 100 kept): a stable orbit is returned to, an "
        "unstable one is left. Ω in rad/s, amplitudes in mm, impact speeds in m/s; the "
        "simulated amplitude is followed by its relative difference from the closed form.",
        "",
        "| Ω | amplitude | impact speed | admissible | largest multiplier | simulated | orbit |",
        "|---|---|---|---|---|---|---|",
        *_closed_form_rows(),
        "",
        "## Compliant contact towards the rigid limit",
        "",
        f"At Ω = {W_LIMIT:g} rad/s, each compliant contact is stiffened with its damping set to "
        "give the same restitution e: c1 from Step 9's closed form for the linear law, χ from "
        "Step 11 at the orbit's impact speed for Hunt–Crossley (`symimpact.forced.orbits.rigid_limit`). "
        f"Each run starts on the stable rigid orbit and lasts {PERIODS} periods, the last 30 kept; "
        "'transient left' is the section's spread over them. The error falls like the contact "
        "duration: by √10 = 3.162 a decade of stiffness for the linear law (as 1/√k1) and by "
        "10 to the power 0.4 = 2.512 for Hertz (as the stiffness to the power −2/5).",
        "",
    ]
    amp, rows = _limit_rows("linear", LINEAR_K1)
    out += [
        f"Rigid orbit amplitude: {amp * 1e3:.6f} mm.",
        "",
        "| k1 [N/m] | c1 [N s/m] | amplitude [mm] | relative error | ratio to the previous "
        "| transient left |",
        "|---|---|---|---|---|---|",
        *rows,
        "",
    ]
    _, rows = _limit_rows("hunt-crossley", HERTZ_K)
    out += [
        "| Hertz stiffness [N/m¹·⁵] | χ [s/m] | amplitude [mm] | relative error "
        "| ratio to the previous | transient left |",
        "|---|---|---|---|---|---|",
        *rows,
        "",
        "## Compliant branches towards the rigid ones",
        "",
        f"The symmetric two-impact branch, shot at Ω = {W_LIMIT:g} rad/s and continued down in Ω "
        "to its symmetry-breaking branch point, with rigid impacts and with the linear law "
        "integrated through each contact (shooting carries the contact's variational equations; "
        "`symimpact.forced.CompliantContact`), stiffened with c1 from Step 9 for the same e. "
        f"The branch point's Ω [rad/s] and the amplitude at {W_LIMIT:g} rad/s [mm], each with "
        "its difference from the rigid value (Ω: rigid − linear; amplitude: relative) and that "
        "difference's ratio to the previous row's (√10 = 3.162 for a contact whose duration "
        "falls as 1/√k1).",
        "",
        "| k1 [N/m] | c1 [N s/m] | branch point Ω | difference | ratio | amplitude "
        "| relative difference | ratio |",
        "|---|---|---|---|---|---|---|---|",
        *_branch_rows(),
        "",
    ]
    return "\n".join(out)
