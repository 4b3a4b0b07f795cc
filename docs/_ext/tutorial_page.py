"""The tutorial page: design an impact damper for an aluminium cantilever.

Every command shown is run when the documentation is built and its real output is inserted, so
the numbers on the page are the package's, not typed in.
"""

from __future__ import annotations

import contextlib
import io
import textwrap
from collections.abc import Callable
from pathlib import Path

# The beam the tutorial designs for (inputs, not results): an aluminium strip 500 × 30 × 5 mm.
E, RHO, L, WIDTH, THICK = "70 GPa", "2700 kg/m^3", "0.5 m", 0.03, 0.005
I_AREA = WIDTH * THICK**3 / 12  # m^4
AREA = WIDTH * THICK  # m^2


def _py(code: str, env: dict) -> str:
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        exec(code, env)  # the tutorial's own code, shown verbatim on the page
    return buf.getvalue().rstrip()


#: Longest line of a code block: what the docs' content column shows without scrolling at a
#: 1000 px wide window (the docs test measures the rendered page).
CODE_COLUMNS = 64


def _command(argv: list[str]) -> str:
    """``$ symimpact …`` with its options wrapped (shell line continuations) to
    :data:`CODE_COLUMNS` columns, an option and its value kept together."""
    words = ["$ symimpact", argv[0]]
    i = 1
    while i < len(argv):
        a = argv[i]
        if a.startswith("--") and i + 1 < len(argv) and not argv[i + 1].startswith("--"):
            v = argv[i + 1]
            words.append(f'{a} "{v}"' if " " in v else f"{a} {v}")
            i += 2
        else:
            words.append(a)
            i += 1
    lines, current = [], words[0]
    for w in words[1:]:
        if len(current) + 1 + len(w) + 2 > CODE_COLUMNS:
            lines.append(current + " \\")
            current = "    " + w
        else:
            current += " " + w
    lines.append(current)
    return "\n".join(lines)


def tutorial_page(folder: Path, run_cli: Callable[[list[str]], str]) -> str:
    folder.mkdir(parents=True, exist_ok=True)
    out = ["# Tutorial: an impact damper for an aluminium cantilever", ""]
    out += [
        "We design a damper for an aluminium strip clamped at one end: length 500 mm, width "
        "30 mm, thickness 5 mm (E = 70 GPa, ρ = 2700 kg/m³). The loose mass sits in a box at "
        "the tip. Each step is shown twice, on the command line and in Python; every output "
        "below was produced by the package when this page was built.",
        "",
        "## 1. From the beam to K and M (Eq. 1–6)",
        "",
        f"I = b·h³/12 = {I_AREA:.6g} m⁴ and A = b·h = {AREA:.6g} m².",
        "",
    ]
    argv = ["ritz", "--E", E, "--I", f"{I_AREA:.6g}", "--rho", RHO, "--A", f"{AREA:.6g}",
            "--L", L]  # fmt: skip
    out += ["```console", _command(argv), run_cli(argv), "```", ""]
    env: dict = {}
    code1 = f"""from symimpact.model.system import ImpactSystem, beam_constants
K, M = beam_constants(E="{E}", I={I_AREA:.6g}, rho="{RHO}",
                      A={AREA:.6g}, L="{L}")
print(f"K = {{K:.3f}} N/m, M = {{M:.4f}} kg")"""
    out += ["```python", code1, "```", "", "```text", _py(code1, env), "```", ""]
    M_modal = env["M"]
    code1b = f"""import math
from scipy.integrate import quad
from symimpact.generated import ritz
bL = ritz.BETA_L[0]                     # mode 1 (Eq. 4)
m_beam = 2700 * {AREA:.6g} * 0.5  # kg
# Eq. 3's shape scaled to unit modal mass, as an FE model
# or a modal test reports a mode: phi^T M phi = 1
norm = quad(lambda u: ritz.mode_shape(bL, u) ** 2, 0, 1)[0]
def phi(xi):                            # kg^-1/2
    return ritz.mode_shape(bL, xi) / math.sqrt(m_beam * norm)
f_n = math.sqrt(K / M) / (2 * math.pi)
for where, xi in (("tip", 1.0), ("mid-span", 0.5)):
    M_d = 1 / phi(xi) ** 2              # kg, at the damper
    K_d = M_d * (2 * math.pi * f_n) ** 2
    print(f"damper at the {{where}}: phi = {{phi(xi):.4f}}, "
          f"M = {{M_d:.4f}} kg, K = {{K_d:.2f}} N/m")
print(f"f_n = {{f_n:.3f}} Hz; rho*A*L/4 = {{m_beam / 4:.4f}} kg")"""
    out += [
        "**The same from modal data.** A finite-element model or a modal test gives the natural "
        "frequency f<sub>n</sub> and the mode shape normalised to unit modal mass (φᵀ**M**φ = 1, "
        "φ in kg<sup>−1/2</sup>). The paper's one-mode model refers the motion to the point "
        "where the damper sits, which moves by one unit: there the modal mass is M = 1/φ(x<sub>d"
        "</sub>)² and the stiffness K = M(2πf<sub>n</sub>)². Here the beam's mode stands in for "
        "what the FE model would print:",
        "",
        "```python",
        code1b,
        "```",
        "",
        "```text",
        _py(code1b, env),
        "```",
        "",
        "At the tip this is the Ritz M and K above (a cantilever's modal mass at its tip is a "
        "quarter of its mass); at mid-span the same mode moves less, so the damper sees a larger "
        "mass and stiffness, with the same f<sub>n</sub>. On the command line the modal data go "
        "in as they are: `--fn` with `--M` (the modal mass at the damper), e.g. "
        f'`--fn "{env["f_n"]:.4g} Hz" --M {M_modal:.4g}` for the tip.',
        "",
    ]
    ball = (
        f"steel sphere {1e3 * (6 * 0.1 * M_modal / (7850 * 3.141592653589793)) ** (1 / 3):.1f} mm"
    )
    out += [
        "## 2. The contact, from the ball and the box (Step 13)",
        "",
        f"The loose mass is about 10 % of the beam's modal mass: a {ball.replace('sphere', 'ball')}"
        ". Hertz's theory gives its contact from the materials and the shapes. Against the bare "
        "aluminium wall of the box, at a tip speed of 1 m/s:",
        "",
    ]
    argv = ["contact", "--impactor", ball, "--cavity", "aluminium alloy flat", "--v0", "1 m/s",
            "--M", f"{M_modal:.6g}"]  # fmt: skip
    out += ["```console", _command(argv), run_cli(argv), "```", ""]
    out += [
        "That e holds at 1 m/s. A slower impact dents less and gives back more (e = 1 below the "
        "yield speed), so a run of rigid impacts can take the materials' e at each impact's own "
        "speed, `--e material` (here the tip shaken at its natural frequency by a base "
        "acceleration of 0.5 g, 200 periods):",
        "",
    ]
    argv = ["simulate", "--fn", f'{env["f_n"]:.6g} Hz', "--M", f"{M_modal:.6g}", "--zeta",
            "0.01", "--impactor", ball, "--cavity", "aluminium alloy flat", "--gap", "10 mm",
            "--contact", "rigid", "--e", "material", "--base-acc", "0.5 g", "--freq",
            f'{env["f_n"]:.6g} Hz', "--periods", "200"]  # fmt: skip
    # its one line of summary, wrapped to the code column as a terminal would
    said = textwrap.fill(run_cli(argv).strip(), CODE_COLUMNS, subsequent_indent="  ")
    out += ["```console", _command(argv), said, "```", ""]
    out += [
        "A contact of microseconds, ten million times stiffer than the paper's "
        "$K_{Hz}$ = 1000 N/m<sup>1.5</sup>, and plastic at this speed: the dent takes most of the "
        "energy (Thornton's model; it describes fresh surfaces — repeated impacts work-harden "
        "the spot). We line the box with polyurethane instead, a resilient contact like the "
        "paper's (whose 1000 N/m<sup>1.5</sup> is softer still, rubber-like):",
        "",
    ]
    argv = ["contact", "--impactor", ball, "--cavity", "polyurethane flat", "--v0", "1 m/s",
            "--M", f"{M_modal:.6g}"]  # fmt: skip
    out += ["```console", _command(argv), run_cli(argv), "```", ""]
    code2 = f"""from symimpact.free.contact import c1_for_restitution
from symimpact.model.derived_contact import derived_contact
lined = derived_contact(
    "{ball}", "polyurethane flat", "1 m/s", M=M
)
system = ImpactSystem.from_beam(
    E="70 GPa", I=I, rho="2700 kg/m^3", A=A, L="0.5 m",
    m=lined.m, gap="10 mm", zeta=0.01, contact="hertz",
    k_hz=lined.k_hz, c1=0, delta_max=lined.max_penetration,
)
# the dashpot c1 (Eq. 10) that gives the liner's e at 1 m/s
c1 = c1_for_restitution(system, lined.e, "1 m/s", law="hertz")
system = system.with_(c1=c1)
print(f"m = {{system.m * 1e3:.2f}} g, "
      f"K_Hz = {{system.k_hz:.4g}} N/m^1.5")
print(f"c1 = {{c1:.4g}} N s/m (e = {{lined.e:.3f}})")
print(f"M = {{system.M:.4f}} kg, K = {{system.K:.2f}} N/m, "
      f"f_n = {{system.omega_n / 6.2832:.2f}} Hz")"""
    env.update({"I": I_AREA, "A": AREA})
    out += [
        "In Python, the beam with the lined box (a 1 % damped beam; the Hertz law with the "
        "dashpot that gives the liner's restitution):",
        "",
        "```python",
        code2,
        "```",
        "",
        "```text",
        _py(code2, env),
        "```",
        "",
        "## 3. How long does a contact last? (Eq. 31, 34, 35)",
        "",
        "The perturbation formula (on the cubic law fitted over the impact's penetration), the "
        "Hertz and linear closed forms and the numerical truth for an approach speed of 0.2 m/s:",
        "",
    ]
    code3 = """from symimpact.free.contact import contact_duration
for method in ("perturbation", "hertz", "linear", "numerical"):
    T = contact_duration(system, "0.2 m/s", method).value  # [s]
    print(f"{method:>12}: {T * 1e3:7.3f} ms")"""
    out += ["```python", code3, "```", "", "```text", _py(code3, env), "```", ""]
    out += [
        "The closed forms leave out the beam's spring; the [accuracy map](report.md) shows "
        "where each one is within 1, 5 and 10 % of the numerical truth.",
        "",
        "## 4. Choosing the gap from a sweep (Eq. 36–38)",
        "",
        "Free vibration from a tip velocity of 1 m/s, 3 s of motion, gaps from 2 to 20 mm. For "
        "each gap: total and effective impacts, effectiveness and damping inclination DI.",
        "",
    ]
    plot = folder / "sweep.png"
    code4 = f"""from symimpact.report.plots import plot_sweep
from symimpact.maps import sweep
import numpy as np
gaps = np.arange(2, 20.1, 1.0) * 1e-3
rows = sweep(system, gaps, "gap", xdot0=1.0, t_end=3.0,
             workers=1, progress=False)
plot_sweep(rows, "gap", "{plot}")
inside = [r for r in rows if r["class"] == "in range"
          and r["damping_inclination"]]
best = max(inside, key=lambda r: r["damping_inclination"])
print(f"in range: {{len(inside)}} of {{len(rows)}} gaps; "
      f"largest DI at d = {{best['gap'] * 1e3:.0f}} mm:")
print(f"DI = {{best['damping_inclination'] * 1e6:.1f}} µm, "
      f"N_tot = {{best['n_impacts']}}, "
      f"N_eff = {{best['n_effective']}}")"""
    shown4 = code4.replace(str(plot), "sweep.png")
    out += ["```python", shown4, "```", "", "```text", _py(code4, env), "```", ""]
    sysd = env["system"]
    argv = ["sweep", "--M", f"{sysd.M:.6g}", "--K", f"{sysd.K:.6g}", "--zeta", "0.01",
            "--m", f"{sysd.m:.6g}", "--contact", "hertz", "--k-hz", f"{sysd.k_hz:.6g}",
            "--c1", f"{sysd.c1:.6g}", "--gap", "2 mm:20 mm:1 mm", "--xdot0", "1 m/s",
            "--t-end", "3", "--workers", "1", "--quiet", "--csv", str(folder / "sweep.csv")]  # fmt: skip
    shown = _command(argv).replace(str(folder) + "/", "")
    # the first lines (the table), with their common indent removed
    lines = textwrap.dedent("\n".join(run_cli(argv).splitlines()[:8])).splitlines()
    out += ["The same from the command line (`--plot` writes the figure, `--csv` the table; the "
            "first lines of its output):", "", "```console", shown,
            *lines[:8], "```", "",
            "![DI, N_eff and effectiveness against the gap](tutorial/sweep.png)", ""]  # fmt: skip
    sim_plot = folder / "simulation.png"
    code5 = f"""from symimpact.report.plots import plot_simulation
from symimpact.free.simulation import simulate
chosen = system.with_(gap=best["gap"])
result = simulate(chosen, xdot0=1.0, t_end=3.0, history=True)
plot_simulation(result, "{sim_plot}")
print(f"N_tot = {{result.n_impacts}}, "
      f"N_eff = {{result.n_effective}}, energy residual "
      f"{{result.energy['relative_residual']:.1e}}")"""
    out += [
        "## 5. The chosen design",
        "",
        "```python",
        code5.replace(str(sim_plot), "simulation.png"),
        "```",
        "",
        "```text",
        _py(code5, env),
        "```",
        "",
        "![Response with the chosen gap](tutorial/simulation.png)",
        "",
        'Next: check the design against the other contact laws (`contact="cubic"`, fitted over `delta_max`), against '
        "the `solve_ivp` reference (`symimpact.free.reference.reference_impacts`), and map it over "
        "mass ratio and contact damping with `symimpact sweep --over m` or `--over c1`.",
        "",
    ]
    return "\n".join(out)
