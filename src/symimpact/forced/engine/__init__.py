"""The compiled engines of the forced response: event-driven runs, closed form between events.

The flights are the derivations' generated kernels (Step 8, Eq. F1; Step 16 for sampled records);
the events are rigid impacts (Step 9, Eq. F2) with chatter taken to its accumulation point and
sticking, or compliant contacts integrated (Eq. F4).  :mod:`._modal` runs a structure of N modes
with K dampers and stops (the paper's primary is N = K = 1); :mod:`._chain` differentiates a run
through its events (saltation matrices).  Nothing here checks its input: the modules above it do.
"""
