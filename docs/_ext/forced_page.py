"""The forced-response checks page: the closed-form two-impact orbits against the simulator, the
compliant contacts stiffened towards the rigid limit, and the harmonic balance's error against H.

Every number on the page is computed when the documentation is built (about a minute).
"""

from __future__ import annotations

from pathlib import Path

# The system of the forced-response issue (inputs, not results): SI units.
SYSTEM = {"M": 1.0, "K": 1000.0, "C": 0.5, "m": 0.05, "gap": 0.02}
F0, E = 2.0, 0.6
OMEGAS = (30.0, 32.0, 34.0, 36.0, 38.0, 40.0)
W_LIMIT = 36.0
#: Where the harmonic balance's figure is written (beside the page, docs/_generated/).
OUT_FIGURE = Path(__file__).resolve().parent.parent / "_generated" / "hb_convergence.png"
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


#: The balance's convergence in H: harmonics, samples 8H a period (AFT), and the impact damper at
#: 34 rad/s with a Hertz contact (k_hz 1e5 N/m^1.5) and a dashpot c₁ 0.5 N s/m (a step at each
#: onset, ν = 0) or Hunt–Crossley's χ 0.5 s/m (ν = 3/2), as in tests/test_hb_convergence.py.
HB_HARMONICS = (4, 6, 8, 12, 16, 24, 32, 48, 64)
HB_OMEGA = 34.0
#: Duffing's x'' + 0.1x' + x + 0.5x³ = 0.3 cos 1.2t (no clearance: a smooth force).
DUFFING = (0.5, 0.3, 1.2, 0.1)


def _duffing_errors() -> list[float]:
    """The balance's x(0) and ẋ(0) (the larger error) against DOP853 shooting at rtol 1e-13."""
    import math

    import numpy as np
    from scipy.integrate import solve_ivp
    from scipy.optimize import fsolve

    from symimpact.forced.orbits.harmonic_balance import Basis, Problem, newton

    beta, F, W, zeta2 = DUFFING

    def rhs(t, s):
        return [s[1], F * math.cos(W * t) - zeta2 * s[1] - s[0] - beta * s[0] ** 3]

    T = 2 * math.pi / W

    def period_map(s):
        return solve_ivp(rhs, (0, T), s, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1]

    s = solve_ivp(rhs, (0, 200 * T), [0.0, 0.0], rtol=1e-10, atol=1e-12).y[:, -1]
    s = fsolve(lambda s: period_map(s) - s, s, xtol=1e-13)

    def force(q, qd):
        return -beta * q**3, (-3.0 * beta * q**2)[None], np.zeros((1, 1, q.shape[1]))

    out, U = [], None
    for H in HB_HARMONICS:
        F_ext = np.zeros((1, 2 * H + 1))
        F_ext[0, 1] = F
        pr = Problem(np.eye(1), zeta2 * np.eye(1), np.eye(1), F_ext, force, Basis.of(H, 8 * H))
        U0 = (
            np.eye(2 * H + 1)[1] if U is None else np.concatenate([U, np.zeros(2 * H + 1 - len(U))])
        )
        U, _, _ = newton(pr, U0, W, 1.0)
        x0 = pr.basis.at(U, np.array([0.0]))[0]
        v0 = W * pr.basis.at(U, np.array([0.0]), 1)[0]
        out.append(max(abs(x0 - s[0]), abs(v0 - s[1])) / max(abs(s[0]), abs(s[1])))
    return out


def _contact_errors(law: str) -> list[float]:
    """The balance's amplitude against shooting's, relative, each H started from the last."""
    import numpy as np

    from symimpact.forced import CompliantContact, Forcing
    from symimpact.forced.orbits.harmonic_balance import hb_orbit
    from symimpact.forced.orbits.shooting import shoot_from_rest
    from symimpact.model.system import ImpactSystem

    c1, chi = (0.5, None) if law == "hertz" else (0.0, 0.5)
    s = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, k_hz=1e5, c1=c1)
    f, contact = Forcing(F0=2.0, omega=HB_OMEGA), CompliantContact(law, chi=chi)
    exact = shoot_from_rest(s, f, contact).amplitude
    out, U = [], None
    for H in HB_HARMONICS:
        start = None
        if U is not None:  # the last coefficients, zeros in the harmonics added
            old = len(U) // 2
            start = np.zeros(2 * (2 * H + 1))
            start[:old], start[2 * H + 1 : 2 * H + 1 + old] = U[:old], U[old:]
        o = hb_orbit(s, f, contact, harmonics=H, time_samples=8 * H, start=start)
        U = np.array(o.x + o.y)
        out.append(abs(o.amplitude - exact) / exact)
    return out


def _hb_section() -> list[str]:
    """Error against H: the table, the fitted rates beside Step 17's orders, and the figure."""

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from derive import cache

    board = cache.boards()["multi_harmonic_balance"]
    orders = next(line.value for line in board.lines if line.name == "truncation_orders")
    predicted = {"hertz": orders["any dashpot c₁δ̇ (a step)"][1],
                 "hunt-crossley": orders["Hertz or Hunt–Crossley k δ¹·⁵"][1]}  # fmt: skip
    duffing = _duffing_errors()
    cases = {"hertz": _contact_errors("hertz"), "hunt-crossley": _contact_errors("hunt-crossley")}
    H = np.array(HB_HARMONICS, dtype=float)
    rates = {law: -np.polyfit(np.log(H), np.log(e), 1)[0] for law, e in cases.items()}
    # Duffing's error falls exponentially until rounding (below 1e-13 it is the period map's)
    kept = [k for k, e in enumerate(duffing) if e > 1e-13]
    decade = -1.0 / np.polyfit(H[kept], np.log10(np.array(duffing)[kept]), 1)[0]

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(H, duffing, "o-", label="Duffing, no clearance (smooth)")
    ax.loglog(H, cases["hertz"], "s-", label="Hertz with a dashpot c₁ (a step at each onset)")
    ax.loglog(H, cases["hunt-crossley"], "^-", label="Hunt–Crossley (starts as δ¹·⁵)")
    ax.set_xticks(HB_HARMONICS, [str(h) for h in HB_HARMONICS])
    ax.minorticks_off()
    ax.set_xlabel("harmonics H")
    ax.set_ylabel("relative error")
    ax.set_title("Harmonic balance against the exact orbit")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(OUT_FIGURE, dpi=110)
    plt.close(fig)

    rows = [f"| {h} | {d:.2e} | {a:.2e} | {b:.2e} |"
            for h, d, a, b in zip(HB_HARMONICS, duffing, cases["hertz"], cases["hunt-crossley"],
                                  strict=True)]  # fmt: skip
    return [
        "## Harmonic balance against H",
        "",
        "The multi-harmonic balance (`symimpact.forced.orbits.harmonic_balance`, AFT with 8H "
        "samples a period) against the exact orbit: Duffing's oscillator "
        f"x'' + {DUFFING[3]:g}x' + x + {DUFFING[0]:g}x³ = {DUFFING[1]:g} cos {DUFFING[2]:g}t "
        "(the state at t = 0 against DOP853 shooting at rtol 1e-13), and the impact damper "
        f"above at Ω = {HB_OMEGA:g} rad/s with a Hertz contact (stiffness 1e5 N/m¹·⁵) and a dashpot "
        "c₁ = 0.5 N s/m, or Hunt–Crossley's χ = 0.5 s/m (its amplitude against shooting's, the "
        "compliant engine). Each H starts from the last one's coefficients.",
        "",
        "![Relative error against H](hb_convergence.png)",
        "",
        "| H | Duffing | Hertz with c₁ | Hunt–Crossley |",
        "|---|---|---|---|",
        *rows,
        "",
        f"Duffing's error falls spectrally: a decade every {decade:.1f} harmonics. The contacts' "
        "fall as a power of H; the least-squares order over the table is "
        f"{rates['hertz']:.2f} with the dashpot's step and {rates['hunt-crossley']:.2f} for "
        "Hunt–Crossley, where Step 17 of the derivations gives the truncation's order ν + 2: "
        f"{predicted['hertz']} and {predicted['hunt-crossley']} (the force starts as $s_+^\\nu$ at an "
        "onset). The amplitude is read where the primary is far from its walls, and the "
        "balance's error is not only the truncation's (AFT folds the force's harmonics beyond "
        "8H − H onto the kept ones), so a measured order need not be ν + 2; the step's measured "
        f"order is {'below' if rates['hertz'] < rates['hunt-crossley'] else 'not below'} "
        "Hunt–Crossley's. `tests/test_hb_convergence.py` checks the rate at which the contact "
        "force's own harmonics fall, $k^{-(\\nu+1)}$, on the exact orbits.",
        "",
    ]


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
        *_hb_section(),
    ]
    return "\n".join(out)
