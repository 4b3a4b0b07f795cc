"""``python -m benchmarks --only N --write RESULTS.md`` replaces section N and keeps the others
as they were: merging the same run twice gives the same file (the kept sections' blank lines
once grew by one a run)."""

from __future__ import annotations

import datetime

from benchmarks.__main__ import _merged

OLD = """# Benchmark figures

```text
machine: test

=== 1. one ===
(run started 2026-01-01 00:00 UTC; machine: test)
a: 1 s


=== 2. two ===
(run started 2026-01-01 00:00 UTC; machine: test)
b: 2 s
```
"""


def test_merging_a_section_keeps_the_others_byte_for_byte(tmp_path):
    path = tmp_path / "RESULTS.md"
    path.write_text(OLD)
    run = "machine: new\n\n=== 2. two ===\nb: 3 s\n(1 s)"
    when = datetime.datetime(2026, 2, 2, 12, 0)
    first = _merged(str(path), run, when)
    path.write_text("# Benchmark figures\n\n```text\n" + first + "\n```\n")
    second = _merged(str(path), run, when)
    assert second == first
    assert (
        "=== 1. one ===\n(run started 2026-01-01 00:00 UTC; machine: test)\na: 1 s\n\n=== 2."
        in first
    )
    assert "b: 3 s" in first and "b: 2 s" not in first
    assert "(run started 2026-02-02 12:00 UTC; machine: new)" in first
