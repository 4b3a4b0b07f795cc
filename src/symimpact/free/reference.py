"""Reference simulation: the whole motion integrated by ``scipy.integrate.solve_ivp`` with events.

Independent of the compiled stepper (no closed forms, no shared code but the contact force law):
free flight integrates Eq. 7, contact integrates Eq. 10, and terminal events abs(y − x) = d/2 and
δ = 0 switch between them.  The tests use it to check :func:`symimpact.free.simulation.simulate`
(impact counts and times); the benchmark uses it as the baseline.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from ..model.system import ImpactSystem


def _force(system: ImpactSystem, law: str, delta: float, ddelta: float) -> float:
    if law == "hertz":
        fe = system.k_hz * max(delta, 0.0) ** 1.5
    elif law == "linear":
        fe = system.k1 * delta
    else:
        fe = system.a * delta**3 + system.b * delta
    return fe + system.c1 * ddelta


def reference_impacts(
    system: ImpactSystem,
    x0: float,
    xdot0: float,
    y0: float,
    ydot0: float,
    t_end: float,
    law: str | None = None,
    method: str = "DOP853",
    rtol: float = 1e-12,
    atol: float = 1e-15,
    rest: float = 1e-12,
    steps_per_period: float = 200.0,
) -> list[dict[str, Any]]:
    """Impact log (onset time, side, state at onset, contact end time) by solve_ivp (Eq. 7, 10).

    In free flight the step is capped at 1/``steps_per_period`` of the natural period 2π/ω_n:
    solve_ivp looks at the event functions only at its steps, and a shallow excursion past d/2
    (a grazing impact) between two steps would be missed.

    Stops, as :func:`symimpact.free.simulation.simulate` does, at the first onset that finds less than
    ``rest`` × the initial mechanical energy in the system (0: never).
    """
    law = law or system.contact
    M, K, C, m, h = system.M, system.K, system.C, system.m, 0.5 * system.gap

    def energy(u):
        return 0.5 * M * u[1] ** 2 + 0.5 * K * u[0] ** 2 + 0.5 * m * u[3] ** 2

    def free(t, u):
        return [u[1], -(C * u[1] + K * u[0]) / M, u[3], 0.0]

    def touch_pos(t, u):
        return (u[2] - u[0]) - h

    def touch_neg(t, u):
        return -(u[2] - u[0]) - h

    for ev in (touch_pos, touch_neg):
        ev.terminal = True
        ev.direction = 1

    # solve_ivp checks event signs only at its steps: cap the step so that a shallow excursion
    # past d/2 (a grazing impact) is not stepped over.
    max_step = 2 * np.pi / np.sqrt(K / M) / steps_per_period
    impacts: list[dict[str, Any]] = []
    t, u = 0.0, np.array([x0, xdot0, y0, ydot0], dtype=float)
    e_rest = rest * energy(u)
    while t < t_end:
        sol = solve_ivp(
            free,
            (t, t_end),
            u,
            method=method,
            rtol=rtol,
            atol=atol,
            events=(touch_pos, touch_neg),
            max_step=max_step,
        )
        hits = [(te[0], k) for k, te in enumerate(sol.t_events) if len(te)]
        if not hits:
            break
        t, k = min(hits)
        u = sol.y_events[k][0].copy()
        if energy(u) < e_rest:
            break
        side = 1.0 if k == 0 else -1.0
        record = {"t": t, "side": int(side), "x": u[0], "xdot": u[1], "y": u[2], "ydot": u[3]}

        def contact(t, u, side=side):
            delta = side * (u[2] - u[0]) - h
            f = _force(system, law, delta, side * (u[3] - u[1]))
            return [u[1], (side * f - C * u[1] - K * u[0]) / M, u[3], -side * f / m]

        def release(t, u, side=side):
            return side * (u[2] - u[0]) - h

        release.terminal = True
        release.direction = -1
        sol = solve_ivp(contact, (t, t_end), u, method=method, rtol=rtol, atol=atol, events=release)
        if not len(sol.t_events[0]):
            record["t_off"] = None
            impacts.append(record)
            break
        t = float(sol.t_events[0][0])
        u = sol.y_events[0][0].copy()
        record["t_off"] = t
        impacts.append(record)
        # step off the boundary so the free-flight events do not fire at once
        u[2] = u[0] + side * h
    return impacts
