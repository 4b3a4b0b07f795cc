"""Loads beyond a sine: sampled records of force or base acceleration and the responses to them.

Records (random of a PSD, shocks, sine sweeps), the primary's exact linear response to a record
(Step 16, Eq. F8) and its shock-response spectrum, the event-driven response with a damper,
random ensembles and their statistics, shocks, sweeps, and the estimate of a run's time.
"""
