"""Forced response of the primary with an impact damper (beyond the paper).

- :class:`Forcing`: a force F0·cos(Ωt + φ) on the main mass and/or base motion X_b·cos(Ωt + φ).
- :func:`simulate_forced`: event-driven simulation with rigid impacts (Eq. F1, F2), chatter and
  sticking, or with a compliant contact (cubic, Hertz, linear, Hunt–Crossley, Eq. F4) integrated
  with the forcing; its ``steady`` summary (amplitude, impacts per period, period of the motion).
- :func:`periodic_orbits`: the symmetric two-impact periodic motions in closed form (Eq. F3),
  admissibility and stability.
- :func:`rigid_limit`: compliant contacts stiffened with their damping set from e, against the
  rigid orbit they converge to.
- :func:`shoot`, :func:`shoot_from_rest`, :func:`settled_state`, :func:`monodromy`: periodic
  orbits by Newton's method on the stroboscopic map, with the monodromy carried through flights
  and rigid impacts (saltation matrices) or through compliant contacts (variational equations,
  the located onsets and exits differentiated), and their Floquet multipliers.
- :class:`CompliantContact`: a compliant law given in place of the restitution e to shooting,
  continuation, the frequency-response curve and the design map.
- :func:`continue_orbit`, :func:`trace_branch`: pseudo-arclength continuation of those orbits in
  Ω, d, F0, X_b or e (one direction, or both joined), with folds, branch points, period
  doublings, Neimark–Sacker points and grazings located.
- :func:`slow_flow_responses`, :func:`backbone`, :func:`best_clearance`: the 1:1 slow flow of a
  vibro-impact absorber (Eq. F5), for a light impact mass.
- :class:`Record`, :func:`random_record`, :func:`shock_record`, :func:`sweep_record`: loads
  beyond a sine as sampled records (random of a PSD, shocks, sine sweeps; a force or a base
  acceleration), and :func:`primary_response`, :func:`srs`: the primary's exact response to a
  record (Eq. F8, Step 16) and a record's shock-response spectrum.
"""

from .contact_law import CompliantContact
from .continuation import Bifurcation, Branch, BranchPoint, continue_orbit, trace_branch
from .forcing import Forcing
from .loads import Record, random_record, shock_record, sweep_record
from .periodic import PeriodicOrbit, periodic_orbits
from .record_flight import RecordResponse, primary_response, srs
from .rigid_limit import RigidLimitRow, rigid_limit
from .shooting import ShootingOrbit, monodromy, settled_state, shoot, shoot_from_rest
from .simulation import ForcedResult, Steady, simulate_forced, steady_state
from .slow_flow import (
    Backbone,
    BestClearance,
    SlowFlowResponse,
    backbone,
    best_clearance,
    slow_flow_responses,
)

__all__ = [
    "Backbone",
    "BestClearance",
    "Bifurcation",
    "Branch",
    "BranchPoint",
    "CompliantContact",
    "ForcedResult",
    "Forcing",
    "PeriodicOrbit",
    "Record",
    "RecordResponse",
    "RigidLimitRow",
    "ShootingOrbit",
    "SlowFlowResponse",
    "Steady",
    "backbone",
    "best_clearance",
    "continue_orbit",
    "monodromy",
    "periodic_orbits",
    "primary_response",
    "random_record",
    "rigid_limit",
    "settled_state",
    "shock_record",
    "shoot",
    "shoot_from_rest",
    "simulate_forced",
    "slow_flow_responses",
    "srs",
    "steady_state",
    "sweep_record",
    "trace_branch",
]
