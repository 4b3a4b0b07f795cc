"""The frequency-response curve by harmonic balance beside the exact one (issue 83, item 2).

:func:`hb_frequency_response` draws the balance's curve (:mod:`.harmonic_balance`: H harmonics,
AFT with N samples, Hill's stability) over the band of an exact curve
(:func:`symimpact.forced.orbits.frf.frequency_response`) and in its schema: each exact branch
seeds it, its orbits' samples transformed into coefficients and balanced at their Ω, and every
balanced orbit that no branch of the balance holds yet is followed both ways in Ω by
pseudo-arclength until it leaves the band or its corrector fails.  The balance's curve is thus
found where the exact one is; a branch the balance has and the exact curve lacks is found only
where it is joined to one they share (a fold connects them), which :func:`compare` reports.

:func:`compare` sets the two side by side, per exact branch: the balance's error in amplitude at
the exact orbits (the balance from each exact orbit's own coefficients: the nearest balanced
orbit), the harmonics it needs for 1 % and 0.1 % (the ladder :data:`LADDER`, at the branch's
ends and its largest orbit), the frequencies where Hill's stability and shooting's disagree and
where the balance finds no orbit near the exact one; and over the balance's curve, its stable
stretches with no exact orbit near, each checked by shooting from the balance's own state (an
orbit of the compliant engine that exists, missing from the exact curve, or a motion the
balance predicts that shooting does not find).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..._threads import on_one_blas_thread
from ...errors import MethodNotApplicable, ParameterError
from ...model.system import ImpactSystem
from ..contact_law import CompliantContact
from ..forcing import Forcing
from .continuation import Bifurcation, Branch, BranchPoint
from .frf import FrequencyResponse
from .harmonic_balance import (
    Basis,
    HBOrbit,
    _amplitude,
    _checked,
    _orbit,
    _problem,
    arc,
    coefficients_of,
    hb_orbit,
    newton,
    with_stability,
)
from .peak import Peak

#: The harmonics at which :func:`compare` measures the balance's error to find the fewest that
#: reach each of :data:`LEVELS` (N = 4H samples each).
LADDER = (1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128)
LEVELS = (0.01, 0.001)
#: Two balanced orbits at one Ω are one where their coefficients differ by less than this share
#: of the clearance's half (Newton's tolerance is 1e-10 of it; a contact's samples switching
#: between iterates leave some 1e-11).
SAME = 1e-7
#: A balanced orbit is tried against a branch's orbits lying within this scaled distance of it
#: (the arc's longest step is 0.05 in the unknowns U/(d/2), Ω/Ω₀).
NEAR = 0.1
#: A balanced orbit lies on a branch where it is this close (scaled unknowns) to the polyline
#: through the branch's orbits: the arc's chords, of 0.05 at most, stray from the curve by
#: ds²κ/8, some 3e-4 times its curvature; and where c₁δ̇ switches on with a step the balance's
#: residual is discontinuous, its Newton landing on neighbouring near-solutions (on the README's
#: primary with the default linear contact, two traces of one branch 30.8–31.4 rad/s were
#: 1e-3 apart).  Newton from the nearest orbit decides beyond.
CHORD = 1e-2
#: The most exact orbits of one branch :func:`compare` balances (evenly spread beyond).
COMPARED = 60
#: A stable balanced orbit has an exact one near where an exact orbit of its period lies within
#: this share of the band's step in Ω and this share of its amplitude (the balance's own error
#: at the user's H is reported separately, per branch).
AMPLITUDE_NEAR = 0.05


def _balanced(system, forcing, contact, point: BranchPoint, k: int, H: int, N: int):
    """(problem, U) of the balance (forcing phase 0 at θ = 0) nearest the exact orbit ``point``
    of k periods: Newton from its own samples' coefficients, no stability yet; None where Newton
    fails."""
    U = coefficients_of(system, forcing.at(point.omega, point.phase), contact, point.state, H, k,
                        phase=0.0)  # fmt: skip
    problem = _problem(system, forcing.at(point.omega, 0.0), contact, H, N, k)
    try:
        U, _, _ = newton(problem, U, point.omega / k, 0.5 * system.gap)
    except MethodNotApplicable:
        return None
    return problem, U


def _seeded(system, forcing, contact, point: BranchPoint, k: int, H: int, N: int):
    """:func:`_balanced`'s orbit with its Hill stability, or None."""
    found = _balanced(system, forcing, contact, point, k, H, N)
    return None if found is None else _orbit(found[0], found[1], point.omega, k, 0)


def _on(omega: float, k: int, U: np.ndarray, curves: list[list[HBOrbit]], system, forcing,
        contact) -> bool:  # fmt: skip
    """Whether the balanced orbit U of k periods at ``omega`` is one of the balanced branches
    ``curves``: the nearest of their orbits of its period, balanced again at ``omega``, lands on
    it."""
    s = 0.5 * system.gap
    U = U / s
    for curve in curves:
        if curve[0].subharmonic != k:
            continue
        Y = np.array([o.x + o.y for o in curve]) / s
        dist = np.linalg.norm(Y - U, axis=1) + np.abs([o.omega / omega - 1 for o in curve])
        i = int(np.argmin(dist))
        if dist[i] > NEAR:
            continue
        if _chord_distance(Y, [o.omega / omega for o in curve], U) < CHORD:
            return True
        near = curve[i]
        problem = _problem(system, forcing.at(omega, 0.0), contact, near.harmonics,
                           near.samples, k)  # fmt: skip
        try:
            again, _, _ = newton(problem, np.array(near.x + near.y), omega / k, s)
        except MethodNotApplicable:
            continue
        if np.max(np.abs(again / s - U)) < SAME * 1e3:
            return True
    return False


def _retraced(orbits: list[HBOrbit], curves: list[list[HBOrbit]], gap: float) -> int | None:
    """The curve of ``curves`` that at least half of ``orbits`` lie on (within :data:`CHORD` of
    its polyline, the same period), or None."""
    s = 0.5 * gap
    for i, curve in enumerate(curves):
        if curve[0].subharmonic != orbits[0].subharmonic or len(curve) < 2:
            continue
        Y = np.array([o.x + o.y for o in curve]) / s
        on = sum(_chord_distance(Y, [c.omega / o.omega for c in curve], np.array(o.x + o.y) / s)
                 < CHORD for o in orbits)  # fmt: skip
        if 2 * on >= len(orbits):
            return i
    return None


def _chord_distance(Y: np.ndarray, w: list[float], U: np.ndarray) -> float:
    """The distance in the scaled unknowns (U/(d/2), Ω/Ω_U) from (U, 1) to the polyline through
    the curve's orbits (Y, w)."""
    P = np.column_stack([Y, w])
    q = np.concatenate([U, [1.0]])
    a, b = P[:-1], P[1:]
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", q - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab),
                                                                 1e-300), 0.0, 1.0)  # fmt: skip
    if len(P) == 1:
        return float(np.linalg.norm(P[0] - q))
    return float(np.min(np.linalg.norm(a + t[:, None] * ab - q, axis=1)))


def _contacts_per_period(orbit: HBOrbit, gap: float) -> float:
    """Contact phases a forcing period: the onsets of δ > 0 on either wall among the balance's
    own N samples of the orbit's period, divided by its period multiple."""
    b = Basis.of(orbit.harmonics, orbit.samples)
    z = b.E @ (np.array(orbit.y) - np.array(orbit.x))
    on = np.abs(z) > 0.5 * gap
    onsets = int(np.sum(on & ~np.roll(on, 1)))
    return onsets / orbit.subharmonic


def _point(orbit: HBOrbit, gap: float) -> BranchPoint:
    T = 2.0 * math.pi * orbit.subharmonic / orbit.omega
    mult = tuple(complex(np.exp(x * T)) for x in orbit.exponents)
    n = _contacts_per_period(orbit, gap)
    return BranchPoint(omega=orbit.omega, state=orbit.state(0.0), amplitude=orbit.amplitude,
                       impacts_per_period=n, multipliers=mult, stable=orbit.stable,
                       value=orbit.omega, phase=0.0, impact_events_per_period=n)  # fmt: skip


def _stability_changes(points: list[BranchPoint], folds: tuple[float, ...], step: float):
    """Where Hill's stability changes between neighbours away from a fold, the kind read from
    the multiplier that leaves the unit circle (real +1: branch point, −1: period doubling,
    complex: Neimark–Sacker), at the midpoint (to within the arc's step)."""
    out = []
    for a, b in itertools.pairwise(points):
        if a.stable == b.stable:
            continue
        w = 0.5 * (a.omega + b.omega)
        if any(abs(w - f) <= max(step, abs(b.omega - a.omega)) for f in folds):
            continue  # the fold's own exchange of stability
        outside = (b if a.stable else a).multipliers
        lam = max(outside, key=abs)
        angle = abs(math.atan2(lam.imag, lam.real))
        kind = ("branch-point" if angle < 0.1 else "period-doubling" if angle > math.pi - 0.1
                else "neimark-sacker")  # fmt: skip
        out.append(Bifurcation(kind, w, 0.5 * (a.amplitude + b.amplitude), w))
    return out


def _branch(orbits: list[HBOrbit], folds, ended: str, origin: str, system, step) -> Branch:
    points = [_point(o, system.gap) for o in orbits]
    bif = []
    for f in folds:
        i = int(np.argmin([abs(p.omega - f) for p in points]))
        bif.append(Bifurcation("fold", f, points[i].amplitude, f))
    bif += _stability_changes(points, folds, step)
    bif.sort(key=lambda x: x.omega)
    return Branch(points=points, bifurcations=bif, period_multiple=orbits[0].subharmonic,
                  stopped=ended, phase=0.0, origin=origin, origin_omega=orbits[0].omega)  # fmt: skip


def _peak(branches: list[Branch]) -> Peak | None:
    """The largest stable balanced orbit (a point of the arc: the balance's curve is read to its
    arc step, 0.05 of d/2 at most)."""
    best = None
    for i, b in enumerate(branches):
        for p in b.points:
            if p.stable and (best is None or p.amplitude > best[1].amplitude):
                best = (i, p)
    if best is None:
        return None
    i, p = best
    return Peak(p.amplitude, p.omega, "periodic", "point", i, branches[i].period_multiple,
                p.impacts_per_period, p.impact_events_per_period)  # fmt: skip


@on_one_blas_thread
def hb_frequency_response(system: ImpactSystem, forcing: Forcing, contact: CompliantContact,
                          exact: FrequencyResponse, harmonics: Any = 15,
                          time_samples: Any = None) -> FrequencyResponse:  # fmt: skip
    """The curve by harmonic balance (H = ``harmonics``, N = ``time_samples``, default 4H) over
    the band of ``exact`` and as far as its branches reach past it (module text), in :class:`FrequencyResponse`'s schema: its branches
    (each orbit's ``impacts_per_period`` the contact phases a period among the balance's
    samples), folds and Hill's changes of stability, the largest stable orbit as its peak; the
    primary without the damper, the motion without impacts and the brute-force sweeps are the
    exact curve's (they do not depend on the method)."""
    H, N, _ = _checked(system, forcing, contact, harmonics, time_samples, 1)
    if not isinstance(exact, FrequencyResponse):
        raise ParameterError("exact", "must be a FrequencyResponse (frequency_response)")
    drawn = [p.omega for b in exact.branches for p in b.points]  # a branch may end past the band
    lo, hi = min([float(exact.omegas[0]), *drawn]), max([float(exact.omegas[-1]), *drawn])
    step = float(np.max(np.diff(exact.omegas)))
    curves: list[list[HBOrbit]] = []
    branches, notes = [], []

    def grow(orbit: HBOrbit, origin: str) -> None:
        # Hill's stability only once the arc is kept (a retraced arc's eigenvalues were a
        # third of benchmark 17's)
        down = arc(system, forcing.at(orbit.omega, 0.0), contact, orbit, (lo, hi), -1,
                   stability=False)  # fmt: skip
        up = arc(system, forcing.at(orbit.omega, 0.0), contact, orbit, (lo, hi), +1,
                 stability=False)  # fmt: skip
        orbits = list(reversed(down.orbits)) + list(up.orbits[1:])
        traced = _retraced(orbits, curves, system.gap)
        curves.append(orbits)
        if traced is not None:  # a second trace of a branch from one of its near-solutions
            return
        problem = _problem(system, forcing.at(orbit.omega, 0.0), contact, orbit.harmonics,
                           orbit.samples, orbit.subharmonic)  # fmt: skip
        orbits = [o if o.multipliers else with_stability(problem, o) for o in orbits]
        if len(orbits) < 2:
            notes.append(f"the balanced orbit at Ω = {orbit.omega:.6g} rad/s ({origin}) could "
                         "not be continued either way")  # fmt: skip
            return
        ended = "; ".join(dict.fromkeys([down.ended, up.ended]))
        folds = sorted(f for f in down.folds + up.folds if lo <= f <= hi)
        branches.append(_branch(orbits, folds, ended, origin, system, step))

    for i, b in enumerate(exact.branches):
        k = b.period_multiple
        if k > H:
            notes.append(f"branch {i} ({k} periods) needs H ≥ {k}: not balanced")
            continue
        for p in b.points:
            if any(_close(p, c) for c in curves if c[0].subharmonic == k):
                continue
            found = _balanced(system, forcing, contact, p, k, H, N)
            if found is None or _on(p.omega, k, found[1], curves, system, forcing, contact):
                continue
            grow(_orbit(found[0], found[1], p.omega, k, 0),
                 f"exact branch {i} at Ω = {p.omega:.6g} rad/s")  # fmt: skip
    if not exact.branches:
        try:
            grow(hb_orbit(system, forcing.at(lo), contact, H, N, 1), "run from rest")
        except MethodNotApplicable as err:
            notes.append(f"no balanced orbit from rest at the band's start: {err}")
    out = FrequencyResponse(
        omegas=exact.omegas, branches=branches, baseline=exact.baseline,
        sweep_up=exact.sweep_up, sweep_down=exact.sweep_down, notes=notes,
        no_impact=list(exact.no_impact), no_impact_grazings=list(exact.no_impact_grazings),
        peak=_peak(branches), baseline_peak=exact.baseline_peak,
    )  # fmt: skip
    return out


def _close(point: BranchPoint, curve: list[HBOrbit]) -> bool:
    """A balanced orbit of ``curve`` lies within 0.1 % in Ω and 1e-3 of the amplitude of the
    exact orbit ``point``: its seed would land on that branch (checked by :func:`_on` where not)."""
    for o in curve:
        if abs(o.omega / point.omega - 1) < 1e-3 and abs(o.amplitude / point.amplitude - 1) < 1e-3:
            return True
    return False


@dataclass(frozen=True)
class BranchComparison:
    """The balance beside one exact branch (SI): ``hb_error``, the largest relative error in
    amplitude (A_HB − A)/A in modulus over the exact orbits the balance found an orbit near, at
    ``worst_omega`` [rad/s]; ``harmonics_for``: the fewest harmonics of :data:`LADDER` at which the
    error falls below each level of :data:`LEVELS` at the branch's ends and its largest orbit (None: not within the ladder); ``stability_disagreements`` [rad/s]: where Hill's
    verdict differs from shooting's; ``missed`` [rad/s]: exact orbits near which the balance
    finds none; ``compared``: how many exact orbits were balanced."""

    branch: int
    period_multiple: int
    compared: int
    hb_error: float | None
    worst_omega: float | None
    harmonics_for: dict[str, int | None]
    stability_disagreements: tuple[float, ...]
    missed: tuple[float, ...]

    def as_dict(self) -> dict[str, Any]:
        return {
            "branch": self.branch, "period_multiple": self.period_multiple,
            "compared": self.compared, "hb_error": self.hb_error,
            "worst_omega": self.worst_omega, "harmonics_for": dict(self.harmonics_for),
            "stability_disagreements": list(self.stability_disagreements),
            "missed": list(self.missed),
        }  # fmt: skip


@dataclass(frozen=True)
class Unmatched:
    """A stretch of the balance's stable orbits with no exact orbit near (SI): its branch and Ω
    bounds [rad/s], and what shooting from the balance's state at its middle found: "exists"
    (an orbit within :data:`AMPLITUDE_NEAR` of its amplitude, stable: missing from the exact
    curve), "unstable" (there, but unstable) or "not found" (shooting fails or lands far:
    a motion the balance predicts that the exact model does not have there)."""

    branch: int
    omega_from: float
    omega_to: float
    amplitude: float
    shooting: str
    shooting_amplitude: float | None

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


@dataclass(frozen=True)
class Comparison:
    """:func:`compare`'s outcome: ``branches`` (one :class:`BranchComparison` per exact branch)
    and ``unmatched`` (:class:`Unmatched`), with the balance's H and N."""

    harmonics: int
    time_samples: int
    branches: tuple[BranchComparison, ...] = field(default_factory=tuple)
    unmatched: tuple[Unmatched, ...] = field(default_factory=tuple)

    def as_dict(self) -> dict[str, Any]:
        return {
            "harmonics": self.harmonics, "time_samples": self.time_samples,
            "branches": [b.as_dict() for b in self.branches],
            "unmatched": [u.as_dict() for u in self.unmatched],
        }  # fmt: skip


def _spread(points: list[BranchPoint], most: int) -> list[BranchPoint]:
    if len(points) <= most:
        return list(points)
    return [points[round(i)] for i in np.linspace(0, len(points) - 1, most)]


def _error_at(system, forcing, contact, p: BranchPoint, k: int, H: int) -> float | None:
    """The balance's relative amplitude error at the exact orbit ``p`` with H harmonics (its
    stability not computed: the ladder needs only the amplitude); None where Newton fails."""
    found = _balanced(system, forcing, contact, p, k, H, 4 * H)
    if found is None:
        return None
    problem, U = found
    return abs(_amplitude(problem.basis, U[: 2 * H + 1]) / p.amplitude - 1.0)


def _harmonics_for(system, forcing, contact, b: Branch) -> dict[str, int | None]:
    """The fewest harmonics of :data:`LADDER` (≥ the period multiple) at which the largest error
    at the branch's ends and largest orbit falls below each level of :data:`LEVELS` (the ladder
    climbed until the smallest level is reached); None where it is not within the ladder."""
    k = b.period_multiple
    pts = [b.points[0], b.points[-1], max(b.points, key=lambda p: p.amplitude)]
    out: dict[str, int | None] = {f"{level:g}": None for level in LEVELS}
    for H in (h for h in LADDER if h >= k):
        e = [_error_at(system, forcing, contact, p, k, H) for p in pts]
        err = math.inf if any(x is None for x in e) else max(e)
        for level in LEVELS:
            if out[f"{level:g}"] is None and err < level:
                out[f"{level:g}"] = H
        if err < min(LEVELS):
            break
    return out


@on_one_blas_thread
def compare(system: ImpactSystem, forcing: Forcing, contact: CompliantContact,
            exact: FrequencyResponse, hb: FrequencyResponse, harmonics: Any = 15,
            time_samples: Any = None, ladder: bool = True) -> Comparison:  # fmt: skip
    """The balance (H = ``harmonics``, N = ``time_samples``) beside the exact curve ``exact``,
    ``hb`` its balanced curve (:func:`hb_frequency_response`): module text.  ``ladder`` False
    skips the harmonics needed (the costliest part: up to H = 128)."""
    H, N, _ = _checked(system, forcing, contact, harmonics, time_samples, 1)
    rows = []
    for i, b in enumerate(exact.branches):
        k = b.period_multiple
        worst, at, disagree, missed = None, None, [], []
        compared = _spread(b.points, COMPARED) if k <= H else []
        for p in compared:
            orbit = _seeded(system, forcing, contact, p, k, H, N)
            if orbit is None:
                missed.append(p.omega)
                continue
            err = abs(orbit.amplitude / p.amplitude - 1.0)
            if worst is None or err > worst:
                worst, at = err, p.omega
            if orbit.stable != p.stable:
                disagree.append(p.omega)
        need = _harmonics_for(system, forcing, contact, b) if ladder and compared else {
            f"{level:g}": None for level in LEVELS}  # fmt: skip
        rows.append(BranchComparison(i, k, len(compared), worst, at, need, tuple(disagree),
                                     tuple(missed)))  # fmt: skip
    return Comparison(H, N, tuple(rows), tuple(_unmatched(system, forcing, contact, exact, hb)))


def _near_exact(p: BranchPoint, k: int, exact: FrequencyResponse, step: float) -> bool:
    """Whether an exact branch of k periods passes within :data:`AMPLITUDE_NEAR` of the
    amplitude of ``p`` at its Ω: between two of its orbits that bracket Ω (the amplitude
    interpolated; a continuation's steps are longer than the band's where the curve is
    straight), or at one within the band's step of it."""
    for b in exact.branches:
        if b.period_multiple != k:
            continue
        for q in b.points:
            if (
                abs(q.omega - p.omega) <= step
                and abs(q.amplitude / p.amplitude - 1) <= AMPLITUDE_NEAR
            ):
                return True
        for q, r in itertools.pairwise(b.points):
            if min(q.omega, r.omega) <= p.omega <= max(q.omega, r.omega) and q.omega != r.omega:
                a = q.amplitude + (r.amplitude - q.amplitude) * (p.omega - q.omega) / (
                    r.omega - q.omega
                )
                if abs(a / p.amplitude - 1) <= AMPLITUDE_NEAR:
                    return True
    return False


def _unmatched(system, forcing, contact, exact, hb) -> list[Unmatched]:
    """The balance's stable stretches with no exact orbit of their period near
    (:func:`_near_exact`), each checked by shooting from the balance's state at its middle."""
    from .shooting import shoot

    step = float(np.max(np.diff(exact.omegas)))
    out = []
    for i, b in enumerate(hb.branches):
        k = b.period_multiple
        alone = [p.stable and not _near_exact(p, k, exact, step) for p in b.points]
        j = 0
        while j < len(alone):
            if not alone[j]:
                j += 1
                continue
            start = j
            while j < len(alone) and alone[j]:
                j += 1
            run = b.points[start:j]
            mid = run[len(run) // 2]
            try:
                found = shoot(system, forcing.at(mid.omega, 0.0), contact, mid.state, periods=k)
                near = abs(found.amplitude / mid.amplitude - 1) <= AMPLITUDE_NEAR
                verdict = ("exists" if found.stable else "unstable") if near else "not found"
                amp = found.amplitude
            except MethodNotApplicable:
                verdict, amp = "not found", None
            out.append(Unmatched(i, min(p.omega for p in run), max(p.omega for p in run),
                                 max(p.amplitude for p in run), verdict, amp))  # fmt: skip
    return out
