"""One impact: amplitude ratio B/A, contact duration by four methods, contact motion, restitution.

Methods of :func:`contact_duration`:

- ``perturbation``: the fixed point of Eq. 31 (two-variable expansion, Sect. 2.4), iterated from
  T⁽⁰⁾ to convergence, with its history (Fig. 3b), in the derived form and as printed.
- ``hertz``: Eq. 34, two free bodies with the Hertz law.
- ``linear``: Eq. 35, the linear spring k₁ with the dashpot c₁.
- ``numerical``: the contact phase of the chosen law integrated (Dormand–Prince 5(4), rtol 1e-12)
  until the penetration returns to zero: the main mass starts at rest at x = 0 on its spring (or
  free with ``free=True``), the impact mass arrives with relative speed v0.

B/A enters Eq. 31–33; see :func:`amplitude_ratio` for the roots and the default.

Beyond the paper, one impact under the Hunt–Crossley law (Step 11, Eq. F4) is in
:mod:`symimpact.model.hunt_crossley`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import ConvergenceError, MethodNotApplicable, ParameterError
from ..generated import closed_forms, harmonic_balance, lindstedt
from ..generated import multiple_scales as ms
from ..model.system import ImpactSystem
from ..model.units import nonnegative, nonnegative_float, positive, positive_float, si, si_float

METHODS = ("perturbation", "hertz", "linear", "numerical")
BA_CHOICES = ("impact", "out_of_phase", "in_phase", "free")


# --- B/A ------------------------------------------------------------------------------------------
def amplitude_ratio_roots(
    M: Any, K: Any, m: Any, b: Any, a: Any = 0.0, v0: Any = None
) -> dict[str, float]:
    """The values B/A can take in Eq. 31–33 [1] (Eq. 12–13, 15, 20).

    With a = 0 (or no ``v0``) the two single-harmonic balances of Eq. 12 are linear and their
    determinant has two roots ω² (kernels ``linear_frequency_squared_*``): ``in_phase`` (B/A > 0)
    and ``out_of_phase`` (B/A < 0).  With a > 0 and an approach speed v0 each root is corrected
    by the Lindstedt–Poincaré frequency of Eq. 20 at the main-mass amplitude α = v0/(ω·abs(B/A − 1))
    (the amplitude at which the relative speed amplitude is v0), solved self-consistently with
    Eq. 13 and 15.  ``free`` is the K → 0 limit −M/m (two free bodies; the limit of the
    out-of-phase root).  ``impact`` is the root with the larger abs(B/A): the mode dominated by the
    impact mass's motion, which is the out-of-phase one when K is small against the contact
    stiffness and the in-phase one when the main spring is much stiffer than the contact.
    """
    M, K, m, b = (positive_float(n, v) for n, v in (("M", M), ("K", K), ("m", m), ("b", b)))
    a = nonnegative_float("a", a)
    roots = {}
    for name in ("in_phase", "out_of_phase"):
        w2 = float(getattr(harmonic_balance, f"linear_frequency_squared_{name}")(K, M, m, b))
        ratio = float(getattr(harmonic_balance, f"linear_amplitude_ratio_{name}")(K, M, m, b))
        if a > 0 and v0 is not None:
            if not w2 > 0:  # the lower root of Eq. 12 is a difference that can round to ≤ 0
                raise MethodNotApplicable(
                    "perturbation",
                    f"the {name.replace('_', '-')} frequency of Eq. 12 rounds to {w2:g} rad²/s² "
                    "for these magnitudes of K, M, m and b, so Eq. 20 cannot correct it",
                )
            ratio = _eq20_ratio(M, K, m, a, b, positive_float("v0", v0), math.sqrt(w2), ratio)
        roots[name] = ratio
    roots["free"] = -M / m
    roots["impact"] = max(roots["in_phase"], roots["out_of_phase"], key=abs)
    return roots


def _eq20_ratio(M, K, m, a, b, v0, w_lin, ratio_lin):
    """B/A on the branch through the linear root with the frequency of Eq. 20 (secant on ω)."""

    def residual(w):
        ba = float(harmonic_balance.amplitude_ratio_scalar(K, M, m, w))
        w0sq = harmonic_balance.duffing_omega0_squared_scalar(K, M, m, b, w)
        if w0sq <= 0 or ba == 1.0:
            return math.nan, ba
        alpha = v0 / (w * abs(ba - 1.0))
        return w - lindstedt.frequency_eq20_scalar(K, M, a, b, math.sqrt(w0sq), alpha), ba

    w_prev, w = w_lin, w_lin * (1 + 1e-6)
    r_prev, _ = residual(w_prev)
    history = [w_prev]
    for _ in range(100):
        r, ba = residual(w)
        history.append(w)
        if not math.isfinite(r):
            break
        if r == 0.0 or abs(w - w_prev) <= 1e-14 * w:
            return ba
        w_prev, w, r_prev = w, w - r * (w - w_prev) / (r - r_prev), r
        if not (w > 0 and math.isfinite(w)):
            break
    raise ConvergenceError("Eq. 20 frequency on the B/A branch", history)


def amplitude_ratio(
    system: ImpactSystem, ba: Any = "impact", v0: Any = None, nonlinear: bool = False
) -> float:
    """B/A for ``system``: a named root of :func:`amplitude_ratio_roots` or a number.

    ``nonlinear`` applies the Eq. 20 correction at approach speed ``v0``.  The value must make
    Eq. 31 real: (B/A − 1)/(B/A) > 0, i.e. B/A < 0 or B/A > 1.
    """
    if isinstance(ba, str) and ba in BA_CHOICES:
        if system.b is None:
            raise ParameterError("b", "B/A from Eq. 13 needs the cubic law's b")
        with np.errstate(all="ignore"):  # a non-finite root is reported below, not warned
            value = amplitude_ratio_roots(
                system.M, system.K, system.m, system.b, system.a or 0.0, v0 if nonlinear else None
            )[ba]
        if not math.isfinite(value):
            raise MethodNotApplicable(
                "perturbation",
                f"the {ba} root B/A of Eq. 13 is not finite for M = {system.M:g} kg, "
                f"K = {system.K:g} N/m, m = {system.m:g} kg, b = {system.b:g} N/m (the masses "
                "or stiffnesses are too far apart for float arithmetic)",
            )
    elif isinstance(ba, str):
        try:
            value = float(ba)
        except ValueError:
            raise ParameterError(
                "ba", f"must be a number or one of {', '.join(BA_CHOICES)}"
            ) from None
    else:
        value = si_float("ba", ba)
    if 0.0 <= value <= 1.0:
        raise ParameterError(
            "ba", f"B/A = {value:g} in [0, 1] makes (B/A − 1)/(B/A) ≤ 0: Eq. 31 has no real root"
        )
    return value


# --- contact duration -----------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactDuration:
    """A contact duration by one method [s], with what that method gives besides: what
    :func:`contact_duration` returns for every method.

    ``value`` [s] (an array when v0 is one) and ``method``.  ``perturbation`` (Eq. 31) also
    fills ``history`` (the iterates, shape (iterations + 1, ...)), ``printed`` and
    ``printed_history`` (Eq. 31 as printed), ``ba`` and ``iterations``; ``hertz`` fills
    ``printed`` (Eq. 34 with the printed constant 2.9432).  Fields a method does not have are
    None.  ``float(d)`` is ``float(d.value)``.
    """

    value: np.ndarray | float
    method: str = "perturbation"
    history: np.ndarray | None = None
    printed: np.ndarray | float | None = None
    printed_history: np.ndarray | None = None
    ba: np.ndarray | float | None = None
    iterations: int = 0
    notes: list[str] = field(default_factory=list)

    def __float__(self) -> float:
        return float(self.value)


#: The former name of :class:`ContactDuration` (Eq. 31's result).
PerturbationDuration = ContactDuration


def _iterate(start, step, what, tol=1e-14, max_iter=500):
    T = np.asarray(start, dtype=float)
    history = [T]
    for it in range(1, max_iter + 1):
        Tn = np.asarray(step(T), dtype=float)
        history.append(Tn)
        if np.all(np.abs(Tn - T) <= tol * np.abs(Tn)):
            return Tn, np.array(history), it
        T = Tn
    bad = np.argmax(np.abs(history[-1] - history[-2]) - tol * np.abs(history[-1]))
    raise ConvergenceError(what, [float(np.ravel(h)[bad]) for h in history[-6:]])


def perturbation_duration(m: Any, a: Any, b: Any, c1: Any, v0: Any, ba: Any) -> ContactDuration:
    """Contact duration T_CD of Eq. 31 iterated from T⁽⁰⁾ to abs(ΔT) ≤ 1e-14·T [s] (vectorised).

    ``m`` [kg], ``a`` [N/m³], ``b`` [N/m], ``c1`` [N s/m], approach speed ``v0`` [m/s] and
    ``ba`` = B/A [1] broadcast against each other.  Returns the derived form (see errata.md,
    Eq. 21: factor (B−A)/B) and the printed form (B/(B−A)), each with its iteration history.
    """
    m = positive("m", m)
    a = nonnegative("a", a)
    b = positive("b", b)
    c1 = nonnegative("c1", c1)
    v0 = positive("v0", v0)
    ba = si("ba", ba)
    bad = (np.asarray(ba) >= 0) & (np.asarray(ba) <= 1)
    if np.any(bad):
        raise ParameterError("ba", "B/A in [0, 1] makes Eq. 31 complex; need B/A < 0 or > 1")
    args = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (m, a, b, c1, v0, ba)))
    m, a, b, c1, v0, ba = args
    value, hist, its = _iterate(
        ms.contact_duration_start(m, b, ba),
        lambda T: ms.contact_duration_map(T, m, a, b, c1, v0, ba),
        "Eq. 31 fixed point (derived form)",
    )
    pvalue, phist, _ = _iterate(
        ms.contact_duration_start_printed(m, b, ba),
        lambda T: ms.contact_duration_map_printed(T, m, a, b, c1, v0, ba),
        "Eq. 31 fixed point (as printed)",
    )
    return ContactDuration(
        value=value[()],
        method="perturbation",
        history=hist,
        printed=pvalue[()],
        printed_history=phist,
        ba=ba[()],
        iterations=its,
    )


def perturbation_durations(
    m: Any,
    a: Any,
    b: Any,
    c1: Any,
    v0: Any,
    ba: Any,
    *,
    method: str = "iteration",
    tol: float = 1e-14,
    max_iter: int = 100,
) -> Any:
    """Contact durations T_CD of Eq. 31 [s] for many impacts at once, in compiled code.

    The fixed point of Eq. 31 (derived form) for arguments that broadcast against each other:
    ``m`` [kg], ``a`` [N/m³], ``b`` [N/m], ``c1`` [N s/m], approach speed ``v0`` [m/s],
    ``ba`` = B/A [1] (< 0 or > 1).  ``method="iteration"`` (default) runs Eq. 31 itself from
    T⁽⁰⁾ (``generated.fixed_points.contact_duration``); ``"newton"`` finds a fixed point by
    Newton's method on h(T) = T²·D(T) − π² from its closed form at c₁ = 0
    (``contact_duration_newton``): several times faster, and it converges where the iteration
    oscillates (strong nonlinearity).  Where Eq. 31 has two positive fixed points (a strong
    cubic term with strong contact damping: 0.40 % of the declared ranges, see the Kernels page
    of the documentation) the two settle on different ones: Newton on the shorter, the
    iteration on the one that attracts it.  No
    history is kept; :func:`perturbation_duration` gives the iterates.

    Raises :class:`ConvergenceError` (with the last iterates of the first such point) where the
    iteration does not settle to ``tol`` in ``max_iter`` steps, and :class:`MethodNotApplicable`
    where Eq. 31 has no real fixed point.
    """
    from ..generated import fixed_points

    if method not in ("newton", "iteration"):
        raise ParameterError("method", "must be 'newton' or 'iteration'")
    if not (isinstance(tol, float | int) and 0 < tol < 1e-3):
        raise ParameterError("tol", "must lie in (0, 1e-3)")
    if not (isinstance(max_iter, int) and max_iter >= 1):
        raise ParameterError("max_iter", "must be a positive integer")
    m, b, v0 = positive("m", m), positive("b", b), positive("v0", v0)
    a, c1 = nonnegative("a", a), nonnegative("c1", c1)
    ba = si("ba", ba)
    if np.any((np.asarray(ba) >= 0) & (np.asarray(ba) <= 1)):
        raise ParameterError("ba", "B/A in [0, 1] makes Eq. 31 complex; need B/A < 0 or > 1")
    kernel = (
        fixed_points.contact_duration_newton
        if method == "newton"
        else fixed_points.contact_duration
    )
    with np.errstate(all="ignore"):
        value, steps = kernel(m, a, b, c1, v0, ba, tol, max_iter)
    bad = ~np.isfinite(value)
    if np.any(bad):
        i = np.unravel_index(np.argmax(bad), np.shape(bad))
        at = ", ".join(
            f"{n} = {float(np.broadcast_to(v, np.shape(bad))[i]):.6g}"
            for n, v in (("m", m), ("a", a), ("b", b), ("c1", c1), ("v0", v0), ("ba", ba))
        )
        raise MethodNotApplicable(
            "perturbation",
            f"Eq. 31 has no real positive fixed point at {at} (an iterate left the reals); the "
            "numerical method still applies",
        )
    stuck = steps >= max_iter
    if np.any(stuck):
        i = np.unravel_index(np.argmax(stuck), np.shape(stuck))
        point = [float(np.broadcast_to(v, np.shape(stuck))[i]) for v in (m, a, b, c1, v0, ba)]
        with np.errstate(all="ignore"):  # the iterates after max_iter − 5 … max_iter steps
            history = [
                float(kernel(*point, tol, n)[0]) for n in range(max(0, max_iter - 5), max_iter + 1)
            ]
        raise ConvergenceError(
            f"Eq. 31 {'iteration' if method == 'iteration' else 'Newton solve'} at m, a, b, c1, "
            f"v0, ba = {', '.join(f'{p:.6g}' for p in point)} ({int(stuck.sum())} of "
            f"{stuck.size} points)",
            history,
        )
    return value[()] if isinstance(value, np.ndarray) else value


def contact_duration(
    system: ImpactSystem,
    v0: Any,
    method: str = "perturbation",
    *,
    ba: Any = "impact",
    law: str | None = None,
    free: bool = False,
) -> ContactDuration:
    """Contact duration of one impact at approach speed ``v0`` [m/s] by ``method``, as a
    :class:`ContactDuration` whatever the method (its ``value`` in s).

    - ``perturbation`` (Eq. 31): also the iterates and the printed form.
    - ``hertz`` (Eq. 34): needs ``system.k_hz``; also the printed constant's value.
    - ``linear`` (Eq. 35): needs ``system.k1``; underdamped contact (c₁² < 4k₁μ) only.
    - ``numerical``: integration of the contact phase of ``law`` (default: the system's law),
      main mass on its spring from rest (``free=True``: without the spring), to 1e-10 relative.

    Every method at once: :func:`contact_durations`.  ``v0`` may be an array; the values then
    have its shape.
    """
    if method == "all":
        raise ParameterError(
            "method", "'all' is contact_durations(); give one of " + ", ".join(METHODS)
        )
    if method not in METHODS:
        raise ParameterError("method", f"must be one of {', '.join(METHODS)}")
    v0 = positive("v0", v0)
    if method == "perturbation":
        if system.a is None or system.b is None:
            raise MethodNotApplicable("perturbation", "needs the cubic coefficients a and b")
        ratio = amplitude_ratio(system, ba=ba)
        return perturbation_duration(system.m, system.a, system.b, system.c1, v0, ratio)
    if method == "hertz":
        if system.k_hz is None:
            raise MethodNotApplicable("hertz", "Eq. 34 needs the Hertz stiffness k_hz")
        args = (system.m, system.M, system.k_hz, v0)
        return ContactDuration(
            value=closed_forms.hertz_contact_duration(*args)[()],
            method="hertz",
            printed=closed_forms.hertz_contact_duration_printed(*args)[()],
        )
    if method == "linear":
        if system.k1 is None:
            raise MethodNotApplicable("linear", "Eq. 35 needs the linear stiffness k1")
        mu = system.m * system.M / (system.m + system.M)
        if system.c1**2 >= 4 * system.k1 * mu:
            raise MethodNotApplicable(
                "linear",
                f"c1 = {system.c1:g} N s/m ≥ 2√(k1·μ) = {2 * math.sqrt(system.k1 * mu):g}: the "
                "contact is overdamped and Eq. 35's square root is imaginary; the numerical "
                "method still applies",
            )
        value = np.broadcast_to(
            closed_forms.linear_contact_duration(system.m, system.M, system.k1, system.c1),
            np.shape(v0),
        )[()]
        return ContactDuration(value=value, method="linear")
    duration = numerical_contact(system, v0, law=law, free=free).duration
    return ContactDuration(value=duration, method="numerical")


def contact_durations(
    system: ImpactSystem,
    v0: Any,
    *,
    ba: Any = "impact",
    law: str | None = None,
    free: bool = False,
) -> dict[str, Any]:
    """:func:`contact_duration` by every method: ``{method: ContactDuration}``, and under
    ``"not_applicable"`` a ``{method: reason}`` for the methods that do not apply."""
    out: dict[str, Any] = {}
    skipped = {}
    for meth in METHODS:
        try:
            out[meth] = contact_duration(system, v0, meth, ba=ba, law=law, free=free)
        except MethodNotApplicable as exc:
            skipped[meth] = exc.reason
    if skipped:
        out["not_applicable"] = skipped
    return out


# --- numerical contact ----------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactOutcome:
    """One contact integrated numerically (SI units; arrays when v0 is an array)."""

    duration: Any  # [s]
    restitution: Any  # −(relative exit speed)/v0 [1]
    energy_lost: Any  # mechanical energy at onset − at exit [J]
    exit_state: Any  # (..., 4): x, ẋ, y, ẏ at the end of contact


def numerical_contact(
    system: ImpactSystem, v0: Any, law: str | None = None, free: bool = False, rtol: float = 1e-12
) -> ContactOutcome:
    """Integrate one contact until the penetration returns to zero (Eq. 10 with ``law``).

    The main mass starts at rest at x = 0 (on its spring K and damper C, or free with
    ``free=True``); the impact mass touches it, y − x = d/2, with relative speed ``v0`` [m/s].
    """
    from . import _stepper

    law = law or system.contact
    if law not in ("cubic", "hertz", "linear"):
        raise ParameterError("law", "must be cubic, hertz or linear")
    code = _stepper.LAWS[law]
    if code == _stepper.HERTZ and system.k_hz is None:
        raise MethodNotApplicable("numerical", "the Hertz law needs k_hz")
    if code == _stepper.LINEAR and system.k1 is None:
        raise MethodNotApplicable("numerical", "the linear law needs k1")
    if code == _stepper.CUBIC and (system.a is None or system.b is None):
        raise MethodNotApplicable("numerical", "the cubic law needs a and b")
    v = np.asarray(positive("v0", v0), dtype=float)
    out_d = np.empty(v.shape)
    out_e = np.empty(v.shape)
    out_l = np.empty(v.shape)
    out_s = np.empty((*v.shape, 4))
    for idx in np.ndindex(v.shape):
        vi = float(v[idx])
        p = _stepper.pack(system, rtol, rtol * 1e-3 * 0.5 * system.gap, rtol * 1e-3 * vi, free=free)
        status, t, u, e_on, e_off = _stepper.one_contact(code, p, vi)
        if status in (_stepper.TOO_MANY_STEPS, _stepper.STEP_UNDERFLOW):
            raise MethodNotApplicable("numerical", _stepper.STATUS_TEXT[status])
        if status != _stepper.OK or not math.isfinite(t):
            raise MethodNotApplicable("numerical", "the contact did not end (sticking contact)")
        out_d[idx] = t
        out_e[idx] = -(u[3] - u[1]) / vi
        out_l[idx] = e_on - e_off
        out_s[idx] = u[:4]
    return ContactOutcome(out_d[()], out_e[()], out_l[()], out_s)


def restitution(system: ImpactSystem, v0: Any, law: str | None = None, free: bool = False) -> Any:
    """Coefficient of restitution of one impact, −(relative exit speed)/v0 [1] (numerical)."""
    return numerical_contact(system, v0, law=law, free=free).restitution


def energy_lost(system: ImpactSystem, v0: Any, law: str | None = None, free: bool = False) -> Any:
    """Mechanical energy lost in one impact [J] (numerical; c₁ and, on the spring, C)."""
    return numerical_contact(system, v0, law=law, free=free).energy_lost


def c1_for_restitution(
    system: ImpactSystem, e: Any, v0: Any, law: str | None = None, free: bool = False
) -> float:
    """Contact damping c₁ [N s/m] that gives the restitution coefficient ``e`` at speed ``v0``.

    Solved by Brent's method on the numerical restitution, which falls monotonically with c₁.
    """
    from scipy.optimize import brentq

    e = si_float("restitution", e)
    if not 0.0 < e < 1.0:
        raise ParameterError("restitution", f"must lie strictly between 0 and 1, got {e:g}")
    v0 = positive_float("v0", v0)
    e_elastic = float(restitution(system.with_(c1=0.0), v0, law, free))
    if e >= e_elastic:
        raise ParameterError(
            "restitution", f"{e:g} is not below the undamped contact's {e_elastic:.6g}"
        )

    def f(c1):
        return float(restitution(system.with_(c1=c1), v0, law, free)) - e

    hi = 1e-3 * math.sqrt(system.m * (system.b or system.k1 or system.k_hz or 1.0))
    while f(hi) > 0:
        hi *= 2
        if hi > 1e12:
            raise ParameterError("restitution", f"no c1 below 1e12 N s/m gives {e:g}")
    return brentq(f, 0.0, hi, xtol=1e-14, rtol=1e-12)


# --- contact motion (Eq. 32–33) -------------------------------------------------------------------
def contact_motion(
    system: ImpactSystem, v0: Any, t: Any, ba: Any = "impact", printed: bool = False
) -> dict[str, Any]:
    """Relative displacement z(t) (Eq. 32) and main-mass displacement x(t) (Eq. 33) [m] during
    a contact that starts at t = 0 with approach speed ``v0``; Ω = π/T_CD from Eq. 31."""
    t = nonnegative("t", t, "s")
    res = contact_duration(system, v0, "perturbation", ba=ba)
    T = res.printed if printed else res.value
    Om = math.pi / float(T)
    ratio = float(res.ba)
    sfx = "_printed" if printed else ""
    args = (t, Om, system.m, system.a, system.c1, positive_float("v0", v0), ratio)
    return {
        "t": t,
        "z": getattr(ms, f"relative_displacement{sfx}")(*args),
        "zdot": getattr(ms, f"relative_velocity{sfx}")(*args),
        "x": getattr(ms, f"main_mass_displacement_contact{sfx}")(*args),
        "duration": float(T),
        "ba": ratio,
    }
