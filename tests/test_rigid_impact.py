"""The rigid impact law of Step 9 (Eq. F2) against a direct integration of a compliant linear
contact between two free masses, with its damping c1 from the same step's inverse formula.

Two free masses meeting through a spring-dashpot (k1, c1), the contact ending when the relative
displacement returns to zero (the paper's criterion): momentum is conserved exactly and the
relative velocity comes back multiplied by exp(−c1 T/(2μ)), so the velocities after the contact
must equal the rigid law's with the wanted e.  Reference: DOP853 at rtol 1e-12 with the end of the
contact located by its event function; its error on the velocities stays below 1e-10 of their
scale, hence the bound below.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from symimpact.generated import closed_forms as cf
from symimpact.generated import rigid_impact as ri

RTOL = 1e-9


@pytest.mark.parametrize(
    "m, M, e, xd, yd",
    [(0.05, 1.0, 0.6, 0.1, -0.4), (0.2, 0.5, 0.95, -0.3, 0.2), (0.01, 3.0, 0.05, 0.0, 1.0)],
)
def test_rigid_law_is_the_linear_contact_of_the_same_restitution(m, M, e, xd, yd):
    k1 = 1e6
    c1 = float(ri.linear_c1_for_restitution(m, M, k1, e))
    assert float(cf.linear_restitution(m, M, k1, c1)) == pytest.approx(e, rel=1e-13)
    approach = yd - xd  # z = y − x grows into the contact when positive; take the sign into z
    sign = np.sign(approach)

    def rhs(t, s):
        x, v, y, u = s
        z, zd = sign * (y - x), sign * (u - v)
        force = k1 * z + c1 * zd  # pushes the masses apart
        return [v, sign * force / M, u, -sign * force / m]

    def separated(t, s):
        return sign * (s[2] - s[0])

    separated.terminal, separated.direction = True, -1
    t_end = 10 * np.pi * np.sqrt(m * M / (m + M) / k1)
    sol = solve_ivp(
        rhs,
        (0, t_end),
        [0.0, xd, 0.0, yd],
        method="DOP853",
        rtol=1e-12,
        atol=1e-16,
        events=separated,
        first_step=t_end * 1e-6,
    )
    assert sol.status == 1, "the contact must end"
    v_end, u_end = sol.y_events[0][-1][1], sol.y_events[0][-1][3]
    scale = abs(xd) + abs(yd)
    assert abs(float(ri.main_velocity_after(m, M, e, xd, yd)) - v_end) <= RTOL * scale
    assert abs(float(ri.impact_velocity_after(m, M, e, xd, yd)) - u_end) <= RTOL * scale
    lost = 0.5 * (M * xd**2 + m * yd**2) - 0.5 * (M * v_end**2 + m * u_end**2)
    assert float(ri.energy_lost(m, M, e, xd, yd)) == pytest.approx(lost, rel=1e-8, abs=1e-14)
