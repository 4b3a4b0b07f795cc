"""The report as data: sections of paragraphs, tables and figures, rendered to Markdown and HTML.

A stage of :mod:`symimpact.report` returns a :class:`Section`; :func:`markdown` and :func:`html`
render the same sections, and :func:`write_csv` writes each :class:`Table` with full precision
(the rendered tables show the rounded values).
"""

from __future__ import annotations

import csv
import html as _html
import math
from dataclasses import dataclass, field
from typing import IO, Any


@dataclass
class Table:
    """A table: ``rows`` hold raw values; ``formats`` give the display format per column."""

    name: str  # CSV file stem
    title: str
    columns: list[str]
    rows: list[list[Any]]
    formats: list[str | None] | None = None
    note: str = ""
    #: A long table (hundreds of rows) is shown as its CSV link and ``note`` only.
    link_only: bool = False

    def cell(self, row: int, column: str) -> Any:
        """The raw value in ``row`` under the column headed ``column``."""
        return self.rows[row][self.columns.index(column)]

    def column(self, column: str) -> list[Any]:
        """Every raw value under the column headed ``column``."""
        j = self.columns.index(column)
        return [r[j] for r in self.rows]

    def display(self, value: Any, j: int) -> str:
        if value is None:
            return "–"
        if isinstance(value, float):
            if not math.isfinite(value):
                return "–"
            fmt = self.formats[j] if self.formats else None
            return format(value, fmt or ".6g")
        return str(value)


@dataclass
class Figure:
    """A PNG written by the stage into the report folder."""

    name: str  # file stem, the PNG is ``<name>.png``
    title: str
    caption: str


@dataclass
class Section:
    """One part of the report: paragraphs (str), tables and figures, in order."""

    key: str
    title: str
    blocks: list[str | Table | Figure] = field(default_factory=list)
    #: What a later stage builds on (not shown), e.g. the reading of Table 2 that was chosen.
    facts: dict[str, Any] = field(default_factory=dict)

    def tables(self) -> list[Table]:
        return [b for b in self.blocks if isinstance(b, Table)]

    def figures(self) -> list[Figure]:
        return [b for b in self.blocks if isinstance(b, Figure)]

    def table(self, name: str) -> Table:
        """The table called ``name``."""
        for t in self.tables():
            if t.name == name:
                return t
        raise KeyError(name)


def write_csv(table: Table, f: IO[str]) -> None:
    """The table's raw values, each float as its shortest round-trip decimal (``repr``: an
    input of 0.1 reads 0.1, not 0.10000000000000001; every value reads back exactly)."""
    w = csv.writer(f, lineterminator="\n")
    w.writerow(table.columns)
    for row in table.rows:
        w.writerow(
            ["" if v is None else repr(float(v)) if isinstance(v, float) else v for v in row]
        )


def markdown(
    title: str, meta: list[tuple[str, str]], sections: list[Section], links: bool = True
) -> str:
    """The whole report as Markdown (tables as pipe tables, figures as image links).

    ``links=False`` leaves out the contents list, the anchors and the CSV links (for embedding
    the report in the documentation, which makes its own).
    """
    out = [f"# {title}", ""]
    out += [f"- **{k}**: {v}" for k, v in meta]
    if links:
        out += ["", "## Contents", ""]
        out += [f"{i}. [{s.title}](#{s.key})" for i, s in enumerate(sections, 1)]
    for s in sections:
        out += ["", f'<a id="{s.key}"></a>'] if links else []
        out += ["", f"## {s.title}", ""]
        for b in s.blocks:
            if isinstance(b, str):
                out += [b, ""]
            elif isinstance(b, Table):
                csv_link = f" ([{b.name}.csv]({b.name}.csv))" if links else ""
                out += [f"**{b.title}**{csv_link}", ""]
                if b.link_only:
                    out += [f"{len(b.rows)} rows, in the CSV file. {b.note}".rstrip(), ""]
                    continue
                out.append("| " + " | ".join(b.columns) + " |")
                out.append("|" + "---|" * len(b.columns))
                for row in b.rows:
                    cells = [b.display(v, j).replace("|", "\\|") for j, v in enumerate(row)]
                    out.append("| " + " | ".join(cells) + " |")
                out.append("")
                if b.note:
                    out += [b.note, ""]
            else:
                out += [f"![{b.title}]({b.name}.png)", "", f"*{b.title}.* {b.caption}", ""]
    return "\n".join(out).rstrip() + "\n"


_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:70rem;margin:2rem auto;
padding:0 1rem;line-height:1.45;color:#222}
table{border-collapse:collapse;margin:.5rem 0 1rem;font-size:.9rem}
th,td{border:1px solid #ccc;padding:.25rem .5rem;text-align:right}
th{background:#f2f2f2}td:first-child,th:first-child{text-align:left}
figure{margin:1rem 0}figure img{max-width:100%;border:1px solid #ddd}
figcaption{font-size:.9rem;color:#444}.meta{background:#f8f8f8;padding:.5rem 1rem}
code{background:#f2f2f2;padding:0 .2rem}
"""


def html(title: str, meta: list[tuple[str, str]], sections: list[Section]) -> str:
    """The whole report as one HTML page (no scripts, no network: images are local PNG files)."""
    e = _html.escape
    out = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{e(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{e(title)}</h1>",
        '<ul class="meta">',
    ]
    out += [f"<li><b>{e(k)}</b>: {e(v)}</li>" for k, v in meta]
    out += ["</ul>", "<h2>Contents</h2>", "<ol>"]
    out += [f'<li><a href="#{s.key}">{e(s.title)}</a></li>' for s in sections]
    out.append("</ol>")
    for s in sections:
        out.append(f'<h2 id="{s.key}">{e(s.title)}</h2>')
        for b in s.blocks:
            if isinstance(b, str):
                out.append(f"<p>{e(b)}</p>")
            elif isinstance(b, Table):
                head = f'<p><b>{e(b.title)}</b> (<a href="{b.name}.csv">{b.name}.csv</a>)</p>'
                if b.link_only:
                    out.append(head + f"<p>{len(b.rows)} rows, in the CSV file. {e(b.note)}</p>")
                    continue
                out.append(head + "<table>")
                out.append("<tr>" + "".join(f"<th>{e(c)}</th>" for c in b.columns) + "</tr>")
                for row in b.rows:
                    cells = "".join(f"<td>{e(b.display(v, j))}</td>" for j, v in enumerate(row))
                    out.append(f"<tr>{cells}</tr>")
                out.append("</table>")
                if b.note:
                    out.append(f"<p>{e(b.note)}</p>")
            else:
                out.append(
                    f'<figure><img src="{b.name}.png" alt="{e(b.title)}">'
                    f"<figcaption><b>{e(b.title)}.</b> {e(b.caption)}</figcaption></figure>"
                )
    out.append("</body></html>")
    return "\n".join(out) + "\n"
