"""Free vibration with impacts: the event-driven simulation and what the paper measures on it.

:func:`simulate` runs the compiled stepper of :mod:`symimpact.free._stepper` (closed-form free flight,
Eq. 7; contact by Eq. 10 with the chosen law, or by the perturbation solution Eq. 31–33) and
returns a :class:`SimulationResult`: the impact log with the effective flag of Eq. 37, N_tot,
N_eff, the effectiveness of Eq. 38, the damping inclination of Eq. 36 and the energy balance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import MethodNotApplicable, ParameterError, SymimpactError
from ..model.system import ImpactSystem
from ..model.units import positive_float, si_float

CONTACT_PATHS = ("cubic", "hertz", "linear", "perturbation")


@dataclass(frozen=True)
class Impact:
    """One contact: the state at onset, Eq. 37's effective flag and what the contact did.

    ``t`` [s], ``x``, ``y`` [m], ``xdot``, ``ydot`` [m/s] at onset; ``duration`` [s] (None if the
    simulation ended during the contact); ``restitution`` = −(relative exit speed)/(approach
    speed) [1]; ``energy_lost`` [J] = mechanical energy at onset − at exit (c₁ and C together);
    ``contact_dissipation`` [J] = ∫c₁δ̇² dt (numerical laws), or for the perturbation path the
    relative kinetic energy the contact took, ½μ(Ż₀² − ż²) with μ = mM/(m + M).
    """

    t: float
    x: float
    xdot: float
    y: float
    ydot: float
    side: int
    effective: bool
    duration: float | None
    restitution: float | None
    energy_lost: float | None
    contact_dissipation: float | None

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


@dataclass(frozen=True)
class SimulationResult:
    """Outcome of :func:`simulate` (SI units throughout)."""

    system: ImpactSystem
    contact: str
    initial_state: tuple[float, float, float, float]
    t_end: float
    impacts: list[Impact]
    peaks: np.ndarray  # (n, 2): time and value of the positive maxima of x
    energy: dict[str, float | None]
    history: dict[str, np.ndarray] | None = None
    notes: list[str] = field(default_factory=list)
    t_rest: float | None = None  # [s] when the run stopped at rest (see ``simulate(rest=…)``)

    @property
    def n_impacts(self) -> int:
        """N_tot: number of contacts (Table 3)."""
        return len(self.impacts)

    @property
    def n_effective(self) -> int:
        """N_eff: contacts with ẋ·ẏ < 0 at onset (Eq. 37)."""
        return sum(1 for i in self.impacts if i.effective)

    @property
    def effectiveness(self) -> float | None:
        """N_eff/(N_tot − N_eff) (Eq. 38); None when every impact (or none) is effective."""
        return effectiveness(self.n_impacts, self.n_effective)

    @property
    def damping_inclination(self) -> float | None:
        """DI [m] (Eq. 36): abs(slope) of the least-squares line through the first four positive
        maxima of x against t' = t·√(K/M); None with fewer than four maxima."""
        return damping_inclination(self.peaks, self.system.omega_n)

    @property
    def zeta_eq(self) -> float | None:
        """Equivalent viscous damping ratio [1] of the envelope of x (see
        :func:`equivalent_damping_ratio`); None with fewer than two envelope maxima."""
        return equivalent_damping_ratio(self.peaks, self.system.omega_n)

    def as_dict(self, with_history: bool = False) -> dict[str, Any]:
        """JSON-ready summary (the ``simulate --json`` contract)."""
        out: dict[str, Any] = {
            "n_impacts": self.n_impacts,
            "n_effective": self.n_effective,
            "effectiveness": self.effectiveness,
            "damping_inclination": self.damping_inclination,
            "zeta_eq": self.zeta_eq,
            "impacts": [i.as_dict() for i in self.impacts],
            "energy_residual": self.energy["residual"],
            "energy": self.energy,
            "peaks": [[float(t), float(x)] for t, x in self.peaks],
            "contact": self.contact,
            "t_end": self.t_end,
            "t_rest": self.t_rest,
            "initial_state": dict(
                zip(("x0", "xdot0", "y0", "ydot0"), self.initial_state, strict=True)
            ),
            "system": self.system.as_dict(),
            "notes": self.notes,
        }
        if with_history and self.history is not None:
            out["history"] = {k: v.tolist() for k, v in self.history.items()}
        return out


#: Impact-time accuracy [s] for each contact-integration rtol: the worst error of the first ten
#: impact times on the two benchmark systems (Table 2 masses, d = 9 mm, K = 100 N/m and N/cm) and
#: 40 seeded random systems, against the same runs at rtol = 1e-14.  Measured by, and held to
#: within a factor of 4 by, tests/test_simulation.py::test_impact_time_accuracy_of_each_rtol.
IMPACT_TIME_ACCURACY = {
    1e-12: 4.4e-12,
    1e-10: 1.6e-10,
    1e-8: 1.6e-8,
    1e-6: 2.2e-6,
    1e-4: 1.1e-4,
    1e-3: 2.2e-3,
}

#: Defaults of :func:`simulate` (contact rtol, the impact limit, the rest fraction), which the
#: compiled map loop uses too.
RTOL, MAX_IMPACTS, REST = 1e-12, 100_000, 1e-12

#: Longest run, in natural periods 2π/ω_n of the main mass (the free-flight search takes about 16
#: steps per period, so 1e7 periods cost seconds even without an impact).
MAX_PERIODS = 1e7


def effectiveness(n_total: int, n_effective: int) -> float | None:
    """Effectiveness N_eff/(N_tot − N_eff) of Eq. 38; None where the ratio is undefined."""
    if n_total - n_effective <= 0:
        return None
    return n_effective / (n_total - n_effective)


def damping_inclination(peaks: np.ndarray, omega_n: float, count: int = 4) -> float | None:
    """Damping inclination DI of Eq. 36 [m].

    abs(slope) of the least-squares line through the first ``count`` positive maxima (t_k, X_k) of
    x, with the dimensionless time t' = t·ω_n (ω_n = √(K/M)).  With two maxima this is
    (X₁ − X₂)/(t'₂ − t'₁), the printed Eq. 36.  None with fewer than ``count`` maxima.
    """
    from . import _batch

    peaks = np.ascontiguousarray(peaks, dtype=float).reshape(-1, 2)
    if not (isinstance(count, int) and count >= 2):
        raise ParameterError("count", "must be an integer ≥ 2")
    di = _batch.damping_inclination_of(peaks, peaks.shape[0], float(omega_n), count)
    return None if math.isnan(di) else float(di)


def equivalent_damping_ratio(peaks: np.ndarray, omega_n: float) -> float | None:
    """Equivalent viscous damping ratio ζ_eq [1] from the decay of the envelope of x.

    Not in the paper (a design figure beside DI, Eq. 36).  The upper envelope is made of the
    positive maxima (t_k, X_k) that exceed every later maximum; ζ_eq = −s/ω_n, where s is the
    least-squares slope of ln X_k against t_k.  For a linear oscillator
    x = A·e^(−ζω_n t)·sin(ω_d t + φ) every maximum lies on the envelope, the successive
    maxima are one damped period apart and ζ_eq = ζ exactly; for an impact damper it is the
    viscous ratio with the same average logarithmic decay.  None with fewer than two envelope
    maxima.
    """
    from . import _batch

    peaks = np.ascontiguousarray(peaks, dtype=float).reshape(-1, 2)
    zeta = _batch.zeta_eq_of(peaks, peaks.shape[0], float(omega_n))
    return None if math.isnan(zeta) else float(zeta)


def simulate(
    system: ImpactSystem,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    t_end: Any = 1.0,
    contact: str | None = None,
    *,
    ba: Any = "impact",
    history: bool = False,
    samples: int = 2000,
    rtol: float = RTOL,
    max_impacts: int = MAX_IMPACTS,
    rest: float = REST,
) -> SimulationResult:
    """Free vibration of the main mass with the impact damper (Eq. 7 between impacts, Eq. 10
    during contact), from the state (x0, xdot0, y0, ydot0) at t = 0 to ``t_end``.

    Parameters
    ----------
    system : the :class:`~symimpact.model.system.ImpactSystem`.
    x0, y0 : initial displacements [m]; xdot0, ydot0 : initial velocities [m/s]; abs(y0 − x0) must
        not exceed d/2.  t_end : end time [s].
    contact : ``"cubic"``, ``"hertz"``, ``"linear"`` (the force law integrated numerically,
        default: the system's law) or ``"perturbation"`` (the cubic law by Eq. 31–33: the contact
        duration and penetration with B/A chosen by ``ba``, see
        :func:`symimpact.free.contact.amplitude_ratio`; the penetration shared between the masses
        without momentum, Eq. 33 with B/A = −M/m, about a centre of mass that moves on the main
        spring and damper, so that no contact adds energy).
    history : also return x, ẋ, y, ẏ on ``samples`` evenly spaced times (closed form in free
        flight, cubic Hermite between integrator steps during contact).
    rtol : relative tolerance of the contact integration, 1e-14 to 1e-3 (absolute tolerances
        scale with the gap and the initial speeds).  Impact-time accuracy, measured on the two
        benchmark systems and 40 random ones (first ten impacts against rtol = 1e-14, see
        ``IMPACT_TIME_ACCURACY``): worst error {accuracy}.  A coarser rtol gives coarser impact
        times, never an error.
    max_impacts : the run stops with an error past this many contacts (chattering); the impact
        log itself has no fixed size.
    rest : the motion counts as at rest, and the run stops, once the mechanical energy of the two
        masses is below ``rest`` × its initial value, at a contact onset or during free flight
        (default 1e-12: velocities about 1e-6 of the initial ones).  Below that the approach
        speeds sink toward the integration's resolution, and neither this stepper nor
        ``solve_ivp`` can place the impacts (their counts and times part ways); 0 disables the
        stop.

    Returns
    -------
    SimulationResult with the impact log, N_tot, N_eff, effectiveness (Eq. 38), DI (Eq. 36) and
    the energy balance: initial = final + dissipated by C + dissipated by c₁ + residual.
    """
    from .. import _interrupt
    from . import _batch, _stepper

    if not isinstance(system, ImpactSystem):
        raise ParameterError("system", "must be an ImpactSystem")
    contact = contact or system.contact
    if contact not in _stepper.LAWS:
        raise ParameterError("contact", f"must be one of {', '.join(CONTACT_PATHS)}")
    law = _stepper.LAWS[contact]
    x0, xdot0, y0, ydot0 = (
        si_float(n, v) for n, v in (("x0", x0), ("xdot0", xdot0), ("y0", y0), ("ydot0", ydot0))
    )
    t_end = positive_float("t_end", t_end)
    periods = t_end * system.omega_n / (2 * math.pi)
    if periods > MAX_PERIODS:
        raise ParameterError(
            "t_end",
            f"{t_end:g} s is {periods:.3g} natural periods of the main mass "
            f"(2π/ω_n = {2 * math.pi / system.omega_n:.3g} s); at most {MAX_PERIODS:g} are simulated",
        )
    if not (isinstance(samples, int) and samples >= 2):
        raise ParameterError("samples", "must be an integer ≥ 2")
    if not (isinstance(rtol, (int, float)) and 1e-14 <= rtol <= 1e-3):
        raise ParameterError("rtol", "must be a number in [1e-14, 1e-3]")
    if not (isinstance(max_impacts, int) and max_impacts >= 1):
        raise ParameterError("max_impacts", "must be an integer ≥ 1")
    if not (isinstance(rest, (int, float)) and 0.0 <= rest < 1.0):  # (NaN fails too)
        raise ParameterError("rest", "must be a number in [0, 1)")
    h = 0.5 * system.gap
    if abs(y0 - x0) > h * (1 + 1e-12):
        raise ParameterError(
            "y0", f"|y0 − x0| = {abs(y0 - x0):g} m exceeds half the clearance d/2 = {h:g} m"
        )
    if law == _stepper.HERTZ and system.k_hz is None:
        raise ParameterError("k_hz", "the Hertz contact law needs k_hz")
    if law == _stepper.LINEAR and system.k1 is None:
        raise ParameterError("k1", "the linear contact law needs k1 (or k_hz to fit it)")
    if law in (_stepper.CUBIC, _stepper.PERTURBATION) and (system.a is None or system.b is None):
        raise ParameterError("a", "the cubic contact law needs a and b (or k_hz to fit them)")
    ba_value = 0.0
    notes: list[str] = []
    if law == _stepper.PERTURBATION:
        from .contact import amplitude_ratio

        ba_value = float(amplitude_ratio(system, ba=ba))
        notes.append(
            f"contact by the perturbation solution (Eq. 31–33) with B/A = {ba_value:.6g} "
            f"({ba if isinstance(ba, str) else 'given'}) for the duration and the penetration; "
            "the masses share the penetration so that it carries no momentum (Eq. 33 with "
            "B/A = −M/m) while their centre of mass moves on the main spring and damper"
        )

    p = _stepper.pack(system, rtol, 0.0, 0.0, ba=ba_value)
    e_initial = _batch.prepare(p, x0, xdot0, y0, ydot0, rtol, rest)

    state0 = np.array([x0, xdot0, y0, ydot0])
    # the buffers grow inside the stepper as they fill; these are only first sizes
    status, n_imp, n_pk, n_tr, u, diss_C, diss_c1, side, t_stop, impacts, peaks, trace = (
        _interrupt.call(
            _stepper.run,
            law,
            p,
            state0,
            t_end,
            np.zeros((64, _stepper.N_IMPACT_COLS)),
            np.zeros((256, 2)),
            np.zeros((4096 if history else 1, _stepper.N_TRACE_COLS)),
            history,
            max_impacts,
        )
    )
    if status == _stepper.FULL_IMPACTS:
        raise SymimpactError(
            f"max_impacts: more than {max_impacts} impacts before t_end = {t_end:g} s "
            "(chattering?); shorten t_end or raise max_impacts"
        )
    if status in (_stepper.STEP_UNDERFLOW, _stepper.TOO_MANY_STEPS):
        raise SymimpactError(f"contact integration: {_stepper.STATUS_TEXT[status]}")
    if status == _stepper.NO_CONVERGENCE:
        row = impacts[n_imp - 1]
        v = abs(row[_stepper.I_YD] - row[_stepper.I_XD])
        raise MethodNotApplicable(
            "perturbation",
            f"Eq. 31 has no converging fixed point for the contact at t = {row[_stepper.I_T]:.6g} s "
            f"(approach speed {v:.4g} m/s, B/A = {ba_value:.6g}): the cubic term "
            "3a·Ż₀²·(T/π)²/4 is not a small correction to b there, which the two-variable "
            "expansion (Eq. 21–33) assumes; use contact='cubic', which integrates the same law",
        )
    log = []
    for row in impacts[:n_imp].tolist():  # Python floats: the same values, cheaper arithmetic
        done = row[_stepper.I_DONE] > 0
        s = row[_stepper.I_SIDE]
        approach = s * (row[_stepper.I_YD] - row[_stepper.I_XD])
        exit_speed = s * (row[_stepper.I_YDOFF] - row[_stepper.I_XDOFF])
        log.append(
            Impact(
                t=float(row[_stepper.I_T]),
                x=float(row[_stepper.I_X]),
                xdot=float(row[_stepper.I_XD]),
                y=float(row[_stepper.I_Y]),
                ydot=float(row[_stepper.I_YD]),
                side=int(s),
                effective=bool(row[_stepper.I_XD] * row[_stepper.I_YD] < 0),
                duration=float(row[_stepper.I_TOFF] - row[_stepper.I_T]) if done else None,
                restitution=float(-exit_speed / approach) if done and approach > 0 else None,
                energy_lost=float(row[_stepper.I_EON] - row[_stepper.I_EOFF]) if done else None,
                contact_dissipation=float(row[_stepper.I_DC1]) if done else None,
            )
        )
    if log and log[-1].duration is None:
        notes.append("the simulation ended during the last contact")
    t_rest = None
    if status == _stepper.AT_REST:
        t_rest = float(t_stop)
        notes.append(
            f"at rest from t = {t_rest:.6g} s: the energy of the two masses fell below {rest:g} "
            "of its initial value (see rest=), where impacts are no longer resolvable; the state "
            "is held from then on"
        )
    e_final, residual = _batch.ledger(law, p, u, side, e_initial, diss_C, diss_c1)
    energy: dict[str, float | None] = {
        "initial": e_initial,
        "final": float(e_final),
        "dissipated_C": float(diss_C),
        "dissipated_c1": float(diss_c1),
        "residual": float(residual),
        "relative_residual": float(residual / e_initial) if e_initial > 0 else 0.0,
    }
    hist = _history(system, p, trace[:n_tr], t_end, samples, u) if history else None
    if peaks[:n_pk].shape[0] < 4:
        notes.append(f"only {n_pk} positive maxima of x: the damping inclination needs four")
    return SimulationResult(
        system=system,
        contact=contact,
        initial_state=(x0, xdot0, y0, ydot0),
        t_end=t_end,
        impacts=log,
        peaks=peaks[:n_pk].copy(),
        energy=energy,
        history=hist,
        notes=notes,
        t_rest=t_rest,
    )


simulate.__doc__ = simulate.__doc__.format(
    accuracy=", ".join(f"{r:.0e} → {e:.1e} s" for r, e in IMPACT_TIME_ACCURACY.items())
)


def _history(system, p, trace, t_end, samples, u_end):
    """x, ẋ, y, ẏ on an even grid from the stepper's trace rows."""
    from ..generated import free_flight as ff

    t = np.linspace(0.0, t_end, samples)
    out = np.empty((4, samples))
    starts = trace[:, 0]
    idx = np.searchsorted(starts, t, side="right") - 1
    idx = np.clip(idx, 0, len(trace) - 1)
    for j in np.unique(idx):
        sel = idx == j
        row = trace[j]
        tau = t[sel] - row[0]
        nxt = trace[j + 1] if j + 1 < len(trace) else None
        if row[7] == 0.0:  # free flight from this row, closed form (Eq. 7)
            args = (system.M, system.K, system.C, row[1], row[2])
            out[0, sel] = ff.main_mass_displacement(tau, *args)
            out[1, sel] = ff.main_mass_velocity(tau, *args)
            out[2, sel] = ff.impact_mass_displacement(tau, row[3], row[4])
            out[3, sel] = ff.impact_mass_velocity(tau, row[4])
        elif nxt is not None and nxt[7] == 1.0:  # between two contact steps: cubic Hermite
            hstep = nxt[0] - row[0]
            s = tau / hstep
            h00, h10 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s
            h01, h11 = -2 * s**3 + 3 * s**2, s**3 - s**2
            for k, (pos, vel, acc) in enumerate(((1, 2, 5), (3, 4, 6))):
                out[2 * k, sel] = (
                    h00 * row[pos]
                    + h10 * hstep * row[vel]
                    + h01 * nxt[pos]
                    + h11 * hstep * nxt[vel]
                )
                out[2 * k + 1, sel] = (
                    h00 * row[vel]
                    + h10 * hstep * row[acc]
                    + h01 * nxt[vel]
                    + h11 * hstep * nxt[acc]
                )
        else:  # last contact point at the end of the run
            out[:, sel] = np.asarray(row[1:5])[:, None]
    return {"t": t, "x": out[0], "xdot": out[1], "y": out[2], "ydot": out[3]}
