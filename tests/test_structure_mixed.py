"""A compliant impact damper beside a rigid one, and beside a linear or a rigid stop, on a
structure of several modes (issue 36: "K impact dampers, each with its mass, total clearance,
attachment point and contact law; plus stops"): the rigid damper flies through the compliant
damper's contact phases and meets its walls there by Eq. F7, its chatter accumulating and its
mass riding on its point there as in the modal engine; a linear stop's spring and dashpot act in
them, its onsets and exits located, and a rigid stop's point takes Newton's law there
(:mod:`symimpact.forced.engine._structure_contact`).  Checked against what does not share that code —
SciPy's DOP853 on the modal equations, the contact forces continuous and the rigid impacts,
closures and releases applied at located events — and against the energy ledger, a rigid damper
out of reach, and the one-line refusal where a point would be held on a rigid stop during a
compliant contact."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symimpact.forced.structure_response import simulate_structure
from symimpact.model.dampers import dampers
from symimpact.model.stops import stop
from symimpact.model.structure import beam_structure, structure_from_dict

#: A steel cantilever, 1 m of 40 mm × 10 mm (8.36, 52.4 and 146.7 Hz), ζ 0.01.
BEAM = {"support": "cantilever", "E": 210e9, "I": 0.04 * 0.01**3 / 12, "rho": 7850.0, "A": 4e-4,
        "L": 1.0}  # fmt: skip
OMEGA = 2 * math.pi * 8.0
#: A 50 g mass in 10 mm at the tip on a Hertz contact (its contacts last ~8 ms, so the rigid
#: damper meets its walls during them).
SOFT = {"name": "d", "at": "tip", "m": 0.05, "gap": "10 mm", "contact": "hertz", "k_hz": 1e5,
        "c1": 5.0}  # fmt: skip


def _modal(structure, F0, force_at, *bodies):
    """The modal equations' data, written out for the references: each mode's Mᵢ, Kᵢ = ωᵢ²Mᵢ,
    Cᵢ = 2ζᵢωᵢMᵢ, the modal force amplitudes F₀φᵢ(force_at), and the shapes at each damper's or
    stop's point."""
    modes = structure.modes
    Mi = np.array([md.mass for md in modes])
    Ki = np.array([md.omega**2 * md.mass for md in modes])
    Ci = np.array([2 * md.zeta * md.omega * md.mass for md in modes])
    fi = F0 * np.array([md.shape[force_at] for md in modes])
    return (Mi, Ki, Ci, fi, *[np.array([md.shape[b.at] for md in modes]) for b in bodies])


def _law(d, y, u, x, xd):
    """A compliant damper's law written out: the wall s its mass is nearer (at y, ẏ = u; its point
    at x, ẋ) and the force it presses with, k₁δ + c₁δ̇ (linear) or k_hz·δ^1.5 + c₁δ̇ (Hertz),
    δ = s(y − x) − d/2 (0 off its wall)."""
    side = 1.0 if y > x else -1.0
    delta = side * (y - x) - d.gap / 2
    if delta <= 0:
        return side, 0.0
    spring = d.k1 * delta if d.contact == "linear" else d.k_hz * delta**1.5
    return side, spring + d.c1 * side * (u - xd)


def _structure():
    return beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=3, zeta=0.01)


def _reference(structure, ds, F0, omega, t_end):
    """DOP853 (rtol 1e-13) on the modal equations: damper 0's Hertz force in the right side, its
    onsets and exits located as events; damper 1 rigid, each meeting of its walls a terminal
    event where Eq. F7's impulse is applied and the integration restarts.  Returns the
    compliant events' times and the rigid impacts' times."""
    N = len(structure.modes)
    d, r = ds
    Mi, Ki, Ci, fi, phi_d, phi_r = _modal(structure, F0, "tip", d, r)
    hd, hr = d.gap / 2, r.gap / 2
    mu = 1.0 / (1.0 / r.m + float(np.sum(phi_r**2 / Mi)))

    def rhs(t, s):
        q, v = s[:N], s[N : 2 * N]
        side, F = _law(d, s[2 * N], s[2 * N + 2], phi_d @ q, phi_d @ v)
        a = (fi * math.cos(omega * t) - Ci * v - Ki * q + phi_d * side * F) / Mi
        return np.concatenate([v, a, [s[2 * N + 2], s[2 * N + 3], -side * F / d.m, 0.0]])

    def contact(t, s):
        return abs(s[2 * N] - phi_d @ s[:N]) - hd

    def upper(t, s):
        return s[2 * N + 1] - phi_r @ s[:N] - hr

    def lower(t, s):
        return -(s[2 * N + 1] - phi_r @ s[:N]) - hr

    for g in (upper, lower):
        g.terminal, g.direction = True, 1.0
    t, s = 0.0, np.zeros(2 * N + 4)
    onsets, impacts = [], []
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                        events=(contact, upper, lower), max_step=2e-4)  # fmt: skip
        onsets += list(sol.t_events[0])
        hit = [(te[0], ye[0], w) for te, ye, w in zip(sol.t_events[1:], sol.y_events[1:],
                                                      (1.0, -1.0), strict=True) if len(te)]  # fmt: skip
        if not hit:
            break
        t, s, wall = min(hit, key=lambda h: h[0])
        s = s.copy()
        P = (1.0 + r.e) * mu * (s[2 * N + 3] - phi_r @ s[N : 2 * N])
        s[N : 2 * N] += phi_r * P / Mi
        s[2 * N + 3] -= P / r.m
        s[2 * N + 1] = phi_r @ s[:N] + wall * hr
        impacts.append(t)
    return np.array(onsets), np.array(impacts)


@pytest.mark.parametrize(("e", "gap"), [(0.6, "2 mm"), (0.8, "1 mm")])
def test_a_rigid_damper_beside_a_compliant_one_against_dop853(e, gap):
    """The Hertz damper at the tip and a rigid 30 g mass at mid-span, 2 N at the tip at 8 Hz for
    four periods, with rigid impacts inside the Hertz contacts: every onset, exit and rigid impact
    against DOP853 with event location (1e-8 s: the reference's rtol 1e-13 with its step capped
    at 0.2 ms, as tests/test_structure_compliant.py's; measured 2.4e-13 to 4.1e-13 s over the 12
    onsets and exits, 5.4e-12 to 4.2e-11 s over the 12 and 17 impacts), and the ledger closes
    (1e-10; measured 8.5e-13 to 1.1e-12)."""
    s = _structure()
    ds = dampers(s, [SOFT, {"name": "r", "at": "mid", "m": 0.03, "gap": gap, "e": e}])
    res = simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=4)
    ev = res.events
    kinds, which = ev[:, 7].astype(int), ev[:, -1].astype(int)
    assert not np.any(np.isin(kinds, [1, 2]))  # no chatter accumulates: DOP853 follows it
    got_c = np.sort(ev[(which == 0) & np.isin(kinds, [3, 4]), 0])
    got_r = np.sort(ev[(which == 1) & (kinds == 0), 0])
    onsets, exits = got_c[::2], np.append(got_c[1::2], np.inf)[: len(got_c[::2])]
    inside = [t for t in got_r if np.any((onsets < t) & (t < exits))]
    assert len(inside) >= 2  # rigid impacts during the compliant contacts
    want_c, want_r = _reference(s, ds, 2.0, OMEGA, res.t_end)
    assert len(got_c) == len(want_c) >= 6 and len(got_r) == len(want_r) >= 10
    assert np.max(np.abs(got_c - want_c)) < 1e-8
    assert np.max(np.abs(got_r - want_r)) < 1e-8
    assert res.energy["relative_residual"] < 1e-10


def test_a_rigid_damper_out_of_reach_leaves_the_compliant_one_s_motion():
    """A rigid damper whose clearance the mid-span never reaches (1 m): the Hertz damper's
    onsets and exits are those of the structure with it alone (1e-11 s: the same integration,
    whose error norm also counts the idle mass's state, so its steps differ; measured 2.8e-13 s),
    and the tip's per-period maxima too (1e-11 of them; measured 5.8e-13)."""
    s = _structure()
    alone = simulate_structure(s, dampers(s, [SOFT]), "tip", 2.0, OMEGA, periods=4)
    far = {"name": "r", "at": "mid", "m": 0.03, "gap": "1 m", "e": 0.6}
    both = simulate_structure(s, dampers(s, [SOFT, far]), "tip", 2.0, OMEGA, periods=4)
    assert not np.any(both.events[:, -1] == 1)
    assert len(both.events) == len(alone.events) >= 6
    assert np.max(np.abs(both.events[:, 0] - alone.events[:, 0])) < 1e-11
    scale = np.max(np.abs(alone.period_max))
    assert np.max(np.abs(both.period_max - alone.period_max)) < 1e-11 * scale


def _riding_reference(structure, ds, F0, omega, t_end):
    """DOP853 (rtol 1e-13) on the modal equations, written from them alone: damper 0's Hertz
    force in the right side (its onsets and exits located as events), damper 1 rigid: free, its
    mass flies and each meeting of a wall is a terminal event where Newton's law acts, P =
    (1 + e)(ẏ − ẋₐ)/(1/m + Σφᵢ²/Mᵢ).  If its point then accelerates into the mass (a > 0) and
    the rebounds would end within simulate_structure's chatter limit (Step 9's sum, 2w/(a(1 − e))
    of 1e-7 forcing periods; at once for e = 0), the structure flies on to that accumulation
    point, where the pair takes one speed, and the mass rides on its point, (diag(Mᵢ) + mφφᵀ)q̈
    = the forces with the Hertz force, until s·ẍₐ turns positive (a terminal event: the wall
    would pull).  Returns the Hertz damper's onsets and exits, and the rigid damper's impacts,
    accumulations and releases, each with whether the Hertz contact was on."""
    N = len(structure.modes)
    d, r = ds
    Mi, Ki, Ci, fi, phi_d, phi_r = _modal(structure, F0, "tip", d, r)
    hd, hr = d.gap / 2, r.gap / 2
    Ms = np.diag(Mi) + r.m * np.outer(phi_r, phi_r)

    def forces(t, s):
        q, v = s[:N], s[N : 2 * N]
        side, F = _law(d, s[2 * N], s[2 * N + 2], phi_d @ q, phi_d @ v)
        return fi * math.cos(omega * t) - Ci * v - Ki * q + phi_d * side * F, -side * F / d.m

    def free(t, s):
        g, ad = forces(t, s)
        return np.concatenate([s[N : 2 * N], g / Mi, [s[2 * N + 2], s[2 * N + 3], ad, 0.0]])

    def riding(t, s):
        g, ad = forces(t, s)
        a = np.linalg.solve(Ms, g)
        return np.concatenate([s[N : 2 * N], a, [s[2 * N + 2], s[2 * N + 3], ad, phi_r @ a]])

    def contact(t, s):
        return abs(s[2 * N] - phi_d @ s[:N]) - hd

    def wall(side):
        def ev(t, s):
            return side * (s[2 * N + 1] - phi_r @ s[:N]) - hr

        ev.terminal, ev.direction = True, 1.0
        return ev

    def on(s):
        return contact(0.0, s) > 0.0

    t, s, side = 0.0, np.zeros(2 * N + 4), 0.0
    hertz, rigid = [], []
    while t < t_end:
        if side == 0.0:
            sol = solve_ivp(free, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                            events=(contact, wall(1.0), wall(-1.0)), max_step=2e-4)  # fmt: skip
            hertz += list(sol.t_events[0])
            hit = [(te[0], j) for j, te in enumerate(sol.t_events[1:]) if len(te)]
            if not hit:
                break
            t, j = min(hit)
            s = sol.y_events[j + 1][0].copy()
            sd = 1.0 if j == 0 else -1.0
            v, u = s[N : 2 * N], s[2 * N + 3]
            P = (1 + r.e) * (u - phi_r @ v) / (1 / r.m + np.sum(phi_r**2 / Mi))
            s[N : 2 * N] += phi_r * P / Mi
            s[2 * N + 3] -= P / r.m
            # on its wall less a few units in the last place: the next meeting is a crossing
            # (not the located root met again at once, when the rebound is slow), 1e-18 m off
            s[2 * N + 1] = phi_r @ s[:N] + sd * (hr - 1e-18)
            rigid.append((t, "impact", on(s)))
            a = -sd * (phi_r @ free(t, s)[N : 2 * N])  # the point's acceleration into the mass
            delta = 2 * abs(s[2 * N + 3] - phi_r @ s[N : 2 * N]) / (a * (1 - r.e)) if a > 0 else 1
            if delta <= 1e-7 * 2 * math.pi / omega:
                if delta > 0:  # on to the accumulation point, the wall's events left out
                    sol = solve_ivp(free, (t, t + delta), s, method="DOP853", rtol=1e-13,
                                    atol=1e-16, events=(contact,))  # fmt: skip
                    hertz += list(sol.t_events[0])
                    t, s = t + delta, sol.y[:, -1].copy()
                v, u = s[N : 2 * N], s[2 * N + 3]
                P = (u - phi_r @ v) / (1 / r.m + np.sum(phi_r**2 / Mi))
                s[N : 2 * N] += phi_r * P / Mi
                s[2 * N + 3] = phi_r @ s[N : 2 * N]
                rigid.append((t, "accumulation", on(s)))
                side = sd
        else:

            def release(t, s, sd=side):
                return sd * (phi_r @ riding(t, s)[N : 2 * N])

            release.terminal, release.direction = True, 1.0
            sol = solve_ivp(riding, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                            events=(contact, release), max_step=2e-4)  # fmt: skip
            hertz += list(sol.t_events[0])
            if not len(sol.t_events[1]):
                break
            t, s = sol.t_events[1][0], sol.y_events[1][0].copy()
            rigid.append((t, "release", on(s)))
            side = 0.0
    return np.array(hertz), rigid


@pytest.mark.parametrize("e", [0.0, 0.2])
def test_a_rigid_mass_riding_on_its_point_during_a_compliant_contact_against_dop853(e):
    """A rigid damper (30 g in 3 mm at mid-span) whose impacts stick, at once (plastic, e 0) or
    at its chatter's accumulation point (e 0.2), rides on its point until its wall would pull,
    the structure carrying it (diag(Mᵢ) + mφφᵀ), while the stiffer Hertz damper at the tip
    (k_hz 1e6) presses its walls: 2 N at the tip at 8 Hz for four periods.  The Hertz onsets and
    exits and the rigid impacts, accumulations and releases, some during the Hertz contacts,
    against DOP853 written from the equations alone (1e-8 s, the bound of the tests above;
    measured for e 0: 1.0e-12 s over 14 onsets and exits, 9.9e-13 and 1.9e-12 s over 9 impacts
    and 4 releases, 4 rigid events in a contact; for e 0.2: 1.4e-11 s over 16 onsets and exits,
    3.0e-11, 4.2e-11 and 1.2e-12 s over 32 impacts, 3 accumulations and 3 releases, 29 rigid
    events in a contact, all 3 accumulations among them), and the ledger closes (1e-10).  The
    impacts in the last TAIL before an accumulation are left out (see TAIL)."""
    s = _structure()
    ds = dampers(s, [SOFT | {"k_hz": 1e6}, {"name": "r", "at": "mid", "m": 0.03, "gap": "3 mm",
                                            "e": e}])  # fmt: skip
    res = simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=4)
    ev = res.events
    kinds, which = ev[:, 7].astype(int), ev[:, -1].astype(int)
    want_c, rigid = _riding_reference(s, ds, 2.0, OMEGA, res.t_end)
    got_c = np.sort(ev[(which == 0) & np.isin(kinds, [3, 4]), 0])
    assert len(got_c) == len(want_c) >= 6
    assert np.max(np.abs(got_c - want_c)) < 1e-8
    assert sum(inside for _, _, inside in rigid) >= 2  # rigid events inside the Hertz contacts
    got_acc = ev[(which == 1) & (kinds == 1), 0]
    want_acc = np.array([t for t, k, _ in rigid if k == "accumulation"])

    def before_tail(times, acc):
        """The impacts more than TAIL before the next accumulation."""
        nxt = np.searchsorted(acc, times)
        left = np.where(nxt < len(acc), acc[np.minimum(nxt, len(acc) - 1)] - times, np.inf)
        return times[left > TAIL]

    for kind, name, bound in ((0, "impact", 1e-8), (1, "accumulation", TAIL),
                              (2, "release", 1e-8)):  # fmt: skip
        got = ev[(which == 1) & (kinds == kind), 0]
        want = np.array([t for t, k, _ in rigid if k == name])
        if name == "impact":
            got, want = before_tail(got, got_acc), before_tail(want, want_acc)
        assert len(got) == len(want) >= 3, name
        assert np.max(np.abs(got - want)) < bound, name
    assert res.energy["relative_residual"] < 1e-10


#: A chatter's last impacts before its accumulation point are not compared one by one: their
#: approach speeds fall geometrically (by e each) to below 1e-5 m/s within the last 1e-6 s,
#: where the reference's positions, integrated to rtol 1e-13 (errors of ~1e-12 m), move an
#: impact by δx/v ~ 1e-7 s, and so the count and times of the tail's impacts and the
#: accumulation point they sum to (measured: 7.1e-7 s on two CPUs; the engine itself moves it by
#: 2e-11 s when the force is changed by 1 ulp or 1e-12).  The impacts before the tail and the
#: releases (the motion after) are compared to 1e-8 s, the accumulation to TAIL.
TAIL = 1e-6


#: The issue's two-DOF chain (masses [1, 1], springs [0, 1, 1], modal damping 1.5 %).
CHAIN = {"fe": {"M": [[1, 0], [0, 1]], "K": [[1, -1], [-1, 2]], "zeta": 0.015}}


def _chain_reference(structure, d, st, F0, omega, t_end):
    """DOP853 (rtol 1e-13) on the chain's modal equations: the compliant damper's linear law and
    the stop's spring and dashpot (both walls) in the right side, every contact's onset and exit
    located as an event."""
    Mi, Ki, Ci, fi, phi_d, phi_s = _modal(structure, F0, "1", d, st)
    h, N = d.gap / 2, len(structure.modes)

    def rhs(t, s):
        q, v = s[:N], s[N : 2 * N]
        side, F = _law(d, s[2 * N], s[2 * N + 1], phi_d @ q, phi_d @ v)
        xs, vs = phi_s @ q, phi_s @ v
        Fs = st.k1 * (xs - math.copysign(st.gap, xs)) + st.c1 * vs if abs(xs) > st.gap else 0.0
        a = (fi * math.cos(omega * t) - Ci * v - Ki * q + phi_d * side * F - phi_s * Fs) / Mi
        return np.concatenate([v, a, [s[2 * N + 1], -side * F / d.m]])

    def damper_wall(t, s):
        return abs(s[2 * N] - phi_d @ s[:N]) - h

    def stop_wall(t, s):
        return abs(phi_s @ s[:N]) - st.gap

    sol = solve_ivp(rhs, (0, t_end), np.zeros(2 * N + 2), method="DOP853", rtol=1e-13,
                    atol=1e-16, events=(damper_wall, stop_wall), max_step=0.05)  # fmt: skip
    return sol.t_events[0], sol.t_events[1]


def test_a_compliant_damper_beside_a_linear_stop_against_dop853():
    """The chain with a linear compliant damper (0.1 in 0.3 at the second DOF, k₁ 5, c₁ 0.05) and
    the issue's stop at the first DOF (here with gap 0.4, both walls, k₁ 50, c₁ 0.3), 0.1 at the
    second DOF at Ω 0.62 for six periods: the stop's contacts begin or end during the damper's,
    and every onset and exit of both against DOP853 with event location (1e-8 of the period: the
    reference's rtol 1e-13 on soft contacts, whose slow exits amplify it; measured 1.7e-9 s over
    the damper's 36, 1.6e-10 s over the stop's 14, the period 10.1 s), the ledger closing (1e-10;
    measured 2.4e-13)."""
    s = structure_from_dict(CHAIN)
    (d,) = dampers(s, [{"name": "d", "at": 1, "m": 0.1, "gap": 0.3, "contact": "linear",
                        "k1": 5.0, "c1": 0.05}])  # fmt: skip
    st = stop(s, "s", 0, 0.4, "both", "linear", 50.0, 0.3)
    omega = 0.62
    res = simulate_structure(s, [d], "1", 0.1, omega, periods=6, stops=[st])
    ev = res.events
    kinds, which = ev[:, 7].astype(int), ev[:, -1].astype(int)
    got_d = np.sort(ev[(which == 0) & np.isin(kinds, [3, 4]), 0])
    got_s = np.sort(ev[(which == 1) & np.isin(kinds, [3, 4]), 0])
    onsets, exits = got_d[::2], np.append(got_d[1::2], np.inf)[: len(got_d[::2])]
    inside = [t for t in got_s if np.any((onsets < t) & (t < exits))]
    assert len(inside) >= 2  # a stop's onset or exit during the damper's contacts
    want_d, want_s = _chain_reference(s, d, st, 0.1, omega, res.t_end)
    period = 2 * math.pi / omega
    assert len(got_d) == len(want_d) >= 4 and len(got_s) == len(want_s) >= 4
    assert np.max(np.abs(got_d - want_d)) < 1e-8 * period
    assert np.max(np.abs(got_s - want_s)) < 1e-8 * period
    assert res.energy["relative_residual"] < 1e-10


def _chain_rigid_stop_reference(structure, d, st, F0, omega, t_end):
    """DOP853 (rtol 1e-13) on the chain's modal equations: the compliant damper's linear law in
    the right side, its onsets and exits located as events; each meeting of the rigid stop's
    walls a terminal event where Newton's law at the point, φᵀq̇⁺ = −e·φᵀq̇⁻, is applied by the
    impulse through the point's effective mass (Σφᵢ²/Mᵢ)⁻¹ and the integration restarts.
    Returns the damper's events' times, the stop's impacts' times and the impacts' losses."""
    Mi, Ki, Ci, fi, phi_d, phi_s = _modal(structure, F0, "1", d, st)
    h, N = d.gap / 2, len(structure.modes)
    m_eff = 1.0 / float(np.sum(phi_s**2 / Mi))

    def rhs(t, s):
        q, v = s[:N], s[N : 2 * N]
        side, F = _law(d, s[2 * N], s[2 * N + 1], phi_d @ q, phi_d @ v)
        a = (fi * math.cos(omega * t) - Ci * v - Ki * q + phi_d * side * F) / Mi
        return np.concatenate([v, a, [s[2 * N + 1], -side * F / d.m]])

    def damper_wall(t, s):
        return abs(s[2 * N] - phi_d @ s[:N]) - h

    def stop_wall(t, s):
        return abs(phi_s @ s[:N]) - st.gap

    stop_wall.terminal, stop_wall.direction = True, 1.0
    t, s = 0.0, np.zeros(2 * N + 2)
    contacts, impacts, losses = [], [], []
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                        events=(damper_wall, stop_wall), max_step=0.05)  # fmt: skip
        contacts += list(sol.t_events[0])
        if not len(sol.t_events[1]):
            break
        t, s = sol.t_events[1][0], sol.y_events[1][0].copy()
        vs = phi_s @ s[N : 2 * N]
        s[N : 2 * N] += phi_s / Mi * (-(1.0 + st.e) * m_eff * vs)
        impacts.append(t)
        losses.append(0.5 * m_eff * (1.0 - st.e**2) * vs * vs)
    return np.array(contacts), np.array(impacts), np.array(losses)


@pytest.mark.parametrize("omega", [0.62, 0.7])
def test_a_compliant_damper_beside_a_rigid_stop_against_dop853(omega):
    """The chain's linear compliant damper (0.1 in 0.3 at the second DOF, k₁ 5, c₁ 0.05) beside a
    rigid stop at the first DOF (gap 0.4, both walls, e 0.6), 0.1 at the second DOF for six
    periods: the stop's impacts fall inside and outside the damper's contacts (Newton's law at
    the point in the contact phases, the modal engine's impact outside them), and every onset,
    exit and impact, and each impact's loss, against DOP853 with the impacts as terminal events
    (1e-8 of the period: the reference's rtol 1e-13 on soft contacts, whose slow exits amplify
    it, as the linear stop's test; measured at Ω 0.62 and 0.7: 4.8e-9 and 1.8e-9 s over the
    damper's 52 and 37 onsets and exits, 4.6e-10 and 1.5e-10 s over the stop's 10 and 9
    impacts, 5 and 2 of them in a contact, the period 10.1 and 9.0 s), the ledger closing
    (1e-10)."""
    s = structure_from_dict(CHAIN)
    (d,) = dampers(s, [{"name": "d", "at": 1, "m": 0.1, "gap": 0.3, "contact": "linear",
                        "k1": 5.0, "c1": 0.05}])  # fmt: skip
    st = stop(s, "s", 0, 0.4, "both", "rigid", e=0.6)
    res = simulate_structure(s, [d], "1", 0.1, omega, periods=6, stops=[st])
    ev = res.events
    kinds, which = ev[:, 7].astype(int), ev[:, -1].astype(int)
    assert not np.any(np.isin(kinds, [1, 2]))  # no chatter accumulates: DOP853 follows it
    got_d = np.sort(ev[(which == 0) & np.isin(kinds, [3, 4]), 0])
    hits = (which == 1) & (kinds == 0)
    got_s, lost = ev[hits, 0], ev[hits, 6]
    onsets, exits = got_d[::2], np.append(got_d[1::2], np.inf)[: len(got_d[::2])]
    inside = [t for t in got_s if np.any((onsets < t) & (t < exits))]
    assert 1 <= len(inside) < len(got_s)  # impacts in a contact phase and in flight
    want_d, want_s, want_lost = _chain_rigid_stop_reference(s, d, st, 0.1, omega, res.t_end)
    period = 2 * math.pi / omega
    assert len(got_d) == len(want_d) >= 8 and len(got_s) == len(want_s) >= 6
    assert np.max(np.abs(got_d - want_d)) < 1e-8 * period
    assert np.max(np.abs(got_s - want_s)) < 1e-8 * period
    assert np.max(np.abs(lost - want_lost)) < 1e-7 * np.max(want_lost)
    assert res.energy["relative_residual"] < 1e-10


def _held_reference(structure, d, st, F0, omega, t_end):
    """DOP853 (rtol 1e-13) on the chain's modal equations, written from them alone: the compliant
    damper's linear law in the right side (its onsets and exits located as events); the rigid
    stop (e = 0): free, each meeting of a wall is a terminal event where the point stops,
    P = −φᵀq̇/(Σφᵢ²/Mᵢ); if the free structure then accelerates the point into the wall, the
    wall holds it: q̈ = M⁻¹(g + φλ) with φᵀq̈ = 0, λ = −φᵀM⁻¹g/(φᵀM⁻¹φ), until s·λ turns
    positive (a terminal event: the wall would pull).  Returns the damper's onsets and exits,
    and the stop's impacts and releases, each with whether the damper's contact was on."""
    Mi, Ki, Ci, fi, phi_d, phi_s = _modal(structure, F0, "1", d, st)
    h, N = d.gap / 2, len(structure.modes)

    def forces(t, s):
        q, v = s[:N], s[N : 2 * N]
        side, F = _law(d, s[2 * N], s[2 * N + 1], phi_d @ q, phi_d @ v)
        return fi * math.cos(omega * t) - Ci * v - Ki * q + phi_d * side * F, -side * F / d.m

    def reaction(t, s):
        g, _ = forces(t, s)
        return -(phi_s @ (g / Mi)) / np.sum(phi_s**2 / Mi)

    def free(t, s):
        g, a = forces(t, s)
        return np.concatenate([s[N : 2 * N], g / Mi, [s[2 * N + 1], a]])

    def held(t, s):
        g, a = forces(t, s)
        return np.concatenate([s[N : 2 * N], (g + phi_s * reaction(t, s)) / Mi,
                               [s[2 * N + 1], a]])  # fmt: skip

    def contact(t, s):
        return abs(s[2 * N] - phi_d @ s[:N]) - h

    def wall(t, s):
        return abs(phi_s @ s[:N]) - st.gap

    wall.terminal, wall.direction = True, 1.0
    t, s, side = 0.0, np.zeros(2 * N + 2), 0.0
    hits, stops = [], []
    while t < t_end:
        if side == 0.0:
            sol = solve_ivp(free, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                            events=(contact, wall), max_step=0.05)  # fmt: skip
            hits += list(sol.t_events[0])
            if not len(sol.t_events[1]):
                break
            t, s = sol.t_events[1][0], sol.y_events[1][0].copy()
            sd = math.copysign(1.0, phi_s @ s[:N])
            s[N : 2 * N] -= phi_s / Mi * (phi_s @ s[N : 2 * N]) / np.sum(phi_s**2 / Mi)
            stops.append((t, "impact", contact(t, s) > 0))
            if sd * (phi_s @ free(t, s)[N : 2 * N]) > 0:  # into the wall: held
                side = sd
            else:  # a few units in the last place inside: the next meeting is a crossing
                s[:N] -= phi_s / Mi * 1e-16 * st.gap / np.sum(phi_s**2 / Mi) * sd
        else:

            def release(t, s, sd=side):
                return sd * reaction(t, s)

            release.terminal, release.direction = True, 1.0
            sol = solve_ivp(held, (t, t_end), s, method="DOP853", rtol=1e-13, atol=1e-16,
                            events=(contact, release), max_step=0.05)  # fmt: skip
            hits += list(sol.t_events[0])
            if not len(sol.t_events[1]):
                break
            t, s = sol.t_events[1][0], sol.y_events[1][0].copy()
            stops.append((t, "release", contact(t, s) > 0))
            s[:N] -= phi_s / Mi * 1e-16 * st.gap / np.sum(phi_s**2 / Mi) * side
            side = 0.0
    return np.array(hits), stops


@pytest.mark.parametrize(("at", "omega", "periods"), [(1, 0.62, 2), (0, 0.55, 3)])
def test_a_point_held_on_a_rigid_stop_during_a_compliant_contact_against_dop853(at, omega, periods):
    """A plastic rigid stop (e 0, gap 0.2, both walls) holds its point at each impact until its
    wall would pull, the structure constrained there (φᵀq̈ = 0), beside the chain's linear
    compliant damper: at the damper's DOF at Ω 0.62 (an impact during the damper's contact) for
    two periods, and at the first DOF at Ω 0.55 (the damper's contact beginning while the stop
    holds) for three.  The damper's onsets and exits and the stop's impacts and releases against
    DOP853 written from the equations alone (1e-8 of the period, as the tests above; measured
    4.5e-11 and 2.8e-8 s over the periods 10.1 and 11.4 s.  The motion at Ω 0.55 is sensitive
    to its state: the two differences grow about tenfold a period, to 1e-3 s within eight),
    the ledger closing (1e-10; measured 4.2e-14 and 1.9e-13)."""
    s = structure_from_dict(CHAIN)
    (d,) = dampers(s, [{"name": "d", "at": 1, "m": 0.1, "gap": 0.3, "contact": "linear",
                        "k1": 5.0, "c1": 0.05}])  # fmt: skip
    st = stop(s, "s", at, 0.2, "both", "rigid", e=0.0)
    res = simulate_structure(s, [d], "1", 0.1, omega, periods=periods, stops=[st])
    ev = res.events
    kinds, which = ev[:, 7].astype(int), ev[:, -1].astype(int)
    want_d, stops = _held_reference(s, d, st, 0.1, omega, res.t_end)
    period = 2 * math.pi / omega
    got_d = np.sort(ev[(which == 0) & np.isin(kinds, [3, 4]), 0])
    assert len(got_d) == len(want_d) >= 6
    assert np.max(np.abs(got_d - want_d)) < 1e-8 * period
    assert sum(inside for *_, inside in stops) >= 1
    for kind, name, least in ((0, "impact", 3), (2, "release", 1)):
        got = ev[(which == 1) & (kinds == kind), 0]
        want = np.array([t for t, k, _ in stops if k == name])
        assert len(got) == len(want) >= least, name
        assert np.max(np.abs(got - want)) < 1e-8 * period, name
    assert res.energy["relative_residual"] < 1e-10


def test_a_contact_phase_with_a_riding_mass_and_a_holding_stop_at_one_point_runs():
    """The 3-mode cantilever at 0.9 of its first mode, 1 N at the tip and the supports moving
    1 mm: a linear damper (50 g in 2 mm, k₁ 1000 N/m) at mid-span presses its wall while, at the
    tip, a plastic rigid damper (20 g in 2 mm) rides on its point and a rigid stop (e 0.6, 2 mm)
    chatters and holds it.  Before, at 0.26096 s the mass's impact let the stop go, the stop's
    point met its wall again 1e-16 s later at a rounding-level speed, that impact let the mass
    go, and the contact phase then stood at that instant until it gave up after two million
    steps ("too stiff"): the mass was set on its wall to the bit, an ulp beyond it by the
    rounding of y − xₐ, and met it again at once, over and over; and the stop's rebounds
    accumulated within the time's resolution, where the step, cut to that point, became zero
    and stayed zero.  Now a mass let go or met is set four ulps inside its wall, an
    accumulation within the time's resolution closes at once, and a step cut short leaves the
    step control's length alone.  The run ends (with these changes the rounding no longer
    leads to that instant's double release), its ledger closes (1e-11), and it has about a
    hundred events."""
    structure = _structure()
    ds = dampers(structure, [
        {"name": "d0", "at": "mid", "m": 0.05, "gap": "2 mm", "contact": "linear", "k1": 1000.0,
         "c1": 1.0},
        {"name": "d1", "at": "tip", "m": 0.02, "gap": "2 mm", "e": 0.0}])  # fmt: skip
    sts = [stop(structure, "s0", "tip", 0.002, "+", "rigid", e=0.6),
           stop(structure, "s1", "mid", 0.004, "+", "linear", 10000.0, 1.0)]  # fmt: skip
    omega = 2 * math.pi * structure.modes[0].frequency * 0.9
    r = simulate_structure(structure, ds, "tip", 1.0, omega, periods=2, stops=sts, base=0.001)
    kind = r.events[:, 7].astype(int)
    assert np.count_nonzero(kind == 1) > 2 and np.count_nonzero(kind == 2) > 2  # holds, releases
    assert len(r.events) < 1000
    assert r.energy["relative_residual"] < 1e-11
