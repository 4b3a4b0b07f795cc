"""``symimpact export``: each target's files, byte for byte, usable as its README says."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from symimpact.generated import closed_forms

from symimpact.cli import main
from symimpact.errors import ParameterError
from symimpact.export import export_kernels
from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent
ARGS = (0.25, 1.0, 1000.0, 0.075)  # m, M, k_hz, ż0 of Table 1
EXPECTED = float(closed_forms.hertz_contact_duration(*ARGS))


@pytest.mark.parametrize(
    ("target", "sub"), [("numpy", ""), ("c", "c"), ("c-cmake", "c"), ("octave", "octave")]
)
def test_export_copies_the_generated_files(tmp_path, target, sub, capsys):
    out = tmp_path / "kernels"
    assert main(["export", "--target", target, "--out", str(out)]) == 0
    assert "README.md" in capsys.readouterr().out
    source = ROOT / "generated" / sub
    wanted = {
        p.name
        for p in source.iterdir()
        if p.is_file() and p.suffix in {"numpy": (".py", ".md"), "c": (".c", ".h", ".md", ".txt", ".in"),
                                        "c-cmake": (".c", ".h", ".md", ".txt", ".in"),
                                        "octave": (".m", ".md")}[target]
    }  # fmt: skip
    assert {p.name for p in out.iterdir()} == wanted | {".symimpact-output"}  # --force's marker
    for name in wanted:
        assert (out / name).read_bytes() == (source / name).read_bytes(), name


def test_exported_numpy_package_imports_under_its_folder_name(tmp_path):
    export_kernels("numpy", tmp_path / "kernels")
    code = (
        f"import sys; sys.path.insert(0, {str(tmp_path)!r}); from kernels import closed_forms; "
        f"print(repr(float(closed_forms.hertz_contact_duration{ARGS})))"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert float(run.stdout) == EXPECTED


def test_exported_c_compiles_and_runs_as_its_readme_says(tmp_path):
    cc = require_tool("cc")
    out = tmp_path / "c"
    export_kernels("c", out)
    (tmp_path / "main.c").write_text(
        '#include <stdio.h>\n#include "symimpact.h"\n'
        "int main(void)\n{\n"
        f'    printf("%.17g\\n", symimpact_closed_forms_hertz_contact_duration{ARGS});\n'
        "    return 0;\n}\n"
    )
    flags = ["-std=c99", "-O2", "-Wall", "-Wextra", "-pedantic", "-Werror"]
    subprocess.run([cc, *flags, "-c", "symimpact.c"], cwd=out, check=True)
    subprocess.run(
        [cc, *flags, f"-I{out}", "main.c", str(out / "symimpact.o"), "-o", "main", "-lm"],
        cwd=tmp_path,
        check=True,
    )
    run = subprocess.run([str(tmp_path / "main")], capture_output=True, text=True, check=True)
    assert float(run.stdout) == pytest.approx(EXPECTED, rel=1e-14)


def test_exported_octave_runs_as_its_readme_says(tmp_path):
    octave = require_tool("octave-cli")
    out = tmp_path / "octave"
    export_kernels("octave", out)
    script = (
        f"addpath('{out}'); T = closed_forms_hertz_contact_duration{ARGS}; "
        "[T31, steps] = fixed_points_contact_duration(0.25, 0.155265e6, 83.595, 0.0, 0.075, -4.0); "
        "printf('[%.17g, %.17g, %d]\\n', T, T31, steps)"
    )
    run = subprocess.run(
        [octave, "--no-gui", "--norc", "--quiet", "--eval", script],
        capture_output=True,
        text=True,
        timeout=120,
    )
    T, T31, steps = json.loads(run.stdout)
    assert T == pytest.approx(EXPECTED, rel=1e-14)
    from symimpact.generated import fixed_points

    value, n = fixed_points.contact_duration(0.25, 0.155265e6, 83.595, 0.0, 0.075, -4.0)
    assert T31 == pytest.approx(float(value), rel=1e-13) and abs(steps - int(n)) <= 1


def test_export_refuses_a_full_folder_and_leaves_nothing_when_interrupted(tmp_path, monkeypatch):
    out = tmp_path / "c"
    export_kernels("c", out)
    with pytest.raises(ParameterError, match="not empty; pass --force"):
        export_kernels("c", out)
    export_kernels("octave", out, force=True)  # replaced as a whole
    assert not (out / "symimpact.c").exists() and (out / "README.md").exists()
    with pytest.raises(ParameterError, match="target: must be one of"):
        export_kernels("julia", tmp_path / "f")

    import symimpact.export as export

    calls = {"n": 0}
    real = export.shutil.copyfile

    def copy_then_fail(src, dst):
        calls["n"] += 1
        if calls["n"] == 2:
            raise KeyboardInterrupt
        return real(src, dst)

    monkeypatch.setattr(export.shutil, "copyfile", copy_then_fail)
    with pytest.raises(KeyboardInterrupt):
        export_kernels("numpy", tmp_path / "new")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c"]
