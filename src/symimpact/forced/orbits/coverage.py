"""Which steady motions a frequency-response curve holds: multi-start brute force over the band
(:func:`attractors`) and the share of the periodic ones that lie on a traced stable branch
(:func:`coverage`).

At each of :data:`FREQUENCIES` frequencies spread over the band (fixed by the band's ends, not
by its step, so that the curve does not depend on how finely it is sampled; for a curve, each
initial state's interval between neighbouring frequencies, or between a band's end and its
nearest frequency, halved where it lands on motions of another kind at its ends, down to
:data:`REFINE` of the band, :data:`REFINE_IRREGULAR` next to a motion that does not repeat) the event-driven
simulation (rigid impacts with chatter and sticking, or a compliant contact; Eq. F1, F2) runs
from :data:`STARTS` initial states until the primary's free transient has decayed to 1e-6
(exp(−ζω_n·t), at most :data:`WARMUP` periods), and its last periods are classified by
:func:`symimpact.forced.steady_state`:

- **periodic** (k ≤ 4 forcing periods, with impacts; with rigid impacts chatter and sticking
  included): shooting converges on it (:func:`symimpact.forced.shoot`), which gives its exact
  amplitude;
- **no impact**: the impact mass floats at rest (the primary's linear response);
- **chatter or sticking**: periodic, but shooting does not converge on it (a compliant
  contact's chatter, more than its contacts' cap a period; Newton's steps pressing the impact
  mass into a wall);
- **chaotic** or **quasi-periodic** (rigid impacts): no period up to 8, and the largest
  Lyapunov exponent (:func:`lyapunov`, carried through the impacts by the saltation matrices)
  positive, or zero within LYAPUNOV_ZERO a period;
- **not periodic**: no period up to 8 where no exponent can be computed (a compliant contact, or
  an impact at zero relative speed on the way);
- **not settled**: a transient still decaying over the kept periods, or an impact mass drifting
  with fewer than one impact a period where the motion without impacts exists (the floating
  mass is neutral: with e < 1 it creeps towards rest over many more periods).  Not an attractor:
  counted, not listed as missed.

The periodic orbits embedded in a chaotic motion are found from the close returns of its
Poincaré section (:func:`section_states`, :func:`close_returns`): starts for shooting whose
branches lead to stable windows narrower than the multi-start's spacing (``frf --embedded``).
"""

from __future__ import annotations

import itertools
import math
import os
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ... import _pool
from ...errors import SymimpactError
from ...model import checks
from ...model.system import ImpactSystem
from ..contact_law import is_rigid, simulation_arguments
from ..forcing import Forcing
from ..simulation import settling_periods, simulate_forced
from .peak import UNTRACEABLE, linear_amplitude
from .shooting import MAX_PERIODS, monodromy, shoot

#: Frequencies of the multi-start, spread evenly inside the band (its ends excluded).
FREQUENCIES = 15
#: Initial states at each frequency (see :func:`initial_states`).
STARTS = 4
#: At most this many forcing periods before the steady state is read; 20 more are kept.
WARMUP, KEPT = 400, 20
#: The periods a periodic attractor may have to be shot and traced.
MAX_SHOT_PERIODS = 4
#: Forcing periods over which the largest Lyapunov exponent is averaged, in this many stretches
#: whose spread says how well it is known.
LYAPUNOV_PERIODS, LYAPUNOV_BLOCKS = 400, 4
#: Periods carried by one call of the compiled map between renormalisations of the tangent
#: vector: its growth over 10 periods stays far inside float range (e^(λ·10T) with λT of order 1)
#: and the Python overhead per period falls tenfold.
LYAPUNOV_CHUNK = 10
#: A Lyapunov exponent whose size over a forcing period, abs(λ)·T, is below this is zero: the
#: motion is quasi-periodic (measured on the README system just past its Neimark–Sacker point:
#: λT = 0.003, against about 1 for its chaotic motion at 28.75 rad/s).
LYAPUNOV_ZERO = 0.01


@dataclass(frozen=True)
class Attractor:
    """A steady motion a brute-force run settled on (SI): ``omega`` [rad/s], ``amplitude`` [m]
    (the shot orbit's where shooting converged, else the run's), ``kind`` ("periodic", "no
    impact", "chatter or sticking", "not periodic"), ``period_multiple`` (0 if not periodic),
    ``impacts_per_period``, ``state`` (x, ẋ, z, ẏ) at the forcing phase of the run's end, and
    ``stable`` (the shot orbit's multipliers; None where not shot)."""

    omega: float
    amplitude: float
    kind: str
    period_multiple: int
    impacts_per_period: float
    state: tuple[float, float, float, float]
    stable: bool | None = None
    #: the largest Lyapunov exponent [1/s] of a motion that does not repeat, and half the range
    #: of its estimates over LYAPUNOV_BLOCKS consecutive stretches (None where not computed)
    lyapunov: float | None = None
    lyapunov_spread: float | None = None

    def as_dict(self) -> dict[str, Any]:
        return {k: v for k, v in self.__dict__.items() if k != "state"}


@dataclass
class Coverage:
    """:func:`coverage`'s outcome: ``attractors`` found by the multi-start at ``frequencies``
    [rad/s] from ``starts`` initial states each (and, refined, between them), each periodic one
    ``traced`` or not (same order as the periodic ones); ``check``: the same measured at a
    second, independent set of frequencies drawn at random inside the band
    (:func:`check_frequencies`, seed ``seed``), whose landings start no branch.  ``share`` is the
    lower of the two shares traced / periodic (NaN with none): it claims no more than either set
    of samples shows."""

    attractors: list[Attractor] = field(default_factory=list)
    traced: list[bool] = field(default_factory=list)
    frequencies: tuple[float, ...] = ()
    starts: int = STARTS
    check: Coverage | None = None
    seed: int | None = None

    @property
    def periodic(self) -> list[Attractor]:
        return [a for a in self.attractors if a.kind == "periodic"]

    @property
    def grid_share(self) -> float:
        """traced / periodic among this set's own landings (NaN with none)."""
        return sum(self.traced) / len(self.traced) if self.traced else math.nan

    @property
    def share(self) -> float:
        shares = [self.grid_share, self.check.grid_share if self.check else math.nan]
        shares = [v for v in shares if not math.isnan(v)]
        return min(shares) if shares else math.nan

    @property
    def missed(self) -> list[Attractor]:
        """The attractors not on a traced branch: periodic ones missed, and every motion whose
        kind shooting cannot follow (UNTRACEABLE)."""
        periodic = [a for a, t in zip(self.periodic, self.traced, strict=True) if not t]
        return periodic + [a for a in self.attractors if a.kind in UNTRACEABLE]

    def as_dict(self) -> dict[str, Any]:
        out = {
            "share": None if math.isnan(self.share) else self.share,
            "grid_share": None if math.isnan(self.grid_share) else self.grid_share,
            "frequencies": list(self.frequencies),
            "starts": self.starts,
            "attractors": len(self.attractors),
            "periodic": len(self.periodic),
            "missed": [a.as_dict() for a in self.missed],
        }
        if self.check is not None:
            out["check"] = {"seed": self.seed, **self.check.as_dict()}
            del out["check"]["share"]
        return out


#: The independent check of a curve's coverage: this many frequencies drawn uniformly inside the
#: band by a generator of this seed (the same for every band: stated, reproducible).
CHECK_FREQUENCIES, CHECK_SEED = 5, 2026


def check_frequencies(band: tuple[float, float], n: int = CHECK_FREQUENCIES,
                      seed: int = CHECK_SEED) -> np.ndarray:  # fmt: skip
    """The coverage's check frequencies [rad/s]: ``n`` drawn uniformly inside ``band`` by
    ``numpy.random.default_rng(seed)``, sorted."""
    return np.sort(np.random.default_rng(seed).uniform(band[0], band[1], n))


def frequencies(band: tuple[float, float], n: int = FREQUENCIES) -> np.ndarray:
    """The multi-start's frequencies: ``n`` evenly inside ``band`` [rad/s], ends excluded."""
    return np.linspace(band[0], band[1], n + 2)[1:-1]


def initial_states(
    system: ImpactSystem, forcing: Forcing
) -> list[tuple[float, float, float, float]]:
    """Initial states (x, ẋ, z, ẏ): rest; the primary displaced by A with the impact mass near
    either wall; the primary moving through zero at ΩA with the impact mass moving against it.
    A is the primary's linear amplitude at Ω (Eq. F1), at most two clearances."""
    h = system.gap / 2.0
    w = forcing.omega
    A = min(float(linear_amplitude(system, forcing, w)), 4.0 * h)
    return [(0.0, 0.0, 0.0, 0.0), (A, 0.0, 0.9 * h, 0.0), (-A, 0.0, -0.9 * h, 0.0),
            (0.0, w * A, 0.0, -w * A)][:STARTS]  # fmt: skip


def attractor(
    system: ImpactSystem, forcing: Forcing, e: Any, start, *, exponent: bool = True
) -> Attractor:
    """The steady motion a run from ``start`` (x, ẋ, z, ẏ) settles on (module text); without
    ``exponent`` a motion that does not repeat is "not periodic", its Lyapunov exponent not
    computed (for a caller that needs only the periodic ones)."""
    x, v, z, u = start
    n = settling_periods(system, forcing, KEPT, WARMUP + KEPT)
    res = simulate_forced(system, forcing, **simulation_arguments(e), periods=n, discard=n - KEPT,
                          x0=x, xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
    st = res.steady
    fx, fv, fy, fu = res.final_state
    end = (fx, fv, fy - fx, fu)
    if st.impacts_per_period == 0 and not res.final_stuck:
        return Attractor(forcing.omega, st.amplitude, "no impact", 0, 0.0, end)
    if not st.periodic:
        h = system.gap / 2.0
        drifting = (
            st.impacts_per_period < 1 and linear_amplitude(system, forcing, forcing.omega) < h
        )
        if drifting:
            return Attractor(forcing.omega, st.amplitude, "not settled", 0,
                             st.impacts_per_period, end)  # fmt: skip
        lam = spread = None
        kind = "not settled" if st.settling else "not periodic"
        if is_rigid(e) and exponent:
            try:
                lam, spread = lyapunov(system, forcing, e, end)
            except SymimpactError:  # a zero-speed impact on the way: no monodromy there
                pass
        if lam is not None:
            kind = _kind(lam, spread, forcing.period)
            if kind == "quasi-periodic" and st.settling:
                kind = "not settled"  # a zero exponent while the section still draws in
        return Attractor(forcing.omega, st.amplitude, kind, 0, st.impacts_per_period, end,
                         lyapunov=lam, lyapunov_spread=spread)  # fmt: skip
    k = st.period_multiple
    chatter = Attractor(forcing.omega, st.amplitude, "chatter or sticking", k,
                        st.impacts_per_period, end)  # fmt: skip
    if k > min(MAX_SHOT_PERIODS, MAX_PERIODS):
        return Attractor(forcing.omega, st.amplitude, "periodic", k, st.impacts_per_period, end)
    try:
        orbit = shoot(system, forcing, e, end, periods=k)
    except SymimpactError:
        return chatter
    least = least_period(system, forcing, e, orbit.state, k, orbit.amplitude)
    if least < k:  # a slow transient read as a longer period: the orbit itself repeats sooner
        orbit = shoot(system, forcing, e, orbit.state, periods=least)
        k = least
    return Attractor(forcing.omega, orbit.amplitude, "periodic", k, orbit.impacts_per_period,
                     orbit.state, orbit.stable)  # fmt: skip


def least_period(
    system: ImpactSystem, forcing: Forcing, e: Any, state: Any, k: int, amplitude: float
) -> int:
    """The least number of forcing periods after which the period-``k`` orbit through ``state``
    (x, ẋ, z, ẏ) repeats: the smallest divisor d of k whose stroboscopic map P^d (Eq. F1, F2)
    brings the state back to 1e-8 of its scales (``amplitude`` [m], Ω times it, and d/2)."""
    s = np.asarray(state, dtype=float)
    a = max(amplitude, 1e-12)
    scale = np.array([a, a * forcing.omega, system.gap / 2.0, a * forcing.omega])
    for d in range(1, k):
        if k % d:
            continue
        try:
            ps = monodromy(system, forcing, e, s, d, jacobian=False)[0]
        except SymimpactError:
            continue
        if np.max(np.abs((ps - s) / scale)) < 1e-8:
            return d
    return k


#: Periods of a non-periodic motion's Poincaré section searched for close returns
#: (:func:`close_returns`), and how many distinct returns per period k are kept: the chaotic
#: motion at 28.75 rad/s on the README system holds eight period-3 orbits among the ten best
#: returns of 1000 periods, one of them on the branch through the stable period-3 window at
#: 28.125–28.199 rad/s (not among the four best returns of 300 periods).
RETURN_PERIODS, RETURNS = 1000, 10
#: Two returns are distinct when their states differ by more than this share of the section's
#: spread (its standard deviation per coordinate) in some coordinate.
RETURNS_APART = 0.05


def section_states(
    system: ImpactSystem, forcing: Forcing, e: Any, state: Any, periods: int = RETURN_PERIODS
) -> np.ndarray:
    """The Poincaré section of the motion from ``state`` (x, ẋ, z, ẏ) at the forcing phase of
    ``forcing``, contact ``e`` (a restitution: rigid impacts): ``periods`` + 1 states, one a forcing
    period apart (the stroboscopic map, Eq. F1 between impacts and Step 9's impact law,
    :func:`symimpact.forced.monodromy` without its Jacobian).  Raises where the map does."""
    out = [np.asarray(state, dtype=float)]
    for _ in range(periods):
        out.append(monodromy(system, forcing, e, out[-1], 1, jacobian=False)[0])
    return np.array(out)


def close_returns(sections: np.ndarray, k: int, count: int = RETURNS) -> list[np.ndarray]:
    """Starts for shooting the period-``k`` orbits embedded in a motion that does not repeat,
    from its Poincaré ``sections`` (:func:`section_states`): the ``count`` states s_n whose
    return s_(n+k) comes closest, max over the coordinates of abs(s_(n+k) − s_n) in units of
    the section's spread, apart by RETURNS_APART from each other and from the k − 1 states that
    follow each, which are the same cycle at another phase.  This is the method of close
    returns: a chaotic attractor is the closure of the unstable periodic orbits in it, and its
    motion shadows each for a while (Auerbach, Cvitanović, Eckmann, Gunaratne and Procaccia,
    "Exploring chaotic motion through periodic orbits", Phys. Rev. Lett. 58, 2387, 1987).  A
    stable window of period k inside a chaotic band is the continuation of such an orbit."""
    if k < 1 or len(sections) <= k:
        return []
    scale = np.std(sections, axis=0)
    scale = np.where(scale > 0, scale, 1.0)
    gaps = np.max(np.abs((sections[k:] - sections[:-k]) / scale), axis=1)
    picked: list[int] = []
    for n in np.argsort(gaps, kind="stable"):
        # another phase of a picked return's cycle is the same orbit
        if all(np.max(np.abs((sections[n] - sections[j + i]) / scale)) > RETURNS_APART
               for j in picked for i in range(k)):  # fmt: skip
            picked.append(int(n))
            if len(picked) == count:
                break
    return [sections[n] for n in picked]


def lyapunov(
    system: ImpactSystem, forcing: Forcing, e: Any, state: Any,
    periods: int = LYAPUNOV_PERIODS,
) -> tuple[float, float]:  # fmt: skip
    """The largest Lyapunov exponent λ [1/s] of the motion from ``state`` (x, ẋ, z, ẏ) at the
    forcing phase of ``forcing``, rigid impacts of restitution ``e``: a tangent vector carried
    LYAPUNOV_CHUNK periods at a time by the stroboscopic map's Jacobian (Step 8's flight
    transition matrices and Step 9's saltation matrices at the impacts,
    :func:`symimpact.forced.monodromy`) and renormalised, λ = Σ ln‖v‖ / (``periods``·T); with
    half the range of the estimates over
    LYAPUNOV_BLOCKS equal stretches; chatter and sticking are carried through
    (:func:`symimpact.forced.orbits.shooting.rigid_monodromy`).  Raises at an impact at zero relative
    speed, which has no saltation matrix."""
    s = np.array(state, dtype=float)
    v = np.ones(4) / 2.0
    sizes = [len(b) for b in np.array_split(np.arange(periods), LYAPUNOV_BLOCKS)]
    blocks = []  # each stretch's mean rate [1/s]
    for size in sizes:
        growth = 0.0
        for done in range(0, size, LYAPUNOV_CHUNK):
            n = min(LYAPUNOV_CHUNK, size - done)
            s, J, _ = monodromy(system, forcing, e, s, n)
            v = J @ v
            norm = float(np.linalg.norm(v))
            growth += math.log(norm)
            v /= norm
        blocks.append(growth / (size * forcing.period))
    lam = float(np.dot(blocks, sizes)) / periods
    return lam, 0.5 * (max(blocks) - min(blocks))


def _kind(lam: float, spread: float, period: float) -> str:
    """ "chaotic" for an exponent above zero by more than LYAPUNOV_ZERO a period and three
    spreads, "quasi-periodic" for one within LYAPUNOV_ZERO a period of zero, "not settled" for a
    negative one (the motion still converges onto something periodic)."""
    if lam * period > LYAPUNOV_ZERO and lam > 3 * spread:
        return "chaotic"
    if abs(lam) * period <= LYAPUNOV_ZERO:
        return "quasi-periodic"
    return "not settled" if lam < 0 else "not periodic"


#: With ``refine``, the multi-start's interval between two neighbouring frequencies (or a band's
#: end and its nearest frequency) is halved where one initial state lands on motions of another
#: kind, period or count of impacts at its ends, down to this share of the band: the stable
#: windows of a resonance broken up by chatter (the README's 29–33 rad/s) are narrower than the
#: multi-start's spacing.
REFINE = 1.0 / 256
#: Where one of the two ends lands on a motion that does not repeat, down to this share: the
#: windows inside chaotic motion are narrower still.  On benchmark 6's band three stable motions
#: lie in windows that 1/256 passes over (period 3 at 28.18, 5 impacts at 29.88 and 14 at
#: 30.67 rad/s, the last 0.0096 rad/s wide), each found at 1/1024 from intervals with a chaotic
#: end; the multi-start on 2 processes takes 6.3 s there against 2.5 s at 1/256.
REFINE_IRREGULAR = 1.0 / 1024


#: The landings beside which the refinement goes on to REFINE_IRREGULAR: motions that do not
#: repeat after the run has settled (a run still settling, or an impact mass drifting with fewer
#: than one impact a period, "not settled", is not chaos and hides no window).
IRREGULAR = ("chaotic", "quasi-periodic", "not periodic")


def _finest(la: Attractor | None, lb: Attractor | None) -> float:
    """The share of the band below which an interval whose ends land on ``la`` and ``lb`` is not
    halved: REFINE_IRREGULAR where either does not repeat once settled (IRREGULAR), else
    REFINE."""
    irregular = any(a is not None and a.kind in IRREGULAR for a in (la, lb))
    return REFINE_IRREGULAR if irregular else REFINE


def _landing_key(a: Attractor | None) -> tuple | None:
    """What a landing is, for the refinement: its kind (a motion that does not repeat counts as
    one kind, whether or not its exponent was computed), period and impacts a period."""
    if a is None:
        return None
    repeats = a.kind not in ("chaotic", "quasi-periodic", "not periodic", "not settled")
    kind = a.kind if repeats else "not periodic"
    return kind, a.period_multiple, round(a.impacts_per_period, 6)


def _landings(job: tuple) -> tuple[list, list, list]:
    """One initial state's runs of :func:`attractors`: its landing at each multi-start frequency
    (None where the run failed), and with ``refine`` the shot periodic landings at the band's
    ends and at the halving points, each as (Ω, attractor) in the order they were found."""
    system, forcing, e, band, ws, j, refine = job
    landing: dict[float, Attractor | None] = {}
    base: list[Attractor | None] = []
    for w in ws:
        f = forcing.at(w)
        try:
            a = attractor(system, f, e, initial_states(system, f)[j])
        except SymimpactError:
            a = None
        _pool.counted(0)  # one landing of the multi-start's grid (its progress)
        landing[w] = a
        base.append(a)
    ends: list[tuple[float, Attractor]] = []
    halved: list[tuple[float, Attractor]] = []
    if not refine:
        return base, ends, halved
    width = band[1] - band[0]

    def landed(w: float, into: list) -> Attractor | None:
        """Where the initial state lands at ``w``, its exponent not computed; a shot periodic
        landing is kept ``into``."""
        f = forcing.at(w)
        try:
            a = attractor(system, f, e, initial_states(system, f)[j], exponent=False)
        except SymimpactError:
            return None
        finally:
            _pool.counted(1)  # one run of the refinement (its progress)
        if a.kind == "periodic" and a.stable is not None:
            into.append((w, a))
        return a

    # the band's ends bound the first and last intervals, which are halved like the others
    # (a stable window between the last frequency and the band's end is otherwise never run)
    for w in band:
        landing[w] = landed(w, ends)
    stack = [(a, b, landing.get(a), landing.get(b))
             for a, b in itertools.pairwise([band[0], *ws, band[1]])]  # fmt: skip
    while stack:
        a, b, la, lb = stack.pop()
        if _landing_key(la) == _landing_key(lb) or b - a < 2 * _finest(la, lb) * width:
            continue
        m = 0.5 * (a + b)
        lm = landed(m, halved)
        stack += [(a, m, la, lm), (m, b, lm, lb)]
    return base, ends, halved


def attractors(
    system: ImpactSystem, forcing: Forcing, e: Any, band: tuple[float, float],
    n: int = FREQUENCIES, *, refine: bool = False, workers: int | None = None,
) -> list[Attractor]:  # fmt: skip
    """The attractors of the multi-start over ``band`` (module text), each distinct one at a
    frequency once, in the order of the frequencies.  With ``refine``, each initial state's
    interval between neighbouring frequencies (and between each of the band's ends and its nearest
    frequency) is halved where its landings at the ends differ (:data:`REFINE`, and
    :data:`REFINE_IRREGULAR` where one of them does not repeat); the shot
    periodic landings at the band's ends and the halving points are added (those of at
    most MAX_SHOT_PERIODS periods, which a curve traces; a motion that does not repeat there is
    not added: its exponent is not computed).  The initial states' runs are independent: they
    are spread over ``workers`` local processes (None: one per core, at most STARTS; one, or a
    call from a worker or another thread: here), with the same outcome in the same order."""
    return MultiStart(system, forcing, e, band, n, refine=refine, workers=workers).result()


class MultiStart:
    """:func:`attractors` started on the workers at once (the caller goes on meanwhile: a curve
    traces its other starts); :meth:`result` waits and gives the attractors, :meth:`cancel`
    ends the workers."""

    def __init__(self, system: ImpactSystem, forcing: Forcing, e: Any,
                 band: tuple[float, float], n: int = FREQUENCIES, *, refine: bool = False,
                 workers: int | None = None, ws: Any = None) -> None:  # fmt: skip
        if workers is None:
            workers = min(STARTS, os.cpu_count() or 1)
        workers = checks.whole_number("workers", workers, 1, 1024)
        self.ws = tuple(float(w) for w in (frequencies(band, n) if ws is None else ws))
        # the warm-up before the workers fork: one initial state at one frequency
        self.pending = _pool.Pending(_landings, [(system, forcing, e, band, self.ws, j, refine)
                                                 for j in range(STARTS)], workers,
                                     warm=(system, forcing, e, band, self.ws[:1], 0, False))  # fmt: skip

    def cancel(self) -> None:
        """End the workers without waiting for their runs."""
        self.pending.cancel()

    @property
    def runs(self) -> int:
        """The landings of the grid: one an initial state and frequency."""
        return STARTS * len(self.ws)

    def counts(self) -> tuple[int, int]:
        """(landings of the grid, runs of the refinement) ended so far."""
        grid, refined = self.pending.counts()[:2]  # (kinds 0 and 1 of _pool.counted)
        return grid, refined

    def result(self, on_wait: Any = None) -> list[Attractor]:
        """The attractors (as :func:`attractors` returns them), once every run has ended;
        ``on_wait()`` is called while they run (:meth:`symimpact._pool.Pending.result`)."""
        return _gathered(self.ws, self.pending.result(on_wait))


def _gathered(ws: tuple[float, ...], parts: list) -> list[Attractor]:
    """The initial states' landings (:func:`_landings`), each distinct attractor at a frequency
    once."""
    # gathered in the order one process would find them: by frequency and then initial state,
    # then the band ends' and the halvings' landings, initial state by initial state
    runs: dict[float, list[Attractor]] = {w: [] for w in ws}
    for i, w in enumerate(ws):
        runs[w] += [base[i] for base, _, _ in parts if base[i] is not None]
    for w, a in [wa for _, ends, _ in parts for wa in ends] + [
        wa for _, _, halved in parts for wa in halved
    ]:
        runs.setdefault(w, []).append(a)
    found: list[Attractor] = []
    for w in sorted(runs):
        here: list[Attractor] = []
        for a in runs[w]:
            # a periodic motion found again: the same period and amplitude to 1e-9; a chaotic,
            # quasi-periodic or not periodic one: its amplitude is a sample of its envelope, so
            # the same kind within 5 % is the same attractor (the largest sample kept)
            tol = 5e-2 if a.kind in UNTRACEABLE else 1e-9
            same = [i for i, b in enumerate(here)
                    if b.kind == a.kind and b.period_multiple == a.period_multiple
                    and abs(b.amplitude - a.amplitude) <= tol * max(a.amplitude, 1e-300)]  # fmt: skip
            if not same:
                here.append(a)
            elif a.amplitude > here[same[0]].amplitude:
                here[same[0]] = a
        found += here
    return found
