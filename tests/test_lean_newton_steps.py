"""What the continuation's Newton steps skip, and what they must still get right.

A curve makes tens of thousands of one-period runs of 30 µs; around each one the checks of the
public entry, the energy ledger, a checked ``Forcing`` and the SIGINT deferral cost more than the
run.  The steps now call the checked work directly (``stroboscopic_map``), build the forcing at a
new frequency without converting it again (``Forcing.at``), form the ledger only when it is read,
and share one SIGINT deferral over the whole continuation (``_interrupt.stretch``).  Checked here
against the paths they bypass, and a SIGINT within a stretch against Python's own handling."""

from __future__ import annotations

import math
import signal

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from symimpact import _interrupt
from symimpact.errors import ParameterError
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.shooting import monodromy, stroboscopic_map
from symimpact.forced.simulation import _ledger
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


@given(
    omega=st.floats(0.1, 1e4),
    phase=st.one_of(st.none(), st.floats(-10.0, 10.0)),
    base=st.sampled_from(["F0", "X_b", "V_b", "A_b"]),
)
def test_forcing_at_a_new_frequency_equals_the_forcing_built_and_checked(omega, phase, base):
    amplitude = {"F0": 2.0, "X_b": 1e-3, "V_b": 0.05, "A_b": 9.80665}[base]
    f = Forcing(**{base: amplitude}, omega=30.0, phase=0.3)
    g = f.at(omega, phase)
    kept = {base: amplitude}
    built = Forcing(**kept, omega=omega, phase=0.3 if phase is None else phase)
    # every field the same, to the bit (the frequency in Hz, X_b from V_b or A_b included)
    assert g == built
    assert (g.freq, g.X_b, g.omega, g.phase) == (built.freq, built.X_b, built.omega, built.phase)


@pytest.mark.parametrize("omega", [0.0, -3.0, math.inf, math.nan])
def test_forcing_at_a_frequency_that_is_none_is_refused(omega):
    with pytest.raises(ParameterError, match="omega"):
        Forcing(F0=1.0, omega=30.0).at(omega)


def test_the_map_for_checked_arguments_equals_the_checked_monodromy():
    f = Forcing(F0=2.0, omega=34.0)
    s = (0.004, -0.05, 0.003, 0.2)
    for parameter in (None, "omega", "gap"):
        a = monodromy(SYSTEM, f, E, s, 2, parameter=parameter)
        b = stroboscopic_map(SYSTEM, f, E, s, 2, parameter=parameter)
        assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])
    # a state that is not finite, or beyond a wall, is still refused in one line
    with pytest.raises(ParameterError, match="state"):
        stroboscopic_map(SYSTEM, f, E, (math.nan, 0.0, 0.0, 0.0), 1)
    with pytest.raises(ParameterError, match="state"):
        stroboscopic_map(SYSTEM, f, E, (0.0, 0.0, 0.02, 0.0), 1)


def test_the_energy_ledger_formed_when_read_is_the_run_s_balance():
    res = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=34.0), e=E, periods=50, x0=0.01)
    assert "energy" not in res.__dict__  # not formed by the run
    final, ledger, potential, potential0 = res.ledger_terms
    expected = _ledger(SYSTEM, res.forcing, res.initial_state, final, ledger, potential,
                       potential0)  # fmt: skip
    assert res.energy == expected
    # the balance closes: the forcing's work less the dissipation is the change of energy
    assert res.energy["relative_residual"] < 1e-11
    assert res.as_dict()["energy"] == expected


@pytest.fixture
def python_sigint():
    """SIGINT handled by Python's own handler (a test worker may ignore it), restored after."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)


def test_a_sigint_within_a_stretch_is_raised_by_the_next_compiled_call(python_sigint):
    f = Forcing(F0=2.0, omega=34.0)
    s = (0.004, -0.05, 0.003, 0.2)
    wakeup = signal.set_wakeup_fd(-1)
    signal.set_wakeup_fd(wakeup)
    reached = []
    with pytest.raises(KeyboardInterrupt):
        with _interrupt.stretch():
            assert signal.getsignal(signal.SIGINT) is not signal.default_int_handler
            stroboscopic_map(SYSTEM, f, E, s, 1)  # no signal: the run's result is returned
            signal.raise_signal(signal.SIGINT)  # while Python runs: recorded, not raised
            reached.append(True)
            stroboscopic_map(SYSTEM, f, E, s, 1)  # raised here, before the run
            reached.append(False)
    assert reached == [True]
    # the handler and the wakeup descriptor the stretch replaced are back
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert signal.set_wakeup_fd(wakeup) == wakeup
    # and a later call defers on its own again
    assert np.all(np.isfinite(stroboscopic_map(SYSTEM, f, E, s, 1)[1]))


def test_a_sigint_at_a_stretch_s_end_is_raised_there(python_sigint):
    with pytest.raises(KeyboardInterrupt):
        with _interrupt.stretch():
            signal.raise_signal(signal.SIGINT)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_stretch_leaves_the_results_as_they_are(python_sigint):
    f = Forcing(F0=2.0, omega=34.0)
    s = (0.004, -0.05, 0.003, 0.2)
    alone = stroboscopic_map(SYSTEM, f, E, s, 3)
    with _interrupt.stretch():
        with _interrupt.stretch():  # nested: the outer one serves
            inside = stroboscopic_map(SYSTEM, f, E, s, 3)
    assert np.array_equal(alone[0], inside[0]) and np.array_equal(alone[1], inside[1])
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_a_process_forked_within_a_stretch_defers_on_its_own(python_sigint):
    """A child forked inside a stretch neither uses the parent's stretch (its pipe and handler
    are the parent's) nor is kept by it from opening its own."""
    import multiprocessing

    s = (0.004, -0.05, 0.003, 0.2)
    alone = stroboscopic_map(SYSTEM, Forcing(F0=2.0, omega=34.0), E, s, 2)[0]
    with _interrupt.stretch():
        parent = _interrupt._stretch.pid
        with multiprocessing.get_context("fork").Pool(1) as pool:
            result, own = pool.apply(_forked_map, (s,))
    assert np.array_equal(result, alone)
    assert own != parent


def _forked_map(s):
    """In the child: the map within a stretch of its own, and that stretch's process."""
    with _interrupt.stretch():
        out = stroboscopic_map(SYSTEM, Forcing(F0=2.0, omega=34.0), E, s, 2)[0]
        return out, _interrupt._stretch.pid
