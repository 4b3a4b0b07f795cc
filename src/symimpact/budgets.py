"""The work budgets of the forced computations: every run, Newton iteration and continuation stops
at one of these and says which, so that every command ends (a clearance far below the motion, a
chattering or near-grazing orbit, an enormous run) within a bound known before it starts.

Plain numbers with no imports, so that ``symimpact --help`` states them without loading the
simulation; the modules that enforce each one import it from here.
"""

from __future__ import annotations

#: A rigid run stops, saying so, past this many impacts (about a microsecond each).
MAX_EVENTS = 10_000_000
#: A compliant run integrates every contact (compiled, 0.1–1 ms each): it stops, saying so, past
#: this many (a minute or two of work) rather than running on for hours.
MAX_CONTACTS = 200_000
#: The contacts' work budget of one compliant run, in evaluations of the equations of motion
#: (about 0.1 µs each).
RHS_BUDGET = 500_000_000
#: The longest run, in natural periods of the primary 2π√(M/K): flight is evaluated 16 times per
#: natural period, so 10⁶ of them are seconds of work; a slower forcing (Ω → 0) or more periods
#: would run for hours and is refused at once.
MAX_NATURAL_PERIODS = 1_000_000
#: Shooting follows no rigid orbit with more impacts a forcing period that do not accumulate
#: (a chatter sequence that does is taken to its accumulation point in closed form).
MAX_IMPACTS_PER_PERIOD = 1000
#: Shooting follows a compliant orbit through as many contacts a forcing period as it has, each
#: integrated with its variational equations, within this many evaluations of their equations
#: a period (about 0.1 µs each, so 0.2 s a period: 600 to 1600 contacts of 1300-3400
#: evaluations each, measured on Hunt–Crossley orbits of 2 to 94 contacts a period): a chatter of
#: stiff contacts that does not end (cubic a = 1e20 N/m³) would otherwise integrate the run's
#: whole budget at every Newton step.
SHOOTING_EVALUATIONS_PER_PERIOD = 2_000_000
#: Newton's iterations of one shooting.
MAX_ITER = 30
#: Continuation points of one branch in one direction.
MAX_POINTS = 2000
#: The longest a command under a sampled load (random, shock, sweep-sine) runs without
#: ``--no-budget``, by the estimate it makes before it starts [s]
#: (:mod:`symimpact.forced.loads.record_cost`).
MAX_SECONDS = 3600.0
#: Estimates from this many seconds up are printed before the run starts.
SAY_SECONDS = 10.0


def text() -> str:
    """The budgets in words, for the forced commands' ``--help``."""
    return (
        "Every run ends within its budget, and a run that meets one says which in one line: "
        f"a simulation at most {MAX_NATURAL_PERIODS:.0e} natural periods of the primary and "
        f"{MAX_EVENTS:.0e} rigid impacts or {MAX_CONTACTS:,} compliant contacts "
        f"({RHS_BUDGET:.0e} evaluations of their equations); shooting at most {MAX_ITER} Newton "
        f"steps and {MAX_IMPACTS_PER_PERIOD} rigid impacts ({SHOOTING_EVALUATIONS_PER_PERIOD:.0e} "
        "evaluations of the compliant contacts' equations) a period; a branch at most "
        f"{MAX_POINTS} continuation points each way."
    )
