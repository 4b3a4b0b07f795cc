"""The frequency-response curve of the primary with an impact damper — rigid impacts of
restitution e, or a compliant contact (a :class:`~symimpact.forced.CompliantContact` in place of
e): :func:`frequency_response`.

Branches of periodic orbits are continued in Ω (:func:`symimpact.forced.continue_orbit`) from
several kinds of starting point, so that coexisting motions are found:

- the closed-form symmetric two-impact orbits (Eq. F3) that are admissible, at frequencies spread
  over the band (rigid impacts only);
- the orbits brute-force runs from rest settle near (:func:`symimpact.forced.settled_state`),
  of one and two forcing periods;
- the periodic attractors of a multi-start brute force at frequencies fixed by the band's ends
  (:mod:`symimpact.forced.orbits.coverage`), which also measures the share of them the branches trace;
- branch switching at every located branch point and period doubling;
- jumps: where a branch ends on a stable orbit inside the band, or loses its stability at a
  fold, branch point, period doubling or Neimark–Sacker point, a run from there just beyond it
  lands on the motion a slow sweep would jump to, whose branch is traced in turn.  Near the
  resonance of a heavily impacting damper the curve breaks into many short branches between
  grazings (6 to 70 impacts a period on the README system), reached this way.

A start that lies on a branch already traced is skipped.  Every start depends on the band's ends
only, not on its step, so the branches and the located peak (:mod:`symimpact.forced.orbits.peak`) do
not depend on how finely the band is sampled.  Beside the branches: the primary without the
damper (the linear response of M, K, C, Step 8's steady solution) and brute-force sweeps up and
down the band, each run started from the previous one's end state, as a cross-check of the
stable branches and of where the motion jumps.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ... import _interrupt
from ..._progress import Stages
from ...errors import ParameterError, SymimpactError
from ...generated import forced_flight as ff
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import checked, is_constant, is_rigid, simulation_arguments
from ..forcing import Forcing
from ..responses import SAMPLES, response_key, steady_response
from ..simulation import settling_periods, simulate_forced
from .continuation import (
    SWITCHES,
    Branch,
    branch_starts,
    continue_orbit,
    leave,
    orbit_amplitude,
    orbit_beside_grazing,
    orbits_at,
    trace_branch,
)
from .coverage import (
    CHECK_SEED,
    FREQUENCIES,
    Coverage,
    MultiStart,
    attractor,
    check_frequencies,
    close_returns,
    initial_states,
    least_period,
    section_states,
)
from .peak import Peak, baseline_peak, curve_peak, linear_amplitude
from .periodic import periodic_orbits
from .shooting import settled_state, shoot
from .worst_case import worst_case

#: Periods kept for each brute-force sweep point's steady state; before them the run lasts until
#: the free transient has decayed to SWEEP_SETTLED of its start, exp(−ζω_n·t) (at most
#: SWEEP_MAX periods): near the resonance a neighbouring point's amplitude can be ten times
#: larger, so 1e-6 leaves ~1e-5 of the amplitude.
SWEEP_KEPT, SWEEP_SETTLED, SWEEP_MAX = 30, 1e-6, 5000
#: A swept amplitude carries what is left of its transient, relative to its amplitude: its run
#: lasts until the free transient is SWEEP_SETTLED of its start and a neighbouring point is at
#: most ~12 times larger near resonance (tests/test_frf.py measures the sweeps against the
#: textbook response to this).
SWEEP_ACCURACY = 1e-4
#: Branch switching: at most this many switches for one curve, onto orbits of at most this many
#: forcing periods: doublings followed to period 16 (1 → 2 → 4 → 8 → 16, 3 → 6 → 12).  At 4 the
#: cascades stopped short: on issue 81's base-excited system the stable period-6 orbit near
#: 16.55 rad/s that every start of a multi-start reaches was not drawn (tests/test_cascades.py).
MAX_SWITCHES, MAX_SWITCH_PERIODS = 24, 16
#: The periods of the orbits started from a motion the multi-start, a sweep or a run at a branch
#: end lands on, and of those embedded in chaos: at most this many (the branches of period 5 to
#: 8 these would start, windows inside chaotic bands, are not yet checked against the drawn
#: curve's bound: on the README system a period-5 branch near 30.57 rad/s lies 0.8 % beside
#: another of its impacts, which tests/test_drawn_curve.py's walk between points cannot tell
#: apart).
MAX_START_PERIODS = 4
#: Jumps from branch ends (:func:`_jump_from`) and the runs at branch ends
#: (:func:`_start_at_ends`): at most this many runs for one curve (224 on benchmark 6's band: 68
#: jumps and 156 runs at ends), each jump at
#: JUMP of the band beyond a stable end (on the README's curve 0.02 rad/s: the resonance's
#: short branches lie 0.01–0.02 rad/s apart and are 0.01–0.13 rad/s long).  With a compliant
#: contact none by default (``jumps``): every run and branch integrates each contact, and on
#: benchmark 6's band the jumps took its curve from 17.5 s to 114 s.
MAX_JUMPS, JUMP = 256, 1e-3
#: The multi-start's states are run at branch ends at least this fraction of the band apart
#: (:func:`_start_at_ends`; 0.04 rad/s on the README's curve, about the length of the
#: resonance's short branches).
ENDS_APART = 2e-3


@dataclass
class FrequencyResponse:
    """Outcome of :func:`frequency_response` (SI).

    ``branches``: the continued branches; ``baseline``: (Ω, amplitude) of the primary without the
    damper; ``sweep_up``/``sweep_down``: (Ω, steady amplitude) of the brute-force sweeps;
    ``notes``: starts that failed and why; ``no_impact``: the Ω intervals of the band where the
    motion without impacts exists (the impact mass at rest midway, the primary's linear response
    inside the clearance: X(Ω) < d/2), ``no_impact_grazings``: where it grazes a wall (X = d/2).
    That motion is neutral, not asymptotically stable (the floating mass keeps any drift given to
    it, multipliers 1); a sweep from rest follows it.
    """

    omegas: np.ndarray
    branches: list[Branch] = field(default_factory=list)
    baseline: np.ndarray | None = None
    sweep_up: np.ndarray | None = None
    sweep_down: np.ndarray | None = None
    notes: list[str] = field(default_factory=list)
    #: the notes' reasons with their frequencies [rad/s] (for text in another unit)
    note_omegas: list[tuple[str, list[float]]] = field(default_factory=list)
    no_impact: list[tuple[float, float]] = field(default_factory=list)
    no_impact_grazings: list[float] = field(default_factory=list)
    #: the largest amplitude of a stable orbit or of the motion without impacts over the band,
    #: located (:mod:`symimpact.forced.orbits.peak`); None where the curve holds neither
    peak: Peak | None = None
    #: the largest amplitude of the primary without the damper over the band, located
    baseline_peak: Peak | None = None
    #: the multi-start's attractors and the share of the periodic ones on a traced branch
    coverage: Coverage = field(default_factory=Coverage)
    #: the motions a brute force reaches at the located peak's Ω and just beside it
    #: (:func:`.worst_case.beside_peak`); the peak is the largest of them where it is larger
    beside_peak: list = field(default_factory=list)
    #: the swept motions that impact and do not repeat, as (sweep "up" or "down", Ω [rad/s],
    #: the lowest and the highest of the kept periods' largest abs(x) [m]): the envelope of the
    #: non-periodic bands, which no branch draws (a displacement, whatever ``response`` is)
    not_periodic: list[tuple[str, float, float, float]] = field(default_factory=list)
    #: what the ``amplitude`` fields hold: "displacement" (max abs(x)), or another response of
    #: :data:`symimpact.forced.responses.RESPONSES` (:func:`.response_curve.response_curve`),
    #: whose name replaces the key "amplitude" in :meth:`as_dict`
    response: str = "displacement"

    @property
    def reduction(self) -> float:
        """1 − peak/baseline peak: the share of the primary's resonant amplitude the damper
        removes over the band (NaN without a located peak, or undriven: no baseline to reduce)."""
        if self.peak is None or self.baseline_peak is None or not self.baseline_peak.amplitude > 0:
            return math.nan
        return 1.0 - self.peak.amplitude / self.baseline_peak.amplitude

    def as_dict(self) -> dict[str, Any]:
        """The JSON contract: points and bifurcations, each with its branch number; a point's
        ``impacts_per_period`` counts every impact the simulation resolved, its
        ``impact_events_per_period`` a chatter sequence once (its accumulation), and its
        ``kind`` is "periodic" (every traced point is an orbit; the multi-start's other
        attractors are in ``coverage``).  In another response than the displacement its name
        (``force``, ``relative_displacement``, …) replaces every "amplitude" key but the
        coverage's (the attractors' displacements)."""
        out = self._as_dict()
        if self.response == "displacement":
            return out
        key = response_key(self.response)

        def renamed(row):
            if isinstance(row, dict):
                return {key if k == "amplitude" else k: v for k, v in row.items()}
            return row

        for name in ("points", "bifurcations", "baseline", "sweep_up", "sweep_down"):
            out[name] = [renamed(r) for r in out[name]]
        for name in ("peak", "baseline_peak"):
            out[name] = renamed(out[name])
        from ..responses import response_unit

        out["response"] = {"name": self.response, "unit": response_unit(self.response)}
        return out

    def _as_dict(self) -> dict[str, Any]:
        points, bifurcations = [], []
        for i, b in enumerate(self.branches):
            for p in b.points:
                points.append({
                    "omega": p.omega, "amplitude": p.amplitude, "stable": p.stable,
                    "impacts_per_period": p.impacts_per_period,
                    "impact_events_per_period": p.impact_events_per_period,
                    "asymmetric": p.asymmetric, "kind": "periodic",
                    "period_multiple": b.period_multiple, "branch": i,
                })  # fmt: skip
            for f in b.bifurcations:
                row = {"kind": f.kind, "omega": f.omega, "amplitude": f.amplitude, "branch": i}
                if f.kind == "grazing":  # the impacts a period on both sides (null: it ends)
                    row["impacts_before"] = f.impacts_before
                    row["impacts_after"] = None if math.isnan(f.impacts_after) else f.impacts_after
                bifurcations.append(row)
        return {
            "points": points,
            "bifurcations": bifurcations,
            "branches": [
                {
                    "branch": i,
                    "period_multiple": b.period_multiple,
                    "phase": b.phase,
                    "stopped": b.stopped,
                    "origin": b.origin,
                    "mirrored": b.mirrored,
                }
                for i, b in enumerate(self.branches)
            ],
            "baseline": [{"omega": w, "amplitude": a} for w, a in self.baseline],
            "sweep_up": [{"omega": w, "amplitude": a} for w, a in self.sweep_up],
            "sweep_down": [{"omega": w, "amplitude": a} for w, a in self.sweep_down],
            "no_impact": [{"omega_from": a, "omega_to": b} for a, b in self.no_impact],
            "no_impact_grazings": list(self.no_impact_grazings),
            "not_periodic": [
                {"sweep": d, "omega": w, "displacement_low": lo, "displacement_high": hi}
                for d, w, lo, hi in self.not_periodic
            ],
            "peak": None if self.peak is None else self.peak.as_dict(),
            "baseline_peak": None if self.baseline_peak is None else self.baseline_peak.as_dict(),
            "reduction": None if math.isnan(self.reduction) else self.reduction,
            "coverage": self.coverage.as_dict(),
            "notes": self.notes,
        }


def _forcing(forcing: Forcing, omega: float) -> Forcing:
    return forcing.at(omega)


def _on_branch(branches: list[Branch], omega: float, amplitude: float, k: int) -> bool:
    """Whether (Ω, amplitude) lies on a traced branch of the same period: between two of its
    consecutive points, within 2 % of the amplitude interpolated between them (the points are up
    to ~0.5 rad/s apart on a curved branch; distinct coexisting orbits differ by far more)."""
    for b in branches:
        if b.period_multiple != k:
            continue
        pts = b.points
        for p, q in itertools.pairwise(pts):
            lo, hi = sorted((p.omega, q.omega))
            if lo - 1e-9 <= omega <= hi + 1e-9:
                f = 0.0 if hi == lo else (omega - p.omega) / (q.omega - p.omega)
                a = p.amplitude + f * (q.amplitude - p.amplitude)
                if abs(a - amplitude) <= 2e-2 * max(abs(a), 1e-12):
                    return True
    return False


def _traced(branches, system, forcing, e, omega: float, amplitude: float, k: int) -> bool:
    """Whether an orbit of period k and ``amplitude`` at Ω = ``omega`` (exact: shot) lies on a
    traced branch: a branch near it (:func:`_on_branch`) holds an orbit at that Ω whose amplitude
    agrees to 1e-7 (:func:`symimpact.forced.orbits.continuation.orbits_at`: Newton from the branch's
    interpolated state).  The 2 % of :func:`_on_branch` alone would take the asymmetric orbits
    beside a symmetric branch for it (1.2 % apart at 25.39 rad/s on the issue's system)."""
    if any(len(b.points) == 1 and b.period_multiple == k
           and abs(b.points[0].omega - omega) <= 1e-9 * omega
           and abs(b.points[0].amplitude - amplitude) <= 1e-7 * amplitude
           for b in branches):  # fmt: skip
        return True  # a branch of one orbit (impacts appear on both sides of it)
    near = [b for b in branches if _on_branch([b], omega, amplitude, k)]
    f = _forcing(forcing, omega)
    return any(abs(o.amplitude - amplitude) <= 1e-7 * amplitude
               for b in near for o in orbits_at(b, system, f, e, omega))  # fmt: skip


def _trace(system, forcing, e, state, band, k, step) -> Branch:
    """Both directions in Ω from the start, joined into one branch."""
    return trace_branch(system, forcing, e, state, band, periods=k, step=step)


def _section_state(orbit, omega: float, h: float, system: ImpactSystem, forcing: Forcing):
    """A closed-form orbit's state a quarter period after its impact on +d/2, with the forcing
    whose t = 0 is that instant."""
    f = _forcing(forcing, omega)
    T = 2 * math.pi / omega
    args = (system.M, system.K, system.C, f.primary_force, f.X_b, omega, orbit.impact_phase,
            orbit.X, orbit.V)  # fmt: skip
    x = float(ff.forced_displacement(T / 4, *args))
    v = float(ff.forced_velocity(T / 4, *args))
    state = (x, v, h + orbit.U * T / 4 - (x - orbit.X), orbit.U)
    return state, f.at(omega, orbit.impact_phase + math.pi / 2)


@_interrupt.stretch()
def frequency_response(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    omegas: Any,
    *,
    starts: int = 6,
    sweeps: bool = True,
    multistart: int = FREQUENCIES,
    jumps: int | None = None,
    folds: bool = False,
    embedded: bool = False,
    workers: int | None = None,
    progress: Any = None,
) -> FrequencyResponse:
    """The frequency-response curve over the band ``omegas`` [rad/s] (its first and last values
    bound the branches; the sweeps and the baseline use every value): branches continued from
    ``starts`` frequencies spread over the band (closed-form orbits and brute-force steady
    states of one and two periods), from the periodic attractors of a multi-start at
    ``multistart`` frequencies (0: none), with rigid impacts refined where an initial state
    lands on motions of another kind at neighbouring frequencies
    (:func:`symimpact.forced.orbits.coverage.attractors`, ``refine``), by branch switching and by at
    most ``jumps`` runs from the branches' stable ends and losses of stability and of the multi-start's initial
    states at the branches' ends (None: MAX_JUMPS with rigid impacts, none with a compliant
    contact); with ``folds`` (rigid impacts), each branch that ends at a grazing beyond which
    no orbit continues it turned back there onto the orbits with the new impact
    (:func:`_turn_at_grazing_ends`); with ``embedded``, the periodic orbits embedded in the
    multi-start's chaotic motions (:func:`_embedded`); the located peak; the linear
    response without the damper (Step 8, Eq. F1), the motion without impacts, and, with
    ``sweeps``, the up and down brute-force sweeps.  The multi-start's initial states run on
    ``workers`` local processes (:func:`symimpact.forced.orbits.coverage.attractors`; None: one per
    core).  ``progress``: each stage's runs as they end (:class:`symimpact._progress.Stages`:
    True draws a bar a stage on stderr, a callable is called with (stage, done, total); the
    stages are :data:`STAGES`)."""
    with Stages(progress, "frf") as stages:
        return _frequency_response(system, forcing, e, omegas, starts, sweeps, multistart,
                                   jumps, folds, embedded, workers, stages)  # fmt: skip


#: The stages of a curve, in order, as its progress names them (:func:`frequency_response`);
#: each counts its runs (a start frequency, a landing of the multi-start's grid, a start shot
#: and traced, a swept frequency, a branch switched and jumped from, ...).
STAGES = (
    "starts",
    "multi-start",
    "multi-start's orbits",
    "sweeps",
    "branches",
    "folds",
    "embedded orbits",
    "coverage check",
    "worst case",
)


def _frequency_response(system, forcing, e, omegas, starts, sweeps, multistart, jumps, folds,
                        embedded, workers, stages: Stages) -> FrequencyResponse:  # fmt: skip
    """:func:`frequency_response`, its progress told to ``stages``."""
    system, forcing, e = checked(system, forcing, e)
    starts = checks.whole_number("starts", starts, 0, 1000)
    sweeps = checks.flag("sweeps", sweeps)
    multistart = checks.whole_number("multistart", multistart, 0, 1000)
    if jumps is None:
        jumps = MAX_JUMPS if is_rigid(e) else 0
    jumps = checks.whole_number("jumps", jumps, 0, 10_000)
    folds = checks.flag("folds", folds)
    embedded = checks.flag("embedded", embedded)
    if embedded and not is_rigid(e):
        raise ParameterError("embedded", "the orbits embedded in chaotic motions are searched "
                                         "with rigid impacts, whose multi-start tells chaos by "
                                         "its Lyapunov exponent; a compliant contact's motions "
                                         "that do not repeat are not classified")  # fmt: skip
    w = checks.numbers("omegas", omegas)
    if w.ndim != 1 or len(w) < 2 or not np.all(np.isfinite(w)) or np.any(w <= 0):
        raise ParameterError("omega", "the band needs at least two positive frequencies")
    if np.any(np.diff(w) <= 0):
        raise ParameterError("omega", "the band's frequencies must increase")
    band = (float(w[0]), float(w[-1]))
    h = system.gap / 2.0
    out = FrequencyResponse(omegas=w)
    failures: dict[str, list[float]] = {}  # reason → the frequencies where it happened
    step = 0.05

    def follow(origin: str, k: int, state, fs: Forcing, guess: bool = False) -> Branch | None:
        """Shoot from ``state`` and, unless the orbit is on a traced branch, continue it: the
        new branch, or None (with a note where shooting fails, unless the start is a
        ``guess``)."""
        try:
            orbit = shoot(system, fs, e, state, periods=k)
        except SymimpactError as exc:
            if not guess:
                failures.setdefault(f"{origin}: {exc}", []).append(fs.omega)
            return None
        if k > 1 and least_period(system, fs, e, orbit.state, k, orbit.amplitude) < k:
            return None  # an orbit of fewer periods (one found as two, two as four)
        if _traced(out.branches, system, fs, e, fs.omega, orbit.amplitude, k):
            return None
        try:
            out.branches.append(_trace(system, fs, e, orbit.state, band, k, step))
        except SymimpactError as exc:
            failures.setdefault(f"{origin}: {exc}", []).append(fs.omega)
            return None
        return out.branches[-1]

    # the multi-start runs on the workers while this process traces the other starts
    multi = (MultiStart(system, forcing, e, band, multistart, refine=is_rigid(e), workers=workers)
             if multistart else None)  # fmt: skip
    try:
        stages.stage("starts", starts, unit="Ω")
        for omega in np.linspace(band[0], band[1], starts + 2)[1:-1]:
            f = _forcing(forcing, float(omega))
            for o in periodic_orbits(system, f, e) if is_constant(e) else ():
                if o.admissible:
                    follow("closed form", 1, *_section_state(o, float(omega), h, system, forcing))
            # one run from rest; its end shot as an orbit of one and of two periods
            _from_rest(system, f, e, omega, failures, follow)
            stages.advance()
        out.baseline = np.column_stack([w, linear_amplitude(system, forcing, w)])
        out.baseline_peak = baseline_peak(system, forcing, band)
        out.no_impact, out.no_impact_grazings = _no_impact(
            system, forcing, w, out.baseline_peak.omega
        )
    except BaseException:
        if multi is not None:
            multi.cancel()
        raise
    # the multi-start: every periodic attractor that no branch traces starts one
    # refined with rigid impacts (whose resonance breaks into narrow stable windows between
    # grazings); a compliant contact's runs integrate every contact, at far greater cost
    found = _waited(multi, stages, "multi-start") if multi is not None else []
    shot = [a for a in found if a.kind == "periodic" and a.period_multiple <= MAX_START_PERIODS]
    stages.stage("multi-start's orbits", len(shot), unit="orbit")
    for a in shot:
        follow("multi-start", a.period_multiple, a.state, _forcing(forcing, a.omega))
        stages.advance()
    swept: list[_SweepPoint] = []
    if sweeps:
        stages.stage("sweeps", 2 * len(w), unit="Ω")
        up = _sweep_runs(system, forcing, e, w, tick=stages.advance)
        down = _sweep_runs(system, forcing, e, w[::-1], tick=stages.advance)[::-1]
        swept = [*up, *down]
        out.sweep_up = np.array([(r.omega, r.amplitude) for r in up])
        out.sweep_down = np.array([(r.omega, r.amplitude) for r in down])
        out.not_periodic = [(d, r.omega, r.low, r.amplitude)
                            for d, runs in (("up", up), ("down", down)) for r in runs
                            if not r.periodic and r.impacts_per_period > 0]  # fmt: skip
        # a periodic swept motion that no branch holds starts one (chatter and sticking
        # included: shooting follows them)
        for r in (*up, *down):
            if (r.periodic and 0 < r.period_multiple <= MAX_START_PERIODS and r.impacts_per_period > 0
                    and not _on_branch(out.branches, r.omega, r.amplitude, r.period_multiple)):  # fmt: skip
                follow("sweep", r.period_multiple, r.state, _forcing(forcing, r.omega))
    else:
        out.sweep_up = out.sweep_down = np.zeros((0, 2))
    _grow(out, system, forcing, e, band, step, failures, follow, jumps, stages)
    if folds and is_rigid(e):
        stages.stage("folds", None, unit="branch")
        _turn_at_grazing_ends(out, system, forcing, e, band, step, failures)
    if embedded:  # rigid impacts (checked above)
        _embedded(found, system, forcing, e, failures, follow, stages)
    out.coverage = _coverage(found, out.branches, system, forcing, e, multi.ws if multi else ())
    if multi is not None:  # the independent check: random frequencies, their landings traced?
        check = MultiStart(system, forcing, e, band, workers=workers, ws=check_frequencies(band))
        checked_ = _waited(check, stages, "coverage check")
        out.coverage.check = _coverage(checked_, out.branches, system, forcing, e, check.ws)
        out.coverage.seed = CHECK_SEED
    _drop_repeated_bifurcations(out.branches, 1e-6 if is_rigid(e) else 1e-5)
    out.peak = curve_peak(out.branches, system, forcing, e, band, out.no_impact, found)
    # the worst case: what a brute force reaches beside the peak (rigid impacts: a compliant
    # contact's runs are classified by its contact onsets, which a mass pressed for whole
    # periods does not show)
    if out.peak is not None and is_rigid(e):
        stages.stage("worst case", None)
        worse, out.beside_peak = worst_case(system, forcing, e, band, out.peak, out.branches,
                                            swept, float(np.median(np.diff(w))),
                                            tick=stages.advance)  # fmt: skip
        if worse is not out.peak:
            p = out.peak
            kind = "repeats" if worse.motion == "periodic" else "does not repeat"
            failures.setdefault(
                f"beside the located peak ({p.motion}, {p.amplitude:.6g} m, {p.where}) a motion "
                f"that {kind} reaches {worse.amplitude:.6g} m, the worst case reported (the "
                "located peak's frequency, then the worst case's)",
                [],
            ).extend([p.omega, worse.omega])
            out.peak = worse
    if sweeps and out.peak is not None:
        top = max((*out.sweep_up, *out.sweep_down), key=lambda r: r[1])
        if top[1] > out.peak.amplitude * (1.0 + SWEEP_ACCURACY):
            failures.setdefault(
                f"a swept motion reaches {top[1]:.6g} m, above the located peak "
                f"{out.peak.amplitude:.6g} m (a chattering, sticking or untraced motion)",
                [],
            ).append(float(top[0]))
    out.note_omegas = [(reason, list(ws)) for reason, ws in failures.items()]
    out.notes = [
        f"{reason} (at Ω {', '.join(f'{x:.4g}' for x in ws)} rad/s)"
        for reason, ws in failures.items()
    ]
    return out


#: The multi-start's motions whose embedded periodic orbits are searched for (:func:`_embedded`).
EMBEDDING = ("chaotic", "not periodic")


def _coverage(found, branches, system, forcing, e, ws) -> Coverage:
    """The share of the periodic attractors ``found`` at ``ws`` that lie on a traced branch."""
    return Coverage(found, [
        _traced(branches, system, forcing, e, a.omega, a.amplitude, a.period_multiple)
        for a in found if a.kind == "periodic"
    ], tuple(ws))  # fmt: skip


def _from_rest(system, f, e, omega, failures, follow) -> None:
    """One run from rest at ``omega``; its end shot as an orbit of one and of two periods, each
    traced unless on a traced branch (a branch start of :func:`frequency_response`)."""
    try:
        rest, law = settled_state(system, f, e, warmup=settling_periods(system, f, 20, 300))
    except SymimpactError as exc:
        failures.setdefault(f"from rest: {exc}", []).append(omega)
        return
    for k in (1, 2):
        try:
            shot = shoot(system, f, law, rest, periods=k)
        except SymimpactError as exc:
            failures.setdefault(f"{k} period(s) from rest: {exc}", []).append(omega)
            continue
        follow("from rest", k, shot.state, f)


def _waited(multi: MultiStart, stages: Stages, name: str) -> list:
    """The attractors of ``multi``, its landings told to ``stages`` as stage ``name`` while its
    workers run (the grid's landings counted, the refinement's runs noted beside them)."""
    stages.stage(name, multi.runs, unit="run")

    def told() -> None:
        grid, refined = multi.counts()
        stages.reach(min(grid, multi.runs))
        if refined:
            stages.note(f"refined by {refined} more runs")

    found = multi.result(told if stages.enabled else None)
    if stages.enabled:
        told()
    return found


def _embedded(found, system, forcing, e, failures, follow, stages: Stages | None = None) -> None:
    """The periodic orbits of 1 to MAX_START_PERIODS periods embedded in each chaotic or not
    periodic motion the multi-start found (rigid impacts): shot from the close returns of its
    Poincaré section (:func:`symimpact.forced.orbits.coverage.close_returns`) and traced unless on a
    traced branch (a close return that shooting does not converge from is a guess, and no
    note).  Unstable where they are found, they lead to the stable windows inside a chaotic
    band that lie between the multi-start's frequencies: on the README system the period-3
    window at 28.125–28.199 rad/s, from the chaotic motion at 28.75 rad/s (benchmark 6's band,
    when the multi-start refined to 1/256 everywhere: 124 → 126 of the 200-frequency brute
    force's 128 periodic attractors on the curve; refined beside chaos to 1/1024, the default
    curve holds that window too, 127 of 128 with or without this, which adds 27 branches and 1.2
    times the time).  Done after the other starts (their budgets spent as before); the new
    branches are not switched or jumped from."""
    chaotic = [a for a in found if a.kind in EMBEDDING]
    if stages is not None:
        stages.stage("embedded orbits", len(chaotic), unit="motion")
    for n, a in enumerate(chaotic):
        if stages is not None:
            stages.reach(n)  # the motions before this one are done
        fs = _forcing(forcing, a.omega)
        try:
            sections = section_states(system, fs, e, a.state)
        except SymimpactError as exc:
            failures.setdefault(f"orbits in a non-periodic motion: {exc}", []).append(a.omega)
            continue
        for k in range(1, MAX_START_PERIODS + 1):
            for state in close_returns(sections, k):
                new = follow("orbits in a non-periodic motion", k, state, fs, guess=True)
                if new is not None:
                    new.origin = (f"period-{k} orbit in the {a.kind} motion at "
                                  f"Ω = {a.omega:.6g} rad/s")  # fmt: skip
                    new.origin_omega = a.omega
    if stages is not None:
        stages.reach(len(chaotic))


def _grow(out, system, forcing, e, band, step, failures, follow, jumps: int,
          stages: Stages | None = None) -> None:  # fmt: skip
    """Every branch in turn, the new ones included (so that a branch found by a switch or a jump
    is itself switched from and jumped from): branch switching at its located points
    (:func:`_switch_at`) and jumps from its stable ends (:func:`_jump_from`); then the
    multi-start's states at the branches' ends (:func:`_start_at_ends`), and the same again on
    the branches these find, until a round finds none (``stages``: a stage "branches", one run
    a branch grown, its count of branches found and jumps noted beside it)."""
    budget = {"switches": 0, "jumps": 0, "max_jumps": jumps}
    stages = stages if stages is not None else Stages(None)
    stages.stage("branches", None, unit="branch")
    sources: list[tuple[float, float, int]] = []  # (Ω, amplitude, direction) jumped from
    places: list[float] = []  # the Ω of the branch ends started from (:func:`_start_at_ends`)
    i = 0
    while True:
        while i < len(out.branches):
            _switch_at(out, i, system, forcing, e, band, step, failures, budget)
            _jump_from(out, i, system, forcing, e, band, failures, follow, budget, sources)
            i += 1
            stages.note(f"{len(out.branches)} found; {budget['switches']} switches, "
                        f"{budget['jumps']} of at most {jumps} jumps")  # fmt: skip
            stages.advance()
        known = len(out.branches)
        _start_at_ends(out, system, forcing, e, band, failures, follow, budget, places)
        if len(out.branches) == known:
            return


def _turn_at_grazing_ends(out, system, forcing, e, band, step, failures) -> None:
    """Where a branch ends at a grazing beyond which no orbit continues it, the branch is
    continued from its end again, turning back there onto the orbits with the new low-speed
    impact on the same side (a non-smooth fold,
    :func:`symimpact.forced.orbits.continuation.continue_orbit` with ``folds`` 1); the part beyond the
    fold is a new branch unless its first orbit lies on a traced one; each end turns at its own
    grazing (a branch folded between two grazings of one Ω turns at both), and beside each
    turned branch the orbits with one more impact are traced (:func:`_beside`).  On the
    README's curve the symmetric four-impact orbits' grazing at 30.4438 rad/s leads to the
    stable five-impact motion near 29.876 rad/s, and the symmetric 12-impact orbits' at
    30.6907 rad/s, through the 13-impact orbits it turns onto, to the stable 14-impact motion
    near 30.672 rad/s (benchmark 6's band, when the multi-start refined to 1/256 everywhere and
    nothing else reached either: 124 → 126 of the brute force's 128 periodic attractors on the
    curve; refined beside chaos to 1/1024, the default curve holds both, 127 of 128 with or
    without this, which adds 66 branches and twice the time).
    Done after the other starts (their budgets spent as before); the new branches are not
    switched or jumped from."""
    width = band[1] - band[0]
    reached: list[tuple[float, float]] = []  # (Ω, amplitude) of the grazings a turn ended at

    def seen(g) -> bool:
        return any(abs(w - g.omega) <= 1e-5 * w and abs(a - g.amplitude) <= 1e-3 * a
                   for w, a in reached)  # fmt: skip

    for i, b in enumerate(list(out.branches)):
        if b.parameter != "omega" or len(b.points) < 2:
            continue
        ends = [g for g in b.bifurcations
                if g.kind == "grazing" and math.isnan(g.impacts_after)]  # fmt: skip
        for end, near in ((b.points[0], b.points[1]), (b.points[-1], b.points[-2])):
            # each end turns at its own grazing: the nearest in Ω and amplitude (a branch whose
            # two ends stop at grazings of one Ω, either side of a fold, turns at both)
            g = min(ends, default=None,
                    key=lambda g: (abs(g.omega - end.omega) / width
                                   + abs(g.amplitude - end.amplitude) / end.amplitude))  # fmt: skip
            if g is None or seen(g) or abs(end.omega - g.omega) > 1e-3 * width:
                continue
            direction = int(np.sign(g.omega - end.omega) or np.sign(end.omega - near.omega))
            if not direction:
                continue
            try:
                turned = continue_orbit(system, forcing.at(end.omega, end.phase), e, end.state,
                                        band, periods=b.period_multiple, direction=direction,
                                        step=step, folds=1)  # fmt: skip
            except SymimpactError as exc:
                failures.setdefault(f"turning back at a grazing: {exc}", []).append(g.omega)
                continue
            count = end.impact_events_per_period
            k = next((j for j, p in enumerate(turned.points)
                      if p.impact_events_per_period != count), None)  # fmt: skip
            if k is None or len(turned.points) < k + 2:
                continue
            first = turned.points[k]
            if _traced(out.branches, system, forcing.at(first.omega, first.phase), e,
                       first.omega, first.amplitude, b.period_multiple):  # fmt: skip
                continue
            turned.points = turned.points[k - 1 :]
            # a turn that ends at another branch's grazing end would be found again from there
            reached.extend((f.omega, f.amplitude) for f in turned.bifurcations[1:]
                           if f.kind == "grazing" and math.isnan(f.impacts_after))  # fmt: skip
            turned.origin = f"turned back at the grazing of branch {i} at Ω = {g.omega:.6g} rad/s"
            turned.origin_omega = g.omega
            out.branches.append(turned)
            _beside(out, system, forcing, e, band, step, turned, failures)


#: How many of the turned branch's points :func:`_beside` looks beside, the nearest the turn first,
#: and the share of the curve's step its branch is traced with.
BESIDE_TRIES = 6
BESIDE_STEP = 1 / 8


def _beside(out, system, forcing, e, band, step, turned, failures) -> None:
    """The branch of the orbits with one more impact beside the branch ``turned`` back at a
    grazing (:func:`symimpact.forced.orbits.continuation.orbit_beside_grazing` at its points past the
    turn, the first found), traced unless on a traced branch.  A symmetric orbit grazing both
    walls at once turns onto the asymmetric orbits with one new impact, beside which lie the
    symmetric ones with two.  The points looked beside lie at least the continuation's shortest
    step (step/64, in Ω a tenth of the band each unit) from the turn: the new impact's region is
    as narrow as its distance from the grazing, and from an orbit nearer than that the
    continuation meets the grazing within its shortest step; the branch is traced with
    BESIDE_STEP of the step for the same reason (measured on the README's curve, the turn at
    30.6907 rad/s: from the orbits beside 4e-4 and 7e-4 rad/s from it the continuation crosses
    onto other orbits at once with either step; from those 1.6e-3 and 2.4e-3 rad/s away it
    does so with the curve's step and follows the 14-impact orbits down through their fold and
    stable stretch with an eighth of it, as from 3.7e-3 rad/s away with either)."""
    n = turned.period_multiple
    shortest = step / 64 * (band[1] - band[0]) / 10.0
    away = [p for p in turned.points[1:] if abs(p.omega - turned.origin_omega) >= shortest]
    for p in away[:BESIDE_TRIES]:
        got = orbit_beside_grazing(system, forcing.at(p.omega, p.phase), e, p.state, band,
                                   periods=n)  # fmt: skip
        if got is None or not band[0] <= got[1].omega <= band[1]:
            continue  # (Newton's method within the hyperplane may leave the band)
        state, fs = got
        try:
            orbit = shoot(system, fs, e, state, periods=n)
            if _traced(out.branches, system, fs, e, fs.omega, orbit.amplitude, n):
                return
            new = _trace(system, fs, e, orbit.state, band, n, step * BESIDE_STEP)
        except SymimpactError as exc:
            failures.setdefault(f"beside a turned branch: {exc}", []).append(fs.omega)
            return
        new.origin = f"beside the branch turned back at Ω = {turned.origin_omega:.6g} rad/s"
        new.origin_omega = fs.omega
        out.branches.append(new)
        return


def _switch_at(out, i, system, forcing, e, band, step, failures, budget) -> None:
    """Branch switching on branch ``i``: from every branch point and period doubling located on
    it, the branches that leave it (:func:`symimpact.forced.orbits.continuation.branch_starts`) are
    traced unless their start lies on a traced branch; the mirror image of an asymmetric orbit
    is recognised (the same amplitude at the same Ω, to 1e-8) and marks its branch
    ``mirrored``.  At most MAX_SWITCHES switches for the curve, and periods up to
    MAX_SWITCH_PERIODS."""
    b = out.branches[i]
    for f in list(b.bifurcations):
        if f.kind not in SWITCHES or f.state is None:
            continue
        if b.period_multiple * SWITCHES[f.kind][1] > MAX_SWITCH_PERIODS:
            continue
        if budget["switches"] == MAX_SWITCHES:
            failures.setdefault(f"branch switching: stopped after {MAX_SWITCHES} switches",
                                []).append(f.omega)  # fmt: skip
            return
        budget["switches"] += 1
        fs = forcing.at(f.omega, f.phase)
        try:
            starts = branch_starts(system, fs, e, f, band, periods=b.period_multiple, step=step)
        except SymimpactError as exc:
            failures.setdefault(f"branch switching: {exc}", []).append(f.omega)
            continue
        traced: list[Branch] = []
        for start in starts:
            amp = orbit_amplitude(start)
            w = start.forcing.omega
            mirror = [t for t in traced if any(abs(o.amplitude - amp) <= 1e-8 * amp
                      for o in orbits_at(t, start.system, start.forcing, start.e, w))]  # fmt: skip
            if mirror:  # the mirror image of an orbit just traced
                continue
            if _traced(out.branches, system, forcing, e, w, amp, start.periods):
                continue
            try:
                new = leave(start, f, band, step=step)
            except SymimpactError as exc:
                failures.setdefault(f"branch switching: {exc}", []).append(f.omega)
                continue
            new.origin = f"{f.kind} of branch {i} at Ω = {f.omega:.6g} rad/s"
            new.origin_omega = f.omega
            traced.append(new)
            out.branches.append(new)


#: The located points where a branch loses its stability, from which a slow sweep jumps.
LOSSES = ("fold", "branch-point", "period-doubling", "neimark-sacker")


def _departures(branch: Branch) -> list[tuple[float, Any, float, float, int]]:
    """Where a slow sweep along ``branch``'s stable orbits would leave it: (Ω [rad/s], state,
    phase [rad], amplitude [m], direction in Ω) at its first and last points where they are
    stable (outward; both ways for a branch of one point), at each grazing it ends at beside a
    stable point (outward), and at each located fold, branch point, period doubling and
    Neimark–Sacker point between a stable and an unstable point (beyond a fold; towards the
    unstable side of the others)."""
    pts = branch.points
    out = []
    if len(pts) == 1:
        ends = [(pts[0], 1), (pts[0], -1)]
    else:
        ends = [(pts[0], int(np.sign(pts[0].omega - pts[1].omega))),
                (pts[-1], int(np.sign(pts[-1].omega - pts[-2].omega)))]  # fmt: skip
    for p, d in ends:
        if p.stable and d:
            out.append((p.omega, p.state, p.phase, p.amplitude, d))
    for g in branch.bifurcations:
        if g.kind != "grazing" or not math.isnan(g.impacts_after) or g.state is None:
            continue
        near = min(pts, key=lambda q: abs(q.omega - g.omega))
        d = int(np.sign(g.omega - near.omega))
        if near.stable and d:
            out.append((g.omega, g.state, g.phase, g.amplitude, d))
    for p, q in itertools.pairwise(pts):
        if p.stable == q.stable:
            continue
        s, u = (p, q) if p.stable else (q, p)
        lo, hi = sorted((p.amplitude, q.amplitude))
        for f in branch.bifurcations:
            if f.kind not in LOSSES or f.state is None:
                continue
            if not lo * (1 - 1e-9) <= f.amplitude <= hi * (1 + 1e-9):
                continue
            d = int(np.sign((f.omega if f.kind == "fold" else u.omega) - s.omega))
            if d:
                out.append((f.omega, f.state, f.phase, f.amplitude, d))
            break
    return out


def _jump_from(out, i, system, forcing, e, band, failures, follow, budget, sources) -> None:
    """Where branch ``i`` ends inside the band on a stable orbit — at a grazing it does not
    cross, or where the corrector fails among impacts that appear and vanish (the resonance of a
    heavily impacting damper breaks into many short branches) — or loses its stability
    (:func:`_departures`), a slow sweep would jump to another motion: a run from the orbit
    there at Ω JUMP of the band beyond it, classified by
    :func:`symimpact.forced.orbits.coverage.attractor`, gives that motion, and a periodic one not on a
    traced branch starts a branch (which is jumped from in turn).  A place met again (within
    half a jump in Ω and 1e-3 in amplitude, the same direction: the branches of one orbit that
    the cascades of grazings near 30.9 rad/s on the README system return to) is not jumped
    from again; at most ``budget["max_jumps"]`` runs for the curve."""
    branch = out.branches[i]
    if branch.parameter != "omega":
        return
    width = band[1] - band[0]
    for omega, state, phase, amp, d in _departures(branch):
        w = omega + d * JUMP * width
        if not band[0] < w < band[1]:
            continue
        if any(abs(omega - o) <= 0.5 * JUMP * width and abs(amp - a) <= 1e-3 * a and d == dd
               for o, a, dd in sources):  # fmt: skip
            continue
        sources.append((omega, amp, d))
        origin = f"jump from branch {i} at Ω = {omega:.6g} rad/s"
        if not _run_and_follow(system, e, forcing.at(w, phase), state, omega,
                               "jump from a branch end", origin, failures, follow,
                               budget):  # fmt: skip
            return


def _start_at_ends(out, system, forcing, e, band, failures, follow, budget, places) -> None:
    """The multi-start's initial states (:func:`symimpact.forced.orbits.coverage.initial_states`) run
    at the Ω of every branch end inside the band, stable or not, at least ENDS_APART of the band
    from one another and from the places started from before: a branch that ends where no
    grazing is crossed (the corrector fails among impacts that appear and vanish, or at a sharp
    turn) marks a stretch whose other motions lie on short branches of their own, which neither
    a stable end nor a loss of stability leads to (on the README's curve the 4- to 16-impact
    branches of 29.3–31.9 rad/s).  A periodic attractor not on a traced branch starts a branch.
    Each run counts against ``budget["max_jumps"]``."""
    width = band[1] - band[0]
    ends = sorted({p.omega for b in out.branches if b.parameter == "omega"
                   for p in (b.points[0], b.points[-1])})  # fmt: skip
    for omega in ends:
        if not band[0] + JUMP * width < omega < band[1] - JUMP * width:
            continue
        if any(abs(omega - w) <= ENDS_APART * width for w in places):
            continue
        places.append(omega)
        fs = forcing.at(omega)
        for state in initial_states(system, fs):
            if not _run_and_follow(system, e, fs, state, omega, "start at a branch end",
                                   f"a start at a branch end at Ω = {omega:.6g} rad/s",
                                   failures, follow, budget):  # fmt: skip
                return


def _run_and_follow(system, e, fs, state, omega, what, origin, failures, follow, budget) -> bool:
    """One run from ``state`` under ``fs``, classified by
    :func:`symimpact.forced.orbits.coverage.attractor`; a periodic landing on no traced branch starts
    one, whose ``origin`` is set (``omega``: the place run from).  False, with a note, when the
    budget of runs (``budget["max_jumps"]``, shared by the jumps and the starts at branch ends)
    is spent."""
    if budget["jumps"] == budget["max_jumps"]:
        if budget["max_jumps"]:
            failures.setdefault(f"jumps and starts from branch ends: stopped after "
                                f"{budget['jumps']} runs", []).append(omega)  # fmt: skip
        return False
    budget["jumps"] += 1
    try:
        a = attractor(system, fs, e, state, exponent=False)
    except SymimpactError as exc:
        failures.setdefault(f"{what}: {exc}", []).append(omega)
        return True
    if a.kind == "periodic" and a.period_multiple <= MAX_START_PERIODS:
        new = follow(what, a.period_multiple, a.state, fs)
        if new is not None:
            new.origin = origin
            new.origin_omega = omega
    return True


def _drop_repeated_bifurcations(branches: list[Branch], rtol: float = 1e-6) -> None:
    """A point located again on a later branch that overlaps an earlier one (two starts whose
    branches share a stretch) is listed once, with the first: same kind and period, Ω within
    ``rtol`` of it and amplitude within 1e-4.  Rigid impacts locate points to far better than
    1e-6; a compliant contact's map carries ~1e-12 of noise, which the ill-conditioned location
    of a fold beside a branch point amplifies (a fold located twice 1.2e-6 apart on the issue's
    system with the linear law), so 1e-5 is used there."""
    seen: list[tuple[str, int, float, float]] = []
    for b in branches:
        kept = []
        for f in b.bifurcations:
            if any(k == f.kind and n == b.period_multiple and abs(w - f.omega) <= rtol * w
                   and abs(a - f.amplitude) <= 1e-4 * a for k, n, w, a in seen):  # fmt: skip
                continue
            kept.append(f)
            seen.append((f.kind, b.period_multiple, f.omega, f.amplitude))
        b.bifurcations = kept


def _no_impact(system: ImpactSystem, forcing: Forcing, w: np.ndarray, top: float):
    """The motion without impacts: the impact mass at rest midway while the primary follows its
    linear response X(Ω) (Step 8, Eq. F1) — a steady motion wherever X(Ω) < d/2.  Returns its
    Ω intervals within the band and the frequencies where it grazes (X = d/2), each located by
    Brent's method between two frequencies that bracket it (to 1e-12 rad/s): the band's, and
    ``top`` [rad/s], X's one maximum in the band (the primary alone's peak,
    :func:`~symimpact.forced.orbits.peak.baseline_peak`), so that a resonance reaching past d/2
    between two band frequencies is not read as a motion without impacts whatever the step."""
    from scipy.optimize import brentq

    h = system.gap / 2.0

    def excess(omega: float) -> float:
        return float(linear_amplitude(system, forcing, np.array([omega]))[0]) - h

    w = np.unique(np.append(w, top))  # X rises to its maximum and falls: two crossings at most
    inside = linear_amplitude(system, forcing, w) < h
    ends: list[float] = []
    for k in range(1, len(w)):
        if inside[k] != inside[k - 1]:
            ends.append(brentq(excess, float(w[k - 1]), float(w[k]), xtol=1e-12))
    intervals: list[tuple[float, float]] = []
    cuts = [float(w[0]), *ends, float(w[-1])]
    state = bool(inside[0])
    for lo, hi in itertools.pairwise(cuts):
        if state:
            intervals.append((lo, hi))
        state = not state
    return intervals, ends


@dataclass(frozen=True)
class _SweepPoint:
    omega: float
    amplitude: float
    state: tuple[float, float, float, float]  # (x, ẋ, z, ẏ) at the end, forcing phase φ
    periodic: bool
    period_multiple: int
    impacts_per_period: float
    response: float = math.nan  # the response asked of the sweep over its kept periods [SI]
    low: float = (
        math.nan
    )  # the lowest of the kept periods' largest |x| [m] (``amplitude``: the highest)


def _sweep_runs(
    system,
    forcing,
    e,
    omegas,
    settled: float = SWEEP_SETTLED,
    response: str | None = None,
    tick: Any = None,
) -> list[_SweepPoint]:
    """Brute-force sweep: at each Ω, a run from the previous end state until its transient has
    fallen to ``settled``; the steady amplitude over the last SWEEP_KEPT periods, the end state
    and whether the motion repeats (:func:`symimpact.forced.steady_state`); with ``response``
    (:data:`symimpact.forced.responses.RESPONSES`) also that response over the same periods
    (:func:`symimpact.forced.responses.steady_response`; a compliant run then records its state
    at :data:`symimpact.forced.responses.SAMPLES` samples a period); ``tick()`` after each Ω
    (the curve's progress)."""
    state = (0.0, 0.0, 0.0, 0.0)
    rows = []
    for omega in omegas:
        f = _forcing(forcing, float(omega))
        periods = settling_periods(system, f, SWEEP_KEPT, SWEEP_MAX, settled)
        res = simulate_forced(system, f, **simulation_arguments(e), periods=periods,
                              discard=periods - SWEEP_KEPT, x0=state[0], xdot0=state[1],
                              y0=state[2], ydot0=state[3])  # fmt: skip
        x, v, y, u = res.final_state
        st = res.steady
        value = math.nan
        if response is not None and is_rigid(e):  # the run's state is rebuilt exactly
            value = steady_response(response, res, periods - SWEEP_KEPT)
        elif response is not None:  # the kept periods again, recorded densely
            again = simulate_forced(system, f, **simulation_arguments(e), periods=SWEEP_KEPT,
                                    x0=x, xdot0=v, y0=y, ydot0=u,
                                    samples_per_period=SAMPLES)  # fmt: skip
            value = steady_response(response, again, 0)
        kept = res.period_max[periods - SWEEP_KEPT : periods]
        rows.append(_SweepPoint(float(omega), st.amplitude, (x, v, y - x, u), bool(st.periodic),
                                int(st.period_multiple or 0), float(st.impacts_per_period),
                                float(value), float(np.min(kept))))  # fmt: skip
        # the forcing phase restarts at t = 0: the end state after whole periods is at phase φ
        state = (x, v, y, u)
        if tick is not None:
            tick()
    return rows


def _sweep(system, forcing, e, omegas, settled: float = SWEEP_SETTLED) -> np.ndarray:
    """(Ω, steady amplitude) of :func:`_sweep_runs`."""
    return np.array([(r.omega, r.amplitude) for r in _sweep_runs(system, forcing, e, omegas,
                                                                  settled)])  # fmt: skip
