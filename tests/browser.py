"""Headless Chromium as a reader's browser: open a built docs page, let MathJax typeset it, and
measure the rendered page.

The page is not changed on disk: :func:`instrumented` writes a copy beside it (same folder, so
relative links and MathJax still load) with one script appended.  That script waits for MathJax,
then measures every element inside the content column (``div.body``) with
``getBoundingClientRect`` and ``scrollWidth`` and writes the figures as JSON into the DOM, which
``chromium --dump-dom`` prints.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

MEASURE_JS = r"""
<script>
(async () => {
  const out = {};
  try {
    // MathJax loads deferred: wait until it has started, then until its typesetting is done
    for (let i = 0; i < 300 && !(window.MathJax && MathJax.startup && MathJax.startup.promise); i++) {
      await new Promise((r) => setTimeout(r, 50));
    }
    out.mathjax = !!(window.MathJax && MathJax.startup && MathJax.startup.promise);
    if (out.mathjax) await MathJax.startup.promise;
    const body = document.querySelector('div.body') || document.body;
    // the column is the body's box: the theme's code blocks reach into its side padding
    const box = body.getBoundingClientRect();
    const left = box.left, right = box.right;
    out.column = right - left;
    const describe = (el) => {
      let what = el.tagName.toLowerCase();
      if (el.id) what += '#' + el.id;
      if (el.className && typeof el.className === 'string') what += '.' + el.className.trim().split(/\s+/).join('.');
      const mml = el.tagName === 'MJX-CONTAINER' && el.querySelector('mjx-assistive-mml');
      const text = (mml || el).textContent || '';
      return what + ' "' + text.replace(/\s+/g, ' ').trim().slice(0, 80) + '"';
    };
    let widest = {width: 0, what: ''};
    let content = {width: 0, what: ''};  // the widest formula, code block, table or figure
    const over = [];
    for (const el of body.querySelectorAll('*')) {
      // a formula is judged as a whole: its container's box (MathJax's inner boxes of
      // fractions and tables are positioned relative to it, some with negative offsets)
      if (el.parentElement && el.parentElement.closest('mjx-container')) continue;
      const r = el.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) continue;
      const natural = Math.max(r.width, el.scrollWidth || 0);
      if (natural > widest.width) widest = {width: natural, what: describe(el)};
      if (['MJX-CONTAINER', 'PRE', 'TABLE', 'IMG'].includes(el.tagName)) {
        // a display formula's box is the column's width: its math is measured inside it
        const math = el.tagName === 'MJX-CONTAINER' && el.querySelector('mjx-math');
        const own = math ? Math.max(math.getBoundingClientRect().width, el.scrollWidth - el.clientWidth + math.getBoundingClientRect().width) : natural;
        if (own > content.width) content = {width: own, what: describe(el)};
      }
      const sticks = r.right > right + 1 || r.left < left - 1;
      const hides = (el.scrollWidth || 0) > el.clientWidth + 1 && el.clientWidth > 0;
      if (sticks || hides) over.push({width: natural, what: describe(el)});
    }
    out.widest = widest;
    out.content = content;
    over.sort((a, b) => b.width - a.width);
    out.over = over.slice(0, 20);
    out.n_over = over.length;
    out.containers = document.querySelectorAll('mjx-container').length;
    out.merror = document.querySelectorAll('mjx-merror').length;
  } catch (e) {
    out.error = String(e);
  }
  const pre = document.createElement('pre');
  pre.id = 'symimpact-measure';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>
"""


def chromium() -> str | None:
    """The Chromium executable (Debian's ``chromium``), or None."""
    return shutil.which("chromium") or shutil.which("chromium-browser")


def run(exe: str, profile: Path, *args: str) -> subprocess.CompletedProcess:
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--hide-scrollbars", f"--user-data-dir={profile}", "--virtual-time-budget=20000"]  # fmt: skip
    return subprocess.run([exe, *flags, *args], capture_output=True, text=True, timeout=240)


def instrumented(page: Path) -> Path:
    """A copy of ``page`` beside it with the measuring script appended."""
    html = page.read_text(encoding="utf-8")
    copy = page.with_name(page.stem + ".measure.html")
    copy.write_text(html.replace("</body>", MEASURE_JS + "</body>", 1), encoding="utf-8")
    return copy


def measure(exe: str, profile: Path, url: str, width: int = 1000) -> tuple[dict, str]:
    """(figures, rendered DOM) of the instrumented page at ``url`` in a ``width`` px window."""
    res = run(exe, profile, f"--window-size={width},1400", "--dump-dom", url)
    if res.returncode != 0:
        raise RuntimeError(res.stderr[-2000:])
    m = re.search(r'<pre id="symimpact-measure">(.*?)</pre>', res.stdout, re.S)
    if m is None:
        raise RuntimeError(f"no measurement in the page {url}")
    text = m.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">")
    return json.loads(text.replace("&amp;", "&")), res.stdout


def text_outside_math(dom: str) -> str:
    """The content column's text with scripts, styles and typeset math removed."""
    body = dom.split('<div class="body"', 1)[-1]
    body = body.split('<pre id="symimpact-measure">', 1)[0]
    for tag in ("script", "style", "mjx-container", "pre", "code"):
        body = re.sub(rf"<{tag}\b.*?</{tag}>", "", body, flags=re.S)
    return re.sub(r"<[^>]+>", " ", body)
