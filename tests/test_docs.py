"""The documentation builds with warnings as errors, and its math is typeset in a real browser.

The site is built once (``sphinx-build -W``) into ``docs/_build/html``; one derivation page is
served on loopback and opened in headless Chromium (Debian's ``chromium``, installed by
``.ci/run``).  The check reads the DOM *after* MathJax ran — not the HTML source — and a
screenshot is saved under the build folder.
"""

from __future__ import annotations

import functools
import http.server
import os
import re
import shutil
import struct
import subprocess
import sys
import threading
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
BUILD = ROOT / "docs" / "_build" / "html"
PAGE = "_generated/derivations/multiple_scales.html"


@pytest.fixture(scope="module")
def site():
    if BUILD.exists():
        shutil.rmtree(BUILD)
    proc = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-b", "html",
         str(ROOT / "docs"), str(BUILD)],
        capture_output=True, text=True, timeout=900,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr[-4000:]
    return BUILD


def _chromium() -> str:
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    if exe is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is not installed (.ci/run installs Debian's chromium)")
        pytest.skip("chromium is not installed here")
    return exe


@pytest.fixture(scope="module")
def server(site):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    httpd = http.server.ThreadingHTTPServer(
        ("127.0.0.1", 0), functools.partial(Quiet, directory=str(site))
    )
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()


def _browser(exe: str, tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=15000"]  # fmt: skip
    return subprocess.run([exe, *flags, *args], capture_output=True, text=True, timeout=180)


def test_docs_build_has_every_page_and_offline_mathjax(site):
    for page in ("index.html", "api.html", "kernels.html", "targets.html", "_generated/tutorial.html",
                 "_generated/errata.html", "_generated/cli.html", "_generated/report.html",
                 PAGE):  # fmt: skip
        assert (site / page).is_file(), page
    html = (site / PAGE).read_text(encoding="utf-8")
    scripts = re.findall(r'<script[^>]+src="([^"]+)"', html)
    assert any("mathjax/tex-chtml.js" in s for s in scripts)
    assert not [s for s in scripts if s.startswith(("http:", "https:", "//"))], scripts
    assert (site / "_static" / "mathjax" / "tex-chtml.js").is_file()
    api = (site / "api.html").read_text(encoding="utf-8")
    assert "contact_duration" in api and "Eq. 31" in api  # docstrings made it in


def test_derivation_math_is_typeset_in_chromium(site, server, tmp_path):
    exe = _chromium()
    url = f"{server}/{PAGE}"
    dom = _browser(exe, tmp_path, "--dump-dom", url)
    assert dom.returncode == 0, dom.stderr[-2000:]
    rendered = dom.stdout
    source = (ROOT / "docs" / "_generated" / "derivations" / "multiple_scales.md").read_text()
    n_display = source.count("$$\n") // 2
    containers = re.findall(r"<mjx-container[^>]*>", rendered)
    assert n_display > 10
    assert len(containers) >= n_display, (len(containers), n_display)
    assert "<mjx-merror" not in rendered  # no TeX error anywhere on the page
    # what is left outside the typeset containers holds no raw TeX any more
    body = rendered.split("<body", 1)[1]
    for tag in ("script", "style", "mjx-container"):
        body = re.sub(rf"<{tag}\b.*?</{tag}>", "", body, flags=re.S)
    assert "\\frac" not in body and "\\[" not in body and "\\(" not in body
    shot = BUILD / "screenshots" / "multiple_scales.png"
    shot.parent.mkdir(parents=True, exist_ok=True)
    res = _browser(exe, tmp_path, f"--screenshot={shot}", "--window-size=1200,1600", url)
    assert res.returncode == 0, res.stderr[-2000:]
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", data[16:24]) == (1200, 1600)
    assert len(data) > 20_000
