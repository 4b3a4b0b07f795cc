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

#: Where each name of the package lives: imported on first use, so that a command loads only
#: the modules it runs (the continuation and SciPy's optimisers cost a simulation 0.6 s).
_WHERE = {
    "CompliantContact": "contact_law",
    "Forcing": "forcing",
    "ForcedResult": "simulation", "Steady": "simulation", "simulate_forced": "simulation",
    "steady_state": "simulation",
    "Bifurcation": "orbits.continuation", "Branch": "orbits.continuation",
    "BranchPoint": "orbits.continuation", "continue_orbit": "orbits.continuation",
    "trace_branch": "orbits.continuation",
    "PeriodicOrbit": "orbits.periodic", "periodic_orbits": "orbits.periodic",
    "RigidLimitRow": "orbits.rigid_limit", "rigid_limit": "orbits.rigid_limit",
    "ShootingOrbit": "orbits.shooting", "monodromy": "orbits.shooting",
    "settled_state": "orbits.shooting", "shoot": "orbits.shooting",
    "shoot_from_rest": "orbits.shooting",
    "Backbone": "orbits.slow_flow", "BestClearance": "orbits.slow_flow",
    "SlowFlowResponse": "orbits.slow_flow", "backbone": "orbits.slow_flow",
    "best_clearance": "orbits.slow_flow", "slow_flow_responses": "orbits.slow_flow",
    "Record": "loads.records", "random_record": "loads.records", "shock_record": "loads.records",
    "sweep_record": "loads.records",
    "RecordResponse": "loads.record_flight", "primary_response": "loads.record_flight",
    "srs": "loads.record_flight",
}  # fmt: skip


def __getattr__(name: str):
    """A name of the package, from its module on first use (:data:`_WHERE`)."""
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(f"{__name__}.{_WHERE[name]}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(list(globals()) + __all__)


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
