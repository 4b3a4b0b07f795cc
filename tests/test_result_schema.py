"""One result schema for one mode and for structures (issue 79, item 3): ``simulate --json``
answers "how far does each point move, how often does each damper strike, does the energy
close" with the same keys for the paper's primary and for a structure file, and the primary's
values under them are its own (``steady.amplitude``, its impacts), against a structure of one mode
of shape 1 carrying the same damper: the same motion (the engine runs the primary as N = K = 1)."""

from __future__ import annotations

import json

import pytest

from symimpact.cli import main

SHARED = {"amplitudes", "impacts", "energy", "t_end", "notes"}
#: The README's primary (M 1 kg, K 1000 N/m, C 0.5 N s/m) with its 50 g damper in 20 mm, e 0.6.
PRIMARY = ["--M", "1 kg", "--K", "1000 N/m", "--C", "0.5 N*s/m", "--m", "50 g", "--gap", "20 mm",
           "--contact", "rigid", "--e", "0.6", "--force", "2 N", "--omega", "36 rad/s",
           "--periods", "60", "--discard", "40"]  # fmt: skip


def _json(capsys, argv):
    capsys.readouterr()
    assert main(argv) in (0, None)
    return json.loads(capsys.readouterr().out)


@pytest.fixture
def structure_file(tmp_path):
    """The same primary as a structure of one mode of shape 1 at 'primary' (ω = √(K/M),
    ζ = C/(2√(KM))) with the same damper and force."""
    import math

    zeta = 0.5 / (2 * math.sqrt(1000.0))
    path = tmp_path / "primary.json"
    path.write_text(json.dumps({
        "modes": [{"omega": math.sqrt(1000.0), "mass": 1.0, "zeta": zeta,
                   "shape": {"primary": 1.0}}],
        "dampers": [{"name": "damper", "at": "primary", "m": "50 g", "gap": "20 mm",
                     "contact": "rigid", "e": 0.6}],
        "force": {"at": "primary", "amplitude": "2 N"},
    }))  # fmt: skip
    return path


def test_one_mode_and_a_structure_answer_with_the_same_keys(capsys, structure_file):
    one = _json(capsys, ["simulate", *PRIMARY, "--json"])
    many = _json(capsys, ["simulate", "--structure", str(structure_file), "--omega", "36 rad/s",
                          "--periods", "60", "--discard", "40", "--json"])  # fmt: skip
    assert SHARED <= set(one) and SHARED <= set(many), (set(one), set(many))
    # the primary's own numbers under the shared keys
    assert one["amplitudes"] == {"primary": one["steady"]["amplitude"]}
    assert one["impacts"] == {"damper": one["n_impacts"]}
    # and the structure of one mode of shape 1 is the same motion: the same impacts, and the
    # same amplitude to the engine's rounding (its modal parameters K = ω²M and C = 2ζωM
    # recomputed from f and ζ: a few ulps, amplified by the impacts over 60 periods)
    assert set(many["amplitudes"]) == {"primary"} and set(many["impacts"]) == {"damper"}
    assert many["impacts"]["damper"] == one["impacts"]["damper"]
    assert many["amplitudes"]["primary"] == pytest.approx(one["amplitudes"]["primary"], rel=1e-9)
