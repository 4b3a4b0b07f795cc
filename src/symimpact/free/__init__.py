"""Free vibration with impacts, the paper's own subject (Sect. 2–4).

- :mod:`._stepper` — the compiled event-driven stepper: free flight in closed form (Eq. 7),
  contact integrated by Dormand–Prince 5(4);
- :mod:`._batch` — its compiled figures of a run and the loop the maps run;
- :mod:`.contact` — one impact: the amplitude ratio B/A, the contact duration by four methods
  (Eq. 31–35), the contact motion and the restitution;
- :mod:`.simulation` — :func:`~.simulation.simulate`: the decay with impacts and what the paper
  measures on it (effectiveness, damping inclination);
- :mod:`.reference` — the same motion by ``scipy.integrate.solve_ivp``, for checks.

Imports come from :mod:`symimpact.model` and the generated kernels only.
"""
