"""The continuation's Newton corrector in Ω for rigid impacts, compiled.

:func:`symimpact.forced.orbits.continuation._correct` solves [F(y) = 0, tᵀ(y − y_pred) = 0] for
y = (s/scale, Ω/unit), F(y) = (P(s; Ω) − s)/scale, with P the stroboscopic map over k periods
(Step 8's flights, Step 9's impacts, chatter to its accumulation and sticking) and its Jacobian
carried along the same motion (the monodromy and ∂P/∂Ω, :func:`._chain.rigid_jacobian`).  Each
Newton step costs one run of the one-mode engine (:func:`._modal.one_mode_run`'s three steps); from Python the
checks, the result's assembly, the scaling and the linear algebra around it cost three to five
times the run itself on the short orbits of a curve (measured on the README's system: 165 µs a
step against 28 µs for the run and its chain).  Here the whole iteration runs compiled, with the
same arithmetic and the same refusals as the Python path (a state that is not finite or lies
beyond a wall, Ω at a lightly damped resonance where Eq. F1 cancels or too many natural
periods, a run that does not end well, a Jacobian that is not finite, a singular system); the
converged point is evaluated again from Python, as before, for the orbit's result.
"""

from __future__ import annotations

import math

import numpy as np

from ... import _interrupt
from ..._compiled import compiled
from ..engine import _chain, _rigid
from ..engine._modal import one_mode_arguments, one_mode_result, run
from ..simulation import _EPS, CANCELLATION, MAX_NATURAL_PERIODS, _absorbed

#: Outcomes of :func:`correct` beside the interrupt's status.
CONVERGED, GRAZED, FAILED = 0, 1, 2
#: The chain's code for ∂P/∂Ω (:data:`._chain.PARAMETERS`).
_OMEGA = _chain.PARAMETERS.index("omega")


@compiled
def _refused(p, omega: float, periods: int) -> bool:
    """Whether :func:`symimpact.forced.simulation._simulate` refuses a rigid run at Ω = ``omega``
    over ``periods`` periods: Ω not positive and finite, within the cancelling distance of the
    primary's resonance alone or stuck with the impact mass, or more natural periods than
    MAX_NATURAL_PERIODS."""
    if not (omega > 0.0 and omega < math.inf):
        return True
    K, C = p[_rigid.P_K], p[_rigid.P_C]
    for mass in (p[_rigid.P_M], p[_rigid.P_M] + p[_rigid.P_m]):
        detuning = K - mass * omega * omega
        if C == 0.0 and detuning == 0.0:
            continue
        if K / math.hypot(detuning, C * omega) > CANCELLATION:
            return True
    t_end = periods * (2.0 * math.pi / omega)
    return not t_end * math.sqrt(K / p[_rigid.P_M]) / (2.0 * math.pi) <= MAX_NATURAL_PERIODS


@compiled
def correct(p, y_pred, y_start, tangent, scale, unit, periods, count, max_events, max_newton,
            tol, noise, stall, watch):  # fmt: skip
    """Newton on [F(y) = 0, tᵀ(y − y_pred) = 0] from ``y_start`` (module text), the run's
    parameters ``p`` (:mod:`._rigid`'s layout; its Ω replaced by each iterate's); with ``count``
    ≥ 0, an iterate whose impact events per period differ from it ends the correction (GRAZED).
    Returns (outcome, y): CONVERGED with the last iterate when a step falls below ``tol`` or
    below ``noise`` times the system's condition number (capped at ``stall``); FAILED after
    ``max_newton`` steps or a refusal; the interrupt's status if a run was interrupted."""
    y = y_start.copy()
    q = p.copy()
    state0 = np.empty(4)
    A = np.empty((5, 5))
    b = np.empty(5)
    h = p[_rigid.P_h]
    release, accumulation = float(_rigid.KIND_RELEASE), float(_rigid.KIND_ACCUMULATION)
    for _ in range(max_newton):
        x, v, z, u = y[0] * scale[0], y[1] * scale[1], y[2] * scale[2], y[3] * scale[3]
        omega = y[4] * unit
        if not (np.isfinite(x) and np.isfinite(v) and np.isfinite(z) and np.isfinite(u)):
            return FAILED, y
        if abs(z) > h + h * 1e-12 + 4.0 * _EPS * max(abs(x), abs(x + z)):
            return FAILED, y  # beyond a wall (within_walls, with its rounding)
        if _refused(p, omega, periods):
            return FAILED, y
        q[_rigid.P_W] = omega
        t_end = periods * (2.0 * math.pi / omega)
        state0[0], state0[1], state0[2], state0[3] = x, v, x + z, u
        args = one_mode_arguments(q, state0, t_end, max_events, False, False, watch)
        status, events, n_ev, _, _, final = one_mode_result(*run(*args)[:6])
        if status == _interrupt.INTERRUPTED:
            return status, y
        if status != _rigid.OK:
            return FAILED, y
        ev = np.ascontiguousarray(events[:n_ev])
        fx, fv, fy, fu = final[1], final[2], final[3], final[4]
        start = np.array([x, v])
        end_state = np.array([fx, fv, fu - fv])
        J5 = _chain.rigid_jacobian(q, ev, final[0], final[5] != 0.0, _OMEGA, start, end_state)
        if not np.all(np.isfinite(J5)):
            return FAILED, y  # an impact at zero relative speed: no saltation
        if count >= 0.0:
            kind = np.ascontiguousarray(ev[:, _rigid.E_KIND])
            side = np.ascontiguousarray(ev[:, _rigid.E_SIDE])
            absorbed = _absorbed(kind, side, release, accumulation)
            n = 0
            for i in range(n_ev):
                if kind[i] != release and not absorbed[i]:
                    n += 1
            if n / periods != count:
                return GRAZED, y
        ps = (fx, fv, fy - fx, fu)
        s = (x, v, z, u)
        for i in range(4):
            for j in range(4):
                A[i, j] = (J5[i, j] - (1.0 if i == j else 0.0)) * scale[j] / scale[i]
            A[i, 4] = J5[i, 4] * unit / scale[i]
            b[i] = -(ps[i] - s[i]) / scale[i]
        d = 0.0
        for j in range(5):
            A[4, j] = tangent[j]
            d += tangent[j] * (y[j] - y_pred[j])
        b[4] = -d
        sv = np.linalg.svd(A)[1]
        if not sv[4] > 0.0:
            return FAILED, y  # singular (numpy.linalg.solve's LinAlgError on the Python path)
        try:  # an exact zero pivot of the LU factors, which the singular values may not show
            dy = np.linalg.solve(A, b)
        except Exception:  # numba raises the LinAlgError as an exception of its own
            return FAILED, y
        y = y + dy
        step = np.max(np.abs(dy))
        if step < tol or step < min(noise * (sv[0] / sv[4]), stall):
            return CONVERGED, y
    return FAILED, y


def _forget_stale_compilations() -> None:
    """This module's cached code, dropped when it or any compiled code it holds inlined changed:
    the one-mode engine (:mod:`._modal`'s parts and its borrowed views, :mod:`._borrowed`, the one-mode
    flights of :mod:`._rigid`, the generated forced-flight kernels, the stepper's secant), the
    chain (:mod:`._chain`) or the chatter count (:func:`symimpact.forced.simulation._absorbed`)."""
    from pathlib import Path

    from ...free import _stepper
    from ...generated import forced_flight
    from .. import simulation
    from ..engine import _borrowed, _modal

    sources = [Path(__file__), *_modal.PARTS, Path(_borrowed.__file__),
               Path(_rigid.__file__), Path(_chain.__file__), Path(simulation.__file__),
               Path(forced_flight.__file__), Path(_stepper.__file__)]  # fmt: skip
    _stepper.forget_stale_compilations(correct, sources, ("_corrector.",))


_forget_stale_compilations()
