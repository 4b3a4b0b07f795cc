"""One answer everywhere (issue 80, item 3): ``design`` prints its answer first, and its JSON,
its CSV (the refined row, flagged) and its figure hold that same refined clearance; ``frf``
prints its peak first; both JSONs name the answer ``peak``, ``baseline_peak`` and
``reduction``, and the reduction in dB is 20·log₁₀ of the amplitudes' ratio."""

from __future__ import annotations

import csv
import json
import math

import pytest

from symimpact.cli import main

#: The README's system, a band of two frequencies and three clearances (about 20 s a run on one
#: core: 13 designs, then e ± 0.1).  With 40, 50 and 60 mm the best lay beyond the grid and the
#: walk past it took 19 designs, 64 s a run.
DESIGN = ["design", "--M", "1", "--K", "1000", "--C", "0.5", "--m", "0.05", "--force", "2 N",
          "--contact", "rigid", "--e", "0.6", "--omega-range", "31:32:1", "--gaps",
          "60 mm,75 mm,90 mm", "--multistart", "0", "--tolerance", "2 mm", "--quiet",
          "--workers", "1"]  # fmt: skip


@pytest.fixture(scope="module")
def design(tmp_path_factory):
    folder = tmp_path_factory.mktemp("design")
    argv = [*DESIGN, "--csv", str(folder / "d.csv"), "--plot", str(folder / "d.png")]
    return argv, folder


def test_the_design_answer_is_the_same_in_text_json_and_csv(design, capsys):
    argv, folder = design
    assert main(argv) == 0
    text = capsys.readouterr().out
    assert main([*DESIGN, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    with open(folder / "d.csv") as f:
        rows = list(csv.DictReader(f))
    refined = [r for r in rows if r["refined"] == "True"]
    assert len(refined) == 1 and len(rows) == 4  # three grid rows, then the refined one
    r = refined[0]
    (best,) = out["best"]
    # the CSV's refined row is the JSON's best and its answer, to the last digit (SI)
    assert float(r["gap [m]"]) == best["gap"] == out["peak"]["gap"]
    assert float(r["tolerance [m]"]) == best["tolerance"] == out["peak"]["tolerance"] == 0.002
    assert float(r["peak_amplitude [m]"]) == best["peak_amplitude"] == out["peak"]["amplitude"]
    assert float(r["peak_omega [rad/s]"]) == out["peak"]["omega"]
    assert out["baseline_peak"]["amplitude"] == float(r["baseline_peak [m]"])
    peak, base = out["peak"]["amplitude"], out["baseline_peak"]["amplitude"]
    assert out["reduction"] == pytest.approx(1 - peak / base, rel=1e-15)
    # the text's first line states that answer, in mm, %, and dB
    first = text.splitlines()[0]
    assert first.startswith(f"best clearance: d {best['gap'] * 1e3:.0f} ± 2 mm;")
    assert f"worst case {peak * 1e3:.5g} mm" in first
    assert f"without the damper {base * 1e3:.5g} mm" in first
    assert f"reduction {100 * (1 - peak / base):.1f} %" in first
    assert f"({20 * math.log10(base / peak):.2f} dB)" in first
    assert (folder / "d.png").stat().st_size > 10_000
    # the grid rows are flagged, with no tolerance
    assert all(r["refined"] == "False" and r["tolerance [m]"] == "" for r in rows[:3])


def test_frf_states_its_peak_first_with_the_same_keys(capsys):
    argv = ["frf", *DESIGN[1:15], "--gap", "20 mm", "--omega-range", "30:34:1", "--no-sweeps",
            "--multistart", "0", "--quiet"]  # fmt: skip
    assert main(argv) == 0
    first, second, third = capsys.readouterr().out.splitlines()[:3]
    assert first.startswith("peak with the damper:")
    assert second.startswith("peak without the damper:")
    assert main([*argv, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert {"peak", "baseline_peak", "reduction"} <= set(out)
    ratio = out["peak"]["amplitude"] / out["baseline_peak"]["amplitude"]
    assert third == (f"reduction: {100 * out['reduction']:.4g} % "
                     f"({-20 * math.log10(ratio):.2f} dB)")  # fmt: skip
