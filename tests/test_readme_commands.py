"""Every command of the README runs as written and prints what the README shows (its three
tasks, issue 80), and every command of the guide's command-line block (``docs/guide.md``, moved
there from the README) runs and shows something worth looking at (issue 17, item 4): impacts
and a defined DI, figures and tables that are not empty."""

from __future__ import annotations

import json
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


README = (ROOT / "README.md").read_text(encoding="utf-8")


def _commands() -> list[str]:
    """The guide's block of commands, one a line once continuations are joined; its comment
    lines (each above its command) left out."""
    text = (ROOT / "docs" / "guide.md").read_text(encoding="utf-8")
    block = next(b for b in text.split("```bash\n")[1:] if "symimpact fit" in b.split("```")[0])
    block = block.split("```", 1)[0].replace("\\\n", " ")
    lines = [line.split("#", 1)[0].strip() for line in block.splitlines()]
    return [line for line in lines if line]


COMMANDS = _commands()


def test_the_block_holds_every_subcommand():
    assert [c.split()[1] for c in COMMANDS] == [
        "fit", "ritz", "ritz", "contact", "contact-duration", "simulate", "simulate", "simulate",
        "periodic", "periodic", "periodic", "periodic", "frf", "frf", "frf", "branch",
        "design", "design",
        "random", "shock", "sweep-sine", "sweep",
        "map",
    ]  # fmt: skip


def _marked(command: str):
    """The design commands (five clearances, each a whole curve over 17 frequencies, then Brent's
    method on the best one to 2 mm with its walk and e ± 0.1, 16 curves more: 160 s on 2 cores,
    warm, on 2026-12-07; the robust one, two clearances at three restitutions with Brent's method
    on each: about 40 s) run in the slow set, which CI runs as its second step."""
    slow = command.split()[1] == "design"
    return pytest.param(command, marks=pytest.mark.slow) if slow else command


@pytest.mark.parametrize("command", [_marked(c) for c in COMMANDS],
                         ids=lambda c: c.split()[1])  # fmt: skip
def test_readme_command_runs_and_shows_something(command, tmp_path):
    args = shlex.split(command)
    run = subprocess.run(
        [sys.executable, "-m", "symimpact.cli", *args[1:]],
        capture_output=True, text=True, cwd=tmp_path, timeout=600,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert "Traceback" not in run.stderr
    out = run.stdout
    sub = args[1]
    if sub == "fit":
        assert set(json.loads(out)) >= {"a", "b", "k1"}
    elif sub == "ritz" and "--modes" in args:  # the clamped–clamped beam's modes at midspan
        assert out.count("node") == 4 and "% short" in out  # modes 2 and 4: nodes
    elif sub == "simulate" and "--force" in args:  # forced: two impacts per period, period 1
        assert "2 impacts per period, periodic with 1 forcing period" in out
        (png,) = [a for a in args if a.endswith(".png")]
        assert (tmp_path / png).stat().st_size > 10_000
    elif sub == "periodic" and "hb" in args:  # H = 40 beside the exact orbit: 0.016 % apart
        error = float(re.search(r"amplitude error ([-+\d.e]+) %", out)[1])
        assert abs(error) < 0.05 and "shooting, the exact orbit: amplitude 6.87778 mm" in out
    elif sub == "periodic" and "shooting" in args:  # Ω 34: the stable asymmetric orbit
        assert "2 impacts per period, stable" in out
    elif sub == "frf" and "--base-acc" in args:  # the shaker: the textbook peak 0.862 mm × 50
        assert "peak without the damper: 43.154 mm at Ω 11.9964 Hz" in out and "rad/s" not in out
        assert (tmp_path / "shaker.png").stat().st_size > 10_000
    elif sub == "frf" and "force" in args:  # the force into the ground: F0 × max TR = 50 × 50.01
        assert "peak force without the damper: 2500.6 N at Ω" in out and "rad/s" not in out
        assert "peak force with the damper:" in out
    elif sub == "frf":  # the stable symmetric branch and its symmetry-breaking branch point
        assert "branch-point at Ω 34.53" in out
        assert (tmp_path / "frf.png").stat().st_size > 10_000
    elif sub == "branch":  # the symmetric orbit in d: its pitchfork (tests/test_branch_cli.py)
        assert "branch-point at gap = 14.637 mm" in out
        assert (tmp_path / "branch.png").stat().st_size > 10_000
    elif sub == "contact":  # steel on steel: ~1.5e10 N/m^1.5, plastic at 0.5 m/s
        k_hz = float(re.search(r"Hertz stiffness K_Hz\s+([\d.e+]+)", out)[1])
        assert 1e10 < k_hz < 2e10 and "[Thornton]" in out
    elif sub == "design" and "--e-samples" in args:  # robust: both best clearances stated
        assert "robust clearance (smallest worst case over e): d" in out
        assert "best clearance at the nominal e 0.5" in out
    elif sub == "design":  # five clearances: the best one is inside the range, refined
        best = re.search(r"best clearance: d ([\d.]+) ± 2 mm \(Brent's method", out)
        assert best and 80 < float(best[1]) < 160, out
        assert (tmp_path / "design.png").stat().st_size > 10_000
    elif sub == "periodic":  # Ω 38 rad/s: one stable admissible orbit and one unstable
        rows = [line.split() for line in out.splitlines()[2:]]
        assert [(r[3], r[4]) for r in rows] == [("yes", "yes"), ("yes", "no")]
    elif sub == "simulate":
        impacts = int(re.search(r"impacts (\d+)", out)[1])
        assert impacts > 0 and "DI —" not in out
        assert (tmp_path / "sim.png").stat().st_size > 10_000
        assert len((tmp_path / "sim.csv").read_text().splitlines()) > 100
    elif sub == "random":  # inelastic impacts: a reduction whose interval excludes zero
        lo = float(re.search(r"RMS displacement: .* reduction [\d.]+ % \(([-\d.]+)–", out)[1])
        assert lo > 0 and (tmp_path / "psd.png").stat().st_size > 10_000
    elif sub == "shock":
        assert re.search(
            r"peak displacement [\d.]+ mm with the damper, [\d.]+ mm alone \(\d+ impacts", out
        )
        assert (tmp_path / "srs.png").stat().st_size > 10_000
    elif sub == "sweep-sine":  # the run-up peaks below the primary alone's, both ways
        peaks = [float(v) for v in re.findall(r"peak ([\d.]+) mm", out)]
        alone = [float(v) for v in re.findall(r"alone ([\d.]+) mm", out)]
        assert len(peaks) == len(alone) == 2 and all(
            p < a for p, a in zip(peaks, alone, strict=True)
        )
        assert (tmp_path / "run-up.png").stat().st_size > 10_000
    elif sub in ("sweep", "map"):
        assert "in range" in out
        png = tmp_path / ("sweep.png" if sub == "sweep" else "heat.png")
        assert png.stat().st_size > 10_000
    else:
        assert out.strip()


# --- the README's three tasks ----------------------------------------------------------------


def _blocks(language: str) -> list[str]:
    """The README's fenced blocks of ``language``, in order."""
    return [b.split("```", 1)[0] for b in README.split(f"```{language}\n")[1:]]


def _task(word: str) -> tuple[list[str], list[str]]:
    """(the argv of the README's ``symimpact <word>`` task, the lines of the text block that
    follows it: what the README says the command prints)."""
    bash = next(b for b in _blocks("bash") if b.startswith(f"symimpact {word} "))
    after = README.split(bash, 1)[1]
    shown = after.split("```text\n", 1)[1].split("```", 1)[0]
    return shlex.split(bash.replace("\\\n", " ")), shown.strip().splitlines()


def _run(args: list[str], cwd: Path) -> str:
    run = subprocess.run([sys.executable, "-m", "symimpact.cli", *args[1:]], capture_output=True,
                         text=True, cwd=cwd, timeout=900)  # fmt: skip
    assert run.returncode == 0 and "Traceback" not in run.stderr, run.stderr
    return run.stdout


def _numbers(line: str) -> list[float]:
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", line)]


def test_the_readme_random_task_prints_what_the_readme_shows(tmp_path):
    """Task 2, the beam of the README's JSON block: the load line exactly (arithmetic: 0.25/95
    g²/Hz) and the closed form's line to its printed digits (a quadrature to 1e-10); each RMS line
    shown, found in the output by its label, with its numbers within 1 % (the ball's impacts are
    chaotic: the last bits of a CPU's arithmetic move a long run's RMS within its sampling
    spread, here a 95 % interval of ±2 %)."""
    (beam,) = _blocks("json")
    (tmp_path / "beam.json").write_text(beam)
    args, shown = _task("random")
    out = _run(args, tmp_path).splitlines()
    assert out[0] == shown[0]
    assert out[-1] == shown[-1]
    for said in shown[1:-1]:
        label = said.split(":")[0].split(" of ")[0]
        (got,) = [line for line in out if line.startswith(label)]
        assert re.sub(r"[\d.]+", "#", got) == re.sub(r"[\d.]+", "#", said)
        assert _numbers(got) == pytest.approx(_numbers(said), rel=0.01), (got, said)
    assert (tmp_path / "psd.png").stat().st_size > 10_000


@pytest.mark.slow  # a design map of ten clearances and its refinement: 1.5 minutes
def test_the_readme_design_task_prints_what_the_readme_shows(tmp_path):
    """Task 1: the answer line, the clearance and the primary alone's peak exactly (the grid,
    Brent's method to 0.5 mm and a linear resonance), the worst case and the reduction within
    0.2 % (a peak located on the refined design's curve: its last digits follow the engine's
    rounding); the figure and the CSV with the refined row written."""
    args, shown = _task("design")
    out = _run(args, tmp_path).splitlines()
    (said,) = shown
    assert out[0].split(";")[0] == said.split(";")[0]  # best clearance: d 9.1 ± 0.5 mm
    assert re.sub(r"[\d.]+", "#", out[0]) == re.sub(r"[\d.]+", "#", said)
    assert _numbers(out[0]) == pytest.approx(_numbers(said), rel=2e-3), (out[0], said)
    assert "without the damper 10.995 mm at Ω 11.999 Hz" in out[0]
    assert (tmp_path / "design.png").stat().st_size > 10_000
    assert ",True," in (tmp_path / "design.csv").read_text()


def test_the_readme_python_kernel_prints_what_its_comment_says():
    (block,) = _blocks("python")
    code, _, said = block.partition("  # ")
    value = eval(code.split("\n\n", 1)[1], {"closed_forms": __import__(
        "symimpact.generated.closed_forms", fromlist=["x"])})  # fmt: skip
    assert f"→ {value:.6g} s" in said


@pytest.mark.skipif(shutil.which("cc") is None, reason="no C compiler here (CI installs gcc)")
def test_the_readme_c_kernel_builds_and_prints_what_its_comment_says(tmp_path):
    (bash,) = [b for b in _blocks("bash") if b.startswith("symimpact export")]
    script = bash.replace("symimpact export", f"{sys.executable} -m symimpact.cli export", 1)
    run = subprocess.run(["bash", "-euo", "pipefail", "-c", script], capture_output=True,
                         text=True, cwd=tmp_path, timeout=300)  # fmt: skip
    assert run.returncode == 0, run.stderr
    said = bash.rsplit("# ", 1)[1].strip()
    assert run.stdout.strip().splitlines()[-1] == said == "0.150918 s"  # after export's line
